//! Random axisymmetric scenes against their exact values: an untilted flat
//! punch, paraboloid, sphere or cone, with or without adhesion (one work of
//! adhesion or hysteresis), on every kind of body (half-space, bonded or
//! resting layers on rigid or elastic bases, stacks of two or three layers),
//! moduli and thicknesses over decades, Poisson's ratios up to 0.5, driven
//! through a depth cycle at 16 cells across, and compared with
//! [`Scene::reference`] (the exact axisymmetric solutions). Every case must
//! end in a curve within [`TOLERANCE`] of each exact force and
//! [`RADIUS_TOLERANCE`] of each exact contact radius, or in a typed error
//! that names a limit of the method (not a failed iteration).
//!
//! A sweep of this kind, run through the tool, found a warm start that
//! stalled (and, deeper, returned a force 1.6e4 times too large) where a
//! cycle unloads to a hair's breadth of first contact
//! (`tests/hard_cases.rs`, `warm_starts_far_above_the_new_depth`). At
//! seed 11 it found a punch whose receding contact snapped onto a disc of
//! 12 cells (a pull-off 78 % beyond the exact one) and a wide sphere on a
//! stack of thin layers 12 % under its exact peak force at any
//! resolution (`tests/scene_reference.rs`).
//!
//! Seeds 13 and 17 (200 cases each, 2026-11-29; measured in BENCHMARKS.md,
//! "Slow scenes of the reference sweep") each draw a scene that
//! passes the 60 s bound of a case, slow rather than wrong: a sphere on an
//! incompressible layer resting on a base about a thousand times stiffer,
//! whose pull-off contact is 44 (seed 17) and 53 (seed 13) times narrower
//! than its peak's. Sized for 16 cells across the pull-off contact, the
//! grids are 1080 and 1296 cells across, and the energy balance solves
//! about 140 sets of its family there (two clamped solves each). Seed 19
//! draws one more of the kind (a paraboloid on a 1.7 kPa layer resting on
//! a nearly incompressible base 488 times stiffer, 672 cells across). All
//! three come within 0.07 % of their exact values. Since 2026-11-30 the
//! family's smaller sets are solved on windows of the grid around them
//! (BENCHMARKS.md, "The family on windows of the grid"): seed 17's scene
//! takes about a tenth of the time it took, but seeds 13 and 17 still pass
//! the bound at one thread. Seed 23 ran 117 cases without a failure or a
//! slow one (the worst at 0.59 of its tolerance) before it was stopped.
//!
//! With `LAYERED_CONTACT_REFERENCE_METHOD=cohesive_zone` the adhesive
//! scenes go through the cohesive zone (the method of every shape that is
//! not axisymmetric) against the same exact values. Its first cases
//! (seed 7, 2026-12-02) found a sticky flat punch pressed a few
//! micrometres ended in `NoConvergence` 4096 loading depths above the
//! surface (its pull-off at 50000), and a cone on a stiff coating over a
//! base 1350 times softer 36 % weak at the pull-off and, with hysteresis,
//! 14 % short at the peak, silently (`tests/scene_tilted_punch.rs`,
//! `tests/scene_cone.rs`). On a stiff layer over a base a hundred to
//! thousands of times softer (seeds 7 and 11) the zone's first cold solve
//! did not converge (`NoConvergence` after 2000 rounds); both are fixed
//! (`tests/scene_cohesive.rs`; BENCHMARKS.md, "A stiff film over a far
//! softer base"), but seed 7's sixth case (a film 4700 times stiffer than
//! its base, 196^2 cells) still takes about four minutes, past the 60 s
//! bound: slow, not wrong. Seed 11 then passes its 60 cases (the worst at
//! 0.95 of its tolerance, a contact radius). Seed 13's first case was a
//! silent wrong answer: a paraboloid on a stiff plate over a layer 370
//! times softer, peak force -69 % and pull-off +114 % off with only the
//! caveat of a zone long against the layer; the zone's law now takes the
//! body's modulus at the zone's wavelengths
//! (`tests/scene_cohesive_soft_below.rs`; BENCHMARKS.md, "The zone's
//! modulus"), and seed 13 passed its first 25 cases (3 refused) and
//! stopped at its 26th: a sphere (R 97 mm, 0.32 J/m^2, on a 5.9 kPa
//! half-space) whose peak contact radius through the zone, read from the
//! closed cells, was 10.3, 6.7 and 3.8 % short at 16, 32 and 64 cells
//! across (most of the zone inside the JKR edge). Since 2026-12-03 a
//! cohesive contact's area is its equivalent crack's (BENCHMARKS.md, "The
//! cohesive contact's area"): +2.1 % at 16, and seed 13 passes its 40
//! cases (the worst at 0.85 of its tolerance, 3 refused), seeds 11 and 19
//! theirs (0.78 and 0.92). The forces were within 1.6 % at 32.
//! `LAYERED_CONTACT_REFERENCE_PRINT` prints every case's
//! scene, not only the failing ones'.
//!
//! `cargo test --release --test reference_sweep` runs a small seeded budget;
//! `LAYERED_CONTACT_REFERENCE_CASES=2000` a large one, and
//! `LAYERED_CONTACT_REFERENCE_SEED` draws other scenes (see
//! `doc::reliability`). `LAYERED_CONTACT_CASE_SECONDS=400` lets the slow
//! classes above finish instead of stopping the sweep: so bounded, the
//! energy balance's seeds 80, 83, 85, 89 and 93 and the cohesive zone's 79
//! and 106, each stopped at 60 s before, pass their 40 cases
//! (BENCHMARKS.md, "The zone stiffer than the contact").

#![cfg(feature = "serde")]

mod common;

use common::bounded_case;
use layered_contact::scene::{Caveat, Quantity, Scene};
use layered_contact::Error;
use proptest::prelude::*;

/// The largest relative error allowed against an exact force (or
/// stiffness) at 16 cells across. The worst of 300 cases
/// (`LAYERED_CONTACT_REFERENCE_CASES=300`, 2026-11-29): peak forces and
/// stiffnesses 3.05 %, pull-off forces 3.14 % (the staircase of 16 cells);
/// the failures this sweep is for were off by 9 % to orders of magnitude.
const TOLERANCE: f64 = 0.05;

/// The same for the contact radius (of equal area; the worst of the 300
/// cases 2.9 %), compared only where the layers' moduli are within
/// [`RADIUS_CONTRAST`] of each other. On a
/// stiff layer over a far softer base the gap opens so slowly at the edge
/// that the staircase's area converges late: at `E2/E1` = 3e-4 a
/// paraboloid's radius 6.2, 2.8, 0.75, 0.18 % off at 16, 32, 64, 128 cells
/// across, a sphere's 16.3, 6.2, 2.1 % at 16, 32, 64 (33 % at 16 with `nu`
/// = 0.45), their forces within 0.4 % at 16.
const RADIUS_TOLERANCE: f64 = 0.06;

/// The relative error allowed against an exact force for a curve that
/// carries `caveat` (a known limit of the method, reported with the
/// curve), instead of [`TOLERANCE`]: the worst the caveat quotes at 16
/// cells across, with a margin. Such a case is not a silent wrong answer,
/// but one beyond what its caveat says still fails. Radii get the same
/// widening. Before 2026-12-03 (twenty-sixth session) the sweep did not
/// read the caveats and stopped at the first flagged case of seeds 53, 56
/// and 60.
fn caveat_tolerance(caveat: &Caveat) -> f64 {
    match caveat {
        // -26.5 to +11.7 % at 16 cells over the sweeps' seeds 11, 37 and 50
        // to 69 (BENCHMARKS.md, "The loading branch under hysteresis").
        Caveat::CohesivePinnedPullOff => 0.3,
        // Alone: at most 11.3 % at 16 cells over the sweeps' seeds 51, 53,
        // 56, 60, 71, 75, 77 and 80 to 92 (BENCHMARKS.md, "The zone stiffer
        // than the contact").
        Caveat::CohesiveZoneLongAgainstLayer => 0.15,
        // +40 % at 16 cells, a zone 2.9 times the layer's thickness over a
        // base 3850 times softer (seed 74; BENCHMARKS.md, "Seeds 74 to 85").
        Caveat::CohesiveZoneStifferThanContact => 0.5,
        // 0.9 to 25 % weak (BENCHMARKS.md, "The cohesive zone on contacts it
        // spans").
        Caveat::CohesiveZoneSpansContact => 0.3,
        // +4.9 % at 16 cells (a punch on a plate over a 190 Pa base;
        // BENCHMARKS.md, "Seeds 156, 159 and 162 settled").
        Caveat::EnergyBalanceFlatStiffness => 0.1,
        _ => TOLERANCE,
    }
}

/// The largest ratio of two moduli of a body (layers and base) whose
/// contact radius [`sweep`] compares.
const RADIUS_CONTRAST: f64 = 100.0;

fn cases() -> u32 {
    common::env_number("LAYERED_CONTACT_REFERENCE_CASES", 12)
}

/// The longest a failing sweep spends shrinking its case, ms (proptest's
/// default has no bound): a case that passes the 60 s bound of
/// `bounded_case` costs a minute at each shrinking step: seed 74's slow
/// scene was tried five more times before its run ended and seed 78's
/// was still shrinking when it was stopped (2026-12-03). The first failing
/// case's scene is printed, whole, when it fails.
const MAX_SHRINK_MS: u32 = 300_000;

/// The sweep's seed: `LAYERED_CONTACT_REFERENCE_SEED` (default 7, the seed
/// `cargo test` runs), so that a large run can draw other scenes.
fn seed() -> u64 {
    common::env_number("LAYERED_CONTACT_REFERENCE_SEED", 7)
}

/// The adhesion method the sweep asks of its adhesive scenes:
/// `LAYERED_CONTACT_REFERENCE_METHOD` (`auto` unless set, the scene's
/// own choice: the energy balance for these untilted scenes), so that a
/// large run can hold the cohesive zone (the method of every other shape)
/// to the same exact values on every kind of body.
fn method() -> String {
    common::env_number("LAYERED_CONTACT_REFERENCE_METHOD", "auto".to_string())
}

/// `10^x`.
fn decade(x: f64) -> f64 {
    10f64.powf(x)
}

const POISSON: [f64; 7] = [0.0, 0.2, 0.3, 0.45, 0.49, 0.4999, 0.5];

/// One scene as TOML text, from the drawn numbers.
#[allow(clippy::too_many_arguments)]
fn scene_text(
    body: usize,
    indenter: usize,
    adhesion: usize,
    (modulus, ratio, base_ratio): (f64, usize, usize),
    (radius, depth, thickness, contrast): (f64, f64, f64, f64),
    (second, third, work, hysteresis): (f64, f64, f64, f64),
) -> (String, f64) {
    let (e1, nu1, nu2) = (decade(modulus), POISSON[ratio % 7], POISSON[base_ratio % 7]);
    let kind = ["sphere", "paraboloid", "flat_punch", "cone"][indenter % 4];
    let r = decade(radius);
    // A cone's half-angle, 0.5 to 1.4 rad (29 to 80 degrees), and the
    // slope of its face; its base radius is `r`.
    let half_angle = 0.5 + 0.225 * (radius + 5.0);
    let slope = 1.0 / half_angle.tan();
    // The contact radius: the punch's, Sneddon's `2 d / (pi s)` for a cone
    // (at most 0.19 of its base), or about sqrt(R d) for a curve.
    let (d, a) = match kind {
        "flat_punch" => (r * decade(depth - 3.0), r),
        "cone" => {
            let d = r * decade(depth);
            (d, 2.0 * d / (std::f64::consts::PI * slope))
        }
        _ => {
            let d = r * decade(depth);
            (d, (r * d).sqrt())
        }
    };
    let h = a * decade(thickness);
    let e2 = e1 * decade(contrast);
    // The largest ratio of the body's moduli.
    let mut moduli = vec![e1];
    let substrate = match body % 7 {
        0 => format!("kind = \"half_space\"\nyoungs_modulus = {e1:e}\npoisson_ratio = {nu1}\n"),
        1 | 2 => format!(
            "kind = \"{}\"\nyoungs_modulus = {e1:e}\npoisson_ratio = {nu1}\nthickness = {h:e}\n",
            ["layer_on_rigid_base", "layer_resting_on_rigid_base"][body % 7 - 1]
        ),
        3 | 4 => {
            moduli.push(e2);
            format!(
                "kind = \"{}\"\nyoungs_modulus = {e1:e}\npoisson_ratio = {nu1}\nthickness = {h:e}\n\
                 base_youngs_modulus = {e2:e}\nbase_poisson_ratio = {nu2}\n",
                ["layer_on_elastic_base", "layer_resting_on_elastic_base"][body % 7 - 3]
            )
        }
        k => {
            let layer = |e: f64, nu: f64, t: f64| {
                format!("{{ youngs_modulus = {e:e}, poisson_ratio = {nu}, thickness = {t:e} }}")
            };
            let mut layers = vec![
                layer(e1, nu1, h),
                layer(e1 * decade(second), nu2, h * decade(second / 6.0)),
            ];
            moduli.push(e1 * decade(second));
            if third > 0.0 {
                layers.push(layer(e1 * decade(-third), nu1, h * decade(third / 6.0)));
                moduli.push(e1 * decade(-third));
            }
            let base = if k == 6 {
                moduli.push(e2);
                format!("base = {{ youngs_modulus = {e2:e}, poisson_ratio = {nu2} }}\n")
            } else {
                String::new()
            };
            format!(
                "kind = \"stack\"\nlayers = [ {} ]\n{base}",
                layers.join(", ")
            )
        }
    };
    // The work of adhesion in units of `E1 a (a/R)^2`, so that a curved
    // indenter's JKR pull-off contact is a fifth to once its peak contact
    // (`(R^2 w / E*)^(1/3)`): a far smaller one is resolved by its own 16
    // cells, a grid of hundreds across the peak contact (minutes a case).
    // A cone's (`18 w / (pi E* s^2)`, Maugis & Barquins 1981) is linear in
    // `w`: its work spans a third of the decades, in units of `0.23 E1 a
    // s^2` (a fifth to once the peak contact too). Its jump-off contact
    // under displacement control is a ninth of that, and the grid resolves
    // it by 7.2 cells: up to about 650 cells across on a half-space, and
    // 1620 to 1680 on layers that shrink it further (seeds 80, 83 and 85
    // of the energy balance; 83 and 85 alone: 148 and 83 s at one thread,
    // within 0.02 %; BENCHMARKS.md, "Seeds 74 to 85").
    let w = match kind {
        "flat_punch" => e1 * a * decade(work),
        "cone" => 0.23 * e1 * a * slope * slope * decade(work / 3.0),
        _ => e1 * a * (a / r).powi(2) * decade(work),
    };
    let adhesion = match adhesion % 3 {
        0 => String::new(),
        1 => format!("[adhesion]\nkind = \"constant\"\nwork_of_adhesion = {w:e}\n"),
        _ => format!(
            "[adhesion]\nkind = \"hysteresis\"\nloading = {:e}\nunloading = {w:e}\n",
            w * decade(-hysteresis)
        ),
    };
    let (least, most) = moduli
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(l, m), e| (l.min(*e), m.max(*e)));
    let size = if kind == "cone" {
        format!("half_angle = {half_angle}\nbase_radius = {r:e}\n")
    } else {
        format!("radius = {r:e}\n")
    };
    let solver = format!("[solver]\nadhesion_method = \"{}\"\n", method());
    let text = format!(
        "[substrate]\n{substrate}[indenter]\nkind = \"{kind}\"\n{size}{adhesion}\
         [protocol]\nkind = \"cycle\"\nmax_depth = {d:e}\nsteps = 4\n\
         [resolution]\ncells_across = 16\n{solver}"
    );
    (text, most / least)
}

/// Runs one scene and returns the largest relative error against its
/// exact values over their tolerances (0 without any; below 1 passes;
/// widened to [`caveat_tolerance`] for a curve that carries a caveat), or
/// the typed error that ended it. A scene outside its tolerances at 16
/// cells across is run again at 32, and passes if it has come within them
/// there (errors that fall with the cells are the discretisation's: a
/// sphere at 0.8 of its radius on a layer about half a cell thick over a
/// base 500 times softer, its pull-off 5.4 % and 2.0 % off at 16 and 32
/// cells).
fn sweep(text: &str, contrast: f64) -> Result<f64, Error> {
    let scene = Scene::from_toml(text).expect("the sweep writes valid TOML");
    scene.validate()?;
    // Where the exact solution is not tabulated that far (a contact much
    // wider than the surface modulus's Hertz radius) there is no
    // reference; the curve still had to come out finite.
    let references = scene.reference().ok();
    let worst = worst_error(&scene, references.as_deref(), contrast)?;
    if worst < 1.0 {
        return Ok(worst);
    }
    let finer = Scene {
        resolution: layered_contact::scene::Resolution {
            cells_across: 32,
            ..scene.resolution
        },
        ..scene.clone()
    };
    println!("at 32 cells across:");
    // A typed error at 32 cells excuses nothing at 16.
    Ok(match worst_error(&finer, references.as_deref(), contrast) {
        Ok(refined) if refined < worst => refined,
        _ => worst,
    })
}

/// The largest relative error of `scene`'s curve against `references`
/// over their tolerances (widened to [`caveat_tolerance`] if the curve
/// carries a caveat).
fn worst_error(
    scene: &Scene,
    references: Option<&[layered_contact::scene::Reference]>,
    contrast: f64,
) -> Result<f64, Error> {
    let curve = scene.run(&mut |_| {})?;
    for step in &curve.steps {
        assert!(step.depth.is_finite() && step.force.is_finite());
    }
    if !curve.caveats.is_empty() {
        println!("caveats: {:?}", curve.caveats);
    }
    let widening = curve
        .caveats
        .iter()
        .map(caveat_tolerance)
        .fold(TOLERANCE, f64::max)
        / TOLERANCE;
    // An adhesive peak's net force is a difference of compression and
    // adhesion and may be far smaller than either (-1.06e-5 N against a
    // pull-off of -1.9e-3 N, its contact radius within 0.06 %): its error
    // is measured against the cycle's force scale, the larger of it and
    // the pull-off force.
    let references = references.unwrap_or_default();
    let scale = references
        .iter()
        .filter(|r| r.quantity == Quantity::PullOffForce)
        .map(|r| r.value.abs())
        .fold(0.0, f64::max);
    let mut worst = 0.0f64;
    for reference in references {
        let radius = reference.quantity == Quantity::PeakContactRadius;
        let Some(value) = reference.quantity.of(&curve) else {
            continue;
        };
        if radius && contrast > RADIUS_CONTRAST {
            continue;
        }
        let error = if reference.quantity == Quantity::PeakForce {
            (value - reference.value).abs() / reference.value.abs().max(scale)
        } else {
            (value / reference.value - 1.0).abs()
        };
        assert!(
            error.is_finite(),
            "{}: {value} against {}",
            reference.quantity.name(),
            reference.value
        );
        // In units of the quantity's tolerance.
        let bound = widening * if radius { RADIUS_TOLERANCE } else { TOLERANCE };
        println!("{} {error:e}", reference.quantity.name());
        worst = worst.max(error / bound);
    }
    Ok(worst)
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: cases(),
        rng_seed: proptest::test_runner::RngSeed::Fixed(seed()),
        failure_persistence: None,
        max_shrink_time: MAX_SHRINK_MS,
        ..ProptestConfig::default()
    })]

    /// Each drawn scene: within [`TOLERANCE`] of its exact forces and
    /// [`RADIUS_TOLERANCE`] of its contact radius (moduli within
    /// [`RADIUS_CONTRAST`]), widened to [`caveat_tolerance`] under a caveat,
    /// or a typed error that is not a failed iteration.
    #[test]
    fn random_axisymmetric_scenes_match_their_exact_values(
        kinds in (0usize..7, 0usize..4, 0usize..3),
        material in (3.0f64..11.0, 0usize..7, 0usize..7),
        shape in (-5.0f64..-1.0, -4.0f64..-1.3, -1.5f64..1.5, -4.0f64..4.0),
        more in (-3.0f64..3.0, -3.0f64..3.0, -2.5f64..0.0, 0.0f64..1.0),
    ) {
        let (text, contrast) = scene_text(kinds.0, kinds.1, kinds.2, material, shape, more);
        let label = text.clone();
        let outcome = bounded_case(&label, move || sweep(&text, contrast));
        // `--nocapture` shows each case's outcome (the large run's worst).
        println!("case: {:?}", outcome.as_ref().map_err(|e| e.to_string()));
        if outcome.is_err() || std::env::var_os("LAYERED_CONTACT_REFERENCE_PRINT").is_some() {
            println!("{label}");
        }
        match outcome {
            Ok(worst) => prop_assert!(worst < 1.0, "{worst:e} of the tolerance:\n{label}"),
            Err(e @ (Error::NoConvergence { .. } | Error::Internal { .. })) => {
                prop_assert!(false, "{e}:\n{label}")
            }
            Err(_) => {}
        }
    }
}
