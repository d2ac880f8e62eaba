//! # uvt-testkit
//!
//! The one seeded random number generator of uvt's tests — the core's unit tests and the
//! integration tests alike — and their two switches: `UVT_SEED` (the seed, printed by every
//! failing seeded test so the failure can be rerun) and `UVT_EXTENSIVE=1` (many more cases, for
//! long soaks). Test code only: no product crate depends on it.
#![forbid(unsafe_code)]
#![deny(missing_docs)]

/// Environment variable holding the seed of the seeded-random tests.
pub const SEED_VAR: &str = "UVT_SEED";
/// Environment variable that switches on the slow extensive mode.
pub const EXTENSIVE_VAR: &str = "UVT_EXTENSIVE";

/// The seed for seeded-random tests: `UVT_SEED` or a fixed default.
pub fn seed() -> u64 {
    std::env::var(SEED_VAR)
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0x5eed_0001)
}

/// Whether the slow extensive mode is on (`UVT_EXTENSIVE` set and not `0`).
pub fn extensive() -> bool {
    std::env::var(EXTENSIVE_VAR).is_ok_and(|v| v != "0")
}

/// Number of cases: `quick` normally, `slow` in extensive mode.
pub fn cases(quick: u32, slow: u32) -> u32 {
    if extensive() {
        slow
    } else {
        quick
    }
}

/// SplitMix64: small, well-known, deterministic.
#[derive(Clone, Debug)]
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
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    /// Uniform integer in [0, n).
    pub fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n.max(1)
    }
    /// Uniform-ish integer in `[lo, hi]` (`lo ≤ hi`; the remainder of the next 64 bits).
    pub fn int_range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next_u64() % ((hi - lo + 1) as u64)) as i64
    }
    /// In `[lo, hi]`, a third of the time one of the ends or the neighbour of `lo`.
    pub fn biased(&mut self, lo: i64, hi: i64) -> i64 {
        match self.next_u64() % 9 {
            0 => lo,
            1 => hi,
            2 => (lo + 1).min(hi),
            _ => self.int_range(lo, hi),
        }
    }
    /// In `[-m, m]` with a bias to the ends and to small values (`m ≥ 1`): the domain-corner
    /// draws of the core's tests.
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

impl rand_core::RngCore for Rng {
    fn next_u32(&mut self) -> u32 {
        (self.next_u64() >> 32) as u32
    }
    fn next_u64(&mut self) -> u64 {
        Rng::next_u64(self)
    }
    fn fill_bytes(&mut self, dest: &mut [u8]) {
        rand_core::impls::fill_bytes_via_next(self, dest)
    }
    fn try_fill_bytes(&mut self, dest: &mut [u8]) -> Result<(), rand_core::Error> {
        self.fill_bytes(dest);
        Ok(())
    }
}
