//! The tiny tile framebuffer: `TW×TH` pixels × `S` samples of color and depth (a
//! [`SampleStore`] with the one depth test, [`depth_test`]: strictly less wins) and resolve
//! (round half up).

use embedded_graphics_core::pixelcolor::{Rgb888, RgbColor};

use crate::config::formats::{DEPTH_EMPTY, MAX_VIEWPORT};
use crate::input::MAX_PATTERN;
use crate::raster::store::{depth_test, resolve_colors, DepthTest, PixelStats, SampleStore};

/// Color and depth of `TW×TH` pixels with `S` samples each.
///
/// Sizes are checked at compile time: `1 ≤ TW, TH ≤ 2048` (the render loop walks the screen in
/// `u16` steps of `TW`, `TH`; a zero step would never advance) and `1 ≤ S ≤ 64` (the pattern's
/// limit). A buffer outside these fails to build:
///
/// ```
/// use uvt_core::{Rgb888, TileBuffer};
/// let fb = TileBuffer::<8, 8, 4>::new(Rgb888::new(0, 0, 0));
/// assert_eq!(fb.depth(7, 7, 3), Some(uvt_core::config::formats::DEPTH_EMPTY));
/// ```
/// ```compile_fail,E0080
/// use uvt_core::{Rgb888, TileBuffer};
/// let fb = TileBuffer::<0, 8, 4>::new(Rgb888::new(0, 0, 0));
/// ```
/// ```compile_fail,E0080
/// use uvt_core::{Rgb888, TileBuffer};
/// let fb = TileBuffer::<8, 0, 4>::new(Rgb888::new(0, 0, 0));
/// ```
/// ```compile_fail,E0080
/// use uvt_core::{Rgb888, TileBuffer};
/// let fb = TileBuffer::<8, 8, 0>::new(Rgb888::new(0, 0, 0));
/// ```
/// ```compile_fail,E0080
/// use uvt_core::{Rgb888, TileBuffer};
/// let fb = TileBuffer::<4096, 1, 1>::new(Rgb888::new(0, 0, 0));
/// ```
#[derive(Clone, Debug)]
pub struct TileBuffer<const TW: usize, const TH: usize, const S: usize> {
    color: [[[Rgb888; S]; TW]; TH],
    depth: [[[i32; S]; TW]; TH],
    pub(crate) stats: [[PixelStats; TW]; TH],
}

impl<const TW: usize, const TH: usize, const S: usize> TileBuffer<TW, TH, S> {
    /// The size check of every constructor: evaluating it fails the build unless
    /// `1 ≤ TW, TH ≤ 2048` and `1 ≤ S ≤ 64`.
    const SIZES: () = {
        assert!(
            TW >= 1 && TW <= MAX_VIEWPORT as usize,
            "TileBuffer: TW must be 1..=2048"
        );
        assert!(
            TH >= 1 && TH <= MAX_VIEWPORT as usize,
            "TileBuffer: TH must be 1..=2048"
        );
        assert!(
            S >= 1 && S <= MAX_PATTERN as usize,
            "TileBuffer: S must be 1..=64"
        );
    };

    /// A cleared buffer. Fails to build unless `1 ≤ TW, TH ≤ 2048` and `1 ≤ S ≤ 64`.
    pub fn new(clear: Rgb888) -> Self {
        let () = Self::SIZES;
        TileBuffer {
            color: [[[clear; S]; TW]; TH],
            depth: [[[DEPTH_EMPTY; S]; TW]; TH],
            stats: [[PixelStats::default(); TW]; TH],
        }
    }

    /// Clear color, depth (to [`DEPTH_EMPTY`]) and per-pixel counters.
    pub fn clear(&mut self, clear: Rgb888) {
        *self = Self::new(clear);
    }

    /// Depth-test and write one sample (strictly less wins). `None`, with nothing changed, for
    /// out-of-range indices or `depth == DEPTH_EMPTY` (not a depth the sample test outputs).
    pub fn write(
        &mut self,
        x: usize,
        y: usize,
        s: usize,
        color: Rgb888,
        depth: i32,
    ) -> Option<DepthTest> {
        let d = self.depth.get_mut(y)?.get_mut(x)?.get_mut(s)?;
        let r = depth_test(d, depth);
        if r == Some(DepthTest::Written) {
            if let Some(c) = self
                .color
                .get_mut(y)
                .and_then(|r| r.get_mut(x))
                .and_then(|p| p.get_mut(s))
            {
                *c = color;
            }
        }
        r
    }

    /// Stored depth of one sample (raw I8F24), if in range.
    pub fn depth(&self, x: usize, y: usize, s: usize) -> Option<i32> {
        self.depth.get(y)?.get(x)?.get(s).copied()
    }

    /// The largest stored depth over every sample of the pixels `cols.0..cols.1` ×
    /// `rows.0..rows.1` (ranges clipped to the buffer), and how many slots were read: a pixel's
    /// Zmax register refresh, and the reduction the registers' tile maximum equals
    /// ([`crate::raster::zmax`]). `i32::MIN` with 0 reads for an empty range; an empty slot
    /// reads as [`DEPTH_EMPTY`].
    pub fn max_depth(&self, cols: (usize, usize), rows: (usize, usize)) -> (i32, u64) {
        let mut max = i32::MIN;
        let mut reads = 0u64;
        let pick = |r: (usize, usize), n: usize| r.0.min(n)..r.1.min(n);
        for row in self.depth.get(pick(rows, TH)).unwrap_or(&[]) {
            for px in row.get(pick(cols, TW)).unwrap_or(&[]) {
                for &d in px {
                    max = max.max(d);
                }
                // S ≤ 64 (compile-time check).
                reads = reads.saturating_add(S as u64);
            }
        }
        (max, reads)
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

    /// [`Self::new`] built from zeroed arrays (memclr calls) and [`Self::clear_fill`]: the same
    /// buffer and size check without the unrolled stores (the static-only unit's renderer).
    pub(crate) fn new_fill(clear: Rgb888) -> Self {
        let () = Self::SIZES;
        let mut fb = TileBuffer {
            color: [[[Rgb888::BLACK; S]; TW]; TH],
            depth: [[[0; S]; TW]; TH],
            stats: [[PixelStats::default(); TW]; TH],
        };
        fb.clear_fill(clear);
        fb
    }

    /// [`Self::clear`] as one loop over the pixels (the static-only unit's renderer,
    /// `static_unit.rs`: the same contents without `Self::new`'s unrolled stores, several KB of
    /// a small program's flash).
    #[inline(never)]
    pub(crate) fn clear_fill(&mut self, clear: Rgb888) {
        let pixels = self.color.iter_mut().flatten();
        let pixels = pixels.zip(self.depth.iter_mut().flatten());
        for ((c, d), st) in pixels.zip(self.stats.iter_mut().flatten()) {
            *c = [clear; S];
            *d = [DEPTH_EMPTY; S];
            *st = PixelStats::default();
        }
    }

    /// Count one sample test of pixel (x, y) in its counters; nothing for out-of-range indices.
    pub(crate) fn count(&mut self, x: usize, y: usize, covered: bool) {
        if let Some(ps) = self.stats.get_mut(y).and_then(|r| r.get_mut(x)) {
            ps.tested = ps.tested.saturating_add(1);
            ps.covered = ps.covered.saturating_add(u32::from(covered));
        }
    }

    /// Count one written sample of pixel (x, y) (as [`Self::count`]).
    pub(crate) fn count_written(&mut self, x: usize, y: usize) {
        if let Some(ps) = self.stats.get_mut(y).and_then(|r| r.get_mut(x)) {
            ps.written = ps.written.saturating_add(1);
        }
    }

    /// Resolved color: per channel `(Σ + S/2) / S` (round half up), see [`resolve_colors`].
    pub fn resolve(&self, x: usize, y: usize) -> Rgb888 {
        match self.color.get(y).and_then(|r| r.get(x)) {
            Some(p) => resolve_colors(p),
            None => Rgb888::BLACK,
        }
    }
}

impl<const TW: usize, const TH: usize, const S: usize> SampleStore for TileBuffer<TW, TH, S> {
    #[inline(always)]
    fn size(&self) -> (usize, usize, usize) {
        (TW, TH, S)
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
        TileBuffer::write(self, x, y, s, color, depth)
    }
    #[inline(always)]
    fn count(&mut self, x: usize, y: usize, covered: bool) {
        TileBuffer::count(self, x, y, covered);
    }
    #[inline(always)]
    fn count_written(&mut self, x: usize, y: usize) {
        TileBuffer::count_written(self, x, y);
    }
    #[inline(always)]
    fn max_depth(&self, cols: (usize, usize), rows: (usize, usize)) -> (i32, u64) {
        TileBuffer::max_depth(self, cols, rows)
    }
}

/// `(TW, TH)` as `u16`: both are 1..=2048 (asserted at compile time by [`TileBuffer::new`],
/// the only way to obtain the buffer a tile walk uses), so the conversion is exact.
pub(crate) fn tile_size<const TW: usize, const TH: usize>() -> (u16, u16) {
    (
        u16::try_from(TW).unwrap_or(MAX_VIEWPORT),
        u16::try_from(TH).unwrap_or(MAX_VIEWPORT),
    )
}
