//! Coverage from the model itself: the decision paths a sample test takes, reported by the code
//! that computes its outputs. [`bins`] is the one registry of the bins (stable names, the record
//! kind each belongs to, and for a bin no input can reach the reason); a [`Probe`] is the
//! parameter through which the tests report them. [`NoProbe`] (what every unprobed entry point
//! passes) is zero-sized and its [`Probe::hit`] empty and always inlined, so the optimiser
//! removes every report where nobody reads it; [`Counts`] counts them (no heap).
//!
//! A bin counts decisions, not records: one record hits an edge bin three times (one per edge)
//! and a rounding bin once per rounding of that step.

pub mod bins;

pub use bins::Bin;

/// Where a decision path reports itself. The tests call these methods only (never code of
/// their own for a report), so that in their generic form each report is one opaque call and
/// with [`NoProbe`] nothing at all: not even the report's operands are formed.
pub trait Probe {
    /// Whether the probe reads anything (the tests take the probed out-of-line helpers only
    /// where it does).
    const ON: bool = true;
    /// The path `bin` was taken once.
    fn hit(&mut self, bin: Bin);
    /// `yes` if `cond`, else `no`.
    fn pick(&mut self, cond: bool, yes: Bin, no: Bin);
    /// The sign of `x`: `bins` = (negative, zero, positive).
    fn sign(&mut self, x: i64, bins: [Bin; 3]);
    /// A rounding to nearest, ties up, of `p` to a multiple of 2^`bits` (`bits` in 1..=63):
    /// `bins` = (exact, down, up), by the part it discards.
    fn round(&mut self, p: i64, bits: u32, bins: [Bin; 3]);
}

/// The probe nobody reads: zero-sized, every report compiled away.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoProbe;

impl Probe for NoProbe {
    const ON: bool = false;
    #[inline(always)]
    fn hit(&mut self, _bin: Bin) {}
    #[inline(always)]
    fn pick(&mut self, _cond: bool, _yes: Bin, _no: Bin) {}
    #[inline(always)]
    fn sign(&mut self, _x: i64, _bins: [Bin; 3]) {}
    #[inline(always)]
    fn round(&mut self, _p: i64, _bits: u32, _bins: [Bin; 3]) {}
}

/// Hits per bin, indexed by [`Bin::index`] (saturating at `u32::MAX`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Counts {
    /// the count of every bin of [`Bin::ALL`], in that order
    pub n: [u32; Bin::COUNT],
}

impl Default for Counts {
    #[inline]
    fn default() -> Self {
        Counts { n: [0; Bin::COUNT] }
    }
}

impl Counts {
    /// The count of `bin`.
    #[must_use]
    #[inline]
    pub fn get(&self, bin: Bin) -> u32 {
        self.n.get(bin.index()).copied().unwrap_or(0)
    }

    /// Add `other`'s counts (saturating).
    #[inline]
    pub fn add(&mut self, other: &Counts) {
        for (a, b) in self.n.iter_mut().zip(other.n.iter()) {
            *a = a.saturating_add(*b);
        }
    }
}

impl Probe for Counts {
    #[inline]
    fn hit(&mut self, bin: Bin) {
        if let Some(c) = self.n.get_mut(bin.index()) {
            *c = c.saturating_add(1);
        }
    }

    #[inline]
    fn pick(&mut self, cond: bool, yes: Bin, no: Bin) {
        self.hit(if cond { yes } else { no });
    }

    #[inline]
    fn sign(&mut self, x: i64, bins: [Bin; 3]) {
        let [neg, zero, pos] = bins;
        self.hit(match x.signum() {
            -1 => neg,
            0 => zero,
            _ => pos,
        });
    }

    #[inline]
    #[allow(clippy::arithmetic_side_effects, clippy::cast_sign_loss)]
    fn round(&mut self, p: i64, bits: u32, bins: [Bin; 3]) {
        let [exact, down, up] = bins;
        // bits ∈ 1..=63: the mask and the half step fit u64.
        let frac = (p as u64) & ((1u64 << bits) - 1);
        let half = 1u64 << (bits - 1);
        self.hit(if frac == 0 {
            exact
        } else if frac < half {
            down
        } else {
            up
        });
    }
}

/// Whether `pr`'s type reads anything ([`Probe::ON`]).
#[inline(always)]
pub(crate) const fn on<Pr: Probe>(_pr: &Pr) -> bool {
    Pr::ON
}
