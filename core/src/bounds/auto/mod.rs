//! `auto`: a bounds strategy chosen per triangle ([`Auto`]). Setup already knows the triangle's
//! class, its footprint and its boxes at the two lens corners; the rule ([`RULE`], one [`Tier`]
//! per class) keeps Laine 2011 (the cheapest setup) below an area of the triangle's own extent
//! ([`Auto::area`]) and takes heavier strategies with cheaper tiles, predicates and fewer sample
//! tests ([`Pick`]) from larger areas on: the hull from one area, hull+edge-t from another,
//! optionally only for triangles that travel little for their size (**Travel**).
//!
//! **Why the own extent, not the footprint.** Per axis [`Auto::area`] takes the least of the
//! footprint's side and the sides of the boxes at the two lens corners: the box at one lens
//! corner holds the triangle at both shutter ends shifted by its CoC, so its side is the
//! triangle's own extent and its screen travel, without the CoC's spread (with no defocus both
//! boxes are the footprint, so static and motion triangles are ranked by their footprint). What
//! the hull culls of a defocused triangle is, to first order, its own box minus itself: the
//! hull of the triangle grown by the square lens, `T ⊕ S`, has area `A(T) + 2c·(w + h) + 4c²`
//! against the box's `(w + 2c)·(h + 2c)`, a difference of `w·h − A(T)` whatever the CoC `c`;
//! the CoC only adds tiles the hull's faces must be tested on. A tiny triangle with a large CoC
//! (a dense scene out of focus, more so at a higher resolution, where the CoC spans more
//! pixels) has a large footprint and nothing for the hull to cull: by its footprint the rule
//! took the hull there and paid for it (measured: 1.126× Laine 2011's instructions on the full
//! dense defocus ×2 row), by its own extent it does not.
//!
//! **Travel.** A tier may keep hull+edge-t for the triangles whose own extent is at most
//! `edge_travel` times their own box at the shutter's start ([`Auto::start_area`]: the same
//! measure of the lens-corner boxes of the three shutter-open vertices; the other triangles of
//! that area get the hull). The ratio says how far the triangle travels for its size. What
//! edge-t adds to the hull is a t bound along the triangle's most oblique edge; on the game
//! motion rows it bought the sample-test efficiency on triangles that sweep a region a few times
//! their own size and cost more than it saved on those that sweep far past it (measured by the
//! rule's model: with the limit the motion tier keeps 92% of `best`'s efficiency on three of the
//! four game motion rows within 1.03× the row's cheapest candidate; without it on none). The
//! start box takes four projections per axis, so it is computed only when the area already picks
//! hull+edge-t under a tier with a limit.
//!
//! The rule is derived from measured Cortex-M4F instructions per stage and per strategy on the
//! bench rows' own triangles at both sizes, each row priced with its own figures (`uvt
//! auto-rule`, which writes [`rule`] from `host/report/m4_strategies.json`; its module docs
//! give the totals): per class the tier that keeps the most rows within 1.03× the row's
//! cheapest candidate, then the most at 92% of `best`'s sample-test efficiency, then the most
//! at most Laine 2011's, then the least total, over both areas and the travel limit (no limit
//! on a tie). [`tier`] holds the rule's types.
//!
//! **Why it is conservative.** For each triangle `auto` is exactly one of the registry's
//! strategies — its coefficients, row spans, tile bounds and predicate are that strategy's,
//! unchanged (the enums below only carry them) — and every one of those strategies is
//! conservative (the proof at the top of its file). A sample the sample test covers is therefore
//! never outside its tile's bounds, whatever the rule picks; the rule decides the cost only.
//!
//! **Cost.** The choice first checks the footprint ([`CHECK_OPS`] operations in setup: its two
//! sides, their product, the least of the tier's two areas, one compare): the own extent is
//! never larger than the footprint on either axis, so a footprint below both of the tier's
//! areas is Laine 2011 whatever [`Auto::area`] gives, and the choice ends there. On the dense
//! rows that is nearly every triangle; measured on the Cortex-M4F (quick dense defocus, every
//! 16th triangle, `auto` forced to Laine 2011), the check cut `auto`'s setup over Laine 2011's
//! from 226 to 38 instructions per triangle. Otherwise it adds [`PICK_OPS`] (per axis and lens
//! corner two floors, a subtract and an add; per axis two minima; the area's multiply; two
//! compares with the class's thresholds; one select), and where the area picks hull+edge-t
//! under a tier with a travel limit the start boxes' operations (counted by setup's box code)
//! and [`TRAVEL_OPS`]. Per tile and per sample nothing beyond
//! the picked strategy's own work: the renderer walks a triangle's tiles with the picked strategy's
//! own walk and tile type ([`BoundsStrategy::walk`]), so its per-tile and per-sample code is
//! that strategy's, with one branch per walked region.
#![warn(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_possible_wrap
)]

use crate::bounds::composed::{hull, hull_edge};
use crate::bounds::edge_time::{EdgeCoeffs, EdgeTile, EdgeTime};
use crate::bounds::hull::tiles::HullTiles;
use crate::bounds::hull::HullCull;
use crate::bounds::laine::{Laine2011, LaineCoeffs};
use crate::bounds::strategy::{
    walk_tiles, BoundsStrategy, CellVisitor, RowSpan, TileBounds, UvtBox,
};
use crate::config::unit::Unit;
use crate::input::PixelRect;
use crate::setup::boxes::{floor_px, start_boxes, AxisBoxes};
use crate::setup::Setup;
use crate::stats::Ops;

pub mod rule;
pub mod tier;

pub use rule::RULE;
pub use tier::{Pick, Tier};

/// The per-triangle choice: the registry's `auto` ([`Auto::new`]) follows [`RULE`]; any other
/// rule ([`Auto::with_rule`]) is as conservative (module docs) and serves the tests, which force
/// every pick.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Auto {
    rule: [Tier; 4],
}

impl Default for Auto {
    fn default() -> Self {
        Auto::new()
    }
}

/// The picked strategy's coefficients.
#[derive(Clone, Copy, Debug)]
pub enum AutoCoeffs {
    /// Laine 2011's
    Laine(LaineCoeffs),
    /// hull's
    Hull((HullTiles, LaineCoeffs)),
    /// hull+edge-t's
    HullEdge((HullTiles, EdgeCoeffs<LaineCoeffs>)),
}

/// The picked strategy's tile.
#[derive(Clone, Copy, Debug)]
pub enum AutoTile {
    /// a box (Laine 2011, hull)
    Box(UvtBox),
    /// hull+edge-t's tile
    Edge(EdgeTile<UvtBox>),
}

impl TileBounds for AutoTile {
    #[inline]
    fn uvt_box(&self) -> &UvtBox {
        match self {
            AutoTile::Box(b) => b,
            AutoTile::Edge(e) => e.uvt_box(),
        }
    }
    #[inline]
    fn predicate(&self, u: i32, v: i32, t: i32, ops: &mut Ops) -> bool {
        match self {
            AutoTile::Box(b) => b.predicate(u, v, t, ops),
            AutoTile::Edge(e) => e.predicate(u, v, t, ops),
        }
    }
}

/// The footprint check's setup operations per triangle (module docs, **Cost**): 2 sides, their
/// product, the least of two areas, a compare.
pub const CHECK_OPS: u64 = 5;

/// The own extent's setup operations per triangle when the footprint check does not decide
/// (module docs, **Cost**): 2 axes × (2 corners × 4 + 2) + 4.
pub const PICK_OPS: u64 = 24;

/// The travel check's setup operations per triangle, beside the start boxes' own (module docs,
/// **Cost**; counted only when the tier reads the travel and the area picks hull+edge-t): the
/// start box's area as the own extent's (2 axes × (2 corners × 4 + 2) + 1), the limit's
/// multiply and the compare.
pub const TRAVEL_OPS: u64 = 23;

const HULL: HullCull<Laine2011> = hull();
const HULL_EDGE: HullCull<EdgeTime<Laine2011>> = hull_edge();

impl Auto {
    /// The registry's `auto`: the derived [`RULE`].
    pub const fn new() -> Auto {
        Auto { rule: RULE }
    }
    /// `auto` with another rule (one tier per class, [`crate::config::class::Class::index`]
    /// order).
    pub const fn with_rule(rule: [Tier; 4]) -> Auto {
        Auto { rule }
    }
    /// What the rule picks for a set-up triangle (its class's tier at [`Auto::area`]).
    pub fn pick(&self, setup: &Setup) -> Pick {
        self.pick_counted(setup, &mut Ops::default())
    }
    /// [`Auto::pick`], counting its operations: [`CHECK_OPS`], and [`PICK_OPS`] when the
    /// footprint is not below both of the tier's areas (module docs, **Cost**). The early answer
    /// is the tier's at [`Auto::area`]: the area is at most the footprint's (each side is), so
    /// below both areas it is Laine 2011 either way (`tests/tests/model/auto.rs` checks the two agree).
    fn pick_counted(&self, setup: &Setup, ops: &mut Ops) -> Pick {
        let Some(t) = self.rule.get(setup.class.index()) else {
            return Pick::Laine;
        };
        let fp = setup.footprint;
        // Sides ≤ 2048 (the viewport): the product is < 2^22, no saturation.
        let full = u32::from(fp.x1.saturating_sub(fp.x0))
            .saturating_mul(u32::from(fp.y1.saturating_sub(fp.y0)));
        ops.add_setup(CHECK_OPS);
        if full < t.hull_from.min(t.edge_from) {
            return Pick::Laine;
        }
        ops.add_setup(PICK_OPS);
        let area = Auto::area(setup);
        if t.reads_travel() && t.pick(area) == Pick::HullEdge {
            let start = Auto::start_area(setup, ops);
            ops.add_setup(TRAVEL_OPS);
            return t.pick_travel(area, start);
        }
        t.pick(area)
    }
    /// The area of the triangle's own box at the shutter's start, in pixels: [`Auto::area`]'s
    /// measure (per axis the least of the footprint's side and the lens corners' box sides) of
    /// the boxes of the shutter-open vertices alone, without ε (a rank, not a bound). With the
    /// own extent it tells how far the triangle travels for its size (module docs, **Travel**).
    /// Counts the start boxes' operations (three points per axis, four projections).
    pub fn start_area(setup: &Setup, ops: &mut Ops) -> u32 {
        let (vp, bnd) = (setup.viewport, setup.prec.bnd());
        let axes = [
            start_boxes(&setup.tri, 0, i64::from(vp.w), bnd, ops),
            start_boxes(&setup.tri, 1, i64::from(vp.h), bnd, ops),
        ];
        own_area(setup.footprint, &axes, bnd)
    }
    /// The area the rule ranks a triangle by, in pixels: per axis the least of the footprint's
    /// side and the sides of the boxes at the two lens corners (module docs), multiplied. A
    /// box's side is counted as the footprint counts it (`floor(hi) − floor(lo) + 1` pixels);
    /// an axis with a side unbounded (a camera-plane crossing) takes the footprint's side.
    /// The footprint's sides are ≤ 2048 (the viewport), so the area is ≤ 2^22.
    pub fn area(setup: &Setup) -> u32 {
        own_area(setup.footprint, &setup.axes, setup.prec.bnd())
    }
}

/// Per axis the least of the footprint's side and the sides of `axes`' boxes at the two lens
/// corners, multiplied ([`Auto::area`]). A box's side is counted as the footprint counts it
/// (`floor(hi) − floor(lo) + 1` pixels); an axis with a side unbounded (a camera-plane
/// crossing) takes the footprint's side. The footprint's sides are ≤ 2048 (the viewport), so
/// the area is ≤ 2^22.
fn own_area(fp: PixelRect, axes: &[AxisBoxes; 2], bnd: u32) -> u32 {
    let sides = [fp.x1.saturating_sub(fp.x0), fp.y1.saturating_sub(fp.y0)];
    let [w, h] = [0, 1].map(|k| {
        let full = sides.get(k).copied().unwrap_or(0);
        let own = axes.get(k).and_then(|b| match (b.lo, b.hi) {
            // Raw coordinates |X| < 2^57 (formats.rs): floors, difference and + 1 exact.
            (Some(lo), Some(hi)) => lo
                .iter()
                .zip(&hi)
                .map(|(l, h)| {
                    floor_px(*h, bnd)
                        .saturating_sub(floor_px(*l, bnd))
                        .saturating_add(1)
                })
                .min(),
            _ => None,
        });
        // ≤ the footprint's side ≤ 2048: the conversion is exact; a side < 1 cannot occur
        // (hi ≥ lo at each corner) and is taken as 0.
        own.map_or(full, |o| {
            u16::try_from(o.clamp(0, i64::from(full))).unwrap_or(full)
        })
    });
    u32::from(w).saturating_mul(u32::from(h))
}

impl BoundsStrategy for Auto {
    type Coeffs = AutoCoeffs;
    type Tile = AutoTile;
    fn name(&self) -> &'static str {
        "auto"
    }
    #[inline(always)]
    fn prepare<U: Unit>(&self, setup: &Setup, ops: &mut Ops) -> AutoCoeffs {
        match self.pick_counted(setup, ops) {
            Pick::Laine => AutoCoeffs::Laine(Laine2011.prepare::<U>(setup, ops)),
            Pick::Hull => AutoCoeffs::Hull(HULL.prepare::<U>(setup, ops)),
            Pick::HullEdge => AutoCoeffs::HullEdge(HULL_EDGE.prepare::<U>(setup, ops)),
        }
    }
    /// The picked strategy's own walk: every cell of the triangle gets that strategy's row
    /// spans and tile type, so the renderer's per-sample loop is the picked strategy's loop
    /// (one branch per walked region, none per tile or sample).
    #[inline(always)]
    fn walk<U: Unit, V: CellVisitor>(
        &self,
        setup: &Setup,
        c: &AutoCoeffs,
        region: PixelRect,
        bt: u16,
        ops: &mut Ops,
        v: &mut V,
    ) {
        match c {
            AutoCoeffs::Laine(c) => walk_tiles::<_, U, V>(&Laine2011, setup, c, region, bt, ops, v),
            AutoCoeffs::Hull(c) => walk_tiles::<_, U, V>(&HULL, setup, c, region, bt, ops, v),
            AutoCoeffs::HullEdge(c) => {
                walk_tiles::<_, U, V>(&HULL_EDGE, setup, c, region, bt, ops, v)
            }
        }
    }
    fn tile<U: Unit>(
        &self,
        setup: &Setup,
        c: &AutoCoeffs,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<AutoTile> {
        match c {
            AutoCoeffs::Laine(c) => Laine2011.tile::<U>(setup, c, tile, ops).map(AutoTile::Box),
            AutoCoeffs::Hull(c) => HULL.tile::<U>(setup, c, tile, ops).map(AutoTile::Box),
            AutoCoeffs::HullEdge(c) => HULL_EDGE.tile::<U>(setup, c, tile, ops).map(AutoTile::Edge),
        }
    }
    fn row_span(
        &self,
        setup: &Setup,
        c: &AutoCoeffs,
        row: PixelRect,
        bt: u16,
        ops: &mut Ops,
    ) -> RowSpan {
        match c {
            AutoCoeffs::Laine(c) => Laine2011.row_span(setup, c, row, bt, ops),
            AutoCoeffs::Hull(c) => HULL.row_span(setup, c, row, bt, ops),
            AutoCoeffs::HullEdge(c) => HULL_EDGE.row_span(setup, c, row, bt, ops),
        }
    }
    fn span_tile<U: Unit>(
        &self,
        setup: &Setup,
        c: &AutoCoeffs,
        span: &RowSpan,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<AutoTile> {
        match c {
            AutoCoeffs::Laine(c) => Laine2011
                .span_tile::<U>(setup, c, span, tile, ops)
                .map(AutoTile::Box),
            AutoCoeffs::Hull(c) => HULL
                .span_tile::<U>(setup, c, span, tile, ops)
                .map(AutoTile::Box),
            AutoCoeffs::HullEdge(c) => HULL_EDGE
                .span_tile::<U>(setup, c, span, tile, ops)
                .map(AutoTile::Edge),
        }
    }
}
