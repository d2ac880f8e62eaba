//! Step 8 of the bounded sample test: depth from the rounded edge values, and its exact
//! 64-by-32-bit quotient on every target.

use crate::arith::div::div64_32;
use crate::config::formats::{DEPTH_FAR, DEPTH_FRAC, DEPTH_NEAR};
use crate::coverage::{Bin, Probe};

/// 2^24: the depth quotient's scale.
const DEPTH_SCALE: i64 = 1 << DEPTH_FRAC;

/// 2^(31 − DEPTH_FRAC) = 2^7: the quotient saturates where num ≥ 2^7·den (a constant shift,
/// checked by the compiler).
const DEPTH_SAT_SCALE: i64 = 1 << (31 - DEPTH_FRAC);

/// `floor(num·2^24 / den)` for `den` ∈ (0, 2^55) and |num| < 2^7·den, exactly: the same
/// quotient on every target. 64-bit targets (the host) divide the < 2^86 magnitude by `den` in
/// `u128` (one 128-by-64-bit hardware division there, [`depth_quotient_wide`]); the others use
/// 32-bit divides only ([`depth_quotient_32`], the Cortex-M's UDIV). `bounded_frozen` checks
/// both against the 128-bit floor division on extreme and random operands on the host, and the
/// Cortex-M4F checksum test (`tests/tests/external/m4_qemu.rs`) runs the 32-bit one against the host's
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
pub(crate) fn depth(e: &[i64; 3], wz: &[(i32, i32); 3], sign: i64, pr: &mut impl Probe) -> i32 {
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
    if den <= 0 {
        pr.hit(Bin::BsDepthDen);
        return DEPTH_FAR;
    }
    if num >= lim {
        pr.hit(Bin::BsDepthFar);
        return DEPTH_FAR;
    }
    if num <= -lim {
        pr.hit(Bin::BsDepthNear);
        return DEPTH_NEAR;
    }
    let q = depth_quotient(num, den);
    pr.pick(q > i64::from(DEPTH_FAR), Bin::BsDepthTop, Bin::BsDepthIn);
    // In [−2^31, 2^31): after the clamp to DEPTH_FAR it fits i32.
    q.min(i64::from(DEPTH_FAR)) as i32
}
