//! Reading the files the crate opens (scene files, height maps), bounded:
//! only regular files, and no more bytes than the largest valid input, so
//! that `/dev/zero`, a named pipe or a file whose header claims more than it
//! holds is an error, not an exhausted machine.

use std::io::Read;
use std::path::Path;

/// The largest scene file read, bytes (scenes are a few hundred bytes).
#[cfg(feature = "serde")]
pub(crate) const MAX_SCENE_BYTES: u64 = 16 << 20;
/// The largest `.npy` height map read, bytes: the grid's limit of `2^26`
/// cells of 8 bytes, and room for the header.
pub(crate) const MAX_NPY_BYTES: u64 = ((crate::grid::MAX_CELLS as u64) << 3) + (1 << 20);
/// The largest text height map read, bytes: `2^26` values of up to 31
/// characters and a separator each.
pub(crate) const MAX_TEXT_MAP_BYTES: u64 = (crate::grid::MAX_CELLS as u64) << 5;

/// The bytes of the regular file at `path`, at most `limit` of them; the
/// error is a sentence for the caller's typed error.
pub(crate) fn read_bounded(path: &Path, limit: u64) -> Result<Vec<u8>, String> {
    let (file, metadata) = open_bounded(path, limit)?;
    let too_long = |bytes: u64| format!("{bytes} bytes, more than the {limit} bytes read at most");
    let mut bytes = Vec::new();
    bytes
        .try_reserve_exact(metadata.len() as usize)
        .map_err(|_| format!("{} bytes could not be allocated", metadata.len()))?;
    // The file may grow while it is read: read one byte past the limit.
    file.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| e.to_string())?;
    if bytes.len() as u64 > limit {
        return Err(too_long(bytes.len() as u64));
    }
    Ok(bytes)
}

/// The regular file at `path`, if it holds at most `limit` bytes, and its
/// metadata; the error is a sentence for the caller's typed error.
pub(crate) fn open_bounded(
    path: &Path,
    limit: u64,
) -> Result<(std::fs::File, std::fs::Metadata), String> {
    let file = std::fs::File::open(path).map_err(|e| e.to_string())?;
    let metadata = file.metadata().map_err(|e| e.to_string())?;
    if !metadata.is_file() {
        return Err("not a regular file (a device, a pipe or a folder cannot be read)".into());
    }
    if metadata.len() > limit {
        return Err(format!(
            "{} bytes, more than the {limit} bytes read at most",
            metadata.len()
        ));
    }
    Ok((file, metadata))
}

/// The text of the regular file at `path`, at most `limit` bytes of UTF-8.
pub(crate) fn read_text_bounded(path: &Path, limit: u64) -> Result<String, String> {
    String::from_utf8(read_bounded(path, limit)?)
        .map_err(|e| format!("not UTF-8 text (byte {})", e.utf8_error().valid_up_to()))
}
