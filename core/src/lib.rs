//! # uvt-core
//!
//! A bit-accurate fixed-point reference model of a fixed-function stochastic rasterizer with
//! motion blur and defocus blur: the golden model RTL is checked against. `no_std`, no heap, no
//! floating point, no panics: every input outside the declared domain is refused with an
//! [`Error`].
//!
//! Pipeline, one folder per block (read them in this order):
//! 1. [`setup`] — once per triangle: class, culling, lens-corner boxes, footprint, time span,
//!    the conservative epsilon and the planar test's per-triangle setup.
//! 2. [`bounds`] — per bounds tile: (u, v, t) intervals, behind the [`BoundsStrategy`] trait
//!    ([`Laine2011`] dual-space bounds; [`BboxScan`] as the baseline; tighter, composable
//!    strategies beside them).
//! 3. [`sample`] — the sample test: the exact test, the bounded (hardware-width) test of a
//!    [`Bounded`] precision and the planar static test of a [`Planar`] precision, behind one
//!    dispatch.
//! 4. [`raster`] — the one render loop ([`Engine`]: any region of the screen into any sample
//!    store, watched by an [`Observer`]), the tile framebuffer, resolve, the no-heap
//!    [`Renderer`] and the optional Zmax culling ([`Zmax`], Akenine-Möller et al. 2007 §3.4);
//!    [`units`] — the
//!    static-only unit's own setup, 2D tile cull and sample test at a [`Planar`] precision, and
//!    the motion-only unit's own setup, time-slab tile cull and sample test at a bounded
//!    precision.
//!
//! Below them: [`config`] (every signal's format, the precision types, the units, the class),
//! [`arith`] (wide accumulator, intervals, divisions), [`input`], [`error`], [`stats`]. The
//! width table of every intermediate is [`widths`]; `core/README.md` has it.
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

pub mod arith;
// With its macros (the strategies' one list, `bounds::registry`) in textual scope below.
#[macro_use]
pub mod bounds;
pub mod config;
pub mod coverage;
pub mod error;
pub mod input;
pub mod raster;
pub mod sample;
pub mod setup;
pub mod stats;
pub mod units;
#[cfg(test)]
mod verify;
pub mod widths;

pub use arith::interval::Interval;
pub use arith::wide::Wide;
pub use bounds::bbox::BboxScan;
pub use bounds::laine::Laine2011;
pub use bounds::strategy::{walk_tiles, BoundsStrategy, RowSpan, TileBounds, UvtBox};
pub use config::class::Class;
pub use config::formats::{Coord, Depth, Lens, SubPixel, Time};
pub use config::precision::{
    Bounded, BoundedPrecision, DefaultPrecision, Exact, Planar, PlanarPrecision, Prec, Precision,
    PrecisionBits,
};
pub use config::unit::{DefocusOnly, Full, MotionOnly, StaticOnly, Unit};
pub use embedded_graphics_core::pixelcolor::Rgb888;
pub use error::{Error, Field, SampleField};
pub use input::{PixelRect, Prim, Sample, SamplePattern, Triangle, Vertex, Viewport};
pub use raster::engine::{Drawn, Engine};
pub use raster::observe::{Fate, Observer, Seen, Unobserved};
pub use raster::renderer::{MotionRenderer, Raster, RenderError, Renderer, StaticRenderer};
pub use raster::store::{resolve_colors, DepthTest, PixelStats, RegionBuffer, SampleStore};
pub use raster::tile_buffer::TileBuffer;
pub use raster::zmax::{DepthCull, NoZmax, RegionMax, Zmax};
pub use sample::bounded::BoundedEval;
pub use sample::exact::ExactEval;
pub use sample::planar::PlanarEval;
pub use sample::pos::{Hit, ScreenPos};
pub use setup::eps::Eps;
pub use setup::{setup, setup_scaled, Cull, Outcome, Setup};
pub use stats::{Ops, Stats};
pub use units::general::General;
pub use units::motion_only::setup::MotionSetup;
pub use units::motion_only::{MotionEntry, MotionPipeline};
pub use units::pipeline::Pipeline;
pub use units::select::{PipelineOf, Select};
pub use units::static_only::setup::StaticSetup;
pub use units::static_only::StaticPipeline;
