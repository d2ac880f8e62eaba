//! `uvt fit SCENE.json`: which rasterizer unit a scene needs, and what it saves — the smallest unit
//! variant (`uvt_core::config::unit`) that accepts every primitive's class, the narrowest configuration of
//! the precision sweep (`uvt_core::config::registry::sweep`) whose documented error distance
//! meets the tolerance *for this scene's geometry*, the bounds strategy and tile size with the most
//! covered samples per unit of cost; then a render with that choice to confirm it ([`confirm`]).
//! `uvt units` prints the variant table ([`units_table::units_md`]).
//!
//! Its files from the bottom up, each using only files listed before it (and nothing of this
//! `mod.rs`); below them are the configurations and their costs ([`crate::config`]):
//!
//! - [`m4`]: the Cortex-M4F figures of the unit programs;
//! - [`synth`]: the synthesized counts of the RTL units;
//! - [`units_table`]: the unit-variant table of `uvt units`;
//! - [`select`]: the selection — tolerance, d_q of every configuration, the narrowest one;
//! - [`search`]: the strategy and tile-size search, the scene's inputs on a configuration's grids;
//! - [`confirm`]: the confirmation render;
//! - [`report`]: `uvt fit`'s driver and its Markdown and JSON report.

pub mod confirm;
pub mod m4;
pub mod report;
pub mod search;
pub mod select;
pub mod synth;
pub mod units_table;
