//! Progress on standard error: a bar on a terminal, plain lines otherwise
//! (logs of batch jobs).

use std::io::IsTerminal;

use indicatif::{ProgressBar, ProgressStyle};
use layered_contact::scene::{Protocol, Scene, Step};
use layered_contact::solver::IterationInfo;

/// Reports the stages and steps of one scene.
pub struct Progress {
    bar: Option<ProgressBar>,
    steps: usize,
    started: std::time::Instant,
}

impl Progress {
    /// A bar sized by the protocol's expected steps (loading and unloading)
    /// when standard error is a terminal.
    pub fn new(scene: &Scene) -> Self {
        let expected = match scene.protocol {
            Protocol::Depth { .. } | Protocol::Force { .. } => 1,
            Protocol::Cycle { steps, .. } | Protocol::ForceCycle { steps, .. } => 2 * steps + 2,
        };
        let bar = std::io::stderr().is_terminal().then(|| {
            let bar = ProgressBar::new(expected as u64);
            if let Ok(style) =
                ProgressStyle::with_template("{elapsed_precise} [{bar:30}] {pos}/~{len} {msg}")
            {
                bar.set_style(style);
            }
            bar
        });
        Progress {
            bar,
            steps: 0,
            started: std::time::Instant::now(),
        }
    }

    /// A new stage of the run.
    pub fn stage(&mut self, what: &str) {
        match &self.bar {
            Some(bar) => bar.set_message(what.to_string()),
            None => tell!("[{:8.1} s] {what}", self.started.elapsed().as_secs_f64()),
        }
    }

    /// One contact set of the energy balance's family solved (before the
    /// steps, which follow all at once).
    pub fn contact_set(&mut self, info: &IterationInfo) {
        match &self.bar {
            Some(bar) => bar.set_message(format!(
                "adhesive branches: contact set {} of {} cells",
                info.iteration, info.contact_cells
            )),
            None => tell!(
                "[{:8.1} s] adhesive branches: contact set {}, {} cells, residual {:.1e}",
                self.started.elapsed().as_secs_f64(),
                info.iteration,
                info.contact_cells,
                info.residual
            ),
        }
    }

    /// One step done.
    pub fn step(&mut self, step: &Step) {
        self.steps += 1;
        match &self.bar {
            Some(bar) => {
                if bar.length().is_some_and(|len| self.steps as u64 > len) {
                    bar.set_length(self.steps as u64);
                }
                bar.set_position(self.steps as u64);
                bar.set_message(format!(
                    "{} d = {:.3e} m, F = {:.3e} N",
                    step.phase.name(),
                    step.depth,
                    step.force
                ));
            }
            None => tell!(
                "[{:8.1} s] step {}: {}, depth {:.6e} m, force {:.6e} N, contact radius {:.6e} m, {} iterations",
                self.started.elapsed().as_secs_f64(),
                self.steps,
                step.phase.name(),
                step.depth,
                step.force,
                step.contact_radius,
                step.iterations
            ),
        }
    }

    /// The run is over.
    pub fn finish(&mut self) {
        match &self.bar {
            Some(bar) => bar.finish_and_clear(),
            None => tell!(
                "[{:8.1} s] done, {} steps",
                self.started.elapsed().as_secs_f64(),
                self.steps
            ),
        }
    }
}
