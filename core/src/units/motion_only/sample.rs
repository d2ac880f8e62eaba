//! The motion-specialised sample test of the motion-only unit ([`crate::units::motion_only::setup`]): the
//! bounded sample test (`bounded.rs`) of a static or motion triangle, bit for bit, with every
//! per-triangle factor precomputed in [`MotionSetup`] and nothing else.
//!
//! **Same contract, same bits.** Steps 1–8 of `bounded.rs` for `MOTION = true, DEFOCUS = false`:
//! the fast datapath (`bounded::fast_vertex`: the lerps one rounded high word each, the offsets
//! one rounded high word of `swq·x + ngxq·w`) where `bounded::Fast::new` takes it (T ≠ 2^15 and
//! both viewport sides below 2^(S−9)), the step-by-step general datapath otherwise
//! (`general`, out of line); steps 5–7 with the same fast decision and `bounded::decide_slow`
//! (out of line) for the rare path (some w ≤ 0 or some E' = 0); the depth on hits by
//! `bounded::depth`'s function (`motion_depth.rs`, bit for bit). The offsets are the same sums
//! regrouped in exact i64: `swq·x_t + ngxq·w + 2^31 = (swq·b_x + 2^31) + swq·δ_x + ngxq·w`
//! with the bracket from setup (`x_t = b_x + δ_x`, the rounded lerp). A static triangle is run as a motion one with `r − q = 0`: every rounded lerp of a
//! zero difference is the base value exactly (`f0 + floor((0 + 2^31)/2^32) = f0` on the fast
//! datapath, `f0 + floor(2^15/2^16) = f0` on the general one), and for a static triangle the two
//! shutter ends are equal (`Triangle::class`: the motion-only unit has CoC 0 throughout), so the
//! values — hence the bits — are those of the full unit's static instantiation. A static
//! triangle with every w > 0 on a fast viewport (`MotionSetup::still`) takes `still`: its
//! vertices do not depend on t, so only `ngxq·w` is formed per sample.
//!
//! **Early exit.** A sample with two edge values of strictly different signs is not covered,
//! whatever the third and the w: the fast decision needs one common strict sign, and
//! `decide_slow` covers only when every non-zero `E'` has the orientation's sign (with every
//! w > 0 the orientation is then 0; otherwise it is `sign(Σ E'·w)`, which at most one of the
//! two matches). The test returns before the third edge.

use crate::config::formats::TUV_FRAC;
use crate::config::precision::{Precision, OFFSET_SHIFT_MAX, OFFSET_SHIFT_MIN};
use crate::input::Sample;
use crate::sample::bounded::datapath::{lerp, mla_hi};
use crate::sample::bounded::decide_slow;
use crate::sample::pos::{Hit, ScreenPos};
use crate::units::motion_only::depth::depth;
use crate::units::motion_only::setup::{MotionSetup, Vfast};

/// Field indices of a [`MotionSetup`] vertex (x, y, w, z): w and z.
pub(crate) const MW: usize = 2;
pub(crate) const MZ: usize = 3;

/// 2^15: the middle of the shutter, the one T the fast lerp refuses.
const HALF: i32 = 1 << (TUV_FRAC - 1);
/// 2^16: one t step.
const ONE: i32 = 1 << TUV_FRAC;

/// `a_i·b_j − a_j·b_i`: an edge value (step 5), |a|, |b| < 2^30: each product < 2^60, the
/// sum < 2^61 (i64). Written `a_i·b_j + a_j·(−b_i)` (−b_i exact: |b_i| < 2^30), the same
/// integer, so that it is one SMULL and one SMLAL.
#[inline(always)]
#[allow(clippy::arithmetic_side_effects)]
fn edge(ai: i32, bi: i32, aj: i32, bj: i32) -> i64 {
    i64::from(ai) * i64::from(bj) + i64::from(aj) * i64::from(-bi)
}

/// The motion-only unit's sample test at screen position `pos` and sample `s`: bit for bit
/// the full unit's bounded test of the same triangle (module docs); `None` when not covered or
/// outside the viewport. Out of line: one copy for the renderer and the cost workload, and
/// the whole register file for the test (its callers' loop state is saved by the call).
#[inline(never)]
#[allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_wrap,
    clippy::indexing_slicing
)]
pub fn motion_test<P: Precision>(m: &MotionSetup, pos: ScreenPos, s: &Sample) -> Option<Hit> {
    if pos.xs >= m.end[0] || pos.ys >= m.end[1] {
        return None;
    }
    // xs < 256W ≤ 2^19, ys < 256H: exact in i32.
    let (xs, ys) = (pos.xs as i32, pos.ys as i32);
    // A planar precision's renderer sets static triangles up with `static_unit`, so the static
    // path is not linked there; a static `MotionSetup` at it takes the moving path with
    // `r − q = 0`, the same bits (module docs).
    if !P::PLANAR && m.still {
        return still(m, xs, ys);
    }
    let t = s.t().to_bits();
    if !m.fast || t == HALF {
        return general(m, xs, ys, t);
    }
    let late = t > HALF;
    // T ∈ [0, 2^16] \ {2^15}: min(T, 2^16 − T) < 2^15, so |tq| < 2^31 (`bounded::Fast::new`).
    let tq = if late { t - ONE } else { t } * ONE;
    // `fast`: 256·max(W, H)·k < 2^31 with k = 2^(32−S); |sw − 2xs| ≤ sw and |2ys − sh| ≤ sh
    // (|.| ≤ 2^19), so both scaled factors fit i32 (`bounded::Fast::new`).
    let ngxq = (m.sw - 2 * xs) * m.k;
    let ngyq = (2 * ys - m.sh) * m.k;
    let [v0, v1, v2] = if late { &m.hot[1] } else { &m.hot[0] };
    let (swq, shq) = (m.swq, m.shq);
    // One vertex: `w = b_w + δ_w`, and the offsets with the base's part `swq·b_x + 2^31`
    // from setup: `x_t = b_x + δ_x` with `δ_x = floor((tq·d_x + 2^31)/2^32)` (`mla_hi`), so
    // `swq·x_t + ngxq·w + 2^31 = c_x + swq·δ_x + ngxq·w`, the same sum (|δ| ≤ 2^30: |swq·δ|
    // < 2^61, |c_x| < 2^60 + 2^31, |ngxq·w| < 2^60: every partial sum < 2^63). Returns
    // `(a', b', w − 1)` (|w| ≤ 2^29).
    let vert = |v: &Vfast| {
        let w = mla_hi(tq, v.dw, v.bw);
        let sum = |c: i64, e: i32, d: i32, ng: i32| {
            ((c + i64::from(e) * i64::from(mla_hi(tq, d, 0)) + i64::from(ng) * i64::from(w)) >> 32)
                as i32
        };
        (
            sum(v.cx, swq, v.dx, ngxq),
            sum(v.cy, shq, v.dy, ngyq),
            w - 1,
        )
    };
    let (a0, b0, n0) = vert(v0);
    let (a1, b1, n1) = vert(v1);
    let (a2, b2, n2) = vert(v2);
    let ab = [a0, b0, a1, b1, a2, b2];
    let e2 = edge(a0, b0, a1, b1);
    let e0 = edge(a1, b1, a2, b2);
    // Two strict signs that differ: not covered (module docs, early exit).
    if (e0 > 0 && e2 < 0) || (e0 < 0 && e2 > 0) {
        return None;
    }
    let e1 = edge(a2, b2, a0, b0);
    // The sign bit of `n0 | n1 | n2` is set iff some w ≤ 0.
    if (n0 | n1 | n2) < 0 || e0 == 0 || e1 == 0 || e2 == 0 {
        return rare(m, tq, late, &ab);
    }
    // Every w > 0 and every E' ≠ 0: covered iff the three strict signs agree (`e0`, `e2`
    // agree here).
    if (e0 ^ e1) < 0 {
        return None;
    }
    hit(m, tq, late, &ab)
}

/// The edge values `[E'_0, E'_1, E'_2]` of the offsets `[a0, b0, a1, b1, a2, b2]`.
#[inline(always)]
fn edges(ab: &[i32; 6]) -> [i64; 3] {
    let [a0, b0, a1, b1, a2, b2] = *ab;
    [
        edge(a1, b1, a2, b2),
        edge(a2, b2, a0, b0),
        edge(a0, b0, a1, b1),
    ]
}

/// A covered sample's depth on the fast datapath (every w > 0, the three E' of one strict
/// sign): the edges and (w, z) recomputed ([`wz_fast`]) and [`depth`]. Out of line: nothing of
/// it stays live through the common miss.
#[inline(never)]
fn hit(m: &MotionSetup, tq: i32, late: bool, ab: &[i32; 6]) -> Option<Hit> {
    let e = edges(ab);
    let sign = if e[0] < 0 { -1 } else { 1 };
    Some(Hit {
        depth: depth_out(&e, &wz_fast(m, tq, late), sign),
    })
}

/// The rare path of the fast datapath (some w ≤ 0 or some E' = 0): the edges and w
/// recomputed, `bounded::decide_slow` (orientation, fill rule), the depth on a hit.
#[cold]
#[inline(never)]
fn rare(m: &MotionSetup, tq: i32, late: bool, ab: &[i32; 6]) -> Option<Hit> {
    let e = edges(ab);
    let wz = wz_fast(m, tq, late);
    let [a0, b0, a1, b1, a2, b2] = *ab;
    let [(w0, _), (w1, _), (w2, _)] = wz;
    let (sign, covered, _) = decide_slow(e, [(a0, b0, w0), (a1, b1, w1), (a2, b2, w2)]);
    covered.then(|| Hit {
        depth: depth_out(&e, &wz, sign),
    })
}

/// [`depth`] out of line, for the paths that are not hot (rare, general, moving hits): one
/// copy of it in the program beside the static path's inlined one.
#[inline(never)]
fn depth_out(e: &[i64; 3], wz: &[(i32, i32); 3], sign: i64) -> i32 {
    depth(e, wz, sign)
}

/// The static path of [`motion_test`] (`MotionSetup::still`: `r = q`, every w > 0, a `fast`
/// viewport): the fast datapath's offsets with the position-independent part precomputed,
/// `floor((swq·x + 2^31 + ngxq·w)/2^32)` = `floor((c + ngxq·w)/2^32)` — the same sum, so the
/// same bits (|c| < 2^60 + 2^31, |ngxq·w| < 2^60: < 2^62 in i64); the lerps of a zero
/// difference are the base values (module docs), every w > 0 is known, and (w, z) are
/// loaded for the depth. `xs < 256W`, `ys < 256H` (checked by [`motion_test`]).
#[inline(always)]
#[allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_truncation,
    clippy::indexing_slicing
)]
fn still(m: &MotionSetup, xs: i32, ys: i32) -> Option<Hit> {
    // As in [`motion_test`]: both scaled factors fit i32 (`fast`).
    let ngxq = (m.sw - 2 * xs) * m.k;
    let ngyq = (2 * ys - m.sh) * m.k;
    // [_; 3] and [_; 2] indexed by constants.
    let v = |k: usize| {
        let w = m.wz[k].0;
        let Vfast { cx, cy, .. } = m.hot[0][k];
        let hi = |c: i64, ng: i32| ((c + i64::from(ng) * i64::from(w)) >> 32) as i32;
        (hi(cx, ngxq), hi(cy, ngyq))
    };
    let (a0, b0) = v(0);
    let (a1, b1) = v(1);
    let e2 = edge(a0, b0, a1, b1);
    let (a2, b2) = v(2);
    let e0 = edge(a1, b1, a2, b2);
    if e0 != 0 && e2 != 0 && (e0 < 0) != (e2 < 0) {
        return None;
    }
    let e1 = edge(a2, b2, a0, b0);
    let e = [e0, e1, e2];
    let sign = if e0 != 0 && e1 != 0 && e2 != 0 {
        if e0 & e1 & e2 < 0 {
            -1
        } else if e0 | e1 | e2 >= 0 {
            1
        } else {
            return None;
        }
    } else {
        let [(w0, _), (w1, _), (w2, _)] = m.wz;
        let (sign, covered, _) = decide_slow(e, [(a0, b0, w0), (a1, b1, w1), (a2, b2, w2)]);
        if !covered {
            return None;
        }
        sign
    };
    Some(Hit {
        depth: depth(&e, &m.wz, sign),
    })
}

/// The step-1 (w, z) of every vertex on the fast datapath (hits only, out of line: w and z
/// are not kept live through the common miss). |d| ≤ 2^30, |tq| < 2^31 (as in
/// [`motion_test`]).
#[inline(always)]
#[allow(clippy::indexing_slicing)]
fn wz_fast(m: &MotionSetup, tq: i32, late: bool) -> [(i32, i32); 3] {
    let b = if late { &m.base[1] } else { &m.base[0] };
    let at = |d: &[i32; 4], b: &[i32; 4]| (mla_hi(tq, d[MW], b[MW]), mla_hi(tq, d[MZ], b[MZ]));
    let ([d0, d1, d2], [b0, b1, b2]) = (&m.d, b);
    [at(d0, b0), at(d1, b1), at(d2, b2)]
}

/// The general datapath (`bounded::eval_general` of the motion class, step by step): the
/// inputs the fast one refuses (T = 2^15, a viewport side ≥ 2^(S−9)). `xs < 256W`,
/// `ys < 256H` (checked by [`motion_test`]).
#[cold]
#[inline(never)]
#[allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_truncation,
    clippy::indexing_slicing
)]
fn general(m: &MotionSetup, xs: i32, ys: i32, t: i32) -> Option<Hit> {
    let (q, r) = (&m.base[0], &m.base[1]);
    // ngx = 256W − 2xs ∈ (−256W, 256W], ngy likewise (|.| ≤ 2^19).
    let (ngx, ngy) = (m.sw - 2 * xs, 2 * ys - m.sh);
    // 2^31 >> (32 − S) = 2^(S−1) (a right shift of a constant; 32 − S ∈ 0..=12,
    // `MotionSetup::shift`).
    let half = (1i64 << 31) >> (OFFSET_SHIFT_MAX - m.shift);
    let fine = m.shift - OFFSET_SHIFT_MIN;
    // |e·p| ≤ 2^19·2^29, |ng·w| ≤ 2^19·2^29, + 2^31: < 2^49 (i64); `>> 20` leaves < 2^31
    // (exact in i32), then `>> fine` (≤ 12): nested floors compose (`bounded::offset`).
    let off = |e: i32, p: i32, ng: i32, w: i32| {
        (((i64::from(e) * i64::from(p) + i64::from(ng) * i64::from(w) + half) >> OFFSET_SHIFT_MIN)
            as i32)
            >> fine
    };
    // Per vertex the lerped (x, y, w, z) (fields by constant, vertices by destructuring: no
    // index check, hence no panic path, is linked).
    let at = |qk: &[i32; 4], rk: &[i32; 4]| {
        let [qx, qy, qw, qz] = *qk;
        let [rx, ry, rw, rz] = *rk;
        [
            lerp(qx, rx, t),
            lerp(qy, ry, t),
            lerp(qw, rw, t),
            lerp(qz, rz, t),
        ]
    };
    let ([q0, q1, q2], [r0, r1, r2]) = (q, r);
    let p = [at(q0, r0), at(q1, r1), at(q2, r2)];
    let v = p.map(|[x, y, w, _]| (off(m.sw, x, ngx, w), off(m.sh, y, ngy, w), w));
    let [(a0, b0, w0), (a1, b1, w1), (a2, b2, w2)] = v;
    let e = [
        edge(a1, b1, a2, b2),
        edge(a2, b2, a0, b0),
        edge(a0, b0, a1, b1),
    ];
    let [e0, e1, e2] = e;
    let sign = if w0 > 0 && w1 > 0 && w2 > 0 && e0 != 0 && e1 != 0 && e2 != 0 {
        if e0 & e1 & e2 < 0 {
            -1
        } else if e0 | e1 | e2 >= 0 {
            1
        } else {
            return None;
        }
    } else {
        let (sign, covered, _) = decide_slow(e, v);
        if !covered {
            return None;
        }
        sign
    };
    let wz = p.map(|[_, _, w, z]| (w, z));
    Some(Hit {
        depth: depth_out(&e, &wz, sign),
    })
}

#[cfg(test)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]
mod tests {
    use super::*;
    use uvt_testkit::{cases, seed, Rng};

    /// [`edge`] (`a_i·b_j + a_j·(−b_i)`) against the bounded test's form `a_i·b_j − a_j·b_i`
    /// evaluated in i128, bit for bit: every combination of the offset corners (±(2^30 − 1),
    /// ±2^29, ±1, 0) and seeded random offsets with |.| < 2^30. Prints the inputs and both
    /// values (decimal and hex) on a failure.
    #[test]
    fn edge_is_the_difference_of_products() {
        let s = seed();
        let check = |ai: i32, bi: i32, aj: i32, bj: i32| {
            let want = i128::from(ai) * i128::from(bj) - i128::from(aj) * i128::from(bi);
            let got = edge(ai, bi, aj, bj);
            assert_eq!(
                i128::from(got),
                want,
                "UVT_SEED={s}: a_i {ai} ({ai:#x}) b_i {bi} ({bi:#x}) a_j {aj} ({aj:#x}) b_j {bj} \
                 ({bj:#x}): got {got} ({got:#x}), want {want} ({want:#x})"
            );
        };
        let m = (1 << 30) - 1;
        let corners = [m, -m, 1 << 29, -(1 << 29), 1, -1, 0];
        for &ai in &corners {
            for &bi in &corners {
                for &aj in &corners {
                    for &bj in &corners {
                        check(ai, bi, aj, bj);
                    }
                }
            }
        }
        let mut rng = Rng(s);
        for _ in 0..cases(200_000, 5_000_000) {
            let mut v = || rng.signed(i64::from(m)) as i32;
            let (ai, bi, aj, bj) = (v(), v(), v(), v());
            check(ai, bi, aj, bj);
        }
    }
}
