//! What a configuration's core perturbs, against the exact inputs: the rounding of every input
//! onto its grids ([`Rounding`]) and the bounded sample test's own vertex perturbation
//! ([`eps_of`]). The comparison's bound (`crate::compare::bound`) and the error statements
//! ([`super::dq`]) are built from these two.
//!
//! **Rounding of the inputs**: clip x, y, w and CoC c of each vertex end by at most
//! `δp = 2^-(POS+1)` (round to nearest); t, u, v by at most `δt = 2^-17` (round to 16 bits), plus
//! `2^-(TUV+1)` when TUV < 16 (the second rounding to the coarser grid); the sub-pixel position
//! is floored, `0 ≤ x − x' < 1/256` px (same for y).

use uvt_core::Setup;

/// The largest rounding of each kind of input the core saw (module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rounding {
    /// clip x, y, w and CoC of every vertex end: |core − exact| ≤ `pos`
    pub pos: f64,
    /// t, u, v: |core − exact| ≤ `tuv`
    pub tuv: f64,
    /// sub-pixel x, y: 0 ≤ exact − core < `sub` px
    pub sub: f64,
}

impl Rounding {
    /// Inputs rounded to nearest on a `pos`-fraction-bit position grid and (via 16 bits) a
    /// `tuv`-fraction-bit t/u/v grid; sub-pixel floored to 1/256 px (`Pattern::with_tuv`,
    /// `SceneTri::to_core_with`).
    pub fn at(pos: u32, tuv: u32) -> Rounding {
        let half = |bits: u32| 2f64.powi(-(bits as i32) - 1);
        Rounding {
            pos: half(pos),
            tuv: half(16) + if tuv < 16 { half(tuv) } else { 0.0 },
            sub: 1.0 / 256.0,
        }
    }

    /// The default precision: 16 fraction bits for positions and t/u/v.
    pub fn default_precision() -> Rounding {
        Rounding::at(16, 16)
    }
}

/// The perturbation bound of the core's sample test for a setup, clip units `[x, y, w]`: the
/// bounded test decides exactly on a triangle whose vertices lie within `Setup::eps()` (raw
/// 2^-16, rounded up) of the exact test's at the same quantized inputs (`uvt_core::sample::bounded`);
/// zero for the exact test.
pub fn eps_of(s: &Setup) -> [f64; 3] {
    let e = s.eps();
    let raw = |v: i32| f64::from(v) / 65536.0;
    [raw(e.x()[0]), raw(e.x()[1]), raw(e.w())]
}
