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
//! **Conservative epsilon** (a [`crate::config::precision::Bounded`] precision, `bounded.rs`): that test
//! decides exactly on a triangle whose vertices lie within ε_x (this axis) and ε_w of the exact
//! ones at the sample's (t, u, v) ([`crate::setup::eps::Eps`]), and covers d only if
//! `min_k f'_k ≤ 0 ≤ max_k f'_k` for its perturbed values f' (d = Σ b_k·P'_k, b_k ≥ 0 not all 0,
//! and d's own dual value is 0). A perturbation δa, δw moves `f_k` by `δa·E + δw·(E − 2ξ)`, at
//! most `(ε_x + ε_w)·E` for ξ ∈ [0, E] (the footprint lies in the viewport), so
//! `min_k f'_k ≥ g − (ε_x + ε_w)·E ≥ L − (ε_x + ε_w)·E`. Setup lowers every lower corner value
//! and raises every upper one by that constant (Laine's term, `bounds.rs`, `dual_axis`); the
//! bilinear interpolation of corner values lowered by a constant is L lowered by it, so the
//! argument above holds unchanged. With ε = 0 the values are unchanged.
//!
//! **Per-tile cost.** Each bounding line is affine in ξ: `v0·(ξb − ξ) + v1·(ξ − ξa) = K + S·ξ`,
//! so of a tile's two ends [xl, xl + n] the lower (upper) value is at the end the sign of S picks
//! (known in setup): `K + S·xl + T·n` with `T = min(S, 0)` (`max(S, 0)`), exactly the min (max)
//! of the two end values. The coefficients c0..c3 are a fixed linear map of the corner values,
//! so each is `α + β·xl + γ·(n − 1)` with integers α, β, γ computed once in `prepare`; a tile
//! evaluates `α + β·xl` (2 ops per coefficient, 16 per axis, plus the width n and the compare
//! n = 1) and adds `γ·(n − 1)` only when its side is not 1 pixel. The surfaces are the same integers
//! as those of the corner values evaluated per tile (`core/src/verify/hyper_reference.rs`
//! compares every tile with that formulation).
#![warn(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_possible_wrap
)]

use crate::bounds::laine::{Laine2011, LaineCoeffs};
use crate::bounds::strategy::{BoundsStrategy, TileBounds, UvtBox};
use crate::config::class::Class;
use crate::config::unit::Unit;
use crate::input::{PixelRect, Triangle, W};
use crate::setup::boxes::axis_coord;
use crate::setup::Setup;
use crate::stats::Ops;

/// Laine 2011's box plus bilinear (u, t) / (v, t) bounding surfaces checked per sample.
#[derive(Clone, Copy, Debug, Default)]
pub struct Hyper;

/// Dual values of one axis at the corners: `[t][lens −1/+1][footprint end]`, lower (min over
/// vertices) and upper (max), and the footprint ends (setup's intermediate; the per-tile form is
/// [`HyperAxis`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Corners {
    pub(crate) xi: [i64; 2],
    pub(crate) lo: [[[i64; 2]; 2]; 2],
    pub(crate) hi: [[[i64; 2]; 2]; 2],
}

/// One surface coefficient as an affine function of the tile: `α + β·xl + γ·(n − 1)`, with xl
/// the tile's first column (row) and n its width (height) in pixels.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Affine {
    a: i128,
    b: i128,
    g: i128,
}

/// Per-tile form of one axis: `[lower, upper]` surfaces' coefficients c0..c3 (module docs,
/// "Per-tile cost").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HyperAxis {
    c: [[Affine; 4]; 2],
}

/// [`Hyper`] coefficients: Laine's, and the per-tile surface forms per axis (motion + defocus
/// only).
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
    pub(crate) b: UvtBox,
    pub(crate) s: Option<[[Surface; 2]; 2]>,
}

/// Corner values of one axis, widened by the conservative epsilon `eps = ε_x + ε_w` (module
/// docs). |a + w| < 2^31, |cs| ≤ 2^29, E, ξ ≤ 2^11: |f| < 2^44; eps < 2^25: |eps·E| < 2^36, so
/// every widened value is < 2^45.
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn corners(tri: &Triangle, xi: [i64; 2], axis: usize, e: i64, eps: i64) -> Corners {
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
    Corners { xi, lo, hi }
}

/// Surface through corner values `v[t][lens]` (already bounded over the tile):
/// 2^33·L = 2^33·A0 + 2^16·(B0 − A0)·σ + 2^17·(A1 − A0)·t + (A0 − B0 − A1 + B1)·t·σ.
/// A linear map of the corner values (checked; `None` on overflow): |v| < 2^58 gives |c0| <
/// 2^91, the others < 2^76.
pub(crate) fn surface(v: [[i128; 2]; 2]) -> Option<Surface> {
    let [[a0, b0], [a1, b1]] = v;
    let c0 = a0.checked_mul(1 << 33)?;
    let c1 = b0.checked_sub(a0)?.checked_mul(1 << 16)?;
    let c2 = a1.checked_sub(a0)?.checked_mul(1 << 17)?;
    let c3 = a0.checked_sub(b0)?.checked_sub(a1)?.checked_add(b1)?;
    Some(Surface {
        c: [c0, c1, c2, c3],
    })
}

/// One bounding line's value over a tile [xl, xl + n] (n ≥ 0) as an [`Affine`]: the line
/// `v0·(ξb − x) + v1·(x − ξa)` is `K + S·x` with `K = v0·ξb − v1·ξa`, `S = v1 − v0`; its
/// minimum over the tile's two ends is `K + S·xl + min(S, 0)·n` (maximum: `max(S, 0)`), i.e.
/// `α = K + T`, `β = S`, `γ = T` with `T = min(S, 0)` (`max`). Exact: |v| < 2^45 and
/// 0 ≤ ξa, ξb ≤ 2^11 (the footprint lies in the viewport): |K| < 2^57, |S|, |T| < 2^46,
/// |α| < 2^58 in i128.
#[allow(clippy::arithmetic_side_effects)]
fn line_affine(v: [i64; 2], xi: [i64; 2], low: bool) -> Affine {
    let [v0, v1] = v.map(i128::from);
    let [xa, xb] = xi.map(i128::from);
    let k = v0 * xb - v1 * xa;
    let s = v1 - v0;
    let t = if low { s.min(0) } else { s.max(0) };
    Affine {
        a: k + t,
        b: s,
        g: t,
    }
}

/// [`surface`] applied to each of α, β, γ of the corners' affine forms: the surface map is
/// linear, so the resulting α + β·xl + γ·(n − 1) is exactly the surface of the corner values.
fn surface_affine(v: [[Affine; 2]; 2]) -> Option<[Affine; 4]> {
    let a = surface(v.map(|r| r.map(|x| x.a)))?.c;
    let b = surface(v.map(|r| r.map(|x| x.b)))?.c;
    let g = surface(v.map(|r| r.map(|x| x.g)))?.c;
    let mut out = [Affine::default(); 4];
    for (o, ((a, b), g)) in out.iter_mut().zip(a.into_iter().zip(b).zip(g)) {
        *o = Affine { a, b, g };
    }
    Some(out)
}

/// The per-tile form of one axis from its corner values ([`AXIS_FORM_OPS`], counted in
/// `ops.setup` by the caller).
fn axis_form(d: &Corners) -> Option<HyperAxis> {
    let lo = d.lo.map(|l| l.map(|v| line_affine(v, d.xi, true)));
    let hi = d.hi.map(|l| l.map(|v| line_affine(v, d.xi, false)));
    Some(HyperAxis {
        c: [surface_affine(lo)?, surface_affine(hi)?],
    })
}

/// Setup ops of [`axis_form`] per axis: 8 lines (4 lower, 4 upper: t ∈ {0, 1} × 2 lens
/// corners) × 6 (K: 2 mul + 1 sub; S: 1 sub; T: 1 min/max; α: 1 add) + 2 surfaces × 3
/// components (α, β, γ) × 5 (the adds and subtracts of [`surface`]'s corner map; its ×2^k are
/// shifts).
const AXIS_FORM_OPS: u64 = 8 * 6 + 2 * 3 * 5;

/// The tile's start and width along one axis: `(min(x0, x1), |x1 − x0|)`. A renderer tile has
/// x0 < x1, so the ordering is the identity there (not counted, as in `bounds::dual_t`).
fn start_width(x0: u16, x1: u16) -> (i128, i128) {
    let (l, h) = (x0.min(x1), x0.max(x1));
    (i128::from(l), i128::from(h).saturating_sub(i128::from(l)))
}

impl HyperAxis {
    /// The `[lower, upper]` surfaces of the tile [xl, xl + n]: each coefficient `α + β·xl`, plus
    /// `γ·(n − 1)` when n ≠ 1. Counted: n (1 sub) and n = 1 (1 compare), 2 ops per coefficient
    /// (1 mul, 1 add), and for n ≠ 1 another 1 + 2 per coefficient: 18 ops for a 1-pixel tile
    /// side, 35 otherwise. Exact: |α| < 2^91, |β|, |γ| < 2^80 ([`surface`] of |α| < 2^58 and
    /// |S|, |T| < 2^46 per line), 0 ≤ xl, n < 2^16: every term < 2^97; checked anyway (`None`
    /// admits, never reached).
    fn surfaces(&self, xl: i128, n: i128, ops: &mut Ops) -> Option<[Surface; 2]> {
        ops.add_bounds(2 + 16);
        let m = n.checked_sub(1)?;
        if m != 0 {
            ops.add_bounds(1 + 16);
        }
        let eval = |f: &Affine| {
            let v = f.a.checked_add(f.b.checked_mul(xl)?)?;
            if m == 0 {
                Some(v)
            } else {
                v.checked_add(f.g.checked_mul(m)?)
            }
        };
        let mut out = [Surface { c: [0; 4] }; 2];
        for (o, cs) in out.iter_mut().zip(self.c.iter()) {
            for (c, f) in o.c.iter_mut().zip(cs.iter()) {
                *c = eval(f)?;
            }
        }
        Some(out)
    }
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

impl BoundsStrategy for Hyper {
    type Coeffs = HyperCoeffs;
    type Tile = HyperTile;
    fn name(&self) -> &'static str {
        "hyper"
    }
    #[inline(always)]
    fn prepare<U: Unit>(&self, setup: &Setup, ops: &mut Ops) -> HyperCoeffs {
        let laine = Laine2011.prepare::<U>(setup, ops);
        let axes = (setup.class == Class::MotionDefocus).then(|| {
            let fp = setup.footprint;
            let vp = setup.viewport;
            // The conservative epsilon per axis, ε_x + ε_w (0 for the exact test).
            let eps = |axis: usize| {
                let ex = setup.eps.x.get(axis).copied().unwrap_or(0);
                i64::from(ex.saturating_add(setup.eps.w))
            };
            // 6 vertex ends × 2 lens corners × 2 footprint ends × 9 ops, and the per-tile form,
            // per axis.
            ops.add_setup(2 * (216 + AXIS_FORM_OPS));
            let x = corners(
                &setup.tri,
                [i64::from(fp.x0), i64::from(fp.x1)],
                0,
                i64::from(vp.width()),
                eps(0),
            );
            let y = corners(
                &setup.tri,
                [i64::from(fp.y0), i64::from(fp.y1)],
                1,
                i64::from(vp.height()),
                eps(1),
            );
            Some([axis_form(&x)?, axis_form(&y)?])
        });
        let axes = axes.flatten();
        HyperCoeffs { laine, axes }
    }
    fn tile<U: Unit>(
        &self,
        setup: &Setup,
        c: &HyperCoeffs,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<HyperTile> {
        let b = Laine2011.tile::<U>(setup, &c.laine, tile, ops)?;
        let s = c.axes.as_ref().and_then(|[x, y]| {
            let (xl, nx) = start_width(tile.x0, tile.x1);
            let (yl, ny) = start_width(tile.y0, tile.y1);
            Some([x.surfaces(xl, nx, ops)?, y.surfaces(yl, ny, ops)?])
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
