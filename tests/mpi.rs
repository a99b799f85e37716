//! The solver split across MPI ranks against the serial solver, on 2 and 4
//! ranks (`cargo test --release --features mpi --test mpi`).
//!
//! Run as a plain test, this program starts itself under `mpirun` with 2
//! and with 4 processes; under `mpirun` each rank solves every case twice,
//! serially (the whole grid) and split across the ranks, and compares its
//! own rows. Both solve to a relative tolerance of 1e-14, so they agree to
//! far below the asserted 1e-12: they take the same steps, and differ only
//! in the order in which sums over the grid are added.

use std::process::{Command, ExitCode};

use layered_contact::distributed::Ranks;
use layered_contact::indenter::{HeightMap, Indenter, Sphere};
use layered_contact::solver::{ContactSolver, Fields, SolverParams};
use layered_contact::topography::{Amplitude, SelfAffine};
use layered_contact::{Boundary, Grid, Material, Substrate};

/// The largest relative difference asserted between the serial and the
/// split solves.
const AGREEMENT: f64 = 1e-12;

fn main() -> ExitCode {
    if std::env::var_os("LAYERED_CONTACT_MPI_RANK").is_some() {
        return match ranks_main() {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("{e}");
                ExitCode::FAILURE
            }
        };
    }
    let exe = std::env::current_exe().expect("the test's own path");
    for np in ["2", "4"] {
        let status = Command::new("mpirun")
            .args(["-np", np])
            .arg(&exe)
            .env("LAYERED_CONTACT_MPI_RANK", "1")
            // Open MPI: allow root (CI containers) and more ranks than cores.
            .env("OMPI_ALLOW_RUN_AS_ROOT", "1")
            .env("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
            .env("OMPI_MCA_rmaps_base_oversubscribe", "1")
            .status();
        match status {
            Ok(s) if s.success() => println!("mpirun -np {np}: ok"),
            other => {
                eprintln!("mpirun -np {np} failed: {other:?}");
                return ExitCode::FAILURE;
            }
        }
    }
    ExitCode::SUCCESS
}

/// One case: a body, a grid, an indenter and loads.
struct Case {
    name: &'static str,
    body: Substrate,
    grid: Grid,
    boundary: Boundary,
    indenter: Box<dyn Indenter>,
    /// Loads in order (each solve warm-started from the last): depths
    /// (m) if `force` is false, forces (N) if true.
    loads: Vec<f64>,
    force: bool,
}

fn rough(grid: &Grid, side: f64, seed: u64) -> Result<HeightMap, layered_contact::Error> {
    SelfAffine {
        hurst: 0.8,
        amplitude: Amplitude::RmsSlope(0.1),
        long_cutoff: 0.25 * side,
        short_cutoff: 4.0 * grid.spacing(),
        seed,
    }
    .indenter(grid)
}

fn cases() -> Result<Vec<Case>, layered_contact::Error> {
    let side = 1e-3;
    let film = Substrate::layer_on_rigid_base(Material::new(1e6, 0.49)?, 1e-4)?;
    let half_space = Substrate::half_space(Material::new(1e6, 0.3)?);
    let periodic = Grid::square_of_side(128, side)?;
    let odd = Grid::new(130, 72, side / 128.0)?;
    let sphere_grid = Grid::new(128, 128, 2e-5)?;
    Ok(vec![
        Case {
            name: "rough film on glass, periodic 128 x 128, force control",
            body: film.clone(),
            grid: periodic,
            boundary: Boundary::Periodic,
            indenter: Box::new(rough(&periodic, side, 1)?),
            loads: vec![5e3 * side * side, 2e4 * side * side],
            force: true,
        },
        Case {
            name: "rough half-space, isolated 130 x 72 (odd coarse rows), depth control",
            body: half_space,
            grid: odd,
            boundary: Boundary::Isolated,
            indenter: Box::new(rough(&odd, side, 2)?),
            loads: vec![0.5e-6, 1e-6],
            force: false,
        },
        Case {
            name: "sphere on a film on glass, isolated 128 x 128, depth control",
            body: film,
            grid: sphere_grid,
            boundary: Boundary::Isolated,
            indenter: Box::new(Sphere::new(5e-3)?),
            loads: vec![2e-6, 4e-6],
            force: false,
        },
    ])
}

fn ranks_main() -> Result<(), String> {
    let (universe, _) = mpi::initialize_with_threading(mpi::Threading::Serialized)
        .ok_or("MPI is already initialised")?;
    let ranks = Ranks::new(universe.world()).map_err(|e| e.to_string())?;
    let params = SolverParams {
        tolerance: 1e-14,
        fields: Fields {
            pressure: true,
            displacement: false,
            gap: true,
        },
        ..SolverParams::default()
    };
    let text = |e: layered_contact::Error| e.to_string();
    let mut failures = Vec::new();
    for case in cases().map_err(text)? {
        let mut serial =
            ContactSolver::new(&case.body, &case.grid, case.boundary, params).map_err(text)?;
        let mut split =
            ContactSolver::distributed(&case.body, &case.grid, case.boundary, params, &ranks)
                .map_err(text)?;
        let rows = split.local_rows();
        let columns = case.grid.columns();
        let (mut warm_serial, mut warm_split) = (None, None);
        for &load in &case.loads {
            let (a, wa) = if case.force {
                serial.solve_force(&*case.indenter, load, warm_serial.as_ref(), &mut ())
            } else {
                serial.solve_depth(&*case.indenter, load, warm_serial.as_ref(), &mut ())
            }
            .map_err(text)?;
            let (b, wb) = if case.force {
                split.solve_force(&*case.indenter, load, warm_split.as_ref(), &mut ())
            } else {
                split.solve_depth(&*case.indenter, load, warm_split.as_ref(), &mut ())
            }
            .map_err(text)?;
            let relative = |x: f64, y: f64| (x - y).abs() / x.abs().max(f64::MIN_POSITIVE);
            let p = a.pressure.as_ref().ok_or("serial pressure")?;
            let q = b.pressure.as_ref().ok_or("split pressure")?;
            let largest = p.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            let own = p.as_slice().ok_or("pressure layout")?
                [rows.start * columns..rows.end * columns]
                .iter()
                .zip(q.iter());
            // This rank's rows; every rank checks its own.
            let worst = own.fold(0.0_f64, |m, (x, y)| m.max((x - y).abs())) / largest;
            let errors = [
                ("force", relative(a.force, b.force)),
                ("depth", relative(a.depth, b.depth)),
                ("contact area", relative(a.contact_area, b.contact_area)),
                (
                    "pressure (largest difference over the largest pressure)",
                    worst,
                ),
            ];
            if ranks.rank() == 0 {
                println!(
                    "{} ranks, {}, load {load:e}: F = {:.12e} N, {} iterations (+{} coarse) \
                     serial, {} (+{}) split; differences {:?}",
                    ranks.count(),
                    case.name,
                    b.force,
                    a.iterations,
                    a.coarse_iterations,
                    b.iterations,
                    b.coarse_iterations,
                    errors.map(|(_, e)| e)
                );
            }
            // Failures are collected, not returned at once: the other
            // ranks go on to the next solve, which needs this one too.
            for (what, error) in errors {
                if error > AGREEMENT || error.is_nan() {
                    failures.push(format!(
                        "rank {}: {}: {what} differs by {error:e} (asserted below {AGREEMENT:e})",
                        ranks.rank(),
                        case.name
                    ));
                }
            }
            warm_serial = Some(wa);
            warm_split = Some(wb);
        }
    }
    if failures.is_empty() {
        Ok(())
    } else {
        Err(failures.join("\n"))
    }
}
