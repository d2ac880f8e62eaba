//! The frame engine: runs a pipeline (the fixed-point core or the f64 reference) over a whole
//! frame and measures it, and compares the two sample by sample. Its files from the bottom up,
//! each using only files listed before it (and nothing of this `mod.rs`):
//!
//! - [`pipeline`]: the interface a pipeline implements ([`pipeline::FramePipeline`]); it uses
//!   nothing of the crate, which lets the scene's memory budget size the driver's per-triangle
//!   entry ([`crate::scene::budget`]);
//! - [`pipelines`]: the core and the reference as pipelines;
//! - [`counters`]: the counters of a frame and the rendered frame;
//! - [`driver`]: the frame driver ([`driver::run`]);
//! - [`compare`]: the core's coverage against the reference's, with the quantization bound.

pub mod compare;
pub mod counters;
pub mod driver;
pub mod pipeline;
pub mod pipelines;
