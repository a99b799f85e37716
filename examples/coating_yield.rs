//! Where a hard coating on steel first yields under a ball, and where its
//! interfaces carry the most shear: 2 um of TiN on 1 um of chromium on
//! steel, a rigid ball of radius 100 um, each material with its own yield
//! stress. The depth at which the largest ratio of von Mises stress to the
//! local yield stress reaches one is found by bisection; the stress planes
//! are planned once and reused for every pressure.
//!
//! `cargo run --release --example coating_yield` (about 20 s); the numbers
//! are quoted in `doc::subsurface`.

use layered_contact::indenter::Sphere;
use layered_contact::solver::{ContactSolver, Fields, SolverParams};
use layered_contact::stress::{Side, SubsurfaceStress};
use layered_contact::{Base, Boundary, Grid, Material, Substrate};

/// `(name, E, nu, thickness, yield stress)`; the last is the base.
const LAYERS: [(&str, f64, f64, f64, f64); 3] = [
    ("TiN", 400e9, 0.25, 2e-6, 8.0e9),
    ("chromium", 279e9, 0.21, 1e-6, 1.2e9),
    ("steel", 210e9, 0.30, f64::INFINITY, 1.6e9),
];

/// The most loaded point of a solve: the largest von Mises / yield ratio,
/// its plane's depth and cell, and the solve's force, contact radius and
/// pressure.
struct Found {
    ratio: f64,
    depth: f64,
    cell: usize,
    force: f64,
    contact_radius: f64,
    pressure: Vec<f64>,
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let material = |k: usize| Material::new(LAYERS[k].1, LAYERS[k].2);
    let body = Substrate::stack(
        &[(material(0)?, LAYERS[0].3), (material(1)?, LAYERS[1].3)],
        Base::Elastic(material(2)?),
    )?;
    let radius = 100e-6;
    // 128 cells over 8 um: the contact at first yield is about 3 um wide.
    let grid = Grid::new(128, 128, 8e-6 / 128.0)?;
    let params = SolverParams {
        fields: Fields {
            pressure: true,
            ..Fields::default()
        },
        ..SolverParams::default()
    };
    let mut solver = ContactSolver::new(&body, &grid, Boundary::Isolated, params)?;
    let mut stress = SubsurfaceStress::new(&body, &grid, Boundary::Isolated)?;
    let depths: Vec<f64> = (0..=60).map(|k| 0.1e-6 * k as f64).collect();
    let yield_at = |z: f64| {
        if z < LAYERS[0].3 {
            LAYERS[0].4
        } else if z < LAYERS[0].3 + LAYERS[1].3 {
            LAYERS[1].4
        } else {
            LAYERS[2].4
        }
    };
    let mut worst = |depth: f64| -> Result<Found, Box<dyn std::error::Error>> {
        let (s, _) = solver.solve_depth(&Sphere::new(radius)?, depth, None, &mut ())?;
        let pressure: Vec<f64> = s.pressure.ok_or("no pressure")?.iter().copied().collect();
        let mut found = Found {
            ratio: 0.0,
            depth: 0.0,
            cell: 0,
            force: s.force,
            contact_radius: s.contact_radius,
            pressure: Vec::new(),
        };
        for plane in stress.planes(&pressure, &depths, Side::Below)? {
            let (vm, cell) = plane.max_of(|t| t.von_mises());
            let ratio = vm / yield_at(plane.depth);
            if ratio > found.ratio {
                (found.ratio, found.depth, found.cell) = (ratio, plane.depth, cell);
            }
        }
        found.pressure = pressure;
        Ok(found)
    };
    let (mut low, mut high) = (0.01e-6, 1e-6);
    for _ in 0..40 {
        let mid = 0.5 * (low + high);
        if worst(mid)?.ratio < 1.0 {
            low = mid;
        } else {
            high = mid;
        }
        if high - low < 1e-4 * high {
            break;
        }
    }
    let found = worst(high)?;
    let centre = |cell: usize| grid.cell_centre(cell / grid.columns(), cell % grid.columns());
    let (x, y) = centre(found.cell);
    println!(
        "first yield: depth {high:.4e} m, force {:.4e} N (von Mises / yield {:.4})",
        found.force, found.ratio
    );
    let z = found.depth;
    let layer = if z < 2e-6 {
        "TiN"
    } else if z < 3e-6 {
        "chromium"
    } else {
        "steel"
    };
    println!("  at z = {z:.3e} m ({layer}), r = {:.3e} m", x.hypot(y));
    let p = found.pressure;
    println!(
        "  contact radius {:.3e} m, peak pressure {:.4e} Pa",
        found.contact_radius,
        p.iter().copied().fold(0.0, f64::max)
    );
    for t in stress.interfaces(&p)? {
        let (shear, k) = t.largest_shear();
        let (x, y) = centre(k);
        let normal = t.normal.iter().copied().fold(0.0, f64::min);
        println!(
            "  interface at {:.1e} m: largest shear traction {shear:.4e} Pa at r = {:.3e} m; largest normal compression {:.4e} Pa",
            t.depth,
            x.hypot(y),
            -normal
        );
    }
    Ok(())
}
