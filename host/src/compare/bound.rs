//! The quantization bound that says where the core's decisions may disagree with the f64
//! reference's — checked per differing sample in edge-function space ([`check_sample_eps`]), so
//! it holds for every geometry, camera-plane crossings and w ≤ 0 vertices included. The
//! comparison that applies it to every sample is [`super::pass`].
//!
//! **Setting.** The core's decision is the exact decision for its *quantized* inputs
//! (`uvt_core::sample`): with `d = (2x/W − 1, 1 − 2y/H, 1)` the sample's direction and `p_k` the
//! vertices' clip `(x + u·c, y + v·c, w)` at (t, u, v), it covers iff `det = [p0 p1 p2] ≠ 0` and
//! every edge value `E_k = [d p_{k+1} p_{k+2}]` (3×3 determinants; the core's integers are these
//! times positive constants) has the sign of `det` (zeros: fill rule). The reference decides on
//! the *exact* inputs by a ray test, which in exact arithmetic is the same sign condition (its
//! barycentrics are `E_k/ΣE`, its distance `det/ΣE`). Hence if none of the four values
//! `E_0, E_1, E_2, det` changes sign between exact and quantized inputs, and f64 round-off flips
//! none of them, both decide the same. A differing sample is **explained** iff some value `v` has
//! `|v| ≤ B_v + F_v` at the exact inputs; otherwise it is counted **beyond bound** (must be 0).
//! No geometry is exempt: every term below is finite for any finite input.
//!
//! **Rounding of the inputs** ([`Rounding`], `crate::config::rounding`): clip x, y, w and CoC c
//! of each vertex end by at most `δp = 2^-(POS+1)` (round to nearest); t, u, v by at most
//! `δt = 2^-17` (round to 16 bits), plus `2^-(TUV+1)` when TUV < 16 (the second rounding to the
//! coarser grid); the sub-pixel position is floored, `0 ≤ x − x' < 1/256` px (same for y).
//!
//! **Vertex perturbation** (exact, not first order). The core's vertex at (t', u', v') is the lerp
//! of its rounded ends, `X'(t') = (1−t')x0' + t'x1'`, so
//! `X'(t') − X(t) = (1−t')ε0 + t'ε1 + (t'−t)(x1 − x0)`, `|·| ≤ δp + δt·|x1 − x0|`; likewise for
//! c, y, w. With `|u'| ≤ 1`, `u'C'(t') − uC(t) = u'(C' − C) + (u' − u)C(t)`. So vertex k moves by
//! at most `Δx_k = δp + δt|Δx| + δp + δt|Δc| + δt|C_k(t)|` (Δ = t1 − t0 change of that vertex),
//! `Δy_k` the same with y, `Δw_k = δp + δt|Δw|`, and `δ_k = ‖(Δx_k, Δy_k, Δw_k)‖₂`. The direction
//! moves by `‖Δd‖ ≤ (2/256)·√(1/W² + 1/H²)`.
//!
//! **Edge-value bound.** Determinants are trilinear, so exactly
//! `[d' a' b'] − [d a b] = [Δd a' b'] + [d Δa b'] + [d a Δb]`, and Hadamard's inequality
//! `|[x y z]| ≤ ‖x‖‖y‖‖z‖` gives, with `‖a'‖ ≤ ‖a‖ + δ_a`,
//!   `B_k = ‖Δd‖(‖a‖+δ_a)(‖b‖+δ_b) + ‖d‖δ_a(‖b‖+δ_b) + ‖d‖‖a‖δ_b`  (a, b = p_{k+1}, p_{k+2}),
//!   `B_det = δ_0(‖p1‖+δ_1)(‖p2‖+δ_2) + ‖p0‖δ_1(‖p2‖+δ_2) + ‖p0‖‖p1‖δ_2`.
//! No factor is asserted: this is a rigorous bound on the change, for any sign of w.
//!
//! **f64 round-off.** The reference (and this check) evaluate positions and 3×3 determinants in
//! f64: each computed value is a sum of six triple products after at most 16 roundings (positions
//! included), so its error is at most `γ_16 ≤ 2^-48` times the sum of the absolute values of the
//! terms. With `m_k` the sum of |x|, |y|, |w|, |c| of vertex k over both ends (it bounds every
//! coordinate of p_k at any t, u, v) and `Σ|d_i| ≤ 3` inside the viewport, that sum is at most
//! `3·m_a·m_b` for `E_k` and `m_0·m_1·m_2` for det, so `F_E = 2^-40·3(Σm_k)²` and
//! `F_det = 2^-40·(Σm_k)³` bound the round-off with a 256× margin (still 2^-23 below the 2^-17
//! quantization scale, so the margin does not blunt the check). The reference's ray test divides
//! by `ΣE` and compares barycentrics with 0 and 1; when all `|E_k| > F_E` with equal signs,
//! `|ΣE| > F_E` and those comparisons have the signs of `E_k`, so round-off cannot flip its
//! decision outside the same margins.
//!
//! **Tightness (measured).** Rounding every input to a corner of its box moves a value by up to
//! 0.88 of its bound (`tests/tests/model/quant_check.rs`, 4000 random triangles of every kind); the
//! differing samples of the test scenes use at most 0.31 of it (default precision), 0.21 (8/8
//! bits, camera-plane crossing), so a bound 16× smaller would already be violated there.
//!
//! **In pixels.** `E_k` is affine in the screen position with gradient `(2n_x/W, −2n_y/H)`
//! (`n = a × b`), so `|E_k| ≤ B_k` says the sample lies within `B_k/|∇E_k|` px of edge line k at
//! its (t, u, v) — reported as the per-sample quantization distance where defined. The distance
//! of a differing sample from the nearest edge (`reference::sample::edge_distance_px`, segment
//! distance when the hit is in front of the camera) is reported beside it. Samples explained only
//! by `det` (the triangle is near edge-on at that t, u, v) and differing samples of triangles with
//! a vertex at w ≤ 0 at either end of the shutter (where a screen-space bound has no meaning) are
//! counted separately; both are checked like every other.

use glam::DVec3;
use uvt_core::PixelRect;

use crate::config::rounding::Rounding;
use crate::reference;
use crate::scene::tri::SceneTri;

/// The quantization check of one sample (module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampleCheck {
    /// `E_0, E_1, E_2, det` at the exact inputs (f64)
    pub values: [f64; 4],
    /// their bounds `B_v + F_v`: the quantized inputs' values lie within these of `values`
    pub bounds: [f64; 4],
    /// `min_v |v| / (B_v + F_v)`: ≤ 1 iff a decision difference at this sample is explained by
    /// the input rounding
    pub ratio: f64,
    /// the value attaining the minimum: edge 0, 1, 2, or 3 for det
    pub which: usize,
    /// `(B_k + F_k)/|∇E_k|`: the quantization distance (px) of edge `which` at this sample; `None`
    /// for det or a zero gradient
    pub bound_px: Option<f64>,
    /// some vertex has w ≤ 0 at either end of the shutter (where the old pixel bound was
    /// infinite)
    pub behind: bool,
}

/// Hadamard bound of `[x' y' z'] − [x y z]` given the norms and perturbation norms.
fn det_change(n: [f64; 3], dn: [f64; 3]) -> f64 {
    dn[0] * (n[1] + dn[1]) * (n[2] + dn[2]) + n[0] * dn[1] * (n[2] + dn[2]) + n[0] * n[1] * dn[2]
}

/// Check one sample at exact screen position (x, y) px and exact (u, v, t) (module docs).
#[allow(clippy::too_many_arguments)]
pub fn check_sample(
    tri: &SceneTri,
    vp: (u16, u16),
    x: f64,
    y: f64,
    u: f64,
    v: f64,
    t: f64,
    r: &Rounding,
) -> SampleCheck {
    check_sample_eps(tri, vp, x, y, u, v, t, r, [0.0; 3])
}

/// [`check_sample`] for a core sample test that adds a vertex perturbation of at most `eps`
/// (clip units, x, y, w; [`eps_of`]) after the input rounding: the two perturbations add, so
/// `Δx_k`, `Δy_k`, `Δw_k` of the module docs grow by `eps` and the bound stays rigorous.
#[allow(clippy::too_many_arguments)]
pub fn check_sample_eps(
    tri: &SceneTri,
    vp: (u16, u16),
    x: f64,
    y: f64,
    u: f64,
    v: f64,
    t: f64,
    r: &Rounding,
    eps: [f64; 3],
) -> SampleCheck {
    let mut delta = [0.0; 3];
    for (k, dk) in delta.iter_mut().enumerate() {
        let (a, b) = (tri.t0[k], tri.t1[k]);
        let mv = |f: usize| r.pos + r.tuv * (b[f] - a[f]).abs();
        let lens = mv(4) + r.tuv * (a[4] + t * (b[4] - a[4])).abs();
        *dk = DVec3::new(mv(0) + lens + eps[0], mv(1) + lens + eps[1], mv(3) + eps[2]).length();
    }
    check_sample_within(tri, vp, x, y, u, v, t, r.sub, delta)
}

/// [`check_sample`] for vertex perturbations of at most `delta[k]` (clip units, Euclidean, vertex
/// k at the sample's t, u, v) and a sub-pixel position moved by less than `sub` px: whether a
/// differing decision is consistent with a triangle whose vertices lie within `delta` of the
/// input (`ratio` ≤ 1), the test of the clip-space statement (`crate::config::dq`).
#[allow(clippy::too_many_arguments)]
pub fn check_sample_within(
    tri: &SceneTri,
    vp: (u16, u16),
    x: f64,
    y: f64,
    u: f64,
    v: f64,
    t: f64,
    sub: f64,
    delta: [f64; 3],
) -> SampleCheck {
    let (p, _) = reference::sample::positions(tri, t, u, v);
    let d = reference::sample::direction(vp, x, y);
    let (w, h) = (vp.0 as f64, vp.1 as f64);
    let dd = 2.0 * sub * (1.0 / (w * w) + 1.0 / (h * h)).sqrt();
    let mut m = 0.0;
    for k in 0..3 {
        let (a, b) = (tri.t0[k], tri.t1[k]);
        m += [0, 1, 3, 4]
            .iter()
            .map(|&f| a[f].abs() + b[f].abs())
            .sum::<f64>();
    }
    let f_e = 2f64.powi(-40) * 3.0 * m * m;
    let f_det = 2f64.powi(-40) * m * m * m;
    let norm = p.map(|q| q.length());
    let n = [0, 1, 2].map(|k| p[(k + 1) % 3].cross(p[(k + 2) % 3]));
    let mut values = [0.0; 4];
    let mut bounds = [0.0; 4];
    for k in 0..3 {
        let (a, b) = ((k + 1) % 3, (k + 2) % 3);
        values[k] = n[k].dot(d);
        bounds[k] = det_change([d.length(), norm[a], norm[b]], [dd, delta[a], delta[b]]) + f_e;
    }
    values[3] = p[0].dot(n[0]);
    bounds[3] = det_change(norm, delta) + f_det;
    let mut which = 0;
    for k in 1..4 {
        if values[k].abs() / bounds[k] < values[which].abs() / bounds[which] {
            which = k;
        }
    }
    let bound_px = n.get(which).and_then(|nk| {
        let g = ((2.0 * nk.x / w).powi(2) + (2.0 * nk.y / h).powi(2)).sqrt();
        (g > 0.0).then(|| bounds[which] / g)
    });
    SampleCheck {
        values,
        bounds,
        ratio: values[which].abs() / bounds[which],
        which,
        bound_px,
        behind: tri.t0.iter().chain(tri.t1.iter()).any(|q| q[3] <= 0.0),
    }
}

/// The bounding rectangle of two optional footprints (`None` if both are absent).
pub fn footprint_union(a: Option<PixelRect>, b: Option<PixelRect>) -> Option<PixelRect> {
    match (a, b) {
        (Some(a), Some(b)) => Some(PixelRect {
            x0: a.x0.min(b.x0),
            y0: a.y0.min(b.y0),
            x1: a.x1.max(b.x1),
            y1: a.y1.max(b.y1),
        }),
        (Some(a), None) | (None, Some(a)) => Some(a),
        (None, None) => None,
    }
}
