//! # Scene files: the reference
//!
//! A scene ([`Scene`](crate::scene::Scene)) describes one contact
//! experiment: the body, the indenter, adhesion, how the indenter is
//! driven, the grid and what to keep. The tool reads it from a TOML file
//! (`layered-contact run scene.toml`), or JSON by the `.json` extension;
//! Python takes the same keys as a dict (`layered_contact.run_scene`).
//! A minimal scene:
//!
//! ```toml
//! [substrate]
//! kind = "layer_on_rigid_base"   # a rubber film on glass
//! youngs_modulus = 0.324e6       # Pa
//! poisson_ratio = 0.48
//! thickness = 10e-3              # m
//!
//! [indenter]
//! kind = "sphere"
//! radius = 30e-3                 # m
//!
//! [protocol]
//! kind = "cycle"                 # press to max_depth and pull back off
//! max_depth = 0.3e-3             # m
//! steps = 15
//! ```
//!
//! `examples/scenes/` has more (an adhesive cycle, a stack, stresses below
//! the surface, a flat punch in JSON, a periodic array of pillars).
//!
//! **Validation.** `layered-contact schema` prints the JSON Schema of a
//! scene ([`Scene::json_schema`](crate::scene::Scene::json_schema),
//! generated from the scene types and their doc comments): point an
//! editor's TOML or JSON language server at it for completion and
//! checking as you type, or validate with any JSON Schema tool
//! (the Python tests validate every example scene with `jsonschema`).
//! `layered-contact check scene.toml` goes further: it builds the grid
//! and checks the ranges the schema cannot express (a Poisson ratio
//! below 0.5, a grid that fits in memory) before anything is solved.
//!
//! **Mistakes** are reported by key. In a TOML file, a misspelt key by
//! its line and name:
//!
//! ```text
//! line 7, key `radus`: unknown field `radus`, expected `radius`
//! ```
//!
//! In JSON and in Python dicts, by the key's path:
//!
//! ```text
//! key `indenter.radius`: invalid type: string "x", expected f64
//! key `substrate.layers[1].thickness`: invalid type: string "q", expected f64
//! ```
//!
//! ## Every key
//!
//! Units are SI (m, Pa, N, J/m^2, radians). Tables chosen by `kind` list
//! each kind's keys under its `kind = ...` row. `layered-contact schema
//! --markdown` prints this table; a test checks that it matches the types.
//!
#![doc = include_str!("scene_keys.md")]
