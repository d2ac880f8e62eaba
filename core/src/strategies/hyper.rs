//! Joint (u, t) and (v, t) bounds after Munkberg & Akenine-Möller 2012 ("Hyperplane Culling for
//! Stochastic Rasterization"): instead of a box, per bounds tile and axis, one lower and one
//! upper bounding surface of the dual-space values over the whole (t, lens) square, checked per
//! sample. The surfaces are bilinear in (t, s) (s = (u + 1)/2): the interpolation of four
//! corner values, tighter than a separating plane wherever the coverage band is oblique.
//!
//! **Why it is conservative.** Dual value of vertex k on one axis (`bounds.rs`):
//! `f_k(t, u, ξ) = (a_k(t) + u·cs_k(t) + w_k(t))·E − 2·w_k(t)·ξ`, with a, cs, w affine in t, so
//! f_k is affine in t (fixed u, ξ), in u (fixed t, ξ) and in ξ (fixed t, u), for any sign of w.
//! Coverage needs `g = min_k f_k ≤ 0 ≤ max_k f_k = G`. g is a minimum of functions affine in each
//! variable, hence concave in each variable separately, so with non-negative weights:
//! `g(t, u, ξ) ≥ (1−t)·g(0, u, ξ) + t·g(1, u, ξ)`, `g(τ, u, ξ) ≥ (1−s)·g(τ, −1, ξ) + s·g(τ, 1, ξ)`,
//! and on the footprint [ξa, ξb] `g(τ, ±1, ξ)` is above the line through its end values (Laine's
//! bounding lines); a tile takes the lower of that line's values at its two ends: A_τ (u = −1) and
//! B_τ (u = +1). So `L(t, s) = (1−t)((1−s)A0 + sB0) + t((1−s)A1 + sB1) ≤ g`, and a covered sample
//! has L ≤ 0; symmetrically the upper surface U ≥ G (convex, chords above, max of tile ends) has
//! U ≥ 0. Scaled by 2^33 with the sample's raw t (16 bits) and σ = u + 2^16 (17 bits), L is
//! `c0 + c1·σ + c2·t + c3·t·σ` with integer coefficients: exact, no rounding at all (the sample's
//! raw values are used directly). Ranges at each function; overflow (outside the domain) admits.
//!
//! **Conservative epsilon** (a [`crate::formats::Bounded`] precision, `bounded.rs`): that test
//! decides exactly on a triangle whose vertices lie within ε_x (this axis) and ε_w of the exact
//! ones at the sample's (t, u, v) ([`crate::bounded::Eps`]), and covers d only if
//! `min_k f'_k ≤ 0 ≤ max_k f'_k` for its perturbed values f' (d = Σ b_k·P'_k, b_k ≥ 0 not all 0,
//! and d's own dual value is 0). A perturbation δa, δw moves `f_k` by `δa·E + δw·(E − 2ξ)`, at
//! most `(ε_x + ε_w)·E` for ξ ∈ [0, E] (the footprint lies in the viewport), so
//! `min_k f'_k ≥ g − (ε_x + ε_w)·E ≥ L − (ε_x + ε_w)·E`. Setup lowers every lower corner value
//! and raises every upper one by that constant (Laine's term, `bounds.rs`, `dual_axis`); the
//! bilinear interpolation of corner values lowered by a constant is L lowered by it, so the
//! argument above holds unchanged. With ε = 0 the values are unchanged.
#![warn(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_possible_wrap
)]

use crate::bounds::{BoundsStrategy, Laine2011, LaineCoeffs, TileBounds, UvtBox};
use crate::input::{PixelRect, Triangle, W};
use crate::setup::{axis_coord, Class, Setup};
use crate::stats::Ops;

/// Laine 2011's box plus bilinear (u, t) / (v, t) bounding surfaces checked per sample.
#[derive(Clone, Copy, Debug, Default)]
pub struct Hyper;

/// Dual values of one axis at the corners: `[t][lens −1/+1][footprint end]`, lower (min over
/// vertices) and upper (max), and the footprint ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HyperAxis {
    xi: [i64; 2],
    lo: [[[i64; 2]; 2]; 2],
    hi: [[[i64; 2]; 2]; 2],
}

/// [`Hyper`] coefficients: Laine's, and the corner values per axis (motion + defocus only).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HyperCoeffs {
    laine: LaineCoeffs,
    axes: Option<[HyperAxis; 2]>,
}

/// One surface `c0 + c1·σ + c2·t + c3·t·σ` (sign: ≤ 0 for the lower, ≥ 0 for the upper).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Surface {
    c: [i128; 4],
}

/// One tile: Laine's box and, for a motion + defocus triangle, `[axis][lower, upper]` surfaces.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HyperTile {
    b: UvtBox,
    s: Option<[[Surface; 2]; 2]>,
}

/// Corner values of one axis, widened by the conservative epsilon `eps = ε_x + ε_w` (module
/// docs). |a + w| < 2^31, |cs| ≤ 2^29, E, ξ ≤ 2^11: |f| < 2^44; eps < 2^25: |eps·E| < 2^36, so
/// every widened value is < 2^45.
#[allow(clippy::arithmetic_side_effects)]
fn hyper_axis(tri: &Triangle, xi: [i64; 2], axis: usize, e: i64, eps: i64) -> HyperAxis {
    let pert = eps * e;
    let mut lo = [[[i64::MAX; 2]; 2]; 2];
    let mut hi = [[[i64::MIN; 2]; 2]; 2];
    for ((ends, lo_t), hi_t) in tri.v.iter().zip(lo.iter_mut()).zip(hi.iter_mut()) {
        for p in ends.iter() {
            let (a, cs) = axis_coord(p, axis);
            let w = i64::from(*p.get(W).unwrap_or(&0));
            for ((lo_l, hi_l), lens) in lo_t.iter_mut().zip(hi_t.iter_mut()).zip([-1i64, 1]) {
                for ((l, h), x) in lo_l.iter_mut().zip(hi_l.iter_mut()).zip(xi.iter()) {
                    let f = (a + lens * cs + w) * e - 2 * w * x;
                    *l = (*l).min(f - pert);
                    *h = (*h).max(f + pert);
                }
            }
        }
    }
    HyperAxis { xi, lo, hi }
}

/// Surface through corner values `v[t][lens]` (already bounded over the tile):
/// 2^33·L = 2^33·A0 + 2^16·(B0 − A0)·σ + 2^17·(A1 − A0)·t + (A0 − B0 − A1 + B1)·t·σ.
/// |v| < 2^56 (line values scaled by ξb − ξa ≤ 2^11): |c0| < 2^89, the others < 2^75.
fn surface(v: [[i128; 2]; 2]) -> Option<Surface> {
    let [[a0, b0], [a1, b1]] = v;
    let c0 = a0.checked_mul(1 << 33)?;
    let c1 = b0.checked_sub(a0)?.checked_mul(1 << 16)?;
    let c2 = a1.checked_sub(a0)?.checked_mul(1 << 17)?;
    let c3 = a0.checked_sub(b0)?.checked_sub(a1)?.checked_add(b1)?;
    Some(Surface {
        c: [c0, c1, c2, c3],
    })
}

impl Surface {
    /// Value at raw t ∈ [0, 2^16] and σ = u + 2^16 ∈ [0, 2^17], with `ts = t·σ` (≤ 2^33):
    /// every term < 2^108, exact; `None` on overflow.
    fn eval(&self, t: i128, sigma: i128, ts: i128) -> Option<i128> {
        let [c0, c1, c2, c3] = self.c;
        c0.checked_add(c1.checked_mul(sigma)?)?
            .checked_add(c2.checked_mul(t)?)?
            .checked_add(c3.checked_mul(ts)?)
    }
}

/// The four surfaces' corner values for tile ends [x0, x1] ⊆ [ξa, ξb]: lower = min of the two
/// ends of each bounding line, upper = max. Values scaled by ξb − ξa (> 0).
#[allow(clippy::arithmetic_side_effects)]
fn tile_surfaces(d: &HyperAxis, x0: i64, x1: i64) -> Option<[Surface; 2]> {
    let [xa, xb] = d.xi;
    // |v| < 2^45, 0 ≤ xb − x, x − xa with (xb − x) + (x − xa) = xb − xa ≤ 2^11: |line| < 2^56.
    let line = |v: &[i64; 2], x: i64| {
        i128::from(v[0]) * i128::from(xb - x) + i128::from(v[1]) * i128::from(x - xa)
    };
    let lo = d.lo.map(|l| l.map(|v| line(&v, x0).min(line(&v, x1))));
    let hi = d.hi.map(|l| l.map(|v| line(&v, x0).max(line(&v, x1))));
    Some([surface(lo)?, surface(hi)?])
}

impl BoundsStrategy for Hyper {
    type Coeffs = HyperCoeffs;
    type Tile = HyperTile;
    fn name(&self) -> &'static str {
        "hyper"
    }
    fn prepare(&self, setup: &Setup, ops: &mut Ops) -> HyperCoeffs {
        let laine = Laine2011.prepare(setup, ops);
        let axes = (setup.class == Class::MotionDefocus).then(|| {
            let fp = setup.footprint;
            let vp = setup.viewport;
            // The conservative epsilon per axis, ε_x + ε_w (0 for the exact test).
            let eps = |axis: usize| {
                let ex = setup.eps.x.get(axis).copied().unwrap_or(0);
                i64::from(ex.saturating_add(setup.eps.w))
            };
            // 6 vertex ends × 2 lens corners × 2 footprint ends × 9 ops, per axis.
            ops.setup = ops.setup.saturating_add(2 * 216);
            [
                hyper_axis(
                    &setup.tri,
                    [i64::from(fp.x0), i64::from(fp.x1)],
                    0,
                    i64::from(vp.width()),
                    eps(0),
                ),
                hyper_axis(
                    &setup.tri,
                    [i64::from(fp.y0), i64::from(fp.y1)],
                    1,
                    i64::from(vp.height()),
                    eps(1),
                ),
            ]
        });
        HyperCoeffs { laine, axes }
    }
    fn tile(
        &self,
        setup: &Setup,
        c: &HyperCoeffs,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<HyperTile> {
        let b = Laine2011.tile(setup, &c.laine, tile, ops)?;
        let s = c.axes.as_ref().and_then(|[x, y]| {
            // 16 line values (3 ops) + 8 min/max + 2 × 7 coefficient ops, per axis.
            ops.bounds = ops.bounds.saturating_add(2 * 70);
            let sx = tile_surfaces(x, i64::from(tile.x0), i64::from(tile.x1))?;
            let sy = tile_surfaces(y, i64::from(tile.y0), i64::from(tile.y1))?;
            Some([sx, sy])
        });
        Some(HyperTile { b, s })
    }
}

impl TileBounds for HyperTile {
    fn uvt_box(&self) -> &UvtBox {
        &self.b
    }
    /// Per axis: σ (1 add), t·σ (1 mul), two surfaces (3 mul, 3 add, 1 compare each): 16 ops.
    fn predicate(&self, u: i32, v: i32, t: i32, ops: &mut Ops) -> bool {
        let Some(axes) = self.s.as_ref() else {
            return true;
        };
        let t = i128::from(t);
        for ([lo, hi], lens) in axes.iter().zip([u, v]) {
            ops.predicate = ops.predicate.saturating_add(16);
            let sigma = i128::from(lens).saturating_add(1 << 16);
            let ts = t.saturating_mul(sigma);
            let below = lo.eval(t, sigma, ts).map_or(true, |x| x <= 0);
            let above = hi.eval(t, sigma, ts).map_or(true, |x| x >= 0);
            if !(below && above) {
                return false;
            }
        }
        true
    }
}
