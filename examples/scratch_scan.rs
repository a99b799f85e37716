use layered_contact::analytic::Axisymmetric;
use layered_contact::scene::*;
fn main() -> layered_contact::Result<()> {
    let a = 3.5e-3;
    for nu in [0.3, 0.48] {
        for ah in [0.0] {
            let substrate = SubstrateSpec::HalfSpace {
                youngs_modulus: 0.324e6,
                poisson_ratio: nu,
            };
            let body = substrate.build()?;
            let exact = Axisymmetric::up_to_contact_radius(&body, a)?;
            let punch = exact.flat_punch(a)?;
            let r = 2.0 * std::f64::consts::PI * a * a * punch.energy_release_rate(1.0)
                / punch.stiffness();
            let mut line = format!("nu {nu} a/h {ah}: r {r:.3}");
            for cells in [16usize, 32, 64, 128] {
                for method in [AdhesionMethod::EnergyBalance, AdhesionMethod::CohesiveZone] {
                    let scene = Scene {
                        substrate: substrate.clone(),
                        indenter: IndenterSpec::FlatPunch { radius: a },
                        adhesion: Adhesion::Hysteresis {
                            loading: 0.0175,
                            unloading: 0.326,
                        },
                        protocol: Protocol::Cycle {
                            max_depth: 2e-5,
                            steps: 4,
                        },
                        resolution: Resolution {
                            cells_across: cells,
                            margin: 0.0,
                        },
                        solver: SolverSettings {
                            adhesion_method: method,
                            ..Default::default()
                        },
                        ..Scene::default()
                    };
                    let reference = scene
                        .reference()?
                        .into_iter()
                        .find(|r| r.quantity == Quantity::PullOffForce)
                        .map(|r| r.value);
                    let e = match (reference, scene.run(&mut |_| {})) {
                        (Some(x), Ok(c)) => format!(
                            "{:+.3}",
                            100.0 * (c.pull_off().map_or(f64::NAN, |p| p.force) / x - 1.0)
                        ),
                        (_, Err(e)) => format!(
                            "ERR:{}",
                            format!("{e:?}").chars().take(12).collect::<String>()
                        ),
                        _ => "-".into(),
                    };
                    line += &format!(
                        " | {cells} {} {e}",
                        if method == AdhesionMethod::EnergyBalance {
                            "EB"
                        } else {
                            "CZ"
                        }
                    );
                }
            }
            println!("{line}");
        }
    }
    Ok(())
}
