//! Seeded random numbers for the core's unit tests: `UVT_SEED` (printed on failure by the
//! tests), `UVT_EXTENSIVE=1` for many more cases (same conventions as `tests/src/lib.rs`).
#![allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_wrap,
    clippy::cast_possible_truncation
)]

/// `UVT_SEED` or a fixed default.
pub fn seed() -> u64 {
    std::env::var("UVT_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0x5eed_0001)
}

/// `quick` cases normally, `slow` with `UVT_EXTENSIVE=1`.
pub fn cases(quick: u32, slow: u32) -> u32 {
    if std::env::var("UVT_EXTENSIVE").is_ok_and(|v| v != "0") {
        slow
    } else {
        quick
    }
}

/// SplitMix64.
pub struct Rng(pub u64);

impl Rng {
    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    /// Uniform-ish in `[-m, m]` with a bias to the ends and to small values (`m ≥ 1`).
    pub fn signed(&mut self, m: i64) -> i64 {
        let r = self.next_u64();
        let mag = match r % 8 {
            0 => m,
            1 => m - 1,
            2 => (r >> 8) as i64 % 4,
            3 => (r >> 8) as i64 % 64,
            4 => ((r >> 8) as i64 % m.max(1)) >> ((r >> 40) % 40),
            _ => (r >> 8) as i64 % (m + 1),
        };
        if r & (1 << 60) != 0 {
            -mag
        } else {
            mag
        }
    }
}
