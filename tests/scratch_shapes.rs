use layered_contact::scene::{Adhesion, IndenterSpec, Protocol, Resolution, Scene, SubstrateSpec, Tilt};

#[test]
fn scratch() {
    let (mut ok, mut err) = (0, 0);
    let substrates = [
        SubstrateSpec::HalfSpace { youngs_modulus: 1e6, poisson_ratio: 0.48 },
        SubstrateSpec::LayerOnRigidBase { youngs_modulus: 1e6, poisson_ratio: 0.49, thickness: 2e-4 },
    ];
    let indenters = [
        IndenterSpec::Paraboloid { radius: 1e-2 },
        IndenterSpec::Sphere { radius: 1e-3 },
        IndenterSpec::Cone { half_angle: 1.3, base_radius: 1e-3 },
        IndenterSpec::FlatPunch { radius: 2e-4 },
    ];
    for substrate in &substrates {
        for indenter in &indenters {
            for tilt in [0.0, 0.01, 0.05] {
                for protocol in [
                    Protocol::Cycle { max_depth: 2e-6, steps: 4 },
                    Protocol::Cycle { max_depth: 2e-8, steps: 2 },
                    Protocol::ForceCycle { max_force: 1e-3, steps: 3 },
                    Protocol::ForceCycle { max_force: 1e-7, steps: 2 },
                ] {
                    for cells in [8usize, 16] {
                        let scene = Scene {
                            substrate: substrate.clone(),
                            indenter: indenter.clone(),
                            tilt: (tilt > 0.0).then_some(Tilt { angle_y: tilt, angle_x: 0.3 * tilt }),
                            adhesion: Adhesion::Constant { work_of_adhesion: 0.05 },
                            protocol,
                            resolution: Resolution { cells_across: cells, margin: 0.5 },
                            ..Scene::default()
                        };
                        let t = std::time::Instant::now();
                        let label = format!("{substrate:?} {indenter:?} {tilt} {protocol:?} {cells}");
                        match scene.run(&mut |_| {}) {
                            Ok(c) => { ok += 1; assert!(c.steps.iter().all(|s| s.force.is_finite() && s.depth.is_finite())); println!("OK {label}: {:?} {:?} {:.1}s", c.pull_off().map(|p| p.force), c.caveats, t.elapsed().as_secs_f64()); }
                            Err(e) => { err += 1; println!("ERR {label}: {e:?} {:.1}s", t.elapsed().as_secs_f64()); }
                        }
                    }
                }
            }
        }
    }
    println!("ok {ok} err {err}");
}
