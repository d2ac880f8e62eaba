//! Closed intervals of t, u or v in the raw t/u/v format, and the two solvers every bound uses.
//!
//! Both solvers answer "for which s ∈ [0, 1] does `s·d ≤ n` hold?" for exact integers `d`, `n`
//! and round the answer outward to the t/u/v grid (upper ends up, lower ends down). Every bound in
//! `setup.rs` and `bounds.rs` is a conjunction of such linear constraints.

use crate::error::Error;
use crate::formats::{ceil_div, floor_div, TUV_FRAC, TUV_ONE};

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
        self.lo <= x && x <= self.hi
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

/// `{ s ∈ [0,1] : s·d ≤ n }` by exact division, ends rounded outward; `None` if empty.
///
/// Cases: d > 0 gives s ≤ n/d (ceil), d < 0 gives s ≥ (−n)/(−d) (floor), d = 0 gives all or
/// nothing. If `n·2^16` would overflow (|n| ≥ 2^111, far outside the documented ranges) the
/// answer is the whole unit interval or, where the sign already decides, empty: conservative.
pub fn solve_le(d: i128, n: i128) -> Option<Interval> {
    let full = Some(Interval::UNIT);
    if d > 0 {
        if n < 0 {
            return None;
        }
        if n >= d {
            return full;
        }
        match n.checked_mul(1 << TUV_FRAC).and_then(|m| ceil_div(m, d)) {
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
        match b.checked_mul(1 << TUV_FRAC).and_then(|m| floor_div(m, a)) {
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

    /// Precompute the reciprocals of `d` (setup, once per triangle).
    pub fn new(d: i64) -> RecipConstraint {
        const K: i128 = 1i128 << crate::formats::RECIP_SHIFT;
        let k = K;
        // |d| ≤ 2^63 as i128: abs exact.
        let a = i128::from(d).saturating_abs();
        let (r_up, r_dn) = match (ceil_div(k, a), floor_div(k, a)) {
            (Some(u), Some(l)) => (u, l),
            _ => (0, 0),
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
        // 2^(K − 16) = 2^64 as a constant (no run-time shift).
        const SH: i128 = 1i128 << (crate::formats::RECIP_SHIFT - TUV_FRAC);
        let (d, n) = (i128::from(self.d), i128::from(n));
        if d > 0 {
            if n < 0 {
                return None;
            }
            if n >= d {
                return Some(Interval::UNIT);
            }
            let hi = n
                .checked_mul(self.r_up)
                .and_then(|p| ceil_div(p, SH))
                .unwrap_or(i128::from(TUV_ONE));
            Some(Interval {
                lo: 0,
                hi: clamp_raw(hi),
            })
        } else if d < 0 {
            // |d|, |n| ≤ 2^63 as i128: negation exact.
            let (a, b) = (d.checked_neg()?, n.checked_neg()?);
            if b <= 0 {
                return Some(Interval::UNIT);
            }
            if b > a {
                return None;
            }
            let lo = b
                .checked_mul(self.r_dn)
                .and_then(|p| floor_div(p, SH))
                .unwrap_or(0);
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
