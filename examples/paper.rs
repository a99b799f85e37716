//! Reproduces the simulations and analytics of Lyashenko, Popov & Borysiuk
//! (2023, Lubricants 11, 84): the same as `layered-contact paper`.
//!
//! ```text
//! cargo run --release --example paper -- [--out DIR] [--fine]
//! ```
//!
//! Writes CSV tables and SVG figures to `DIR` (default `target/paper`) and
//! prints a summary; `--fine` doubles the resolution. See the module docs of
//! `src/bin/layered-contact/paper/mod.rs` for the files.

#[path = "../src/bin/layered-contact/say.rs"]
#[macro_use]
mod say;
#[path = "../src/bin/layered-contact/paper/mod.rs"]
mod paper;

fn main() -> paper::Result<()> {
    let mut out = std::path::PathBuf::from("target/paper");
    let mut fine = false;
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--out" => out = args.next().ok_or("--out needs a directory")?.into(),
            "--fine" => fine = true,
            other => {
                return Err(format!("unknown argument {other}; use --out DIR and/or --fine").into())
            }
        }
    }
    paper::run(&out, fine)
}
