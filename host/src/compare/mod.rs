//! The core against the f64 reference, sample by sample. Its files from the bottom up, each using
//! only files listed before it (and nothing of this `mod.rs`):
//!
//! - [`bound`]: the quantization bound — where a differing decision is explained by the inputs'
//!   rounding and the datapath's perturbation;
//! - [`pass`]: **the one comparison** of every footprint sample, culled ones included: decisions
//!   under the bound and the error statements, depth, and the bounds' conservativeness.

pub mod bound;
pub mod pass;
