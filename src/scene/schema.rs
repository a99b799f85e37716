//! The scene files' JSON Schema, generated from the scene types
//! (`schemars`, which reads their serde attributes and doc comments), and
//! the key reference of [`doc::scene_files`](crate::doc::scene_files)
//! rendered from it.

use super::Scene;

impl Scene {
    /// The JSON Schema (draft 2020-12) of a scene file, pretty-printed:
    /// every key with its type, default and description (units included),
    /// for editors and validators. `layered-contact schema` prints it.
    ///
    /// ```
    /// let schema = layered_contact::scene::Scene::json_schema();
    /// assert!(schema.contains("\"cells_across\""));
    /// ```
    pub fn json_schema() -> String {
        let schema = schemars::schema_for!(Scene);
        serde_json::to_string_pretty(&schema).unwrap_or_default()
    }
}

impl Scene {
    /// Every key of a scene file as a Markdown table (key path, type,
    /// default, description), rendered from [`Scene::json_schema`]: the
    /// reference in [`doc::scene_files`](crate::doc::scene_files).
    /// `layered-contact schema --markdown` prints it.
    pub fn key_reference() -> String {
        let schema = serde_json::to_value(schemars::schema_for!(Scene)).unwrap_or_default();
        let mut rows = Vec::new();
        rows_of(&schema, &schema, "", &mut rows, 0);
        let mut text = String::from("| key | type | default | description |\n|---|---|---|---|\n");
        for row in rows {
            text.push_str(&row);
            text.push('\n');
        }
        text
    }
}

use serde_json::Value;

/// How deep the scene's tables nest, at most (a guard on the walk).
const MAX_DEPTH: usize = 8;

/// The schema `node` refers to, through `$ref` into `root`'s `$defs`.
fn resolve<'a>(root: &'a Value, node: &'a Value) -> &'a Value {
    match node.get("$ref").and_then(Value::as_str) {
        Some(reference) => reference
            .strip_prefix("#/$defs/")
            .and_then(|name| root.get("$defs").and_then(|defs| defs.get(name)))
            .unwrap_or(node),
        None => node,
    }
}

/// A cell's text: one line, pipes escaped, rustdoc links reduced to code.
fn cell(text: &str) -> String {
    text.split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
        .replace('|', "\\|")
        .replace("](self)", "]")
        .replace("[`", "`")
        .replace("`]", "`")
}

/// The type of `node` in a few words.
fn type_of(root: &Value, node: &Value) -> String {
    let node = resolve(root, node);
    if let Some(options) = node.get("anyOf").and_then(Value::as_array) {
        let kinds: Vec<String> = options
            .iter()
            .filter(|o| o.get("type").and_then(Value::as_str) != Some("null"))
            .map(|o| type_of(root, o))
            .collect();
        return format!("{} (optional)", kinds.join(" or "));
    }
    if let Some(values) = node.get("enum").and_then(Value::as_array) {
        let names: Vec<String> = values.iter().map(|v| format!("`{v}`")).collect();
        return format!("one of {}", names.join(", "));
    }
    if let Some(variants) = node.get("oneOf").and_then(Value::as_array) {
        let names: Vec<String> = variants
            .iter()
            .filter_map(|v| resolve(root, v).get("const"))
            .map(|v| format!("`{v}`"))
            .collect();
        return if names.len() == variants.len() {
            format!("one of {}", names.join(", "))
        } else if variants
            .iter()
            .all(|v| resolve(root, v).pointer("/properties/kind/const").is_some())
        {
            "table, by `kind`".into()
        } else {
            "table with one of the keys below".into()
        };
    }
    match node.get("type") {
        Some(Value::String(t)) if t == "array" => match node.get("items") {
            Some(items) => format!("array of {}", type_of(root, items)),
            None => "array".into(),
        },
        Some(Value::String(t)) if t == "object" => "table".into(),
        Some(Value::String(t)) => t.clone(),
        Some(Value::Array(ts)) => {
            ts.iter()
                .filter_map(Value::as_str)
                .filter(|t| *t != "null")
                .collect::<Vec<_>>()
                .join(" or ")
                + " (optional)"
        }
        _ => "any".into(),
    }
}

/// Rows for the properties of `node` (and of the variants of a tagged
/// table) under the key path `prefix`.
fn rows_of(root: &Value, node: &Value, prefix: &str, rows: &mut Vec<String>, depth: usize) {
    if depth > MAX_DEPTH {
        return;
    }
    let node = resolve(root, node);
    if let Some(options) = node.get("anyOf").and_then(Value::as_array) {
        for option in options {
            rows_of(root, option, prefix, rows, depth + 1);
        }
        return;
    }
    if let Some(items) = node.get("items") {
        rows_of(root, items, &format!("{prefix}[]"), rows, depth + 1);
        return;
    }
    if let Some(variants) = node.get("oneOf").and_then(Value::as_array) {
        for variant in variants {
            let variant = resolve(root, variant);
            let description = variant
                .get("description")
                .and_then(Value::as_str)
                .unwrap_or("");
            if let Some(value) = variant.get("const") {
                // A unit variant: the value itself.
                rows.push(format!(
                    "| `{prefix} = {value}` | | | {} |",
                    cell(description)
                ));
                continue;
            }
            match variant.pointer("/properties/kind/const") {
                Some(kind) => rows.push(format!(
                    "| `{prefix}.kind = {kind}` | | | {} |",
                    cell(description)
                )),
                // A table with one key naming the variant: the variant's
                // description goes with that key.
                None => {
                    rows_of_properties(root, variant, prefix, rows, depth, description);
                    continue;
                }
            }
            rows_of_properties(root, variant, prefix, rows, depth, "");
        }
        return;
    }
    rows_of_properties(root, node, prefix, rows, depth, "");
}

/// Rows for the properties of `node`; a property without a description of
/// its own takes `fallback`.
fn rows_of_properties(
    root: &Value,
    node: &Value,
    prefix: &str,
    rows: &mut Vec<String>,
    depth: usize,
    fallback: &str,
) {
    let Some(properties) = node.get("properties").and_then(Value::as_object) else {
        return;
    };
    let required: Vec<&str> = node
        .get("required")
        .and_then(Value::as_array)
        .map(|r| r.iter().filter_map(Value::as_str).collect())
        .unwrap_or_default();
    for (key, property) in properties {
        if key == "kind" && property.get("const").is_some() {
            continue;
        }
        let path = if prefix.is_empty() {
            key.clone()
        } else {
            format!("{prefix}.{key}")
        };
        let default = match property.get("default") {
            Some(Value::Object(_)) | Some(Value::Array(_)) => "see below".to_string(),
            Some(v) => format!("`{v}`"),
            None if required.contains(&key.as_str()) => "required".to_string(),
            None => String::new(),
        };
        let description = property
            .get("description")
            .or_else(|| resolve(root, property).get("description"))
            .and_then(Value::as_str)
            .unwrap_or(fallback);
        rows.push(format!(
            "| `{path}` | {} | {default} | {} |",
            type_of(root, property),
            cell(description)
        ));
        rows_of(root, property, &path, rows, depth + 1);
    }
}
