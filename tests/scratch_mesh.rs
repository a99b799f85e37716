use layered_contact::scene::{Adhesion, AdhesionMethod, IndenterSpec, Protocol, Scene, SubstrateSpec};
use layered_contact::topography::Amplitude;
use layered_contact::Boundary;

fn rough_film(seed: u64, hysteresis: bool, protocol: Protocol) -> Scene {
    let (cells, spacing) = (16, 2e-5);
    let mut s = Scene {
        boundary: Boundary::Periodic,
        substrate: SubstrateSpec::LayerOnRigidBase { youngs_modulus: 1e6, poisson_ratio: 0.48, thickness: 2e-4 },
        indenter: IndenterSpec::RoughSurface { hurst: 0.8, amplitude: Amplitude::RmsHeight(1e-6), long_cutoff: 2.5e-4, short_cutoff: 4.0 * spacing, seed, cells, spacing },
        adhesion: if hysteresis { Adhesion::Hysteresis { loading: 0.01, unloading: 0.05 } } else { Adhesion::Constant { work_of_adhesion: 0.05 } },
        protocol,
        ..Scene::default()
    };
    s.solver.adhesion_method = AdhesionMethod::MeshCriterion;
    s
}

#[test]
fn scratch() {
    let (mut ok, mut err) = (0, 0);
    for seed in 1..=5 {
        for max_depth in [1e-9, 1e-8, 1e-7, 1e-6, 3e-6] {
            for steps in [1usize, 2, 10] {
                for h in [false, true] {
                    let t = std::time::Instant::now();
                    match rough_film(seed, h, Protocol::Cycle { max_depth, steps }).run(&mut |_| {}) {
                        Ok(c) => { ok += 1; assert!(c.steps.iter().all(|s| s.force.is_finite() && s.depth.is_finite())); println!("{seed} {max_depth} {steps} {h}: {:?} {:.1}s", c.pull_off().map(|p| p.force), t.elapsed().as_secs_f64()); }
                        Err(e) => { err += 1; println!("{seed} {max_depth} {steps} {h}: ERR {e:?}"); }
                    }
                }
            }
        }
    }
    println!("ok {ok} err {err}");
}
