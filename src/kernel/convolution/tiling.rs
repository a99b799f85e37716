//! The tiles a [`Convolution`](super::Convolution) keeps its half-spectra
//! in: per block of adjacent spectrum columns, a row-major tile of all
//! rows, padded by a cache line.

use num_complex::Complex;

/// Complex values of padding after each tile (a cache line): tiles of a
/// power-of-two size would otherwise put the pieces of one row, a tile
/// apart, in the same cache sets, and the row passes would evict their own
/// lines (measured: a quarter of a periodic 1024^2 round trip).
pub(super) const TILE_PAD: usize = 4;

/// The tiles of `buffer`: per block of `block` of the `width` spectrum
/// columns, a row-major `rows x block` tile (the last one narrower), each
/// followed by [`TILE_PAD`] values of padding.
pub(super) fn tiles_mut<T>(
    buffer: &mut [Complex<T>],
    rows: usize,
    block: usize,
    width: usize,
) -> impl Iterator<Item = &mut [Complex<T>]> {
    buffer
        .chunks_mut(block * rows + TILE_PAD)
        .zip((0..width).step_by(block.max(1)))
        .map(move |(tile, j0)| &mut tile[..block.min(width - j0) * rows])
}

/// As [`tiles_mut`], read-only.
pub(super) fn tiles<T>(
    buffer: &[Complex<T>],
    rows: usize,
    block: usize,
    width: usize,
) -> impl Iterator<Item = &[Complex<T>]> {
    buffer
        .chunks(block * rows + TILE_PAD)
        .zip((0..width).step_by(block.max(1)))
        .map(move |(tile, j0)| &tile[..block.min(width - j0) * rows])
}
