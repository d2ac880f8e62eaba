//! What a unit's pipeline is: setup once per triangle, a tile step per bounds tile and a sample
//! test per sample. The one render loop ([`crate::raster::renderer`]) and the cost workloads
//! drive every pipeline through [`Pipeline`]; [`crate::units::select`] picks the pipeline of a
//! (precision, unit).
//!
//! Three pipelines implement it: the general one ([`crate::units::general`]: setup, a
//! [`BoundsStrategy`] and the sample test of the precision, with the effects the unit lacks
//! compiled out), the static-only unit's at a planar precision
//! ([`crate::units::static_only`]) and the motion-only unit's at a bounded precision
//! ([`crate::units::motion_only`]). Every pipeline renders the same image as the full unit's
//! general pipeline at the same precision for every triangle its unit accepts (the module docs
//! of each say why); what differs is the work: tiles visited and skipped, samples tested, the
//! operation counts and the program.

use crate::bounds::strategy::{Admit, BoundsStrategy, CellVisitor};
use crate::config::class::Class;
use crate::config::formats::DEPTH_NEAR;
use crate::config::unit::Unit;
use crate::input::{PixelRect, Sample, Triangle, Viewport};
use crate::sample::pos::{Hit, ScreenPos};
use crate::setup::Outcome;
use crate::stats::Ops;

/// A unit's pipeline, stage by stage (module docs).
pub trait Pipeline: Sized {
    /// The bounds strategy the renderer is given: the general pipeline's per-tile bounds; the
    /// specialised pipelines have their own tile cull and keep it unused.
    type Bounds: BoundsStrategy;
    /// The unit whose pipeline this is (acceptance, refusal messages).
    type Unit: Unit;
    /// One visible triangle's data.
    type Entry: Copy;
    /// What the tile step hands the sample loop for a kept bounds tile (whether a sample of it
    /// is tested at all: [`Admit`], counted in `ops.predicate`).
    type Tile: Admit;
    /// The renderer's name in reports: `Renderer` (general), `StaticRenderer`,
    /// `MotionRenderer` (the type aliases of [`crate::raster::renderer`]).
    const NAME: &'static str;
    /// The pipeline with bounds strategy `bounds`.
    fn new(bounds: Self::Bounds) -> Self;
    /// Setup of one triangle: [`Outcome::Refused`] (nothing computed beyond
    /// [`Triangle::class`]) for a class the unit does not accept, else culled or visible.
    /// Counts in `ops.setup`.
    fn setup(&self, tri: &Triangle, vp: Viewport, ops: &mut Ops) -> Outcome<Self::Entry>;
    /// The class of a visible triangle.
    fn class(entry: &Self::Entry) -> Class;
    /// Pixels that may hold covered samples (inside the viewport).
    fn footprint(entry: &Self::Entry) -> PixelRect;
    /// The tile step of one bounds tile `cell` (counted in `ops.bounds`): `None` when the tile
    /// holds no covered sample (conservative: a sample the test covers is never culled).
    fn tile(&self, entry: &Self::Entry, cell: PixelRect, ops: &mut Ops) -> Option<Self::Tile>;
    /// Walk the bounds tiles (`bt` pixels, aligned to the `bt` grid) of `region`, a part of the
    /// footprint, in raster order, handing `v` each cell with its tile step. Default: every
    /// cell of `region.cells(bt)` through [`Self::tile`]; the general pipeline walks row by row
    /// with its strategy's row spans ([`BoundsStrategy::walk`]), whose tiles may be of another
    /// type than [`Self::Tile`] (`auto` hands over the picked strategy's).
    fn walk<V: CellVisitor>(
        &self,
        entry: &Self::Entry,
        region: PixelRect,
        bt: u16,
        ops: &mut Ops,
        v: &mut V,
    ) {
        for cell in region.cells(bt) {
            let t = self.tile(entry, cell, ops);
            v.cell(cell, t, ops);
        }
    }
    /// The sample test of a sample at screen position `pos`: the depth on a hit.
    fn test(entry: &Self::Entry, pos: ScreenPos, s: &Sample, ops: &mut Ops) -> Option<Hit>;
    /// A lower bound of every depth [`Self::test`] outputs for this triangle (Zmax culling,
    /// [`crate::raster::zmax`]), its operations counted in `ops.zmax`. Default:
    /// [`DEPTH_NEAR`], never culled.
    fn depth_floor(_entry: &Self::Entry, _ops: &mut Ops) -> i32 {
        DEPTH_NEAR
    }
    /// The operations of one sample test that [`Self::test`] does not count itself (the
    /// specialised units count theirs in the render loop; default: none).
    #[inline(always)]
    fn count(_covered: bool, _ops: &mut Ops) {}
}
