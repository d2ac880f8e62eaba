//! The static-only unit's tile cull: per bounds tile, the largest fill-adjusted edge value of
//! each edge over the tile's sample rectangle (module docs of [`crate::units::static_only`]).

use crate::config::formats::SUBPIXEL_BITS;
use crate::input::PixelRect;
use crate::stats::Ops;
use crate::units::static_only::setup::StaticSetup;
use crate::units::static_only::setup::{dxy, edge};

/// Whether bounds tile `cell` may hold a covered sample: `false` only if some edge's largest
/// fill-adjusted `σE_k` over the tile's sample rectangle is negative (module docs; exact and
/// conservative). Counts its operations in `ops.bounds`.
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_wrap)]
pub fn static_tile(s: &StaticSetup, cell: PixelRect, ops: &mut Ops) -> bool {
    if cell.is_empty() {
        return false;
    }
    if cell.x1 > s.vp.w || cell.y1 > s.vp.h {
        // Not a tile the renderer walks (it clips to the viewport): kept, and the sample test
        // refuses every position outside the viewport.
        return true;
    }
    ops.add_bounds(4 + 3 * 4);
    // cell.x1 ≤ W ≤ 2048 and x1 > x0 ≥ 0: 256·x1 − 1 < 2^19, exact in i32 (the same for y).
    let one = 1i32 << SUBPIXEL_BITS;
    let (dxl, dyl) = dxy(s, i32::from(cell.x0) * one, i32::from(cell.y0) * one);
    let (dxh, dyh) = dxy(
        s,
        i32::from(cell.x1) * one - 1,
        i32::from(cell.y1) * one - 1,
    );
    s.ab.iter().zip(s.c.iter()).all(|(ab, &c)| {
        // d_x grows with xs, d_y falls with ys: the corner of the largest σE_k.
        let dx = if ab[0] > 0 { dxh } else { dxl };
        let dy = if ab[1] > 0 { dyl } else { dyh };
        edge(ab, c, dx, dy) >= 0
    })
}
