//! Stage 2 — per-tile (u, v, t) bounds, behind one replaceable interface.
//!
//! A [`BoundsStrategy`] prepares per-triangle coefficients once (counted as setup) and then, for
//! a bounds tile (1×1 … 8×8 pixels, clipped to the footprint), returns intervals u ∈ [u0, u1],
//! v ∈ [v0, v1], t ∈ [t0, t1] or `None` (skip the tile). Contract: **a sample that the sample
//! test covers never lies outside its tile's intervals.** A strategy may also return a per-sample
//! predicate with the box ([`TileBounds`]); the tighter strategies of [`crate::strategies`]
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
//! **Bounded sample test** (a [`crate::formats::Bounded`] precision, `bounded.rs`): that test
//! decides exactly on a perturbed triangle whose vertices lie within ε_x (x and y, per axis) and
//! ε_w (w) of the exact ones at the sample's (t, u, v) ([`crate::bounded::Eps`]). Setup widens
//! the lens-corner boxes, the separating-line test and the frustum span by it (proofs beside
//! `axis_boxes` and `frustum_span` in `setup.rs`), and [`Laine2011`] the dual-space bias by
//! `(ε_x + ε_w)·E` (proof at `dual_axis`). The u/v bounds come from the widened boxes, so they
//! need no term of their own. With the exact test ε = 0 and every bound is unchanged.

use crate::formats::DualDelta;
use crate::input::{PixelRect, Triangle, W};
use crate::interval::{solve_le64, Interval, RecipConstraint};
use crate::setup::{axis_coord, Setup};
use crate::stats::Ops;
use crate::unit::{Full, Unit};

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

/// A per-tile bounds algorithm.
pub trait BoundsStrategy {
    /// Per-triangle coefficients, computed once in setup.
    type Coeffs: Copy;
    /// Per-tile result: a box, possibly with a per-sample predicate.
    type Tile: TileBounds;
    /// Short name for reports.
    fn name(&self) -> &'static str;
    /// Per-triangle preparation (counted in `ops.setup`).
    fn prepare(&self, setup: &Setup, ops: &mut Ops) -> Self::Coeffs;
    /// Bounds of one tile inside the triangle's footprint (counted in `ops.bounds`).
    fn tile(
        &self,
        setup: &Setup,
        c: &Self::Coeffs,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<Self::Tile>;
    /// [`Self::prepare`] on unit `U` for a setup whose class `U` accepts (the renderer
    /// checks): the same value, with the terms of the effects `U` lacks compiled out where the
    /// strategy gates them (default: `prepare` itself).
    fn prepare_unit<U: Unit>(&self, setup: &Setup, ops: &mut Ops) -> Self::Coeffs {
        self.prepare(setup, ops)
    }
    /// [`Self::tile`] on unit `U`, as [`Self::prepare_unit`].
    fn tile_unit<U: Unit>(
        &self,
        setup: &Setup,
        c: &Self::Coeffs,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<Self::Tile> {
        self.tile(setup, c, tile, ops)
    }
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
    /// Bounds of a tile inside the span `span` of its row: the same value as
    /// [`Self::tile_unit`] (a strategy may skip there the part of its test that the span has
    /// already decided). Default: [`Self::tile_unit`].
    fn span_tile_unit<U: Unit>(
        &self,
        setup: &Setup,
        c: &Self::Coeffs,
        _span: &RowSpan,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<Self::Tile> {
        self.tile_unit::<U>(setup, c, tile, ops)
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
/// `region.cells(bt)`), handing `f` each cell with its bounds, `None` for a cell outside the span
/// or culled by [`BoundsStrategy::span_tile_unit`].
pub fn walk_tiles<B: BoundsStrategy, U: Unit>(
    b: &B,
    setup: &Setup,
    c: &B::Coeffs,
    region: PixelRect,
    bt: u16,
    ops: &mut Ops,
    mut f: impl FnMut(PixelRect, Option<B::Tile>, &mut Ops),
) {
    for row in region.rows(bt) {
        let span = b.row_span(setup, c, row, bt, ops);
        for cell in row.cells(bt) {
            let t = if span.admits(&cell) {
                b.span_tile_unit::<U>(setup, c, &span, cell, ops)
            } else {
                None
            };
            f(cell, t, ops);
        }
    }
}

/// The bounding-box scan: every sample of the footprint is tested, whatever its (u, v, t)
/// (Laine 2011 "Bbox scan": a box that covers the triangle for all (u, v, t)).
#[derive(Clone, Copy, Debug, Default)]
pub struct BboxScan;

impl BoundsStrategy for BboxScan {
    type Coeffs = ();
    type Tile = UvtBox;
    fn name(&self) -> &'static str {
        "bbox"
    }
    fn prepare(&self, _: &Setup, _: &mut Ops) {}
    fn tile(&self, _: &Setup, _: &(), _: PixelRect, _: &mut Ops) -> Option<UvtBox> {
        Some(UvtBox::FULL)
    }
}

/// Laine et al. 2011 clipless dual-space bounds.
#[derive(Clone, Copy, Debug, Default)]
pub struct Laine2011;

/// One side of one axis's lens bound: `s·d ≤ n(tile)` with `n = sign·(tile edge − base)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LensSide {
    /// box value at lens −1 (raw pixel coordinate)
    pub base: i64,
    /// slope and its reciprocals
    pub c: RecipConstraint,
}

/// Lens bound of one axis; `None` sides are unbounded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LensAxis {
    /// box minimum side: `s·(m⁺ − m⁻) ≤ X1 − m⁻`
    pub lo: Option<LensSide>,
    /// box maximum side: `s·(M⁻ − M⁺) ≤ M⁻ − X0`
    pub hi: Option<LensSide>,
}

/// Dual-space bounding values of one axis: δmin/δmax at the footprint ends, t = 0 and 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DualAxis {
    /// footprint start ξa and end ξb (pixels)
    pub xi: [i64; 2],
    /// δmin `[t][end]`
    pub lo: [[DualDelta; 2]; 2],
    /// δmax `[t][end]`
    pub hi: [[DualDelta; 2]; 2],
}

/// [`Laine2011`] coefficients: lens bounds per axis (defocus only), dual lines (motion only).
/// Only [`Laine2011::prepare`] builds them from a [`Setup`], so their values stay in the ranges
/// the per-tile arithmetic is proven for; read through the methods.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LaineCoeffs {
    lens: [Option<LensAxis>; 2],
    dual: [Option<DualAxis>; 2],
}

impl LaineCoeffs {
    /// Lens bounds `[x → u, y → v]`.
    pub fn lens(&self) -> [Option<LensAxis>; 2] {
        self.lens
    }
    /// Dual-space lines `[x, y]`.
    pub fn dual(&self) -> [Option<DualAxis>; 2] {
        self.dual
    }
}

// Box coordinates |X| < 2^58 (`core/README.md`), so the slopes m1 − m0, h0 − h1 are < 2^59.
#[allow(clippy::arithmetic_side_effects)]
fn lens_axis(setup: &Setup, axis: usize, ops: &mut Ops) -> LensAxis {
    let b = setup.axes.get(axis).copied();
    let lo = b.and_then(|b| b.lo).map(|[m0, m1]| LensSide {
        base: m0,
        c: RecipConstraint::new(m1 - m0),
    });
    let hi = b.and_then(|b| b.hi).map(|[h0, h1]| LensSide {
        base: h0,
        c: RecipConstraint::new(h0 - h1),
    });
    ops.add_setup(8);
    LensAxis { lo, hi }
}

/// Conservative epsilon (bounded sample test, `bounded.rs`): a vertex perturbed by ≤ ε_x in a
/// and ≤ ε_w in w moves δ by `δa·E + δw·(E − 2ξ)`, at most `(ε_x + ε_w)·E` for ξ ∈ [0, E] (the
/// footprint lies in the viewport): a constant added to the lens bias `|c|·E`, so the concavity
/// and chord arguments above hold unchanged (`eps` = ε_x + ε_w; 0 for the exact test).
// Ranges (checked triangle and viewport): |a + w| < 2^31, E ≤ 2^11, ξ ≤ 2^11 (footprint inside
// the viewport), |c| ≤ 2^29, eps < 2^25: |(a + w)·E| < 2^42, |2·w·ξ| < 2^41,
// (|c| + eps)·E < 2^41, so |δ ± (|c| + eps)·E| < 2^44 in i64.
#[allow(clippy::arithmetic_side_effects)]
fn dual_axis(
    tri: &Triangle,
    fp: &PixelRect,
    axis: usize,
    extent: i64,
    eps: i32,
    ops: &mut Ops,
) -> DualAxis {
    let eps = i64::from(eps);
    let xi = if axis == 0 {
        [fp.x0, fp.x1].map(i64::from)
    } else {
        [fp.y0, fp.y1].map(i64::from)
    };
    let mut lo = [[DualDelta::MAX; 2]; 2];
    let mut hi = [[DualDelta::MIN; 2]; 2];
    for ((ends, lo_t), hi_t) in tri.v.iter().zip(lo.iter_mut()).zip(hi.iter_mut()) {
        for p in ends.iter() {
            let (a, cs) = axis_coord(p, axis);
            let w = i64::from(p[W]);
            let bias = (cs.abs() + eps) * extent;
            for ((l, h), x) in lo_t.iter_mut().zip(hi_t.iter_mut()).zip(xi.iter()) {
                let delta = (a + w) * extent - 2 * w * x;
                *l = (*l).min(delta - bias);
                *h = (*h).max(delta + bias);
                ops.add_setup(7);
            }
        }
    }
    DualAxis { xi, lo, hi }
}

/// t interval of one axis for a tile [x0, x1] ⊆ [ξa, ξb].
///
/// Each bounding line `v0·(ξb − x) + v1·(x − ξa)` is evaluated as `v0·D + (v1 − v0)·(x − ξa)`
/// (D = ξb − ξa; the same integer), and of its values at the tile's two ends the smaller (the
/// larger, for δmax) is the one at the end the slope's sign picks: one evaluation per line
/// instead of two, the same values.
// Ranges: |δ| < 2^44 (so |v1 − v0| < 2^45); ξa, ξb, x0, x1 are pixel indices < 2^16 (u16), so
// |D|, |x − ξa| < 2^16: |v0·D| < 2^60, |(v1 − v0)·(x − ξa)| < 2^61, each line value < 2^62 in
// i64, and the differences handed to `solve_le64` are < 2^63. `fast_corners::
// dual_t_at_the_domain_corners` drives the extremes against an i128 computation.
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn dual_t(d: &DualAxis, x0: i64, x1: i64, ops: &mut Ops) -> Option<Interval> {
    let [xa, xb] = d.xi;
    let (xl, xh) = (x0.min(x1), x0.max(x1));
    let span = xb - xa;
    // The line's minimum (`low`) or maximum over x ∈ {xl, xh}.
    let line = |v: &[DualDelta; 2], low: bool| {
        let slope = v[1] - v[0];
        let x = if (slope >= 0) == low { xl } else { xh };
        v[0] * span + slope * (x - xa)
    };
    let [lo0, lo1] = d.lo.map(|v| line(&v, true));
    let [hi0, hi1] = d.hi.map(|v| line(&v, false));
    ops.add_bounds(24);
    // (1−t)·lo0 + t·lo1 ≤ 0  and  (1−t)·hi0 + t·hi1 ≥ 0.
    let a = solve_le64(lo1 - lo0, -lo0)?;
    let b = solve_le64(hi0 - hi1, hi0)?;
    ops.add_bounds(8);
    a.meet(b)
}

/// s interval (lens parameter) of one axis for tile columns [x0, x1).
///
/// The tile edges go to the bound grid by a multiplication by `2^bnd` (no shift): x0, x1 are
/// pixel indices < 2^16 and bnd ≤ 16 (`PrecisionBits`), so `x·2^bnd` < 2^32; box values
/// |base| < 2^58: every difference is < 2^59 in i64. Tested at the corners by
/// `tests::lens_edges_at_the_domain_corners`.
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn lens_s(l: &LensAxis, x0: i64, x1: i64, bnd: u32, ops: &mut Ops) -> Option<Interval> {
    let scale = 2i64.pow(bnd);
    let mut s = Interval::UNIT;
    if let Some(side) = l.lo {
        s = s.meet(side.c.solve(x1 * scale - side.base)?)?;
        ops.add_bounds(4);
    }
    if let Some(side) = l.hi {
        s = s.meet(side.c.solve(side.base - x0 * scale)?)?;
        ops.add_bounds(4);
    }
    Some(s)
}

impl BoundsStrategy for Laine2011 {
    type Coeffs = LaineCoeffs;
    type Tile = UvtBox;
    fn name(&self) -> &'static str {
        "laine2011"
    }

    fn prepare(&self, setup: &Setup, ops: &mut Ops) -> LaineCoeffs {
        self.prepare_unit::<Full>(setup, ops)
    }

    fn tile(
        &self,
        setup: &Setup,
        c: &LaineCoeffs,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<UvtBox> {
        self.tile_unit::<Full>(setup, c, tile, ops)
    }

    // Gated on the unit: lens terms only with `U::DEFOCUS`, dual lines only with `U::MOTION`
    // (for an accepted class the same coefficients: a class without defocus gets no lens axis,
    // one without motion no dual axis, on every unit).
    fn prepare_unit<U: Unit>(&self, setup: &Setup, ops: &mut Ops) -> LaineCoeffs {
        // Filled in place (no array `map` of the ~100-byte axis values: each would be copied).
        let mut c = LaineCoeffs {
            lens: [None; 2],
            dual: [None; 2],
        };
        if U::DEFOCUS && setup.class.defocus() {
            for (a, slot) in c.lens.iter_mut().enumerate() {
                *slot = Some(lens_axis(setup, a, ops));
            }
        }
        if U::MOTION && setup.class.motion() {
            let ext = [setup.viewport.w, setup.viewport.h];
            for ((a, slot), e) in c.dual.iter_mut().enumerate().zip(ext) {
                let ex = setup.eps.x.get(a).copied().unwrap_or(0);
                let eps = ex.saturating_add(setup.eps.w);
                *slot = Some(dual_axis(
                    &setup.tri,
                    &setup.footprint,
                    a,
                    i64::from(e),
                    eps,
                    ops,
                ));
            }
        }
        c
    }

    fn tile_unit<U: Unit>(
        &self,
        setup: &Setup,
        c: &LaineCoeffs,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<UvtBox> {
        let xs = [
            (tile.x0 as i64, tile.x1 as i64),
            (tile.y0 as i64, tile.y1 as i64),
        ];
        let mut b = UvtBox {
            t: setup.span,
            ..UvtBox::FULL
        };
        for (axis, &(p0, p1)) in xs.iter().enumerate() {
            if let (true, Some(Some(l))) = (U::DEFOCUS, c.lens.get(axis)) {
                let lens = lens_s(l, p0, p1, setup.prec.bnd(), ops)?
                    .s_to_lens()
                    .round_out(setup.prec.tuv());
                if axis == 0 {
                    b.u = lens;
                } else {
                    b.v = lens;
                }
            }
            if let (true, Some(Some(d))) = (U::MOTION, c.dual.get(axis)) {
                b.t =
                    b.t.meet(dual_t(d, p0, p1, ops)?.round_out(setup.prec.tuv()))?;
            }
        }
        Some(b)
    }
}
