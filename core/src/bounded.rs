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

use crate::formats::Precision;
use crate::formats::{
    DEPTH_FAR, DEPTH_FRAC, DEPTH_NEAR, OFFSET_SHIFT_MAX, OFFSET_SHIFT_MIN, SUBPIXEL_BITS, TUV_FRAC,
};
use crate::input::{Sample, Viewport, C, W, X, Y, Z};
use crate::sample::{Hit, ScreenPos};
use crate::setup::{Class, Setup};
use crate::stats::Ops;
use crate::unit::{Full, Unit};

/// 2^16: one t/u/v step.
const TUV_SCALE: i64 = 1 << TUV_FRAC;
/// 2^8: one pixel in sample-position units.
const SUBPIXEL_SCALE: i32 = 1 << SUBPIXEL_BITS;
/// 2^24: the depth quotient's scale.
const DEPTH_SCALE: i64 = 1 << DEPTH_FRAC;
/// 2^(31 − DEPTH_FRAC) = 2^7: the quotient saturates where num ≥ 2^7·den (a constant shift,
/// checked by the compiler).
const DEPTH_SAT_SCALE: i64 = 1 << (31 - DEPTH_FRAC);

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
            let num = 2i64.checked_pow(s).and_then(|p| {
                p.checked_add(k.checked_mul(i64::from(SUBPIXEL_SCALE))?.checked_mul(e)?)
            });
            let den = 2i64
                .saturating_mul(i64::from(SUBPIXEL_SCALE))
                .saturating_mul(e);
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

/// Per-sample constants of the general datapath ([`eval_general`], the inputs [`Fast::new`]
/// refuses). Ranges (checked `Sample`, `Viewport`, the position check in [`bounded_eval`]): `t` ∈
/// [0, 2^16], `u`, `v` ∈ [−2^16, 2^16]; `sw = 256W`, `sh = 256H` ≤ 2^19; `ngx = sw − 2xs` ∈
/// (−sw, sw], `ngy = 2ys − sh` ∈ [−sh, sh) (so |ngx|, |ngy| ≤ 2^19); `half = 2^(S−1)` ≤ 2^31;
/// `fine = S − 20` ∈ 0..=12.
struct Ctx {
    t: i32,
    u: i32,
    v: i32,
    sw: i32,
    sh: i32,
    ngx: i32,
    ngy: i32,
    half: i64,
    fine: u32,
}

/// `f0 + round(T·(f1 − f0) / 2^16)` (nearest, ties toward +∞): the step-1 lerp. It equals
/// `rnd16(f0·2^16 + T·(f1 − f0))` of the module table because `f0·2^16` is a multiple of 2^16.
/// Ranges: |f0|, |f1| ≤ 2^29 so |f1 − f0| ≤ 2^30 (i32); T ∈ [0, 2^16], the product ≤ 2^46 (one
/// 32 × 32 → 64 multiply, SMULL); the result is the rounded convex combination
/// `((2^16 − T)·f0 + T·f1)/2^16`, |.| ≤ 2^29, so the narrowing to i32 is exact
/// (`bounded_corners.rs` drives f0 = ±2^29, f1 = ∓2^29, T = 2^16).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]
pub(crate) fn lerp(f0: i32, f1: i32, t: i32) -> i32 {
    // (p + 2^15) >> 16 on i64: an arithmetic shift by a constant, the exact floor.
    f0 + ((i64::from(t) * i64::from(f1 - f0) + TUV_SCALE / 2) >> TUV_FRAC) as i32
}

/// `round(L·c / 2^16)` (nearest, ties toward +∞), the step-2 lens offset: |L| ≤ 2^16, |c| ≤ 2^29,
/// |L·c| ≤ 2^45 (SMULL), result |.| ≤ 2^29 (exact in i32).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]
fn lens(l: i32, c: i32) -> i32 {
    ((i64::from(l) * i64::from(c) + TUV_SCALE / 2) >> TUV_FRAC) as i32
}

/// `round((e·p + ng·w) / 2^S)` (nearest, ties toward +∞): steps 3–4 for one axis, `e` = 256W
/// (or 256H), `ng` = −g. |e·p| ≤ 2^19·2^30, |ng·w| ≤ 2^19·2^29, so with `half` ≤ 2^31 the sum
/// is < 1.5·2^49 + 2^31 (i64; one SMULL and one SMLAL). The floor division by 2^S is done as
/// `>> 20` on i64 (|.| < 1.5·2^29 + 1 < 2^31 afterwards: the narrowing to i32 is exact) and then
/// `>> (S − 20)` on i32 — nested floors by powers of two compose to the floor by 2^S exactly.
/// Result |a'| < 2^(50−S) ≤ 2^30.
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]
fn offset(e: i32, p: i32, ng: i32, w: i32, c: &Ctx) -> i32 {
    let acc = i64::from(e) * i64::from(p) + i64::from(ng) * i64::from(w) + c.half;
    // `fine` ≤ 12 < 32 (Ctx): the i32 shift cannot overflow.
    ((acc >> OFFSET_SHIFT_MIN) as i32) >> c.fine
}

/// One vertex at the sample on the general datapath: `(a', b', w)` (z is lerped on hits only,
/// [`depth`]). Steps 1–4; `MOTION` and `DEFOCUS` select the rounded lerp and the lens offset at
/// compile time (no per-vertex class branch).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects)]
fn vertex<const MOTION: bool, const DEFOCUS: bool>(
    q: &[i32; 5],
    r: &[i32; 5],
    c: &Ctx,
) -> (i32, i32, i32) {
    let (mut x, mut y, w) = if MOTION {
        (
            lerp(q[X], r[X], c.t),
            lerp(q[Y], r[Y], c.t),
            lerp(q[W], r[W], c.t),
        )
    } else {
        (q[X], q[Y], q[W])
    };
    if DEFOCUS {
        let coc = if MOTION { lerp(q[C], r[C], c.t) } else { q[C] };
        // |x_t|, |lens| ≤ 2^29: |x| ≤ 2^30 (i32).
        x += lens(c.u, coc);
        y += lens(c.v, coc);
    }
    (
        offset(c.sw, x, c.ngx, w, c),
        offset(c.sh, y, c.ngy, w, c),
        w,
    )
}

/// `acc + floor((m·n + 2^31) / 2^32)`: the high word of a rounded 32 × 32 → 64 product, added
/// to `acc` — one SMMLAR on the Cortex-M4. |m·n| < 2^62 for every caller (i64, no overflow);
/// the caller proves that the sum fits i32.
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]
pub(crate) fn mla_hi(m: i32, n: i32, acc: i32) -> i32 {
    // |m·n| ≤ 2^62 < 2^63 − 2^31; the shift by the constant 32 is the exact floor, and the
    // quotient is < 2^31 in magnitude (each caller's range), so the narrowing is exact.
    acc + ((i64::from(m) * i64::from(n) + (1 << 31)) >> 32) as i32
}

/// Per-sample constants of the fast datapath: every rounding of steps 1–4 becomes the rounded
/// high word of a 64-bit sum of 32 × 32 products (SMMLAR / SMULL + SMLAL on the M4), by
/// scaling one factor so that the rounding point lands at 2^32. Identical results (proofs on
/// [`fast_vertex`]); [`Fast::new`] refuses the few inputs whose scaled factors do not fit i32,
/// which go to the general datapath ([`eval_general`]).
///
/// - `tq = ±min(T, 2^16 − T)·2^16`, |tq| < 2^31 (T ≠ 2^15): `+T·2^16` for T < 2^15, and
///   `−(2^16 − T)·2^16` with `late = T > 2^15`.
/// - `uq = U·2^15`, `vq = V·2^15` ∈ [−2^31, 2^31) (U, V ≠ 2^16).
/// - `swq = 256W·2^(32−S)`, `shq`, `ngxq = ngx·2^(32−S)`, `ngyq` (|.| < 2^31, checked).
struct Fast {
    tq: i32,
    late: bool,
    uq: i32,
    vq: i32,
    swq: i32,
    shq: i32,
    ngxq: i32,
    ngyq: i32,
}

impl Fast {
    /// The fast constants of a sample for a triangle of class (`MOTION`, `DEFOCUS`), or `None`
    /// when a scaled factor would not fit i32: T = 2^15 (motion classes), U or V = 2^16
    /// (defocus classes), or `max(W, H) ≥ 2^(S−9)` (at S = 20: a 2048-pixel side). `xs`, `ys`
    /// inside the viewport and `shift` ∈ 20..=32 (checked by the caller). Fields a class does
    /// not use are 0.
    #[inline(always)]
    #[allow(clippy::arithmetic_side_effects)]
    fn new<const MOTION: bool, const DEFOCUS: bool, const G20: bool>(
        vp: Viewport,
        xs: i32,
        ys: i32,
        s: &Sample,
        shift: u32,
    ) -> Option<Fast> {
        const HALF: i32 = 1 << (TUV_FRAC - 1);
        const ONE: i32 = 1 << TUV_FRAC;
        let t = if MOTION { s.t().to_bits() } else { 0 };
        let (u, v) = if DEFOCUS {
            (s.u().to_bits(), s.v().to_bits())
        } else {
            (0, 0)
        };
        // `G20`: the default grid 2^20, with the constants below folded.
        let shift = if G20 { OFFSET_SHIFT_MIN } else { shift };
        // `shift` − 9 ∈ 11..=23: the right shift of a constant is 2^(S−9) ≥ 2048, a power of
        // two, so max(W, H) < 2^(S−9) iff W | H < 2^(S−9).
        let side = (1u32 << 23) >> (OFFSET_SHIFT_MAX - shift);
        if t == HALF || u == ONE || v == ONE || u32::from(vp.w | vp.h) >= side {
            return None;
        }
        let late = t > HALF;
        // T ∈ [0, 2^16] \ {2^15}: the smaller of T, 2^16 − T is < 2^15, so `tq` < 2^31; U, V ∈
        // [−2^16, 2^16): U·2^15 ∈ [−2^31, 2^31). Multiplications by the constants 2^16, 2^15.
        // Negated for T > 2^15: −(2^16 − T)·2^16 > −2^31 (i32).
        let tq = if late { t - ONE } else { t } * ONE;
        // 2^(32−S) ∈ [1, 2^12] (a right shift of a constant). 256·max(W, H) < 2^(S−1), so
        // 256W·2^(32−S) < 2^31, and |ngx| ≤ 256W, |ngy| ≤ 256H: all four products fit i32.
        let k = (1i32 << 12) >> (shift - OFFSET_SHIFT_MIN);
        let (sw, sh) = (
            SUBPIXEL_SCALE * i32::from(vp.w),
            SUBPIXEL_SCALE * i32::from(vp.h),
        );
        Some(Fast {
            tq,
            late,
            uq: u * HALF,
            vq: v * HALF,
            swq: sw * k,
            shq: sh * k,
            ngxq: (sw - 2 * xs) * k,
            ngyq: (2 * ys - sh) * k,
        })
    }
}

/// One vertex at the sample on the fast datapath: the same `(a', b', w)` as [`vertex`]. `b` is
/// the vertex at the shutter end nearer to T (`q` for `T < 2^15`, `r` for `T > 2^15`; `q` for
/// the classes without motion), `d` the setup's `r − q` of the same vertex ([`Setup::dv`]).
///
/// - **Lerp** `f0 + rnd16(T·(f1 − f0))`: for T < 2^15 it is `mla_hi(T·2^16, d, f0)` with
///   `d = f1 − f0`, since `floor((T·2^16·d + 2^31)/2^32) = floor((T·d + 2^15)/2^16)` (numerator
///   and denominator scaled by 2^16). For T > 2^15, with T' = 2^16 − T and `tq = −T'·2^16`:
///   `mla_hi(tq, d, f1) = f1 + floor((T'·2^16·(f0 − f1) + 2^31)/2^32) = f1 + floor((T·d +
///   2^15)/2^16 − d) = f0 + floor((T·d + 2^15)/2^16)` (subtracting the integer d inside the
///   floor). |d| ≤ 2^30, |tq| < 2^31: |product| < 2^61; the result is the lerp, |.| ≤ 2^29.
/// - **Lens** `x + rnd16(U·c)` = `mla_hi(U·2^15, 2c, x)`: `U·2^15·2c = 2^16·U·c`, the same
///   scaling; |2c| ≤ 2^30, result |x| ≤ 2^30.
/// - **Offset** `floor((e·p + ng·w + 2^(S−1))/2^S)` = `floor((e·2^(32−S)·p + ng·2^(32−S)·w +
///   2^31)/2^32)` (scaled by 2^(32−S)); |swq·x| < 2^31·2^30, |ngxq·w| < 2^31·2^29: the sum
///   < 2^62 (i64), its high word the result |a'| < 2^30.
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]
fn fast_vertex<const MOTION: bool, const DEFOCUS: bool>(
    b: &[i32; 5],
    d: &[i32; 5],
    f: &Fast,
) -> (i32, i32, i32) {
    // |d| ≤ 2^30 (checked triangle, |f| ≤ 2^29; `Setup::dv`).
    let at = |f0: i32, d: i32| {
        if MOTION {
            mla_hi(f.tq, d, f0)
        } else {
            f0
        }
    };
    let (mut x, mut y, w) = (at(b[X], d[X]), at(b[Y], d[Y]), at(b[W], d[W]));
    if DEFOCUS {
        // |c_t| ≤ 2^29: 2c ≤ 2^30 (i32).
        let c2 = at(b[C], d[C]) * 2;
        x = mla_hi(f.uq, c2, x);
        y = mla_hi(f.vq, c2, y);
    }
    let hi = |e: i32, p: i32, ng: i32| {
        ((i64::from(e) * i64::from(p) + i64::from(ng) * i64::from(w) + (1 << 31)) >> 32) as i32
    };
    (hi(f.swq, x, f.ngxq), hi(f.shq, y, f.ngyq), w)
}

/// Fill-rule decision on `E'_k = 0` (step 7), for edge k with vertices `i = k+1`, `j = k+2`:
/// inside iff `s·κ > 0` with the antisymmetric tie key `κ = cmp((b'_i, a'_i, w_i), (b'_j, a'_j,
/// w_j))` (lexicographic). Comparators only; see the module docs for why it is watertight.
#[inline]
fn fill_rule(v: &[(i32, i32, i32); 3], i: usize, j: usize, s: i64) -> bool {
    let (Some(&(ai, bi, wi)), Some(&(aj, bj, wj))) = (v.get(i), v.get(j)) else {
        return false;
    };
    match (bi, ai, wi).cmp(&(bj, aj, wj)) {
        core::cmp::Ordering::Greater => s > 0,
        core::cmp::Ordering::Less => s < 0,
        core::cmp::Ordering::Equal => false,
    }
}

/// `floor(u / v)` for a normalized `v` ∈ [2^31, 2^32) and `u < 2^32·v` (so the quotient fits
/// u32): long division in two base-2^16 digits with 32-bit divides (Hacker's Delight `divlu`;
/// the Cortex-M's UDIV), no 64-bit division routine. Each digit estimate `q̂ = ⌊(2 digits)/vn1⌋`
/// is at most 2 too large (normalized divisor) and is corrected by at most two steps (the loop
/// stops at the first step whose test fails: q̂ and rhat are then unchanged, so it would fail
/// again). Ranges: `vn1` ∈ [2^15, 2^16) (no zero division); `q̂·vn0` is formed only when
/// `q̂ < 2^16` (< 2^32), `rhat·2^16 + un` only when `rhat < 2^16` (< 2^32); the partial
/// remainder `un21`'s true value is < v < 2^32, so forming it modulo 2^32 (wrapping) is exact.
#[inline]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]
pub(crate) fn div64_32(u: u64, v: u32) -> u32 {
    const B: u32 = 1 << 16;
    let (u1, u0) = ((u >> 32) as u32, u as u32);
    let (vn1, vn0) = (v >> 16, v & 0xffff);
    let digit = |hi: u32, lo: u32| {
        let mut q = hi / vn1;
        let mut rhat = hi - q * vn1;
        for _ in 0..2 {
            if q < B && q * vn0 <= rhat * B + lo {
                break;
            }
            q -= 1;
            rhat += vn1;
            if rhat >= B {
                break;
            }
        }
        q
    };
    let q1 = digit(u1, u0 >> 16);
    let un21 = u1
        .wrapping_mul(B)
        .wrapping_add(u0 >> 16)
        .wrapping_sub(q1.wrapping_mul(v));
    let q0 = digit(un21, u0 & 0xffff);
    // q1, q0 < 2^16 after the corrections.
    q1 * B + q0
}

/// `floor(num·2^24 / den)` for `den` ∈ (0, 2^55) and |num| < 2^7·den, exactly: the same
/// quotient on every target. 64-bit targets (the host) divide the < 2^86 magnitude by `den` in
/// `u128` (one 128-by-64-bit hardware division there, [`depth_quotient_wide`]); the others use
/// 32-bit divides only ([`depth_quotient_32`], the Cortex-M's UDIV). `bounded_frozen` checks
/// both against the 128-bit floor division on extreme and random operands on the host, and the
/// Cortex-M4F checksum test (`tests/tests/m4_qemu.rs`) runs the 32-bit one against the host's
/// image.
#[inline]
pub(crate) fn depth_quotient(num: i64, den: i64) -> i64 {
    #[cfg(target_pointer_width = "64")]
    {
        depth_quotient_wide(num, den)
    }
    #[cfg(not(target_pointer_width = "64"))]
    {
        depth_quotient_32(num, den)
    }
}

/// [`depth_quotient`] by a `u128` division of magnitudes: `|num|·2^24` < 2^86 (exact in u128),
/// `den` > 0, so `q = floor(|num|·2^24/den)` < 2^31 and the remainder `|num|·2^24 − q·den`
/// ∈ [0, den) are exact; the floor of the negative quotient is `−q` if the remainder is 0, else
/// `−q − 1`. Compiled on every target (tested on the host), used on 64-bit ones.
#[allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_truncation,
    clippy::cast_possible_wrap,
    clippy::cast_sign_loss
)]
#[cfg_attr(not(target_pointer_width = "64"), allow(dead_code))]
#[inline]
pub(crate) fn depth_quotient_wide(num: i64, den: i64) -> i64 {
    // den > 0 (caller): the conversion is exact; |num| < 2^62, shifted by the constant 24 < 2^86.
    let d = u128::from(den as u64);
    let m = u128::from(num.unsigned_abs()) << 24;
    let q = m / d;
    // q < 2^31 (|num| < 2^7·den): the narrowing is exact; q·d ≤ m.
    let rem = m - q * d;
    let q = q as i64;
    if num >= 0 {
        q
    } else {
        -q - i64::from(rem != 0)
    }
}

/// `floor(num·2^24 / den)` for `den` ∈ (0, 2^55) and |num| < 2^7·den, exactly, without a
/// 64- or 128-bit division routine. Then the quotient lies in [−2^31, 2^31).
///
/// With `L = bitlen(den)` ∈ 1..=55 and `x = |num|·2^24/den` (< 2^31): `D = floor(den·2^(32−L))`
/// ∈ [2^31, 2^32) (a right shift of `den` for L > 32, else a multiplication by 2^(32−L) < 2^32)
/// and `U = |num|·2^(56−L)` (exact, < 2^(7+L+56−L) = 2^63), so `x = U/(den·2^(32−L))` with
/// `den·2^(32−L)` ∈ [D, D + 1). Hence `U/D ≥ x` and `U/D − x < U/(D(D + 1)) < 2^63/2^62 = 2`:
/// the magnitude divide `q̂ = floor(U/D)` ([`div64_32`], U < 2^32·D) is `floor(x)` plus 0, 1 or
/// 2. The remainder `R = |num|·2^24 − q̂·den` is formed modulo 2^64 (wrapping): its true value
/// lies in [−2·den, den), |R| < 2^56, so the wrapped value is exact, and at most two steps
/// `q̂ − 1`, `R + den` reach `0 ≤ R < den`, i.e. q̂ = floor(x). For `num < 0` the floor is
/// `−q̂` if R = 0, else `−q̂ − 1`. `bounded_frozen` checks it against the 128-bit division on
/// extreme and random operands (on the host, where [`depth_quotient`] uses
/// [`depth_quotient_wide`]).
#[allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_truncation,
    clippy::cast_possible_wrap,
    clippy::cast_sign_loss
)]
#[cfg_attr(target_pointer_width = "64", allow(dead_code))]
#[inline]
pub(crate) fn depth_quotient_32(num: i64, den: i64) -> i64 {
    // den > 0: the conversion is exact.
    let den = den as u64;
    let len = u64::BITS - den.leading_zeros();
    let d = if len > 32 {
        // len − 32 ∈ 1..=23: the top 32 bits of den.
        (den >> (len - 32)) as u32
    } else {
        // len ∈ 1..=32: 2^31 >> (len − 1) = 2^(32−len) (a right shift of a constant), and
        // den < 2^len, so the product is < 2^32.
        (den as u32) * ((1u32 << 31) >> (len - 1))
    };
    let mag = num.unsigned_abs();
    // 2^55 >> (len − 1) = 2^(56−len) (a right shift of a constant); the product is < 2^63.
    let u = mag * ((1u64 << 55) >> (len - 1));
    let mut q = div64_32(u, d);
    let mut r = mag
        .wrapping_mul(DEPTH_SCALE as u64)
        .wrapping_sub(u64::from(q).wrapping_mul(den)) as i64;
    for _ in 0..2 {
        if r >= 0 {
            break;
        }
        q -= 1;
        r += den as i64;
    }
    // q = floor(x) < 2^31, 0 ≤ r < den.
    let q = i64::from(q);
    if num >= 0 {
        q
    } else {
        -q - i64::from(r != 0)
    }
}

/// Depth z/w from the rounded edge values (step 8; rounding as in `sample.rs`: floor), `wz`
/// the step-1 (w, z) of each vertex.
///
/// Called on covered samples only. `E'' = floor(E'/2^sh)` with `sh = max(0, bitlen(max|E'|) −
/// 24)` (the bit length of the largest magnitude is that of the OR of the magnitudes): |E''| ≤ 2^24 (exact in i32);
/// |w|, |z| ≤ 2^29, so each product ≤ 2^53 (SMULL/SMLAL) and the oriented sums
/// |num|, |den| < 2^55. With `den > 0` (else `DEPTH_FAR`): `num ≥ 2^7·den` means a quotient
/// ≥ 2^31 (saturates to `DEPTH_FAR`), `num ≤ −2^7·den` one ≤ −2^31 (`DEPTH_NEAR`); otherwise
/// [`depth_quotient`] is exact and in [−2^31, 2^31), clamped to `DEPTH_FAR` at the top. This is
/// `clamp(floor(num·2^24/den), DEPTH_NEAR, DEPTH_FAR)` exactly, as the 128-bit division gave.
#[inline]
#[allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss
)]
pub(crate) fn depth(e: &[i64; 3], wz: &[(i32, i32); 3], sign: i64) -> i32 {
    // A covered sample's E' are each 0 or of the orientation's sign, so |E'| = sign·E'
    // (|E'| < 2^61: the negation cannot overflow).
    let big = e.iter().fold(0, |m, &x| m | if sign < 0 { -x } else { x }) as u64;
    let len = u64::BITS - big.leading_zeros();
    // Floor shift by sh ≤ 37 (|E'| < 2^61): an arithmetic right shift, exact floor.
    let sh = len.saturating_sub(24);
    let (mut num, mut den) = (0i64, 0i64);
    for (&ek, &(w, z)) in e.iter().zip(wz.iter()) {
        let ek = (ek >> sh) as i32;
        num += i64::from(ek) * i64::from(z);
        den += i64::from(ek) * i64::from(w);
    }
    let (num, den) = if sign < 0 { (-num, -den) } else { (num, den) };
    // 2^7·den < 2^62 (den < 2^55).
    let lim = den * DEPTH_SAT_SCALE;
    if den <= 0 || num >= lim {
        return DEPTH_FAR;
    }
    if num <= -lim {
        return DEPTH_NEAR;
    }
    // In [−2^31, 2^31): after the clamp to DEPTH_FAR it fits i32.
    depth_quotient(num, den).min(i64::from(DEPTH_FAR)) as i32
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
    let (sign, n) = if p.iter().all(|&(_, _, w)| w > 0) {
        let pos = e.iter().any(|&x| x > 0);
        let neg = e.iter().any(|&x| x < 0);
        (i64::from(pos && !neg) - i64::from(neg && !pos), 3)
    } else {
        (det_sign(&e, p.map(|(_, _, w)| w)), 6)
    };
    let covered = sign != 0
        && e.iter().enumerate().all(|(k, &ek)| {
            if ek == 0 {
                fill_rule(&p, (k + 1) % 3, (k + 2) % 3, sign)
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
fn finish<const MOTION: bool, const DEFOCUS: bool>(
    ab: [(i32, i32); 3],
    wpos: bool,
    wz: impl Fn() -> [(i32, i32); 3],
    ops: &mut Ops,
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
    // Fast path (every w > 0, no E' = 0): the sign bit of `e0 | e1 | e2` is set iff some E' < 0,
    // that of `e0 & e1 & e2` iff every E' < 0. Covered iff all E' share one strict sign, which
    // is then the orientation (module table step 6). Anything else goes to `decide_slow`.
    let (sign, covered) = if wpos && e0 != 0 && e1 != 0 && e2 != 0 {
        n += 3;
        if e0 & e1 & e2 < 0 {
            (-1, true)
        } else if e0 | e1 | e2 >= 0 {
            (1, true)
        } else {
            (0, false)
        }
    } else {
        let [(w0, _), (w1, _), (w2, _)] = wz();
        let (sign, covered, k) = decide_slow(e, [(a0, b0, w0), (a1, b1, w1), (a2, b2, w2)]);
        n += k;
        (sign, covered)
    };
    let hit = covered.then(|| {
        n += 12;
        Hit {
            depth: depth(&e, &wz(), sign),
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
/// compile time; dispatched once per call from the setup's class by [`bounded_eval`]); the
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
) -> BoundedEval {
    let Some(f) = Fast::new::<MOTION, DEFOCUS, G20>(setup.viewport, xs, ys, s, shift) else {
        return eval_general_at::<MOTION, DEFOCUS>(setup, shift, xs, ys, s, ops);
    };
    let [v0, v1] = &setup.tri.v;
    // The shutter end nearer to T is the base of every lerp (`fast_vertex`).
    let [b0, b1, b2] = if MOTION && f.late { v1 } else { v0 };
    let [d0, d1, d2] = &setup.dv;
    let (a0, bb0, w0) = fast_vertex::<MOTION, DEFOCUS>(b0, d0, &f);
    let (a1, bb1, w1) = fast_vertex::<MOTION, DEFOCUS>(b1, d1, &f);
    let (a2, bb2, w2) = fast_vertex::<MOTION, DEFOCUS>(b2, d2, &f);
    let wpos = w0 > 0 && w1 > 0 && w2 > 0;
    // Motion classes recompute w and z out of line; the others only load them.
    let wz = || {
        if MOTION {
            fast_wz::<MOTION>(setup, f.tq, f.late)
        } else {
            [b0, b1, b2].map(|v| (v[W], v[Z]))
        }
    };
    finish::<MOTION, DEFOCUS>([(a0, bb0), (a1, bb1), (a2, bb2)], wpos, wz, ops)
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
) -> BoundedEval {
    let [v0, v1] = &setup.tri.v;
    let [q0, q1, q2] = v0;
    let [r0, r1, r2] = v1;
    let (a0, b0, w0) = vertex::<MOTION, DEFOCUS>(q0, r0, c);
    let (a1, b1, w1) = vertex::<MOTION, DEFOCUS>(q1, r1, c);
    let (a2, b2, w2) = vertex::<MOTION, DEFOCUS>(q2, r2, c);
    let z = |q: &[i32; 5], r: &[i32; 5]| if MOTION { lerp(q[Z], r[Z], c.t) } else { q[Z] };
    let wz = || [(w0, z(q0, r0)), (w1, z(q1, r1)), (w2, z(q2, r2))];
    let wpos = w0 > 0 && w1 > 0 && w2 > 0;
    finish::<MOTION, DEFOCUS>([(a0, b0), (a1, b1), (a2, b2)], wpos, wz, ops)
}

/// [`eval_general`] of one class: out of line, it serves only rare inputs. `xs`, `ys`
/// inside the viewport, `shift` ∈ 20..=32 (checked by [`bounded_eval`]).
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
    eval_general::<MOTION, DEFOCUS>(setup, &c, ops)
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
    eval_at::<Full>(setup, shift, pos, s, ops)
}

/// [`bounded_eval`] for a `shift` ∈ [`OFFSET_SHIFT_MIN`]..=[`OFFSET_SHIFT_MAX`] (the caller's
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
    // The default grid 2^20 gets its own copy with the scaling constants folded in.
    Some(match (m, d, shift == OFFSET_SHIFT_MIN) {
        (false, false, true) => eval_fast::<false, false, true>(setup, shift, xs, ys, s, ops),
        (true, false, true) => eval_fast::<true, false, true>(setup, shift, xs, ys, s, ops),
        (false, true, true) => eval_fast::<false, true, true>(setup, shift, xs, ys, s, ops),
        (true, true, true) => eval_fast::<true, true, true>(setup, shift, xs, ys, s, ops),
        (false, false, false) => eval_fast::<false, false, false>(setup, shift, xs, ys, s, ops),
        (true, false, false) => eval_fast::<true, false, false>(setup, shift, xs, ys, s, ops),
        (false, true, false) => eval_fast::<false, true, false>(setup, shift, xs, ys, s, ops),
        (true, true, false) => eval_fast::<true, true, false>(setup, shift, xs, ys, s, ops),
    })
}

/// Whether [`bounded_eval`] takes the fast datapath for these inputs (for the boundary tests;
/// inputs as [`bounded_eval`] accepts them).
#[cfg(test)]
#[allow(clippy::cast_possible_wrap)]
pub(crate) fn takes_fast_path(setup: &Setup, shift: u32, pos: ScreenPos, s: &Sample) -> bool {
    let (vp, xs, ys) = (setup.viewport, pos.xs as i32, pos.ys as i32);
    match setup.class {
        Class::Static => Fast::new::<false, false, false>(vp, xs, ys, s, shift).is_some(),
        Class::Motion => Fast::new::<true, false, false>(vp, xs, ys, s, shift).is_some(),
        Class::Defocus => Fast::new::<false, true, false>(vp, xs, ys, s, shift).is_some(),
        Class::MotionDefocus => Fast::new::<true, true, false>(vp, xs, ys, s, shift).is_some(),
    }
}

/// The bounded sample test: the depth on a hit (`S` = the setup's offset shift; a setup of the
/// exact test is evaluated at the finest grid, [`OFFSET_SHIFT_MIN`]).
#[inline]
pub fn bounded_test(setup: &Setup, pos: ScreenPos, s: &Sample, ops: &mut Ops) -> Option<Hit> {
    // A setup's shift is in range by construction (`PrecisionBits::of` of a sealed precision
    // whose OFF is checked at compile time), so `bounded_eval`'s range check is not repeated.
    let shift = setup.prec.offset_shift().unwrap_or(OFFSET_SHIFT_MIN);
    eval_at::<Full>(setup, shift, pos, s, ops)?.hit
}

/// [`bounded_test`] of precision `P` on unit `U`, for a setup of precision `P`: the grid is
/// `P`'s constant (so one grid's copy is compiled) and only the classes `U` accepts are
/// instantiated; `None` (not covered) for a class `U` does not accept.
#[inline]
pub fn bounded_test_unit<P: Precision, U: Unit>(
    setup: &Setup,
    pos: ScreenPos,
    s: &Sample,
    ops: &mut Ops,
) -> Option<Hit> {
    let shift = P::OFFSET_SHIFT.unwrap_or(OFFSET_SHIFT_MIN);
    eval_at::<U>(setup, shift, pos, s, ops)?.hit
}
