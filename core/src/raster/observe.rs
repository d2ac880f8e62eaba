//! What a caller may watch of the render loop ([`crate::raster::engine`]): every bounds tile of
//! every triangle with what became of it ([`Fate`]), every sample the loop tests with its
//! decisions ([`Seen`]), and the end of each kept tile. A tool's counters, an oracle or a trace
//! of every stage are observers; the loop itself counts what [`crate::Stats`] holds.
//!
//! Every hook does nothing by default, so a loop run with [`Unobserved`] compiles to the loop
//! alone (the Cortex-M programs' renderers).

use crate::bounds::strategy::UvtBox;
use crate::input::{PixelRect, Sample};
use crate::raster::store::DepthTest;
use crate::sample::pos::Hit;

/// What became of one bounds tile of a triangle's walk.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fate {
    /// culled by the tile step (or outside its row's span): no sample is tested
    Skipped,
    /// kept by the tile step, then skipped by Zmax culling: no sample is tested
    Zculled,
    /// kept: its samples go through the tile's admission, then the sample test; `bounds` holds
    /// every sample the tile admits (`Admit::enclosing_box`)
    Kept {
        /// the tile's (u, v, t) box
        bounds: UvtBox,
    },
}

/// One sample of a kept tile as the loop saw it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Seen {
    /// the tile admitted it (it was tested and counted); `false` only for an observer that asks
    /// for the culled samples too ([`Observer::CULLED_SAMPLES`])
    pub admitted: bool,
    /// the sample test's hit (depth), if covered
    pub hit: Option<Hit>,
    /// the depth test's outcome of an admitted hit (`None` for a miss or a culled sample)
    pub depth_test: Option<DepthTest>,
}

/// A watcher of the render loop (module docs). `tri` is the triangle's index in the list the
/// caller submitted; pixels are screen pixels; `si` is the sample's index in its pixel.
pub trait Observer {
    /// Also run the sample test on the samples of a kept tile that the tile does not admit, and
    /// hand them to [`Observer::sample`] with `admitted = false`: not counted, never written
    /// (a trace shows that they miss). Default: no.
    const CULLED_SAMPLES: bool = false;
    /// A bounds tile `cell` of triangle `tri` and its fate, before any of its samples.
    #[inline(always)]
    fn cell(&mut self, _tri: u32, _cell: PixelRect, _fate: Fate) {}
    /// Sample `si` of pixel (`px`, `py`) of a kept tile of triangle `tri`.
    #[inline(always)]
    fn sample(&mut self, _tri: u32, _px: u16, _py: u16, _si: usize, _s: &Sample, _seen: Seen) {}
    /// The end of a kept tile's samples.
    #[inline(always)]
    fn cell_end(&mut self, _tri: u32, _cell: PixelRect) {}
}

/// No observer: the loop alone.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Unobserved;

impl Observer for Unobserved {}
