//! Stage 3, bounded — a hardware-width sample test that rounds at declared points to declared
//! widths and then decides coverage exactly on the rounded values
//! (`shared/notes/bounded-datapath.md` §1–2). Selected by a [`crate::formats::Bounded`]
//! precision (`OFFSET_SHIFT = Some(S)`); the exact test in `sample.rs` stays the `Prec` path.
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
//! | 6 orientation | all `w_k > 0`: the common sign of the `E'_k`, no product; else `sign(Σ E'_k·w_k)` | none | **rare path** 64 × 32 → i128, \|Σ\| < 2^92 |
//! | 7 fill rule (`E'_k = 0`) | tie key `κ = cmp((b', a', w)_{k+1}, (b', a', w)_{k+2})` (lexicographic, −1/0/1); the sample is inside edge k iff `s·κ > 0` | none | comparators only, no multiplier |
//! | 8 depth | `E'' = floor(E'/2^sh)` with \|E''\| < 2^24 (`sh` = bit length of max\|E'\| − 24, ≥ 0), `num = Σ E''·z`, `den = Σ E''·w` | floor | 25 × 30 → i64 sums < 2^55; quotient `floor(num·2^24/den)` saturated to the depth range: a 79-by-56-bit divide (i128) |
//!
//! `w` and `z` here are the step-1 values (exact for static and defocus-only triangles).
//!
//! **What the test decides.** With `x' = (a'·2^S + (2xs − 256W)·w)/(256W)` and `y'` likewise,
//! `E'` and `det' = Σ E'_k·w_k` are positive multiples of the exact test's `E_k` and `det` for
//! the triangle `P'_k = (x'_k, y'_k, w_k)` (the translation by the sample and the common scale
//! cancel: note §1), so off the edges (every `E'_k ≠ 0`) coverage is **exactly** the exact
//! test's on `P'`. A sample exactly on a rounded edge (`E'_k = 0`) is decided by a tie key that
//! needs no multiplier (step 7) instead of `sample.rs`'s edge-normal rule, which would cost four
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
//!   take the integer ceilings of these as the conservative epsilon (`setup.rs`, `bounds.rs`).
//!
//! A sample position outside the viewport (`xs ≥ 256W` or `ys ≥ 256H`) is never covered: the
//! range proofs above assume `|2xs − 256W| ≤ 256W`, and a renderer never asks.

use crate::formats::{
    DEPTH_FAR, DEPTH_FRAC, DEPTH_NEAR, OFFSET_SHIFT_MAX, OFFSET_SHIFT_MIN, SUBPIXEL_BITS, TUV_FRAC,
};
use crate::input::{Sample, Viewport, C, W, X, Y, Z};
use crate::sample::{Hit, ScreenPos};
use crate::setup::{Class, Setup};
use crate::stats::Ops;

/// 2^16: one t/u/v step (a multiplication by this constant, not a shift).
const TUV_SCALE: i64 = 1 << TUV_FRAC;
/// 2^8: one pixel in sample-position units.
const SUBPIXEL_SCALE: i64 = 1 << SUBPIXEL_BITS;
/// 2^24: the depth quotient's scale.
const DEPTH_SCALE: i128 = 1 << DEPTH_FRAC;

/// The conservative epsilon of a setup: how far the bounded test's rounding can move a vertex,
/// in raw clip units (2^-16), rounded up to integers. All zero for the exact test, so every
/// bound is then bit-identical to the exact configuration's.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Eps {
    pub(crate) x: [i32; 2],
    pub(crate) w: i32,
}

impl Eps {
    /// Perturbation bound of x (`[0]`) and y (`[1]`), raw clip units.
    pub fn x(&self) -> [i32; 2] {
        self.x
    }
    /// Perturbation bound of w, raw clip units.
    pub fn w(&self) -> i32 {
        self.w
    }
    /// The epsilon of the bounded test with offset grid `2^shift` for a triangle of `class` in
    /// `vp` (module docs): `ceil(k/2 + 2^(shift−1)/(256·E))` per axis, `ceil(1/2)` for w of a
    /// moving triangle. `shift = None` (exact test): zero.
    pub fn of(shift: Option<u32>, class: Class, vp: Viewport) -> Eps {
        let Some(s) = shift else {
            return Eps::default();
        };
        let k: i64 = match class {
            Class::Static => 0,
            Class::Motion | Class::Defocus => 1,
            Class::MotionDefocus => 3,
        };
        // ceil((k·256E + 2^s) / (512E)): 2^s ≤ 2^32 (OFFSET_SHIFT_MAX), 256E ≤ 2^19, k ≤ 3;
        // every term < 2^34. `checked_pow` and `checked_*` make any surprise a huge epsilon
        // (conservative), never a panic; E ≥ 1 so the divisor is positive.
        let axis = |e: u16| {
            let e = i64::from(e);
            let num = 2i64
                .checked_pow(s)
                .and_then(|p| p.checked_add(k.checked_mul(SUBPIXEL_SCALE)?.checked_mul(e)?));
            let den = 2i64.saturating_mul(SUBPIXEL_SCALE).saturating_mul(e);
            num.and_then(|n| crate::formats::ceil_div(i128::from(n), i128::from(den)))
                .and_then(|q| i32::try_from(q).ok())
                .unwrap_or(1 << 24)
        };
        Eps {
            x: [axis(vp.w), axis(vp.h)],
            w: i32::from(class.motion()),
        }
    }
    /// Whether every term is zero (the exact test).
    pub fn is_zero(&self) -> bool {
        self.x == [0, 0] && self.w == 0
    }
}

/// `round(v / 2^16)`, to nearest with ties toward +∞: `floor((v + 2^15) / 2^16)`.
/// Callers pass |v| ≤ 2^45 (module table), so the sum cannot overflow and the result is ≤ 2^29.
#[inline]
#[allow(clippy::arithmetic_side_effects)]
fn rnd16(v: i64) -> i64 {
    // floor((v + 2^15) / 2^16) as an arithmetic right shift by the constant 16 (exact floor).
    (v + TUV_SCALE / 2).checked_shr(TUV_FRAC).unwrap_or(0)
}

/// Vertex positions `(x, y, w, z)` at the sample's (t, u, v), each on the raw 2^-16 grid
/// (steps 1–2 of the module table). Ranges: |x|, |y| ≤ 2^30, |w|, |z| ≤ 2^29.
// Checked triangle: every field |f| ≤ 2^29, |f1 − f0| ≤ 2^30; |T| ≤ 2^16, |U|, |V| ≤ 2^16:
// f0·2^16 + T·(f1 − f0) = (2^16 − T)·f0 + T·f1, ≤ 2^45; U·c_t ≤ 2^45. All in i64.
#[allow(clippy::arithmetic_side_effects)]
fn positions(setup: &Setup, s: &Sample, ops: &mut Ops) -> [[i64; 4]; 3] {
    let [v0, v1] = &setup.tri.v;
    let t = i64::from(s.t().to_bits());
    let (u, v) = (i64::from(s.u().to_bits()), i64::from(s.v().to_bits()));
    let motion = setup.class.motion();
    let defocus = setup.class.defocus();
    let mut out = [[0i64; 4]; 3];
    for ((q, r), o) in v0.iter().zip(v1.iter()).zip(out.iter_mut()) {
        let mut f = q.map(i64::from);
        if motion {
            for (fi, &ri) in f.iter_mut().zip(r.iter()) {
                *fi = rnd16(*fi * TUV_SCALE + t * (i64::from(ri) - *fi));
            }
            ops.add_sample(15);
        }
        if defocus {
            f[X] += rnd16(u * f[C]);
            f[Y] += rnd16(v * f[C]);
            ops.add_sample(6);
        }
        *o = [f[X], f[Y], f[W], f[Z]];
    }
    out
}

/// `round(v / 2^s)`, to nearest with ties toward +∞, for the offset grid (step 4): `half` is
/// 2^(s−1); the arithmetic right shift by `s` is the floor division by 2^s (a right shift
/// cannot overflow; `s` ≤ 32 < 64, so `checked_shr` never returns `None`, and if it did the
/// result would be 0, not a panic). |v| < 1.5·2^49, half ≤ 2^31: the sum cannot overflow;
/// |result| < 2^30 for s ≥ 20. (A shift rather than a division: no 64-bit divide on the M4.)
#[inline]
#[allow(clippy::arithmetic_side_effects)]
fn rnd_grid(v: i64, half: i64, s: u32) -> i64 {
    (v + half).checked_shr(s).unwrap_or(0)
}

/// Fill-rule decision on `E'_k = 0` (step 7), for edge k with vertices `i = k+1`, `j = k+2`:
/// inside iff `s·κ > 0` with the antisymmetric tie key `κ = cmp((b'_i, a'_i, w_i), (b'_j, a'_j,
/// w_j))` (lexicographic). Comparators only; see the module docs for why it is watertight.
#[inline]
fn fill_rule(ab: &[(i64, i64); 3], w: &[i64; 3], i: usize, j: usize, s: i64) -> bool {
    let (Some(&(ai, bi)), Some(&(aj, bj)), Some(&wi), Some(&wj)) =
        (ab.get(i), ab.get(j), w.get(i), w.get(j))
    else {
        return false;
    };
    match (bi, ai, wi).cmp(&(bj, aj, wj)) {
        core::cmp::Ordering::Greater => s > 0,
        core::cmp::Ordering::Less => s < 0,
        core::cmp::Ordering::Equal => false,
    }
}

/// Depth z/w from the rounded edge values (step 8; rounding as in `sample.rs`: floor).
// After the shift |e''| < 2^24, |w|, |z| ≤ 2^29: products < 2^53, sums of three < 2^55 (i64);
// num·2^24 < 2^79 and den > 0 at the division (i128).
#[allow(clippy::arithmetic_side_effects)]
fn depth(e: &[i64; 3], wz: &[(i64, i64); 3], sign: i64) -> i32 {
    let big = e.iter().map(|x| x.unsigned_abs()).max().unwrap_or(0);
    let len = u64::BITS - big.leading_zeros();
    // Floor shift by sh ≤ 37 (|E'| < 2^61): an arithmetic right shift, exact floor, cannot fail.
    let sh = len.saturating_sub(24);
    let (mut num, mut den) = (0i64, 0i64);
    for (ek, &(w, z)) in e.iter().zip(wz.iter()) {
        let ek = ek.checked_shr(sh).unwrap_or(0);
        num += ek * z;
        den += ek * w;
    }
    let (num, den) = (i128::from(num * sign), i128::from(den * sign));
    // den > 0 (checked by floor_div) and the quotient's floor; through a 64-bit divide when the
    // scaled numerator fits (`floor_div`), else the 128-bit one.
    let Some(q) = crate::formats::floor_div(num * DEPTH_SCALE, den) else {
        return DEPTH_FAR;
    };
    let clamped = q.clamp(i128::from(DEPTH_NEAR), i128::from(DEPTH_FAR));
    i32::try_from(clamped).unwrap_or(DEPTH_FAR)
}

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

/// The bounded sample test with its intermediates, offsets on the grid `2^shift`. Counts its
/// arithmetic in `ops.sample`. `None` for a position outside the viewport (module docs) or a
/// `shift` outside [`OFFSET_SHIFT_MIN`]..=[`OFFSET_SHIFT_MAX`] (the range the proofs cover).
// Ranges in the module table: |x| ≤ 2^30, |w| ≤ 2^29, 256W ≤ 2^19 and |2xs − 256W| ≤ 256W
// (checked below), so |A| < 1.5·2^49; |a'| < 2^30 (grid ≥ 2^20); |E'| < 2^61; the rare-path
// Σ E'·w < 2^92.
#[allow(clippy::arithmetic_side_effects)]
pub fn bounded_eval(
    setup: &Setup,
    shift: u32,
    pos: ScreenPos,
    s: &Sample,
    ops: &mut Ops,
) -> Option<BoundedEval> {
    if !(OFFSET_SHIFT_MIN..=OFFSET_SHIFT_MAX).contains(&shift) {
        return None;
    }
    let half = 2i64.checked_pow(shift.checked_sub(1)?)?;
    let vp = setup.viewport;
    let (sw, sh) = (
        SUBPIXEL_SCALE * i64::from(vp.w),
        SUBPIXEL_SCALE * i64::from(vp.h),
    );
    let (xs, ys) = (i64::from(pos.xs), i64::from(pos.ys));
    if xs >= sw || ys >= sh {
        return None;
    }
    let (gx, gy) = (2 * xs - sw, sh - 2 * ys);
    let p = positions(setup, s, ops);
    let ab = p.map(|[x, y, w, _]| {
        (
            rnd_grid(sw * x - gx * w, half, shift),
            rnd_grid(sh * y - gy * w, half, shift),
        )
    });
    let w = p.map(|q| q[2]);
    let [(a0, b0), (a1, b1), (a2, b2)] = ab;
    let e = [a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0];
    ops.add_sample(2 + 3 * 8 + 9);
    let sign = if w.iter().all(|&wk| wk > 0) {
        let pos_ = e.iter().any(|&x| x > 0);
        let neg = e.iter().any(|&x| x < 0);
        ops.add_sample(3);
        match (pos_, neg) {
            (true, false) => 1,
            (false, true) => -1,
            _ => 0,
        }
    } else {
        let det: i128 = e
            .iter()
            .zip(w.iter())
            .map(|(&ek, &wk)| i128::from(ek) * i128::from(wk))
            .sum();
        ops.add_sample(6);
        i64::from(det > 0) - i64::from(det < 0)
    };
    let covered = sign != 0
        && e.iter()
            .enumerate()
            .all(|(k, &ek)| match (ek * sign).signum() {
                1 => true,
                0 => fill_rule(&ab, &w, (k + 1) % 3, (k + 2) % 3, sign),
                _ => false,
            });
    let hit = covered.then(|| {
        ops.add_sample(12);
        Hit {
            depth: depth(&e, &p.map(|q| (q[2], q[3])), sign),
        }
    });
    Some(BoundedEval {
        ab,
        e,
        det_sign: sign,
        hit,
    })
}

/// The bounded sample test: the depth on a hit (`S` = the setup's offset shift; a setup of the
/// exact test is evaluated at the finest grid, [`OFFSET_SHIFT_MIN`]).
pub fn bounded_test(setup: &Setup, pos: ScreenPos, s: &Sample, ops: &mut Ops) -> Option<Hit> {
    let shift = setup.prec.offset_shift().unwrap_or(OFFSET_SHIFT_MIN);
    bounded_eval(setup, shift, pos, s, ops)?.hit
}
