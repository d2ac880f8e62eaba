//! The units' pipelines and the one place that picks them: what a pipeline is
//! ([`pipeline`]), the general pipeline every unit runs at an exact precision ([`general`]),
//! the static-only unit's own pipeline at a planar precision ([`static_only`]), the motion-only
//! unit's own pipeline at a bounded precision ([`motion_only`]), and the choice between them
//! ([`select`]).

pub mod general;
pub mod motion_only;
pub mod pipeline;
pub mod select;
pub mod static_only;
