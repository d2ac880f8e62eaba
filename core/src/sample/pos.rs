//! The sample's screen position, its scaled direction and a hit: shared by every sample test.

use crate::config::formats::SUBPIXEL_BITS;
use crate::input::{Sample, Viewport};

/// 2^8: one pixel in sample-position units.
const SUBPIXEL_SCALE: u32 = 1 << SUBPIXEL_BITS;

/// A sample's screen position in 1/256 pixel: `xs = 256·column + sx`, `ys = 256·row + sy`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ScreenPos {
    /// x in 1/256 pixels
    pub xs: u32,
    /// y in 1/256 pixels (downward)
    pub ys: u32,
}

impl ScreenPos {
    /// Position of `sample` in pixel (`px`, `py`).
    // px, py < 2^16 and the sub-pixel offset < 2^8: 256·p + s < 2^24, exact in u32.
    #[allow(clippy::arithmetic_side_effects)]
    pub fn of(px: u16, py: u16, sample: &Sample) -> ScreenPos {
        ScreenPos {
            xs: u32::from(px) * SUBPIXEL_SCALE + u32::from(sample.sx().to_bits()),
            ys: u32::from(py) * SUBPIXEL_SCALE + u32::from(sample.sy().to_bits()),
        }
    }
}

/// The scaled direction `d` of a screen position (|d_i| ≤ 2^30 for positions inside viewports
/// ≤ 2048; < 2^45 for any `u32` position).
// W, H ≤ 2^11 (checked `Viewport`), xs, ys < 2^32: |2·xs − 256·W| < 2^33 and times H < 2^44;
// 256·W·H ≤ 2^30. Every intermediate is far inside i64.
#[allow(clippy::arithmetic_side_effects)]
pub fn direction(vp: Viewport, pos: ScreenPos) -> [i64; 3] {
    let (w, h) = (i64::from(vp.w), i64::from(vp.h));
    let one = i64::from(SUBPIXEL_SCALE);
    let (xs, ys) = (i64::from(pos.xs), i64::from(pos.ys));
    [(2 * xs - one * w) * h, (one * h - 2 * ys) * w, one * w * h]
}

/// Result of a sample test that covers: the depth z/w, raw I8F24.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Hit {
    /// z/w at the hit, raw `Depth` bits in `[DEPTH_NEAR, DEPTH_FAR]` (never `DEPTH_EMPTY`; see
    /// the module docs)
    pub depth: i32,
}
