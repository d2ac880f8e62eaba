//! Stage 4 — the tiny tile framebuffer and the render loop.
//!
//! [`TileBuffer`] holds `TW×TH` pixels × `S` samples of color and depth. Depth test: strictly
//! less wins, so of equal depths the first writer keeps the slot. The buffer clears to
//! [`DEPTH_EMPTY`] (raw `i32::MAX`), which the sample test never outputs (its depths saturate to
//! `[DEPTH_NEAR, DEPTH_FAR]`, `sample.rs`): a covered sample is either written or rejected by the
//! depth test against a value an earlier triangle wrote, and [`Stats`] counts which
//! (`samples_covered = samples_written + samples_occluded`). Resolve averages the S samples per channel with
//! round-half-up: `(Σ + S/2) / S`. [`Renderer`] sets every triangle up exactly once into a
//! fixed-capacity `heapless::Vec` (no heap; memory is `N` setups plus one tile buffer), then walks
//! the screen tile by tile; per screen tile, per triangle whose footprint meets it, per bounds
//! tile (aligned to the bounds-tile grid, clipped to footprint and screen tile) it asks the bounds
//! strategy for (u, v, t) intervals and runs the sample test on the samples inside them; the
//! tiles are walked row by row, each row first narrowed by the strategy's row span
//! ([`crate::bounds::strategy::walk_tiles`]).

use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::pixelcolor::Rgb888;
use embedded_graphics_core::prelude::{Pixel, Point};

use crate::bounds::strategy::{walk_tiles, BoundsStrategy, TileBounds};
use crate::config::precision::{DefaultPrecision, Precision};
use crate::config::unit::{Full, Unit};
use crate::error::Error;
use crate::input::{PixelRect, Prim, SamplePattern, Viewport};
use crate::raster::tile_buffer::{tile_size, DepthTest, PixelStats, TileBuffer};
use crate::sample::pos::ScreenPos;
use crate::sample::sample_test_unit;
use crate::setup::{setup_unit, Cull, Outcome, Setup};
use crate::stats::{Ops, Stats};

/// The screen walk of every renderer's `render_with`: for each screen tile of `vp` (raster
/// order) `render(x0, y0, fb)` renders it into `fb`, then each of its pixels inside `vp` goes to
/// `out(x, y, color, stats)` in raster order.
pub(crate) fn walk_screen<const TW: usize, const TH: usize, const S: usize>(
    vp: Viewport,
    fb: &mut TileBuffer<TW, TH, S>,
    mut render: impl FnMut(u16, u16, &mut TileBuffer<TW, TH, S>) -> Result<(), Error>,
    mut out: impl FnMut(u16, u16, Rgb888, PixelStats),
) -> Result<(), Error> {
    let (tw, th) = tile_size::<TW, TH>();
    let mut y0 = 0u16;
    while y0 < vp.h {
        let mut x0 = 0u16;
        while x0 < vp.w {
            render(x0, y0, fb)?;
            // The tile's pixels in raster order, one loop (not unrolled per column).
            for (ty, tx) in (0..th).flat_map(|ty| (0..tw).map(move |tx| (ty, tx))) {
                // x0 + tx < 2048 + 2048: no saturation happens.
                let (x, y) = (x0.saturating_add(tx), y0.saturating_add(ty));
                if x < vp.w && y < vp.h {
                    let (tx, ty) = (usize::from(tx), usize::from(ty));
                    out(x, y, fb.resolve(tx, ty), fb.pixel_stats(tx, ty));
                }
            }
            // tw ≥ 1 (TileBuffer's const assertion), so the walk advances.
            x0 = x0.saturating_add(tw);
        }
        y0 = y0.saturating_add(th);
    }
    Ok(())
}

/// The argument checks of every renderer's `render_tile`: the pattern has `S` samples per
/// pixel ([`Error::SppMismatch`]), the bounds tile is 1, 2, 4 or 8 and divides `TW` and `TH`
/// ([`Error::BoundsTile`]), and (`x0`, `y0`) lies in `vp` ([`Error::PixelOutOfRange`]); then
/// the tile's pixels clipped to the viewport.
#[inline(always)]
pub(crate) fn tile_screen<const TW: usize, const TH: usize, const S: usize>(
    pattern: &SamplePattern<'_>,
    bounds_tile: u8,
    x0: u16,
    y0: u16,
    vp: &Viewport,
) -> Result<PixelRect, Error> {
    check_tile_args::<TW, TH, S>(pattern, bounds_tile, x0, y0, vp)?;
    let (tw, th) = tile_size::<TW, TH>();
    Ok(PixelRect {
        x0,
        y0,
        x1: x0.saturating_add(tw).min(vp.w),
        y1: y0.saturating_add(th).min(vp.h),
    })
}

/// The checks of [`tile_screen`].
fn check_tile_args<const TW: usize, const TH: usize, const S: usize>(
    pattern: &SamplePattern<'_>,
    bounds_tile: u8,
    x0: u16,
    y0: u16,
    vp: &Viewport,
) -> Result<(), Error> {
    if usize::from(pattern.spp()) != S {
        return Err(Error::SppMismatch {
            tile: u16::try_from(S).unwrap_or(u16::MAX),
            pattern: pattern.spp(),
        });
    }
    let bt = usize::from(bounds_tile);
    let divides = |n: usize| n.checked_rem(bt) == Some(0);
    if !matches!(bounds_tile, 1 | 2 | 4 | 8) || !divides(TW) || !divides(TH) {
        return Err(Error::BoundsTile { size: bounds_tile });
    }
    if x0 >= vp.w || y0 >= vp.h {
        return Err(Error::PixelOutOfRange);
    }
    Ok(())
}

/// Renders a triangle list with bounds strategy `B`, holding at most `N` visible setups, at
/// precision `P` (default: [`DefaultPrecision`]) on unit `U` (default: [`Full`]; a narrower
/// unit refuses the classes it lacks, [`Error::ClassNotInUnit`]).
pub struct Renderer<
    B: BoundsStrategy,
    const N: usize,
    P: Precision = DefaultPrecision,
    U: Unit = Full,
> {
    prec: core::marker::PhantomData<(P, U)>,
    bounds: B,
    vp: Viewport,
    setups: heapless::Vec<(Setup, B::Coeffs, Rgb888), N>,
    /// counters accumulated over setup and every rendered tile
    pub stats: Stats,
}

impl<B: BoundsStrategy, const N: usize, P: Precision, U: Unit> Renderer<B, N, P, U> {
    /// Set every triangle up exactly once. Fails if more than `N` triangles are visible, or
    /// with [`Error::ClassNotInUnit`] (naming the first such primitive, culled or not) if a
    /// primitive's class is not accepted by `U`: every class is checked before any setup.
    pub fn new(bounds: B, vp: Viewport, prims: &[Prim]) -> Result<Self, Error> {
        for (index, p) in prims.iter().enumerate() {
            let class = p.tri.class();
            if !U::accepts(class) {
                return Err(Error::ClassNotInUnit {
                    index,
                    class,
                    unit: U::NAME,
                });
            }
        }
        let mut r = Renderer {
            prec: core::marker::PhantomData,
            bounds,
            vp,
            setups: heapless::Vec::new(),
            stats: Stats::default(),
        };
        for (index, p) in prims.iter().enumerate() {
            Stats::inc(&mut r.stats.triangles);
            // Every class is accepted (checked above): `Err` cannot occur; were it to, the
            // primitive is refused, never rendered.
            let outcome = setup_unit::<P, U>(&p.tri, vp, &mut r.stats.ops);
            match outcome.map_err(|class| Error::ClassNotInUnit {
                index,
                class,
                unit: U::NAME,
            })? {
                Outcome::Culled(Cull::Outside) => Stats::inc(&mut r.stats.culled_outside),
                Outcome::Culled(Cull::Degenerate) => Stats::inc(&mut r.stats.culled_degenerate),
                Outcome::Visible(s) => {
                    if let Some(c) = r.stats.by_class.get_mut(s.class.index()) {
                        Stats::inc(c);
                    }
                    let coeffs = r.bounds.prepare_unit::<U>(&s, &mut r.stats.ops);
                    r.setups
                        .push((s, coeffs, p.color))
                        .map_err(|_| Error::TooManyTriangles { capacity: N })?;
                }
            }
        }
        Ok(r)
    }

    /// The visible setups.
    pub fn setups(&self) -> impl Iterator<Item = &Setup> {
        self.setups.iter().map(|(s, _, _)| s)
    }

    /// Render the screen tile whose top-left pixel is (`x0`, `y0`) into `fb` (cleared first).
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
        fb.clear(clear);
        let b = u16::from(bounds_tile);
        let Renderer {
            bounds,
            setups,
            stats,
            ..
        } = self;
        for (setup, coeffs, color) in setups.iter() {
            let region = setup.footprint().intersect(&screen);
            if region.is_empty() {
                continue;
            }
            // Row → span → tiles; a cell outside its row's span counts as visited and skipped,
            // like a cell the per-tile test culls (the same counters either way).
            let mut ops = Ops::default();
            walk_tiles::<B, U>(bounds, setup, coeffs, region, b, &mut ops, |cell, t, _| {
                Stats::inc(&mut stats.tiles_visited);
                let Some(uvt) = t else {
                    Stats::inc(&mut stats.tiles_skipped);
                    return;
                };
                shade_cell::<_, P, U, TW, TH, S>(
                    setup, &uvt, cell, screen, pattern, *color, fb, stats,
                );
            });
            stats.ops.add(&ops);
        }
        Ok(())
    }

    /// Render the whole viewport tile by tile, handing every resolved pixel with its counters to
    /// `out(x, y, color, stats)`. One `TileBuffer` lives on the stack.
    pub fn render_with<const TW: usize, const TH: usize, const S: usize>(
        &mut self,
        pattern: &SamplePattern<'_>,
        bounds_tile: u8,
        clear: Rgb888,
        out: impl FnMut(u16, u16, Rgb888, PixelStats),
    ) -> Result<(), Error> {
        let mut fb = TileBuffer::<TW, TH, S>::new(clear);
        let vp = self.vp;
        walk_screen(
            vp,
            &mut fb,
            |x0, y0, fb| self.render_tile(x0, y0, pattern, bounds_tile, clear, fb),
            out,
        )
    }

    /// Render the whole viewport into an embedded-graphics `DrawTarget`, one tile at a time.
    pub fn render<D, const TW: usize, const TH: usize, const S: usize>(
        &mut self,
        pattern: &SamplePattern<'_>,
        bounds_tile: u8,
        clear: Rgb888,
        target: &mut D,
    ) -> Result<(), RenderError<D::Error>>
    where
        D: DrawTarget<Color = Rgb888>,
    {
        let mut draw_err = None;
        self.render_with::<TW, TH, S>(pattern, bounds_tile, clear, |x, y, c, _| {
            if draw_err.is_none() {
                let px = Pixel(Point::new(x as i32, y as i32), c);
                if let Err(e) = target.draw_iter(core::iter::once(px)) {
                    draw_err = Some(e);
                }
            }
        })
        .map_err(RenderError::Core)?;
        match draw_err {
            Some(e) => Err(RenderError::Draw(e)),
            None => Ok(()),
        }
    }
}

/// Test the samples of one bounds tile that fall inside its intervals.
#[allow(clippy::too_many_arguments)]
fn shade_cell<
    T: TileBounds,
    P: Precision,
    U: Unit,
    const TW: usize,
    const TH: usize,
    const S: usize,
>(
    setup: &Setup,
    uvt: &T,
    cell: PixelRect,
    screen: PixelRect,
    pattern: &SamplePattern<'_>,
    color: Rgb888,
    fb: &mut TileBuffer<TW, TH, S>,
    stats: &mut Stats,
) {
    let mut ops = Ops::default();
    for py in cell.y0..cell.y1 {
        for px in cell.x0..cell.x1 {
            // The cell lies inside the screen tile, so both differences are in [0, TW), [0, TH).
            let (Some(tx), Some(ty)) = (px.checked_sub(screen.x0), py.checked_sub(screen.y0))
            else {
                continue;
            };
            let (tx, ty) = (usize::from(tx), usize::from(ty));
            for (si, s) in pattern.pixel(px, py).iter().enumerate() {
                if !uvt.admits(s.u().to_bits(), s.v().to_bits(), s.t().to_bits(), &mut ops) {
                    continue;
                }
                Stats::inc(&mut stats.samples_tested);
                let hit = sample_test_unit::<P, U>(setup, ScreenPos::of(px, py, s), s, &mut ops);
                let ps = fb.stats.get_mut(ty).and_then(|r| r.get_mut(tx));
                if let Some(ps) = ps {
                    ps.tested = ps.tested.saturating_add(1);
                    ps.covered = ps.covered.saturating_add(u32::from(hit.is_some()));
                }
                if let Some(h) = hit {
                    Stats::inc(&mut stats.samples_covered);
                    // In range (tx < TW, ty < TH, si < S = spp) and h.depth ≠ DEPTH_EMPTY.
                    match fb.write(tx, ty, si, color, h.depth) {
                        Some(DepthTest::Written) => {
                            Stats::inc(&mut stats.samples_written);
                            if let Some(ps) = fb.stats.get_mut(ty).and_then(|r| r.get_mut(tx)) {
                                ps.written = ps.written.saturating_add(1);
                            }
                        }
                        Some(DepthTest::Occluded) => Stats::inc(&mut stats.samples_occluded),
                        None => {}
                    }
                }
            }
        }
    }
    stats.ops.add(&ops);
}

/// Error of [`Renderer::render`]: the core's, or the draw target's.
#[derive(Debug, PartialEq, Eq)]
pub enum RenderError<E> {
    /// refused by the core
    Core(Error),
    /// the draw target failed
    Draw(E),
}
