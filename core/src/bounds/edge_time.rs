//! Edge-direction time bounds for moving triangles: Laine 2011's dual-space t bound
//! (`bounds.rs`, `dual_axis`/`dual_t`) taken along one more screen direction n — the normal of
//! the triangle's most oblique edge at mid-shutter — and intersected with the inner strategy's
//! box ([`EdgeTime`] wraps any strategy). By the separating-axis theorem a triangle and a
//! rectangle are disjoint iff they are separated along x, y or one of the triangle's edge
//! normals; Laine's x and y intervals cover the first two, and for a translating triangle (its
//! edges keep their direction) this bound is the tile-vs-edge test at every t. Axis-aligned edges
//! need nothing (they are Laine's x / y), so setup picks the edge that cuts the most from the
//! triangle's box: the one with the largest |Δξ·Δη| on screen.
//!
//! **Why it is conservative (any integer n, also when vertices cross the camera plane).** For a
//! pixel-space direction n = (n_x, n_y) (ξ right, η down, pixels) and a sample at (ξ, η) take
//! the linear functional of a homogeneous clip point p = (x, y, w)
//! `φ(p) = n_x·((x + w)·W − 2w·ξ) + n_y·((w − y)·H − 2w·η) = A(p) − 2w·ζ`, with
//! `A(p) = n_x·W·(x + w) + n_y·H·(w − y)` and `ζ = n_x·ξ + n_y·η` (the sample's coordinate along
//! n): `n_x` times Laine's x dual value plus `n_y` times his y one (`axis_coord` negates y). The
//! sample's direction `d ∝ (2ξ/W − 1, 1 − 2η/H, 1)` (`sample::direction`) has `φ(d) = 0`. The
//! sample test covers d only if `d = Σ b_k·P_k` with every b_k ≥ 0, not all 0 (Cramer's rule,
//! as in `hull.rs`), so `0 = Σ b_k·φ(P_k)` and coverage needs `min_k φ(P_k) ≤ 0 ≤ max_k φ(P_k)` —
//! no projection, so nothing depends on the sign of any w. For a motion-only triangle,
//! `P_k(t)` is affine in t, so `φ(P_k(t))` is affine in t (fixed ζ) and in ζ (fixed t). With
//! defocus, the lens moves vertex k by `u·c_k(t)` in x and by `v·c_k(t)` in y (|u|, |v| ≤ 1,
//! c_k affine in t), which moves φ by at most `L·|c_k(t)|` with `L = |n_x|·W + |n_y|·H` (as
//! Laine's lens bias `|c|·E` per axis); `φ_k − L·|c_k|` is concave in t (|c_k| is convex) and
//! affine in ζ, and its minimum over k is ≤ the minimum over the lens-shifted vertices. Then
//! exactly Laine's argument, with φ_k lowered by `L·|c_k|` (raised, for the maximum):
//! `g = min_k φ_k` is concave in t, so `g(t, ζ) ≥ (1 − t)·g(0, ζ) +
//! t·g(1, ζ)`; concave in ζ, so on the footprint's range `[ζa, ζb]` of ζ (min / max over its
//! corners; every covered sample lies in the footprint) `g(τ, ·)` is above the line through its
//! values at ζa and ζb; the tile's samples have ζ in the tile's range `[ζ0, ζ1]` ⊆ `[ζa, ζb]` (the
//! closed tile rectangle's corners), where a line is ≥ its smaller end value `lo_τ`. With
//! non-negative weights `g(t, ζ) ≥ (1 − t)·lo_0 + t·lo_1`, so a covered sample has
//! `(1 − t)·lo_0 + t·lo_1 ≤ 0`; symmetrically `(1 − t)·hi_0 + t·hi_1 ≥ 0` for the maximum
//! (convex, chords above, larger end value). Both are solved exactly with the ends rounded
//! outward ([`solve_le`]); the values are scaled by `D = ζb − ζa ≥ 0` instead of divided
//! (exact integers; D = 0 makes every value 0 and admits everything). The interval is then
//! intersected with the inner strategy's t, which is itself conservative. The direction n only
//! decides how tight the bound is, never whether it holds, so its choice (quantized, from the
//! mid-shutter edge) needs no exactness argument.
//!
//! **Conservative epsilon** (a [`crate::config::precision::Bounded`] precision, `bounded.rs`): that test
//! decides exactly on a perturbed triangle whose vertices lie within ε_x (x), ε_y (y) and ε_w
//! (w) of the exact ones at the sample's (t, u, v) ([`crate::setup::eps::Eps`]), and covers d only if
//! `d = Σ b_k·P'_k` with b_k ≥ 0, not all 0 (`hull.rs`), so coverage needs
//! `min_k φ(P'_k) ≤ 0 ≤ max_k φ(P'_k)`. A perturbation (δx, δy, δw) moves φ by
//! `n_x·W·δx − n_y·H·δy + δw·(n_x·(W − 2ξ) + n_y·(H − 2η))`, and with ξ ∈ [0, W], η ∈ [0, H]
//! (samples lie in the viewport) at most
//! `ρ = |n_x|·W·(ε_x + ε_w) + |n_y|·H·(ε_y + ε_w)` — Laine's `(ε_x + ε_w)·E` per axis, weighted
//! by |n|. Setup lowers every lower value and raises every upper value by this constant, which
//! keeps the concavity and chord arguments above. With the exact test ε = 0.
//!
//! **Cost.** Per triangle: one edge direction (moving triangles; static and defocus-only ones pass the
//! inner strategy through unchanged). Per tile 34 operations in `ops.bounds`: the tile's ζ range
//! relative to ζa from the two corners picked by n's signs (4 selects, 4 multiplies, 4 adds);
//! each of the four lines evaluated once, at the tile end its precomputed slope sign picks
//! (select, multiply, add); two differences, two solves and their meet as in `dual_t` (8); the
//! meet with the inner box (2).
#![warn(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_possible_wrap
)]

use crate::arith::div::floor_div;
use crate::arith::interval::{solve_le, Interval};
use crate::bounds::strategy::{BoundsStrategy, RowSpan, TileBounds, UvtBox};
use crate::config::unit::Unit;
use crate::input::{PixelRect, Triangle, Viewport, C, W, X, Y};
use crate::setup::Setup;
use crate::stats::Ops;

/// Largest |component| of the quantized direction n (its larger component is ±`N_MAX`).
pub const N_MAX: i64 = 256;

/// The inner strategy's bounds, with t narrowed by the dual-space bound along one edge normal
/// (moving triangles, with or without defocus).
#[derive(Clone, Copy, Debug, Default)]
pub struct EdgeTime<S> {
    inner: S,
    name: &'static str,
}

impl<S> EdgeTime<S> {
    /// Edge-direction time bounds on top of `inner`, reported as `name`.
    pub const fn new(inner: S, name: &'static str) -> Self {
        EdgeTime { inner, name }
    }
}

/// Per-triangle values of the edge direction: n, the footprint's ζ minimum, and the four
/// bounding lines `[lo t=0, lo t=1, hi t=0, hi t=1]` as `base + slope·(ζ − ζa)` (base = v0·D,
/// slope = v1 − v0 for end values v0 at ζa, v1 at ζb), each with the tile end that gives its
/// minimum (lower lines) or maximum (upper lines). Built only by [`EdgeTime`]'s prepare, so the
/// values stay in the ranges the per-tile arithmetic is proven for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EdgeAxis {
    pub(crate) n: [i64; 2],
    za: i64,
    pub(crate) base: [i128; 4],
    pub(crate) slope: [i64; 4],
    at_max: [bool; 4],
}

impl EdgeAxis {
    /// The pixel-space direction n = (n_x, n_y), |n_i| ≤ [`N_MAX`].
    pub fn n(&self) -> [i64; 2] {
        self.n
    }

    /// t interval of tile `tile` ⊆ footprint (module docs); `None`: no sample of the tile can be
    /// covered. 32 operations (the meet with the inner box is counted by the caller).
    // Ranges: |n_i| ≤ 2^8, pixel indices ≤ 2^11 (viewport ≤ 2048): |ζ| ≤ 2^20, so
    // 0 ≤ ζ − ζa ≤ 2^21; |slope| < 2^53 (values < 2^52, `edge_axis`): |slope·(ζ − ζa)| < 2^74;
    // |base| < 2^73: each line value < 2^75 in i128, differences < 2^76.
    #[allow(clippy::arithmetic_side_effects)]
    pub(crate) fn t(&self, tile: PixelRect, ops: &mut Ops) -> Option<Interval> {
        let [nx, ny] = self.n;
        let (x0, x1) = (i64::from(tile.x0), i64::from(tile.x1));
        let (y0, y1) = (i64::from(tile.y0), i64::from(tile.y1));
        let (xl, xh) = if nx >= 0 { (x0, x1) } else { (x1, x0) };
        let (yl, yh) = if ny >= 0 { (y0, y1) } else { (y1, y0) };
        let zl = i128::from(nx * xl + ny * yl - self.za);
        let zh = i128::from(nx * xh + ny * yh - self.za);
        let mut v = [0i128; 4];
        for (((out, &b), &s), &m) in v
            .iter_mut()
            .zip(self.base.iter())
            .zip(self.slope.iter())
            .zip(self.at_max.iter())
        {
            *out = b + i128::from(s) * if m { zh } else { zl };
        }
        ops.add_bounds(24);
        let [lo0, lo1, hi0, hi1] = v;
        // (1−t)·lo0 + t·lo1 ≤ 0  and  (1−t)·hi0 + t·hi1 ≥ 0.
        let a = solve_le(lo1 - lo0, -lo0)?;
        let b = solve_le(hi0 - hi1, hi0)?;
        ops.add_bounds(8);
        a.meet(b)
    }
}

/// [`EdgeTime`] coefficients: the edge direction's lines (moving triangles with a usable
/// oblique edge) and the inner strategy's coefficients.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EdgeCoeffs<C> {
    edge: Option<EdgeAxis>,
    inner: C,
}

impl<C> EdgeCoeffs<C> {
    /// The edge direction's values (`None`: no edge bound for this triangle).
    pub fn edge(&self) -> Option<&EdgeAxis> {
        self.edge.as_ref()
    }
    /// The inner strategy's coefficients.
    pub fn inner(&self) -> &C {
        &self.inner
    }
}

/// One tile: the inner strategy's box with t narrowed, and the inner tile (its predicate).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EdgeTile<T> {
    b: UvtBox,
    inner: T,
}

impl<T: TileBounds> TileBounds for EdgeTile<T> {
    #[inline]
    fn uvt_box(&self) -> &UvtBox {
        &self.b
    }
    /// The inner predicate (the box is a subset of the inner box, where that predicate holds
    /// for every covered sample).
    #[inline]
    fn predicate(&self, u: i32, v: i32, t: i32, ops: &mut Ops) -> bool {
        self.inner.predicate(u, v, t, ops)
    }
}

/// Twice the mid-shutter vertex, `q + r` per field x, y, w: |.| ≤ 2^30 (both ends ≤ 2^29).
#[allow(clippy::arithmetic_side_effects, clippy::indexing_slicing)]
fn mid2(tri: &Triangle) -> [[i64; 3]; 3] {
    let [q, r] = &tri.v;
    let mut m = [[0i64; 3]; 3];
    for ((out, a), b) in m.iter_mut().zip(q.iter()).zip(r.iter()) {
        // Constant indices X, Y, W < 5.
        *out = [X, Y, W].map(|f| i64::from(a[f]) + i64::from(b[f]));
    }
    m
}

/// The pixel-space direction of the edge (i, j) of the mid-shutter triangle and its score
/// (2^18·|Δξ·Δη| rounded down, saturated: the area the edge cuts from the triangle's box, up to
/// a constant; 0 unless both ends have w > 0). The screen line through the two
/// homogeneous points is `l = P_i × P_j`; its gradient in (ξ, η) is ∝ `(l0·H, −l1·W)`
/// (ξ = (X + 1)·W/2, η = (1 − Y)·H/2), quantized to |n| ≤ [`N_MAX`] by rounding
/// `g·N_MAX/max|g|`. On screen Δξ = W·l1/(2·w_i·w_j), |Δη| = H·|l0|/(2·w_i·w_j) (w_i, w_j > 0;
/// the same for the doubled points `q + r`, whose cross product and w product are both 4×).
// Ranges: |P| ≤ 2^30: |l0|, |l1| < 2^61 (i64); |g| < 2^72, |g·2·N_MAX| < 2^81 (i128); the score
// numerators |l|·E·2^8 < 2^80 over w_i·w_j ∈ [1, 2^60], quotients < 2^80, product saturated.
#[allow(clippy::arithmetic_side_effects, clippy::indexing_slicing)]
fn edge_dir(p: &[i64; 3], q: &[i64; 3], vp: Viewport, ops: &mut Ops) -> Option<([i64; 2], u128)> {
    // Constant indices 0..3 of [x, y, w].
    let l0 = p[1] * q[2] - p[2] * q[1];
    let l1 = p[2] * q[0] - p[0] * q[2];
    let (ew, eh) = (i128::from(vp.width()), i128::from(vp.height()));
    let g = [i128::from(l0) * eh, -i128::from(l1) * ew];
    let m = g[0].abs().max(g[1].abs());
    ops.add_setup(12);
    if m == 0 {
        return None;
    }
    let mut n = [0i64; 2];
    for (o, gi) in n.iter_mut().zip(g) {
        // round(gi·N/m) = floor((2·gi·N + m)/(2m)) ∈ [−N, N].
        let q = floor_div(gi * 2 * i128::from(N_MAX) + m, 2 * m)?;
        *o = i64::try_from(q).ok()?;
    }
    ops.add_setup(8);
    let score = if p[2] > 0 && q[2] > 0 {
        let den = i128::from(p[2]) * i128::from(q[2]);
        let dx = floor_div(i128::from(l1).abs() * ew * 256, den)?.unsigned_abs();
        let dy = floor_div(i128::from(l0).abs() * eh * 256, den)?.unsigned_abs();
        ops.add_setup(10);
        dx.saturating_mul(dy)
    } else {
        0
    };
    Some((n, score))
}

/// The edge direction and its four bounding lines for a moving triangle (module docs);
/// `None` when no edge of the mid-shutter triangle is oblique on screen (every score 0, or an
/// axis-aligned direction: then the bound is Laine's own x or y one).
// Ranges: |n_i| ≤ 2^8, W, H ≤ 2^11, |x + w|, |w − y| ≤ 2^30: |A| ≤ 2^50; |ζ| ≤ 2^20 (footprint
// corners ≤ 2^11), |2w·ζ| ≤ 2^50: |φ| ≤ 2^51; ε_x, ε_w < 2^25: ρ < 2^45; the lens weight
// |n_x|·W + |n_y|·H ≤ 2^20 and |c| ≤ 2^29: lens term ≤ 2^49; so every widened value is < 2^52
// in i64. D = ζb − ζa ≤ 2^21: |base| = |v0·D| < 2^73 (i128); |slope| < 2^53.
#[allow(clippy::arithmetic_side_effects, clippy::indexing_slicing)]
pub(crate) fn edge_axis(setup: &Setup, ops: &mut Ops) -> Option<EdgeAxis> {
    let tri = &setup.tri;
    let m = mid2(tri);
    ops.add_setup(9);
    let mut best: Option<([i64; 2], u128)> = None;
    for (i, j) in [(0usize, 1usize), (1, 2), (2, 0)] {
        // Constant indices < 3.
        let Some((n, s)) = edge_dir(&m[i], &m[j], setup.viewport, ops) else {
            continue;
        };
        ops.add_setup(1);
        if s > 0 && n[0] != 0 && n[1] != 0 && best.map_or(true, |(_, b)| s > b) {
            best = Some((n, s));
        }
    }
    let [nx, ny] = best?.0;
    let (ew, eh) = (i64::from(setup.viewport.w), i64::from(setup.viewport.h));
    let fp = setup.footprint;
    let corners = [
        (fp.x0, fp.y0),
        (fp.x1, fp.y0),
        (fp.x0, fp.y1),
        (fp.x1, fp.y1),
    ]
    .map(|(x, y)| nx * i64::from(x) + ny * i64::from(y));
    let za = corners.iter().copied().min().unwrap_or(0);
    let zb = corners.iter().copied().max().unwrap_or(0);
    ops.add_setup(18);
    let ex = i64::from(setup.eps.x[0]);
    let ey = i64::from(setup.eps.x[1]);
    let e_w = i64::from(setup.eps.w);
    let rho = nx.abs() * ew * (ex + e_w) + ny.abs() * eh * (ey + e_w);
    let lens = nx.abs() * ew + ny.abs() * eh;
    ops.add_setup(12);
    // [t][end ζa, ζb]
    let mut lo = [[i64::MAX; 2]; 2];
    let mut hi = [[i64::MIN; 2]; 2];
    for ((ends, lo_t), hi_t) in tri.v.iter().zip(lo.iter_mut()).zip(hi.iter_mut()) {
        for p in ends.iter() {
            // Constant indices X, Y, W < 5.
            let (x, y, w) = (i64::from(p[X]), i64::from(p[Y]), i64::from(p[W]));
            let a = nx * ew * (x + w) + ny * eh * (w - y);
            // The lens term (0 without defocus) plus the epsilon.
            let bias = lens * i64::from(p[C]).abs() + rho;
            ops.add_setup(10);
            for ((l, h), z) in lo_t.iter_mut().zip(hi_t.iter_mut()).zip([za, zb]) {
                let phi = a - 2 * w * z;
                *l = (*l).min(phi - bias);
                *h = (*h).max(phi + bias);
                ops.add_setup(7);
            }
        }
    }
    let d = i128::from(zb - za);
    let lines = [lo[0], lo[1], hi[0], hi[1]];
    let mut base = [0i128; 4];
    let mut slope = [0i64; 4];
    let mut at_max = [false; 4];
    for (k, v) in lines.iter().enumerate() {
        let s = v[1] - v[0];
        base[k] = i128::from(v[0]) * d;
        slope[k] = s;
        // Lower lines (k < 2): the minimum over [ζ0, ζ1] is at ζ1 when the slope is negative;
        // upper lines: the maximum is at ζ1 when the slope is non-negative.
        at_max[k] = if k < 2 { s < 0 } else { s >= 0 };
        ops.add_setup(4);
    }
    Some(EdgeAxis {
        n: [nx, ny],
        za,
        base,
        slope,
        at_max,
    })
}

impl<S: BoundsStrategy> BoundsStrategy for EdgeTime<S> {
    type Coeffs = EdgeCoeffs<S::Coeffs>;
    type Tile = EdgeTile<S::Tile>;
    fn name(&self) -> &'static str {
        self.name
    }
    // Gated on the unit: the edge bound only with `U::MOTION` (a class without motion gets none
    // on every unit).
    #[inline(always)]
    fn prepare<U: Unit>(&self, setup: &Setup, ops: &mut Ops) -> Self::Coeffs {
        let edge = if U::MOTION && setup.class.motion() {
            edge_axis(setup, ops)
        } else {
            None
        };
        EdgeCoeffs {
            edge,
            inner: self.inner.prepare::<U>(setup, ops),
        }
    }
    fn tile<U: Unit>(
        &self,
        setup: &Setup,
        c: &Self::Coeffs,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<Self::Tile> {
        self.edge_tile::<U>(setup, c, tile, ops, |ops| {
            self.inner.tile::<U>(setup, &c.inner, tile, ops)
        })
    }
    /// The inner strategy's span (the edge bound has no row step).
    fn row_span(
        &self,
        setup: &Setup,
        c: &Self::Coeffs,
        row: PixelRect,
        bt: u16,
        ops: &mut Ops,
    ) -> RowSpan {
        self.inner.row_span(setup, &c.inner, row, bt, ops)
    }
    /// As [`Self::tile`], with the inner strategy's span tile.
    fn span_tile<U: Unit>(
        &self,
        setup: &Setup,
        c: &Self::Coeffs,
        span: &RowSpan,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<Self::Tile> {
        self.edge_tile::<U>(setup, c, tile, ops, |ops| {
            self.inner.span_tile::<U>(setup, &c.inner, span, tile, ops)
        })
    }
}

impl<S: BoundsStrategy> EdgeTime<S> {
    /// The edge interval, then the inner bounds from `inner`, met.
    fn edge_tile<U: Unit>(
        &self,
        setup: &Setup,
        c: &EdgeCoeffs<S::Coeffs>,
        tile: PixelRect,
        ops: &mut Ops,
        inner: impl FnOnce(&mut Ops) -> Option<S::Tile>,
    ) -> Option<EdgeTile<S::Tile>> {
        // The edge interval first: a tile it culls costs no inner bounds.
        let t = match (U::MOTION, c.edge.as_ref()) {
            (true, Some(e)) => Some(e.t(tile, ops)?.round_out(setup.prec.tuv())),
            _ => None,
        };
        let inner = inner(ops)?;
        let mut b = *inner.uvt_box();
        if let Some(t) = t {
            ops.add_bounds(2);
            b.t = b.t.meet(t)?;
        }
        Some(EdgeTile { b, inner })
    }
}
