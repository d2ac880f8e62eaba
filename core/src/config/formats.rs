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
//! | edge value E, det | [`crate::arith::wide::Wide`] 192-bit | | | < 2^190 raw |
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

/// Screen position in pixels with 16 fraction bits (raw `i64`), used by bounds.
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

/// Fixed-point shift of the lens-bound reciprocals (`2^RECIP_SHIFT / Δ`), see `bounds.rs`.
pub const RECIP_SHIFT: u32 = 80;

/// Significant bits kept of each edge value for the depth interpolation, see `sample.rs`.
pub const DEPTH_EDGE_BITS: u32 = 32;
