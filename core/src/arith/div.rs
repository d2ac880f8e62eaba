//! The shared divisions: floor and ceiling division of `i128` by a positive divisor (bounds round
//! outward with them), the low-bit mask of a grid check, and a 64-by-32-bit long division in
//! 32-bit divides (`div64_32`: the bounded and planar datapaths on a 32-bit core).

/// `2^k − 1`, the mask of the low `k` bits, for `k ≤ 30` (`None` above): the grid check of a
/// narrower precision (`k = 16 − frac ≤ 14`).
pub(crate) const fn low_bits_mask(k: u32) -> Option<i32> {
    match 2i32.checked_pow(k) {
        Some(p) => p.checked_sub(1),
        None => None,
    }
}

/// Floor division of `n` by a positive `d` (rounds toward -∞). `d > 0` is the caller's duty and
/// is checked: a non-positive `d` returns `None`.
#[inline]
pub fn floor_div(n: i128, d: i128) -> Option<i128> {
    if d <= 0 {
        return None;
    }
    // Same exact quotient through a 64-bit divide when both operands fit (much cheaper on a
    // 32-bit core than the 128-bit library divide); d > 0 so `div_euclid` is the floor.
    if let (Ok(n64), Ok(d64)) = (i64::try_from(n), i64::try_from(d)) {
        return Some(n64.div_euclid(d64) as i128);
    }
    Some(n.div_euclid(d))
}

/// Ceiling division of `n` by a positive `d` (rounds toward +∞); `None` if `d ≤ 0`.
#[inline]
pub fn ceil_div(n: i128, d: i128) -> Option<i128> {
    floor_div(n.checked_neg()?, d).and_then(i128::checked_neg)
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_directions() {
        assert_eq!(floor_div(7, 2), Some(3));
        assert_eq!(floor_div(-7, 2), Some(-4));
        assert_eq!(ceil_div(7, 2), Some(4));
        assert_eq!(ceil_div(-7, 2), Some(-3));
        assert_eq!(ceil_div(6, 3), Some(2));
        assert_eq!(floor_div(1, 0), None);
        assert_eq!(ceil_div(1, -1), None);
    }
}
