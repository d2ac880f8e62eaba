//! Stage 4, optional — Zmax culling (Akenine-Möller, Munkberg, Hasselgren 2007, §3.4): a bounds
//! tile the tile step keeps is skipped for a triangle when the triangle's smallest possible depth
//! is not less than the largest depth stored in that tile, since then every one of its samples
//! would fail the depth test. Only the work changes: image, depth buffer and written samples are
//! bit-identical with and without it (`tests/tests/model/zmax.rs`).
//!
//! The render loop takes it as a type parameter ([`DepthCull`]: [`NoZmax`], the default,
//! compiles it out; [`Zmax`] runs it), so every renderer — a screen tile on the Cortex-M, a band
//! of the screen on the host — makes the one decision ([`depth_floor`], [`hides`]).
//!
//! **The triangle's depth floor** ([`depth_floor`], once per triangle at setup). For a covered
//! sample every datapath computes its depth as `⌊2^24·Σ e_k·z_k / Σ e_k·w_k⌋`, clamped to
//! [`DEPTH_NEAR`, `DEPTH_FAR`] (`DEPTH_FAR` when the denominator is ≤ 0), where `(w_k, z_k)` are
//! the vertices' values at the sample's t and `e_k` the floor-shifted edge values oriented by
//! the triangle's sign: each `e_k ≥ 0` for a covered sample (a floor shift keeps the sign of a
//! value or makes it 0; `sample::exact`, `sample::bounded::depth`). When every `w_k > 0` the
//! quotient is the convex combination `Σ μ_k·(z_k/w_k)` with `μ_k = e_k·w_k / Σ e_j·w_j ≥ 0`,
//! so it is at least `min_k z_k/w_k` — whatever the triangle's orientation at that t, which is
//! the paper's trap for plane-equation estimates: only vertex values are used here. The lens
//! moves x and y only, so defocus changes nothing. Over the shutter:
//! - the exact datapath uses `w_k(T)`, `z_k(T)` linear in T exactly; the bounded ones (and the
//!   motion-only unit's) round each lerp to nearest, so `|w' − w(T)|, |z' − z(T)| ≤ 1/2` raw
//!   (exact for static and defocus-only triangles);
//! - hence `z'/w' ≥ min((z(T) − ½)/(w(T) + ½), (z(T) − ½)/(w(T) − ½))` whenever `w(T) − ½ > 0`
//!   (the first for a non-negative numerator, the second for a negative one); each of the two is
//!   linear-fractional in T with a denominator that does not vanish on [0, 1] (it is linear and
//!   positive at both ends), hence monotone, and takes its minimum at T = 0 or T = 1.
//!
//! So with raw ends `(w, z)` of every vertex at t = 0 and t = 1, all `w ≥ 1` raw, the floor is
//! `min ⌊2^24·(2z − 1)/(2w ± 1)⌋` over the six ends (`+` for `2z − 1 ≥ 0`, `−` otherwise),
//! clamped to the depth range: every depth the test outputs for this triangle is at least it
//! (`⌊⌋` and the clamp are monotone). A triangle with some end at `w < 1` raw (behind, on or
//! within half an LSB of the camera plane, where the datapaths take their rare paths and depth
//! may diverge) gets [`DEPTH_NEAR`]: it is never culled. Neither is a static triangle at a
//! planar precision (its depth comes from a rounded depth plane with a per-sample error bound,
//! `sample::planar`): [`DEPTH_NEAR`] too. `tests/tests/model/zmax.rs` checks the floor against every
//! covered sample's depth at every precision.
//!
//! **The Zmax registers** ([`DepthCull::Registers`]: [`PixelMax`] with Zmax, the zero-sized
//! [`NoRegisters`] without, so a renderer without Zmax carries and updates nothing). Per pixel of
//! the screen tile, one register in the depth format ([`ZMAX_BITS`], no rounding): the largest of
//! the pixel's `S` stored depths, cleared with the tile to
//! [`crate::config::formats::DEPTH_EMPTY`] = `i32::MAX` (above every floor: a tile with an empty
//! slot is never culled) and refreshed after every written sample ([`ZmaxRegisters::refresh`]:
//! an `S`-input maximum of the pixel's depths — a write lowers one, so the register may fall).
//! Each register therefore equals its pixel's true maximum at every moment, and a bounds tile's
//! maximum is the largest register of its pixels (a `b²`-input maximum): the same value as a
//! reduction over every stored sample ([`crate::raster::tile_buffer::TileBuffer::max_depth`], which the tests compare it
//! with). For a unit with a fixed bounds tile size the registers can be kept per bounds tile
//! instead, refreshed from the same `b²·S` values. The comparison is [`hides`]: `floor ≥ max`,
//! the depth test's tie rule (a sample is written only when strictly nearer, so a sample at
//! exactly the stored depth loses).
//!
//! **Cost** (counted in [`Ops::zmax`], apart from every other stage): the floor, [`FLOOR_OPS`]
//! per triangle; per written sample the register's refresh (`S` depth reads); per kept bounds
//! tile one read per pixel register of the tile and the final comparison.

use crate::config::formats::{DEPTH_EMPTY, DEPTH_FAR, DEPTH_FRAC, DEPTH_NEAR};
use crate::config::precision::Precision;
use crate::config::unit::Unit;
use crate::input::{Triangle, W, Z};
use crate::raster::store::SampleStore;
use crate::sample::takes_planar;
use crate::setup::Setup;
use crate::stats::Ops;

/// Whether a renderer runs Zmax culling (a type parameter of [`crate::Raster`] and
/// [`crate::raster::engine::Engine`]).
pub trait DepthCull: Copy + Default + core::fmt::Debug + Send + Sync + 'static {
    /// Zmax culling runs.
    const ENABLED: bool;
    /// The name in reports (`none`, `zmax`).
    const NAME: &'static str;
    /// The Zmax registers of a `TW` × `TH` screen tile (module docs).
    type Registers<const TW: usize, const TH: usize>: ZmaxRegisters + Cleared;
    /// The Zmax registers of a region of any size, over a caller-owned slice.
    type RegionRegisters<'a>: ZmaxRegisters + Send;
    /// The cleared registers of a region `width` pixels wide over `max`, one value per pixel
    /// ([`RegionMax::new`]; without Zmax nothing is kept and `max` may be empty).
    fn region_registers(
        width: u16,
        max: &mut [i32],
    ) -> Result<Self::RegionRegisters<'_>, crate::error::Error>;
}

/// The Zmax registers the render loop keeps beside its [`SampleStore`] (module docs): one per
/// pixel of the store, or none ([`NoRegisters`]).
pub trait ZmaxRegisters {
    /// Whether these are registers at all: must equal the renderer's [`DepthCull::ENABLED`]
    /// (the loop checks at compile time).
    const KEEPS: bool;
    /// After a sample of pixel (`x`, `y`) of `fb` was written: the pixel's register becomes the
    /// largest of its stored depths (`S` reads counted in `ops.zmax`).
    fn refresh<B: SampleStore>(&mut self, fb: &B, x: usize, y: usize, ops: &mut Ops);
    /// Whether a triangle with depth floor `floor` is hidden in the bounds tile of
    /// store-relative pixels `cols.0..cols.1` × `rows.0..rows.1`: the tile's maximum from its
    /// pixels' registers (one read each, counted), then [`hides`].
    fn hides(&self, floor: i32, cols: (usize, usize), rows: (usize, usize), ops: &mut Ops) -> bool;
    /// Whether there is a register for every pixel of a `width` × `height` store (a bounds tile
    /// beyond the registers would read no register and be culled: the loop refuses them).
    fn covers(&self, width: usize, height: usize) -> bool;
}

/// Registers that start at the clear value ([`crate::config::formats::DEPTH_EMPTY`]).
pub trait Cleared {
    /// Every register cleared.
    fn cleared() -> Self;
}

/// No Zmax culling: the renderer's default; the step is compiled out.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NoZmax;

/// Zmax culling per bounds tile (module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Zmax;

impl DepthCull for NoZmax {
    const ENABLED: bool = false;
    const NAME: &'static str = "none";
    type Registers<const TW: usize, const TH: usize> = NoRegisters;
    type RegionRegisters<'a> = NoRegisters;
    fn region_registers(_: u16, _: &mut [i32]) -> Result<NoRegisters, crate::error::Error> {
        Ok(NoRegisters)
    }
}

impl DepthCull for Zmax {
    const ENABLED: bool = true;
    const NAME: &'static str = "zmax";
    type Registers<const TW: usize, const TH: usize> = PixelMax<TW, TH>;
    type RegionRegisters<'a> = RegionMax<'a>;
    fn region_registers(width: u16, max: &mut [i32]) -> Result<RegionMax<'_>, crate::error::Error> {
        RegionMax::new(width, max)
    }
}

/// No registers (a renderer without Zmax): nothing stored, refreshed or culled.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NoRegisters;

impl Cleared for NoRegisters {
    #[inline(always)]
    fn cleared() -> Self {
        NoRegisters
    }
}

impl ZmaxRegisters for NoRegisters {
    const KEEPS: bool = false;
    #[inline(always)]
    fn refresh<B: SampleStore>(&mut self, _: &B, _: usize, _: usize, _: &mut Ops) {}
    #[inline(always)]
    fn hides(&self, _: i32, _: (usize, usize), _: (usize, usize), _: &mut Ops) -> bool {
        false
    }
    #[inline(always)]
    fn covers(&self, _: usize, _: usize) -> bool {
        true
    }
}

/// One Zmax register per pixel of a `TW` × `TH` screen tile: the largest stored depth of the
/// pixel's samples (module docs).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PixelMax<const TW: usize, const TH: usize> {
    max: [[i32; TW]; TH],
}

impl<const TW: usize, const TH: usize> PixelMax<TW, TH> {
    /// The largest register over the pixels `cols.0..cols.1` × `rows.0..rows.1` (clipped to the
    /// tile) and how many were read; `i32::MIN` with 0 reads for an empty range.
    pub fn tile_max(&self, cols: (usize, usize), rows: (usize, usize)) -> (i32, u64) {
        let pick = |r: (usize, usize), n: usize| r.0.min(n)..r.1.min(n);
        let mut max = i32::MIN;
        let mut reads = 0u64;
        for row in self.max.get(pick(rows, TH)).unwrap_or(&[]) {
            for &m in row.get(pick(cols, TW)).unwrap_or(&[]) {
                max = max.max(m);
                reads = reads.saturating_add(1);
            }
        }
        (max, reads)
    }
}

impl<const TW: usize, const TH: usize> Cleared for PixelMax<TW, TH> {
    fn cleared() -> Self {
        PixelMax {
            max: [[DEPTH_EMPTY; TW]; TH],
        }
    }
}

impl<const TW: usize, const TH: usize> ZmaxRegisters for PixelMax<TW, TH> {
    const KEEPS: bool = true;

    fn refresh<B: SampleStore>(&mut self, fb: &B, x: usize, y: usize, ops: &mut Ops) {
        let (max, reads) = fb.max_depth((x, x.saturating_add(1)), (y, y.saturating_add(1)));
        if let Some(m) = self.max.get_mut(y).and_then(|r| r.get_mut(x)) {
            *m = max;
            ops.add_zmax(reads);
        }
    }

    fn hides(&self, floor: i32, cols: (usize, usize), rows: (usize, usize), ops: &mut Ops) -> bool {
        let (max, reads) = self.tile_max(cols, rows);
        ops.add_zmax(reads);
        hides(floor, max, ops)
    }

    #[inline(always)]
    fn covers(&self, width: usize, height: usize) -> bool {
        width <= TW && height <= TH
    }
}

/// One Zmax register per pixel of a [`crate::raster::store::RegionBuffer`]'s rectangle, over a
/// caller-owned slice (row-major, `width` pixels a row): [`PixelMax`] of any size.
#[derive(Debug)]
pub struct RegionMax<'a> {
    max: &'a mut [i32],
    width: usize,
}

impl<'a> RegionMax<'a> {
    /// Registers of a rectangle `width` pixels wide, one per value of `max` (a whole number of
    /// rows, at least one), cleared. [`crate::error::Error::PatternShape`] (naming the length) when
    /// `width` is 0, `max` is empty or `width` does not divide its length.
    pub fn new(width: u16, max: &'a mut [i32]) -> Result<RegionMax<'a>, crate::error::Error> {
        let w = usize::from(width);
        if w == 0 || max.is_empty() || max.len().checked_rem(w) != Some(0) {
            return Err(crate::error::Error::PatternShape {
                block: width,
                spp: 0,
                len: max.len(),
            });
        }
        max.fill(DEPTH_EMPTY);
        Ok(RegionMax { max, width: w })
    }

    /// The largest register over the pixels `cols.0..cols.1` × `rows.0..rows.1` (clipped) and
    /// how many were read; `i32::MIN` with 0 reads for an empty range.
    pub fn tile_max(&self, cols: (usize, usize), rows: (usize, usize)) -> (i32, u64) {
        let height = self.max.len().checked_div(self.width).unwrap_or(0);
        let c0 = cols.0.min(self.width);
        let c1 = cols.1.min(self.width).max(c0);
        let (mut max, mut reads) = (i32::MIN, 0u64);
        for y in rows.0.min(height)..rows.1.min(height) {
            // y < height, c ≤ width: y·width + c ≤ len (checked regardless).
            let at = |c: usize| y.checked_mul(self.width)?.checked_add(c);
            let (Some(a), Some(b)) = (at(c0), at(c1)) else {
                continue;
            };
            let regs = self.max.get(a..b).unwrap_or(&[]);
            for &m in regs {
                max = max.max(m);
            }
            reads = reads.saturating_add(u64::try_from(regs.len()).unwrap_or(u64::MAX));
        }
        (max, reads)
    }
}

impl ZmaxRegisters for RegionMax<'_> {
    const KEEPS: bool = true;

    fn refresh<B: SampleStore>(&mut self, fb: &B, x: usize, y: usize, ops: &mut Ops) {
        if x >= self.width {
            return;
        }
        let (max, reads) = fb.max_depth((x, x.saturating_add(1)), (y, y.saturating_add(1)));
        let at = y.checked_mul(self.width).and_then(|r| r.checked_add(x));
        if let Some(m) = at.and_then(|i| self.max.get_mut(i)) {
            *m = max;
            ops.add_zmax(reads);
        }
    }

    fn hides(&self, floor: i32, cols: (usize, usize), rows: (usize, usize), ops: &mut Ops) -> bool {
        let (max, reads) = self.tile_max(cols, rows);
        ops.add_zmax(reads);
        hides(floor, max, ops)
    }

    fn covers(&self, width: usize, height: usize) -> bool {
        let rows = self.max.len().checked_div(self.width).unwrap_or(0);
        width <= self.width && height <= rows
    }
}

/// Bits of one tile's stored maximum: the depth format, I8F24 (no rounding, so no widening).
pub const ZMAX_BITS: u32 = 32;

/// Operations of [`depth_floor`] per triangle: per vertex and shutter end a doubling and an
/// add for each of numerator and denominator, the scale, the division and the running minimum
/// (7), six ends, and the clamp (2).
pub const FLOOR_OPS: u64 = 6 * 7 + 2;

/// The depth floor of a triangle from its vertices' raw `(w, z)` at both shutter ends, `wz[end][k]`
/// (module docs): every depth the exact or the bounded datapath outputs for a covered sample of
/// the triangle is at least the result. [`DEPTH_NEAR`] (no culling) when some end has `w < 1` raw.
///
/// Ranges: `|w|, |z| ≤ 2^29` (the declared domain, checked by [`Triangle::new`]), so
/// `|2z − 1|·2^24 < 2^55` and `1 ≤ 2w ± 1 ≤ 2^30 + 1`: every value fits `i64` and the divisor
/// is positive. `tests::floor_at_the_domain_corners` drives the extremes.
#[allow(clippy::arithmetic_side_effects)]
pub fn floor_of(wz: &[[(i32, i32); 3]; 2], ops: &mut Ops) -> i32 {
    ops.add_zmax(FLOOR_OPS);
    let mut lo = i64::MAX;
    for &(w, z) in wz.iter().flatten() {
        let (w, z) = (i64::from(w), i64::from(z));
        if w < 1 {
            return DEPTH_NEAR;
        }
        let num = (2 * z - 1) * (1 << DEPTH_FRAC);
        let den = if num >= 0 { 2 * w + 1 } else { 2 * w - 1 };
        // den ≥ 1: the floor division cannot fail.
        lo = lo.min(num.div_euclid(den));
    }
    // In [DEPTH_NEAR, DEPTH_FAR] after the clamp, so the conversion is exact.
    i32::try_from(lo.clamp(i64::from(DEPTH_NEAR), i64::from(DEPTH_FAR))).unwrap_or(DEPTH_NEAR)
}

/// The raw `(w, z)` of `tri`'s vertices at both shutter ends, as [`floor_of`] takes them.
pub fn ends_wz(tri: &Triangle) -> [[(i32, i32); 3]; 2] {
    tri.v.map(|end| end.map(|v| (v[W], v[Z])))
}

/// The depth floor of a general-pipeline setup of precision `P` on unit `U`: [`floor_of`] its
/// (unit-view) triangle, or [`DEPTH_NEAR`] where the planar test decides (module docs).
pub fn depth_floor<P: Precision, U: Unit>(s: &Setup, ops: &mut Ops) -> i32 {
    if takes_planar::<P, U>(s.class()) {
        return DEPTH_NEAR;
    }
    floor_of(&ends_wz(s.tri()), ops)
}

/// Whether a triangle with depth floor `floor` is hidden in a tile whose largest stored depth is
/// `max`: `floor ≥ max` (one comparison, counted).
#[inline]
pub fn hides(floor: i32, max: i32, ops: &mut Ops) -> bool {
    ops.add_zmax(1);
    floor >= max
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::Vertex;
    use crate::raster::store::DepthTest;
    use crate::raster::tile_buffer::TileBuffer;

    fn tri(w: [i32; 3], z: [i32; 3]) -> Triangle {
        let x = [0, 65536, 2 * 65536];
        let v = [0, 1, 2].map(|k| {
            let pick = |a: [i32; 3]| a.get(k).copied().unwrap_or(0);
            Vertex::from_bits([pick(x), 0, pick(z), pick(w), 0])
        });
        Triangle::new_static(v).expect("in domain")
    }

    #[test]
    fn floor_at_the_domain_corners() {
        let m = 1 << 29;
        let mut ops = Ops::default();
        // z/w = -1 at the largest w: the floor lies just below -1.
        let f = floor_of(&ends_wz(&tri([m; 3], [-m; 3])), &mut ops);
        assert!(f < -(1 << 24) && f > -(1 << 24) - 4, "{f}");
        // z/w = 2^29 at w = 1 raw saturates to the far end.
        assert_eq!(
            floor_of(&ends_wz(&tri([1; 3], [m; 3])), &mut ops),
            DEPTH_FAR
        );
        // z/w = -2^29 at w = 1 raw saturates to the near end.
        assert_eq!(
            floor_of(&ends_wz(&tri([1; 3], [-m; 3])), &mut ops),
            DEPTH_NEAR
        );
        // A vertex at w = 0: no floor.
        assert_eq!(
            floor_of(&ends_wz(&tri([m, m, 0], [0; 3])), &mut ops),
            DEPTH_NEAR
        );
        assert_eq!(ops.zmax, 4 * FLOOR_OPS);
    }

    #[test]
    fn floor_is_below_each_vertex_depth() {
        let mut ops = Ops::default();
        let t = tri([65536, 2 * 65536, 3 * 65536], [32768, 65536, 3 * 65536]);
        let f = floor_of(&ends_wz(&t), &mut ops);
        // min z/w = 0.5 (vertex 0, and vertex 1): 2^23, less half an LSB of z over (w + ½).
        assert!(f < 1 << 23 && f > (1 << 23) - 256, "{f} {f:#x}");
    }

    /// Registers refreshed after each write equal the reduction over the stored samples for every
    /// rectangle of pixels, including after a write that lowers a pixel's maximum; without the
    /// refresh they would stay at the clear value.
    #[test]
    fn registers_equal_the_stored_maximum() {
        use embedded_graphics_core::pixelcolor::Rgb888;
        let mut fb = TileBuffer::<3, 2, 4>::new(Rgb888::new(0, 0, 0));
        let mut regs = PixelMax::<3, 2>::cleared();
        let mut ops = Ops::default();
        let mut seed = 0x2545_f491_u32;
        let mut next = move || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            seed >> 8
        };
        let mut written = 0u64;
        for _ in 0..400 {
            let (x, y, s) = (
                next() as usize % 3,
                next() as usize % 2,
                next() as usize % 4,
            );
            let depth = i32::try_from(next() % 4096).unwrap_or(0) - 2048;
            if fb.write(x, y, s, Rgb888::new(9, 9, 9), depth) == Some(DepthTest::Written) {
                regs.refresh(&fb, x, y, &mut ops);
                written += 1;
            }
            for (cols, rows) in [((0, 3), (0, 2)), ((x, x + 1), (y, y + 1)), ((1, 3), (1, 2))] {
                let (want, _) = fb.max_depth(cols, rows);
                let (got, reads) = regs.tile_max(cols, rows);
                assert_eq!(
                    got, want,
                    "pixels {cols:?} x {rows:?} after writing ({x}, {y}, {s})"
                );
                assert_eq!(reads, ((cols.1 - cols.0) * (rows.1 - rows.0)) as u64);
            }
        }
        assert!(written > 24, "the maxima fell: {written} writes");
        assert_eq!(ops.zmax, 4 * written, "S reads per refresh");
        assert!(regs.tile_max((0, 3), (0, 2)).0 < DEPTH_EMPTY);
    }

    #[test]
    fn hides_uses_the_depth_tests_tie_rule() {
        let mut ops = Ops::default();
        assert!(hides(5, 5, &mut ops));
        assert!(hides(6, 5, &mut ops));
        assert!(!hides(4, 5, &mut ops));
        assert!(!hides(DEPTH_FAR, i32::MAX, &mut ops));
        assert_eq!(ops.zmax, 4);
    }
}
