//! Zmax culling's own work (`uvt_core::raster::zmax`) on a workload, as `examples/m4_stages`
//! measures it beside the bounds strategies' stages: the three calls the renderer adds with
//! `Zmax`, each timed by the caller's `lap` (instructions since its previous call, on the
//! Cortex-M; the host passes a closure returning 0).
//!
//! - **floor**: [`Pipeline::depth_floor`] of every visible triangle of the workload, through the
//!   general pipeline at precision `P` on the full unit (what `Raster::load` runs once per
//!   visible triangle), one lap per call;
//! - **check**: [`ZmaxRegisters::hides`] of a bounds tile of the workload's size in a
//!   [`TILE`] × [`TILE`] screen tile (the tile's maximum from its pixels' registers, then the
//!   comparison), [`CALLS`] calls over the tiles in turn, one lap for all;
//! - **refresh**: [`ZmaxRegisters::refresh`] of a pixel after a write at [`S`] samples per pixel
//!   (the `S`-input maximum), [`CALLS`] calls over the pixels in turn, one lap for all.
//!
//! The check's and refresh's instruction counts do not depend on the stored depths (a fixed
//! number of loads and maxima); the buffer is filled from a fixed seed. The loop's own
//! increment and branch are included in the per-call figure (an over-, not an under-estimate).

use core::hint::black_box;

use uvt_core::config::unit::Full;
use uvt_core::raster::zmax::{Cleared, PixelMax, ZmaxRegisters};
use uvt_core::units::select::{PipelineOf, Select};
use uvt_core::{Laine2011, Ops, Outcome, Pipeline, Precision, Rgb888, TileBuffer};

use crate::workload::{FormatError, Workload};

/// Calls of the check and of the refresh.
pub const CALLS: u32 = 4096;
/// Side of the measuring screen tile (pixels).
pub const TILE: usize = 8;
/// Samples per pixel of the measuring buffer (the bench rows').
pub const S: usize = 16;

/// Counts and instructions of [`zmax_cost`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ZmaxCost {
    /// visible triangles (one floor each)
    pub floors: u64,
    /// tile checks timed
    pub checks: u64,
    /// register refreshes timed
    pub refreshes: u64,
    /// instructions: floors, checks, refreshes (from `lap`)
    pub insn: [u64; 3],
}

/// The three Zmax calls on `w` (module docs) at precision `P`, the check at the workload's
/// bounds-tile size.
pub fn zmax_cost<P>(
    w: &Workload<'_>,
    lap: &mut impl FnMut() -> u64,
) -> Result<ZmaxCost, FormatError>
where
    P: Precision,
    (P, Full): Select<Laine2011>,
{
    let mut c = ZmaxCost::default();
    let pipe = PipelineOf::<Laine2011, P, Full>::new(Laine2011);
    let vp = w.header().vp;
    let mut ops = Ops::default();
    for tri in w.triangles::<P>() {
        let Outcome::Visible(e) = pipe.setup(&tri?, vp, &mut ops) else {
            continue;
        };
        let _ = lap();
        black_box(PipelineOf::<Laine2011, P, Full>::depth_floor(
            black_box(&e),
            &mut ops,
        ));
        c.insn[0] = c.insn[0].saturating_add(lap());
        c.floors = c.floors.saturating_add(1);
    }
    // A buffer with some samples written, the registers refreshed as the renderer does.
    let mut fb = TileBuffer::<TILE, TILE, S>::new(Rgb888::new(0, 0, 0));
    let mut regs = PixelMax::<TILE, TILE>::cleared();
    let mut seed = 0x2545_f491_u32;
    let mut next = move || {
        seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
        usize::try_from(seed >> 8).unwrap_or(0)
    };
    for _ in 0..TILE * TILE * S {
        let (x, y, s) = (next() % TILE, next() % TILE, next() % S);
        let depth = i32::try_from(next() % (1 << 24)).unwrap_or(0);
        if fb.write(x, y, s, Rgb888::new(9, 9, 9), depth).is_some() {
            regs.refresh(&fb, x, y, &mut ops);
        }
    }
    let bt = usize::from(w.header().bounds_tile).clamp(1, TILE);
    let starts = || (0..TILE).step_by(bt);
    // The tiles in turn (CALLS is a multiple of their number, 1 to 64).
    let mut i = 0u32;
    let _ = lap();
    while i < CALLS {
        for (y0, x0) in starts().flat_map(|y| starts().map(move |x| (y, x))) {
            let floor = i32::try_from(i).unwrap_or(0).wrapping_shl(12);
            let (cols, rows) = ((x0, x0.saturating_add(bt)), (y0, y0.saturating_add(bt)));
            black_box(black_box(&regs).hides(black_box(floor), cols, rows, &mut ops));
            i = i.wrapping_add(1);
        }
    }
    c.insn[1] = lap();
    c.checks = u64::from(CALLS);
    let _ = lap();
    // Rounds over the tile's pixels (CALLS is a multiple of TILE²).
    let rounds = u32::try_from(TILE * TILE).map_or(0, |n| CALLS.checked_div(n).unwrap_or(0));
    for _ in 0..rounds {
        for (y, x) in (0..TILE).flat_map(|y| (0..TILE).map(move |x| (y, x))) {
            black_box(&mut regs).refresh(black_box(&fb), x, y, &mut ops);
        }
    }
    c.insn[2] = lap();
    c.refreshes = u64::from(CALLS);
    black_box(ops);
    Ok(c)
}
