//! Configurations and what they cost: the multiplier model of a configuration's stages, the
//! unit variants' sample-test cost, the documented error distance d_q of a primitive, and the
//! planar static configuration. `uvt fit`, `uvt precision`, `uvt units` and `bench-ste` use these.
//! Its files from the bottom up, each using only files listed before it (and nothing of this
//! `mod.rs`):
//!
//! - [`names`]: the core's configuration and bounds-strategy registries on the command line
//!   (what `--precision`, `--config` and `--bounds` accept);
//! - [`multipliers`]: hard multipliers (DSP48E1, ECP5) and LUT bits of a configuration's stages;
//! - [`strategy_cost`]: the width-weighted hardware figure of every bounds strategy's stages
//!   (operators of `uvt_core::widths::strategies`, tiled by [`multipliers`]);
//! - [`units`]: the unit variants and their sample-test multipliers at a configuration;
//! - [`rounding`]: what a configuration's core perturbs — the inputs' rounding and the bounded
//!   test's vertex perturbation;
//! - [`dq`]: the error statements: the documented error distance d_q of a primitive, its
//!   backward error, the tolerance;
//! - [`planar_static`]: the planar static configuration (`uvt_core::config::registry::PLANAR`).

pub mod dq;
pub mod multipliers;
pub mod names;
pub mod planar_static;
pub mod rounding;
pub mod strategy_cost;
pub mod units;
