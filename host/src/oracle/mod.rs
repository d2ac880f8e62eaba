//! The axis-aligned limit of `uvt bench-ste`: per bounds tile, an inner estimate of the tightest
//! axis-aligned (u, v, t) box of the triangle's coverage set (module docs of [`limit`]). Files:
//! [`search`] (the box search over a membership predicate) and [`clip`] (coverage of a tile at
//! one lens point and time) use nothing of the crate; [`limit`] uses both (nothing uses this
//! `mod.rs`).

pub mod clip;
pub mod limit;
pub mod search;
