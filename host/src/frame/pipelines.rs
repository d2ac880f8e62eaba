//! The two pipelines the frame driver runs: the fixed-point core ([`Fixed`], any bounds strategy
//! and precision) and the independent f64 reference ([`Reference`]).

use uvt_core::bounds::strategy::{Admit, BoundsStrategy, RowSpan, TileBounds};
use uvt_core::config::unit::Full;
use uvt_core::{Ops, Outcome, PixelRect, Triangle, Viewport};

use crate::reference;
use crate::scene::pattern::Pattern;
use crate::scene::tri::SceneTri;

use super::pipeline::{FramePipeline, SetupOut};

/// The fixed-point core with bounds strategy `B` at precision `P`.
pub struct Fixed<'a, B, P = uvt_core::DefaultPrecision> {
    /// precision
    pub prec: std::marker::PhantomData<P>,
    /// bounds strategy
    pub strat: B,
    /// viewport
    pub vp: Viewport,
    /// core triangles
    pub tris: &'a [Triangle],
    /// sample table
    pub pattern: &'a Pattern,
}

impl<'a, B> Fixed<'a, B> {
    /// The core at the default precision.
    pub fn new(strat: B, vp: Viewport, tris: &'a [Triangle], pattern: &'a Pattern) -> Self {
        Fixed {
            prec: std::marker::PhantomData,
            strat,
            vp,
            tris,
            pattern,
        }
    }
}

impl<'a, B, P> Fixed<'a, B, P> {
    /// The core at precision `P` (e.g. `uvt_core::Exact`, whatever the default).
    pub fn new_at(strat: B, vp: Viewport, tris: &'a [Triangle], pattern: &'a Pattern) -> Self {
        Fixed {
            prec: std::marker::PhantomData,
            strat,
            vp,
            tris,
            pattern,
        }
    }
}

impl<B: BoundsStrategy + Sync, P: uvt_core::Precision + Sync> FramePipeline for Fixed<'_, B, P>
where
    B::Coeffs: Send + Sync,
{
    type Setup = (uvt_core::Setup, B::Coeffs);
    type Bounds = B::Tile;
    fn setup(&self, i: usize, ops: &mut Ops) -> SetupOut<Self::Setup> {
        match uvt_core::setup::<P, Full>(&self.tris[i], self.vp, ops) {
            Outcome::Visible(s) => {
                let c = self.strat.prepare::<Full>(&s, ops);
                SetupOut::Visible((s, c), s.class())
            }
            Outcome::Culled(c) => SetupOut::Culled(c),
            Outcome::Refused(_) => unreachable!("the full unit accepts every class"),
        }
    }
    fn footprint(&self, s: &Self::Setup) -> PixelRect {
        s.0.footprint()
    }
    fn row(&self, s: &Self::Setup, row: PixelRect, bt: u16, ops: &mut Ops) -> RowSpan {
        self.strat.row_span(&s.0, &s.1, row, bt, ops)
    }
    fn bounds(
        &self,
        s: &Self::Setup,
        span: &RowSpan,
        cell: PixelRect,
        ops: &mut Ops,
    ) -> Option<Self::Bounds> {
        self.strat.span_tile::<Full>(&s.0, &s.1, span, cell, ops)
    }
    fn inside(&self, b: &Self::Bounds, idx: usize, ops: &mut Ops) -> bool {
        // The renderer's admission of a sample by its tile (box, then predicate).
        b.admit(&self.pattern.quant[idx], ops)
    }
    fn uvt(&self, idx: usize) -> [f64; 3] {
        let q = &self.pattern.quant[idx];
        [q.u().to_num(), q.v().to_num(), q.t().to_num()]
    }
    fn test(&self, s: &Self::Setup, px: u16, py: u16, idx: usize, ops: &mut Ops) -> Option<f64> {
        let q = &self.pattern.quant[idx];
        // The renderer's dispatch: P's test chosen at compile time (the same hit as
        // `uvt_core::sample_test` on a setup of precision P).
        uvt_core::sample::test::<P, uvt_core::Full>(
            &s.0,
            uvt_core::ScreenPos::of(px, py, q),
            q,
            ops,
        )
        .map(|h| h.depth as f64)
    }
    fn far(&self) -> f64 {
        i32::MAX as f64
    }
    fn depth_floor(&self, s: &Self::Setup, ops: &mut Ops) -> f64 {
        uvt_core::raster::zmax::depth_floor::<P, Full>(&s.0, ops) as f64
    }
    fn ranges(&self, b: &Self::Bounds) -> [(f64, f64); 3] {
        let r = |i: uvt_core::Interval| (i.lo() as f64 / 65536.0, i.hi() as f64 / 65536.0);
        let b = b.uvt_box();
        [r(b.u), r(b.v), r(b.t)]
    }
}

/// The f64 reference (Laine bounds in f64, ray-cast sample test) on exact inputs.
pub struct Reference<'a> {
    /// viewport (W, H)
    pub vp: (u16, u16),
    /// f64 triangles
    pub tris: &'a [SceneTri],
    /// sample table (its exact values are used)
    pub pattern: &'a Pattern,
}

impl FramePipeline for Reference<'_> {
    type Setup = reference::setup::RefSetup;
    type Bounds = reference::bounds::RefBox;
    fn setup(&self, i: usize, _: &mut Ops) -> SetupOut<Self::Setup> {
        match reference::setup::setup(&self.tris[i], self.vp) {
            Ok(s) => SetupOut::Visible(s, s.class),
            Err(c) => SetupOut::Culled(c),
        }
    }
    fn footprint(&self, s: &Self::Setup) -> PixelRect {
        s.footprint
    }
    fn bounds(
        &self,
        s: &Self::Setup,
        _: &RowSpan,
        cell: PixelRect,
        _: &mut Ops,
    ) -> Option<Self::Bounds> {
        reference::bounds::tile(s, cell)
    }
    fn inside(&self, b: &Self::Bounds, idx: usize, _: &mut Ops) -> bool {
        let e = &self.pattern.exact[idx];
        b.contains(e[2], e[3], e[4])
    }
    fn uvt(&self, idx: usize) -> [f64; 3] {
        let e = &self.pattern.exact[idx];
        [e[2], e[3], e[4]]
    }
    fn test(&self, s: &Self::Setup, px: u16, py: u16, idx: usize, _: &mut Ops) -> Option<f64> {
        let e = &self.pattern.exact[idx];
        reference::sample::sample_test(
            &s.tri,
            self.vp,
            px as f64 + e[0],
            py as f64 + e[1],
            e[2],
            e[3],
            e[4],
        )
    }
    fn far(&self) -> f64 {
        f64::INFINITY
    }
    fn ranges(&self, b: &Self::Bounds) -> [(f64, f64); 3] {
        [b.u, b.v, b.t]
    }
}
