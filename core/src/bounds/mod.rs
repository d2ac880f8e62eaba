//! Stage 2 — per-tile (u, v, t) bounds behind one replaceable interface ([`strategy`]): the
//! bounding-box scan ([`bbox`]), Laine et al. 2011 ([`laine`]), and the tighter strategies —
//! swept-hull tile culling ([`hull`]), lens-dependent time bounds ([`lens_time`]), bilinear
//! (u, t) / (v, t) surfaces ([`hyper`]), the edge-direction time bound ([`edge_time`]) — with
//! their compositions ([`composed`]), the per-triangle choice among them ([`auto`]) and the list
//! of every named strategy ([`registry`]). The conservativeness proof of each is at the top of
//! its file.

// First, with its macros: the one list of strategies is in textual scope for `any` below and,
// through the crate root's `#[macro_use] pub mod bounds`, for `widths` (no path back to the root).
#[macro_use]
pub mod registry;

pub mod any;
pub mod auto;
pub mod bbox;
pub mod composed;
pub mod edge_time;
pub mod hull;
pub mod hyper;
pub mod laine;
pub mod lens_time;
pub mod strategy;
