//! Stage 4, optional — Zmax culling (Akenine-Möller, Munkberg, Hasselgren 2007, §3.4): a bounds
//! tile the tile step keeps is skipped for a triangle when the triangle's smallest possible depth
//! is not less than the largest depth stored in that tile, since then every one of its samples
//! would fail the depth test. Only the work changes: image, depth buffer and written samples are
//! bit-identical with and without it (`tests/tests/zmax.rs`).
//!
//! The renderer takes it as a type parameter ([`DepthCull`]: [`NoZmax`], the default, compiles
//! it out; [`Zmax`] runs it). The host's frame driver runs the same decision with the same
//! functions ([`depth_floor`], [`hides`]).
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
//! `sample::planar`): [`DEPTH_NEAR`] too. `tests/tests/zmax.rs` checks the floor against every
//! covered sample's depth at every precision.
//!
//! **The tile's maximum** ([`TileBuffer::max_depth`]): the largest stored depth over every
//! sample of the tile's pixels (an empty slot holds [`crate::config::formats::DEPTH_EMPTY`] =
//! `i32::MAX`, above every floor, so a tile with an empty slot is never culled). The model
//! computes it when it is read; hardware keeps it as a per-tile register ([`ZMAX_BITS`], the
//! depth format) refreshed by a max-reduction of the tile's samples when one is written. The
//! comparison is [`hides`]: `floor ≥ max`, the depth test's tie rule (a sample is written only
//! when strictly nearer, so a sample at exactly the stored depth loses).
//!
//! **Cost** (counted in [`Ops::zmax`], apart from every other stage): the floor, [`FLOOR_OPS`]
//! per triangle; per kept bounds tile, one read-and-compare per sample of the tile (the model's
//! max) and the final comparison.

use crate::config::formats::{DEPTH_FAR, DEPTH_FRAC, DEPTH_NEAR};
use crate::config::precision::Precision;
use crate::config::unit::Unit;
use crate::input::{Triangle, W, Z};
use crate::raster::tile_buffer::TileBuffer;
use crate::sample::takes_planar;
use crate::setup::Setup;
use crate::stats::Ops;

/// Whether a renderer runs Zmax culling (a type parameter of [`crate::Raster`]).
pub trait DepthCull: Copy + Default + core::fmt::Debug + 'static {
    /// Zmax culling runs.
    const ENABLED: bool;
    /// The name in reports (`none`, `zmax`).
    const NAME: &'static str;
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
}

impl DepthCull for Zmax {
    const ENABLED: bool = true;
    const NAME: &'static str = "zmax";
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

/// The Zmax test of one kept bounds tile of `fb`: tile-relative pixels `x0..x1` × `y0..y1`
/// (the tile's maximum read with its reads counted, then [`hides`]).
#[inline]
pub(crate) fn hidden_in<const TW: usize, const TH: usize, const S: usize>(
    floor: i32,
    fb: &TileBuffer<TW, TH, S>,
    cols: (usize, usize),
    rows: (usize, usize),
    ops: &mut Ops,
) -> bool {
    let (max, reads) = fb.max_depth(cols, rows);
    ops.add_zmax(reads);
    hides(floor, max, ops)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::Vertex;

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
