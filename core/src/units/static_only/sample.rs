//! The static-only unit's sample test: three fill-adjusted edge values and the depth, bit for
//! bit the planar test (module docs of [`crate::units::static_only`]).

use crate::sample::planar::depth;
use crate::sample::pos::{Hit, ScreenPos};
use crate::units::static_only::setup::StaticSetup;
use crate::units::static_only::setup::{dxy, edge};

/// The static sample test at screen position `pos`: bit for bit the planar test's result
/// (module docs); `None` outside the viewport.
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_wrap)]
pub fn static_test(s: &StaticSetup, pos: ScreenPos) -> Option<Hit> {
    let [ew, eh] = s.end;
    if pos.xs >= ew || pos.ys >= eh {
        return None;
    }
    // xs, ys < 2^19: exact in i32.
    let (dx, dy) = dxy(s, pos.xs as i32, pos.ys as i32);
    for (ab, &c) in s.ab.iter().zip(s.c.iter()) {
        if edge(ab, c, dx, dy) < 0 {
            return None;
        }
    }
    Some(Hit {
        depth: static_depth(s, dx, dy),
    })
}

/// The planar test's depth ([`crate::sample::planar`]: `⌊Σ G_i·d_i / 2^min(f, 63)⌋` saturated to
/// [`DEPTH_NEAR`, `DEPTH_FAR`]) with the constant term `G_2·d_w` from setup: the same sum, the
/// same bits. When setup found that no position of the viewport saturates ([`depth_split`]:
/// `1 ≤ f ≤ 63` and the quotient inside the depth range at the viewport's four corner
/// positions — the sum is affine in the position and the floor monotone, so its extremes are
/// at the corners) the quotient `q = ⌊acc / 2^f⌋` is the depth as it stands and is formed from
/// the sum's two 32-bit words `acc = hi·2^32 + lo` (`hi = ⌊acc / 2^32⌋`, `lo` ∈ [0, 2^32))
/// without a 64-bit variable shift: `q = (hi >> sh)·m + ⌊lo·m / 2^32⌋` modulo 2^32, with
/// - `f ≤ 31`: `sh = 0`, `m = 2^(32−f)` ∈ [2, 2^31]: `acc / 2^f = hi·m + lo·m / 2^32` and `hi·m`
///   is an integer, so `q = hi·m + ⌊lo·m / 2^32⌋` (the high word of the 32 × 32 → 64 unsigned
///   product `lo·m` < 2^63);
/// - `f ≥ 32`: `sh = f − 32` ∈ [0, 31], `m = 1`: `q = ⌊⌊acc / 2^32⌋ / 2^(f−32)⌋ = hi >> sh`,
///   and `⌊lo / 2^32⌋ = 0`.
///
/// `q` ∈ [DEPTH_NEAR, DEPTH_FAR] ⊂ i32 and the wrapping u32 sum is congruent to it modulo
/// 2^32, so its i32 reading is `q` exactly. Otherwise (`fast` false) the planar test's own
/// function decides.
#[inline(always)]
#[allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_truncation,
    clippy::cast_possible_wrap,
    clippy::cast_sign_loss
)]
fn static_depth(s: &StaticSetup, dx: i32, dy: i32) -> i32 {
    if !s.fast {
        return depth(&s.g, s.f, &[dx, dy, s.wh]);
    }
    let [g0, g1, _] = s.g;
    // |G·d| ≤ 2^61 each, three terms < 2^63 (`planar.rs`).
    let acc = s.gw + i64::from(g0) * i64::from(dx) + i64::from(g1) * i64::from(dy);
    split_floor(acc, s.sh, s.m)
}

/// `(hi >> sh)·m + ⌊lo·m / 2^32⌋` modulo 2^32 read as i32, `acc = hi·2^32 + lo` ([`static_depth`];
/// `sh` < 32: the shift is in range; `lo·m` < 2^64 in u64).
#[inline(always)]
#[allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_truncation,
    clippy::cast_possible_wrap,
    clippy::cast_sign_loss
)]
pub(crate) fn split_floor(acc: i64, sh: u32, m: u32) -> i32 {
    let (hi, lo) = ((acc >> 32) as i32, acc as u32);
    let low = ((u64::from(lo) * u64::from(m)) >> 32) as u32;
    ((hi >> sh) as u32).wrapping_mul(m).wrapping_add(low) as i32
}
