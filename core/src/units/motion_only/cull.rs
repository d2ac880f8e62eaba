//! The motion-only unit's tile cull: the time slabs whose screen box meets a bounds tile (module
//! docs of [`crate::units::motion_only`]).

use crate::input::PixelRect;
use crate::stats::Ops;
use crate::units::motion_only::setup::{MotionSetup, SLABS};

/// The slab of a sample's raw t ∈ [0, 2^16]: `min(⌊T·K/2^16⌋, K − 1)` (module docs).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_sign_loss)]
pub fn slab_of(t: i32) -> usize {
    // T ∈ [0, 2^16] (a checked `Sample`): T·K ≤ 2^18, non-negative.
    ((t.max(0) as usize * SLABS) >> 16).min(SLABS - 1)
}

/// The slabs whose box meets bounds tile `cell`, as a bit mask (bit j: slab j; 0: the tile holds
/// no covered sample). Counts its operations in `ops.bounds`.
pub fn motion_tile(m: &MotionSetup, cell: PixelRect, ops: &mut Ops) -> u8 {
    // One rectangle test (4 compares) per slab.
    const TILE_OPS: u64 = 16;
    ops.add_bounds(TILE_OPS);
    let mut mask = 0u8;
    for (bit, s) in [1u8, 2, 4, 8].iter().zip(m.slabs.iter()) {
        if !s.intersect(&cell).is_empty() {
            mask |= bit;
        }
    }
    mask
}
