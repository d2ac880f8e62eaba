//! Closed intervals of t, u or v in the raw t/u/v format, and the two solvers every bound uses.
//!
//! Both solvers answer "for which s ∈ [0, 1] does `s·d ≤ n` hold?" for exact integers `d`, `n`
//! and round the answer outward to the t/u/v grid (upper ends up, lower ends down). Every bound in
//! `setup.rs` and `bounds.rs` is a conjunction of such linear constraints.

use crate::arith::div::{ceil_div, floor_div};
use crate::config::formats::{TUV_FRAC, TUV_ONE};
use crate::error::Error;

/// Inclusive interval `[lo, hi]` of raw t/u/v values (`TUV_FRAC` fraction bits); never empty.
/// Invariant (kept by every constructor): `−TUV_ONE ≤ lo ≤ hi ≤ TUV_ONE`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Interval {
    lo: i32,
    hi: i32,
}

impl Interval {
    /// Checked constructor: `−1 ≤ lo ≤ hi ≤ 1` (raw `−TUV_ONE ..= TUV_ONE`).
    pub const fn new(lo: i32, hi: i32) -> Result<Interval, Error> {
        if lo < -TUV_ONE || lo > TUV_ONE || hi < -TUV_ONE || hi > TUV_ONE || lo > hi {
            return Err(Error::Interval { lo, hi });
        }
        Ok(Interval { lo, hi })
    }
    /// Lower end, raw.
    pub const fn lo(&self) -> i32 {
        self.lo
    }
    /// Upper end, raw.
    pub const fn hi(&self) -> i32 {
        self.hi
    }

    /// t ∈ [0, 1] (or a lens parameter s ∈ [0, 1]).
    pub const UNIT: Interval = Interval { lo: 0, hi: TUV_ONE };
    /// u or v ∈ [-1, 1].
    pub const LENS: Interval = Interval {
        lo: -TUV_ONE,
        hi: TUV_ONE,
    };

    /// Intersection, `None` when empty.
    #[inline]
    pub fn meet(self, o: Interval) -> Option<Interval> {
        let lo = self.lo.max(o.lo);
        let hi = self.hi.min(o.hi);
        (lo <= hi).then_some(Interval { lo, hi })
    }

    /// The smallest interval holding both (ends within the invariant's range since both are).
    #[inline]
    pub fn join(self, o: Interval) -> Interval {
        Interval {
            lo: self.lo.min(o.lo),
            hi: self.hi.max(o.hi),
        }
    }

    /// Whether raw value `x` lies inside.
    #[inline]
    pub fn contains(&self, x: i32) -> bool {
        (self.lo <= x) & (x <= self.hi)
    }

    /// Round outward to the grid of `frac` fraction bits (in the 16-fraction-bit container):
    /// the low end down, the high end up, then clamp the high end to 1. A no-op for `frac` ≥ 16.
    #[inline]
    // Ranges: frac < 16 here, so step = 2^(16−frac) ∈ [2, 2^16]; |lo|, |hi| ≤ 2^16 (invariant),
    // so every quotient·step is a multiple of step within [−2^16, 2^16] (±2^16 are multiples of
    // every step): no product or negation leaves i32, and the result keeps the invariant.
    #[allow(clippy::arithmetic_side_effects)]
    pub fn round_out(self, frac: u32) -> Interval {
        if frac >= TUV_FRAC {
            return self;
        }
        let step = 2i32.pow(TUV_FRAC - frac);
        let lo = self.lo.div_euclid(step) * step;
        let hi = (-((-self.hi).div_euclid(step)) * step).min(TUV_ONE);
        Interval { lo, hi }
    }

    /// Map a lens parameter s ∈ [0, 1] to the lens coordinate u = 2s − 1 (exact for s ∈ [0, 1];
    /// the ends are clamped to [−1, 1], which only matters for an interval reaching below 0).
    #[inline]
    // |lo|, |hi| ≤ 2^16 (invariant): 2·x − 2^16 ∈ [−3·2^16, 2^16], far inside i32.
    #[allow(clippy::arithmetic_side_effects)]
    pub fn s_to_lens(self) -> Interval {
        let map = |x: i32| (2 * x - TUV_ONE).max(-TUV_ONE);
        Interval {
            lo: map(self.lo),
            hi: map(self.hi),
        }
    }
}

/// `x` clamped to [0, 1] (raw [0, 2^16]).
#[inline]
fn clamp_raw(x: i128) -> i32 {
    // The clamped value is in [0, 2^16], so the conversion never fails.
    i32::try_from(x.clamp(0, i128::from(TUV_ONE))).unwrap_or(TUV_ONE)
}

/// `floor(n·2^k / d)` and whether the division leaves a remainder, for `0 ≤ n < d ≤ 2^63`
/// and `k ≤ 16` (checked: anything else returns `None`). Exact, without a 64-bit divide and
/// without 128-bit arithmetic; the quotient q = floor(N/d), N = n·2^k, is < 2^k ≤ 2^16.
///
/// - `d < 2^16`: N < d·2^16 < 2^32, one 32-bit divide (the Cortex-M's `UDIV`).
/// - `2^16 ≤ d < 2^62`: with L = bit length of d and s = L − 16 ≥ 1, the estimate
///   `q1 = floor(N1/d1)` from `N1 = floor(N/2^s) < 2^(k+16) ≤ 2^32` and
///   `d1 = floor(d/2^s) + 1 ∈ (2^15, 2^16]` (one 32-bit divide) satisfies `q − 3 < q1 ≤ q`:
///   q1 ≤ (N/2^s)/(d/2^s) = q', and with x = d/2^s ≥ 2^15,
///   `N1/d1 ≥ (q'·x − 1)/(x + 1) = q' − (q' + 1)/(x + 1) > q' − 2` (q' < 2^16), so
///   q1 > q' − 3. The remainder `N − q1·d` is therefore in [0, 3d) ⊂ [0, 2^64): formed with
///   wrapping 64-bit operations it is exact (both sides agree modulo 2^64 and the true value
///   lies in range), and at most three subtractions of d finish the quotient.
/// - `2^62 ≤ d ≤ 2^63`: restoring long division, k steps of shift, compare, subtract (the
///   partial remainder stays < d, so 2r < 2^64).
///
/// `interval_corners::frac_div_matches_i128` checks every branch against the i128 quotient at
/// its ends and on seeded random operands.
// Ranges: in the doc comment above (n < d; N1 < 2^32; d1 ≤ 2^16; q1·d and N taken modulo 2^64
// on purpose, by `wrapping_mul`/`wrapping_sub`, with the exact result proven in range; q < 2^16
// so q + 1 and 2q + 1 never overflow).
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn frac_div(n: u64, d: u64, k: u32) -> Option<(u64, bool)> {
    if n >= d || d > 1 << 63 || k > TUV_FRAC {
        return None;
    }
    let scale = 2u64.checked_pow(k)?; // k ≤ 16
    if d < 1 << 16 {
        // n < d < 2^16 and scale ≤ 2^16: N < 2^32.
        let (nn, dd) = (u32::try_from(n * scale).ok()?, u32::try_from(d).ok()?);
        let q = nn / dd;
        return Some((u64::from(q), nn - q * dd != 0));
    }
    if d < 1 << 62 {
        // s = L − 16 ∈ [1, 46]; N1 = floor(n·2^k / 2^s) < 2^(L+k−s) = 2^(k+16) ≤ 2^32 (n < 2^L).
        let s = (u64::BITS - d.leading_zeros()) - 16;
        let n1 = if s >= k {
            n.checked_shr(s - k)?
        } else {
            n.checked_mul(2u64.checked_pow(k - s)?)? // k − s ≤ 15; n·2^(k−s) < 2^32
        };
        let d1 = d.checked_shr(s)? + 1; // ≤ 2^16
        let (n1, d1) = (u32::try_from(n1).ok()?, u32::try_from(d1).ok()?);
        let mut q = u64::from(n1 / d1);
        let mut r = (n.wrapping_mul(scale)).wrapping_sub(q.wrapping_mul(d));
        while r >= d {
            r -= d;
            q += 1;
        }
        return Some((q, r != 0));
    }
    let (mut q, mut r) = (0u64, n);
    for _ in 0..k {
        r *= 2;
        q *= 2;
        if r >= d {
            r -= d;
            q += 1;
        }
    }
    Some((q, r != 0))
}

/// `{ s ∈ [0,1] : s·d ≤ n }` by exact division, ends rounded outward; `None` if empty.
///
/// Cases: d > 0 gives s ≤ n/d (ceil), d < 0 gives s ≥ (−n)/(−d) (floor), d = 0 gives all or
/// nothing. Operands that fit i64 (every caller's documented range) go through [`solve_le64`];
/// beyond, the quotient is an i128 division, and if `n·2^16` would overflow i128 (|n| ≥ 2^111)
/// the answer is the whole unit interval or, where the sign already decides, empty:
/// conservative.
pub fn solve_le(d: i128, n: i128) -> Option<Interval> {
    if let (Ok(d), Ok(n)) = (i64::try_from(d), i64::try_from(n)) {
        return solve_le64(d, n);
    }
    let full = Some(Interval::UNIT);
    if d > 0 {
        if n < 0 {
            return None;
        }
        if n >= d {
            return full;
        }
        match n
            .checked_mul(i128::from(TUV_ONE))
            .and_then(|m| ceil_div(m, d))
        {
            Some(hi) => Some(Interval {
                lo: 0,
                hi: clamp_raw(hi),
            }),
            None => full,
        }
    } else if d < 0 {
        let (a, b) = (d.checked_neg()?, n.checked_neg()?);
        if b <= 0 {
            return full;
        }
        if b > a {
            return None;
        }
        match b
            .checked_mul(i128::from(TUV_ONE))
            .and_then(|m| floor_div(m, a))
        {
            Some(lo) => Some(Interval {
                lo: clamp_raw(lo),
                hi: TUV_ONE,
            }),
            None => full,
        }
    } else if n >= 0 {
        full
    } else {
        None
    }
}

/// [`solve_le`] on i64 operands, the same interval: the quotient `ceil(n·2^16/d)` (or the floor
/// of `|n|·2^16/|d|`) by [`frac_div`] on the magnitudes (`unsigned_abs` is exact for every
/// i64), so no 64-bit or 128-bit divide runs.
/// `interval_corners::solve_le_matches_i128_division` checks it against the i128 division.
// q + 1 ≤ 2^16 + 1 (q < 2^16 from `frac_div`).
#[allow(clippy::arithmetic_side_effects)]
pub fn solve_le64(d: i64, n: i64) -> Option<Interval> {
    let full = Some(Interval::UNIT);
    if d > 0 {
        if n < 0 {
            return None;
        }
        if n >= d {
            return full;
        }
        // 0 ≤ n < d: frac_div's contract holds, so `None` (conservative) cannot happen.
        match frac_div(n.unsigned_abs(), d.unsigned_abs(), TUV_FRAC) {
            Some((q, rem)) => Some(Interval {
                lo: 0,
                hi: clamp_raw(i128::from(q + u64::from(rem))),
            }),
            None => full,
        }
    } else if d < 0 {
        if n >= 0 {
            return full;
        }
        let (a, b) = (d.unsigned_abs(), n.unsigned_abs());
        if b > a {
            return None;
        }
        if b == a {
            return Some(Interval {
                lo: TUV_ONE,
                hi: TUV_ONE,
            });
        }
        match frac_div(b, a, TUV_FRAC) {
            Some((q, _)) => Some(Interval {
                lo: clamp_raw(i128::from(q)),
                hi: TUV_ONE,
            }),
            None => full,
        }
    } else if n >= 0 {
        full
    } else {
        None
    }
}

/// A precomputed constraint `s·d ≤ n(tile)` whose `d` is fixed per triangle: the two reciprocals
/// `r_up = ceil(2^K/|d|)` and `r_dn = floor(2^K/|d|)` (K = `RECIP_SHIFT`) let each tile solve it
/// with one multiply instead of a division (Laine 2011 §3.1, "u' = a·x − b").
///
/// Only [`RecipConstraint::new`] builds one, so the reciprocals always belong to `d`
/// (`r_up`, `r_dn` ≤ 2^K), which the range argument of [`RecipConstraint::solve`] needs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RecipConstraint {
    d: i64,
    r_up: i128,
    r_dn: i128,
}

impl RecipConstraint {
    /// The fixed slope d (raw pixel units).
    pub fn d(&self) -> i64 {
        self.d
    }
    /// ceil(2^K / |d|), 0 when d = 0.
    pub fn r_up(&self) -> i128 {
        self.r_up
    }
    /// floor(2^K / |d|), 0 when d = 0.
    pub fn r_dn(&self) -> i128 {
        self.r_dn
    }

    /// Precompute the reciprocals of `d` (setup, once per triangle), exactly
    /// `floor(2^K/|d|)` and `ceil(2^K/|d|)` without a 128-bit divide: with `a = |d| ≥ 2`,
    /// `2^64 = q0·a + r0` (one 64-bit divide of `2^64 − 1`, corrected by one step), so
    /// `2^80 = 2^16·q0·a + 2^16·r0` and `floor(2^80/a) = 2^16·q0 + floor(r0·2^16/a)`, the last
    /// term by [`frac_div`] (r0 < a); the ceiling adds 1 when anything remains. `a = 1` gives
    /// 2^80 for both; `d = 0` gives 0 for both (never used: `solve` decides d = 0 by sign).
    /// `interval_corners::recip_matches_i128` compares with the i128 division at the range's
    /// corners.
    // Ranges: a ≤ 2^63 (|i64|); q0 = floor((2^64 − 1)/a) ≤ 2^63 so q0·a ≤ 2^64 − 1 and
    // m = 2^64 − 1 − q0·a ∈ [0, a − 1]: r0 = m + 1 ∈ [1, a] ≤ 2^63 (r0 = a means a | 2^64, then
    // q0 + 1 ≤ 2^63 and r0 = 0); 2^16·q0 < 2^80 and the fraction < 2^16: far inside i128.
    #[allow(clippy::arithmetic_side_effects)]
    pub fn new(d: i64) -> RecipConstraint {
        // 2^RECIP_SHIFT = 2^80 < 2^126: a constant shift, checked by the compiler.
        const RECIP_ONE: i128 = 1i128 << crate::config::formats::RECIP_SHIFT;
        const _: () = assert!(crate::config::formats::RECIP_SHIFT == 64 + TUV_FRAC);
        let a = d.unsigned_abs();
        let (r_up, r_dn) = match a {
            0 => (0, 0),
            1 => (RECIP_ONE, RECIP_ONE),
            _ => {
                let mut q0 = u64::MAX / a;
                let mut r0 = u64::MAX - q0 * a + 1;
                if r0 == a {
                    q0 += 1;
                    r0 = 0;
                }
                match frac_div(r0, a, TUV_FRAC) {
                    Some((f, rem)) => {
                        let dn = i128::from(q0) * i128::from(TUV_ONE) + i128::from(f);
                        (dn + i128::from(rem), dn)
                    }
                    None => (0, 0),
                }
            }
        };
        RecipConstraint { d, r_up, r_dn }
    }

    /// `{ s ∈ [0,1] : s·d ≤ n }` rounded outward, using the reciprocals.
    ///
    /// Proof of outwardness: for d > 0 and 0 ≤ n < d the true end is n/d ≤ n·r_up/2^K, and the
    /// shift to 16 fraction bits rounds up (ceil); for d < 0 and 0 < −n ≤ |d| the true end is
    /// (−n)/|d| ≥ (−n)·r_dn/2^K and the shift floors. Range: n < |d| < 2^60 and r ≤ 2^80 +1, so
    /// the product is < 2^K + 2^60 < 2^81 (no overflow in i128).
    ///
    /// The products are `checked_mul` anyway; should one fail, the interval falls back to the
    /// whole unit range (conservative: nothing is culled).
    pub fn solve(&self, n: i64) -> Option<Interval> {
        let d = self.d;
        if d > 0 {
            if n < 0 {
                return None;
            }
            if n >= d {
                return Some(Interval::UNIT);
            }
            let hi = mul_shr64(n.unsigned_abs(), self.r_up, true).unwrap_or(i128::from(TUV_ONE));
            Some(Interval {
                lo: 0,
                hi: clamp_raw(hi),
            })
        } else if d < 0 {
            if n >= 0 {
                return Some(Interval::UNIT);
            }
            // The magnitudes (`unsigned_abs` is exact for every i64).
            let (a, b) = (d.unsigned_abs(), n.unsigned_abs());
            if b > a {
                return None;
            }
            let lo = mul_shr64(b, self.r_dn, false).unwrap_or(0);
            Some(Interval {
                lo: clamp_raw(lo),
                hi: TUV_ONE,
            })
        } else if n >= 0 {
            Some(Interval::UNIT)
        } else {
            None
        }
    }
}

/// `ceil(n·r/2^64)` (`up`) or the floor, for `n ≤ 2^63` and `0 ≤ r < 2^81` (a
/// reciprocal): `r = r_hi·2^64 + r_lo` with `r_hi < 2^17`, so
/// `n·r/2^64 = n·r_hi + n·r_lo/2^64`, and the second term's floor is the high half of the
/// 64 × 64 → 128-bit product `n·r_lo` (the low half decides the ceiling). The same quotient as
/// an i128 product and divide, with one widening multiply and no 128 × 128 one. `None` if an
/// operand is outside that range or the sum leaves i128 (never for [`RecipConstraint::solve`]:
/// n < |d| makes `n·r/2^64 < 2^16 + 1`). `interval_corners::recip_solve_matches_i128_product`
/// compares [`RecipConstraint::solve`] with the i128 product and divide.
// Ranges: n·r_lo < 2^128 in u128 (both < 2^64); its high half < 2^64; n·r_hi is a checked
// u64 product; the final sums are checked.
#[allow(clippy::arithmetic_side_effects)]
fn mul_shr64(n: u64, r: i128, up: bool) -> Option<i128> {
    const _: () = assert!(crate::config::formats::RECIP_SHIFT - TUV_FRAC == 64);
    let r = u128::try_from(r).ok()?;
    let r_hi = u64::try_from(r.checked_shr(64)?).ok()?;
    let r_lo = u64::try_from(r & u128::from(u64::MAX)).ok()?;
    let p = u128::from(n) * u128::from(r_lo);
    let p_hi = u64::try_from(p.checked_shr(64)?).ok()?;
    let p_lo_nonzero = p & u128::from(u64::MAX) != 0;
    let q = n.checked_mul(r_hi)?.checked_add(p_hi)?;
    let q = q.checked_add(u64::from(up && p_lo_nonzero))?;
    Some(i128::from(q))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solve_le_cases() {
        // s·4 ≤ 1 → s ≤ 1/4 exactly.
        assert_eq!(
            solve_le(4, 1),
            Some(Interval {
                lo: 0,
                hi: TUV_ONE / 4
            })
        );
        // s·3 ≤ 1 → s ≤ 0.3333…, rounded up.
        assert_eq!(solve_le(3, 1), Some(Interval { lo: 0, hi: 21846 }));
        // s·(−3) ≤ −1 → s ≥ 1/3, rounded down.
        assert_eq!(
            solve_le(-3, -1),
            Some(Interval {
                lo: 21845,
                hi: TUV_ONE
            })
        );
        assert_eq!(solve_le(1, -1), None);
        assert_eq!(solve_le(-1, -2), None);
        assert_eq!(solve_le(0, 0), Some(Interval::UNIT));
        assert_eq!(solve_le(0, -1), None);
        assert_eq!(solve_le(2, 5), Some(Interval::UNIT));
    }

    #[test]
    fn recip_agrees_with_exact_or_is_wider() {
        for d in [-1000i64, -7, -3, -1, 1, 3, 7, 1000, 1 << 40] {
            let c = RecipConstraint::new(d);
            for n in [-2000i64, -999, -5, -1, 0, 1, 2, 5, 999, 2000, 1 << 39] {
                let exact = solve_le(d as i128, n as i128);
                let fast = c.solve(n);
                match (exact, fast) {
                    (None, None) => {}
                    (Some(e), Some(f)) => {
                        assert!(f.lo <= e.lo && f.hi >= e.hi, "d={d} n={n} {e:?} {f:?}");
                        assert!(e.lo - f.lo <= 1 && f.hi - e.hi <= 1, "d={d} n={n}");
                    }
                    _ => panic!("emptiness differs d={d} n={n}"),
                }
            }
        }
    }
}
