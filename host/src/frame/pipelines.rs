//! The two pipelines the frame driver runs: the fixed-point core ([`Fixed`], any bounds strategy
//! and precision) and the independent f64 reference ([`Reference`]).

use uvt_core::bounds::strategy::{Admit, BoundsStrategy, CellVisitor};
use uvt_core::config::unit::Full;
use uvt_core::{Ops, Outcome, PixelRect, Sample, Triangle, Viewport};

use crate::reference;
use crate::scene::pattern::Pattern;
use crate::scene::tri::SceneTri;

use super::pipeline::{FramePipeline, FrameTile, SetupOut, TileSink};

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

impl<B: BoundsStrategy + Sync, P: uvt_core::Precision + Sync> FramePipeline for Fixed<'_, B, P> {
    type Setup = uvt_core::Setup;
    type Sample = Sample;
    fn setup(&self, i: usize, ops: &mut Ops) -> SetupOut<Self::Setup> {
        match uvt_core::setup::<P, Full>(&self.tris[i], self.vp, ops) {
            Outcome::Visible(s) => SetupOut::Visible(s, s.class()),
            Outcome::Culled(c) => SetupOut::Culled(c),
            Outcome::Refused(_) => unreachable!("the full unit accepts every class"),
        }
    }
    fn footprint(&self, s: &Self::Setup) -> PixelRect {
        s.footprint()
    }
    fn walk<V: TileSink<Sample>>(
        &self,
        s: &Self::Setup,
        region: PixelRect,
        bt: u16,
        prep: &mut Ops,
        ops: &mut Ops,
        v: &mut V,
    ) {
        let c = self.strat.prepare::<Full>(s, prep);
        // The renderer's walk: the strategy's own (`auto` walks with the strategy it picked,
        // so the sink's per-sample loop is compiled for that strategy's tile).
        self.strat
            .walk::<Full, _>(s, &c, region, bt, ops, &mut CoreCells(v));
    }
    fn sample(&self, idx: usize) -> &Sample {
        &self.pattern.quant[idx]
    }
    fn uvt(&self, idx: usize) -> [f64; 3] {
        let q = &self.pattern.quant[idx];
        [q.u().to_num(), q.v().to_num(), q.t().to_num()]
    }
    fn test(&self, s: &Self::Setup, px: u16, py: u16, idx: usize, ops: &mut Ops) -> Option<f64> {
        let q = &self.pattern.quant[idx];
        // The renderer's dispatch: P's test chosen at compile time (the same hit as
        // `uvt_core::sample_test` on a setup of precision P).
        uvt_core::sample::test::<P, uvt_core::Full>(s, uvt_core::ScreenPos::of(px, py, q), q, ops)
            .map(|h| h.depth as f64)
    }
    fn far(&self) -> f64 {
        i32::MAX as f64
    }
    fn depth_floor(&self, s: &Self::Setup, ops: &mut Ops) -> f64 {
        uvt_core::raster::zmax::depth_floor::<P, Full>(s, ops) as f64
    }
}

/// The core's tiles handed to a frame sink.
struct CoreCells<'v, V>(&'v mut V);

impl<V: TileSink<Sample>> CellVisitor for CoreCells<'_, V> {
    #[inline(always)]
    fn cell<T: Admit>(&mut self, cell: PixelRect, tile: Option<T>, ops: &mut Ops) {
        self.0.cell(cell, tile.map(CoreTile), ops);
    }
}

/// A core tile as a frame tile.
#[derive(Clone, Copy)]
struct CoreTile<T>(T);

impl<T: Admit> FrameTile<Sample> for CoreTile<T> {
    #[inline(always)]
    fn inside(&self, s: &Sample, ops: &mut Ops) -> bool {
        // The renderer's admission of a sample by its tile (box, then predicate).
        self.0.admit(s, ops)
    }
    fn ranges(&self) -> [(f64, f64); 3] {
        let r = |i: uvt_core::Interval| (i.lo() as f64 / 65536.0, i.hi() as f64 / 65536.0);
        let b = self.0.enclosing_box();
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
    type Sample = [f64; 5];
    fn setup(&self, i: usize, _: &mut Ops) -> SetupOut<Self::Setup> {
        match reference::setup::setup(&self.tris[i], self.vp) {
            Ok(s) => SetupOut::Visible(s, s.class),
            Err(c) => SetupOut::Culled(c),
        }
    }
    fn footprint(&self, s: &Self::Setup) -> PixelRect {
        s.footprint
    }
    /// Every cell of the region in raster order (no row spans), with Laine's f64 bounds.
    fn walk<V: TileSink<[f64; 5]>>(
        &self,
        s: &Self::Setup,
        region: PixelRect,
        bt: u16,
        _: &mut Ops,
        ops: &mut Ops,
        v: &mut V,
    ) {
        for cell in region.cells(bt) {
            v.cell(cell, reference::bounds::tile(s, cell), ops);
        }
    }
    fn sample(&self, idx: usize) -> &[f64; 5] {
        &self.pattern.exact[idx]
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
}

impl FrameTile<[f64; 5]> for reference::bounds::RefBox {
    fn inside(&self, e: &[f64; 5], _: &mut Ops) -> bool {
        self.contains(e[2], e[3], e[4])
    }
    fn ranges(&self) -> [(f64, f64); 3] {
        [self.u, self.v, self.t]
    }
}
