//! Peak resident memory of this process (Linux), shared by the benchmark
//! examples.

/// The process's peak resident set (`VmHWM`), bytes; NaN where
/// `/proc/self/status` does not tell.
pub fn peak_resident_bytes() -> f64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .and_then(|l| l.split_whitespace().nth(1)?.parse::<f64>().ok())
        })
        .map_or(f64::NAN, |kb| kb * 1024.0)
}
