//! Golden test vectors for RTL: export, check, and the format they share. See `vectors/README.md`.
//! Its files from the bottom up, each using only files listed before it (and nothing of this
//! `mod.rs`):
//!
//! - [`format`](mod@format): the file format, shared by the generator and the checker;
//! - [`stages`]: input record → core → expected output record, per stage;
//! - [`cases`]: the named edge cases of the unit-level set;
//! - [`bsample`]: the bounded sample-test records;
//! - [`planar_cases`]: the planar records' own triangles;
//! - [`psample`]: the planar sample-test records;
//! - [`export`]: `uvt vectors export`, the unit-level and frame-level sets;
//! - [`check`]: `uvt vectors check`;
//! - [`committed`]: the committed sets and their exports.

pub mod bsample;
pub mod cases;
pub mod check;
pub mod committed;
pub mod export;
pub mod format;
pub mod planar_cases;
pub mod psample;
pub mod stages;
