//! `layered-contact`: runs contact scenes from TOML or JSON files.
//!
//! ```text
//! layered-contact run scene.toml -o out/     # curve.csv, fields and stresses as .npy, curve.svg, section.svg
//! layered-contact check scene.toml           # validate; grid and memory
//! mpirun -np 4 layered-contact run scene.toml  # split across MPI ranks (feature mpi)
//! layered-contact reference scene.toml       # exact values where they exist
//! layered-contact paper [--out DIR] [--fine] # the reference experiment
//! ```
//!
//! Errors are printed as sentences (a scene file's mistakes with line,
//! column and key) and end the program with exit status 1.

#[macro_use]
mod say;

mod fit;
mod output;
mod paper;
mod progress;
mod stress_output;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use layered_contact::scene::{Caveat, IndenterSpec, Scene};

/// Contact mechanics of coated elastic bodies: run scenes from files.
#[derive(Parser)]
#[command(name = "layered-contact", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a scene file (TOML, or JSON by its extension) and write its
    /// curve (curve.csv), the fields it asks for (.npy, with x.npy and
    /// y.npy: the cell centres, m) and a plot (curve.svg).
    Run {
        /// The scene file. Height-map paths in it are relative to its folder.
        scene: PathBuf,
        /// Output folder (created if missing).
        #[arg(short, long, default_value = "out")]
        out: PathBuf,
    },
    /// Validate a scene file and print the grid it is solved on and the
    /// memory the solve needs.
    Check {
        /// The scene file.
        scene: PathBuf,
        /// Also print the memory per rank of a run split across this many
        /// MPI ranks.
        #[arg(long)]
        ranks: Option<usize>,
    },
    /// Print the exact values of the scene's results, where the library has
    /// them (axisymmetric flat punch, paraboloid, sphere).
    Reference {
        /// The scene file.
        scene: PathBuf,
    },
    /// Fit the exact model of a tip on a film (modulus, contact point and,
    /// on a retract segment, the work of adhesion) to a measured force
    /// curve; prints the estimates with standard errors and writes
    /// fit.csv.
    Fit(Box<fit::FitArgs>),
    /// Print the JSON Schema of scene files (for editors and validators),
    /// or with --markdown the table of every key.
    Schema {
        /// The key table in Markdown instead.
        #[arg(long)]
        markdown: bool,
    },
    /// Reproduce the reference experiment (Lyashenko, Popov & Borysiuk
    /// 2023): CSV tables, SVG figures and a summary.
    Paper {
        /// Output folder.
        #[arg(long, default_value = "target/paper")]
        out: PathBuf,
        /// Twice the resolution.
        #[arg(long)]
        fine: bool,
    },
}

type Result<T> = std::result::Result<T, Box<dyn std::error::Error + Send + Sync>>;

fn main() -> ExitCode {
    match dispatch(Cli::parse().command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            tell!("error: {error}");
            ExitCode::FAILURE
        }
    }
}

fn dispatch(command: Command) -> Result<()> {
    match command {
        Command::Run { scene, out } => run(&Scene::read(&scene)?, &out),
        Command::Check { scene, ranks } => check(&Scene::read(&scene)?, ranks),
        Command::Reference { scene } => reference(&Scene::read(&scene)?),
        Command::Paper { out, fine } => paper::run(&out, fine),
        Command::Fit(args) => fit::fit(&args),
        Command::Schema { markdown } => {
            if markdown {
                say!("{}", Scene::key_reference().trim_end());
            } else {
                say!("{}", Scene::json_schema());
            }
            Ok(())
        }
    }
}

fn run(scene: &Scene, out: &std::path::Path) -> Result<()> {
    // Under mpirun or srun (with the mpi feature), the scene is solved
    // split across the ranks; rank 0 reports and writes.
    #[cfg(feature = "mpi")]
    if let Some((_universe, ranks)) = mpi_ranks()? {
        if ranks.rank() != 0 {
            let mut solver = scene.distributed_solver(&ranks)?;
            scene.run_on(&mut solver, &mut |_| {})?;
            return Ok(());
        }
        say!("split across {} MPI ranks", ranks.count());
        let mut progress = progress::Progress::new(scene);
        progress.stage("building the kernel");
        let solver = scene.distributed_solver(&ranks)?;
        return run_with(scene, solver, progress, out);
    }
    let mut progress = progress::Progress::new(scene);
    progress.stage("building the kernel");
    let solver = scene.solver()?;
    run_with(scene, solver, progress, out)
}

/// MPI and the ranks of its world when this process was started by an MPI
/// launcher with more than one rank (Open MPI's `mpirun`, or a PMI
/// launcher such as MPICH's Hydra or Slurm's `srun`); `None` otherwise.
#[cfg(feature = "mpi")]
fn mpi_ranks() -> Result<
    Option<(
        mpi::environment::Universe,
        layered_contact::distributed::Ranks,
    )>,
> {
    let launched = ["OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"]
        .iter()
        .any(|name| std::env::var_os(name).is_some());
    if !launched {
        return Ok(None);
    }
    let (universe, _) = mpi::initialize_with_threading(mpi::Threading::Serialized)
        .ok_or("MPI was already initialised")?;
    let ranks = layered_contact::distributed::Ranks::new(universe.world())?;
    if ranks.count() < 2 {
        return Ok(None);
    }
    Ok(Some((universe, ranks)))
}

fn run_with(
    scene: &Scene,
    mut solver: layered_contact::solver::ContactSolver,
    mut progress: progress::Progress,
    out: &std::path::Path,
) -> Result<()> {
    progress.stage("solving");
    // The energy balance builds its family of contact sets before any step:
    // each set is reported as it is solved.
    let family =
        scene.adhesion_method_run() == Some(layered_contact::scene::AdhesionMethod::EnergyBalance);
    let progress = std::cell::RefCell::new(progress);
    let curve = scene.run_observed(
        &mut solver,
        &mut |step| progress.borrow_mut().step(step),
        &mut |info: &layered_contact::solver::IterationInfo| {
            if family {
                progress.borrow_mut().contact_set(info);
            }
        },
    );
    let mut progress = progress.into_inner();
    progress.finish();
    let curve = curve?;
    std::fs::create_dir_all(out).map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    let written = output::write_all(scene, &curve, out)?;
    say!(
        "{} steps on a {} x {} grid of {:.4e} m cells",
        curve.steps.len(),
        curve.grid.rows(),
        curve.grid.columns(),
        curve.grid.spacing()
    );
    if let Some(method) = scene.adhesion_method_run() {
        let how = if scene.solver.adhesion_method == method {
            "as the scene asks"
        } else {
            "the automatic choice"
        };
        say!("adhesion: {} ({how})", method.name());
    }
    for caveat in &curve.caveats {
        say!("caveat: {caveat}");
        if *caveat == Caveat::CohesiveZoneLongAgainstLayer {
            if let Some(s) = scene.zone_scales(&curve)? {
                say!(
                    "  the zone: {} cells, {:.4e} m, {:.2} times the top layer's thickness \
                     ({:.4e} m); the body {:.3} times as stiff at its length as at the peak \
                     contact's radius ({:.4e} m)",
                    s.cells,
                    s.length,
                    s.length / s.layer_thickness,
                    s.layer_thickness,
                    s.modulus_ratio,
                    s.contact_radius
                );
                // The cell shrinks as `cells_across` grows (a height map's
                // grid is its own): the zone of two cells within the
                // layer's thickness from this many.
                if !scene.indenter.is_map() {
                    let across =
                        scene.resolution.cells_across as f64 * s.length / s.layer_thickness;
                    say!(
                        "  cells_across = {} or more brings the zone within the layer's \
                         thickness",
                        across.ceil()
                    );
                }
            }
        }
    }
    if let Some(k) = curve.stiffness() {
        say!("stiffness at the peak: {k:.6e} N/m");
    }
    if let Some(p) = curve.pull_off() {
        say!("pull-off: {:.6e} N at depth {:.6e} m", p.force, p.depth);
    }
    if let Some(result) = &curve.stresses {
        for line in stress_output::summary(&curve.grid, result) {
            say!("{line}");
        }
    }
    // The run stands without its exact values: a reference the closed forms
    // cannot reach (a contact beyond the radii they tabulate) is said, not
    // turned into a failed run.
    let references = match scene.reference() {
        Ok(references) => references,
        Err(e) => {
            say!("no exact values to compare with: {e}");
            Vec::new()
        }
    };
    for r in references {
        if let Some(bem) = r.quantity.of(&curve) {
            let error = if r.value == 0.0 {
                format!("difference {:.3e}", bem - r.value)
            } else {
                format!("{:+.3} %", 100.0 * (bem / r.value - 1.0))
            };
            say!(
                "{}: {bem:.6e} (exact {:.6e}, {error}; {})",
                r.quantity.name(),
                r.value,
                r.source
            );
        }
    }
    for path in written {
        say!("wrote {}", path.display());
    }
    Ok(())
}

/// What `check --ranks` adds per rank for the process and its MPI library,
/// and per cell of the rank's rows for what its count leaves out.
const PROCESS_BYTES: usize = 64 << 20;
const SLACK_BYTES_PER_CELL: usize = 8;

fn check(scene: &Scene, ranks: Option<usize>) -> Result<()> {
    scene.validate()?;
    let grid = scene.grid()?;
    let (lx, ly) = grid.extent();
    let bytes = layered_contact::kernel::memory_estimate(&grid, scene.boundary);
    say!("scene is valid");
    say!(
        "grid: {} x {} cells of {:.4e} m ({lx:.4e} m x {ly:.4e} m), {}",
        grid.rows(),
        grid.columns(),
        grid.spacing(),
        match scene.boundary {
            layered_contact::Boundary::Isolated => "isolated",
            layered_contact::Boundary::Periodic => "periodic",
        }
    );
    say!("memory: about {:.1} MB for the solve", bytes as f64 / 1e6);
    if let Some(ranks) = ranks {
        let mut per_rank =
            layered_contact::kernel::distributed_memory_estimate(&grid, scene.boundary, ranks);
        // The process itself, its MPI library and what the count above
        // leaves out (the allocator's slack, the coarse grids' share):
        // measured about 29 MB and 3.6 bytes per cell of the rank's rows
        // on this project's split runs (BENCHMARKS.md), allowed for with
        // a margin.
        per_rank += PROCESS_BYTES + SLACK_BYTES_PER_CELL * grid.len().div_ceil(ranks);
        // Every rank reads a text height map whole (its bytes, the values
        // and the map: 24 bytes per cell); a rank reads its own rows of a
        // `.npy` map, and synthesises its share of a rough surface, and
        // keeps them (8 bytes per cell of its rows; the synthesis's 24
        // come and go before the solver's vectors are allocated).
        let own_rows = match &scene.indenter {
            IndenterSpec::HeightMap { path, .. } => path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("npy")),
            IndenterSpec::RoughSurface { .. } => true,
            _ => false,
        };
        if own_rows {
            per_rank += 8 * grid.len().div_ceil(ranks);
        } else if matches!(scene.indenter, IndenterSpec::HeightMap { .. }) {
            per_rank += 24 * grid.len();
        }
        say!(
            "memory split across {ranks} MPI ranks: about {:.1} MB per rank",
            per_rank as f64 / 1e6
        );
    }
    if let layered_contact::Substrate::Stack(stack) = scene.substrate.build()? {
        // doc::multilayer: about 0.033 L^2 s on 2 cores for an isolated grid.
        let layers = stack.layers().len() as f64;
        say!(
            "kernel: a stack of {layers} layers builds in about {:.0} s on 2 cores \
             (it grows like the square of the layer count, see doc::multilayer)",
            (0.033 * layers * layers).max(1.0)
        );
    }
    Ok(())
}

fn reference(scene: &Scene) -> Result<()> {
    let references = scene.reference()?;
    if references.is_empty() {
        say!(
            "no exact values for this scene (they exist for an untilted flat punch, paraboloid, \
             sphere or cone on an isolated grid, whose contact stays within 50 top-layer \
             thicknesses and, for a sphere, within 0.95 of its radius; without adhesion only \
             where the punch's bonded face, or the tip's disc of contact, presses everywhere: \
             a stiff layer on a far softer base lifts off the middle, and the contact is a ring)"
        );
    }
    for r in references {
        say!("{}: {:.9e} ({})", r.quantity.name(), r.value, r.source);
    }
    Ok(())
}
