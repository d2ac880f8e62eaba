//! Scene input: everything a run starts from, before any pipeline. Its files from the bottom up,
//! each using only files listed before it (and nothing of this `mod.rs`):
//!
//! - [`json`]: strict JSON and the value readers of scene files;
//! - [`tri`]: one scene triangle (f64 clip space) and its rounding to the core's inputs;
//! - [`pattern`]: sample patterns (exact and quantized sample tables);
//! - [`budget`]: the memory budget checked before anything large is allocated;
//! - [`mesh`]: the convenience form (meshes, camera, lens) turned into scene triangles;
//! - [`file`](mod@file): scene files (`"format":"uvt-scene"`) and the validated [`file::Scene`];
//! - [`builtin`]: the built-in scenes (the default scene, the benchmark scenes).

pub mod budget;
pub mod builtin;
pub mod file;
pub mod json;
pub mod mesh;
pub mod pattern;
pub mod tri;
