//! Errors returned by the core. The core never panics; every refusal names what is wrong.

use core::fmt;

/// Which field of a vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Field {
    /// clip x
    X,
    /// clip y
    Y,
    /// clip z
    Z,
    /// clip w
    W,
    /// circle-of-confusion radius
    Coc,
}

impl fmt::Display for Field {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Field::X => "x",
            Field::Y => "y",
            Field::Z => "z",
            Field::W => "w",
            Field::Coc => "coc",
        })
    }
}

/// Which coordinate of a sample.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SampleField {
    /// shutter time t
    T,
    /// lens u
    U,
    /// lens v
    V,
}

impl fmt::Display for SampleField {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            SampleField::T => "t",
            SampleField::U => "u",
            SampleField::V => "v",
        })
    }
}

/// Everything the core can refuse.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Error {
    /// A vertex coordinate is outside the declared domain |v| ≤ 2^13.
    CoordOutOfDomain {
        /// vertex index 0..3
        vertex: u8,
        /// 0 for shutter open, 1 for close
        time: u8,
        /// which field
        field: Field,
        /// the raw I16F16 bits
        raw: i32,
    },
    /// A vertex coordinate has bits below the configured precision's position grid.
    CoordOffGrid {
        /// vertex index 0..3
        vertex: u8,
        /// 0 for shutter open, 1 for close
        time: u8,
        /// which field
        field: Field,
        /// the raw I16F16 bits
        raw: i32,
        /// the precision's position fraction bits
        frac: u8,
    },
    /// Viewport width or height is 0 or above 2048.
    Viewport {
        /// requested width
        width: u16,
        /// requested height
        height: u16,
    },
    /// The sample table's length is not block² × spp, or block/spp is 0 or too large.
    PatternShape {
        /// block side N
        block: u16,
        /// samples per pixel S
        spp: u16,
        /// number of samples supplied
        len: usize,
    },
    /// A sample's t is outside [0, 1] or u/v outside [-1, 1] (refused by `Sample::new`).
    SampleOutOfDomain {
        /// which coordinate
        field: SampleField,
        /// its raw I16F16 bits
        raw: i32,
    },
    /// An interval's ends are outside [-1, 1] (raw ±65536) or `lo > hi`.
    Interval {
        /// requested lower end, raw
        lo: i32,
        /// requested upper end, raw
        hi: i32,
    },
    /// A sample's t, u or v has bits below the configured precision's t/u/v grid.
    SampleOffGrid {
        /// index in the table
        index: usize,
        /// the precision's t/u/v fraction bits
        frac: u8,
    },
    /// The tile framebuffer's sample count differs from the pattern's spp.
    SppMismatch {
        /// framebuffer samples per pixel
        tile: u16,
        /// pattern samples per pixel
        pattern: u16,
    },
    /// Bounds-tile size not 1, 2, 4 or 8, or it does not divide the screen tile.
    BoundsTile {
        /// requested size
        size: u8,
    },
    /// More triangles than the renderer's fixed capacity.
    TooManyTriangles {
        /// capacity
        capacity: usize,
    },
    /// A pixel outside the viewport was asked for.
    PixelOutOfRange,
    /// A primitive's class needs an effect the renderer's [`crate::config::unit::Unit`] has no
    /// hardware for (e.g. a moving triangle in a static-only unit): refused, never rendered
    /// without the effect.
    ClassNotInUnit {
        /// index of the primitive in the list handed to the renderer
        index: usize,
        /// its class (`Triangle::class`)
        class: crate::config::class::Class,
        /// the unit's name (`Unit::NAME`)
        unit: &'static str,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Error::CoordOutOfDomain { vertex, time, field, raw } => write!(
                f,
                "vertex {vertex} at t{time}: {field} = raw {raw:#010x} is outside the domain |v| <= 8192"
            ),
            Error::CoordOffGrid { vertex, time, field, raw, frac } => write!(
                f,
                "vertex {vertex} at t{time}: {field} = raw {raw:#010x} is not on the {frac}-fraction-bit grid of the configured precision"
            ),
            Error::SampleOffGrid { index, frac } => {
                write!(f, "sample {index}: t, u, v must lie on the {frac}-fraction-bit grid of the configured precision")
            }
            Error::Viewport { width, height } => {
                write!(f, "viewport {width}x{height}: each side must be 1..=2048")
            }
            Error::PatternShape { block, spp, len } => write!(
                f,
                "sample table: block {block}, spp {spp} need block*block*spp samples (1..=64 each), got {len}"
            ),
            Error::SampleOutOfDomain { field, raw } => write!(
                f,
                "sample {field} = raw {raw:#010x} ({raw}) is outside the domain (t in [0,1], u and v in [-1,1])"
            ),
            Error::Interval { lo, hi } => write!(
                f,
                "interval [{lo:#x}, {hi:#x}] (raw {lo}, {hi}): ends must satisfy -65536 <= lo <= hi <= 65536"
            ),
            Error::SppMismatch { tile, pattern } => {
                write!(f, "tile buffer has {tile} samples per pixel, the pattern {pattern}")
            }
            Error::BoundsTile { size } => {
                write!(f, "bounds tile {size}: must be 1, 2, 4 or 8 and divide the screen tile")
            }
            Error::TooManyTriangles { capacity } => {
                write!(f, "more than {capacity} triangles for this renderer")
            }
            Error::PixelOutOfRange => f.write_str("pixel outside the viewport"),
            Error::ClassNotInUnit { index, class, unit } => write!(
                f,
                "primitive {index}: class {} is not accepted by the {unit} unit",
                class.name()
            ),
        }
    }
}
