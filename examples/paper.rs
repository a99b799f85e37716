//! Reproduces the reference experiment of Lyashenko, Popov & Borysiuk (2023,
//! Lubricants 11, 84): a soft rubber layer (`E = 0.324 MPa`, `nu = 0.48`) on a
//! glass (rigid) base, probed by flat punches.
//!
//! For now it prints the stiffness series `K / (2 a E*)` (SPEC section 3) for
//! every layer thickness and punch diameter of the experiment, and the two
//! headline numbers of the paper. Later versions add the BEM and exact
//! curves under the same command:
//!
//! ```text
//! cargo run --release --example paper
//! ```

use layered_contact::analytic::{JkrFlatPunch, PunchStiffnessSeries};
use layered_contact::{Error, Material};

const THICKNESSES_MM: [f64; 5] = [5.0, 10.0, 15.0, 20.0, 25.0];
const DIAMETERS_MM: [f64; 6] = [1.0, 2.0, 4.0, 7.0, 10.0, 15.0];
const WORK_OF_ADHESION_UNLOADING: f64 = 0.326;

fn main() -> Result<(), Error> {
    let rubber = Material::new(0.324e6, 0.48)?;
    println!("# Flat punch on a rubber layer on glass: E = 0.324 MPa, nu = 0.48");
    println!(
        "# K / (2 a E*) from the series of SPEC section 3 (* marks a/h > 1, outside its range)\n"
    );
    print!("| h [mm] |");
    for d in DIAMETERS_MM {
        print!(" D = {d} mm |");
    }
    println!();
    println!("|---|{}", "---|".repeat(DIAMETERS_MM.len()));
    for h in THICKNESSES_MM {
        let series = PunchStiffnessSeries::new(rubber, h * 1e-3)?;
        print!("| {h} |");
        for d in DIAMETERS_MM {
            let k = series.evaluate(0.5 * d * 1e-3)?;
            let mark = if k.is_within_validity() { " " } else { "*" };
            print!(" {:.4}{mark}|", k.ratio);
        }
        println!();
    }

    let series = PunchStiffnessSeries::new(rubber, 5e-3)?;
    let at_h_equal_d = series.evaluate(2.5e-3)?.ratio;
    let crossing = diameter_where_ratio_reaches(&series, 1.2)?;
    println!("\nseries ratio at h = D = 5 mm: {at_h_equal_d:.4} (paper: 1.9)");
    println!(
        "h = 5 mm: K/(2aE*) = 1.2 at D = {:.4} mm, h/D = {:.2} (paper: 1.55 mm, 3.2)",
        crossing * 1e3,
        5e-3 / crossing
    );

    println!("\nKendall pull-off force of the punches on a half-space, dgamma = {WORK_OF_ADHESION_UNLOADING} J/m^2:");
    for d in DIAMETERS_MM {
        let punch = JkrFlatPunch::new(&rubber, 0.5 * d * 1e-3, WORK_OF_ADHESION_UNLOADING)?;
        println!("  D = {d:>4} mm: {:.4} mN", punch.pull_off_force() * 1e3);
    }
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
