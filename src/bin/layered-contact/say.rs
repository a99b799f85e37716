//! Printing that never panics: the tool's stdout and stderr may be closed
//! or full (`| head -c0`, `> /dev/full`).

/// `println!` that returns an error from the enclosing function instead of
/// panicking when standard output is closed or full (`| head -c0`,
/// `> /dev/full`): the program then ends with status 1 and a sentence.
macro_rules! say {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        writeln!(std::io::stdout(), $($arg)*)
            .map_err(|e| format!("cannot write to standard output: {e}"))?
    }};
}

/// `eprintln!` that ignores a closed standard error (progress and the final
/// error message are best effort; they never panic).
#[allow(unused_macros)] // the paper example prints no progress
macro_rules! tell {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        // One write per line: standard error is unbuffered, and a
        // formatted line written piece by piece cost 33 system calls.
        let mut line = format!($($arg)*);
        line.push('\n');
        let _ = std::io::stderr().write_all(line.as_bytes());
    }};
}
