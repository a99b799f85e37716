//! Reading a scene file, with its mistakes as readable sentences.

use std::path::Path;

use layered_contact::scene::Scene;

use crate::Result;

/// The scene in `path`: JSON if its extension is `.json`, TOML otherwise.
/// A height map's relative path is taken relative to the scene file.
pub fn read(path: &Path) -> Result<Scene> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let json = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("json"));
    let mut scene: Scene = if json {
        serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?
    } else {
        // toml's message names the line, the column and the key, and shows
        // the line.
        toml::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?
    };
    if let Some(folder) = path.parent() {
        scene.resolve_paths(folder);
    }
    Ok(scene)
}
