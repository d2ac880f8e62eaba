//! Magnitude bounds `m·2^e` with exact, saturating integer arithmetic: the width table's number.

use core::fmt;

/// A non-negative magnitude bound `m·2^e` (exact; `m` odd or zero after normalisation).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mag {
    m: u128,
    e: u32,
}

impl Mag {
    /// Zero.
    pub const ZERO: Mag = Mag { m: 0, e: 0 };
    /// The integer `n`.
    pub const fn int(n: u128) -> Mag {
        Mag { m: n, e: 0 }.norm()
    }
    /// `2^k`.
    pub const fn pow2(k: u32) -> Mag {
        Mag { m: 1, e: k }
    }
    const fn norm(self) -> Mag {
        if self.m == 0 {
            return Mag::ZERO;
        }
        let tz = self.m.trailing_zeros();
        Mag {
            m: self.m.wrapping_shr(tz),
            e: self.e.saturating_add(tz),
        }
    }
    /// Magnitude bits: the bit length of `m·2^e`.
    pub const fn mag_bits(self) -> u32 {
        if self.m == 0 {
            return 0;
        }
        u128::BITS
            .saturating_sub(self.m.leading_zeros())
            .saturating_add(self.e)
    }
    /// Signed width (two's complement, sign included) of a register holding `[−self, self]`.
    pub const fn bits(self) -> u32 {
        self.mag_bits().saturating_add(1)
    }
    /// The value, when it fits `u128`.
    pub const fn to_u128(self) -> Option<u128> {
        if self.m == 0 {
            return Some(0);
        }
        if self.mag_bits() > u128::BITS {
            return None;
        }
        Some(self.m.wrapping_shl(self.e))
    }
    /// Product (exact while the mantissas' product fits `u128`, else rounded up).
    pub const fn mul(self, o: Mag) -> Mag {
        let e = self.e.saturating_add(o.e);
        match self.m.checked_mul(o.m) {
            Some(m) => Mag { m, e }.norm(),
            // Rounded up to a power of two (only for ≥ 128-bit mantissa products).
            None => Mag::pow2(
                e.saturating_add(self.mag_bits().saturating_sub(self.e))
                    .saturating_add(o.mag_bits().saturating_sub(o.e)),
            ),
        }
    }
    /// Sum (exact while the aligned mantissas fit `u128`, else rounded up).
    pub const fn add(self, o: Mag) -> Mag {
        if self.m == 0 {
            return o;
        }
        if o.m == 0 {
            return self;
        }
        let (lo, hi) = if self.e <= o.e { (self, o) } else { (o, self) };
        let d = hi.e.saturating_sub(lo.e);
        if d < 127 {
            if let Some(h) = hi.m.checked_mul(1u128.wrapping_shl(d)) {
                if let Some(m) = h.checked_add(lo.m) {
                    return Mag { m, e: lo.e }.norm();
                }
            }
        }
        // The smaller term is < 2^(mag_bits): round the sum up to the next power of two.
        let b = if hi.mag_bits() >= lo.mag_bits() {
            hi.mag_bits()
        } else {
            lo.mag_bits()
        };
        Mag::pow2(b.saturating_add(1))
    }
    /// `self·k` for a small constant.
    pub const fn times(self, k: u128) -> Mag {
        self.mul(Mag::int(k))
    }
    /// `floor(self / 2^s)` (exact).
    pub const fn shr_floor(self, s: u32) -> Mag {
        if self.e >= s {
            return Mag {
                m: self.m,
                e: self.e.wrapping_sub(s),
            };
        }
        let k = s.wrapping_sub(self.e);
        if k >= 128 {
            return Mag::ZERO;
        }
        Mag::int(self.m.wrapping_shr(k))
    }
    /// The larger of two bounds.
    pub const fn max(self, o: Mag) -> Mag {
        let (a, b) = (self.mag_bits(), o.mag_bits());
        if a != b {
            return if a > b { self } else { o };
        }
        // Same bit length: compare the mantissas aligned to the smaller exponent.
        let (s, t) = (self.shr_floor(0), o);
        if s.e <= t.e {
            let d = t.e.wrapping_sub(s.e);
            if t.m.wrapping_shl(d) >= s.m {
                t
            } else {
                s
            }
        } else {
            let d = s.e.wrapping_sub(t.e);
            if s.m.wrapping_shl(d) >= t.m {
                s
            } else {
                t
            }
        }
    }
}

impl fmt::Display for Mag {
    /// `n` below 2^20, `2^e` or `m·2^e` for small m, else the exact decimal (≤ 2^64) or `m·2^e`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.to_u128() {
            Some(v) if v < 1 << 20 => write!(f, "{v}"),
            _ if self.m == 1 => write!(f, "2^{}", self.e),
            _ if self.m < 1000 => write!(f, "{}·2^{}", self.m, self.e),
            Some(v) if v <= 1 << 64 => write!(f, "{v}"),
            _ => write!(f, "{}·2^{}", self.m, self.e),
        }
    }
}
