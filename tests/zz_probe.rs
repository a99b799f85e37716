use layered_contact::analytic::Axisymmetric;
use layered_contact::{Material, Substrate};
use nalgebra::{DMatrix, DVector};

fn coefficients(substrate: &Substrate, chi_max: f64, degree: usize, tip: &str) -> Vec<f64> {
    let h = substrate.top_thickness().unwrap();
    let estar = substrate.surface_material().contact_modulus();
    let exact = Axisymmetric::new(substrate, 2.0).unwrap();
    let r = 1.0 * h;
    let mut rows = Vec::new();
    let mut rhs = Vec::new();
    for k in 1..=60 {
        let eps = chi_max * k as f64 / 60.0;
        let a = eps * h;
        let (chi, ratio) = if tip == "ball" {
            let s = exact
                .paraboloid(r, 0.0)
                .unwrap()
                .at_contact_radius(a)
                .unwrap();
            let chi = (r * s.depth).sqrt() / h;
            let hertz = 4.0 / 3.0 * estar * r.sqrt() * s.depth.powf(1.5);
            (chi, s.force / hertz)
        } else {
            let p = exact.flat_punch(a).unwrap();
            (eps, p.stiffness() / (2.0 * estar * a))
        };
        rows.push((1..=degree).map(|p| chi.powi(p as i32)).collect::<Vec<_>>());
        rhs.push(ratio - 1.0);
    }
    let m = DMatrix::from_fn(rows.len(), degree, |i, j| rows[i][j]);
    let b = DVector::from_vec(rhs);
    let svd = m.svd(true, true);
    let x = svd.solve(&b, 1e-14).unwrap();
    x.iter().copied().collect()
}

#[test]
fn probe() {
    for nu in [0.0, 0.3, 0.45, 0.5] {
        let layer = Material::new(1e6, nu).unwrap();
        let s = Substrate::layer_on_rigid_base(layer, 1e-5).unwrap();
        let a0 = layered_contact::analytic::a_m(0, nu).unwrap();
        let a1 = layered_contact::analytic::a_m(1, nu).unwrap();
        let a2 = layered_contact::analytic::a_m(2, nu).unwrap();
        println!("nu {nu} a0 {a0} a1 {a1} a2 {a2}");
        println!("ball {:?}", coefficients(&s, 0.1, 9, "ball"));
        println!("punch {:?}", coefficients(&s, 0.1, 9, "punch"));
    }
}
