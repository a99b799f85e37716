//! Temporary measurements of the adhesive solver (not shipped).
use layered_contact::analytic::JkrSphere;
use layered_contact::indenter::Paraboloid;
use layered_contact::solver::{ContactSolver, SolverParams};
use layered_contact::{Boundary, Grid, Material, Substrate};
use std::time::Instant;

fn main() {
    let m = Material::new(1e6, 0.5).unwrap();
    let (r, w) = (0.01, 0.05);
    let jkr = JkrSphere::new(&m, r, w).unwrap();
    let a_po = jkr.pull_off_contact_radius();
    let ns: Vec<usize> = std::env::args()
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect();
    for n in ns {
        let delta = 2.0 * a_po / n as f64;
        let cells = (n as f64 * 2.5).ceil() as usize;
        let grid = Grid::new(cells, cells, delta).unwrap();
        let t = Instant::now();
        let mut solver = ContactSolver::new(
            &Substrate::half_space(m),
            &grid,
            Boundary::Isolated,
            SolverParams {
                tolerance: 1e-8,
                ..Default::default()
            },
        )
        .unwrap();
        let ball = Paraboloid::new(r).unwrap();
        let dmax = (1.3 * a_po).powi(2) / r;
        let b = solver
            .adhesive_branches(
                &ball,
                layered_contact::solver::Reach::Depth(dmax),
                w,
                w,
                &mut (),
            )
            .unwrap();
        let pk = b.at_depth(dmax, 0.0).unwrap();
        let po = b.pull_off(pk.contact_area).unwrap();
        let el = t.elapsed().as_secs_f64();
        // worst error along the unloading branch vs JKR at the same depth
        let mut worst: f64 = 0.0;
        let mut area = b.at_depth(dmax, 0.0).unwrap().contact_area;
        for k in 0..400 {
            let d = dmax - k as f64 * dmax / 150.0;
            let p = b.at_depth(d, area).unwrap();
            area = p.contact_area;
            if area == 0.0 {
                break;
            }
            // exact JKR at same depth: find a on stable branch (a > a_c)
            let (mut lo, mut hi) = (jkr.pull_off_contact_radius() / 9f64.cbrt(), 3.0 * a_po);
            if jkr.depth(lo) > d {
                continue;
            }
            for _ in 0..80 {
                let mid = 0.5 * (lo + hi);
                if jkr.depth(mid) < d {
                    lo = mid
                } else {
                    hi = mid
                }
            }
            let fe = jkr.force(lo);
            worst = worst.max(((p.force - fe) / jkr.pull_off_force()).abs());
            if std::env::var("TRACE").is_ok() {
                println!(
                    "d={:.4e} F={:.5e} exact={:.5e} err={:+.3}% a/apo={:.3} ae/apo={:.3}",
                    d,
                    p.force,
                    fe,
                    100.0 * (p.force - fe) / jkr.pull_off_force(),
                    p.contact_radius / a_po,
                    lo / a_po
                );
            }
        }
        println!("N={n} cells={cells} sets={} pull-off {:.6e} exact {:.6e} err {:+.4}% a {:+.3}% worst-branch {:.3}% time {:.2}s its {}",
            b.sets(), po.force, jkr.pull_off_force(), 100.0 * (po.force / jkr.pull_off_force() - 1.0),
            100.0*(po.contact_radius/a_po-1.0), 100.0*worst, el, b.iterations());
    }
}
