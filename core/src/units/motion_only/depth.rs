//! Step 8 of the bounded sample test (`bounded.rs`: the depth of a covered sample) for the
//! motion-only unit's test ([`crate::units::motion_only::sample`]): the same function as `bounded::depth`,
//! bit for bit, written for a 32-bit core — every division one 32-bit UDIV digit of a
//! normalized long division, the quotient's corrections as explicit steps (a correction
//! loop may be turned by the compiler into a 64-bit division routine call).
//!
//! `bounded::depth`: `E'' = floor(E'/2^sh)` with `sh = max(0, bitlen(max|E'|) − 24)`,
//! `num = Σ E''·z`, `den = Σ E''·w` oriented by the sign, then `DEPTH_FAR` for `den ≤ 0` or
//! `num ≥ 2^7·den`, `DEPTH_NEAR` for `num ≤ −2^7·den`, else `floor(num·2^24/den)` clamped to
//! `DEPTH_FAR`. The quotient here is `bounded::depth_quotient_32`'s algorithm (its proof
//! applies unchanged) with the corrections unrolled; `tests::depth_is_bounded_depth` compares
//! the whole function with `bounded::depth` on extreme and random operands.

use crate::config::formats::{DEPTH_FAR, DEPTH_FRAC, DEPTH_NEAR};

/// 2^24: the depth quotient's scale.
const DEPTH_SCALE: u64 = 1 << DEPTH_FRAC;

/// `floor(u / v)` for a normalized `v` ∈ [2^31, 2^32) and `u < 2^32·v`: `bounded::div64_32`
/// (Hacker's Delight `divlu`, two base-2^16 digits, each estimate corrected at most twice),
/// with the corrections unrolled. Ranges as there: `vn1` ∈ [2^15, 2^16); `q̂·vn0` is formed
/// only when `q̂ < 2^16`, `rhat·2^16 + un` only when `rhat < 2^16`; the partial remainder
/// is exact modulo 2^32.
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]
fn div64_32(u: u64, v: u32) -> u32 {
    const B: u32 = 1 << 16;
    let (u1, u0) = ((u >> 32) as u32, u as u32);
    let (vn1, vn0) = (v >> 16, v & 0xffff);
    let digit = |hi: u32, lo: u32| {
        // vn1 ≥ 2^15 (v normalized): the checked form never takes its fallback; it links no
        // division-by-zero panic (a plain `/` does: the compiler cannot see vn1 ≠ 0).
        let mut q = hi.checked_div(vn1).unwrap_or(u32::MAX);
        let mut rhat = hi - q * vn1;
        if q >= B || q * vn0 > rhat * B + lo {
            q -= 1;
            rhat += vn1;
            if rhat < B && (q >= B || q * vn0 > rhat * B + lo) {
                q -= 1;
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

/// `floor(num·2^24 / den)` for `den` ∈ (0, 2^55) and |num| < 2^7·den: `bounded::
/// depth_quotient_32` (its proof: the estimate `floor(U/D)` is the quotient plus 0, 1 or 2;
/// the remainder, exact modulo 2^64, tells which).
#[inline(always)]
#[allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_truncation,
    clippy::cast_possible_wrap,
    clippy::cast_sign_loss
)]
fn quotient(num: i64, den: i64) -> i64 {
    // den > 0: exact as u64; len ∈ 1..=55.
    let den = den as u64;
    let len = u64::BITS - den.leading_zeros();
    let d = if len > 32 {
        (den >> (len - 32)) as u32
    } else {
        // 2^(32−len) ≤ 2^31, den < 2^len: the product < 2^32.
        (den as u32) * ((1u32 << 31) >> (len - 1))
    };
    let mag = num.unsigned_abs();
    // |num| < 2^(7+len): mag·2^(56−len) < 2^63 (a left shift by 56 − len ∈ 1..=55 of a value
    // below 2^(7+len), written as a multiplication by the power).
    let u = mag * ((1u64 << 55) >> (len - 1));
    let mut q = div64_32(u, d);
    // The true remainder lies in [−2·den, den) (|.| < 2^56): exact modulo 2^64.
    let mut r = mag
        .wrapping_mul(DEPTH_SCALE)
        .wrapping_sub(u64::from(q).wrapping_mul(den)) as i64;
    if r < 0 {
        q -= 1;
        r += den as i64;
        if r < 0 {
            q -= 1;
            r += den as i64;
        }
    }
    let q = i64::from(q);
    if num >= 0 {
        q
    } else {
        -q - i64::from(r != 0)
    }
}

/// `bounded::depth` (module docs): the depth of a covered sample from its edge values `e`,
/// the step-1 `(w, z)` of each vertex and the orientation `sign` (±1).
#[inline(always)]
#[allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss
)]
pub(crate) fn depth(e: &[i64; 3], wz: &[(i32, i32); 3], sign: i64) -> i32 {
    // Covered: each E' is 0 or of the orientation's sign, |E'| < 2^61 (negation exact).
    let big = e.iter().fold(0, |m, &x| m | if sign < 0 { -x } else { x }) as u64;
    let len = u64::BITS - big.leading_zeros();
    // sh ≤ 37: an arithmetic shift (floor); |E''| ≤ 2^24 (exact in i32).
    let sh = len.saturating_sub(24);
    let (mut num, mut den) = (0i64, 0i64);
    for (&ek, &(w, z)) in e.iter().zip(wz.iter()) {
        let ek = (ek >> sh) as i32;
        // |E''| ≤ 2^24, |w|, |z| ≤ 2^29: three products < 2^55 in total.
        num += i64::from(ek) * i64::from(z);
        den += i64::from(ek) * i64::from(w);
    }
    let (num, den) = if sign < 0 { (-num, -den) } else { (num, den) };
    // 2^7·den < 2^62.
    let lim = den * 128;
    if den <= 0 || num >= lim {
        return DEPTH_FAR;
    }
    if num <= -lim {
        return DEPTH_NEAR;
    }
    // In [−2^31, 2^31): after the clamp to DEPTH_FAR it fits i32.
    quotient(num, den).min(i64::from(DEPTH_FAR)) as i32
}

#[cfg(test)]
#[allow(clippy::cast_possible_truncation, clippy::arithmetic_side_effects)]
mod tests {
    use super::*;
    use uvt_testkit::Rng;

    /// [`depth`] against `bounded::depth` (on the host: its 128-bit quotient) on extreme
    /// edge values (±(2^61 − 1), single bits, zeros) and (w, z) (±2^29, ±1, 0), and on random
    /// covered configurations. Prints the inputs on a failure.
    #[test]
    fn depth_is_bounded_depth() {
        let seed = uvt_testkit::seed();
        let mut rng = Rng(seed);
        let ends: [i32; 7] = [1 << 29, -(1 << 29), 1, -1, 0, 12345, -(1 << 28) + 7];
        let check = |e: [i64; 3], wz: [(i32, i32); 3], sign: i64| {
            let want =
                crate::sample::bounded::depth::depth(&e, &wz, sign, &mut crate::coverage::NoProbe);
            let got = depth(&e, &wz, sign);
            assert_eq!(
                got, want,
                "UVT_SEED={seed}: e {e:?} wz {wz:?} sign {sign}: got {got} ({got:#010x}), \
                 want {want} ({want:#010x})"
            );
        };
        let mags: [i64; 6] = [(1 << 61) - 1, 1 << 60, 1 << 24, (1 << 24) - 1, 1, 0];
        for &a in &mags {
            for &b in &mags {
                for &w in &ends {
                    for &z in &ends {
                        for sign in [-1i64, 1] {
                            let e = [a * sign, b * sign, mags[0] * sign];
                            check(e, [(w, z), (z, w), (w, w)], sign);
                        }
                    }
                }
            }
        }
        for _ in 0..uvt_testkit::cases(200_000, 5_000_000) {
            let sign = if rng.next_u64() & 1 == 0 { -1i64 } else { 1 };
            let e = [0; 3].map(|_| rng.signed((1 << 61) - 1).abs() * sign);
            let wz = [0; 3].map(|_| {
                let w = rng.signed(1 << 29) as i32;
                (w, rng.signed(1 << 29) as i32)
            });
            check(e, wz, sign);
        }
    }
}
