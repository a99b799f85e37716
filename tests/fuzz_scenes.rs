//! A scene-file fuzz harness on stable Rust: scene files (TOML and JSON)
//! mutated at random (numbers replaced by extreme values, kinds swapped,
//! lines deleted, duplicated or swapped, bytes inserted), then parsed,
//! validated and, when valid, run at a reduced resolution. Every input must
//! end in a curve with finite numbers or a typed error: no panic, no hang
//! (each case is time-bounded), no NaN.
//!
//! `cargo test --release --test fuzz_scenes` runs a small seeded budget;
//! `LAYERED_CONTACT_FUZZ_CASES=100000` a large one, `LAYERED_CONTACT_FUZZ_SEED`
//! other cases than the default seed's (see `doc::reliability`).

#![cfg(feature = "serde")]

mod common;

use common::bounded_case;
use layered_contact::scene::Scene;
use proptest::prelude::*;

fn fuzz_cases() -> u32 {
    common::env_number("LAYERED_CONTACT_FUZZ_CASES", 96)
}

/// The campaign's seed: `LAYERED_CONTACT_FUZZ_SEED` (default 12, the seed
/// `cargo test` runs), so that a large run can draw other cases.
fn fuzz_seed() -> u64 {
    common::env_number("LAYERED_CONTACT_FUZZ_SEED", 12)
}

/// The seed files: the examples, and scenes reaching the other protocols,
/// indenters, bases and the periodic boundary.
fn seeds() -> Vec<(bool, String)> {
    let toml = |s: &str| (true, s.to_string());
    let json = |s: &str| (false, s.to_string());
    let seeds = vec![
        toml(include_str!("../examples/scenes/sphere_on_film.toml")),
        json(include_str!("../examples/scenes/punch_on_half_space.json")),
        json(
            "{\"substrate\": {\"kind\": \"half_space\", \"youngs_modulus\": 1e6, \"poisson_ratio\": 0.5},\n\
             \"indenter\": {\"kind\": \"flat_punch\", \"radius\": 1e-3},\n\
             \"tilt\": {\"angle_y\": 0.02},\n\
             \"adhesion\": {\"kind\": \"constant\", \"work_of_adhesion\": 0.3},\n\
             \"protocol\": {\"kind\": \"cycle\", \"max_depth\": 2e-5, \"steps\": 4},\n\
             \"resolution\": {\"cells_across\": 16}}\n",
        ),
        toml(
            "[substrate]\nkind = \"layer_on_elastic_base\"\nyoungs_modulus = 1e6\npoisson_ratio = 0.45\n\
             thickness = 1e-3\nbase_youngs_modulus = 1e9\nbase_poisson_ratio = 0.3\n\
             [indenter]\nkind = \"cone\"\nhalf_angle = 1.2\nbase_radius = 5e-3\n\
             [protocol]\nkind = \"force_cycle\"\nmax_force = 0.01\nsteps = 4\n\
             [resolution]\ncells_across = 16\nmargin = 0.25\n",
        ),
        toml(
            "boundary = \"periodic\"\n[substrate]\nkind = \"half_space\"\nyoungs_modulus = 2e6\n\
             poisson_ratio = 0.3\n[indenter]\nkind = \"paraboloid\"\nradius = 1e-2\n\
             [adhesion]\nkind = \"constant\"\nwork_of_adhesion = 0.05\n\
             [protocol]\nkind = \"force\"\nforce = 1e-3\n[tilt]\nangle_y = 1e-3\n\
             [solver]\nadhesion_method = \"mesh_criterion\"\n",
        ),
        toml(
            "boundary = \"periodic\"\n[substrate]\nkind = \"layer_on_rigid_base\"\n\
             youngs_modulus = 1e6\npoisson_ratio = 0.5\nthickness = 1e-4\n\
             [indenter]\nkind = \"rough_surface\"\nhurst = 0.8\namplitude = { rms_slope = 0.1 }\n\
             long_cutoff = 32e-6\nshort_cutoff = 4e-6\nseed = 3\ncells = 32\nspacing = 1e-6\n\
             [protocol]\nkind = \"force\"\nforce = 1e-4\n",
        ),
        toml(include_str!("../examples/scenes/punch_array.toml")),
        // The cohesive zone: a rough film's adhesive cycle with hysteresis
        // (periodic, patches), and a tilted sphere's force cycle on a stack.
        toml(
            "boundary = \"periodic\"\n[substrate]\nkind = \"layer_on_rigid_base\"\n\
             youngs_modulus = 1e6\npoisson_ratio = 0.48\nthickness = 2e-4\n\
             [indenter]\nkind = \"rough_surface\"\nhurst = 0.8\namplitude = { rms_height = 1e-6 }\n\
             long_cutoff = 1.2e-4\nshort_cutoff = 2e-5\nseed = 3\ncells = 24\nspacing = 5e-6\n\
             [adhesion]\nkind = \"hysteresis\"\nloading = 0.01\nunloading = 0.05\n\
             [protocol]\nkind = \"cycle\"\nmax_depth = 3e-6\nsteps = 3\n",
        ),
        toml(
            "[substrate]\nkind = \"stack\"\nlayers = [ { youngs_modulus = 1e6, poisson_ratio = 0.49, \
             thickness = 1e-4 }, { youngs_modulus = 1e8, poisson_ratio = 0.3, thickness = 5e-5 } ]\n\
             base = { youngs_modulus = 1e9, poisson_ratio = 0.3 }\n\
             [indenter]\nkind = \"sphere\"\nradius = 5e-3\n[tilt]\nangle_x = 0.01\n\
             [adhesion]\nkind = \"constant\"\nwork_of_adhesion = 0.05\n\
             [protocol]\nkind = \"force_cycle\"\nmax_force = 1e-3\nsteps = 3\n\
             [resolution]\ncells_across = 12\n",
        ),
    ];
    assert_eq!(seeds.len(), SEEDS);
    seeds
}

/// How many seed files [`seeds`] holds (every one is mutated).
const SEEDS: usize = 9;

const WILD: [&str; 16] = [
    "0",
    "-0",
    "1",
    "-1",
    "1e308",
    "-1e308",
    "5e-324",
    "1e-300",
    "1e300",
    "0.5",
    "0.5000001",
    "1e15",
    "nan",
    "inf",
    "18446744073709551615",
    "3",
];
const KINDS: [&str; 14] = [
    "half_space",
    "layer_on_rigid_base",
    "layer_on_elastic_base",
    "flat_punch",
    "sphere",
    "paraboloid",
    "cone",
    "none",
    "constant",
    "hysteresis",
    "depth",
    "force",
    "cycle",
    "force_cycle",
];

/// One mutation of `text`, chosen by `choice` with parameters `a`, `b`.
fn mutate(text: &str, choice: u8, a: usize, b: usize) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let line = if lines.is_empty() { 0 } else { a % lines.len() };
    match choice % 6 {
        // A number replaced by an extreme value.
        0 => {
            let numbers: Vec<(usize, usize)> = number_spans(text);
            match numbers.get(a % numbers.len().max(1)) {
                Some(&(start, end)) => {
                    format!("{}{}{}", &text[..start], WILD[b % WILD.len()], &text[end..])
                }
                None => text.to_string(),
            }
        }
        // A kind swapped.
        1 => {
            let mut out = text.to_string();
            if let Some(kind) = KINDS.iter().find(|k| text.contains(&format!("\"{k}\""))) {
                out = out.replacen(
                    &format!("\"{kind}\""),
                    &format!("\"{}\"", KINDS[b % KINDS.len()]),
                    1,
                );
            }
            out
        }
        // A line deleted, duplicated or swapped.
        2 => lines
            .iter()
            .enumerate()
            .filter(|(i, _)| *i != line)
            .map(|(_, l)| *l)
            .collect::<Vec<_>>()
            .join("\n"),
        3 => {
            let mut out: Vec<&str> = lines.clone();
            if !lines.is_empty() {
                out.insert(line, lines[line]);
            }
            out.join("\n")
        }
        4 => {
            let mut out: Vec<&str> = lines.clone();
            if !lines.is_empty() {
                out.swap(line, b % lines.len());
            }
            out.join("\n")
        }
        // A byte inserted.
        _ => {
            let mut bytes = text.as_bytes().to_vec();
            let at = a % (bytes.len() + 1);
            bytes.insert(at, (b % 256) as u8);
            String::from_utf8_lossy(&bytes).into_owned()
        }
    }
}

/// Byte spans of the numbers in `text`.
fn number_spans(text: &str) -> Vec<(usize, usize)> {
    let bytes = text.as_bytes();
    let mut spans = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let starts = bytes[i].is_ascii_digit()
            || (bytes[i] == b'-' && i + 1 < bytes.len() && bytes[i + 1].is_ascii_digit());
        let inside_word = i > 0 && (bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_');
        if starts && !inside_word {
            let start = i;
            i += 1;
            while i < bytes.len()
                && (bytes[i].is_ascii_alphanumeric() || matches!(bytes[i], b'.' | b'-' | b'+'))
            {
                i += 1;
            }
            spans.push((start, i));
        } else {
            i += 1;
        }
    }
    spans
}

/// Parses, validates and runs one scene text. Returns whether it ran.
fn exercise(toml_text: bool, text: String) -> bool {
    let parsed: Option<Scene> = if toml_text {
        Scene::from_toml(&text).ok()
    } else {
        Scene::from_json(&text).ok()
    };
    let Some(mut scene) = parsed else {
        return false;
    };
    if scene.validate().is_err() {
        return false;
    }
    // Reduced cost, same code paths.
    scene.resolution.cells_across = scene.resolution.cells_across.min(16);
    scene.solver.max_iterations = scene.solver.max_iterations.min(2000);
    match &mut scene.protocol {
        layered_contact::scene::Protocol::Cycle { steps, .. }
        | layered_contact::scene::Protocol::ForceCycle { steps, .. } => *steps = (*steps).min(8),
        _ => {}
    }
    if let Ok(curve) = scene.run(&mut |_| {}) {
        for step in &curve.steps {
            assert!(
                step.depth.is_finite()
                    && step.force.is_finite()
                    && step.contact_area.is_finite()
                    && step.contact_radius.is_finite(),
                "non-finite step {step:?} of {text}"
            );
        }
    }
    true
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: fuzz_cases(),
        rng_seed: proptest::test_runner::RngSeed::Fixed(fuzz_seed()),
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    /// Mutated scene files: a curve with finite numbers or a typed error.
    #[test]
    fn mutated_scene_files(
        seed in 0usize..SEEDS,
        mutations in proptest::collection::vec((any::<u8>(), any::<usize>(), any::<usize>()), 1..4),
    ) {
        let (toml_text, mut text) = seeds().swap_remove(seed);
        for (choice, a, b) in mutations {
            text = mutate(&text, choice, a, b);
        }
        let label = text.clone();
        bounded_case(&label, move || exercise(toml_text, text));
    }
}

/// The mutations reach every kind of outcome: among a fixed sample some
/// texts fail to parse, some fail validation and some run.
#[test]
fn mutations_reach_parse_errors_validation_errors_and_runs() {
    let (mut parse_errors, mut invalid, mut valid) = (0, 0, 0);
    for k in 0..60usize {
        let (toml_text, text) = seeds().swap_remove(k % SEEDS);
        let text = mutate(&text, (k / 5) as u8, k * 7919, k * 104_729);
        let parsed: Option<Scene> = if toml_text {
            Scene::from_toml(&text).ok()
        } else {
            Scene::from_json(&text).ok()
        };
        match parsed {
            None => parse_errors += 1,
            Some(scene) if scene.validate().is_err() => invalid += 1,
            Some(_) => valid += 1,
        }
    }
    assert!(
        parse_errors > 0 && invalid > 0 && valid > 0,
        "{parse_errors} {invalid} {valid}"
    );
}
