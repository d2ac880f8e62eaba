//! Steps 1–7 of the bounded sample test (module docs of `sample::bounded`): the rounded lerps,
//! lens offsets and grid offsets on the general (step-by-step) and the fast (rounded high word)
//! datapath, and the fill rule's tie key.

use crate::config::formats::{SUBPIXEL_BITS, TUV_FRAC};
use crate::config::precision::{OFFSET_SHIFT_MAX, OFFSET_SHIFT_MIN};
use crate::coverage::{Bin, NoProbe, Probe};
use crate::input::{Sample, Viewport, C, W, X, Y};

/// 2^16: one t/u/v step.
const TUV_SCALE: i64 = 1 << TUV_FRAC;

/// The rounding bins (exact, down, up) of step 1, the lerp.
const LERP: [Bin; 3] = [Bin::BsLerpExact, Bin::BsLerpDown, Bin::BsLerpUp];
/// The rounding bins of step 2, the lens offset.
const LENS: [Bin; 3] = [Bin::BsLensExact, Bin::BsLensDown, Bin::BsLensUp];
/// The rounding bins of step 4, the grid.
const GRID: [Bin; 3] = [Bin::BsGridExact, Bin::BsGridDown, Bin::BsGridUp];

/// 2^8: one pixel in sample-position units.
pub(crate) const SUBPIXEL_SCALE: i32 = 1 << SUBPIXEL_BITS;

/// Per-sample constants of the general datapath ([`eval_general`], the inputs [`Fast::new`]
/// refuses). Ranges (checked `Sample`, `Viewport`, the position check in [`bounded_eval`]): `t` ∈
/// [0, 2^16], `u`, `v` ∈ [−2^16, 2^16]; `sw = 256W`, `sh = 256H` ≤ 2^19; `ngx = sw − 2xs` ∈
/// (−sw, sw], `ngy = 2ys − sh` ∈ [−sh, sh) (so |ngx|, |ngy| ≤ 2^19); `half = 2^(S−1)` ≤ 2^31;
/// `fine = S − 20` ∈ 0..=12.
pub(crate) struct Ctx {
    pub(crate) t: i32,
    pub(crate) u: i32,
    pub(crate) v: i32,
    pub(crate) sw: i32,
    pub(crate) sh: i32,
    pub(crate) ngx: i32,
    pub(crate) ngy: i32,
    pub(crate) half: i64,
    pub(crate) fine: u32,
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
    lerp_p(f0, f1, t, &mut NoProbe)
}

/// [`lerp`], its rounding direction reported to `pr`.
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]
pub(crate) fn lerp_p(f0: i32, f1: i32, t: i32, pr: &mut impl Probe) -> i32 {
    let p = i64::from(t) * i64::from(f1 - f0);
    pr.round(p, TUV_FRAC, LERP);
    // (p + 2^15) >> 16 on i64: an arithmetic shift by a constant, the exact floor.
    f0 + ((p + TUV_SCALE / 2) >> TUV_FRAC) as i32
}

/// `round(L·c / 2^16)` (nearest, ties toward +∞), the step-2 lens offset: |L| ≤ 2^16, |c| ≤ 2^29,
/// |L·c| ≤ 2^45 (SMULL), result |.| ≤ 2^29 (exact in i32).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]
fn lens(l: i32, c: i32, pr: &mut impl Probe) -> i32 {
    let p = i64::from(l) * i64::from(c);
    pr.round(p, TUV_FRAC, LENS);
    ((p + TUV_SCALE / 2) >> TUV_FRAC) as i32
}

/// `round((e·p + ng·w) / 2^S)` (nearest, ties toward +∞): steps 3–4 for one axis, `e` = 256W
/// (or 256H), `ng` = −g. |e·p| ≤ 2^19·2^30, |ng·w| ≤ 2^19·2^29, so with `half` ≤ 2^31 the sum
/// is < 1.5·2^49 + 2^31 (i64; one SMULL and one SMLAL). The floor division by 2^S is done as
/// `>> 20` on i64 (|.| < 1.5·2^29 + 1 < 2^31 afterwards: the narrowing to i32 is exact) and then
/// `>> (S − 20)` on i32 — nested floors by powers of two compose to the floor by 2^S exactly.
/// Result |a'| < 2^(50−S) ≤ 2^30.
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]
fn offset(e: i32, p: i32, ng: i32, w: i32, c: &Ctx, pr: &mut impl Probe) -> i32 {
    let acc = i64::from(e) * i64::from(p) + i64::from(ng) * i64::from(w);
    pr.round(acc, OFFSET_SHIFT_MIN + c.fine, GRID);
    let acc = acc + c.half;
    // `fine` ≤ 12 < 32 (Ctx): the i32 shift cannot overflow.
    ((acc >> OFFSET_SHIFT_MIN) as i32) >> c.fine
}

/// One vertex at the sample on the general datapath: `(a', b', w)` (z is lerped on hits only,
/// [`depth`]). Steps 1–4; `MOTION` and `DEFOCUS` select the rounded lerp and the lens offset at
/// compile time (no per-vertex class branch).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn vertex<const MOTION: bool, const DEFOCUS: bool>(
    q: &[i32; 5],
    r: &[i32; 5],
    c: &Ctx,
    pr: &mut impl Probe,
) -> (i32, i32, i32) {
    let (mut x, mut y, w) = if MOTION {
        (
            lerp_p(q[X], r[X], c.t, pr),
            lerp_p(q[Y], r[Y], c.t, pr),
            lerp_p(q[W], r[W], c.t, pr),
        )
    } else {
        (q[X], q[Y], q[W])
    };
    if DEFOCUS {
        let coc = if MOTION {
            lerp_p(q[C], r[C], c.t, pr)
        } else {
            q[C]
        };
        // |x_t|, |lens| ≤ 2^29: |x| ≤ 2^30 (i32).
        x += lens(c.u, coc, pr);
        y += lens(c.v, coc, pr);
    }
    (
        offset(c.sw, x, c.ngx, w, c, pr),
        offset(c.sh, y, c.ngy, w, c, pr),
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
pub(crate) struct Fast {
    pub(crate) tq: i32,
    pub(crate) late: bool,
    pub(crate) uq: i32,
    pub(crate) vq: i32,
    pub(crate) swq: i32,
    pub(crate) shq: i32,
    pub(crate) ngxq: i32,
    pub(crate) ngyq: i32,
}

impl Fast {
    /// The fast constants of a sample for a triangle of class (`MOTION`, `DEFOCUS`), or `None`
    /// when a scaled factor would not fit i32: T = 2^15 (motion classes), U or V = 2^16
    /// (defocus classes), or `max(W, H) ≥ 2^(S−9)` (at S = 20: a 2048-pixel side). `xs`, `ys`
    /// inside the viewport and `shift` ∈ 20..=32 (checked by the caller). Fields a class does
    /// not use are 0.
    #[inline(always)]
    #[allow(clippy::arithmetic_side_effects)]
    pub(crate) fn new<const MOTION: bool, const DEFOCUS: bool, const G20: bool>(
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
pub(crate) fn fast_vertex<const MOTION: bool, const DEFOCUS: bool>(
    b: &[i32; 5],
    d: &[i32; 5],
    f: &Fast,
    pr: &mut impl Probe,
) -> (i32, i32, i32) {
    // Every rounding here is of a product scaled so that its rounding point is 2^32: the low
    // word is what it discards (the general datapath's remainder times 2^(32 − bits)).
    let mut at = |f0: i32, d: i32| {
        if MOTION {
            pr.round(i64::from(f.tq) * i64::from(d), 32, LERP);
            mla_hi(f.tq, d, f0)
        } else {
            f0
        }
    };
    // |d| ≤ 2^30 (checked triangle, |f| ≤ 2^29; `Setup::dv`).
    let (mut x, mut y, w) = (at(b[X], d[X]), at(b[Y], d[Y]), at(b[W], d[W]));
    if DEFOCUS {
        // |c_t| ≤ 2^29: 2c ≤ 2^30 (i32).
        let c2 = at(b[C], d[C]) * 2;
        pr.round(i64::from(f.uq) * i64::from(c2), 32, LENS);
        x = mla_hi(f.uq, c2, x);
        pr.round(i64::from(f.vq) * i64::from(c2), 32, LENS);
        y = mla_hi(f.vq, c2, y);
    }
    let mut hi = |e: i32, p: i32, ng: i32| {
        let acc = i64::from(e) * i64::from(p) + i64::from(ng) * i64::from(w);
        pr.round(acc, 32, GRID);
        ((acc + (1 << 31)) >> 32) as i32
    };
    (hi(f.swq, x, f.ngxq), hi(f.shq, y, f.ngyq), w)
}

/// Fill-rule decision on `E'_k = 0` (step 7), for edge k with vertices `i = k+1`, `j = k+2`:
/// inside iff `s·κ > 0` with the antisymmetric tie key `κ = cmp((b'_i, a'_i, w_i), (b'_j, a'_j,
/// w_j))` (lexicographic). Comparators only; see the module docs for why it is watertight.
#[inline]
pub(crate) fn fill_rule(v: &[(i32, i32, i32); 3], i: usize, j: usize, s: i64) -> bool {
    let (Some(&(ai, bi, wi)), Some(&(aj, bj, wj))) = (v.get(i), v.get(j)) else {
        return false;
    };
    match (bi, ai, wi).cmp(&(bj, aj, wj)) {
        core::cmp::Ordering::Greater => s > 0,
        core::cmp::Ordering::Less => s < 0,
        core::cmp::Ordering::Equal => false,
    }
}

/// The coverage bin of a [`fill_rule`] decision `inside` on edge (i, j): the key 0 (the two
/// vertices coincide), else inside or outside.
#[inline]
pub(crate) fn tie_bin(v: &[(i32, i32, i32); 3], i: usize, j: usize, inside: bool) -> Bin {
    if v.get(i) == v.get(j) {
        Bin::BsTieCoincident
    } else if inside {
        Bin::BsTieInside
    } else {
        Bin::BsTieOutside
    }
}
