//! The motion-only unit's renderer at a bounded precision ([`crate::units::motion_only::setup`]): one
//! [`MotionSetup`] per visible triangle (or, at a [`crate::config::precision::Planar`] precision, a
//! [`StaticSetup`] for a static one), the slab cull per bounds tile and
//! [`motion_test`] per sample of a kept slab. The same interface and counters as
//! [`crate::Renderer`]; the same image as the full unit (`motion_unit` module docs).

use core::marker::PhantomData;

use embedded_graphics_core::pixelcolor::Rgb888;
use Tested::Run;
use Tested::Skip;

use crate::config::class::Class;
use crate::config::precision::Precision;
use crate::config::unit::{MotionOnly, Unit};
use crate::error::Error;
use crate::input::{PixelRect, Prim, SamplePattern, Viewport};
use crate::raster::renderer::{tile_screen, walk_screen};
use crate::raster::tile_buffer::{DepthTest, PixelStats, TileBuffer};
use crate::sample::pos::{Hit, ScreenPos};
use crate::setup::Cull;
use crate::stats::{Ops, Stats};
use crate::units::motion_only::sample::motion_test;
use crate::units::motion_only::setup::{
    motion_setup, motion_tile, slab_of, MotionOutcome, MotionSetup,
};
use crate::units::static_only::{
    static_setup, static_test, static_tile, StaticOutcome, StaticSetup,
};
/// Operations counted per sample test and per hit: the bounded test's count for the motion
/// class on its fast path (`bounded::class_ops` + 3) and its depth (12).
const SAMPLE_OPS: u64 = 15 * 3 + 2 + 3 * 8 + 9 + 3;
const HIT_OPS: u64 = 12;
/// One visible triangle's setup. (No heap in core, so the large variant stays inline.)
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MotionEntry {
    /// a static or moving triangle on the motion path
    Motion(MotionSetup),
    /// a static triangle at a planar precision (the planar test)
    Static(StaticSetup),
}
/// The motion-only unit's renderer at bounded precision `P`: at most `N` visible triangles.
pub struct MotionRenderer<const N: usize, P: Precision> {
    vp: Viewport,
    setups: heapless::Vec<(MotionEntry, Rgb888), N>,
    /// counters accumulated over setup and every rendered tile
    pub stats: Stats,
    prec: PhantomData<P>,
}
impl<const N: usize, P: Precision> MotionRenderer<N, P> {
    /// Set every triangle up once, in order. Fails with [`Error::ClassNotInUnit`] naming the
    /// first primitive the motion-only unit does not accept (classified before anything is
    /// computed for it), or with [`Error::TooManyTriangles`] if more than `N` triangles before
    /// it are visible. No renderer is returned on an error.
    pub fn new(vp: Viewport, prims: &[Prim]) -> Result<Self, Error> {
        let mut r = MotionRenderer {
            vp,
            setups: heapless::Vec::new(),
            stats: Stats::default(),
            prec: PhantomData,
        };
        for (index, p) in prims.iter().enumerate() {
            Stats::inc(&mut r.stats.triangles);
            let refuse = |class| Error::ClassNotInUnit {
                index,
                class,
                unit: MotionOnly::NAME,
            };
            let ops = &mut r.stats.ops;
            let entry = if P::PLANAR && p.tri.class() == Class::Static {
                match static_setup(&p.tri, vp, ops).map_err(refuse)? {
                    StaticOutcome::Visible(s) => Ok(MotionEntry::Static(s)),
                    StaticOutcome::Culled(c) => Err(c),
                }
            } else {
                match motion_setup::<P>(&p.tri, vp, ops).map_err(refuse)? {
                    MotionOutcome::Visible(m) => Ok(MotionEntry::Motion(m)),
                    MotionOutcome::Outside => Err(Cull::Outside),
                }
            };
            match entry {
                Err(Cull::Outside) => Stats::inc(&mut r.stats.culled_outside),
                Err(Cull::Degenerate) => Stats::inc(&mut r.stats.culled_degenerate),
                Ok(e) => {
                    let class = match e {
                        MotionEntry::Motion(m) => m.class(),
                        MotionEntry::Static(_) => Class::Static,
                    };
                    if let Some(c) = r.stats.by_class.get_mut(class.index()) {
                        Stats::inc(c);
                    }
                    r.setups
                        .push((e, p.color))
                        .map_err(|_| Error::TooManyTriangles { capacity: N })?;
                }
            }
        }
        Ok(r)
    }
    /// The visible setups.
    pub fn setups(&self) -> impl Iterator<Item = &MotionEntry> {
        self.setups.iter().map(|(s, _)| s)
    }
    /// Render the screen tile whose top-left pixel is (`x0`, `y0`) into `fb` (cleared first);
    /// the same checks and errors as [`crate::Renderer::render_tile`].
    pub fn render_tile<const TW: usize, const TH: usize, const S: usize>(
        &mut self,
        x0: u16,
        y0: u16,
        pattern: &SamplePattern<'_>,
        bounds_tile: u8,
        clear: Rgb888,
        fb: &mut TileBuffer<TW, TH, S>,
    ) -> Result<(), Error> {
        let screen = tile_screen::<TW, TH, S>(pattern, bounds_tile, x0, y0, &self.vp)?;
        fb.clear_fill(clear);
        let MotionRenderer { setups, stats, .. } = self;
        let mut ops = Ops::default();
        for (entry, color) in setups.iter() {
            let fp = match entry {
                MotionEntry::Static(s) if P::PLANAR => s.footprint(),
                MotionEntry::Motion(m) => m.footprint(),
                MotionEntry::Static(_) => continue,
            };
            for cell in fp.intersect(&screen).cells(u16::from(bounds_tile)) {
                Stats::inc(&mut stats.tiles_visited);
                let cx = Cell {
                    cell,
                    screen,
                    color: *color,
                };
                match entry {
                    MotionEntry::Static(s) if P::PLANAR => {
                        if !static_tile(s, cell, &mut ops) {
                            Stats::inc(&mut stats.tiles_skipped);
                            continue;
                        }
                        shade_cell(&cx, pattern, fb, stats, &mut ops, |pos, _| {
                            static_test(s, pos)
                        });
                    }
                    MotionEntry::Motion(m) => {
                        let mask = motion_tile(m, cell, &mut ops);
                        if mask == 0 {
                            Stats::inc(&mut stats.tiles_skipped);
                            continue;
                        }
                        shade_cell(&cx, pattern, fb, stats, &mut ops, |pos, smp| {
                            if (mask >> slab_of(smp.t().to_bits())) & 1 == 0 {
                                return Skip;
                            }
                            Run(motion_test::<P>(m, pos, smp))
                        });
                    }
                    MotionEntry::Static(_) => {}
                }
            }
        }
        stats.ops.add(&ops);
        Ok(())
    }
    /// Render the whole viewport tile by tile, handing every resolved pixel with its counters
    /// to `out(x, y, color, stats)` (as [`crate::Renderer::render_with`]).
    pub fn render_with<const TW: usize, const TH: usize, const S: usize>(
        &mut self,
        pattern: &SamplePattern<'_>,
        bounds_tile: u8,
        clear: Rgb888,
        out: impl FnMut(u16, u16, Rgb888, PixelStats),
    ) -> Result<(), Error> {
        let mut fb = TileBuffer::<TW, TH, S>::new_fill(clear);
        let vp = self.vp;
        walk_screen(
            vp,
            &mut fb,
            |x0, y0, fb| self.render_tile(x0, y0, pattern, bounds_tile, clear, fb),
            out,
        )
    }
}
/// What a per-sample closure of [`shade_cell`] reports.
enum Tested {
    /// the sample's slab was culled for this tile: not tested
    Skip,
    /// tested, with its hit
    Run(Option<Hit>),
}

/// A static test's result as a [`Tested`].
impl From<Option<Hit>> for Tested {
    fn from(h: Option<Hit>) -> Self {
        Run(h)
    }
}

/// One bounds tile's place and the triangle's color.
struct Cell {
    cell: PixelRect,
    screen: PixelRect,
    color: Rgb888,
}

/// Test every sample of one bounds tile with `test` (the counters as the general renderer
/// keeps them).
fn shade_cell<const TW: usize, const TH: usize, const S: usize, R: Into<Tested>>(
    c: &Cell,
    pattern: &SamplePattern<'_>,
    fb: &mut TileBuffer<TW, TH, S>,
    stats: &mut Stats,
    ops: &mut Ops,
    test: impl Fn(ScreenPos, &crate::input::Sample) -> R,
) {
    let (cell, screen) = (c.cell, c.screen);
    for py in cell.y0..cell.y1 {
        for px in cell.x0..cell.x1 {
            // The cell lies inside the screen tile, so both differences are in [0, TW), [0, TH).
            let (Some(tx), Some(ty)) = (px.checked_sub(screen.x0), py.checked_sub(screen.y0))
            else {
                continue;
            };
            let (tx, ty) = (usize::from(tx), usize::from(ty));
            for (si, s) in pattern.pixel(px, py).iter().enumerate() {
                let Run(hit) = test(ScreenPos::of(px, py, s), s).into() else {
                    continue;
                };
                Stats::inc(&mut stats.samples_tested);
                ops.add_sample(SAMPLE_OPS);
                fb.count(tx, ty, hit.is_some());
                let Some(h) = hit else {
                    continue;
                };
                ops.add_sample(HIT_OPS);
                Stats::inc(&mut stats.samples_covered);
                // In range (tx < TW, ty < TH, si < S = spp) and h.depth ≠ DEPTH_EMPTY.
                match fb.write(tx, ty, si, c.color, h.depth) {
                    Some(DepthTest::Written) => {
                        Stats::inc(&mut stats.samples_written);
                        fb.count_written(tx, ty);
                    }
                    Some(DepthTest::Occluded) => Stats::inc(&mut stats.samples_occluded),
                    None => {}
                }
            }
        }
    }
}
