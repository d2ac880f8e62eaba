//! The interface between the frame driver and a pipeline: what a pipeline (the fixed-point core,
//! the f64 reference) must answer per triangle, per tile and per sample so that the driver can
//! run it over a frame and count what it does.

use uvt_core::bounds::strategy::RowSpan;
use uvt_core::{Class, Cull, Ops, PixelRect};

/// Setup result of a pipeline.
pub enum SetupOut<S> {
    /// visible, with its class
    Visible(S, Class),
    /// culled
    Culled(Cull),
}

/// One rasterization pipeline the driver can run.
pub trait FramePipeline: Sync {
    /// per-triangle data
    type Setup: Send + Sync;
    /// per-tile bounds
    type Bounds: Copy;
    /// setup of triangle `i`
    fn setup(&self, i: usize, ops: &mut Ops) -> SetupOut<Self::Setup>;
    /// footprint of a setup
    fn footprint(&self, s: &Self::Setup) -> PixelRect;
    /// the run of one row of bounds tiles to visit (`BoundsStrategy::row_span`; default: the
    /// whole row, no ops)
    fn row(&self, _s: &Self::Setup, row: PixelRect, _bt: u16, _ops: &mut Ops) -> RowSpan {
        RowSpan::whole(row)
    }
    /// bounds of one tile inside its row's span
    fn bounds(
        &self,
        s: &Self::Setup,
        span: &RowSpan,
        cell: PixelRect,
        ops: &mut Ops,
    ) -> Option<Self::Bounds>;
    /// whether sample `idx` of the table lies inside the bounds (box, then the strategy's
    /// per-sample predicate, counted in `ops.predicate`)
    fn inside(&self, b: &Self::Bounds, idx: usize, ops: &mut Ops) -> bool;
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
    /// the bounds as real (u, v, t) ranges
    fn ranges(&self, b: &Self::Bounds) -> [(f64, f64); 3];
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
