//! A 192-bit signed accumulator for the exact edge functions of the sample test.
//!
//! A [`Wide`] holds `hi · 2^64 + lo` with `hi: i128` and `lo ∈ [0, 2^64)`: 192 bits, two's
//! complement in spirit. Only the operations the sample test needs exist: multiply-accumulate of
//! an `i128` by an `i64`, the sign, and a floor shift to a small integer. Every step is proven in
//! range in its comment; the ranges are those of `formats.rs` (|a| < 2^126, |b| ≤ 2^63, at most
//! three terms, so |hi| < 2^126 at all times).

/// 192-bit signed integer `hi · 2^64 + lo`, `lo` unsigned.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Wide {
    hi: i128,
    lo: u64,
}

const MASK64: i128 = (1i128 << 64) - 1;

impl Wide {
    /// Zero.
    pub const ZERO: Wide = Wide { hi: 0, lo: 0 };

    /// The value of a plain `i128`.
    // The mask keeps bits 0..64, so the value is in [0, 2^64) and the sign-dropping cast to u64
    // is exact.
    #[allow(clippy::cast_sign_loss, clippy::cast_possible_truncation)]
    pub fn from_i128(x: i128) -> Wide {
        // x = (x >> 64) · 2^64 + (x & MASK64), the shift floors so the low part is non-negative.
        Wide {
            hi: x >> 64,
            lo: (x & MASK64) as u64,
        }
    }

    /// `self + x`. Caller keeps |self| < 2^190 (three terms of < 2^189 each).
    #[inline]
    // Ranges on each line below; `hi` uses wrapping adds whose true sum is proven in range, so
    // wrapping never happens. Casts: `x & MASK64` ∈ [0, 2^64) (sign-free), `s as u64` keeps the
    // low 64 bits on purpose (the carry is `s >> 64` ∈ {0, 1}, which fits i128).
    #[allow(
        clippy::arithmetic_side_effects,
        clippy::cast_sign_loss,
        clippy::cast_possible_truncation,
        clippy::cast_possible_wrap
    )]
    fn add_i128(&mut self, x: i128) {
        let xh = x >> 64; // |xh| < 2^63
        let xl = (x & MASK64) as u128; // < 2^64
        let s = self.lo as u128 + xl; // < 2^65: no overflow in u128
        self.lo = s as u64;
        // hi grows by < 2^63 + 1 per call and stays < 2^126 over three calls of ≤ 2^125 each.
        self.hi = self.hi.wrapping_add(xh).wrapping_add((s >> 64) as i128);
    }

    /// `self + a · b` exactly, for |a| < 2^127 and |b| ≤ 2^63.
    #[inline]
    // ah·b: |ah| ≤ 2^63, |b| ≤ 2^63, so |ah·b| ≤ 2^126; al·b: 0 ≤ al < 2^64, so |al·b| < 2^127.
    // Both fit i128; `a >> 64` and `a & MASK64` cannot overflow.
    #[allow(clippy::arithmetic_side_effects)]
    pub fn mul_add(&mut self, a: i128, b: i64) {
        let ah = a >> 64; // |ah| ≤ 2^63
        let al = a & MASK64; // [0, 2^64)
                             // ah·b: |.| ≤ 2^126, fits i128; it is a multiple of 2^64, so it goes into hi directly.
        self.hi = self.hi.wrapping_add(ah * b as i128);
        // al·b: |.| < 2^64 · 2^63 = 2^127, fits i128.
        self.add_i128(al * b as i128);
    }

    /// Sign: -1, 0 or 1.
    #[inline]
    pub fn signum(&self) -> i32 {
        if self.hi < 0 {
            -1
        } else if self.hi > 0 || self.lo > 0 {
            1
        } else {
            0
        }
    }

    /// Number of significant bits of the value, counting a negative value `v` as `!v = -v-1`
    /// (so `-1` and `0` have length 0). At most 191.
    // leading_zeros ≤ 128 and ≤ 64: both subtractions stay in [0, 128]; the sum ≤ 192.
    #[allow(clippy::arithmetic_side_effects)]
    pub fn bit_len(&self) -> u32 {
        let (h, l) = if self.hi < 0 {
            (!self.hi, !self.lo)
        } else {
            (self.hi, self.lo)
        };
        if h != 0 {
            64 + (128 - h.leading_zeros())
        } else {
            64 - l.leading_zeros()
        }
    }

    /// `floor(self / 2^s)` as `i128`, exact; `None` when the quotient does not fit in `i128`
    /// (the caller picks `s` so that it does: the sample test keeps `bit_len() − s ≤ 32`).
    ///
    /// No left shift: `s ≥ 64` divides `hi` by `2^(s−64)` (floor; `lo < 2^64` only adds a
    /// fraction < 1 at that scale); `s < 64` forms `hi·2^(64−s) + floor(lo/2^s)` with a
    /// `checked_mul` and `checked_add`, so no bit can be lost unnoticed.
    pub fn shr_floor(&self, s: u32) -> Option<i128> {
        match s.checked_sub(64) {
            // |hi| < 2^127, so a shift of 127 or more leaves the sign only: floor is −1 or 0.
            Some(k) if k >= 127 => Some(if self.hi < 0 { -1 } else { 0 }),
            // k ≤ 126: 2^k fits i128; div_euclid by a positive divisor is the floor.
            Some(k) => self.hi.checked_div_euclid(2i128.checked_pow(k)?),
            None => {
                // 64 − s ∈ [1, 64]: 2^(64−s) ≤ 2^64 fits i128.
                let scale = 2i128.checked_pow(64u32.checked_sub(s)?)?;
                let low = i128::from(self.lo.checked_shr(s)?);
                self.hi.checked_mul(scale)?.checked_add(low)
            }
        }
    }

    /// Raw parts `(hi, lo)` for export: value = hi·2^64 + lo.
    pub fn parts(&self) -> (i128, u64) {
        (self.hi, self.lo)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mul_add_matches_i128_in_range() {
        let cases: [(i128, i64); 6] = [
            (5, 7),
            (-5, 7),
            (1 << 100, -3),
            (-(1 << 90), i64::MIN),
            ((1 << 120) - 1, 1),
            (0, 9),
        ];
        for (a, b) in cases {
            let mut w = Wide::ZERO;
            w.mul_add(a, b);
            let exact = a.checked_mul(b as i128);
            if let Some(e) = exact {
                assert_eq!(w, Wide::from_i128(e), "a={a} b={b}");
                assert_eq!(w.signum(), e.signum() as i32);
                assert_eq!(w.shr_floor(0), Some(e));
                assert_eq!(w.shr_floor(3), Some(e >> 3));
            }
        }
    }

    #[test]
    fn large_products_sign_and_shift() {
        // (2^125) · (2^62) = 2^187: beyond i128, exact here.
        let mut w = Wide::ZERO;
        w.mul_add(1 << 125, 1 << 62);
        assert_eq!(w.signum(), 1);
        assert_eq!(w.bit_len(), 188);
        assert_eq!(w.shr_floor(180), Some(128));
        w.mul_add(-(1 << 125), 1 << 62);
        assert_eq!(w, Wide::ZERO);
        w.mul_add(-(1 << 125), 1 << 62);
        assert_eq!(w.signum(), -1);
        assert_eq!(w.shr_floor(180), Some(-128));
        // -1 has length 0, 1 has length 1.
        assert_eq!(Wide::from_i128(-1).bit_len(), 0);
        assert_eq!(Wide::from_i128(1).bit_len(), 1);
    }
}
