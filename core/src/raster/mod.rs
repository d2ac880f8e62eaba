//! Stage 4 — the tile framebuffer ([`tile_buffer`]) and the render loop ([`renderer`]).

pub mod renderer;
pub mod tile_buffer;
