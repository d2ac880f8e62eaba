//! The planar static test's per-triangle setup (`sample::planar` module docs): each vertex of a
//! static triangle rounded once to 15 bits, the exact i32 edge normals of the rounded triangle,
//! its depth plane and the per-triangle conservative epsilon (the rounding residual).

use crate::arith::div::div64_32;
use crate::config::formats::{DEPTH_FRAC, SUBPIXEL_BITS};
use crate::input::{Triangle, Viewport, W, X, Y, Z};
use crate::setup::eps::Eps;
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
// [−61, 15]; every shifted value has ≤ 32 bits (D) or ≤ 62 bits (Zv); f ∈ [−62, 98]. For the
// Zv and D of a triangle (planar_setup) f ≤ 68: P'·Zv = det·ζ with ζ_k = z_k·2^(S − s_k)
// integers, so Zv ≠ 0 has max|Zv_i| ≥ |det|/(3·(2^15 − 1)), D/max|Zv| < 2^S·256·W·H·3·2^15
// < 2^61.6 and f = bitlen(D) − bitlen(max|Zv|) + 6 ≤ 68 (tests/tests/model/planar_exponent.rs).
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
/// The depth plane's divisions take the form `DIV32` picks ([`floor_div_d32`]): the same result
/// bit for bit; `true` links no 64-bit division routine (the static-specialised unit), `false`
/// is the general setup's.
#[allow(clippy::arithmetic_side_effects)] // ranges at each line
pub(crate) fn planar_setup<const DIV32: bool>(
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
