//! The scene files' schema and key reference against the scene types, and
//! mistakes named by their key path.
#![cfg(feature = "serde")]

use layered_contact::scene::Scene;

#[test]
fn the_key_reference_in_the_docs_matches_the_types() {
    // src/doc/scene_keys.md is what `layered-contact schema --markdown`
    // printed; regenerate it when a scene type changes.
    let committed = include_str!("../src/doc/scene_keys.md");
    assert_eq!(committed.trim_end(), Scene::key_reference().trim_end());
}

#[test]
fn the_schema_defaults_are_the_types_defaults() {
    // Every default the schema states for a top-level table reads back,
    // through serde, as the value `Scene` takes when the key is left out.
    let schema: serde_json::Value = serde_json::from_str(&Scene::json_schema()).unwrap();
    let minimal = serde_json::json!({
        "substrate": {"kind": "half_space", "youngs_modulus": 1e6, "poisson_ratio": 0.5},
        "indenter": {"kind": "sphere", "radius": 0.01},
        "protocol": {"kind": "depth", "depth": 1e-5},
    });
    let bare: Scene = serde_json::from_value(minimal.clone()).unwrap();
    let properties = schema["properties"].as_object().unwrap();
    let mut checked = 0;
    for (key, property) in properties {
        let Some(default) = property.get("default") else {
            continue;
        };
        let mut explicit = minimal.clone();
        explicit[key] = default.clone();
        let scene: Scene = serde_json::from_value(explicit).unwrap();
        assert_eq!(scene, bare, "{key}");
        checked += 1;
    }
    // adhesion, boundary, outputs, resolution, solver, tilt.
    assert_eq!(checked, 6);
}

#[test]
fn mistakes_in_json_are_named_by_their_key_path() {
    let scene = |indenter: &str, substrate: &str, rest: &str| {
        format!(
            r#"{{"substrate": {substrate}, "indenter": {indenter},
                 "protocol": {{"kind": "depth", "depth": 1e-5}}{rest}}}"#
        )
    };
    let half_space = r#"{"kind": "half_space", "youngs_modulus": 1e6, "poisson_ratio": 0.5}"#;
    let sphere = r#"{"kind": "sphere", "radius": 0.01}"#;
    let cases = [
        (
            scene(r#"{"kind": "sphere", "radius": "x"}"#, half_space, ""),
            "key `indenter.radius`: invalid type: string \"x\", expected f64",
        ),
        (
            scene(r#"{"kind": "sphere", "radus": 0.01}"#, half_space, ""),
            "key `indenter.radus`: unknown field `radus`, expected `radius`",
        ),
        (
            scene(
                sphere,
                half_space,
                r#", "resolution": {"cells_across": "a"}"#,
            ),
            "key `resolution.cells_across`: invalid type: string \"a\", expected usize",
        ),
        (
            scene(sphere, half_space, r#", "resolutio": {}"#),
            "key `resolutio`: unknown field `resolutio`",
        ),
        (
            scene(
                sphere,
                r#"{"kind": "stack", "base": null, "layers": [
                    {"youngs_modulus": 1e6, "poisson_ratio": 0.5, "thickness": 1e-3},
                    {"youngs_modulus": 1e6, "poisson_ratio": 0.5, "thickness": "q"}]}"#,
                "",
            ),
            "key `substrate.layers[1].thickness`: invalid type: string \"q\", expected f64",
        ),
    ];
    for (text, expected) in cases {
        let error = Scene::from_json(&text).unwrap_err().to_string();
        assert!(
            error.starts_with(&format!("JSON text: {expected}")),
            "{error}"
        );
    }
    // A syntax error keeps its line and column.
    let error = Scene::from_json("{\n\"substrate\": }")
        .unwrap_err()
        .to_string();
    assert!(error.contains("line 2 column 14"), "{error}");
}
