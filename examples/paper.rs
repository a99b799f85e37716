//! Reproduces the reference experiment of Lyashenko, Popov & Borysiuk (2023,
//! Lubricants 11, 84): a soft rubber layer (`E = 0.324 MPa`, `nu = 0.48`) on a
//! glass (rigid) base, probed by flat punches.
//!
//! Prints, for every layer thickness and punch diameter of the experiment,
//! the stiffness `K / (2 a E*)` from the series of SPEC section 3 and from the
//! exact axisymmetric solution, the headline numbers of the paper, and the
//! JKR pull-off forces of the punches on each layer. Later versions add the
//! BEM curves under the same command:
//!
//! ```text
//! cargo run --release --example paper
//! ```

use layered_contact::analytic::{Axisymmetric, JkrFlatPunch, PunchStiffnessSeries};
use layered_contact::{Error, Material, Substrate};

const THICKNESSES_MM: [f64; 5] = [5.0, 10.0, 15.0, 20.0, 25.0];
const DIAMETERS_MM: [f64; 6] = [1.0, 2.0, 4.0, 7.0, 10.0, 15.0];
const PUNCH_DIAMETERS_MM: [f64; 4] = [4.0, 7.0, 10.0, 15.0];
const WORK_OF_ADHESION_UNLOADING: f64 = 0.326;

fn main() -> Result<(), Error> {
    let rubber = Material::new(0.324e6, 0.48)?;
    println!("# Flat punch on a rubber layer on glass: E = 0.324 MPa, nu = 0.48\n");
    println!("## K / (2 a E*): series (SPEC section 3) / exact axisymmetric solution");
    println!("(* marks a/h > 1, outside the series' range)\n");
    print!("| h [mm] |");
    for d in DIAMETERS_MM {
        print!(" D = {d} mm |");
    }
    println!();
    println!("|---|{}", "---|".repeat(DIAMETERS_MM.len()));
    let mut worst_series = (0.0f64, 0.0, 0.0);
    for h in THICKNESSES_MM {
        let thickness = h * 1e-3;
        let series = PunchStiffnessSeries::new(rubber, thickness)?;
        let film = Substrate::layer_on_rigid_base(rubber, thickness)?;
        let exact = Axisymmetric::new(&film, 2.0)?;
        print!("| {h} |");
        for d in DIAMETERS_MM {
            let radius = 0.5 * d * 1e-3;
            let k = series.evaluate(radius)?;
            let exact_ratio = exact.flat_punch(radius)?.ratio();
            let mark = if k.is_within_validity() { " " } else { "*" };
            print!(" {:.4}{mark}/ {exact_ratio:.4} |", k.ratio);
            let deviation = (k.ratio / exact_ratio - 1.0).abs();
            if k.is_within_validity() && deviation > worst_series.0 {
                worst_series = (deviation, h, d);
            }
        }
        println!();
    }
    println!(
        "\nlargest series error where a/h <= 1: {:.2} % (h = {} mm, D = {} mm)",
        100.0 * worst_series.0,
        worst_series.1,
        worst_series.2
    );

    let series = PunchStiffnessSeries::new(rubber, 5e-3)?;
    let at_h_equal_d = series.evaluate(2.5e-3)?.ratio;
    let exact_h_equal_d = Axisymmetric::new(&Substrate::layer_on_rigid_base(rubber, 5e-3)?, 1.0)?
        .flat_punch(2.5e-3)?
        .ratio();
    let crossing = diameter_where_ratio_reaches(&series, 1.2)?;
    println!("\nseries ratio at h = D = 5 mm: {at_h_equal_d:.4} (paper: 1.9); exact: {exact_h_equal_d:.4}");
    println!(
        "h = 5 mm: series K/(2aE*) = 1.2 at D = {:.4} mm, h/D = {:.2} (paper: 1.55 mm, 3.2)",
        crossing * 1e3,
        5e-3 / crossing
    );

    println!("\n## JKR pull-off force [mN] of the punches, dgamma = {WORK_OF_ADHESION_UNLOADING} J/m^2 (exact)\n");
    print!("| h [mm] |");
    for d in PUNCH_DIAMETERS_MM {
        print!(" D = {d} mm |");
    }
    println!();
    println!("|---|{}", "---|".repeat(PUNCH_DIAMETERS_MM.len()));
    for h in THICKNESSES_MM {
        let exact = Axisymmetric::new(&Substrate::layer_on_rigid_base(rubber, h * 1e-3)?, 2.0)?;
        print!("| {h} |");
        for d in PUNCH_DIAMETERS_MM {
            let punch = exact.flat_punch(0.5 * d * 1e-3)?;
            print!(
                " {:.2} |",
                punch.pull_off_force(WORK_OF_ADHESION_UNLOADING) * 1e3
            );
        }
        println!();
    }
    print!("| half-space (Kendall) |");
    for d in PUNCH_DIAMETERS_MM {
        let punch = JkrFlatPunch::new(&rubber, 0.5 * d * 1e-3, WORK_OF_ADHESION_UNLOADING)?;
        print!(" {:.2} |", punch.pull_off_force() * 1e3);
    }
    println!();
    Ok(())
}

/// The punch diameter (m) at which the series reaches `ratio`, by bisection on
/// `D` in `(0, 2h]` (the series increases with `D` there).
fn diameter_where_ratio_reaches(series: &PunchStiffnessSeries, ratio: f64) -> Result<f64, Error> {
    let (mut lo, mut hi) = (1e-9, 5e-3);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if series.evaluate(0.5 * mid)?.ratio < ratio {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}
