//! Stage 4 — the tiny tile framebuffer and the render loop.
//!
//! [`TileBuffer`] holds `TW×TH` pixels × `S` samples of color and depth (depth test: strictly
//! less wins, cleared to far = `i32::MAX`). Resolve averages the S samples per channel with
//! round-half-up: `(Σ + S/2) / S`. [`Renderer`] sets every triangle up exactly once into a
//! fixed-capacity `heapless::Vec` (no heap; memory is `N` setups plus one tile buffer), then walks
//! the screen tile by tile; per screen tile, per triangle whose footprint meets it, per bounds
//! tile (aligned to the bounds-tile grid, clipped to footprint and screen tile) it asks the bounds
//! strategy for (u, v, t) intervals and runs the sample test on the samples inside them.

use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::pixelcolor::{Rgb888, RgbColor};
use embedded_graphics_core::prelude::{Pixel, Point};

use crate::bounds::{BoundsStrategy, TileBounds};
use crate::error::Error;
use crate::formats::{DefaultPrecision, Precision};
use crate::input::{PixelRect, SamplePattern, Triangle, Viewport};
use crate::sample::{sample_test, ScreenPos};
use crate::setup::{setup_with, Cull, Outcome, Setup};
use crate::stats::{Ops, Stats};

/// A triangle with its flat color.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Prim {
    /// geometry
    pub tri: Triangle,
    /// color
    pub color: Rgb888,
}

/// Per-pixel counters of the last rendered tile.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PixelStats {
    /// sample tests run for this pixel (all triangles)
    pub tested: u32,
    /// of which covered
    pub covered: u32,
}

/// Color and depth of `TW×TH` pixels with `S` samples each.
#[derive(Clone, Debug)]
pub struct TileBuffer<const TW: usize, const TH: usize, const S: usize> {
    color: [[[Rgb888; S]; TW]; TH],
    depth: [[[i32; S]; TW]; TH],
    stats: [[PixelStats; TW]; TH],
}

impl<const TW: usize, const TH: usize, const S: usize> TileBuffer<TW, TH, S> {
    /// A cleared buffer.
    pub fn new(clear: Rgb888) -> Self {
        TileBuffer {
            color: [[[clear; S]; TW]; TH],
            depth: [[[i32::MAX; S]; TW]; TH],
            stats: [[PixelStats::default(); TW]; TH],
        }
    }

    /// Clear color, depth (to far) and per-pixel counters.
    pub fn clear(&mut self, clear: Rgb888) {
        *self = Self::new(clear);
    }

    /// Depth-test and write one sample; returns whether it was written. Out-of-range indices are
    /// ignored (returns false).
    pub fn write(&mut self, x: usize, y: usize, s: usize, color: Rgb888, depth: i32) -> bool {
        let slot = self
            .depth
            .get_mut(y)
            .and_then(|r| r.get_mut(x))
            .and_then(|p| p.get_mut(s));
        match slot {
            Some(d) if depth < *d => {
                *d = depth;
                if let Some(c) = self
                    .color
                    .get_mut(y)
                    .and_then(|r| r.get_mut(x))
                    .and_then(|p| p.get_mut(s))
                {
                    *c = color;
                }
                true
            }
            _ => false,
        }
    }

    /// Stored depth of one sample (raw I8F24), if in range.
    pub fn depth(&self, x: usize, y: usize, s: usize) -> Option<i32> {
        self.depth.get(y)?.get(x)?.get(s).copied()
    }

    /// Stored color of one sample, if in range.
    pub fn sample_color(&self, x: usize, y: usize, s: usize) -> Option<Rgb888> {
        self.color.get(y)?.get(x)?.get(s).copied()
    }

    /// Per-pixel counters.
    pub fn pixel_stats(&self, x: usize, y: usize) -> PixelStats {
        self.stats
            .get(y)
            .and_then(|r| r.get(x))
            .copied()
            .unwrap_or_default()
    }

    /// Resolved color: per channel `(Σ + S/2) / S` (round half up), see [`resolve_colors`].
    pub fn resolve(&self, x: usize, y: usize) -> Rgb888 {
        match self.color.get(y).and_then(|r| r.get(x)) {
            Some(p) => resolve_colors(p),
            None => Rgb888::BLACK,
        }
    }
}

/// Resolve one pixel's sample colors: per channel `(Σ + S/2) / S` with S = `colors.len()`
/// (round half up; S ≤ 64 keeps Σ + S/2 < 2^15). Black for S = 0.
pub fn resolve_colors(colors: &[Rgb888]) -> Rgb888 {
    let n = colors.len() as u32;
    if n == 0 {
        return Rgb888::BLACK;
    }
    let mut sum = [0u32; 3];
    for c in colors {
        sum[0] += c.r() as u32;
        sum[1] += c.g() as u32;
        sum[2] += c.b() as u32;
    }
    let avg = sum.map(|v| ((v + n / 2) / n).min(255) as u8);
    Rgb888::new(avg[0], avg[1], avg[2])
}

/// Renders a triangle list with bounds strategy `B`, holding at most `N` visible setups, at
/// precision `P` (default: [`DefaultPrecision`]).
pub struct Renderer<B: BoundsStrategy, const N: usize, P: Precision = DefaultPrecision> {
    prec: core::marker::PhantomData<P>,
    bounds: B,
    vp: Viewport,
    setups: heapless::Vec<(Setup, B::Coeffs, Rgb888), N>,
    /// counters accumulated over setup and every rendered tile
    pub stats: Stats,
}

impl<B: BoundsStrategy, const N: usize, P: Precision> Renderer<B, N, P> {
    /// Set every triangle up exactly once. Fails if more than `N` triangles are visible.
    pub fn new(bounds: B, vp: Viewport, prims: &[Prim]) -> Result<Self, Error> {
        let mut r = Renderer {
            prec: core::marker::PhantomData,
            bounds,
            vp,
            setups: heapless::Vec::new(),
            stats: Stats::default(),
        };
        for p in prims {
            r.stats.triangles += 1;
            match setup_with::<P>(&p.tri, vp, &mut r.stats.ops) {
                Outcome::Culled(Cull::Outside) => r.stats.culled_outside += 1,
                Outcome::Culled(Cull::Degenerate) => r.stats.culled_degenerate += 1,
                Outcome::Visible(s) => {
                    if let Some(c) = r.stats.by_class.get_mut(s.class.index()) {
                        *c += 1;
                    }
                    let coeffs = r.bounds.prepare(&s, &mut r.stats.ops);
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
        if pattern.spp() as usize != S {
            return Err(Error::SppMismatch {
                tile: S as u16,
                pattern: pattern.spp(),
            });
        }
        let bt = bounds_tile as usize;
        if !matches!(bounds_tile, 1 | 2 | 4 | 8) || TW % bt != 0 || TH % bt != 0 {
            return Err(Error::BoundsTile { size: bounds_tile });
        }
        if x0 >= self.vp.w || y0 >= self.vp.h {
            return Err(Error::PixelOutOfRange);
        }
        fb.clear(clear);
        let screen = PixelRect {
            x0,
            y0,
            x1: (x0 as usize + TW).min(self.vp.w as usize) as u16,
            y1: (y0 as usize + TH).min(self.vp.h as usize) as u16,
        };
        let b = bounds_tile as u16;
        for (setup, coeffs, color) in self.setups.iter() {
            let region = setup.footprint.intersect(&screen);
            if region.is_empty() {
                continue;
            }
            for cell in region.cells(b) {
                self.stats.tiles_visited += 1;
                let bounds = self.bounds.tile(setup, coeffs, cell, &mut self.stats.ops);
                let Some(uvt) = bounds else {
                    self.stats.tiles_skipped += 1;
                    continue;
                };
                shade_cell(
                    setup,
                    &uvt,
                    cell,
                    screen,
                    pattern,
                    *color,
                    fb,
                    &mut self.stats,
                );
            }
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
        mut out: impl FnMut(u16, u16, Rgb888, PixelStats),
    ) -> Result<(), Error> {
        let mut fb = TileBuffer::<TW, TH, S>::new(clear);
        let mut y0 = 0u16;
        while y0 < self.vp.h {
            let mut x0 = 0u16;
            while x0 < self.vp.w {
                self.render_tile(x0, y0, pattern, bounds_tile, clear, &mut fb)?;
                for ty in 0..TH {
                    for tx in 0..TW {
                        let (x, y) = (x0 as usize + tx, y0 as usize + ty);
                        if x < self.vp.w as usize && y < self.vp.h as usize {
                            out(
                                x as u16,
                                y as u16,
                                fb.resolve(tx, ty),
                                fb.pixel_stats(tx, ty),
                            );
                        }
                    }
                }
                x0 = x0.saturating_add(TW as u16);
            }
            y0 = y0.saturating_add(TH as u16);
        }
        Ok(())
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
fn shade_cell<T: TileBounds, const TW: usize, const TH: usize, const S: usize>(
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
            let (tx, ty) = ((px - screen.x0) as usize, (py - screen.y0) as usize);
            for (si, s) in pattern.pixel(px, py).iter().enumerate() {
                if !uvt.admits(s.u.to_bits(), s.v.to_bits(), s.t.to_bits(), &mut ops) {
                    continue;
                }
                stats.samples_tested += 1;
                let hit = sample_test(setup, ScreenPos::of(px, py, s), s, &mut ops);
                let ps = fb.stats.get_mut(ty).and_then(|r| r.get_mut(tx));
                if let Some(ps) = ps {
                    ps.tested += 1;
                    ps.covered += hit.is_some() as u32;
                }
                if let Some(h) = hit {
                    stats.samples_covered += 1;
                    fb.write(tx, ty, si, color, h.depth);
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
