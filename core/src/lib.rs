//! # uvt-core
//!
//! A bit-accurate fixed-point reference model of a fixed-function stochastic rasterizer with
//! motion blur and defocus blur: the golden model RTL is checked against. `no_std`, no heap, no
//! floating point, no panics: every input outside the declared domain is refused with an
//! [`Error`].
//!
//! Pipeline, one module per stage (read them in this order):
//! 1. [`setup`] — once per triangle: class, culling, lens-corner boxes, footprint, time span.
//! 2. [`bounds`] — per bounds tile: (u, v, t) intervals, behind the [`BoundsStrategy`] trait
//!    ([`Laine2011`] dual-space bounds; [`BboxScan`] as the baseline; tighter, composable
//!    strategies in [`strategies`]).
//! 3. [`sample`] — the exact 5D sample test with a fill rule, and depth; [`bounded`] — the
//!    bounded (hardware-width) sample test of a [`Bounded`] precision; [`planar`] — the static
//!    test of a [`Planar`] precision (vertices rounded once to 15 bits).
//! 4. [`tile`] — the tile framebuffer, resolve and the render loop; [`static_unit`] — the
//!    static-only unit's own setup, 2D tile cull, sample test and renderer at a [`Planar`]
//!    precision; [`motion_unit`] — the motion-only unit's own setup, time-slab tile cull,
//!    sample test ([`motion_test`]) and renderer ([`motion_render`]) at a bounded precision.
//!
//! Number formats are all in [`formats`]; `core/README.md` has the full width table.
#![cfg_attr(not(test), no_std)]
#![forbid(unsafe_code)]
#![deny(missing_docs)]
// The proof obligations of "nothing overflows, nothing panics": every arithmetic operator,
// index and narrowing cast is flagged; each remaining one carries an `#[allow]` on the smallest
// item with the range argument beside it. (Warnings are errors in CI: `-D warnings`.)
#![warn(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_possible_wrap
)]

pub mod bounded;
#[cfg(test)]
mod bounded_corners;
#[cfg(test)]
mod bounded_frozen;
pub mod bounds;
#[cfg(test)]
mod corners;
pub mod demo;
pub mod error;
#[cfg(test)]
mod fast_corners;
pub mod formats;
pub mod input;
pub mod interval;
#[cfg(test)]
mod interval_corners;
mod motion_depth;
pub mod motion_render;
pub mod motion_test;
pub mod motion_unit;
pub mod planar;
#[cfg(test)]
mod planar_corners;
#[cfg(test)]
mod planar_frozen;
pub mod sample;
pub mod setup;
pub mod static_unit;
pub mod stats;
pub mod strategies;
#[cfg(test)]
mod testrng;
pub mod tile;
pub mod unit;
pub mod wide;
#[cfg(test)]
mod width_corners;
pub mod widths;

pub use bounded::{bounded_eval, bounded_test, BoundedEval, Eps};
pub use bounds::{walk_tiles, BboxScan, BoundsStrategy, Laine2011, RowSpan, TileBounds, UvtBox};
pub use embedded_graphics_core::pixelcolor::Rgb888;
pub use error::{Error, Field, SampleField};
pub use formats::{
    Bounded, BoundedPrecision, Coord, DefaultPrecision, Depth, Exact, Lens, Planar,
    PlanarPrecision, Prec, Precision, PrecisionBits, SubPixel, Time,
};
pub use input::{PixelRect, Sample, SamplePattern, Triangle, Vertex, Viewport};
pub use interval::Interval;
pub use motion_render::{MotionEntry, MotionRenderer};
pub use motion_unit::{MotionOutcome, MotionSetup};
pub use sample::{sample_eval, sample_test, Hit, SampleEval, ScreenPos};
pub use setup::{setup, setup_scaled, setup_with, Class, Cull, Outcome, Setup};
pub use static_unit::{StaticRenderer, StaticSetup};
pub use stats::{Ops, Stats};
pub use tile::{resolve_colors, DepthTest, PixelStats, Prim, RenderError, Renderer, TileBuffer};
pub use unit::{DefocusOnly, Full, MotionOnly, StaticOnly, Unit};
pub use wide::Wide;
