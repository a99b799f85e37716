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
    let value: serde_json::Value = serde_json::from_str(text).map_err(|e| Error::SceneFile {
        source_name: source_name.clone(),
        detail: e.to_string(),
    })?;
    from_value(&value).map_err(|detail| Error::SceneFile {
        source_name,
        detail,
    })
}

/// A scene from a parsed JSON value; a mistake is named by its key path
/// (`indenter.radius`, `substrate.layers[1].thickness`).
fn from_value(value: &serde_json::Value) -> std::result::Result<Scene, String> {
    let (mut path, message) = match serde_path_to_error::deserialize::<_, Scene>(value) {
        Ok(scene) => return Ok(scene),
        Err(e) => {
            let segments = e.path().iter().map(Segment::from).collect::<Vec<_>>();
            (segments, e.into_inner().to_string())
        }
    };
    if let Some(field) = unknown_field(&message) {
        if path.last() != Some(&Segment::Key(field.to_string())) {
            path.push(Segment::Key(field.to_string()));
        }
    } else {
        refine(value, &mut path, &message);
    }
    let path = path.iter().fold(String::new(), |mut text, segment| {
        match segment {
            Segment::Key(key) if text.is_empty() => text.push_str(key),
            Segment::Key(key) => {
                text.push('.');
                text.push_str(key);
            }
            Segment::Index(i) => text.push_str(&format!("[{i}]")),
        }
        text
    });
    Err(if path.is_empty() {
        message
    } else {
        format!("key `{path}`: {message}")
    })
}

/// One step of a key path.
#[derive(Debug, Clone, PartialEq)]
enum Segment {
    Key(String),
    Index(usize),
}

impl From<&serde_path_to_error::Segment> for Segment {
    fn from(segment: &serde_path_to_error::Segment) -> Self {
        match segment {
            serde_path_to_error::Segment::Seq { index } => Segment::Index(*index),
            serde_path_to_error::Segment::Map { key } => Segment::Key(key.clone()),
            serde_path_to_error::Segment::Enum { variant } => Segment::Key(variant.clone()),
            serde_path_to_error::Segment::Unknown => Segment::Key("?".into()),
        }
    }
}

/// Serde reads a tagged table's fields from a buffer and does not name
/// them, so the path it reports ends at the table. Below it, the child
/// whose removal changes the error holds the mistake: descend into it
/// while there is one (the tag `kind` is skipped; removing it always
/// changes the error). Bounded by the depth of the value.
fn refine(root: &serde_json::Value, path: &mut Vec<Segment>, message: &str) {
    while let Some(node) = lookup(root, path) {
        let children: Vec<Segment> = match node {
            serde_json::Value::Object(map) => map
                .keys()
                .filter(|k| k.as_str() != "kind")
                .map(|k| Segment::Key(k.clone()))
                .collect(),
            serde_json::Value::Array(items) => (0..items.len()).map(Segment::Index).collect(),
            _ => return,
        };
        let culprit = children.into_iter().find(|child| {
            let mut pruned = root.clone();
            remove(&mut pruned, path, child);
            match serde_path_to_error::deserialize::<_, Scene>(&pruned) {
                Ok(_) => true,
                Err(e) => e.into_inner().to_string() != message,
            }
        });
        match culprit {
            Some(child) => path.push(child),
            None => return,
        }
    }
}

/// The value at `path` below `root`.
fn lookup<'a>(root: &'a serde_json::Value, path: &[Segment]) -> Option<&'a serde_json::Value> {
    path.iter().try_fold(root, |node, segment| match segment {
        Segment::Key(key) => node.get(key.as_str()),
        Segment::Index(i) => node.get(*i),
    })
}

/// Removes `child` of the value at `path` below `root`.
fn remove(root: &mut serde_json::Value, path: &[Segment], child: &Segment) {
    let mut node = Some(root);
    for segment in path {
        node = node.and_then(|n| match segment {
            Segment::Key(key) => n.get_mut(key.as_str()),
            Segment::Index(i) => n.get_mut(*i),
        });
    }
    match (node, child) {
        (Some(serde_json::Value::Object(map)), Segment::Key(key)) => {
            map.remove(key);
        }
        (Some(serde_json::Value::Array(items)), Segment::Index(i)) if *i < items.len() => {
            items.remove(*i);
        }
        _ => {}
    }
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
