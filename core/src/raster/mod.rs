//! Stage 4 — the tile framebuffer ([`tile_buffer`]), the render loop ([`renderer`]) and its
//! optional Zmax culling ([`zmax`]).

pub mod renderer;
pub mod tile_buffer;
pub mod zmax;
