//! The interface between the frame driver and a pipeline: what a pipeline (the fixed-point core,
//! the f64 reference) must answer per triangle, per tile and per sample so that the driver can
//! run it over a frame and count what it does.

use uvt_core::{Class, Cull, Ops, PixelRect};

/// Setup result of a pipeline.
pub enum SetupOut<S> {
    /// visible, with its class
    Visible(S, Class),
    /// culled
    Culled(Cull),
}

/// A kept bounds tile as the driver's per-sample loop sees it: whether a sample (`S`, the
/// pipeline's view of one table entry) is tested, and the tile as real (u, v, t) ranges (for
/// the oracle).
pub trait FrameTile<S>: Copy {
    /// whether sample `s` lies inside the bounds (box, then the strategy's per-sample
    /// predicate, counted in `ops.predicate`)
    fn inside(&self, s: &S, ops: &mut Ops) -> bool;
    /// the bounds as real (u, v, t) ranges
    fn ranges(&self) -> [(f64, f64); 3];
}

/// The receiver of a pipeline's bounds-tile walk ([`FramePipeline::walk`]): each cell in raster
/// order with its tile, `None` for one skipped (outside its row's span or culled). Generic in
/// the tile type, like the core's `CellVisitor`: a strategy that picks another per triangle
/// (`auto`) hands its cells to a per-sample loop compiled for the picked strategy's tile.
pub trait TileSink<S> {
    /// One bounds tile `cell` of the walk and its bounds.
    fn cell<T: FrameTile<S>>(&mut self, cell: PixelRect, tile: Option<T>, ops: &mut Ops);
}

/// One rasterization pipeline the driver can run.
pub trait FramePipeline: Sync {
    /// per-triangle data: the triangle's setup (the bounds strategy's coefficients are built
    /// from it in [`Self::walk`])
    type Setup: Send + Sync;
    /// one entry of the sample table as this pipeline reads it
    type Sample;
    /// setup of triangle `i`
    fn setup(&self, i: usize, ops: &mut Ops) -> SetupOut<Self::Setup>;
    /// footprint of a setup
    fn footprint(&self, s: &Self::Setup) -> PixelRect;
    /// The bounds strategy's coefficients for `s` (their ops in `prep`), then the walk of
    /// `region`'s bounds tiles (aligned to the `bt` grid, clipped to `region`) in raster order,
    /// row by row with each row's span, handing every cell to `v` (the core's
    /// `BoundsStrategy::prepare` and `BoundsStrategy::walk`: row-span ops in `ops.rows`, tile
    /// ops in `ops.bounds`). The coefficients live only here, so no copy of them is ever moved.
    fn walk<V: TileSink<Self::Sample>>(
        &self,
        s: &Self::Setup,
        region: PixelRect,
        bt: u16,
        prep: &mut Ops,
        ops: &mut Ops,
        v: &mut V,
    );
    /// entry `idx` of the sample table
    fn sample(&self, idx: usize) -> &Self::Sample;
    /// (u, v, t) of sample `idx` as this pipeline sees it
    fn uvt(&self, idx: usize) -> [f64; 3];
    /// sample test: depth on a hit
    fn test(&self, s: &Self::Setup, px: u16, py: u16, idx: usize, ops: &mut Ops) -> Option<f64>;
    /// the far depth the buffer is cleared to
    fn far(&self) -> f64;
    /// a lower bound of every depth [`Self::test`] outputs for the triangle (Zmax culling,
    /// `uvt_core::raster::zmax`), its operations counted in `ops.zmax`; default: −∞, never
    /// culled
    fn depth_floor(&self, _s: &Self::Setup, _ops: &mut Ops) -> f64 {
        f64::NEG_INFINITY
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `scene::budget::per_triangle_bytes` counts a setup outcome as this `Result`.
    #[test]
    fn setup_out_has_the_size_the_budget_counts() {
        use core::mem::size_of;
        assert_eq!(
            size_of::<SetupOut<PixelRect>>(),
            size_of::<Result<(PixelRect, Class), Cull>>()
        );
    }
}
