//! Scene files: TOML or JSON text into a [`Scene`], with mistakes reported
//! by line, column and key.

use std::path::Path;

use crate::error::{Error, Result};

use super::Scene;

impl Scene {
    /// The scene in the file at `path`: JSON if its extension is `.json`,
    /// TOML otherwise. A relative height-map path in it is taken relative to
    /// the file's folder ([`Scene::resolve_paths`]). The scene is parsed,
    /// not validated ([`Scene::validate`]).
    ///
    /// # Errors
    /// [`Error::SceneFile`] naming the file, and for a mistake in it the
    /// line, the column and the key.
    pub fn read(path: impl AsRef<Path>) -> Result<Scene> {
        let path = path.as_ref();
        let name = path.display().to_string();
        let text = crate::files::read_text_bounded(path, crate::files::MAX_SCENE_BYTES).map_err(
            |detail| Error::SceneFile {
                source_name: name.clone(),
                detail,
            },
        )?;
        let json = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("json"));
        let mut scene = if json {
            parse_json(&text, name)?
        } else {
            parse_toml(&text, name)?
        };
        if let Some(folder) = path.parent() {
            scene.resolve_paths(folder);
        }
        Ok(scene)
    }

    /// A scene from TOML text.
    ///
    /// ```
    /// use layered_contact::scene::Scene;
    ///
    /// let text = "[substrate]\nkind = \"half_space\"\nyoungs_modulus = 1e6\n\
    ///             poisson_ratio = 0.5\n[indenter]\nkind = \"sphere\"\nradus = 0.01\n\
    ///             [protocol]\nkind = \"depth\"\ndepth = 1e-5\n";
    /// let error = Scene::from_toml(text).unwrap_err().to_string();
    /// assert!(error.starts_with("TOML text: line 7, key `radus`: unknown field `radus`, expected `radius`"));
    /// ```
    ///
    /// # Errors
    /// [`Error::SceneFile`] with the line, the column and the key.
    pub fn from_toml(text: &str) -> Result<Scene> {
        parse_toml(text, "TOML text".into())
    }

    /// A scene from JSON text.
    ///
    /// # Errors
    /// [`Error::SceneFile`] with the line and the column.
    pub fn from_json(text: &str) -> Result<Scene> {
        parse_json(text, "JSON text".into())
    }
}

fn parse_json(text: &str, source_name: String) -> Result<Scene> {
    serde_json::from_str(text).map_err(|e| Error::SceneFile {
        source_name,
        detail: e.to_string(),
    })
}

fn parse_toml(text: &str, source_name: String) -> Result<Scene> {
    toml::from_str(text).map_err(|e| {
        let message = e.message().to_string();
        // toml points at the table for a field of a tagged table; find the
        // key's own line after it.
        let from = e.span().map_or(0, |s| s.start);
        let key = unknown_field(&message).and_then(|k| key_line(text, from, k).map(|l| (k, l)));
        let detail = match key {
            Some((k, line)) => format!("line {line}, key `{k}`: {message}\n{e}"),
            None => e.to_string(),
        };
        Error::SceneFile {
            source_name,
            detail: detail.trim_end().to_string(),
        }
    })
}

/// The field in serde's "unknown field `x`, expected ..." message.
fn unknown_field(message: &str) -> Option<&str> {
    let rest = message.strip_prefix("unknown field `")?;
    rest.split('`').next()
}

/// The 1-based line, at or after byte `from`, where `key` is assigned.
fn key_line(text: &str, from: usize, key: &str) -> Option<usize> {
    let first = text.get(..from)?.lines().count().max(1);
    text.lines()
        .enumerate()
        .skip(first - 1)
        .find(|(_, line)| {
            line.trim_start()
                .strip_prefix(key)
                .is_some_and(|rest| rest.trim_start().starts_with('='))
        })
        .map(|(index, _)| index + 1)
}
