//! Lens-dependent time bounds after Wu et al. 2014 (stage II): per bounds tile, one t interval
//! per lens sub-region — the lens axis u (for screen x) and v (for screen y) is cut into `R`
//! equal slabs — so the per-sample predicate "t inside the interval of my u slab and of my v slab"
//! follows the oblique (u, t) / (v, t) coverage band that one axis-aligned box cannot.
//!
//! **Why it is conservative.** It is Laine 2011's dual-space t bound (`bounds.rs`) with the
//! lens bias restricted to the slab. Scaled by R, the dual value of vertex k at lens u,
//! `R·δ_k = R·((a_k + w_k)·E − 2·w_k·ξ) + E·(R·u)·cs_k`, is bounded below, for u in slab j
//! (R·u ∈ [2j − R, 2j − R + 2], integers), by `R·δ⁰_k + E·min((2j − R)·cs_k, (2j − R + 2)·cs_k)`
//! and above by the same with max. In t the lower function is affine plus a minimum of affine
//! functions (concave) so it lies above its chord between t = 0 and t = 1; the upper one is
//! convex and lies below its chord. In ξ the minimum over k is concave, so on the footprint
//! [ξa, ξb] it lies above the line through its end values (Laine's bounding lines); a tile takes
//! the lower of that line's values at its two ends. Coverage needs min_k δ_k ≤ 0 ≤ max_k δ_k,
//! which gives, per slab, `(1 − t)·lo0 + t·lo1 ≤ 0` and `(1 − t)·hi0 + t·hi1 ≥ 0`, solved exactly
//! with outward rounding ([`solve_le`]). All values are exact integers (ranges at each function);
//! a sample on a slab boundary lies in both closed slabs, so either slab's interval is valid.
//! The tile's box is Laine's box, narrowed to the slabs with a non-empty interval and to the
//! union of their t intervals; a tile with no non-empty slab on an axis is culled.
//!
//! **Conservative epsilon** (a [`crate::config::precision::Bounded`] precision, `bounded.rs`): that test
//! decides exactly on a triangle whose vertices lie within ε_x (this axis) and ε_w of the exact
//! ones at the sample's (t, u, v) ([`crate::setup::eps::Eps`]). A vertex perturbed by δa, δw moves
//! its dual value by `δa·E + δw·(E − 2ξ)`, at most `(ε_x + ε_w)·E` for ξ ∈ [0, E] (the footprint
//! lies in the viewport), i.e. `R·(ε_x + ε_w)·E` scaled by R: the lower per-slab bound is lowered
//! and the upper raised by that constant, exactly Laine's term (`bounds.rs`, `dual_axis`). A
//! constant keeps the concavity and chord arguments above, and coverage of the perturbed triangle
//! still needs `min_k δ'_k ≤ 0 ≤ max_k δ'_k` (it covers d = Σ b_k·P'_k with b_k ≥ 0, not all 0,
//! and the dual value of d at its own pixel is 0). With ε = 0 the values are unchanged.
#![warn(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_possible_wrap
)]

use crate::arith::interval::{solve_le, Interval};
use crate::bounds::laine::{DualAxis, Laine2011, LaineCoeffs};
use crate::bounds::strategy::{BoundsStrategy, TileBounds, UvtBox};
use crate::config::class::Class;
use crate::config::formats::{TUV_FRAC, TUV_ONE};
use crate::config::unit::Unit;
use crate::input::{PixelRect, Triangle, W};
use crate::setup::boxes::axis_coord;
use crate::setup::Setup;
use crate::stats::Ops;

/// Laine 2011 bounds plus one t interval per lens slab and axis (`R` ∈ {1, 2, 4, 8} slabs).
#[derive(Clone, Copy, Debug, Default)]
pub struct LensTime<const R: usize>;

/// [`LensTime`] coefficients: Laine's, and for a motion + defocus triangle the dual-space
/// values of every slab, `[axis][slab]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LensTimeCoeffs<const R: usize> {
    laine: LaineCoeffs,
    slabs: Option<[[DualAxis; R]; 2]>,
}

impl<const R: usize> LensTimeCoeffs<R> {
    /// Laine's coefficients.
    pub fn laine(&self) -> &LaineCoeffs {
        &self.laine
    }
    /// The per-slab dual values `[axis][slab]` (motion + defocus triangles only).
    pub fn slabs(&self) -> Option<&[[DualAxis; R]; 2]> {
        self.slabs.as_ref()
    }
}

/// One tile: the box and, for a motion + defocus triangle, the t interval of every slab
/// (`None`: no sample of that slab is covered).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LensTimeTile<const R: usize> {
    b: UvtBox,
    t: Option<[[Option<Interval>; R]; 2]>,
}

impl<const R: usize> LensTimeTile<R> {
    /// t interval of slab `slab` on axis `axis` (0: u/x, 1: v/y); `None` if empty or no slabs.
    pub fn slab(&self, axis: usize, slab: usize) -> Option<Interval> {
        self.t.as_ref()?.get(axis)?.get(slab).copied().flatten()
    }
}

impl<const R: usize> LensTime<R> {
    /// log2 R; refuses (at compile time) an R that is not 1, 2, 4 or 8.
    const LOG: u32 = {
        assert!(
            R == 1 || R == 2 || R == 4 || R == 8,
            "LensTime: R must be 1, 2, 4 or 8"
        );
        R.trailing_zeros()
    };

    /// The slab count R ∈ {1, 2, 4, 8} as u64 and i64 (checked at compile time by `LOG`).
    #[allow(clippy::cast_possible_truncation, clippy::cast_possible_wrap)]
    const SUBS: u64 = R as u64;
    /// See [`Self::SUBS`].
    #[allow(clippy::cast_possible_truncation, clippy::cast_possible_wrap)]
    const R: i64 = R as i64;

    /// `R·u` at the low end of slab `j` (exact: 2j − R with j < R ≤ 8).
    #[allow(clippy::arithmetic_side_effects, clippy::cast_possible_wrap)]
    fn slab_lo(j: usize) -> i64 {
        2 * j as i64 - R as i64
    }

    /// Raw lens range `[lo, hi]` of slab `j` (j < R ≤ 8: |values| ≤ 2^16; R divides 2^16, so the
    /// shift is an exact division).
    #[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]
    fn slab_range(j: usize) -> Interval {
        let step = (2 * TUV_ONE) >> Self::LOG;
        let lo = (Self::slab_lo(j) * i64::from(TUV_ONE)) >> Self::LOG;
        let lo = lo as i32; // |lo| ≤ 2^16
                            // lo ∈ [−2^16, 2^16 − step] for j < R, so [lo, lo + step] ⊆ [−1, 1]: `new` cannot refuse
                            // it; the fallback (the whole lens) would only widen the bound.
        Interval::new(lo, lo + step).unwrap_or(Interval::LENS)
    }

    /// Slab index of raw lens coordinate `u` ∈ [−2^16, 2^16].
    #[allow(clippy::arithmetic_side_effects, clippy::cast_sign_loss)]
    fn slab_of(u: i32) -> usize {
        // u + 2^16 ∈ [0, 2^17] (the sample constructor enforces the lens domain); shift < 18.
        let i = ((u.clamp(-TUV_ONE, TUV_ONE) + TUV_ONE) >> (TUV_FRAC + 1 - Self::LOG)) as usize;
        i.min(R - 1)
    }
}

/// Per-slab dual values of one axis: like Laine's `dual_axis`, scaled by R, with the bias of
/// lens range `R·u ∈ [k, k + 2]` and the conservative epsilon `eps = ε_x + ε_w` (module docs).
#[allow(clippy::arithmetic_side_effects)]
fn slab_axis(
    tri: &Triangle,
    xi: [i64; 2],
    axis: usize,
    e: i64,
    r: i64,
    k: i64,
    eps: i64,
) -> DualAxis {
    // r ≤ 8, eps < 2^25, E ≤ 2^11: |pert| < 2^39.
    let pert = r * eps * e;
    let mut lo = [[i64::MAX; 2]; 2];
    let mut hi = [[i64::MIN; 2]; 2];
    for ((ends, lo_t), hi_t) in tri.v.iter().zip(lo.iter_mut()).zip(hi.iter_mut()) {
        for p in ends.iter() {
            let (a, cs) = axis_coord(p, axis);
            let w = i64::from(*p.get(W).unwrap_or(&0));
            // |a + w| < 2^31, E, ξ ≤ 2^11, r ≤ 8, |k|, |k + 2| ≤ 8, |cs| ≤ 2^29:
            // |base| < 2^46, |bias| ≤ 2^43, |pert| < 2^39: every value < 2^47.
            let (b1, b2) = (k * cs * e, (k + 2) * cs * e);
            for ((l, h), x) in lo_t.iter_mut().zip(hi_t.iter_mut()).zip(xi.iter()) {
                let base = r * ((a + w) * e - 2 * w * x);
                *l = (*l).min(base + b1.min(b2) - pert);
                *h = (*h).max(base + b1.max(b2) + pert);
            }
        }
    }
    DualAxis { xi, lo, hi }
}

/// t interval of one slab for tile ends [x0, x1] ⊆ [ξa, ξb] (Laine's bounding lines).
#[allow(clippy::arithmetic_side_effects)]
fn slab_t(d: &DualAxis, x0: i64, x1: i64) -> Option<Interval> {
    let [xa, xb] = d.xi;
    // |v| < 2^47, 0 ≤ xb − x, x − xa ≤ 2^11: each product < 2^58, sums < 2^59 (i128).
    let line = |v: &[i64; 2], x: i64| {
        i128::from(v[0]) * i128::from(xb - x) + i128::from(v[1]) * i128::from(x - xa)
    };
    let [lo0, lo1] = d.lo.map(|v| line(&v, x0).min(line(&v, x1)));
    let [hi0, hi1] = d.hi.map(|v| line(&v, x0).max(line(&v, x1)));
    // (1−t)·lo0 + t·lo1 ≤ 0  and  (1−t)·hi0 + t·hi1 ≥ 0; differences < 2^60.
    solve_le(lo1 - lo0, -lo0)?.meet(solve_le(hi0 - hi1, hi0)?)
}

impl<const R: usize> BoundsStrategy for LensTime<R> {
    type Coeffs = LensTimeCoeffs<R>;
    type Tile = LensTimeTile<R>;
    fn name(&self) -> &'static str {
        "lens-t"
    }

    #[inline(always)]
    fn prepare<U: Unit>(&self, setup: &Setup, ops: &mut Ops) -> Self::Coeffs {
        let laine = Laine2011.prepare::<U>(setup, ops);
        let slabs = (setup.class == Class::MotionDefocus).then(|| {
            let fp = setup.footprint;
            let xi = [
                [i64::from(fp.x0), i64::from(fp.x1)],
                [i64::from(fp.y0), i64::from(fp.y1)],
            ];
            let ext = [
                i64::from(setup.viewport.width()),
                i64::from(setup.viewport.height()),
            ];
            // 6 vertex ends × 2 footprint ends × 9 ops, per slab and axis.
            ops.setup = ops
                .setup
                .saturating_add(108u64.saturating_mul(2u64.saturating_mul(Self::SUBS)));
            let r = Self::R;
            [0usize, 1].map(|axis| {
                let (x, e) = (xi.get(axis).copied(), ext.get(axis).copied());
                let (x, e) = (x.unwrap_or([0, 0]), e.unwrap_or(0));
                // The conservative epsilon of this axis, ε_x + ε_w (0 for the exact test).
                let ex = setup.eps.x.get(axis).copied().unwrap_or(0);
                let eps = i64::from(ex.saturating_add(setup.eps.w));
                core::array::from_fn(|j| {
                    slab_axis(&setup.tri, x, axis, e, r, Self::slab_lo(j), eps)
                })
            })
        });
        LensTimeCoeffs { laine, slabs }
    }

    fn tile<U: Unit>(
        &self,
        setup: &Setup,
        c: &Self::Coeffs,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<Self::Tile> {
        let mut b = Laine2011.tile::<U>(setup, &c.laine, tile, ops)?;
        let Some(slabs) = c.slabs.as_ref() else {
            return Some(LensTimeTile { b, t: None });
        };
        let ends = [
            (i64::from(tile.x0), i64::from(tile.x1)),
            (i64::from(tile.y0), i64::from(tile.y1)),
        ];
        let mut t = [[None; R]; 2];
        for ((axis_slabs, axis_t), (axis, &(p0, p1))) in
            slabs.iter().zip(t.iter_mut()).zip(ends.iter().enumerate())
        {
            let lens = if axis == 0 { b.u } else { b.v };
            let (mut lens_hull, mut t_hull): (Option<Interval>, Option<Interval>) = (None, None);
            for (j, (d, out)) in axis_slabs.iter().zip(axis_t.iter_mut()).enumerate() {
                ops.bounds = ops.bounds.saturating_add(2);
                let Some(range) = Self::slab_range(j).meet(lens) else {
                    continue;
                };
                ops.bounds = ops.bounds.saturating_add(34);
                let Some(iv) = slab_t(d, p0, p1).and_then(|iv| iv.meet(b.t)) else {
                    continue;
                };
                let iv = iv.round_out(setup.prec.tuv());
                *out = Some(iv);
                lens_hull = Some(hull(lens_hull, range));
                t_hull = Some(hull(t_hull, iv));
            }
            let (l, th) = (lens_hull?, t_hull?);
            if axis == 0 {
                b.u = l;
            } else {
                b.v = l;
            }
            b.t = b.t.meet(th)?;
        }
        Some(LensTimeTile { b, t: Some(t) })
    }
}

fn hull(a: Option<Interval>, b: Interval) -> Interval {
    match a {
        Some(a) => a.join(b),
        None => b,
    }
}

impl<const R: usize> TileBounds for LensTimeTile<R> {
    fn uvt_box(&self) -> &UvtBox {
        &self.b
    }
    /// t inside the interval of the sample's u slab and of its v slab: per axis a slab index
    /// (add, shift, min) and two compares, 5 operations.
    fn predicate(&self, u: i32, v: i32, t: i32, ops: &mut Ops) -> bool {
        let Some(slabs) = self.t.as_ref() else {
            return true;
        };
        let [sx, sy] = slabs;
        ops.predicate = ops.predicate.saturating_add(5);
        let ok = |s: &[Option<Interval>; R], l: i32| matches!(s.get(LensTime::<R>::slab_of(l)), Some(Some(iv)) if iv.contains(t));
        if !ok(sx, u) {
            return false;
        }
        ops.predicate = ops.predicate.saturating_add(5);
        ok(sy, v)
    }
}
