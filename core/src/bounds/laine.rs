//! Laine et al. 2011 clipless dual-space bounds: lens bounds from setup's lens-corner boxes, time
//! bounds from the dual-space bounding lines (the proof of both is in `bounds::strategy`).

use crate::arith::interval::{solve_le64, Interval, RecipConstraint};
use crate::bounds::strategy::{BoundsStrategy, UvtBox};
use crate::config::formats::DualDelta;
use crate::config::unit::Unit;
use crate::input::{PixelRect, Triangle, W};
use crate::setup::boxes::axis_coord;
use crate::setup::Setup;
use crate::stats::Ops;

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

    // Gated on the unit: lens terms only with `U::DEFOCUS`, dual lines only with `U::MOTION`
    // (for an accepted class the same coefficients: a class without defocus gets no lens axis,
    // one without motion no dual axis, on every unit).
    #[inline(always)]
    fn prepare<U: Unit>(&self, setup: &Setup, ops: &mut Ops) -> LaineCoeffs {
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

    fn tile<U: Unit>(
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
