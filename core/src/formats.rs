//! Every signal's number format, in one place.
//!
//! This is the table a hardware engineer copies into RTL. Each public alias names one signal; the
//! constants below fix the fraction bits and the declared input domain. `core/README.md` carries
//! the same table with the derived width of every intermediate.
//!
//! | signal | alias / raw type | int.frac bits | LSB | range (declared domain) |
//! |---|---|---|---|---|
//! | clip x, y, z, w, CoC | [`Coord`] = I16F16 in `i32` | 14.16 used (sign + 13 + 16) | 2^-16 | \|v\| ≤ 2^13 = 8192 |
//! | time t | [`Time`] = I16F16 in `i32` | 1.16 unsigned used | 2^-16 | 0 ≤ t ≤ 1 |
//! | lens u, v | [`Lens`] = I16F16 in `i32` | 2.16 signed used | 2^-16 | -1 ≤ u ≤ 1 |
//! | sub-pixel x, y | [`SubPixel`] = U0F8 in `u8` | 0.8 | 2^-8 px | [0, 255/256] |
//! | pixel column/row | `u16` | 11.0 | 1 px | < 2048 |
//! | depth z/w | [`Depth`] = I8F24 in `i32` | 8.24 | 2^-24 | saturated to raw [`DEPTH_NEAR`, `DEPTH_FAR`]; raw [`DEPTH_EMPTY`] is never produced |
//! | box / footprint coordinates | [`PixelCoord`] = `i64` raw | 42.16 | 2^-16 px | \|X\| < 2^57 |
//! | dual-space δ | [`DualDelta`] = `i64` raw | 28.16 (clip·px) | 2^-16 | \|δ\| < 2^44 raw |
//! | sample-test vertex P | `i64` raw | 14.F, F = 16/32/48 by class | 2^-F | \|P\| ≤ 2^14 |
//! | edge normal P×P | `i128` raw | 29.2F | 2^-2F | < 2^125 raw |
//! | edge value E, det | [`crate::wide::Wide`] 192-bit | | | < 2^190 raw |
//!
//! Rounding: inputs are exact; the sample test has no rounding at all; every bound is rounded
//! outward (see `bounds.rs`); depth rounds toward -∞ (see `sample.rs`); resolve rounds half up.

use fixed::types::{I16F16, I8F24, U0F8};

/// Clip-space coordinate or circle-of-confusion radius: I16F16, declared domain |v| ≤ 2^13.
pub type Coord = I16F16;
/// Shutter time: I16F16 storage, declared domain [0, 1] (raw 0 ..= 65536).
pub type Time = I16F16;
/// Lens coordinate u or v: I16F16 storage, declared domain [-1, 1] (raw -65536 ..= 65536).
pub type Lens = I16F16;
/// Sub-pixel sample offset inside a pixel: U0F8, [0, 1).
pub type SubPixel = U0F8;
/// Depth z/w of a covered sample: I8F24, saturated to raw [`DEPTH_NEAR`, `DEPTH_FAR`] =
/// [-128, 128 − 2^-23]. Raw [`DEPTH_EMPTY`] (= `i32::MAX`) is reserved for "no sample written" and
/// is never a depth output, so a covered sample always wins against an empty slot.
pub type Depth = I8F24;
/// Screen position in pixels with [`PX_FRAC`] fraction bits (raw `i64`), used by bounds.
pub type PixelCoord = i64;
/// Dual-space distance δ = (a + w)·E − 2·w·ξ (raw `i64`, [`COORD_FRAC`] fraction bits).
pub type DualDelta = i64;

/// Fraction bits of [`Coord`].
pub const COORD_FRAC: u32 = 16;
/// Largest allowed |raw| of a [`Coord`] input: 2^13 in value (2^29 raw).
pub const COORD_LIMIT_RAW: i32 = 1 << 29;
/// Fraction bits of t, u and v.
pub const TUV_FRAC: u32 = 16;
/// Raw value of 1.0 in the t/u/v format.
pub const TUV_ONE: i32 = 1 << TUV_FRAC;
/// Sub-pixel fraction bits of sample positions.
pub const SUBPIXEL_BITS: u32 = 8;
/// Largest viewport width or height, in pixels.
pub const MAX_VIEWPORT: u16 = 2048;
/// Fraction bits of [`Depth`].
pub const DEPTH_FRAC: u32 = 24;
/// Raw depth a tile buffer clears to: "empty". The sample test never outputs it.
pub const DEPTH_EMPTY: i32 = i32::MAX;
/// The far end of the depth outputs (raw): z/w ≥ 128 − 2^-23 saturates here, and so does a hit
/// whose shifted denominator is not positive (see `sample.rs`).
pub const DEPTH_FAR: i32 = i32::MAX - 1;
/// The near end of the depth outputs (raw): z/w ≤ −128 saturates here.
pub const DEPTH_NEAR: i32 = i32::MIN;
/// Fraction bits of [`PixelCoord`].
pub const PX_FRAC: u32 = 16;
/// Fixed-point shift of the lens-bound reciprocals (`2^RECIP_SHIFT / Δ`), see `bounds.rs`.
pub const RECIP_SHIFT: u32 = 80;
/// Significant bits kept of each edge value for the depth interpolation, see `sample.rs`.
pub const DEPTH_EDGE_BITS: u32 = 32;

/// A precision configuration: the fraction bits of the positions (clip x, y, z, w and CoC), of
/// t/u/v, and of the bound arithmetic (the pixel grid the bounds' box coordinates are rounded to).
///
/// Narrower formats are modelled inside the default containers: a value with F < 16 fraction bits
/// is stored in its I16F16 container with its low 16 − F bits zero (the checked constructors
/// `Triangle::new_with` and `SamplePattern::new_with` refuse anything else). The sample test is
/// exact on its inputs and the bounds round to the configuration's grids, so every output is the
/// one a datapath of exactly these widths produces. The integer bits and the domain are fixed.
///
/// The trait is sealed: [`Prec`] is its only implementor, whose const assertions keep every
/// width inside the ranges the overflow proofs assume (a user impl with, say, 20 position
/// fraction bits would break them). Implementing it outside the crate does not build:
///
/// ```compile_fail,E0277
/// #[derive(Clone, Copy, Debug, Default)]
/// struct Wider;
/// impl uvt_core::Precision for Wider {
///     const POS_FRAC: u32 = 20;
///     const TUV_FRAC: u32 = 16;
///     const BOUND_FRAC: u32 = 16;
/// }
/// ```
pub trait Precision: sealed::Sealed + Copy + Default + core::fmt::Debug + 'static {
    /// fraction bits of positions and CoC (2..=16)
    const POS_FRAC: u32;
    /// fraction bits of t, u, v (2..=16)
    const TUV_FRAC: u32;
    /// fraction bits of the bounds' pixel coordinates (0..=16)
    const BOUND_FRAC: u32;
    /// The sample test's datapath: `None` = the exact test (`sample.rs`); `Some(s)` = the
    /// bounded test (`bounded.rs`) whose sample-relative offsets are rounded to a grid of `2^s`
    /// (s ∈ [`OFFSET_SHIFT_MIN`]..=[`OFFSET_SHIFT_MAX`]).
    const OFFSET_SHIFT: Option<u32> = None;
    /// Whether static triangles (class `Static`) take the planar test (`planar.rs`: each
    /// vertex rounded once to 15 bits, then the exact test on the rounded triangle) instead of
    /// `OFFSET_SHIFT`'s test. Only a
    /// [`Planar`] precision sets it; its other classes run the bounded test.
    const PLANAR: bool = false;
}

mod sealed {
    /// Private supertrait of [`super::Precision`]: only this crate can implement it.
    pub trait Sealed {}
    impl<const POS: u32, const TUV: u32, const BND: u32> Sealed for super::Prec<POS, TUV, BND> {}
    impl<const POS: u32, const TUV: u32, const BND: u32, const OFF: u32> Sealed
        for super::Bounded<POS, TUV, BND, OFF>
    {
    }
    impl<const POS: u32, const TUV: u32, const BND: u32, const OFF: u32> Sealed
        for super::Planar<POS, TUV, BND, OFF>
    {
    }
}

/// The precision with `POS`, `TUV` and `BND` fraction bits (checked at compile time).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Prec<const POS: u32, const TUV: u32, const BND: u32>;

impl<const POS: u32, const TUV: u32, const BND: u32> Precision for Prec<POS, TUV, BND> {
    const POS_FRAC: u32 = {
        assert!(POS >= 2 && POS <= 16, "POS fraction bits must be 2..=16");
        POS
    };
    const TUV_FRAC: u32 = {
        assert!(TUV >= 2 && TUV <= 16, "TUV fraction bits must be 2..=16");
        TUV
    };
    const BOUND_FRAC: u32 = {
        assert!(BND <= 16, "bound fraction bits must be 0..=16");
        BND
    };
}

/// Smallest offset-grid shift of the bounded sample test: with it every rounded offset has
/// |a'| ≤ 2^30 (see `bounded.rs`), so every multiplier operand is ≤ 32 bits.
pub const OFFSET_SHIFT_MIN: u32 = 20;
/// Largest offset-grid shift of the bounded sample test (offsets of ≥ 19 bits with sign; keeps
/// the conservative epsilon < 2^24 raw, inside the bounds' range proofs).
pub const OFFSET_SHIFT_MAX: u32 = 32;

/// A precision with the **bounded** sample test (`bounded.rs`): `POS`, `TUV`, `BND` as in
/// [`Prec`], and the sample-relative offsets rounded to a grid of `2^OFF` raw units
/// (`OFF` ∈ [`OFFSET_SHIFT_MIN`]..=[`OFFSET_SHIFT_MAX`], checked at compile time). Setup and
/// the bounds widen by the conservative epsilon the rounding needs ([`crate::bounded::Eps`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Bounded<const POS: u32, const TUV: u32, const BND: u32, const OFF: u32>;

impl<const POS: u32, const TUV: u32, const BND: u32, const OFF: u32> Precision
    for Bounded<POS, TUV, BND, OFF>
{
    const POS_FRAC: u32 = <Prec<POS, TUV, BND> as Precision>::POS_FRAC;
    const TUV_FRAC: u32 = <Prec<POS, TUV, BND> as Precision>::TUV_FRAC;
    const BOUND_FRAC: u32 = <Prec<POS, TUV, BND> as Precision>::BOUND_FRAC;
    const OFFSET_SHIFT: Option<u32> = {
        assert!(
            OFF >= OFFSET_SHIFT_MIN && OFF <= OFFSET_SHIFT_MAX,
            "OFF must be OFFSET_SHIFT_MIN..=OFFSET_SHIFT_MAX"
        );
        Some(OFF)
    };
}

/// A precision with the **planar static** test (`planar.rs`, name `planar-POS-TUV-BND-OFF`):
/// exactly [`Bounded<POS, TUV, BND, OFF>`] for the moving and defocused classes, and for static
/// triangles (class `Static`, camera-plane crossers included) the planar test — each vertex
/// rounded once to 15 bits (per-vertex shift), the exact i32 edge normals of the rounded
/// triangle, three 32 × 32 dot products per sample: watertight at edges and vertices — with a
/// per-triangle conservative epsilon (the rounding residual, [`crate::planar`]). An addition: the default
/// configuration is unchanged.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Planar<const POS: u32, const TUV: u32, const BND: u32, const OFF: u32>;

impl<const POS: u32, const TUV: u32, const BND: u32, const OFF: u32> Precision
    for Planar<POS, TUV, BND, OFF>
{
    const POS_FRAC: u32 = <Bounded<POS, TUV, BND, OFF> as Precision>::POS_FRAC;
    const TUV_FRAC: u32 = <Bounded<POS, TUV, BND, OFF> as Precision>::TUV_FRAC;
    const BOUND_FRAC: u32 = <Bounded<POS, TUV, BND, OFF> as Precision>::BOUND_FRAC;
    const OFFSET_SHIFT: Option<u32> = <Bounded<POS, TUV, BND, OFF> as Precision>::OFFSET_SHIFT;
    const PLANAR: bool = true;
}

/// The planar static configuration beside the default (`planar-16-16-16-20`): the default's
/// bounded test for every moving or defocused class, the planar test for static triangles.
pub type PlanarPrecision = Planar<16, 16, 16, 20>;

/// The hardware-plausible bounded configuration (`bounded-16-16-16-20`): 16 fraction bits
/// everywhere, offsets on a `2^20` grid (i32 multiplier operands, i64 products). The default.
pub type BoundedPrecision = Bounded<16, 16, 16, 20>;

/// The exact configuration (`exact-16-16-16`): 16 fraction bits everywhere and the exact sample
/// test of `sample.rs`. Always built and tested beside the default; the committed golden
/// vectors are of this configuration.
pub type Exact = Prec<16, 16, 16>;

/// The default configuration: the bounded (hardware-width) sample test, [`BoundedPrecision`].
pub type DefaultPrecision = BoundedPrecision;

/// The fraction bits of a [`Precision`], carried at run time by a setup. Only built from a
/// [`Precision`] ([`PrecisionBits::of`]), so `pos`, `tuv` ∈ 2..=16 and `bnd` ∈ 0..=16.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PrecisionBits {
    pos: u32,
    tuv: u32,
    bnd: u32,
    off: Option<u32>,
    planar: bool,
}

impl PrecisionBits {
    /// Fraction bits of positions (2..=16).
    pub const fn pos(&self) -> u32 {
        self.pos
    }
    /// Fraction bits of t, u, v (2..=16).
    pub const fn tuv(&self) -> u32 {
        self.tuv
    }
    /// Fraction bits of the bounds' pixel coordinates (0..=16).
    pub const fn bnd(&self) -> u32 {
        self.bnd
    }
    /// The offset-grid shift of the bounded sample test ([`OFFSET_SHIFT_MIN`]..=
    /// [`OFFSET_SHIFT_MAX`]), `None` for the exact test.
    pub const fn offset_shift(&self) -> Option<u32> {
        self.off
    }
    /// Whether static triangles take the planar test ([`Precision::PLANAR`]).
    pub const fn planar(&self) -> bool {
        self.planar
    }
    /// The bits of `P`.
    pub const fn of<P: Precision>() -> PrecisionBits {
        PrecisionBits {
            pos: P::POS_FRAC,
            tuv: P::TUV_FRAC,
            bnd: P::BOUND_FRAC,
            off: P::OFFSET_SHIFT,
            planar: P::PLANAR,
        }
    }
    /// The default's.
    pub const DEFAULT: PrecisionBits = PrecisionBits::of::<DefaultPrecision>();
}

/// `2^k − 1`, the mask of the low `k` bits, for `k ≤ 30` (`None` above): the grid check of a
/// narrower precision (`k = 16 − frac ≤ 14`).
pub(crate) const fn low_bits_mask(k: u32) -> Option<i32> {
    match 2i32.checked_pow(k) {
        Some(p) => p.checked_sub(1),
        None => None,
    }
}

/// Floor division of `n` by a positive `d` (rounds toward -∞). `d > 0` is the caller's duty and
/// is checked: a non-positive `d` returns `None`.
#[inline]
pub fn floor_div(n: i128, d: i128) -> Option<i128> {
    if d <= 0 {
        return None;
    }
    // Same exact quotient through a 64-bit divide when both operands fit (much cheaper on a
    // 32-bit core than the 128-bit library divide); d > 0 so `div_euclid` is the floor.
    if let (Ok(n64), Ok(d64)) = (i64::try_from(n), i64::try_from(d)) {
        return Some(n64.div_euclid(d64) as i128);
    }
    Some(n.div_euclid(d))
}

/// Ceiling division of `n` by a positive `d` (rounds toward +∞); `None` if `d ≤ 0`.
#[inline]
pub fn ceil_div(n: i128, d: i128) -> Option<i128> {
    floor_div(n.checked_neg()?, d).and_then(i128::checked_neg)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_directions() {
        assert_eq!(floor_div(7, 2), Some(3));
        assert_eq!(floor_div(-7, 2), Some(-4));
        assert_eq!(ceil_div(7, 2), Some(4));
        assert_eq!(ceil_div(-7, 2), Some(-3));
        assert_eq!(ceil_div(6, 3), Some(2));
        assert_eq!(floor_div(1, 0), None);
        assert_eq!(ceil_div(1, -1), None);
    }
}
