//! Stage 2 — per-tile (u, v, t) bounds, behind one replaceable interface.
//!
//! A [`BoundsStrategy`] prepares per-triangle coefficients once (counted as setup) and then, for
//! a bounds tile (1×1 … 8×8 pixels, clipped to the footprint), returns intervals u ∈ [u0, u1],
//! v ∈ [v0, v1], t ∈ [t0, t1] or `None` (skip the tile). Contract: **a sample that the sample
//! test covers never lies outside its tile's intervals.** A strategy may also return a per-sample
//! predicate with the box ([`TileBounds`]); the tighter strategies of [`crate::bounds`]
//! (swept-hull tile culling, lens-dependent time bounds) are such implementations.
//!
//! [`Laine2011`] (clipless dual-space bounds) — why each part is conservative:
//! - **u (and v):** setup's lens-corner boxes floor the minimum and ceil the maximum over the
//!   front vertices, at lens −1 and +1. For any (t, u) every covered sample's ξ lies in the box of
//!   the triangle at (t, u), whose minimum is ≥ the chord between the corner minima (min of affine
//!   functions of u is concave; vertex projections at time t lie between their t = 0 and t = 1
//!   projections while w > 0; a side that may cross the camera plane is unbounded). So, with
//!   s = (u+1)/2, a covered sample in tile [X0, X1) needs `m⁻ + s(m⁺ − m⁻) ≤ X1` and
//!   `M⁻ + s(M⁺ − M⁻) ≥ X0`: two linear constraints in s with slopes fixed per triangle, solved
//!   with precomputed reciprocals rounded so the ends move outward ([`RecipConstraint`]).
//! - **t:** dual space δ_k(ξ) = (a_k + w_k)·E − 2·w_k·ξ (zero on the sightline at pixel ξ; no
//!   division, valid for w ≤ 0). Coverage needs min_k δ_k ≤ 0 ≤ max_k δ_k. Lens: bias by ∓|c|·E.
//!   In t: each δ_k − |c_k(t)|·E is concave (|c(t)| is convex), so the minimum is above the chord
//!   of its t = 0 and t = 1 values; the maximum is below its chord. In ξ: the minimum over k is
//!   concave, so the line through its values at the footprint ends ξa, ξb is below it on [ξa, ξb]
//!   (Laine's bounding lines); a tile takes the lower of that line's values at its two ends. All of
//!   this is exact integer arithmetic (values scaled by ξb − ξa > 0 instead of divided); only the
//!   final `t·d ≤ n` solve divides, and it rounds outward ([`solve_le`]).
//! - Both axes' intervals and setup's frustum time span are intersected.
//!
//! The margin is therefore zero beyond outward rounding: the sample test is exact, sample (u, v, t)
//! are on the same grid the bounds round to (2^-16 by default; `P::TUV_FRAC` bits for a narrower
//! precision, where every interval is additionally rounded outward to that grid and box
//! coordinates are floored/ceiled to `P::BOUND_FRAC` bits), and tile extents cover every
//! sub-pixel offset.
//!
//! **Bounded sample test** (a [`crate::config::precision::Bounded`] precision, `bounded.rs`): that test
//! decides exactly on a perturbed triangle whose vertices lie within ε_x (x and y, per axis) and
//! ε_w (w) of the exact ones at the sample's (t, u, v) ([`crate::setup::eps::Eps`]). Setup widens
//! the lens-corner boxes, the separating-line test and the frustum span by it (proofs beside
//! `axis_boxes` and `frustum_span` in `setup.rs`), and [`Laine2011`] the dual-space bias by
//! `(ε_x + ε_w)·E` (proof at `dual_axis`). The u/v bounds come from the widened boxes, so they
//! need no term of their own. With the exact test ε = 0 and every bound is unchanged.

use crate::arith::interval::Interval;
use crate::config::unit::Unit;
use crate::input::{PixelRect, Sample};
use crate::setup::Setup;
use crate::stats::Ops;

/// The (u, v, t) box of one bounds tile.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct UvtBox {
    /// lens u
    pub u: Interval,
    /// lens v
    pub v: Interval,
    /// time t
    pub t: Interval,
}

impl UvtBox {
    /// The whole domain.
    pub const FULL: UvtBox = UvtBox {
        u: Interval::LENS,
        v: Interval::LENS,
        t: Interval::UNIT,
    };

    /// Whether a sample's (u, v, t) raw values lie inside. All six comparisons are evaluated
    /// (`&`, not `&&`): one decision per sample instead of a chain of data-dependent branches.
    #[inline]
    pub fn contains(&self, u: i32, v: i32, t: i32) -> bool {
        self.u.contains(u) & self.v.contains(v) & self.t.contains(t)
    }
}

/// What a strategy returns for one bounds tile: an axis-aligned (u, v, t) box plus, optionally,
/// a cheap per-sample predicate (linear constraints, t intervals per lens region, …) that runs on
/// every sample inside the box before the sample test. Contract as for the box: a sample the
/// sample test covers is admitted.
pub trait TileBounds: Copy + core::fmt::Debug {
    /// The axis-aligned box (samples outside it are never tested and cost nothing).
    fn uvt_box(&self) -> &UvtBox;
    /// The per-sample predicate for a sample inside the box (raw u, v, t), its operations counted
    /// in `ops.predicate`. Box-only bounds admit everything at no cost.
    fn predicate(&self, u: i32, v: i32, t: i32, ops: &mut Ops) -> bool;
    /// Box test, then the predicate: whether the sample must be tested.
    #[inline]
    fn admits(&self, u: i32, v: i32, t: i32, ops: &mut Ops) -> bool {
        self.uvt_box().contains(u, v, t) && self.predicate(u, v, t, ops)
    }
}

impl TileBounds for UvtBox {
    #[inline]
    fn uvt_box(&self) -> &UvtBox {
        self
    }
    #[inline]
    fn predicate(&self, _: i32, _: i32, _: i32, _: &mut Ops) -> bool {
        true
    }
}

/// A kept bounds tile as the per-sample loop sees it: whether one sample is tested at all (its
/// operations counted in `ops.predicate`). Every [`TileBounds`] admits by its box, then its
/// predicate; the specialised units' tiles implement it for their own culls.
pub trait Admit: Copy {
    /// Whether sample `s` of the tile must be tested.
    fn admit(&self, s: &Sample, ops: &mut Ops) -> bool;
    /// A (u, v, t) box holding every sample the tile admits (what a report or an oracle may
    /// take as the tile's bounds): a [`TileBounds`]' own box; default, for a tile that keeps no
    /// box, the whole domain. Not part of the per-sample work.
    fn enclosing_box(&self) -> UvtBox {
        UvtBox::FULL
    }
}

impl<T: TileBounds> Admit for T {
    #[inline(always)]
    fn admit(&self, s: &Sample, ops: &mut Ops) -> bool {
        self.admits(s.u().to_bits(), s.v().to_bits(), s.t().to_bits(), ops)
    }
    fn enclosing_box(&self) -> UvtBox {
        *self.uvt_box()
    }
}

/// The receiver of a bounds-tile walk ([`walk_tiles`], [`BoundsStrategy::walk`]): each cell in
/// raster order with its tile, `None` for a culled one. Generic in the tile type, so a strategy
/// that picks another strategy per triangle (`auto`) hands its cells to a per-sample loop
/// compiled for the picked strategy's own tile: the loop pays no dispatch per sample.
pub trait CellVisitor {
    /// One bounds tile `cell` of the walk and its tile step's result.
    fn cell<T: Admit>(&mut self, cell: PixelRect, tile: Option<T>, ops: &mut Ops);
}

/// A per-tile bounds algorithm.
pub trait BoundsStrategy {
    /// Per-triangle coefficients, computed once in setup.
    type Coeffs: Copy;
    /// Per-tile result: a box, possibly with a per-sample predicate.
    type Tile: TileBounds;
    /// Short name for reports.
    fn name(&self) -> &'static str;
    /// Per-triangle preparation (counted in `ops.setup`) on unit `U`, for a setup whose class
    /// `U` accepts (the renderer checks; [`crate::config::unit::Full`] accepts every class):
    /// for every accepted class the full unit's value, with the terms of the effects `U` lacks
    /// compiled out where the strategy gates them.
    ///
    /// Every strategy marks its `prepare` `#[inline(always)]`: the pipeline's setup
    /// (`units::general`) then builds the coefficients in its entry instead of copying them out
    /// of returned values. Measured on the Cortex-M4F (dense static bench row, `auto` with its
    /// rule forced to Laine 2011 against Laine 2011 itself): 1506 more setup instructions per
    /// triangle before (1185 with a 128-byte smaller `Coeffs`: the copies), 28 after. Every
    /// strategy gets the same treatment, so the stage figures compare arithmetic, not moves.
    fn prepare<U: Unit>(&self, setup: &Setup, ops: &mut Ops) -> Self::Coeffs;
    /// Bounds of one tile inside the triangle's footprint (counted in `ops.bounds`) on unit `U`,
    /// as [`Self::prepare`].
    fn tile<U: Unit>(
        &self,
        setup: &Setup,
        c: &Self::Coeffs,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<Self::Tile>;
    /// The run of one row's bounds tiles to visit (counted in `ops.rows`, never in
    /// `ops.bounds`). `row` is one row of cells of the footprint region: its columns `[x0, x1)`
    /// and the rows `[y0, y1)` that every cell of it shares (cells are aligned to the `bt` grid
    /// and clipped to `row`). Contract: a tile outside the span would have been culled by
    /// [`Self::tile`]. Default: the whole row, not pruned, at 0 ops.
    fn row_span(
        &self,
        _setup: &Setup,
        _c: &Self::Coeffs,
        row: PixelRect,
        _bt: u16,
        _ops: &mut Ops,
    ) -> RowSpan {
        RowSpan::whole(row)
    }
    /// Bounds of a tile inside the span `span` of its row: the same value as [`Self::tile`] (a
    /// strategy may skip there the part of its test that the span has already decided).
    /// Default: [`Self::tile`].
    fn span_tile<U: Unit>(
        &self,
        setup: &Setup,
        c: &Self::Coeffs,
        _span: &RowSpan,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<Self::Tile> {
        self.tile::<U>(setup, c, tile, ops)
    }
    /// The renderer's walk of `region`'s bounds tiles on unit `U`, handing each cell to `v`.
    /// Default: [`walk_tiles`] with this strategy; a strategy that delegates per triangle walks
    /// with the delegate (`auto`), so every cell gets the delegate's own tile type.
    #[inline(always)]
    fn walk<U: Unit, V: CellVisitor>(
        &self,
        setup: &Setup,
        c: &Self::Coeffs,
        region: PixelRect,
        bt: u16,
        ops: &mut Ops,
        v: &mut V,
    ) where
        Self: Sized,
    {
        walk_tiles::<Self, U, V>(self, setup, c, region, bt, ops, v);
    }
}

/// The columns `[x0, x1)` of one row of bounds tiles that a strategy's row step keeps
/// ([`BoundsStrategy::row_span`]), and whether the strategy's own per-tile cull test was decided
/// by it (`pruned`). Always inside its row (the constructors clamp); may be empty.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RowSpan {
    cols: PixelRect,
    pruned: bool,
}

impl RowSpan {
    /// The whole row, not pruned (the per-tile test runs on every tile).
    pub fn whole(row: PixelRect) -> RowSpan {
        RowSpan {
            cols: row,
            pruned: false,
        }
    }
    /// Columns `[x0, x1)` of `row` (clamped to it), pruned: every tile inside passes the
    /// strategy's cull test, every tile of the row outside fails it.
    pub fn pruned(row: PixelRect, x0: u16, x1: u16) -> RowSpan {
        let x0 = x0.clamp(row.x0, row.x1);
        let x1 = x1.clamp(x0, row.x1);
        RowSpan {
            cols: PixelRect { x0, x1, ..row },
            pruned: true,
        }
    }
    /// The kept columns (and the row's rows).
    pub fn cols(&self) -> PixelRect {
        self.cols
    }
    /// Whether the row step decided the strategy's cull test.
    pub fn is_pruned(&self) -> bool {
        self.pruned
    }
    /// Whether `cell` (a cell of the row) is visited.
    #[inline]
    pub fn admits(&self, cell: &PixelRect) -> bool {
        cell.x0 >= self.cols.x0 && cell.x1 <= self.cols.x1 && cell.x0 < cell.x1
    }
}

/// The renderer's bounds-tile walk of `region` with strategy `b` on unit `U`: row by row
/// ([`PixelRect::rows`]), the row's span ([`BoundsStrategy::row_span`]), then every cell of the
/// row in order ([`PixelRect::cells`]: the same cells in the same raster order as
/// `region.cells(bt)`), handing `v` each cell with its bounds, `None` for a cell outside the span
/// or culled by [`BoundsStrategy::span_tile`].
pub fn walk_tiles<B: BoundsStrategy, U: Unit, V: CellVisitor>(
    b: &B,
    setup: &Setup,
    c: &B::Coeffs,
    region: PixelRect,
    bt: u16,
    ops: &mut Ops,
    v: &mut V,
) {
    for row in region.rows(bt) {
        let span = b.row_span(setup, c, row, bt, ops);
        for cell in row.cells(bt) {
            let t = if span.admits(&cell) {
                b.span_tile::<U>(setup, c, &span, cell, ops)
            } else {
                None
            };
            v.cell(cell, t, ops);
        }
    }
}
