//! `uvt bench-ste`: the STE benchmark table. [`strategy`] runs one bounds strategy of the core
//! over a frame by name, at any precision (also used by `uvt converge` and `uvt fit`);
//! [`ste_table`] runs every strategy, the f64 reference and the axis-aligned limit over the
//! benchmark scenes and writes the table. `ste_table` uses `strategy`, never the other way round
//! (nor this `mod.rs`). [`workload`] writes a row's own work for the Cortex-M strategy
//! harness, [`m4_stages`] reads what it measured, and [`auto_rule`] derives the rule of the
//! `auto` strategy from it, measured against [`hindsight`]'s bounds. [`zmax`] (`uvt bench-zmax`) runs every strategy with and without
//! Zmax culling on the occlusion rows.

pub mod auto_rule;
pub mod hindsight;
pub mod m4_stages;
pub mod ste_table;
pub mod strategy;
pub mod workload;
pub mod zmax;
