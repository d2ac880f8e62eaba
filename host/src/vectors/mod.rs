//! Golden test vectors for RTL: export, check, and the format they share. See `vectors/README.md`.
//! Its files from the bottom up, each using only files listed before it (and nothing of this
//! `mod.rs`):
//!
//! - [`format`](mod@format) and [`stages`]: the record codec, from `uvt-records` (one codec for
//!   the host, the vectors and the C library `uvt-ffi`);
//! - [`cases`]: the named edge cases of the unit-level set;
//! - [`bsample`]: the bounded sample-test records;
//! - [`bsample_directed`]: bounded records directed at the fill rule's tie key;
//! - [`planar_cases`]: the planar records' own triangles;
//! - [`psample`]: the planar sample-test records;
//! - [`psample_directed`]: planar records directed at single decisions (single-bit edges, the
//!   depth exponent below −33);
//! - [`export`]: `uvt vectors export`, the unit-level and frame-level sets;
//! - [`check`]: `uvt vectors check`;
//! - [`pipe`]: `uvt vectors gen`, `ver` and `decode` (streams and single records);
//! - [`committed`]: the committed sets and their exports;
//! - [`coverage`]: `uvt vectors coverage`, the model's coverage bins over the committed sets and
//!   seeded streams.

pub mod bsample;
pub mod bsample_directed;
pub mod cases;
pub mod check;
pub mod committed;
pub mod coverage;
pub mod export;
pub mod pipe;
pub mod planar_cases;
pub mod psample;
pub mod psample_directed;
pub use uvt_records::{format, stages};
