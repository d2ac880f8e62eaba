//! The conservative epsilon: how far the bounded sample test's rounding can move a vertex
//! (`sample::bounded` module docs derive it); setup and every bounds strategy widen by it.

use crate::config::class::Class;
use crate::config::formats::SUBPIXEL_BITS;
use crate::input::Viewport;

/// 2^8: one pixel in sample-position units.
const SUBPIXEL_SCALE: i32 = 1 << SUBPIXEL_BITS;

/// The conservative epsilon of a setup: how far the bounded test's rounding can move a vertex,
/// in raw clip units (2^-16), rounded up to integers. All zero for the exact test, so every
/// bound is then bit-identical to the exact configuration's.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Eps {
    pub(crate) x: [i32; 2],
    pub(crate) w: i32,
}

impl Eps {
    /// Perturbation bound of x (`[0]`) and y (`[1]`), raw clip units.
    pub fn x(&self) -> [i32; 2] {
        self.x
    }
    /// Perturbation bound of w, raw clip units.
    pub fn w(&self) -> i32 {
        self.w
    }
    /// The epsilon of the bounded test with offset grid `2^shift` for a triangle of `class` in
    /// `vp` (module docs): `ceil(k/2 + 2^(shift−1)/(256·E))` per axis, `ceil(1/2)` for w of a
    /// moving triangle. `shift = None` (exact test): zero.
    pub fn of(shift: Option<u32>, class: Class, vp: Viewport) -> Eps {
        let Some(s) = shift else {
            return Eps::default();
        };
        let k: i64 = match class {
            Class::Static => 0,
            Class::Motion | Class::Defocus => 1,
            Class::MotionDefocus => 3,
        };
        // ceil((k·256E + 2^s) / (512E)): 2^s ≤ 2^32 (OFFSET_SHIFT_MAX), 256E ≤ 2^19, k ≤ 3;
        // every term < 2^34. `checked_pow` and `checked_*` make any surprise a huge epsilon
        // (conservative), never a panic; E ≥ 1 so the divisor is positive.
        let axis = |e: u16| {
            let e = i64::from(e);
            let num = 2i64.checked_pow(s).and_then(|p| {
                p.checked_add(k.checked_mul(i64::from(SUBPIXEL_SCALE))?.checked_mul(e)?)
            });
            let den = 2i64
                .saturating_mul(i64::from(SUBPIXEL_SCALE))
                .saturating_mul(e);
            num.and_then(|n| crate::arith::div::ceil_div(i128::from(n), i128::from(den)))
                .and_then(|q| i32::try_from(q).ok())
                .unwrap_or(1 << 24)
        };
        Eps {
            x: [axis(vp.w), axis(vp.h)],
            w: i32::from(class.motion()),
        }
    }
    /// Whether every term is zero (the exact test).
    pub fn is_zero(&self) -> bool {
        self.x == [0, 0] && self.w == 0
    }
}
