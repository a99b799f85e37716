//! A `.npy` fuzz harness on stable Rust (issue 24): height-map files built
//! by hand (C and Fortran order, other dtypes and byte orders, 1D and 3D
//! shapes) and then mutated at random (header shapes replaced by extreme or
//! lying values, bytes flipped, inserted or cut off), read by
//! `HeightMap::from_npy`. Every input must end in a height map of finite
//! heights on a valid grid or a typed error: no panic, no abort on a huge
//! allocation, no hang (each case is time-bounded).
//!
//! `cargo test --release --test fuzz_npy` runs a small seeded budget;
//! `LAYERED_CONTACT_FUZZ_CASES=100000` a large one (see `doc::reliability`).

mod common;

use common::{bounded_case, npy_file as npy};
use layered_contact::indenter::HeightMap;
use layered_contact::Error;
use proptest::prelude::*;

fn fuzz_cases() -> u32 {
    common::env_number("LAYERED_CONTACT_FUZZ_CASES", 96)
}

fn f64_bytes(values: &[f64], big_endian: bool) -> Vec<u8> {
    values
        .iter()
        .flat_map(|v| {
            if big_endian {
                v.to_be_bytes()
            } else {
                v.to_le_bytes()
            }
        })
        .collect()
}

/// The seed files.
fn seeds() -> Vec<Vec<u8>> {
    let values: Vec<f64> = (0..12).map(|k| 1e-6 * k as f64).collect();
    vec![
        npy("<f8", false, "(3, 4)", &f64_bytes(&values, false)),
        npy("<f8", true, "(4, 3)", &f64_bytes(&values, false)),
        npy(">f8", false, "(3, 4)", &f64_bytes(&values, true)),
        npy("<f4", false, "(3, 4)", &[0u8; 48]),
        npy("<f8", false, "(12,)", &f64_bytes(&values, false)),
        npy("<f8", false, "(2, 2, 3)", &f64_bytes(&values, false)),
    ]
}

const SHAPES: [&str; 10] = [
    "(100000, 100000)",
    "(18446744073709551615, 2)",
    "(4294967296, 4294967296)",
    "(0, 5)",
    "(3, 0)",
    "(-1, 3)",
    "(1, 12)",
    "(32768, 2049)",
    "(3, 4, 5)",
    "()",
];

/// One mutation of `bytes`, chosen by `choice` with parameters `a`, `b`.
fn mutate(bytes: &[u8], choice: u8, a: usize, b: usize) -> Vec<u8> {
    let mut out = bytes.to_vec();
    match choice % 4 {
        // The header's shape replaced (the header length kept where it fits).
        0 => {
            let text = String::from_utf8_lossy(bytes).into_owned();
            if let (Some(start), Some(end)) = (text.find("'shape': "), text.find(", }")) {
                let start = start + "'shape': ".len();
                if start <= end && text.is_char_boundary(start) && text.is_char_boundary(end) {
                    let shape = SHAPES[b % SHAPES.len()];
                    let mut header = text.as_bytes()[..start].to_vec();
                    header.extend_from_slice(shape.as_bytes());
                    header.extend_from_slice(&text.as_bytes()[end..]);
                    out = header;
                }
            }
        }
        // A byte flipped.
        1 => {
            if !out.is_empty() {
                let at = a % out.len();
                out[at] ^= (b % 255 + 1) as u8;
            }
        }
        // A byte inserted.
        2 => out.insert(a % (out.len() + 1), (b % 256) as u8),
        // Cut off.
        _ => out.truncate(a % (out.len() + 1)),
    }
    out
}

/// Writes `bytes` to a fresh file and reads it as a height map.
fn exercise(label: &str, bytes: Vec<u8>) {
    let path = std::env::temp_dir().join(format!(
        "layered-contact-fuzz-{}-{label}.npy",
        std::process::id()
    ));
    std::fs::write(&path, &bytes).unwrap();
    let result = HeightMap::from_npy(&path, 1e-6);
    std::fs::remove_file(&path).ok();
    match result {
        Ok(map) => {
            assert!(map.grid().len() <= layered_contact::grid::MAX_CELLS);
            assert!(map.heights().iter().all(|h| h.is_finite()));
        }
        Err(
            Error::HeightMapFile { .. }
            | Error::InvalidGrid { .. }
            | Error::InvalidParameter { .. }
            | Error::ShapeMismatch { .. },
        ) => {}
        Err(other) => panic!("unexpected error {other:?}"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig {
        cases: fuzz_cases(),
        rng_seed: proptest::test_runner::RngSeed::Fixed(24),
        failure_persistence: None,
        ..ProptestConfig::default()
    })]

    /// Mutated `.npy` files: a valid height map or a typed error.
    #[test]
    fn mutated_npy_files(
        seed in 0usize..6,
        mutations in proptest::collection::vec((any::<u8>(), any::<usize>(), any::<usize>()), 1..4),
        tag in any::<u64>(),
    ) {
        let mut bytes = seeds().swap_remove(seed);
        for (choice, a, b) in mutations {
            bytes = mutate(&bytes, choice, a, b);
        }
        let label = format!("{tag:016x}");
        bounded_case(&label.clone(), move || exercise(&label, bytes));
    }
}

/// The seeds read as the arrays they hold (C and Fortran order), and the
/// others are typed errors; the mutations reach both outcomes.
#[test]
fn seeds_read_exactly_and_mutations_reach_errors() {
    let seeds = seeds();
    for (k, bytes) in seeds.iter().enumerate().take(2) {
        let path = std::env::temp_dir().join(format!(
            "layered-contact-seed-{}-{k}.npy",
            std::process::id()
        ));
        std::fs::write(&path, bytes).unwrap();
        let map = HeightMap::from_npy(&path, 1e-6).unwrap();
        std::fs::remove_file(&path).ok();
        let (rows, columns) = (map.grid().rows(), map.grid().columns());
        assert_eq!((rows, columns), if k == 0 { (3, 4) } else { (4, 3) });
        // Fortran order: element (i, j) is value i + rows j.
        let expected = |i: usize, j: usize| if k == 0 { i * 4 + j } else { i + 4 * j };
        for i in 0..rows {
            for j in 0..columns {
                assert_eq!(map.heights()[i * columns + j], 1e-6 * expected(i, j) as f64);
            }
        }
    }
    let (mut ok, mut errors) = (0, 0);
    for k in 0..40usize {
        let bytes = mutate(&seeds[k % 2], (k / 2) as u8, k * 7919, k * 104_729);
        let path = std::env::temp_dir().join(format!(
            "layered-contact-mut-{}-{k}.npy",
            std::process::id()
        ));
        std::fs::write(&path, &bytes).unwrap();
        match HeightMap::from_npy(&path, 1e-6) {
            Ok(_) => ok += 1,
            Err(_) => errors += 1,
        }
        std::fs::remove_file(&path).ok();
    }
    assert!(ok > 0 && errors > 0, "{ok} {errors}");
}
