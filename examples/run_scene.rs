//! Runs one scene described in a TOML or JSON file and writes its curve as
//! CSV (`phase,depth_m,force_N,contact_area_m2,contact_radius_m,iterations`),
//! so that sweeps can be scripted and handed to a job scheduler one scene
//! per task.
//!
//! ```text
//! cargo run --release --example run_scene -- examples/scenes/sphere_on_film.toml [out.csv]
//! ```
//!
//! Without an output path the CSV goes to standard output; a summary
//! (stiffness, pull-off) goes to standard error.

use std::error::Error;
use std::io::Write;

use layered_contact::scene::Scene;

fn main() -> Result<(), Box<dyn Error>> {
    let mut args = std::env::args().skip(1);
    let input = args
        .next()
        .ok_or("usage: run_scene SCENE.toml|SCENE.json [OUT.csv]")?;
    let text = std::fs::read_to_string(&input)?;
    let scene: Scene = if input.ends_with(".json") {
        serde_json::from_str(&text)?
    } else {
        toml::from_str(&text)?
    };
    scene.validate()?;
    let curve = scene.run(&mut |_| {})?;

    let sink: Box<dyn Write> = match args.next() {
        Some(path) => Box::new(std::fs::File::create(path)?),
        None => Box::new(std::io::stdout()),
    };
    let mut writer = csv::Writer::from_writer(sink);
    writer.write_record([
        "phase",
        "depth_m",
        "force_N",
        "contact_area_m2",
        "contact_radius_m",
        "iterations",
    ])?;
    for s in &curve.steps {
        writer.write_record([
            s.phase.name().to_string(),
            format!("{:e}", s.depth),
            format!("{:e}", s.force),
            format!("{:e}", s.contact_area),
            format!("{:e}", s.contact_radius),
            s.iterations.to_string(),
        ])?;
    }
    writer.flush()?;
    eprintln!(
        "{} steps on a {} x {} grid; stiffness {:?} N/m; pull-off {:?}",
        curve.steps.len(),
        curve.grid.rows(),
        curve.grid.columns(),
        curve.stiffness(),
        curve.pull_off().map(|s| (s.depth, s.force))
    );
    Ok(())
}
