//! Temporary: time and check one paper sphere scene.
#[path = "paper/experiment.rs"]
mod experiment;
use std::time::Instant;
fn main() {
    let a: Vec<f64> = std::env::args().skip(1).map(|s| s.parse().unwrap()).collect();
    if a.len() == 5 { punch(a[0], a[1], a[2] as usize, a[3] > 0.0); return; }
    let (r, h, w1, cells) = (a[0], a[1], a[2], a[3] as usize);
    let scene = experiment::sphere_scene(r, h, w1, 0.5e-3, 20, cells);
    let g = scene.grid().unwrap();
    let t = Instant::now();
    let curve = scene.run(&mut |_| {}).unwrap();
    let exact = experiment::exact_sphere_pull_off(r, h, w1).unwrap();
    let po = experiment::pull_off(&curve);
    let its: usize = curve.steps.iter().map(|s| s.iterations).sum();
    println!("R={r} h={h} w1={w1} grid={}x{} dx={:.3e} pull-off {:.5e} exact {:.5e} err {:+.3}% time {:.2}s its {its} steps {}",
        g.rows(), g.columns(), g.spacing(), po, exact, 100.0*(po/exact-1.0), t.elapsed().as_secs_f64(), curve.steps.len());
}
#[allow(dead_code)]
fn punch(h: f64, d: f64, cells: usize, mesh: bool) {
    let mut scene = experiment::punch_scene(h, d, 0.2e-3, 20);
    scene.resolution.cells_across = cells;
    if mesh { scene.solver.adhesion_method = layered_contact::scene::AdhesionMethod::MeshCriterion; }
    let t = Instant::now();
    let curve = scene.run(&mut |_| {}).unwrap();
    let exact = experiment::exact_punch_pull_off(h, d, experiment::DGAMMA_PUNCH).unwrap();
    let po = experiment::pull_off(&curve);
    let its: usize = curve.steps.iter().map(|s| s.iterations).sum();
    println!("punch h={h} D={d} cells={cells} mesh={mesh} pull-off {:.5e} exact {:.5e} err {:+.3}% time {:.2}s its {its}", po, exact, 100.0*(po/exact-1.0), t.elapsed().as_secs_f64());
}
