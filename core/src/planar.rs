//! Stage 3, planar — the static sample test of a [`crate::formats::Planar`] precision: a static
//! triangle's three edges are fixed planes through the eye, `E_k(d) = n_k·d` with
//! `n_k = P_{k+1} × P_{k+2}` (`StaticEdges`, exact i128), and the sample direction `d` is affine
//! in the sample position; so setup rounds each normal once to i32 and the test per sample is
//! three 32 × 32 → 64 dot products.
//!
//! **Setup, per triangle** (raw clip units, `P_k = (x_k, y_k, w_k)` at t0; no projection, so
//! camera-plane crossers need no special case):
//!
//! | signal | value | rounding | format |
//! |---|---|---|---|
//! | `n_k` | `P_{k+1} × P_{k+2}` | exact | i64, \|.\| ≤ 2^59 (2·16 fraction bits) |
//! | `sh_k` | `max(0, bitlen(max_i \|n_k,i\|) − 30)` | — | 0..=30 |
//! | `n'_k` | `rnd(n_k / 2^sh_k)` per component, `rnd(x) = sign(x)·⌊(\|x\| + 2^(sh−1))/2^sh⌋` | nearest, ties away from 0, symmetric | i32, \|.\| ≤ 2^30 |
//! | `σ` | `sign(det P)`, `det P = P_0 · n_0` | exact (i128, \|.\| < 2^90) | ±1 (0 culled) |
//! | `P''_k` | `n'_{k+1} × n'_{k+2}` | exact | i64, \|.\| ≤ 2^61 |
//! | `det(n')` | `n'_0 · P''_0` | exact | i128, \|.\| < 2^93 (0 culled) |
//! | `G`, `f` | depth plane, below | floor | i32 ×3, exponent i32 |
//!
//! **Per sample** (`d` = [`crate::sample::direction`], each \|d_i\| ≤ 2^30 inside a viewport
//! ≤ 2048, i32): `E'_k = n'_k · d` (three SMULL/SMLAL, \|E'\| ≤ 3·2^60 < 2^62, i64, exact).
//! Covered iff for every k: `σ·E'_k > 0`, or `E'_k = 0` and the fill rule accepts:
//! `σ·a'_k > 0`, or `a'_k = 0` and `σ·b'_k > 0` (`(a', b', c') = n'_k`; comparators only).
//!
//! **What it decides: exactly the exact test on a triangle `Q`.** With `Q_k = τ·P''_k`,
//! `τ = σ·sign(det n')`: the identity `(a×b)×(a×c) = (a·(b×c))·a` gives
//! `Q_{k+1} × Q_{k+2} = det(n')·n'_k` and `det(Q) = τ·det(n')²`, so the exact test of
//! `sample.rs` on `Q` (edge values `det(n')·E'_k`, orientation `sign(det Q) = τ`, fill rule on
//! `det(n')·(a'_k, b'_k)`) is covered iff `σ·E'_k > 0` for all k or on ties `σ·a'_k > 0`, … —
//! the test above, bit for bit (`tests/tests/planar.rs` compares with a 192-bit exact test on
//! `Q`). A triangle with `det(P) = 0` or `det(n') = 0` is culled (`Cull::Degenerate`).
//!
//! **Watertight.** `n'_k` is a function of `n_k` alone (its own shift, a rounding symmetric
//! under negation), and an edge seen as `(i, j)` by one triangle and `(j, i)` by its neighbour
//! has exactly negated `n`, hence exactly negated `n'`: the two rounded planes are one plane.
//! With the same orientation σ (a consistently wound mesh), off the plane exactly one of the
//! two has `σ·E' > 0`; on it (`E' = 0`) the fill rule's key `(a', b')` is negated too, so
//! exactly one accepts (`(a', b') = (0, 0)` means the plane is `d_w = 0`, which no sample is
//! on). **At a shared vertex** the rounded planes of the triangles around it need not meet in
//! one point (each triangle's corner is `P''`, the meet of its own two rounded planes): a sample
//! within the edge distance below of two of those planes can be covered twice or not at all.
//! This is the one place the planar test is not watertight; `tests/tests/planar.rs` measures it.
//!
//! **Agreement with the exact test.** Per component `|n'_k − n_k/2^sh_k| ≤ 1/2`, so
//! `|E'_k − E_k/2^sh_k| ≤ (|d_x| + |d_y| + |d_w|)/2`: a sample decided differently from the
//! exact test has `|E_k| ≤ 2^(sh_k − 1)·‖d‖₁` for some k — within
//! `2^(sh_k−1)·‖d‖₁ / (512·‖(a_k·H, b_k·W)‖)` px of edge k (the gradient of `E_k` is
//! `(2a_k·H, −2b_k·W)` per 1/256 px). Checked exactly (integers) by the agreement test.
//!
//! **Conservative epsilon.** The bounds (`setup.rs` boxes and time span, `HullCull` faces, …)
//! are conservative for every triangle whose vertices lie, up to a positive factor each, within
//! `ε_x` (x), `ε_y` (y), `ε_w` (w) of `P_k` (their proofs only use that vertex box; the exact
//! test's coverage is the open cone of the vertices, invariant under positive per-vertex
//! factors). Coverage here is the exact test on `Q`, so setup stores, rounded up, a bound on
//! `|μ·Q_k − P_k|` for a chosen `μ > 0` per vertex:
//! `μ = w_k/Q_w` when both are non-zero of one sign (then `ε_w` = 0 and
//! `ε_x ≥ ⌈|Q_x·w_k − x_k·Q_w| / |Q_w|⌉`, likewise y); else
//! `μ = 2^(sh_{k+1}+sh_{k+2})/|det P|` (`n_{k+1} × n_{k+2} = det(P)·P_k`, so this is `P_k` up to
//! the roundings), every component `⌈|Q_c·2^s − |det P|·P_c| / |det P|⌉` (`s = sh_{k+1} +
//! sh_{k+2}`). Each ceiling is taken from above (`ceil_div_up`: numerator rounded up, divisor
//! down to 32 bits, one 64-bit division). The maximum over the vertices is the setup's [`Eps`]. Any `μ > 0` gives a valid bound, so each vertex's `μ_k·Q_k`
//! lies in the box and every covered sample (a ray in the open cone of `Q`) is inside every
//! bound. A bound above [`PLANAR_EPS_LIMIT`] (the bounds' range proofs take ε < 2^24), or an
//! overflow of the checked i128 arithmetic, culls the triangle (`Cull::Degenerate`): only a
//! sliver whose rounded planes meet more than 256 clip units from its vertices, counted
//! separately by the tests.
//!
//! **Depth** (hits only), same format, saturation and direction as the bounded test (I8F24,
//! floor, saturated to [`DEPTH_NEAR`, `DEPTH_FAR`]): the hit of ray `d` on the triangle has
//! `w = d_w` and `z = Σ_k z_k·E_k/det(P)`, so `z/w = Zv·d / (det(P)·d_w)` with the exact plane
//! `Zv = Σ_k z_k·n_k` (i128, < 2^90) and `D = det(P)·d_w` (< 2^120): affine in the sample, no
//! division per sample. Setup (D oriented > 0 with Zv): `D32 = ⌊D / 2^rd⌋` with
//! `rd = bitlen(D) − 32` (a left shift, exact, when negative: D ≥ 256), so D32 ∈ [2^31, 2^32);
//! `Z62_i = ⌊Zv_i / 2^rz⌋` with `rz = bitlen(max|Zv_i|) − 62` (exact left shift when
//! negative), |Z62| < 2^62; `G_i = ⌊Z62_i / D32⌋` ∈ [−2^31, 2^31) (i32; three 64-bit
//! divisions per triangle), `f = rd − rz − 24`. Per hit: `acc = Σ G_i·d_i` (\|.\| < 3·2^61,
//! i64 exact), depth = `⌊acc / 2^f⌋` (arithmetic shift; `f ≥ 63` gives 0 or −1) or
//! `acc·2^(−f)` saturated for `f < 0`, then saturated to the depth range (`Zv = 0`: depth 0).
//! Error: G_i is within 1 + 2^-30·|G_i| of `Zv_i·2^(−f−24)/D·2^24`, so the depth is within
//! `(3·2^30 + Σ|G_i·d_i|·2^-30)/2^f + 1` raw of the exact z/w (floor of the exact value
//! included). Depth never influences coverage.

use crate::bounded::Eps;
use crate::formats::{DEPTH_FAR, DEPTH_FRAC, DEPTH_NEAR, SUBPIXEL_BITS};
use crate::input::{Triangle, Viewport, W, X, Y, Z};
use crate::sample::{Hit, ScreenPos};
use crate::setup::Setup;
use crate::stats::Ops;

/// Largest conservative epsilon component the planar setup stores (raw clip units): the
/// bounds' range proofs take ε_x + ε_w < 2^25. A triangle needing more is culled (module docs).
pub const PLANAR_EPS_LIMIT: i32 = (1 << 24) - 1;

/// Magnitude limit of the rounded normals: |n'| ≤ 2^30 (bit length of |n| above 30 is shifted).
const NORMAL_BITS: u32 = 30;

/// The planar test's per-triangle data. Built only by the planar setup from a checked
/// [`Triangle`], so every field is in the range the module table states.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlanarEdges {
    pub(crate) n: [[i32; 3]; 3],
    pub(crate) sh: [u32; 3],
    pub(crate) sigma: i32,
    pub(crate) g: [i32; 3],
    pub(crate) f: i32,
}

impl PlanarEdges {
    /// The rounded edge normals `n'_k = (a', b', c')`, |.| ≤ 2^30.
    pub fn n(&self) -> [[i32; 3]; 3] {
        self.n
    }
    /// The per-edge shifts `sh_k` (0..=29): `n'_k ≈ n_k / 2^sh_k`.
    pub fn shifts(&self) -> [u32; 3] {
        self.sh
    }
    /// The orientation σ = sign(det P): −1 or 1.
    pub fn sigma(&self) -> i32 {
        self.sigma
    }
    /// The depth plane `G` and its exponent `f` (module docs).
    pub fn depth_plane(&self) -> ([i32; 3], i32) {
        (self.g, self.f)
    }
}

/// Bit length of a `u128` (0 for 0).
fn bitlen(x: u128) -> u32 {
    u128::BITS.saturating_sub(x.leading_zeros())
}

/// `rnd(x / 2^sh)`: nearest, ties away from zero, `rnd(−x) = −rnd(x)` (module table). For
/// |x| ≤ 2^59 and `sh` ≤ 30 with |x| < 2^(30 + sh) + 2^sh the result is ≤ 2^30 (i32).
// |x| ≤ 2^59 and half ≤ 2^29: the sum < 2^60 (u64); sh ≤ 30 < 64.
#[allow(clippy::arithmetic_side_effects)]
fn rnd_sym(x: i64, sh: u32) -> i32 {
    let m = x.unsigned_abs();
    let half = if sh == 0 { 0 } else { 1u64 << (sh - 1) };
    let q = i32::try_from((m + half) >> sh).unwrap_or(i32::MAX);
    if x < 0 {
        q.saturating_neg()
    } else {
        q
    }
}

/// Round one exact normal (|n| ≤ 2^59): `(n', sh)`, `sh = max(0, bitlen(max|n_i|) − 30)` ≤ 30.
#[inline(never)]
fn round_normal(n: &[i64; 3]) -> ([i32; 3], u32) {
    let m = n.iter().map(|c| c.unsigned_abs()).max().unwrap_or(0);
    let sh = u64::BITS
        .saturating_sub(m.leading_zeros())
        .saturating_sub(NORMAL_BITS);
    (n.map(|c| rnd_sym(c, sh)), sh)
}

/// Cross product, exact in i64: `a` = rounded normals (|.| ≤ 2^30, products ≤ 2^60, |.| ≤
/// 2^61), or vertices (|.| ≤ 2^29, products ≤ 2^58, |.| ≤ 2^59).
#[inline(never)]
#[allow(clippy::arithmetic_side_effects)] // ranges in the doc comment
fn cross(a: [i64; 3], b: [i64; 3]) -> [i64; 3] {
    let [a0, a1, a2] = a;
    let [b0, b1, b2] = b;
    [a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0]
}

/// `a · b` exact in i128 for |a_i·b_i| < 2^125 (callers: ≤ 2^91, the depth plane's
/// `n·z` ≤ 2^88).
#[inline(never)]
#[allow(clippy::arithmetic_side_effects)]
fn dot128(a: &[i64; 3], b: &[i64; 3]) -> i128 {
    a.iter()
        .zip(b.iter())
        .map(|(&x, &y)| i128::from(x) * i128::from(y))
        .sum()
}

/// An upper bound on `⌈num / den⌉` (`den > 0`) as an epsilon component: with `r =
/// max(0, bitlen(den) − 32)`, `⌈⌈num/2^r⌉ / ⌊den/2^r⌋⌉` (≥ the exact ceiling: the numerator
/// rounds up, the divisor down; one 64-bit division). `None` when `den = 0` or the bound is
/// above [`PLANAR_EPS_LIMIT`].
// r ≤ 96 < 128; ⌊den/2^r⌋ ∈ [1, 2^32); the rounded-up numerator + 1 cannot overflow u128
// (num < 2^122 at every caller).
#[inline(never)]
#[allow(clippy::arithmetic_side_effects)]
fn ceil_div_up(num: u128, den: u128) -> Option<i32> {
    if den == 0 {
        return None;
    }
    let r = bitlen(den).saturating_sub(32);
    let d = u64::try_from(den >> r).ok()?;
    let n = (num >> r) + u128::from(num & ((1u128 << r) - 1) != 0);
    let n = u64::try_from(n).ok()?;
    let q = n / d + u64::from(n % d != 0);
    i32::try_from(q).ok().filter(|&e| e <= PLANAR_EPS_LIMIT)
}

/// The epsilon of one vertex `p` = (x, y, w) for the corner `q` of `Q` (module docs), or
/// `None` above the limit. `s` = sh_{k+1} + sh_{k+2} ≤ 60, `adet` = |det P| ∈ [1, 2^90).
// |Q| ≤ 2^61, |p| ≤ 2^29: Q_c·w and x·Q_w ≤ 2^90, difference < 2^91; Q_c·2^s ≤ 2^121 (a shift
// by s ≤ 60 of |Q| ≤ 2^61), |det|·|p_c| < 2^119, difference < 2^122: all in i128.
#[inline(never)]
#[allow(clippy::arithmetic_side_effects)]
fn vertex_eps(p: [i64; 3], q: [i64; 3], s: u32, adet: u128) -> Option<[i32; 3]> {
    let [x, y, w] = p.map(i128::from);
    let [qx, qy, qw] = q.map(i128::from);
    if w != 0 && qw != 0 && (w > 0) == (qw > 0) {
        // μ = w/Q_w > 0: μ·Q_w = w exactly; |μ·Q_c − p_c| = |Q_c·w − p_c·Q_w| / |Q_w|.
        let e =
            |qc: i128, pc: i128| ceil_div_up((qc * w - pc * qw).unsigned_abs(), qw.unsigned_abs());
        return Some([e(qx, x)?, e(qy, y)?, 0]);
    }
    // μ = 2^s/|det P|: n_{k+1} × n_{k+2} = det·P_k, so μ·Q_k = P_k up to the roundings.
    let a = i128::try_from(adet).ok()?; // < 2^90: always Some
    let e = |qc: i128, pc: i128| ceil_div_up(((qc << s) - a * pc).unsigned_abs(), adet);
    Some([e(qx, x)?, e(qy, y)?, e(qw, w)?])
}

/// `⌊v / 2^r⌋` for `r ≥ 0`, `v·2^(−r)` (exact) for `r < 0`, as i64: the caller picks `r` so
/// that the result has at most 62 bits (`depth_plane`); anything else saturates (not reached).
// |r| < 128: both shifts are in range for i128 and exact (left: the result has ≤ 62 bits).
#[inline(never)]
#[allow(clippy::arithmetic_side_effects)]
fn shift_to_i64(v: i128, r: i32) -> i64 {
    let x = if r >= 0 {
        v >> r.min(127)
    } else {
        v << (-r).min(127)
    };
    i64::try_from(x).unwrap_or(if v < 0 { i64::MIN } else { i64::MAX })
}

/// The depth plane `(G, f)` from the exact `Zv` (< 2^90) and `D ≠ 0` (|D| < 2^120), module
/// docs.
// bitlen ≤ 120: rd = bitlen(D) − 32 ∈ [−23, 88] (D ≥ 256), rz = bitlen(max|Zv|) − 62 ∈
// [−61, 28]; every shifted value has ≤ 32 bits (D) or ≤ 62 bits (Zv); f ∈ [−75, 125].
#[inline(never)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_wrap)]
fn depth_plane(zv: [i128; 3], d: i128) -> Option<([i32; 3], i32)> {
    // Orient D > 0: |D|, |Zv| < 2^120, the negations are exact.
    let (zv, d) = if d < 0 { (zv.map(|c| -c), -d) } else { (zv, d) };
    if d < 256 {
        return None;
    }
    let bz = bitlen(zv.iter().map(|c| c.unsigned_abs()).max().unwrap_or(0)) as i32;
    if bz == 0 {
        return Some(([0; 3], 0));
    }
    let (rd, rz) = (bitlen(d.unsigned_abs()) as i32 - 32, bz - 62);
    let d32 = shift_to_i64(d, rd); // [2^31, 2^32)
    let mut g = [0i32; 3];
    for (gi, &z) in g.iter_mut().zip(zv.iter()) {
        // |Z62| < 2^62, D32 ≥ 2^31: the floor quotient is in [−2^31, 2^31): i32.
        *gi = i32::try_from(shift_to_i64(z, rz).div_euclid(d32)).ok()?;
    }
    // Zv_i / D ≈ G_i·2^(rz − rd); depth·2^-24 = Σ Zv_i·d_i / D: f = rd − rz − 24.
    Some((g, rd - rz - DEPTH_FRAC as i32))
}

/// Planar setup of a static triangle (its t0 vertices) in `vp`: the rounded planes and the
/// conservative epsilon, or `None` (culled as degenerate: det(P) = 0, det(n') = 0, or an
/// epsilon above [`PLANAR_EPS_LIMIT`]).
#[allow(clippy::arithmetic_side_effects)] // ranges at each line
pub(crate) fn planar_setup(
    tri: &Triangle,
    vp: Viewport,
    ops: &mut Ops,
) -> Option<(PlanarEdges, Eps)> {
    let [v0, _] = &tri.v;
    // |P| ≤ 2^29 (checked triangle): each normal component ≤ 2^59 (i64), det < 2^90 (i128).
    let p = v0.map(|q| [q[X], q[Y], q[W]].map(i64::from));
    let [p0, p1, p2] = p;
    let exact = [cross(p1, p2), cross(p2, p0), cross(p0, p1)];
    let [e0, _, _] = exact;
    let det = dot128(&p0, &e0);
    ops.add_setup(30);
    if det == 0 {
        return None;
    }
    let mut n = [[0i32; 3]; 3];
    let mut sh = [0u32; 3];
    for ((nk, sk), ek) in n.iter_mut().zip(sh.iter_mut()).zip(exact.iter()) {
        (*nk, *sk) = round_normal(ek);
    }
    let [n0, n1, n2] = n.map(|v| v.map(i64::from));
    let pp = [cross(n1, n2), cross(n2, n0), cross(n0, n1)];
    let [q0, _, _] = pp;
    // |n'_0| ≤ 2^30, |P''_0| ≤ 2^61: each product ≤ 2^91, the sum < 2^93.
    let detn = dot128(&n0, &q0);
    ops.add_setup(45);
    if detn == 0 {
        return None;
    }
    let sigma: i32 = if det > 0 { 1 } else { -1 };
    let flip = (detn > 0) != (sigma > 0);
    let adet = det.unsigned_abs();
    let [s0, s1, s2] = sh;
    // sh ≤ 30 each: s ≤ 60.
    let shifts = [s1 + s2, s2 + s0, s0 + s1];
    let mut eps = [0i32; 3];
    for ((pk, qk), &s) in p.iter().zip(pp.iter()).zip(shifts.iter()) {
        // Q_k = τ·P''_k: |P''| ≤ 2^61, the negation is exact.
        let q = if flip { qk.map(|c| -c) } else { *qk };
        let e = vertex_eps(*pk, q, s, adet)?;
        for (m, v) in eps.iter_mut().zip(e) {
            *m = (*m).max(v);
        }
        ops.add_setup(12);
    }
    // Depth plane: Zv = Σ z_k·n_k (|z| ≤ 2^29, |n| ≤ 2^59: < 3·2^88), D = det·256·W·H
    // (< 2^90·2^30).
    let z = v0.map(|q| i64::from(q[Z]));
    let [x0, x1, x2] = exact;
    let zv = [0, 1, 2].map(|i| {
        let col = [x0, x1, x2].map(|nk| nk.get(i).copied().unwrap_or(0));
        dot128(&col, &z)
    });
    let dw = i64::from(vp.w) * i64::from(vp.h) * (1i64 << SUBPIXEL_BITS);
    let (g, f) = depth_plane(zv, det * i128::from(dw))?;
    ops.add_setup(20);
    Some((
        PlanarEdges { n, sh, sigma, g, f },
        Eps {
            x: [eps[0], eps[1]],
            w: eps[2],
        },
    ))
}

/// The planar test's intermediates of one sample (for tests).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlanarEval {
    /// edge values `E'_k = n'_k · d` (exact)
    pub e: [i64; 3],
    /// coverage and depth
    pub hit: Option<Hit>,
}

/// The sample direction as i32: inside the viewport (checked by the caller) every component is
/// ≤ 2^30 in magnitude (`sample::direction`).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_wrap)]
fn direction32(vp: Viewport, xs: i32, ys: i32) -> [i32; 3] {
    let (w, h) = (i32::from(vp.w), i32::from(vp.h));
    let one = 1i32 << SUBPIXEL_BITS;
    // |2xs − 256W| ≤ 256W ≤ 2^19, ×H ≤ 2^11: ≤ 2^30; 256·W·H ≤ 2^30.
    [(2 * xs - one * w) * h, (one * h - 2 * ys) * w, one * w * h]
}

/// Fill rule on `E'_k = 0` (module docs): `σ·a' > 0`, or `a' = 0` and `σ·b' > 0`.
#[inline]
fn fill(n: &[i32; 3], sigma: i32) -> bool {
    let [a, b, _] = *n;
    if sigma > 0 {
        a > 0 || (a == 0 && b > 0)
    } else {
        a < 0 || (a == 0 && b < 0)
    }
}

/// Depth of a hit from the plane `(G, f)` (module docs).
#[inline(never)]
#[allow(clippy::arithmetic_side_effects)]
fn depth(g: &[i32; 3], f: i32, d: &[i32; 3]) -> i32 {
    // |G| ≤ 2^31, |d| ≤ 2^30: each product ≤ 2^61, the sum < 2^63.
    let acc: i64 = g
        .iter()
        .zip(d.iter())
        .map(|(&a, &b)| i64::from(a) * i64::from(b))
        .sum();
    let q = if f >= 0 {
        // An arithmetic shift by ≤ 63: the floor (0 or −1 past the magnitude).
        acc >> f.min(63)
    } else if acc == 0 {
        0
    } else {
        let k = f.unsigned_abs();
        match 2i64.checked_pow(k).and_then(|p| acc.checked_mul(p)) {
            Some(v) => v,
            None if acc < 0 => i64::MIN,
            None => i64::MAX,
        }
    };
    // Clamped to [DEPTH_NEAR, DEPTH_FAR]: the conversion is exact.
    i32::try_from(q.clamp(i64::from(DEPTH_NEAR), i64::from(DEPTH_FAR))).unwrap_or(DEPTH_FAR)
}

/// The planar test with its intermediates: `None` for a position outside the viewport or a
/// setup without planar data (not a static triangle of a `Planar` precision).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_wrap)]
pub fn planar_eval(setup: &Setup, pos: ScreenPos, ops: &mut Ops) -> Option<PlanarEval> {
    let crate::setup::Stored::Planar(pl) = &setup.edges else {
        return None;
    };
    let vp = setup.viewport;
    let (sw, sh) = (
        (u32::from(vp.w)) << SUBPIXEL_BITS,
        (u32::from(vp.h)) << SUBPIXEL_BITS,
    );
    if pos.xs >= sw || pos.ys >= sh {
        return None;
    }
    // xs < 2^19, ys < 2^19: exact in i32.
    let d = direction32(vp, pos.xs as i32, pos.ys as i32);
    // |n'| ≤ 2^30, |d| ≤ 2^30: three products ≤ 2^60, |E'| < 2^62 (i64).
    let e = pl.n.map(|nk| {
        nk.iter()
            .zip(d.iter())
            .map(|(&a, &b)| i64::from(a) * i64::from(b))
            .sum::<i64>()
    });
    let [e0, e1, e2] = e;
    let pos_side = pl.sigma > 0;
    let covered = if e0 != 0 && e1 != 0 && e2 != 0 {
        // Every E' has the orientation's strict sign.
        if pos_side {
            e0 > 0 && e1 > 0 && e2 > 0
        } else {
            e0 < 0 && e1 < 0 && e2 < 0
        }
    } else {
        e.iter().zip(pl.n.iter()).all(|(&ek, nk)| {
            if ek == 0 {
                fill(nk, pl.sigma)
            } else {
                (ek > 0) == pos_side
            }
        })
    };
    ops.add_sample(9 + 2 + 3);
    let hit = covered.then(|| {
        ops.add_sample(4);
        Hit {
            depth: depth(&pl.g, pl.f, &d),
        }
    });
    Some(PlanarEval { e, hit })
}

/// The planar test: the depth on a hit ([`planar_eval`]).
#[inline]
pub fn planar_test(setup: &Setup, pos: ScreenPos, ops: &mut Ops) -> Option<Hit> {
    planar_eval(setup, pos, ops)?.hit
}
