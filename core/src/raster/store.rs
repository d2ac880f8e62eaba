//! Where the render loop puts covered samples: a [`SampleStore`] holds colour and depth of the
//! samples of one rectangle of pixels, runs **the one depth test** ([`depth_test`]: strictly
//! nearer wins, so of two equal depths the earlier triangle keeps the slot) and counts per
//! pixel ([`PixelStats`]).
//!
//! Two stores: the fixed-size [`TileBuffer`](crate::raster::tile_buffer::TileBuffer) of a screen
//! tile (no heap; what the Cortex-M programs use) and [`RegionBuffer`], the same store over
//! slices the caller owns, of any rectangle and any samples per pixel (what a host renders a
//! band of the screen into). The loop ([`crate::raster::engine`]) writes only through this
//! trait, so both give the same samples.

use embedded_graphics_core::pixelcolor::{Rgb888, RgbColor};

use crate::config::formats::DEPTH_EMPTY;
use crate::error::Error;
use crate::input::{PixelRect, MAX_PATTERN};

/// Per-pixel counters of a store: what the loop did for one pixel.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PixelStats {
    /// sample tests run for this pixel (all triangles)
    pub tested: u32,
    /// of which covered
    pub covered: u32,
    /// of the covered, written (the others were occluded by an earlier triangle's sample)
    pub written: u32,
}

/// Outcome of the depth test of one covered sample.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DepthTest {
    /// the slot was empty or held a larger depth: color and depth written
    Written,
    /// the slot held a depth ≤ this one, written by an earlier sample: nothing changed
    Occluded,
}

/// Colour and depth of the samples of a rectangle of pixels, with per-pixel counters.
/// Coordinates are relative to the store's first pixel; out-of-range indices change nothing.
pub trait SampleStore {
    /// Width and height in pixels, and samples per pixel.
    fn size(&self) -> (usize, usize, usize);
    /// Depth-test and write sample `s` of pixel (`x`, `y`) ([`depth_test`]); `None`, with nothing
    /// changed, for out-of-range indices or `depth == DEPTH_EMPTY`.
    fn write(
        &mut self,
        x: usize,
        y: usize,
        s: usize,
        color: Rgb888,
        depth: i32,
    ) -> Option<DepthTest>;
    /// Count one sample test of pixel (`x`, `y`) (and whether it covered).
    fn count(&mut self, x: usize, y: usize, covered: bool);
    /// Count one written sample of pixel (`x`, `y`).
    fn count_written(&mut self, x: usize, y: usize);
    /// The largest stored depth over every sample of the pixels `cols.0..cols.1` ×
    /// `rows.0..rows.1` (clipped to the store) and how many slots were read; `i32::MIN` with 0
    /// reads for an empty range (the Zmax registers' refresh, [`crate::raster::zmax`]).
    fn max_depth(&self, cols: (usize, usize), rows: (usize, usize)) -> (i32, u64);
}

/// The depth test of every store: a covered sample at `depth` against the slot's stored depth
/// `slot`. Strictly nearer is written (`slot` takes `depth`; the caller stores the colour);
/// equal or farther is occluded. `None` (nothing changed) for `depth == DEPTH_EMPTY`, which no
/// sample test outputs (it marks an empty slot).
#[inline(always)]
pub fn depth_test(slot: &mut i32, depth: i32) -> Option<DepthTest> {
    if depth == DEPTH_EMPTY {
        return None;
    }
    if depth >= *slot {
        return Some(DepthTest::Occluded);
    }
    *slot = depth;
    Some(DepthTest::Written)
}

/// A [`SampleStore`] over caller-owned slices: the pixels of `rect` (row-major) × `spp` samples.
/// Depth is always kept; colour and the per-pixel counters only when their slices are given
/// (an empty slice keeps none: a run that wants counters but no image pays no colour writes).
/// Built only by [`RegionBuffer::new`], which checks every length.
#[derive(Debug)]
pub struct RegionBuffer<'a> {
    rect: PixelRect,
    spp: usize,
    width: usize,
    height: usize,
    depth: &'a mut [i32],
    color: &'a mut [Rgb888],
    stats: &'a mut [PixelStats],
}

impl<'a> RegionBuffer<'a> {
    /// A store of the pixels of `rect` with `spp` samples each, cleared: depth to
    /// [`DEPTH_EMPTY`], colour to `clear`, counters to 0. `depth` must hold
    /// `pixels · spp` values, `color` the same or none, `stats` `pixels` or none, with `pixels`
    /// the area of `rect` ([`Error::PatternShape`] otherwise, naming `spp` and the length that
    /// does not fit); `1 ≤ spp ≤ 64` and `rect` not empty.
    pub fn new(
        rect: PixelRect,
        spp: u16,
        clear: Rgb888,
        depth: &'a mut [i32],
        color: &'a mut [Rgb888],
        stats: &'a mut [PixelStats],
    ) -> Result<RegionBuffer<'a>, Error> {
        let width = usize::from(rect.x1.saturating_sub(rect.x0));
        let height = usize::from(rect.y1.saturating_sub(rect.y0));
        // width, height ≤ 2^16 and spp ≤ 64: the products fit usize (checked regardless).
        let pixels = width.saturating_mul(height);
        let slots = pixels.saturating_mul(usize::from(spp));
        let shape = |len: usize| Error::PatternShape { block: 0, spp, len };
        if rect.is_empty() || spp == 0 || spp > MAX_PATTERN {
            return Err(shape(depth.len()));
        }
        if depth.len() != slots {
            return Err(shape(depth.len()));
        }
        if !color.is_empty() && color.len() != slots {
            return Err(shape(color.len()));
        }
        if !stats.is_empty() && stats.len() != pixels {
            return Err(shape(stats.len()));
        }
        depth.fill(DEPTH_EMPTY);
        color.fill(clear);
        stats.fill(PixelStats::default());
        Ok(RegionBuffer {
            rect,
            spp: usize::from(spp),
            width,
            height,
            depth,
            color,
            stats,
        })
    }

    /// The pixels it holds.
    pub fn rect(&self) -> PixelRect {
        self.rect
    }

    /// Samples per pixel.
    pub fn spp(&self) -> u16 {
        // spp ≤ 64 (checked constructor).
        u16::try_from(self.spp).unwrap_or(MAX_PATTERN)
    }

    /// The first slot of pixel (`x`, `y`) (relative), if inside.
    #[inline(always)]
    fn pixel(&self, x: usize, y: usize) -> Option<usize> {
        if x >= self.width || y >= self.height {
            return None;
        }
        // y·width + x < pixels ≤ 2^32 (checked constructor): no overflow; checked regardless.
        y.checked_mul(self.width)?.checked_add(x)
    }

    /// Stored depth of sample `s` of pixel (`x`, `y`), if in range.
    pub fn depth(&self, x: usize, y: usize, s: usize) -> Option<i32> {
        let i = self.slot(x, y, s)?;
        self.depth.get(i).copied()
    }

    /// Stored colour of sample `s` of pixel (`x`, `y`), if in range and colour is kept.
    pub fn sample_color(&self, x: usize, y: usize, s: usize) -> Option<Rgb888> {
        let i = self.slot(x, y, s)?;
        self.color.get(i).copied()
    }

    /// The per-pixel counters of pixel (`x`, `y`) (zero when not kept).
    pub fn pixel_stats(&self, x: usize, y: usize) -> PixelStats {
        self.pixel(x, y)
            .and_then(|p| self.stats.get(p))
            .copied()
            .unwrap_or_default()
    }

    /// The resolved colour of pixel (`x`, `y`) ([`resolve_colors`]); `None` when colour is not
    /// kept or the pixel is outside.
    pub fn resolve(&self, x: usize, y: usize) -> Option<Rgb888> {
        let first = self.slot(x, y, 0)?;
        let colors = self.color.get(first..first.checked_add(self.spp)?)?;
        Some(resolve_colors(colors))
    }

    /// The slot of sample `s` of pixel (`x`, `y`), if both are in range.
    #[inline(always)]
    fn slot(&self, x: usize, y: usize, s: usize) -> Option<usize> {
        if s >= self.spp {
            return None;
        }
        self.pixel(x, y)?.checked_mul(self.spp)?.checked_add(s)
    }
}

impl SampleStore for RegionBuffer<'_> {
    fn size(&self) -> (usize, usize, usize) {
        (self.width, self.height, self.spp)
    }

    #[inline(always)]
    fn write(
        &mut self,
        x: usize,
        y: usize,
        s: usize,
        color: Rgb888,
        depth: i32,
    ) -> Option<DepthTest> {
        let i = self.slot(x, y, s)?;
        let r = depth_test(self.depth.get_mut(i)?, depth);
        if r == Some(DepthTest::Written) {
            if let Some(c) = self.color.get_mut(i) {
                *c = color;
            }
        }
        r
    }

    #[inline(always)]
    fn count(&mut self, x: usize, y: usize, covered: bool) {
        let Some(p) = self.pixel(x, y) else {
            return;
        };
        if let Some(ps) = self.stats.get_mut(p) {
            ps.tested = ps.tested.saturating_add(1);
            ps.covered = ps.covered.saturating_add(u32::from(covered));
        }
    }

    #[inline(always)]
    fn count_written(&mut self, x: usize, y: usize) {
        let Some(p) = self.pixel(x, y) else {
            return;
        };
        if let Some(ps) = self.stats.get_mut(p) {
            ps.written = ps.written.saturating_add(1);
        }
    }

    fn max_depth(&self, cols: (usize, usize), rows: (usize, usize)) -> (i32, u64) {
        let (mut max, mut reads) = (i32::MIN, 0u64);
        let c0 = cols.0.min(self.width);
        let c1 = cols.1.min(self.width).max(c0);
        for y in rows.0.min(self.height)..rows.1.min(self.height) {
            // Slots of pixels c0..c1 of row y: < pixels · spp (checked constructor); checked.
            let at = |c: usize| {
                y.checked_mul(self.width)?
                    .checked_add(c)?
                    .checked_mul(self.spp)
            };
            let (Some(a), Some(b)) = (at(c0), at(c1)) else {
                continue;
            };
            let slots = self.depth.get(a..b).unwrap_or(&[]);
            for &d in slots {
                max = max.max(d);
            }
            reads = reads.saturating_add(u64::try_from(slots.len()).unwrap_or(u64::MAX));
        }
        (max, reads)
    }
}

/// Resolve one pixel's sample colors: per channel `(Σ + S/2) / S` with S = `colors.len()`
/// (round half up; S ≤ 64 keeps Σ + S/2 < 2^15, exact for any S < 2^24). Black for S = 0.
pub fn resolve_colors(colors: &[Rgb888]) -> Rgb888 {
    let n = u32::try_from(colors.len()).unwrap_or(u32::MAX);
    let mut sum = [0u32; 3];
    for c in colors {
        for (s, ch) in sum.iter_mut().zip([c.r(), c.g(), c.b()]) {
            *s = s.saturating_add(u32::from(ch));
        }
    }
    // checked_div: None only for S = 0 (black); the quotient is ≤ 255 for S < 2^24.
    let avg = sum.map(|v| {
        let q = v.saturating_add(n / 2).checked_div(n).unwrap_or(0);
        u8::try_from(q).unwrap_or(u8::MAX)
    });
    Rgb888::new(avg[0], avg[1], avg[2])
}
