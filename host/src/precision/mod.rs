//! `uvt precision`: the same core at several precisions against the f64 reference, with the cost
//! of each configuration. Its files from the bottom up, each using only files listed before it
//! (and nothing of this `mod.rs`):
//!
//! - [`row`]: one row of the table, the configurations swept and the documented d_q;
//! - [`costs`]: the cost side (multiplier model, M4 figures, synthesis) and the error/cost plot;
//! - [`measure`]: the brute-force measurement of one scene at one precision;
//! - [`sweep`]: the sweep over configurations, scenes and tile sizes, and the stress cases;
//! - [`tables`]: the Markdown tables.

pub mod costs;
pub mod measure;
pub mod row;
pub mod sweep;
pub mod tables;
