//! Self-affine surfaces and height-map files.

use layered_contact::indenter::{HeightMap, Indenter};
use layered_contact::topography::{Amplitude, SelfAffine};
use layered_contact::{Error, Grid};

fn surface(amplitude: Amplitude, seed: u64) -> SelfAffine {
    SelfAffine {
        hurst: 0.8,
        amplitude,
        long_cutoff: 0.25e-3,
        short_cutoff: 16e-6,
        seed,
    }
}

/// The radially averaged power spectrum of a realisation follows
/// `q^(-2(1+H))` between the cut-offs: a least-squares fit of its log-log
/// slope over the self-affine band gives `-2(1+H) = -3.6` within 0.15 (the
/// band holds thousands of random modes; measured -3.53), and it is flat
/// below the roll-off.
#[test]
fn spectrum_is_self_affine() {
    let n = 256;
    let grid = Grid::square_of_side(n, 1e-3).unwrap();
    let h = surface(Amplitude::RmsHeight(1e-6), 3)
        .heights(&grid)
        .unwrap();
    // Power by integer shell |k| via a direct DFT of each row then column
    // would be slow; use rustfft through a simple 2D transform.
    let mut planner = rustfft::FftPlanner::<f64>::new();
    let fft = planner.plan_fft_forward(n);
    let mut data: Vec<num_complex::Complex<f64>> = h
        .iter()
        .map(|v| num_complex::Complex::new(*v, 0.0))
        .collect();
    for row in data.chunks_exact_mut(n) {
        fft.process(row);
    }
    let mut column = vec![num_complex::Complex::default(); n];
    for j in 0..n {
        for i in 0..n {
            column[i] = data[i * n + j];
        }
        fft.process(&mut column);
        for i in 0..n {
            data[i * n + j] = column[i];
        }
    }
    let mut shells = vec![(0.0, 0usize); n];
    for i in 0..n {
        for j in 0..n {
            let k = |x: usize| {
                if x <= n / 2 {
                    x as f64
                } else {
                    x as f64 - n as f64
                }
            };
            let shell = k(i).hypot(k(j)).round() as usize;
            if shell < n {
                shells[shell].0 += data[i * n + j].norm_sqr();
                shells[shell].1 += 1;
            }
        }
    }
    let power = |s: usize| shells[s].0 / shells[s].1 as f64;
    // Roll-off at k = 1e-3 / 0.25e-3 = 4, cut-off at k = 1e-3 / 16e-6 = 62.5.
    let (xs, ys): (Vec<f64>, Vec<f64>) = (6..60).map(|s| ((s as f64).ln(), power(s).ln())).unzip();
    let (mx, my) = (
        xs.iter().sum::<f64>() / xs.len() as f64,
        ys.iter().sum::<f64>() / ys.len() as f64,
    );
    let slope = xs
        .iter()
        .zip(&ys)
        .map(|(x, y)| (x - mx) * (y - my))
        .sum::<f64>()
        / xs.iter().map(|x| (x - mx).powi(2)).sum::<f64>();
    assert!((slope + 3.6).abs() < 0.15, "{slope}");
    // Below the roll-off the spectrum is flat: shells 1-3 (about 30 random
    // modes, scatter about 20 %) within a factor 2.5 of the roll-off shell,
    // and shell 2 only (8/4)^3.6 = 12 times shell 8, not (8/2)^3.6 = 147.
    let plateau = (power(1) + power(2) + power(3)) / 3.0;
    assert!(
        (0.4..2.5).contains(&(plateau / power(4))),
        "{plateau} {}",
        power(4)
    );
    assert!(power(2) / power(8) < 40.0, "{}", power(2) / power(8));
    assert!(power(70) < 1e-20 * power(10));
}

/// The requested rms height is exact (to rounding), the rms slope matches
/// central differences on the periodic map within 3 % (their error at the
/// cut-off, 16 cells: 1 - sinc(2 pi / 16) = 2.5 % at most, less on
/// average; measured 0.6 % low), the mean is zero, and the seed alone
/// decides the surface.
#[test]
fn amplitude_mean_and_seed() {
    let n = 256;
    let grid = Grid::square_of_side(n, 1e-3).unwrap();
    let delta = grid.spacing();
    let rms = |v: &[f64]| (v.iter().map(|x| x * x).sum::<f64>() / v.len() as f64).sqrt();
    let h = surface(Amplitude::RmsHeight(2e-6), 5)
        .heights(&grid)
        .unwrap();
    assert!((rms(&h) / 2e-6 - 1.0).abs() < 1e-12);
    assert!(h.iter().sum::<f64>().abs() / ((n * n) as f64) < 1e-20);
    assert_eq!(
        h,
        surface(Amplitude::RmsHeight(2e-6), 5)
            .heights(&grid)
            .unwrap()
    );
    assert_ne!(
        h,
        surface(Amplitude::RmsHeight(2e-6), 6)
            .heights(&grid)
            .unwrap()
    );

    let sixteen_cells = SelfAffine {
        short_cutoff: 16.0 * delta,
        ..surface(Amplitude::RmsSlope(0.1), 5)
    };
    let s = sixteen_cells.heights(&grid).unwrap();
    let mut gradient = Vec::with_capacity(2 * n * n);
    for i in 0..n {
        for j in 0..n {
            let at = |a: usize, b: usize| s[(a % n) * n + (b % n)];
            gradient.push((at(i + 1, j) - at(i + n - 1, j)) / (2.0 * delta));
            gradient.push((at(i, j + 1) - at(i, j + n - 1)) / (2.0 * delta));
        }
    }
    // Both components: |grad h|^2 = sum of the two mean squares.
    let slope = rms(&gradient) * 2f64.sqrt();
    assert!((slope / 0.1 - 1.0).abs() < 0.03, "{slope}");
    // Same seed and band, other amplitude: the same shape, scaled.
    let t = SelfAffine {
        amplitude: Amplitude::RmsHeight(1e-6),
        ..sixteen_cells
    }
    .heights(&grid)
    .unwrap();
    let ratio = rms(&s) / rms(&t);
    assert!(s
        .iter()
        .zip(&t)
        .all(|(a, b)| (a - ratio * b).abs() < 1e-12 * rms(&s)));
}

/// As an indenter the surface is turned upside down: its highest summit is
/// the lowest point, at height 0.
#[test]
fn indenter_touches_at_the_highest_summit() {
    let grid = Grid::square_of_side(64, 0.25e-3).unwrap();
    let rough = surface(Amplitude::RmsHeight(1e-6), 9);
    let h = rough.heights(&grid).unwrap();
    let map = rough.indenter(&grid).unwrap();
    let top = h.iter().copied().fold(f64::MIN, f64::max);
    let c = h.iter().position(|v| *v == top).unwrap();
    let x = ((c / 64) as f64 + 0.5) * grid.spacing() - 0.125e-3;
    let y = ((c % 64) as f64 + 0.5) * grid.spacing() - 0.125e-3;
    assert_eq!(map.height(x, y), 0.0);
    assert!(map.heights().iter().all(|f| *f >= 0.0));
}

/// Bad parameters name themselves.
#[test]
fn invalid_surfaces_are_refused() {
    let grid = Grid::square_of_side(64, 1e-3).unwrap();
    for (bad, name) in [
        (
            SelfAffine {
                hurst: 1.0,
                ..surface(Amplitude::RmsHeight(1e-6), 1)
            },
            "hurst",
        ),
        (
            SelfAffine {
                hurst: f64::NAN,
                ..surface(Amplitude::RmsHeight(1e-6), 1)
            },
            "hurst",
        ),
        (surface(Amplitude::RmsHeight(-1e-6), 1), "rms height (m)"),
        (surface(Amplitude::RmsSlope(f64::INFINITY), 1), "rms slope"),
        (
            SelfAffine {
                short_cutoff: 1e-5,
                ..surface(Amplitude::RmsHeight(1e-6), 1)
            },
            "short_cutoff (m)",
        ),
        (
            SelfAffine {
                long_cutoff: 1e-6,
                ..surface(Amplitude::RmsHeight(1e-6), 1)
            },
            "short_cutoff (m)",
        ),
    ] {
        match bad.heights(&grid) {
            Err(Error::InvalidParameter { name: n, .. }) => assert_eq!(n, name),
            other => panic!("{bad:?}: {other:?}"),
        }
    }
    // A band above the grid's longest wavelength (1 mm) holds no mode: the
    // parameter check says so before any synthesis, as the synthesis did.
    let beyond = SelfAffine {
        short_cutoff: 1.5e-3,
        long_cutoff: 2e-3,
        ..surface(Amplitude::RmsHeight(1e-6), 1)
    };
    match beyond.heights(&grid) {
        Err(Error::InvalidParameter { name, expected, .. }) => {
            assert_eq!(name, "short_cutoff (m)");
            assert!(expected.contains("at least one wavevector"));
        }
        other => panic!("{other:?}"),
    }
    // At the grid's side the longest wavelength is in the band.
    let at_side = SelfAffine {
        short_cutoff: 1e-3,
        long_cutoff: 2e-3,
        ..surface(Amplitude::RmsHeight(1e-6), 1)
    };
    assert!(at_side.heights(&grid).is_ok());
}

/// Height maps read from `.npy` and from text equal what was written, on
/// the grid the file's shape and the given spacing define; a text value that
/// is not a number names its line and column.
#[test]
fn height_maps_from_files() {
    let dir = std::env::temp_dir().join(format!("layered_contact_maps_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let values = ndarray::Array2::from_shape_fn((3, 5), |(i, j)| 1e-6 * (i * 5 + j) as f64 - 2e-6);
    let npy = dir.join("map.npy");
    ndarray_npy::write_npy(&npy, &values).unwrap();
    let map = HeightMap::from_npy(&npy, 1e-4).unwrap();
    assert_eq!((map.grid().rows(), map.grid().columns()), (3, 5));
    assert_eq!(map.heights(), values.as_slice().unwrap());

    let text = dir.join("map.txt");
    let rows: Vec<String> = values
        .rows()
        .into_iter()
        .map(|r| {
            r.iter()
                .map(|v| format!("{v:e}"))
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect();
    std::fs::write(&text, format!("# heights, m\n{}\n\n", rows.join("\n"))).unwrap();
    let map = HeightMap::from_text(&text, 1e-4).unwrap();
    assert_eq!(map.heights(), values.as_slice().unwrap());

    std::fs::write(&text, "1 2 3\n4 x 6\n").unwrap();
    let message = HeightMap::from_text(&text, 1e-4).unwrap_err().to_string();
    assert!(message.contains("line 2, value 2: `x`"), "{message}");
    std::fs::write(&text, "1 2 3\n4 5\n").unwrap();
    let message = HeightMap::from_text(&text, 1e-4).unwrap_err().to_string();
    assert!(message.contains("line 2 has 2 values"), "{message}");
    let message = HeightMap::from_npy(dir.join("missing.npy"), 1e-4)
        .unwrap_err()
        .to_string();
    assert!(message.starts_with("height map "), "{message}");
    std::fs::remove_dir_all(&dir).unwrap();
}
