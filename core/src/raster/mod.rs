//! Stage 4 — where covered samples go ([`store`]: the one depth test; [`tile_buffer`]: the
//! screen tile's buffer and resolve), **the one render loop** ([`engine`]) with what a caller may
//! watch of it ([`observe`]) and its optional Zmax culling ([`zmax`]), and the no-heap renderer
//! over it ([`renderer`]).

pub mod engine;
pub mod observe;
pub mod renderer;
pub mod store;
pub mod tile_buffer;
pub mod zmax;
