//! Whether a bonded flat punch comes off where it starts to detach: the
//! critical force along a peeling path, from the local release rates of
//! [`ContactSolver::edge_release`].
//!
//! A flat punch (a disc, a square, a 2:1 rectangle or a 2:1 ellipse, `N`
//! cells across its short side) bonded over its whole face on the rubber half-space
//! (`E = 1 MPa`, `nu = 0.48`, `dgamma = 0.05 J/m^2`) is held at a depth;
//! the force at which its largest release rate reaches the work of adhesion
//! is `F_crit = F sqrt(dgamma / G_max)` (`G` grows like the force squared).
//! Then the edge cells whose release rate is within `fraction` of the
//! largest are peeled off and the next contact is measured, until fewer
//! than four cells are left. Under force control the punch comes off at the
//! most tensile `F_crit` along the path: at the first contact (the onset)
//! where the detachment is unstable, as for Kendall's disc, later where the
//! peeled contacts hold more.
//!
//! ```text
//! cargo run --release --example punch_peel -- [disc|square|rectangle|ellipse] N [fraction [degrees]]
//! ```
//!
//! The face turned by `degrees` on the grid; the environment variable
//! `STRETCH` scales the cells by a factor (1 by default), the face kept,
//! to measure another grid's staircase, and `OFFSET=x,y` moves the face's
//! centre by that many cells (0,0 by default: the grid's centre, a cell
//! corner). With `ellipse` and a fraction of 0 the onset and pull-off are
//! also printed over the exact onset `F = 2 b sqrt(2 pi E* dgamma a)`;
//! with `disc`, a fraction of 0 and `TILT=rise,degrees` the face is tilted
//! towards `degrees` so that it rises by `rise` of Kendall's critical
//! depth across the radius, and the onset and pull-off are printed over the
//! exact onset of a punch under force and moment, `F = 2 E* a (2 a beta -
//! d_c)`, for the staircase's radius (`sqrt(A / pi) - EDGE_SHIFT` cells) and
//! for the punch's own. A negative fraction runs the
//! mesh-dependent criterion instead (`solve_depth_hysteretic`, pulled in
//! steps of 1/200 of the inscribed disc's critical depth to contact loss,
//! the least force). A fraction of 0 runs
//! [`ContactSolver::peel_punch`] (its [`PEEL_FRACTION`]) and the energy
//! balance ([`ContactSolver::adhesive_branches`]) instead, and prints their
//! pull-offs.
//!
//! Prints one line per contact: step, cells, `F_crit` (N), the depth at
//! which it detaches (m), and where its release rate is largest (m from the
//! axis).

use layered_contact::indenter::Indenter;
#[cfg(doc)]
use layered_contact::solver::PEEL_FRACTION;
use layered_contact::solver::{ContactSolver, Reach, SolverParams, EDGE_WINDOW};
use layered_contact::{Boundary, Grid, Material, Result, Substrate};
use ndarray::Array2;

/// A flat face: a disc of radius `half` (`ratio` 0), a rectangle of
/// half-sides `half` and `ratio * half`, or (`elliptic`) an ellipse of
/// semi-axes `half` and `ratio * half`; turned by `angle`, its centre at
/// `centre` (m), its plane rising by `tilt` (rad) towards `towards`.
struct Face {
    half: f64,
    ratio: f64,
    angle: f64,
    elliptic: bool,
    centre: (f64, f64),
    tilt: f64,
    towards: f64,
}

impl Indenter for Face {
    fn height(&self, x: f64, y: f64) -> f64 {
        let (x, y) = (x - self.centre.0, y - self.centre.1);
        let (s, c) = self.angle.sin_cos();
        let (x, y) = (c * x + s * y, -s * x + c * y);
        let inside = if self.ratio == 0.0 {
            x.hypot(y) <= self.half
        } else if self.elliptic {
            (y / self.half).powi(2) + (x / (self.half * self.ratio)).powi(2) < 1.0
        } else {
            x.abs() <= self.half && y.abs() <= self.half * self.ratio
        };
        if inside {
            let (s, c) = (self.towards - self.angle).sin_cos();
            self.tilt * (c * x + s * y)
        } else {
            f64::INFINITY
        }
    }

    fn bounding_radius(&self) -> f64 {
        let radius = if self.elliptic {
            self.half * self.ratio
        } else {
            self.half * (1.0 + self.ratio * self.ratio).sqrt()
        };
        radius + self.centre.0.hypot(self.centre.1)
    }
}

fn main() -> Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let shape = args.first().map(String::as_str);
    let ratio = match shape {
        Some("square") => 1.0,
        Some("rectangle" | "ellipse") => 2.0,
        _ => 0.0,
    };
    let elliptic = shape == Some("ellipse");
    let cells: usize = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(32);
    let fraction: f64 = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(0.9);
    let degrees: f64 = args.get(3).and_then(|a| a.parse().ok()).unwrap_or(0.0);
    let rubber = Material::new(1e6, 0.48)?;
    let work = 0.05;
    let delta = 1e-4;
    let half = 0.5 * cells as f64 * delta;
    // OFFSET=x,y moves the face's centre by that many cells.
    let offset: Vec<f64> = std::env::var("OFFSET")
        .ok()
        .map(|s| s.split(',').filter_map(|v| v.parse().ok()).collect())
        .unwrap_or_default();
    let face = Face {
        half,
        ratio,
        angle: degrees.to_radians(),
        elliptic,
        centre: match offset[..] {
            [x, y] => (x * delta, y * delta),
            _ => (0.0, 0.0),
        },
        tilt: 0.0,
        towards: 0.0,
    };
    // TILT=rise,degrees tilts a disc's face.
    let tilted: Vec<f64> = std::env::var("TILT")
        .ok()
        .map(|s| s.split(',').filter_map(|v| v.parse().ok()).collect())
        .unwrap_or_default();
    let estar = rubber.contact_modulus();
    let kendall_depth = |radius: f64| (2.0 * std::f64::consts::PI * radius * work / estar).sqrt();
    let face = match tilted[..] {
        [rise, towards] if ratio == 0.0 => Face {
            tilt: rise * kendall_depth(half) / half,
            towards: towards.to_radians(),
            ..face
        },
        _ => face,
    };
    // Even, so that the face lies symmetrically on the cells.
    let n = 2 * (face.bounding_radius() / delta).ceil() as usize + 8;
    // STRETCH scales the cells (the face unchanged): the staircase of
    // another grid.
    let stretch: f64 = std::env::var("STRETCH")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1.0);
    let grid = Grid::square_of_side(n, n as f64 * delta * stretch)?;
    let mut solver = ContactSolver::new(
        &Substrate::half_space(rubber),
        &grid,
        Boundary::Isolated,
        SolverParams::default(),
    )?;
    let mut contact = Array2::from_shape_fn((n, n), |(i, j)| {
        let (x, y) = grid.cell_centre(i, j);
        face.height(x, y).is_finite()
    });
    let per = 1e6 / (cells as f64).powf(1.5);
    if fraction == 0.0 {
        // The library's path (`ContactSolver::peel_punch`, PEEL_FRACTION)
        // and the energy balance's pull-off beside it.
        let path = solver.peel_punch(&face, work)?;
        let peeled = path.pull_off();
        if face.tilt != 0.0 {
            // The exact onset of a punch under force and moment, for the
            // staircase's radius and for the punch's.
            let onset = |radius: f64| {
                2.0 * estar * radius * (2.0 * radius * face.tilt - kendall_depth(radius))
            };
            let staircase = (path.points()[0].contact_area / std::f64::consts::PI).sqrt()
                - layered_contact::solver::EDGE_SHIFT * delta;
            let first = path.points()[0].force;
            println!(
                "tilted disc: onset {:+.3} % (the punch's radius {:+.3} %), pull-off {:+.3} % \
                 over the exact onset ({} steps)",
                100.0 * (first / onset(staircase) - 1.0),
                100.0 * (first / onset(half) - 1.0),
                100.0 * (peeled.force / onset(staircase) - 1.0),
                path.points().len()
            );
            return Ok(());
        }
        if elliptic {
            // The exact onset at the ends of the major axis.
            let a = ratio * half;
            let exact = -2.0 * half * (2.0 * std::f64::consts::PI * estar * work * a).sqrt();
            println!(
                "ellipse: onset {:+.3} %, pull-off {:+.3} % over the exact onset ({} steps)",
                100.0 * (path.points()[0].force / exact - 1.0),
                100.0 * (peeled.force / exact - 1.0),
                path.points().len()
            );
            return Ok(());
        }
        let branches = solver.adhesive_branches(&face, Reach::Depth(1e-6), work, work, &mut ())?;
        let balance = branches.pull_off(f64::INFINITY)?;
        println!(
            "peel_punch {:.6e} N ({:.1} uN / N^1.5, {} steps, {} iterations, onset {:.1}); \
             energy balance {:.6e} N ({:.1})",
            peeled.force,
            -peeled.force * per,
            path.points().len(),
            path.iterations(),
            -path.points()[0].force * per,
            balance.force,
            -balance.force * per
        );
        return Ok(());
    }
    if fraction < 0.0 {
        // The mesh-dependent criterion (Pohrt & Popov 2015) beside it: the
        // face pressed in, then pulled in steps of 1/200 of Kendall's
        // critical depth of the inscribed disc until the contact is lost;
        // its pull-off is the least force.
        let estar = rubber.contact_modulus();
        let step = (2.0 * std::f64::consts::PI * half * work / estar).sqrt() / 200.0;
        let (_, mut warm) =
            solver.solve_depth_hysteretic(&face, 1e-7, work, work, None, &mut ())?;
        let (mut least, mut d, mut steps) = (0.0f64, 1e-7, 0);
        while steps < 4000 {
            d -= step;
            steps += 1;
            let (s, w) =
                solver.solve_depth_hysteretic(&face, d, work, work, Some(&warm), &mut ())?;
            warm = w;
            least = least.min(s.force);
            if s.contact_cells == 0 {
                break;
            }
        }
        println!(
            "mesh criterion {least:.6e} N ({:.1} uN / N^1.5, {steps} steps)",
            -least * per
        );
        return Ok(());
    }
    let depth = -1e-6;
    println!("step,cells,f_crit_n,d_crit_m,x_m,y_m");
    for step in 0..n * n {
        let attached = contact.iter().filter(|c| **c).count();
        if attached < 4 {
            break;
        }
        let edge = solver.edge_release(&face, depth, &contact, EDGE_WINDOW)?;
        let Some((top, (x, y))) = edge.max_release().map(|p| (p.release_rate, p.position)) else {
            break;
        };
        if top <= 0.0 {
            break;
        }
        let scale = (work / top).sqrt();
        println!(
            "{step},{attached},{:.6e},{:.6e},{x:.4e},{y:.4e}",
            edge.force * scale,
            depth * scale
        );
        for p in &edge.points {
            if p.release_rate >= fraction * top {
                contact[[p.cell.0, p.cell.1]] = false;
            }
        }
    }
    Ok(())
}
