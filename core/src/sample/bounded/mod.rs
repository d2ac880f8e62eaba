//! Stage 3, bounded — a hardware-width sample test that rounds at declared points to declared
//! widths and then decides coverage exactly on the rounded values. Selected by a
//! [`crate::config::precision::Bounded`] precision (`OFFSET_SHIFT = Some(S)`); the exact test in
//! `exact.rs` stays the `Prec` path.
//!
//! **Datapath, per sample** (raw units: clip values have 16 fraction bits; `T`, `U`, `V` raw
//! t/u/v with 16 fraction bits; `W`, `H` the viewport; `xs`, `ys` the position in 1/256 px):
//!
//! | step | value | rounding | operands → result |
//! |---|---|---|---|
//! | 1 lerp (motion classes) | `f_t = rnd16(f0·2^16 + T·(f1 − f0))` for x, y, w, z, c | nearest, ties up, 1/2 LSB | 17 × 32 → i64 (\|.\| ≤ 2^45), result \|f_t\| ≤ 2^29 (i32) |
//! | 2 lens (defocus classes) | `x = x_t + rnd16(U·c_t)`, `y = y_t + rnd16(V·c_t)` | nearest, ties up, 1/2 LSB | 18 × 31 → i64 (≤ 2^45), result \|x\| ≤ 2^30 (i32) |
//! | 3 offsets | `A = 256W·x − (2xs − 256W)·w`, `B = 256H·y − (256H − 2ys)·w` | none (exact) | 20 × 31 → i64, \|A\| < 1.5·2^49 |
//! | 4 grid | `a' = rnd_S(A)`, `b' = rnd_S(B)` | nearest, ties up, 2^(S−1) | result \|a'\| < 2^(50−S) ≤ 2^30 (i32) |
//! | 5 edges | `E'_k = a'_{k+1}·b'_{k+2} − a'_{k+2}·b'_{k+1}` | none | 32 × 32 → i64, \|E'\| < 2^61 |
//! | 6 orientation | all `w_k > 0`: the common sign of the `E'_k`, no product; else `sign(Σ E'_k·w_k)` | none | **rare path** \|Σ\| < 2^92, its sign from two i64 sums of the high and low words of E' times w (`det_sign`, no 128-bit arithmetic) |
//! | 7 fill rule (`E'_k = 0`) | tie key `κ = cmp((b', a', w)_{k+1}, (b', a', w)_{k+2})` (lexicographic, −1/0/1); the sample is inside edge k iff `s·κ > 0` | none | comparators only, no multiplier |
//! | 8 depth (hits only) | `E'' = floor(E'/2^sh)` with \|E''\| ≤ 2^24 (`sh` = bit length of max\|E'\| − 24, ≥ 0), `num = Σ E''·z`, `den = Σ E''·w` | floor | 25 × 30 → i64 sums < 2^55; quotient `floor(num·2^24/den)` saturated to the depth range: saturation from `num` vs `±2^7·den`, then an exact floor division (`depth_quotient`: on 32-bit targets a 64-by-32-bit long division in 32-bit divides with an exact correction, on 64-bit ones one u128 division) |
//!
//! `w` and `z` here are the step-1 values (exact for static and defocus-only triangles).
//!
//! **Software form (the Cortex-M4 cost).** The values above are computed by one of two
//! datapaths with identical results. The fast one (`fast_vertex`) scales one factor of every
//! rounded product so that its rounding point is 2^32 and the result is the rounded high word of
//! a 32 × 32 → 64 product: the lerps and the lens offsets are one SMMLAR each (`f0 +
//! floor((T·2^16·d + 2^31)/2^32)`, T measured from the nearer shutter end so that `T·2^16`
//! fits i32), the offsets one SMULL + SMLAL and the rounding add (factors `256W·2^(32−S)`,
//! `ngx·2^(32−S)`). It refuses the few inputs where a scaled factor does not fit i32 — T =
//! 2^15, U or V = 2^16, a viewport side ≥ 2^(S−9) (2048 at S = 20) — which take the general
//! datapath (the step-by-step form of the table, out of line). Proofs on `Fast` and
//! `fast_vertex`; `bounded_corners.rs` drives both sides of each boundary against the frozen
//! contract. Misses keep only (a', b') and the sign of w live; w and z are recomputed for the
//! rare path and for depth.
//!
//! **What the test decides.** With `x' = (a'·2^S + (2xs − 256W)·w)/(256W)` and `y'` likewise,
//! `E'` and `det' = Σ E'_k·w_k` are positive multiples of the exact test's `E_k` and `det` for
//! the triangle `P'_k = (x'_k, y'_k, w_k)` (the translation by the sample and the common scale
//! cancel), so off the edges (every `E'_k ≠ 0`) coverage is **exactly** the exact
//! test's on `P'`. A sample exactly on a rounded edge (`E'_k = 0`) is decided by a tie key that
//! needs no multiplier (step 7) instead of `exact.rs`'s edge-normal rule, which would cost four
//! 32 × 30-bit products per edge in hardware for a case that decides only samples at distance 0
//! from an edge. Hence:
//! - **Watertight by construction.** Every rounding is a function of the vertex's own data and
//!   the sample, so a vertex shared by two triangles has the same `P'`; shared edges get exact
//!   negatives. The tie key is antisymmetric, `κ(i, j) = −κ(j, i)`, so on a shared edge seen as
//!   `(i, j)` by one triangle and `(j, i)` by its neighbour of the same orientation `s`, exactly
//!   one of `s·κ(i, j) > 0` and `s·κ(j, i) > 0` holds — the sample goes to exactly one of them.
//!   `κ = 0` only when the two vertices coincide as `(a', b', w)`; then every `E'` of the
//!   triangle is 0 at this sample, `det' = 0`, and the sample is covered by neither.
//! - **Perturbation bound** ([`Eps`]). `|x' − x| ≤ k/2 + 2^(S−1)/(256W)` raw, where `x` is the exact
//!   position at (t, u) and `k` counts the half-LSB roundings on the way (lerp of x; lerp of c,
//!   times \|U\| ≤ 1; the lens product): k = 0 static, 1 motion, 1 defocus, 3 both. Same for y
//!   with H. `|w' − w| ≤ 1/2` raw for motion classes (lerp), 0 otherwise. Setup and the bounds
//!   take the integer ceilings of these as the conservative epsilon (`setup/eps.rs`).
//!
//! A sample position outside the viewport (`xs ≥ 256W` or `ys ≥ 256H`) is never covered: the
//! range proofs above assume `|2xs − 256W| ≤ 256W`, and a renderer never asks.

pub(crate) mod datapath;
pub(crate) mod depth;

use crate::config::precision::{Precision, OFFSET_SHIFT_MAX, OFFSET_SHIFT_MIN};
use crate::config::unit::{Full, Unit};
use crate::coverage::{Bin, NoProbe, Probe};
use crate::input::{Sample, W, Z};
use crate::sample::bounded::datapath::{
    fast_vertex, fill_rule, lerp, mla_hi, tie_bin, vertex, Ctx, Fast, SUBPIXEL_SCALE,
};
use crate::sample::bounded::depth::depth;
use crate::sample::pos::{Hit, ScreenPos};
use crate::setup::Setup;
use crate::stats::Ops;

/// The rounded intermediates of one bounded sample test (for tests and vectors).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BoundedEval {
    /// rounded offsets (a'_k, b'_k)
    pub ab: [(i64, i64); 3],
    /// edge values E'_k
    pub e: [i64; 3],
    /// orientation sign of det' (−1, 0, 1); 0 when the sample is not covered for any orientation
    /// (mixed edge signs with every w > 0) and det' was therefore not formed
    pub det_sign: i64,
    /// coverage and depth
    pub hit: Option<Hit>,
}

/// The edge-sign bins (step 5).
const EDGE: [Bin; 3] = [Bin::BsEdgeNeg, Bin::BsEdgeZero, Bin::BsEdgePos];

/// Operations counted per sample test of a class (the hardware datapath's count, unchanged by
/// the software order: the z lerp is counted with the other lerps though it runs on hits only).
// Constants ≤ 100: no overflow.
#[allow(clippy::arithmetic_side_effects)]
const fn class_ops(motion: bool, defocus: bool) -> u64 {
    let m = if motion { 15 * 3 } else { 0 };
    let d = if defocus { 6 * 3 } else { 0 };
    m + d + 2 + 3 * 8 + 9
}

/// `sign(Σ E'_k·w_k)` (|E'| < 2^61, |w| ≤ 2^29, so |Σ| < 2^92) without 128-bit arithmetic:
/// with `E' = h·2^32 + l` (`h = E' >> 32`, |h| < 2^29; `l` = the low word, 0 ≤ l < 2^32),
/// `Σ E'·w = H·2^32 + L` with `H = Σ h·w` (|.| < 3·2^58) and `L = Σ l·w` (|.| < 3·2^61 < 2^63),
/// both exact in i64; moving `floor(L/2^32)` into H leaves `H'·2^32 + L'` with 0 ≤ L' < 2^32
/// (|H'| < 2^61), whose sign is that of H', or of L' when H' = 0. `bounded_frozen` compares it
/// with the i128 sum of the frozen copy.
#[inline]
#[allow(clippy::arithmetic_side_effects)]
fn det_sign(e: &[i64; 3], w: [i32; 3]) -> i64 {
    let (mut hi, mut lo) = (0i64, 0i64);
    for (&ek, wk) in e.iter().zip(w) {
        // Arithmetic shift by the constant 32 (floor) and the low word (< 2^32, exact in i64).
        hi += (ek >> 32) * i64::from(wk);
        lo += (ek & 0xffff_ffff) * i64::from(wk);
    }
    // Shift by the constant 32 (floor); the mask keeps the low word, ≥ 0.
    let hi = hi + (lo >> 32);
    let lo = lo & 0xffff_ffff;
    if hi != 0 {
        hi.signum()
    } else {
        i64::from(lo != 0)
    }
}

/// Orientation and coverage (steps 6–7) when some `w ≤ 0` or some `E' = 0` (the fast path in
/// [`finish`] takes the rest): with every w > 0 the common sign of the `E'` (0 if they
/// have both signs or are all 0), else `sign(Σ E'_k·w_k)` ([`det_sign`], |Σ| < 2^92); edges
/// with `E' = 0` go to the fill rule. Returns (orientation, covered, operations counted).
#[cold]
#[inline(never)]
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn decide_slow(e: [i64; 3], p: [(i32, i32, i32); 3]) -> (i64, bool, u64) {
    decide_in(&e, &p, &mut NoProbe)
}

/// [`decide_slow`], its paths reported to `pr` (a separate out-of-line copy: [`decide_slow`]
/// itself stays non-generic, compiled once in this crate, where nobody reads the probe).
#[inline(never)]
fn decide_slow_p<Pr: Probe>(e: [i64; 3], p: [(i32, i32, i32); 3], pr: &mut Pr) -> (i64, bool, u64) {
    decide_in(&e, &p, pr)
}

/// The body of [`decide_slow`] and [`decide_slow_p`].
#[inline(always)]
#[allow(clippy::arithmetic_side_effects)]
fn decide_in<Pr: Probe>(e: &[i64; 3], p: &[(i32, i32, i32); 3], pr: &mut Pr) -> (i64, bool, u64) {
    let (sign, n) = if p.iter().all(|&(_, _, w)| w > 0) {
        pr.hit(Bin::BsDecideTie);
        let pos = e.iter().any(|&x| x > 0);
        let neg = e.iter().any(|&x| x < 0);
        (i64::from(pos && !neg) - i64::from(neg && !pos), 3)
    } else {
        pr.hit(Bin::BsDecideRare);
        (det_sign(e, p.map(|(_, _, w)| w)), 6)
    };
    let covered = sign != 0
        && e.iter().enumerate().all(|(k, &ek)| {
            if ek == 0 {
                let (i, j) = ((k + 1) % 3, (k + 2) % 3);
                let inside = fill_rule(p, i, j, sign);
                if Pr::ON {
                    pr.hit(tie_bin(p, i, j, inside));
                }
                inside
            } else {
                (ek > 0) == (sign > 0)
            }
        });
    (sign, covered, n)
}

/// Edges, orientation, coverage and depth (steps 5–8) from the rounded offsets `ab` of the
/// three vertices; `wpos` says whether every step-1 w is > 0, and `wz` gives the step-1 (w, z)
/// of each vertex (called only on the rare path and on hits, so that w and z need not stay
/// live through the common miss).
// |E'| < 2^61 (|a'|, |b'| < 2^30, 32 × 32 → 64 products).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects)]
fn finish<const MOTION: bool, const DEFOCUS: bool, Pr: Probe>(
    ab: [(i32, i32); 3],
    wpos: bool,
    wz: impl Fn() -> [(i32, i32); 3],
    ops: &mut Ops,
    pr: &mut Pr,
) -> BoundedEval {
    let [(a0, b0), (a1, b1), (a2, b2)] = ab;
    let m = |x: i32, y: i32| i64::from(x) * i64::from(y);
    let e = [
        m(a1, b2) - m(a2, b1),
        m(a2, b0) - m(a0, b2),
        m(a0, b1) - m(a1, b0),
    ];
    let mut n = class_ops(MOTION, DEFOCUS);
    let [e0, e1, e2] = e;
    pr.sign(e0, EDGE);
    pr.sign(e1, EDGE);
    pr.sign(e2, EDGE);
    // Fast path (every w > 0, no E' = 0): the sign bit of `e0 | e1 | e2` is set iff some E' < 0,
    // that of `e0 & e1 & e2` iff every E' < 0. Covered iff all E' share one strict sign, which
    // is then the orientation (module table step 6). Anything else goes to `decide_slow`.
    let (sign, covered) = if wpos && e0 != 0 && e1 != 0 && e2 != 0 {
        n += 3;
        pr.hit(Bin::BsDecideFast);
        if e0 & e1 & e2 < 0 {
            (-1, true)
        } else if e0 | e1 | e2 >= 0 {
            (1, true)
        } else {
            (0, false)
        }
    } else {
        let [(w0, _), (w1, _), (w2, _)] = wz();
        let v = [(a0, b0, w0), (a1, b1, w1), (a2, b2, w2)];
        let (sign, covered, k) = if Pr::ON {
            decide_slow_p(e, v, pr)
        } else {
            decide_slow(e, v)
        };
        n += k;
        (sign, covered)
    };
    pr.sign(
        sign,
        [Bin::BsOrientNeg, Bin::BsOrientZero, Bin::BsOrientPos],
    );
    pr.pick(covered, Bin::BsCovered, Bin::BsMissed);
    let hit = covered.then(|| {
        n += 12;
        Hit {
            depth: depth(&e, &wz(), sign, pr),
        }
    });
    ops.add_sample(n);
    BoundedEval {
        ab: ab.map(|(a, b)| (i64::from(a), i64::from(b))),
        e,
        det_sign: sign,
        hit,
    }
}

/// The bounded sample test of one class on the fast datapath (`MOTION`, `DEFOCUS` fixed at
/// compile time; dispatched once per call from the setup's class by [`eval`]); the
/// general datapath for the inputs [`Fast::new`] refuses. `xs`, `ys` inside the viewport and
/// `shift` ∈ 20..=32 (checked by the caller).
#[inline(always)]
fn eval_fast<const MOTION: bool, const DEFOCUS: bool, const G20: bool>(
    setup: &Setup,
    shift: u32,
    xs: i32,
    ys: i32,
    s: &Sample,
    ops: &mut Ops,
    pr: &mut impl Probe,
) -> BoundedEval {
    let Some(f) = Fast::new::<MOTION, DEFOCUS, G20>(setup.viewport, xs, ys, s, shift) else {
        pr.hit(Bin::BsPathGeneral);
        return eval_general_at::<MOTION, DEFOCUS>(setup, shift, xs, ys, s, ops, pr);
    };
    pr.hit(Bin::BsPathFast);
    let [v0, v1] = &setup.tri.v;
    // The shutter end nearer to T is the base of every lerp (`fast_vertex`).
    let [b0, b1, b2] = if MOTION && f.late { v1 } else { v0 };
    let [d0, d1, d2] = &setup.dv;
    let (a0, bb0, w0) = fast_vertex::<MOTION, DEFOCUS>(b0, d0, &f, pr);
    let (a1, bb1, w1) = fast_vertex::<MOTION, DEFOCUS>(b1, d1, &f, pr);
    let (a2, bb2, w2) = fast_vertex::<MOTION, DEFOCUS>(b2, d2, &f, pr);
    let wpos = w0 > 0 && w1 > 0 && w2 > 0;
    // Motion classes recompute w and z out of line; the others only load them.
    let wz = || {
        if MOTION {
            fast_wz::<MOTION>(setup, f.tq, f.late)
        } else {
            [b0, b1, b2].map(|v| (v[W], v[Z]))
        }
    };
    finish::<MOTION, DEFOCUS, _>([(a0, bb0), (a1, bb1), (a2, bb2)], wpos, wz, ops, pr)
}

/// The step-1 (w, z) of every vertex on the fast datapath, as in [`fast_vertex`] (|f1 − f0| ≤
/// 2^30, results |.| ≤ 2^29). Out of line: the rare path and hits recompute them here rather
/// than keep them live (in registers or spilled) through every sample test.
#[inline(never)]
#[allow(clippy::arithmetic_side_effects)]
fn fast_wz<const MOTION: bool>(setup: &Setup, tq: i32, late: bool) -> [(i32, i32); 3] {
    let [v0, v1] = &setup.tri.v;
    let b = if MOTION && late { v1 } else { v0 };
    // |d| ≤ 2^30 (`Setup::dv`).
    let at = |f0: i32, d: i32| {
        if MOTION {
            mla_hi(tq, d, f0)
        } else {
            f0
        }
    };
    let [b0, b1, b2] = b;
    let [d0, d1, d2] = &setup.dv;
    [
        (at(b0[W], d0[W]), at(b0[Z], d0[Z])),
        (at(b1[W], d1[W]), at(b1[Z], d1[Z])),
        (at(b2[W], d2[W]), at(b2[Z], d2[Z])),
    ]
}

/// The bounded sample test of one class on the general datapath (the inputs [`Fast::new`]
/// refuses: T = 2^15, U or V = 2^16, a 2048-pixel viewport side at S = 20).
#[inline(always)]
fn eval_general<const MOTION: bool, const DEFOCUS: bool>(
    setup: &Setup,
    c: &Ctx,
    ops: &mut Ops,
    pr: &mut impl Probe,
) -> BoundedEval {
    let [v0, v1] = &setup.tri.v;
    let [q0, q1, q2] = v0;
    let [r0, r1, r2] = v1;
    let (a0, b0, w0) = vertex::<MOTION, DEFOCUS>(q0, r0, c, pr);
    let (a1, b1, w1) = vertex::<MOTION, DEFOCUS>(q1, r1, c, pr);
    let (a2, b2, w2) = vertex::<MOTION, DEFOCUS>(q2, r2, c, pr);
    let z = |q: &[i32; 5], r: &[i32; 5]| if MOTION { lerp(q[Z], r[Z], c.t) } else { q[Z] };
    let wz = || [(w0, z(q0, r0)), (w1, z(q1, r1)), (w2, z(q2, r2))];
    let wpos = w0 > 0 && w1 > 0 && w2 > 0;
    finish::<MOTION, DEFOCUS, _>([(a0, b0), (a1, b1), (a2, b2)], wpos, wz, ops, pr)
}

/// [`eval_general`] of one class: out of line, it serves only rare inputs. `xs`, `ys`
/// inside the viewport, `shift` ∈ 20..=32 (checked by [`eval`]).
// 256W, 256H ≤ 2^19 and xs < 256W, ys < 256H: every `Ctx` value in its range.
#[cold]
#[inline(never)]
#[allow(clippy::arithmetic_side_effects)]
fn eval_general_at<const MOTION: bool, const DEFOCUS: bool>(
    setup: &Setup,
    shift: u32,
    xs: i32,
    ys: i32,
    s: &Sample,
    ops: &mut Ops,
    pr: &mut impl Probe,
) -> BoundedEval {
    let vp = setup.viewport;
    let sw = SUBPIXEL_SCALE * i32::from(vp.w);
    let sh = SUBPIXEL_SCALE * i32::from(vp.h);
    let c = Ctx {
        t: s.t().to_bits(),
        u: s.u().to_bits(),
        v: s.v().to_bits(),
        sw,
        sh,
        ngx: sw - 2 * xs,
        ngy: 2 * ys - sh,
        // 2^31 >> (32 − S) = 2^(S−1) (a right shift of a constant; 32 − S ∈ 0..=12).
        half: (1i64 << 31) >> (OFFSET_SHIFT_MAX - shift),
        fine: shift - OFFSET_SHIFT_MIN,
    };
    eval_general::<MOTION, DEFOCUS>(setup, &c, ops, pr)
}

/// The bounded sample test with its intermediates, offsets on the grid `2^shift`. Counts its
/// arithmetic in `ops.sample`. `None` for a position outside the viewport (module docs) or a
/// `shift` outside [`OFFSET_SHIFT_MIN`]..=[`OFFSET_SHIFT_MAX`] (the range the proofs cover).
// 256W, 256H ≤ 2^19 and xs < 256W, ys < 256H (checked): every `Ctx` value in its range.
#[inline]
#[allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_wrap,
    clippy::cast_sign_loss
)]
pub fn eval(
    setup: &Setup,
    shift: u32,
    pos: ScreenPos,
    s: &Sample,
    ops: &mut Ops,
) -> Option<BoundedEval> {
    eval_probed(setup, shift, pos, s, ops, &mut NoProbe)
}

/// [`eval`], every decision path it takes reported to `pr` (`crate::coverage`).
#[inline]
pub fn eval_probed(
    setup: &Setup,
    shift: u32,
    pos: ScreenPos,
    s: &Sample,
    ops: &mut Ops,
    pr: &mut impl Probe,
) -> Option<BoundedEval> {
    if !(OFFSET_SHIFT_MIN..=OFFSET_SHIFT_MAX).contains(&shift) {
        return None;
    }
    eval_at::<Full>(setup, shift, pos, s, ops, pr)
}

/// [`eval`] for a `shift` ∈ [`OFFSET_SHIFT_MIN`]..=[`OFFSET_SHIFT_MAX`] (the caller's
/// obligation): the position check and the dispatch by class and grid.
// 256W, 256H ≤ 2^19 and xs < 256W, ys < 256H (checked): every value in its range.
#[inline(always)]
#[allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_wrap,
    clippy::cast_sign_loss
)]
fn eval_at<U: Unit>(
    setup: &Setup,
    shift: u32,
    pos: ScreenPos,
    s: &Sample,
    ops: &mut Ops,
    pr: &mut impl Probe,
) -> Option<BoundedEval> {
    let vp = setup.viewport;
    let sw = SUBPIXEL_SCALE * i32::from(vp.w);
    let sh = SUBPIXEL_SCALE * i32::from(vp.h);
    // sw, sh ∈ [256, 2^19] (positive, exact in u32); xs, ys below them fit i32.
    if pos.xs >= sw as u32 || pos.ys >= sh as u32 {
        return None;
    }
    let (xs, ys) = (pos.xs as i32, pos.ys as i32);
    // Unit `U` instantiates only the classes it accepts: `U::MOTION && class.motion()` is the
    // class's own flag for an accepted class and a constant `false` where `U` lacks the effect.
    if !U::accepts(setup.class) {
        return None;
    }
    let m = U::MOTION && setup.class.motion();
    let d = U::DEFOCUS && setup.class.defocus();
    pr.hit(match (m, d) {
        (false, false) => Bin::BsClassStatic,
        (true, false) => Bin::BsClassMotion,
        (false, true) => Bin::BsClassDefocus,
        (true, true) => Bin::BsClassBoth,
    });
    // The default grid 2^20 gets its own copy with the scaling constants folded in.
    Some(match (m, d, shift == OFFSET_SHIFT_MIN) {
        (false, false, true) => eval_fast::<false, false, true>(setup, shift, xs, ys, s, ops, pr),
        (true, false, true) => eval_fast::<true, false, true>(setup, shift, xs, ys, s, ops, pr),
        (false, true, true) => eval_fast::<false, true, true>(setup, shift, xs, ys, s, ops, pr),
        (true, true, true) => eval_fast::<true, true, true>(setup, shift, xs, ys, s, ops, pr),
        (false, false, false) => eval_fast::<false, false, false>(setup, shift, xs, ys, s, ops, pr),
        (true, false, false) => eval_fast::<true, false, false>(setup, shift, xs, ys, s, ops, pr),
        (false, true, false) => eval_fast::<false, true, false>(setup, shift, xs, ys, s, ops, pr),
        (true, true, false) => eval_fast::<true, true, false>(setup, shift, xs, ys, s, ops, pr),
    })
}

/// The bounded sample test of precision `P` on unit `U`, for a setup of precision `P`: the depth
/// on a hit. The grid is `P`'s constant `2^S` (so one grid's copy is compiled; an exact `P` is
/// evaluated at the finest grid, [`OFFSET_SHIFT_MIN`]) and only the classes `U` accepts are
/// instantiated; `None` (not covered) for a class `U` does not accept. `P`'s shift is in range
/// by construction (a sealed precision whose OFF is checked at compile time), so [`eval`]'s
/// range check is not repeated.
#[inline]
pub fn test<P: Precision, U: Unit>(
    setup: &Setup,
    pos: ScreenPos,
    s: &Sample,
    ops: &mut Ops,
) -> Option<Hit> {
    let shift = P::OFFSET_SHIFT.unwrap_or(OFFSET_SHIFT_MIN);
    eval_at::<U>(setup, shift, pos, s, ops, &mut NoProbe)?.hit
}
