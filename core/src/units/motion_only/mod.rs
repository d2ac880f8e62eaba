//! The motion-only unit at a bounded precision: its setup and slab cull ([`setup`]), its sample
//! test ([`sample`]) with its depth ([`depth`]), and its renderer ([`render`]).

pub(crate) mod depth;
pub mod render;
pub mod sample;
pub mod setup;
