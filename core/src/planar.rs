//! Stage 3, planar — the static sample test of a [`crate::formats::Planar`] precision. Setup
//! rounds each **vertex** of a static triangle once to 15 bits; from then on everything is
//! exact: the edge normals of the rounded triangle fit i32 and the test per sample is three
//! 32 × 32 → 64 dot products — **exactly the exact test (`sample.rs`) on the rounded
//! triangle**, so it inherits its watertightness at shared edges and shared vertices.
//!
//! **Setup, per triangle** (raw clip units, `P_k = (x_k, y_k, w_k)` at t0, each |.| ≤ 2^29; no
//! projection, so camera-plane crossers and w = 0 vertices need no special case):
//!
//! | signal | value | rounding | format |
//! |---|---|---|---|
//! | `m_k` | `max(\|x_k\|, \|y_k\|, \|w_k\|)` | exact | u32, ≤ 2^29 |
//! | `s_k` | `max(0, bitlen(m_k) − 15)`, plus 1 if `rnd(m_k, s) > 2^15 − 1` | — | 0..=15 |
//! | `P'_k` | `rnd(P_k, s_k)` per component, `rnd(v, s) = sign(v)·⌊(\|v\| + 2^(s−1))/2^s⌋` (0 for s = 0: exact) | nearest, ties away from 0 | i16, \|.\| ≤ 2^15 − 1 |
//! | `z_k` | kept unrounded (the depth plane scales it by `2^(S − s_k)`, `S = max s_k`) | exact | i32, \|.\| ≤ 2^29 |
//! | `n_k` | `P'_{k+1} × P'_{k+2}` | exact | i32, \|.\| ≤ 2·(2^15 − 1)² < 2^31 |
//! | `σ` | `sign(det P')`, `det P' = P'_0 · n_0` | exact | i64 (\|det\| < 3·2^46); ±1, 0 culled |
//! | `ε_x, ε_y, ε_w` | `max_k \|c_k − 2^s_k·c'_k\|` per component c | exact | ≤ 2^14 |
//! | `G`, `f` | depth plane, below | floor | i32 ×3, exponent i32 |
//!
//! `s_k` and `P'_k` are functions of vertex k's own (x, y, w): a vertex shared by several
//! triangles has the same `P'` in each. `rnd(m_k) ≤ 2^15 − 1` bounds every component (rnd is
//! monotone in |v|). `s_k ≤ 15`: `m_k = 2^29` gives s = 15 and `rnd = 2^14`; below, bitlen ≤ 29,
//! s ≤ 14 before the increment, and after it `m_k < 2^(15+s)` gives `rnd(m_k, s + 1) ≤ 2^14`.
//! Coverage and ε need no division and no i128 (the depth plane needs `det·256·W·H` < 2^78 in
//! i128 and three divisions of a 62-bit by a 32-bit value, `floor_div_d32`: a 64-bit division
//! routine, or 32-bit divides in the static-specialised unit — the same quotients).
//!
//! **Per sample** (`d` = [`crate::sample::direction`], each \|d_i\| ≤ 2^30 inside a viewport
//! ≤ 2048, i32): `E_k = n_k · d` (three SMULL/SMLAL, \|E\| < 3·2^61 < 2^63, i64, exact).
//! Covered iff for every k: `σ·E_k > 0`, or `E_k = 0` and the fill rule accepts:
//! `σ·a_k > 0`, or `a_k = 0` and `σ·b_k > 0` (`(a, b, c) = n_k`; comparators only).
//!
//! **What it decides: exactly the exact test on `P'`.** These are the exact test's edge values,
//! orientation and fill rule (`sample.rs`) for the triangle with vertices `P'_k`, bit for bit
//! (`tests/tests/planar.rs` compares with an independent 192-bit evaluation). The open cone of
//! a triangle is invariant under positive per-vertex factors: the triangle `2^s_k·P'_k` has
//! normals `2^(s_{k+1}+s_{k+2})·n_k` and determinant `2^(s_0+s_1+s_2)·det P'` — the same signs,
//! the same decision. A triangle with `det P' = 0` (a sliver that rounding makes degenerate)
//! covers nothing in the exact test on `P'` and is culled (`Cull::Degenerate`).
//!
//! **Watertight, vertices included.** A consistently wound mesh of static triangles becomes,
//! vertex by vertex, the mesh of the `P'` (shared vertices stay shared, since `P'` depends on
//! the vertex alone); the planar test on each triangle is the exact test on that mesh, which is
//! watertight at edges and vertices: an edge seen as `(i, j)` and `(j, i)` has exactly negated
//! normals, so off the plane exactly one side has `σ·E > 0` and on it the fill rule's key
//! `(a, b)` is negated too; at a shared vertex all the triangles' planes pass through the one
//! point `P'`. No exemption.
//!
//! **Agreement with the exact test.** `2^s_k·P'_k = P_k + δ_k` with `|δ_k,c| ≤ h_k =
//! 2^(s_k − 1)` (0 for s_k = 0; `h_k ≤ 2^-16·m_k·(1 + 2^-14)`): each vertex moves by at most
//! 2^-16 of its largest component. The rounded triangle's edge value (up to its positive factor)
//! is `(P_{k+1} + δ_{k+1}) × (P_{k+2} + δ_{k+2}) · d`, which differs from the exact `E_k =
//! n_k·d` by at most `B_k(d) = h_{k+1}·‖P_{k+2} × d‖₁ + h_{k+2}·‖P_{k+1} × d‖₁ +
//! 2·h_{k+1}·h_{k+2}·‖d‖₁`. If every `|E_k| > B_k` the signs agree edge by edge, so a sample
//! decided differently has `|E_k| ≤ B_k` for some k — it lies within `B_k / |∇E_k|` px of edge k
//! (`∇E_k = (2a_k·H, −2b_k·W)` per 1/256 px) — unless the rounding flips the triangle's
//! orientation (a crosser within the rounding of degenerate). Per primitive (the `fit` style):
//! a vertex with `w_k > h_k` projects within `ρ_k = h_k·(1 + max(|x_k|, |y_k|)/w_k)/(w_k − h_k)`
//! NDC of its exact projection — 2^-16·(1 + guard-band ratio) relative to the nearest w; far
//! off-screen vertices at small w (guard band ≈ 2^13) move up to ¼ NDC. The agreement test
//! checks `|E_k| ≤ B_k` exactly (integers) on every differing sample, guard-band cases included.
//!
//! **Conservative epsilon.** The bounds (`setup.rs` boxes and time span, `HullCull` faces, …)
//! are conservative for every triangle whose vertices lie within `ε_x` (x), `ε_y` (y), `ε_w`
//! (w) of `P_k` — up to a positive factor per vertex, since coverage is the cone (their proofs
//! only use that vertex box). Coverage here is the exact test on `2^s_k·P'_k`, whose distance
//! from `P_k` per component is `|c_k − 2^s_k·c'_k|` ≤ 2^(s_k−1) ≤ 2^14: setup stores the
//! maximum over the vertices, per component, as the setup's [`Eps`] — exact, no rounding, well
//! inside the bounds' range proofs (ε < 2^24). No triangle is culled for its epsilon. With
//! `ε_w > 0` the hull (`strategies/hull.rs`) keeps its faces only when every hull point has
//! `w > ε_w` (its projected-perturbation proof needs `w_min − ε_w > 0`): a static triangle with
//! a vertex within ε_w (≤ 0.25 clip units) of the camera plane, or crossing it, keeps no hull
//! faces (the inner strategy's bounds, which carry ε, still apply — conservative, less tight).
//!
//! **Depth** (hits only), same format, saturation and direction as the bounded test (I8F24,
//! floor, saturated to [`DEPTH_NEAR`, `DEPTH_FAR`]): the depth of the exact test on the
//! rounded triangle `Q_k = 2^s_k·P'_k` with the **unrounded** depths `z_k`. The hit of ray `d`
//! is `Σ_k α_k·Q_k = d` with `α_k = E_k(Q)/det Q = 2^(−s_k)·E_k/det P'` (`E_k(Q) =
//! 2^(s_{k+1}+s_{k+2})·E_k`, `det Q = 2^(s_0+s_1+s_2)·det P'`), so `z/w = Σ_k z_k·α_k / d_w =
//! Zv·d / D` with `S = max s_k`, `Zv = Σ_k z_k·2^(S − s_k)·n_k` (i128, \|.\| < 2^77) and `D =
//! det P'·2^S·256·W·H` (i128, < 2^93): affine in the sample, no division per sample. (Until
//! this version z was rounded with its vertex's shift, `z'_k = rnd(z_k, s_k)`, an extra error
//! of up to `Σ_k |α_k|·2^(s_k−1)/d_w` — up to ~0.06 in z/w on the tests' triangles.) Setup (D
//! oriented > 0 with Zv): `D32 = ⌊D / 2^rd⌋` with `rd = bitlen(D) − 32` (a left shift, exact,
//! when negative: D ≥ 256), so D32 ∈ [2^31, 2^32); `Z62_i = ⌊Zv_i / 2^rz⌋` with `rz =
//! bitlen(max|Zv_i|) − 62`, |Z62| < 2^62; `G_i = ⌊Z62_i / D32⌋` ∈ [−2^31, 2^31) (i32; three
//! 64-bit divisions per triangle), `f = rd − rz − 24` ∈ [−62, 98]. Per hit: `acc = Σ G_i·d_i`
//! (\|.\| < 3·2^61, i64 exact), depth = `⌊acc / 2^f⌋` (arithmetic shift; `f ≥ 63` gives 0 or
//! −1) or `acc·2^(−f)` saturated for `f < 0`, then saturated to the depth range (`Zv = 0`:
//! depth 0).
//!
//! *Error against the exact z/w of the rounded triangle* (raw LSBs of 2^-24): at most
//! `(3·2^30 + Σ|G_i·d_i|·2^-30)/2^f + 1` (the floors of G and of the depth, D32's truncation;
//! checked on every hit by `tests/tests/planar.rs`).
//!
//! *Error against the exact depth of the unrounded triangle* (what `Exact` computes, before its
//! own floor): on the triangle's plane z is linear in `X = (x, y, w)`, `z = ζ·X` with `P·ζ = z`
//! (rows `P_k`) exactly and `(P + Δ)·ζ' = z` rounded (`Δ` rows `δ_k`, `|δ_k,c| ≤ h_k`), so
//! `P·(ζ' − ζ) = −Δ·ζ'` and, with `P^(−1) = [n_0 n_1 n_2]/det P`, `(ζ' − ζ)·d = −Σ_k
//! λ_k·(δ_k·ζ')` where `λ_k = E_k/det P` are the exact triangle's ray barycentrics (`Σ λ_k·P_k =
//! d`). Hence `|Δ(z/w)| ≤ Σ_k |λ_k|·h_k·‖ζ'‖₁ / d_w` — the vertex move times the rounded
//! plane's depth slope; for a hit with every `w_k > 0` (`λ_k ≥ 0`, `Σ λ_k·w_k = d_w`) at most
//! `max_k h_k·‖ζ'‖₁ / min_k w_k`. In LSBs: that × 2^24, plus the error above and Exact's own
//! floor (1). Checked per hit, exactly as stated, by `tests/tests/planar.rs`
//! (`depth_within_the_derived_bound_of_exact`), which fails on the old z rounding. Depth never
//! influences coverage.

use crate::bounded::{div64_32, Eps};
use crate::formats::{DEPTH_FAR, DEPTH_FRAC, DEPTH_NEAR, SUBPIXEL_BITS};
use crate::input::{Triangle, Viewport, W, X, Y, Z};
use crate::sample::{Hit, ScreenPos};
use crate::setup::Setup;
use crate::stats::Ops;

/// Bits of a rounded vertex component: |P'| ≤ 2^15 − 1 (i16).
pub const VERTEX_BITS: u32 = 15;

/// The planar test's per-triangle data. Built only by the planar setup from a checked
/// [`Triangle`], so every field is in the range the module table states.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlanarEdges {
    pub(crate) pv: [[i16; 3]; 3],
    pub(crate) s: [u8; 3],
    pub(crate) n: [[i32; 3]; 3],
    pub(crate) sigma: i32,
    pub(crate) g: [i32; 3],
    pub(crate) f: i32,
}

impl PlanarEdges {
    /// The rounded vertices `P'_k = (x', y', w')`, |.| ≤ 2^15 − 1.
    pub fn vertices(&self) -> [[i32; 3]; 3] {
        self.pv.map(|p| p.map(i32::from))
    }
    /// The per-vertex shifts `s_k` (0..=15): `P'_k ≈ P_k / 2^s_k`.
    pub fn shifts(&self) -> [u32; 3] {
        self.s.map(u32::from)
    }
    /// The edge normals `n_k = P'_{k+1} × P'_{k+2} = (a, b, c)`, exact, |.| < 2^31.
    pub fn n(&self) -> [[i32; 3]; 3] {
        self.n
    }
    /// The orientation σ = sign(det P'): −1 or 1.
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

/// `rnd(v, s) = sign(v)·⌊(|v| + 2^(s−1)) / 2^s⌋` (module table; exact for s = 0): nearest, ties
/// away from zero. For |v| ≤ 2^29 and s ≤ 15 the sum is < 2^30 (u32) and the result ≤ 2^29.
// s ≤ 15 (callers): the shifts are in range; |v| + half < 2^30 in u32; the result ≤ 2^29 fits
// i32 and its negation is exact.
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_wrap)]
fn rnd(v: i32, s: u32) -> i32 {
    let half = if s == 0 { 0 } else { 1u32 << (s - 1) };
    let q = ((v.unsigned_abs() + half) >> s) as i32;
    if v < 0 {
        -q
    } else {
        q
    }
}

/// The shift `s` (0..=15) of one vertex from `m = max(|x|, |y|, |w|)` ≤ 2^29 (module table):
/// the least of `bitlen(m) − 15` and one more, such that `rnd(m, s) ≤ 2^15 − 1`.
// bitlen(m) ≤ 30: s ≤ 15; the increment happens only for bitlen ≤ 29 (s ≤ 14), module docs.
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_wrap)]
fn vertex_shift(m: u32) -> u32 {
    let s = u32::BITS
        .saturating_sub(m.leading_zeros())
        .saturating_sub(VERTEX_BITS);
    if rnd(m as i32, s) > (1 << VERTEX_BITS) - 1 {
        s + 1
    } else {
        s
    }
}

/// Cross product of rounded vertices (|.| ≤ 2^15 − 1): each product ≤ (2^15 − 1)² < 2^30, each
/// difference ≤ 2·(2^15 − 1)² < 2^31: exact in i32.
#[inline(never)]
#[allow(clippy::arithmetic_side_effects)] // ranges in the doc comment
fn cross(a: [i32; 3], b: [i32; 3]) -> [i32; 3] {
    let [a0, a1, a2] = a;
    let [b0, b1, b2] = b;
    [a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0]
}

/// `a · b` in i64 for |a_i| < 2^31, |b_i| ≤ 2^29: each product < 2^60, the sum < 2^62.
#[inline(never)]
#[allow(clippy::arithmetic_side_effects)]
fn dot64(a: &[i32; 3], b: &[i32; 3]) -> i64 {
    a.iter()
        .zip(b.iter())
        .map(|(&x, &y)| i64::from(x) * i64::from(y))
        .sum()
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

/// `⌊z / d32⌋` for |z| < 2^62 and `d32` ∈ [2^31, 2^32): in [−2^31, 2^31) (i32). `DIV32 =
/// false` (the general units): `i64::div_euclid` (the floor, d32 > 0; a 64-bit division
/// routine on 32-bit targets). `DIV32 = true` (the static-specialised unit): the magnitude's
/// floor `q = ⌊|z| / d32⌋` by [`div64_32`] (32-bit divides, the Cortex-M's UDIV; its
/// precondition `|z| < 2^32·d32` holds as |z| < 2^62 < 2^63 ≤ 2^32·d32), the remainder `r =
/// |z| − q·d32` exact (q·d32 ≤ |z| < 2^62), and the floor of the signed quotient `q` for
/// `z ≥ 0`, `−q − [r ≠ 0]` for `z < 0` — the same integer (`planar_corners.rs` checks both
/// forms bit for bit at the operand corners and on seeded operands and triangles).
#[inline(always)]
#[allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_truncation,
    clippy::cast_possible_wrap,
    clippy::cast_sign_loss
)]
pub(crate) fn floor_div_d32<const DIV32: bool>(z: i64, d32: i64) -> Option<i32> {
    if DIV32 {
        Some(floor_div32(z, d32))
    } else {
        i32::try_from(z.div_euclid(d32)).ok()
    }
}

/// [`floor_div_d32`]'s `DIV32` form (one copy for the three divisions).
#[inline(never)]
#[allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_truncation,
    clippy::cast_possible_wrap,
    clippy::cast_sign_loss
)]
fn floor_div32(z: i64, d32: i64) -> i32 {
    // d32 ∈ [2^31, 2^32): exact in u32.
    let (mag, v) = (z.unsigned_abs(), d32 as u32);
    let q = div64_32(mag, v);
    // q·v ≤ mag < 2^62: the product and the difference are exact.
    let r = mag - u64::from(q) * u64::from(v);
    // q ≤ mag / 2^31 < 2^31: exact in i32, and −q − 1 ≥ −2^31.
    let q = q as i32;
    if z >= 0 {
        q
    } else {
        -q - i32::from(r != 0)
    }
}

/// The depth plane `(G, f)` from the exact `Zv` (< 2^77) and `D ≠ 0` (|D| < 2^93), module
/// docs; the three divisions by [`floor_div_d32`] (`DIV32` picks its form, same bits).
// bitlen(D) ≤ 93: rd = bitlen(D) − 32 ∈ [−23, 61] (D ≥ 256), rz = bitlen(max|Zv|) − 62 ∈
// [−61, 15]; every shifted value has ≤ 32 bits (D) or ≤ 62 bits (Zv); f ∈ [−62, 98].
#[inline(never)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_wrap)]
fn depth_plane<const DIV32: bool>(zv: [i128; 3], d: i128) -> Option<([i32; 3], i32)> {
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
        *gi = floor_div_d32::<DIV32>(shift_to_i64(z, rz), d32)?;
    }
    // Zv_i / D ≈ G_i·2^(rz − rd); depth·2^-24 = Σ Zv_i·d_i / D: f = rd − rz − 24.
    Some((g, rd - rz - DEPTH_FRAC as i32))
}

/// Planar setup of a static triangle (its t0 vertices) in `vp`: the rounded vertices, their
/// exact normals, the epsilon and the depth plane, or `None` (culled as degenerate: det P' = 0).
#[inline]
pub(crate) fn planar_setup(
    tri: &Triangle,
    vp: Viewport,
    ops: &mut Ops,
) -> Option<(PlanarEdges, Eps)> {
    planar_setup_with::<false>(tri, vp, ops)
}

/// [`planar_setup`] with the depth plane's divisions in the form `DIV32` picks
/// ([`floor_div_d32`]): the same result bit for bit; `true` links no 64-bit division routine
/// (the static-specialised unit).
#[allow(clippy::arithmetic_side_effects)] // ranges at each line
pub(crate) fn planar_setup_with<const DIV32: bool>(
    tri: &Triangle,
    vp: Viewport,
    ops: &mut Ops,
) -> Option<(PlanarEdges, Eps)> {
    let [v0, _] = &tri.v;
    let mut pv = [[0i32; 3]; 3];
    let mut s = [0u32; 3];
    let mut z = [0i32; 3];
    let mut eps = [0i32; 3];
    for (k, q) in v0.iter().enumerate() {
        // Checked triangle: |x|, |y|, |z|, |w| ≤ 2^29.
        let p = [q[X], q[Y], q[W]];
        let m = p.iter().map(|c| c.unsigned_abs()).max().unwrap_or(0);
        let sk = vertex_shift(m);
        let r = p.map(|c| rnd(c, sk));
        for ((e, &c), &cr) in eps.iter_mut().zip(p.iter()).zip(r.iter()) {
            // |c'| ≤ 2^15 − 1, s ≤ 15: c'·2^s < 2^30; the residual ≤ 2^(s−1) ≤ 2^14.
            *e = (*e).max((c - (cr << sk)).abs());
        }
        if let (Some(pk), Some(sl), Some(zk)) = (pv.get_mut(k), s.get_mut(k), z.get_mut(k)) {
            (*pk, *sl, *zk) = (r, sk, q[Z]);
        }
        ops.add_setup(12);
    }
    let [p0, p1, p2] = pv;
    let n = [cross(p1, p2), cross(p2, p0), cross(p0, p1)];
    let [n0, n1, n2] = n;
    // |P'| < 2^15, |n| < 2^31: |det P'| < 3·2^46.
    let det = dot64(&p0, &n0);
    ops.add_setup(21);
    if det == 0 {
        return None;
    }
    // Depth plane of the rounded triangle with the unrounded depths (module docs): with S =
    // max s_k, Zv_i = Σ_k z_k·2^(S − s_k)·n_k,i (|z| ≤ 2^29, 2^(S − s_k) ≤ 2^15, |n| < 2^31:
    // each term < 2^75, |Zv| < 2^77, i128) and D = det·2^S·256·W·H (< 3·2^46·2^15·2^30 <
    // 2^93, i128); S − s_k ∈ [0, 15]: the shifts are in range and exact.
    let smax = s.iter().copied().max().unwrap_or(0);
    let zs = [0, 1, 2].map(|k| {
        let (zk, sk) = (
            z.get(k).copied().unwrap_or(0),
            s.get(k).copied().unwrap_or(0),
        );
        i128::from(zk) << (smax - sk)
    });
    let zv = [0, 1, 2].map(|i| {
        [n0, n1, n2]
            .iter()
            .zip(zs.iter())
            .map(|(nk, &zk)| zk * i128::from(nk.get(i).copied().unwrap_or(0)))
            .sum::<i128>()
    });
    let dw = i64::from(vp.w) * i64::from(vp.h) * (1i64 << SUBPIXEL_BITS);
    let (g, f) = depth_plane::<DIV32>(zv, (i128::from(det) << smax) * i128::from(dw))?;
    ops.add_setup(20);
    // |P'| ≤ 2^15 − 1 and s ≤ 15 (module table): the conversions are exact.
    let pv = pv.map(|p| p.map(|c| i16::try_from(c).unwrap_or(0)));
    let s = s.map(|c| u8::try_from(c).unwrap_or(0));
    Some((
        PlanarEdges {
            pv,
            s,
            n,
            sigma: if det > 0 { 1 } else { -1 },
            g,
            f,
        },
        Eps {
            x: [eps[0], eps[1]],
            w: eps[2],
        },
    ))
}

/// The planar test's intermediates of one sample (for tests).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlanarEval {
    /// edge values `E_k = n_k · d` (exact)
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

/// Fill rule on `E_k = 0` (module docs): `σ·a > 0`, or `a = 0` and `σ·b > 0`.
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
pub(crate) fn depth(g: &[i32; 3], f: i32, d: &[i32; 3]) -> i32 {
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
    // |n| < 2^31, |d| ≤ 2^30: three products < 2^61, |E| < 3·2^61 < 2^63 (i64).
    let e = pl.n.map(|nk| {
        nk.iter()
            .zip(d.iter())
            .map(|(&a, &b)| i64::from(a) * i64::from(b))
            .sum::<i64>()
    });
    let [e0, e1, e2] = e;
    let pos_side = pl.sigma > 0;
    let covered = if e0 != 0 && e1 != 0 && e2 != 0 {
        // Every E has the orientation's strict sign.
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
