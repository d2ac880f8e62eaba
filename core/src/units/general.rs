//! The general pipeline: setup ([`crate::setup::setup`]), a bounds strategy's per-tile
//! (u, v, t) bounds and the sample test of the precision ([`crate::sample::test`]), on a unit
//! whose missing effects are compiled out of every stage. Every unit runs it at an exact
//! precision; the full and defocus-only units at every precision.

use core::marker::PhantomData;

use crate::bounds::strategy::{BoundsStrategy, CellVisitor};
use crate::config::class::Class;
use crate::config::precision::Precision;
use crate::config::unit::Unit;
use crate::input::{PixelRect, Sample, Triangle, Viewport};
use crate::raster::zmax;
use crate::sample;
use crate::sample::pos::{Hit, ScreenPos};
use crate::setup::{setup, Outcome, Setup};
use crate::stats::Ops;
use crate::units::pipeline::Pipeline;

/// The general pipeline with bounds strategy `B` at precision `P` on unit `U`.
#[derive(Clone, Copy, Debug)]
pub struct General<B, P, U> {
    bounds: B,
    unit: PhantomData<(P, U)>,
}

impl<B: BoundsStrategy, P: Precision, U: Unit> Pipeline for General<B, P, U> {
    type Bounds = B;
    type Unit = U;
    /// The setup and the strategy's per-triangle coefficients.
    type Entry = (Setup, B::Coeffs);
    type Tile = B::Tile;
    const NAME: &'static str = "Renderer";

    fn new(bounds: B) -> Self {
        General {
            bounds,
            unit: PhantomData,
        }
    }

    #[inline(always)]
    fn setup(&self, tri: &Triangle, vp: Viewport, ops: &mut Ops) -> Outcome<Self::Entry> {
        match setup::<P, U>(tri, vp, ops) {
            Outcome::Visible(s) => {
                let c = self.bounds.prepare::<U>(&s, ops);
                Outcome::Visible((s, c))
            }
            Outcome::Culled(c) => Outcome::Culled(c),
            Outcome::Refused(c) => Outcome::Refused(c),
        }
    }

    fn class(entry: &Self::Entry) -> Class {
        entry.0.class()
    }

    fn footprint(entry: &Self::Entry) -> PixelRect {
        entry.0.footprint()
    }

    #[inline(always)]
    fn tile(&self, entry: &Self::Entry, cell: PixelRect, ops: &mut Ops) -> Option<B::Tile> {
        let (s, c) = entry;
        self.bounds.tile::<U>(s, c, cell, ops)
    }

    /// The strategy's walk ([`BoundsStrategy::walk`]): row by row, each row first narrowed by
    /// the strategy's row span.
    fn walk<V: CellVisitor>(
        &self,
        entry: &Self::Entry,
        region: PixelRect,
        bt: u16,
        ops: &mut Ops,
        v: &mut V,
    ) {
        let (s, c) = entry;
        self.bounds.walk::<U, V>(s, c, region, bt, ops, v);
    }

    #[inline(always)]
    fn test(entry: &Self::Entry, pos: ScreenPos, s: &Sample, ops: &mut Ops) -> Option<Hit> {
        sample::test::<P, U>(&entry.0, pos, s, ops)
    }

    /// [`zmax::depth_floor`] of the setup.
    fn depth_floor(entry: &Self::Entry, ops: &mut Ops) -> i32 {
        zmax::depth_floor::<P, U>(&entry.0, ops)
    }
}
