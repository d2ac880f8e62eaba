//! Stage 2 — per-tile (u, v, t) bounds behind one replaceable interface ([`strategy`]): the
//! bounding-box scan ([`bbox`]), Laine et al. 2011 ([`laine`]), and the tighter strategies —
//! swept-hull tile culling ([`hull`]), lens-dependent time bounds ([`lens_time`]), bilinear
//! (u, t) / (v, t) surfaces ([`hyper`]), the edge-direction time bound ([`edge_time`]) — with
//! their compositions ([`composed`]), the per-triangle choice among them ([`auto`]) and the list
//! of every named strategy ([`registry`]). The conservativeness proof of each is at the top of
//! its file.

pub mod any;
pub mod auto;
pub mod bbox;
pub mod composed;
pub mod edge_time;
pub mod hull;
pub mod hyper;
pub mod laine;
pub mod lens_time;
pub mod registry;
pub mod strategy;
