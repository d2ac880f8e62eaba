//! `uvt bench-ste`: the STE benchmark table. [`strategy`] runs one bounds strategy of the core
//! over a frame by name, at any precision (also used by `uvt converge` and `uvt fit`);
//! [`ste_table`] runs every strategy, the f64 reference and the axis-aligned limit over the
//! benchmark scenes and writes the table. `ste_table` uses `strategy`, never the other way round
//! (nor this `mod.rs`).

pub mod ste_table;
pub mod strategy;
