"""Where the fine solve's wrong joins come from (issue 27): is the gap error
of an early fine iteration long-wavelength, and can the contact's own gaps
estimate it? Reads the dumps of `benches/rough/gap_error_estimate.patch`
(`DBG=1 XDUMP=2 XDUMPDIR=DIR RAYON_NUM_THREADS=1 rough_benchmark peers N`:
the gaps, pressures and working set of fine iterations 2 and 3, and the
solution's gaps and pressures, as raw little-endian f64 on N x N cells).

For the cells that overlap in iteration K (no pressure, gap below zero),
split by whether they carry pressure in the solution (right to join) or
not (wrong), prints the share of the gap error `e = gap_K - gap_final`
(`gap_final` zero on the final contact) in its long wavelengths, and the
fractions of right ones that still overlap and of wrong ones cleared once
the gap less an estimate of the error is read instead:

- the error itself low-passed (wavelengths above `lam` cells; an oracle),
- its lowest Fourier modes,
- the contact's own gaps (zero at the solution) smoothed by a normalised
  Gaussian convolution over the cells in contact, `G * (g m) / G * m`
  (`m` the contact of iteration K), in 2D and along rows only.

Usage: python gap_error.py N DIR   (numpy)
"""

import sys

import numpy as np


def main(n, directory):
    def load(name):
        return np.fromfile(f"{directory}/dump_{name}.bin", dtype="<f8").reshape(n, n)

    gap_final, p_final = load("final_gap"), load("final_p")
    ky = np.fft.fftfreq(n)[:, None] * n
    kx = np.fft.rfftfreq(n)[None, :] * n
    k = np.hypot(kx, ky)
    for it in (2, 3):
        g, p = load(f"{it}_gap"), load(f"{it}_p")
        overlap = (p == 0) & (g < 0)
        right, wrong = overlap & (p_final > 0), overlap & (p_final == 0)
        e = g - np.where(p_final > 0, 0.0, gap_final)
        rms = np.sqrt((e**2).mean())
        print(f"iteration {it}: overlapping {overlap.sum()} (right {right.sum()}, wrong {wrong.sum()});"
              f" rms error {rms:.3e}, mean overlap {g[overlap].mean():.3e}")

        def report(label, estimate, share=None):
            c = g - estimate
            extra = "" if share is None else f" share of the error {share:.2f};"
            print(f"  {label}:{extra} right still overlapping {(c[right] < 0).mean():.0%},"
                  f" wrong cleared {(c[wrong] >= 0).mean():.0%}")

        spectrum = np.fft.rfft2(e)
        for lam in (4, 16, 64, 128):
            low = np.fft.irfft2(spectrum * (k < n / lam), s=(n, n))
            report(f"error above {lam} cells (oracle)", low, np.sqrt((low**2).mean()) / rms)
        for kk in (1, 4):
            low = np.fft.irfft2(spectrum * (k <= kk), s=(n, n))
            report(f"error in modes |k| <= {kk} (oracle)", low, np.sqrt((low**2).mean()) / rms)
        m = (p > 0).astype(float)
        gm, mm = np.fft.rfft2(g * m), np.fft.rfft2(m)
        for s in (2, 4, 8):
            f = np.exp(-0.5 * (2 * np.pi * k / n * s) ** 2)
            est = np.fft.irfft2(gm * f, s=(n, n)) / np.maximum(np.fft.irfft2(mm * f, s=(n, n)), 1e-3)
            report(f"contact's gaps, Gaussian sigma {s} cells", est)
        gm, mm = np.fft.rfft(g * m, axis=1), np.fft.rfft(m, axis=1)
        for s in (4, 8, 16):
            f = np.exp(-0.5 * (2 * np.pi * kx / n * s) ** 2)
            est = np.fft.irfft(gm * f, n=n, axis=1) / np.maximum(np.fft.irfft(mm * f, n=n, axis=1), 1e-3)
            report(f"contact's gaps along rows, sigma {s} cells", est)


if __name__ == "__main__":
    main(int(sys.argv[1]), sys.argv[2])
