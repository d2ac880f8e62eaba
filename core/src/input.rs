//! Checked inputs: triangles, viewport, sample table. Constructors refuse anything outside the
//! declared domain of `formats.rs`, so every later stage may rely on those ranges.

use embedded_graphics_core::pixelcolor::Rgb888;

use crate::arith::div::low_bits_mask;
use crate::config::class::Class;
use crate::config::formats::{
    Coord, Lens, SubPixel, Time, COORD_FRAC, COORD_LIMIT_RAW, MAX_VIEWPORT, TUV_FRAC, TUV_ONE,
};
use crate::config::precision::{DefaultPrecision, Precision};
use crate::error::{Error, Field, SampleField};

/// One vertex at one end of the shutter: clip-space position and signed CoC radius.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Vertex {
    /// clip x
    pub x: Coord,
    /// clip y
    pub y: Coord,
    /// clip z (only used for depth)
    pub z: Coord,
    /// clip w
    pub w: Coord,
    /// signed circle-of-confusion radius, clip units
    pub coc: Coord,
}

impl Vertex {
    /// A vertex from raw I16F16 bits `[x, y, z, w, coc]`.
    pub fn from_bits(b: [i32; 5]) -> Vertex {
        Vertex {
            x: Coord::from_bits(b[0]),
            y: Coord::from_bits(b[1]),
            z: Coord::from_bits(b[2]),
            w: Coord::from_bits(b[3]),
            coc: Coord::from_bits(b[4]),
        }
    }

    /// Raw bits `[x, y, z, w, coc]`.
    pub fn bits(&self) -> [i32; 5] {
        [
            self.x.to_bits(),
            self.y.to_bits(),
            self.z.to_bits(),
            self.w.to_bits(),
            self.coc.to_bits(),
        ]
    }
}

/// A time-continuous triangle: three vertices at t = 0 and at t = 1, linear in between.
/// Only [`Triangle::new`] builds one, so every coordinate is inside the domain.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Triangle {
    pub(crate) v: [[[i32; 5]; 3]; 2],
}

/// Field order of the raw arrays.
pub(crate) const X: usize = 0;
pub(crate) const Y: usize = 1;
pub(crate) const Z: usize = 2;
pub(crate) const W: usize = 3;
pub(crate) const C: usize = 4;

const FIELDS: [Field; 5] = [Field::X, Field::Y, Field::Z, Field::W, Field::Coc];

impl Triangle {
    /// The triangle's class: motion if any field differs between the ends (the CoC only counts
    /// when non-zero somewhere), defocus if any CoC is non-zero.
    pub fn class(&self) -> Class {
        let [v0, v1] = &self.v;
        let defocus = v0.iter().chain(v1.iter()).any(|p| p[C] != 0);
        let motion = v0.iter().zip(v1.iter()).any(|(a, b)| {
            a[X] != b[X]
                || a[Y] != b[Y]
                || a[Z] != b[Z]
                || a[W] != b[W]
                || (defocus && a[C] != b[C])
        });
        match (motion, defocus) {
            (false, false) => Class::Static,
            (true, false) => Class::Motion,
            (false, true) => Class::Defocus,
            (true, true) => Class::MotionDefocus,
        }
    }

    /// Checked constructor: every coordinate must satisfy |v| ≤ 2^13 (default precision).
    pub fn new(t0: [Vertex; 3], t1: [Vertex; 3]) -> Result<Triangle, Error> {
        Triangle::new_with::<DefaultPrecision>(t0, t1)
    }

    /// Checked constructor for precision `P`: |v| ≤ 2^13 and every coordinate on `P`'s position
    /// grid (low 16 − `P::POS_FRAC` bits zero).
    pub fn new_with<P: Precision>(t0: [Vertex; 3], t1: [Vertex; 3]) -> Result<Triangle, Error> {
        // POS_FRAC ∈ 2..=16 (sealed `Precision`), so the mask exists and has ≤ 14 bits.
        let grid = low_bits_mask(COORD_FRAC.saturating_sub(P::POS_FRAC)).unwrap_or(0);
        let frac = u8::try_from(P::POS_FRAC).unwrap_or(u8::MAX);
        let mut v = [[[0i32; 5]; 3]; 2];
        for ((time, ends), out) in (0u8..).zip([t0, t1].iter()).zip(v.iter_mut()) {
            for ((vertex, vert), out) in (0u8..).zip(ends.iter()).zip(out.iter_mut()) {
                for ((f, raw), slot) in FIELDS.iter().zip(vert.bits()).zip(out.iter_mut()) {
                    let field = *f;
                    if raw.unsigned_abs() > COORD_LIMIT_RAW.unsigned_abs() {
                        return Err(Error::CoordOutOfDomain {
                            vertex,
                            time,
                            field,
                            raw,
                        });
                    }
                    if raw & grid != 0 {
                        return Err(Error::CoordOffGrid {
                            vertex,
                            time,
                            field,
                            raw,
                            frac,
                        });
                    }
                    *slot = raw;
                }
            }
        }
        Ok(Triangle { v })
    }

    /// A static triangle (same vertices at both ends).
    pub fn new_static(v: [Vertex; 3]) -> Result<Triangle, Error> {
        Triangle::new(v, v)
    }

    /// The vertices at shutter open (`time = 0`) or close (`time = 1`).
    pub fn vertices(&self, time: usize) -> [Vertex; 3] {
        let ends = if time == 0 { &self.v[0] } else { &self.v[1] };
        [
            Vertex::from_bits(ends[0]),
            Vertex::from_bits(ends[1]),
            Vertex::from_bits(ends[2]),
        ]
    }
}

/// Viewport size in pixels, 1..=2048 per side.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Viewport {
    pub(crate) w: u16,
    pub(crate) h: u16,
}

impl Viewport {
    /// Checked constructor.
    pub fn new(width: u16, height: u16) -> Result<Viewport, Error> {
        if width == 0 || height == 0 || width > MAX_VIEWPORT || height > MAX_VIEWPORT {
            return Err(Error::Viewport { width, height });
        }
        Ok(Viewport {
            w: width,
            h: height,
        })
    }
    /// Width in pixels.
    pub fn width(&self) -> u16 {
        self.w
    }
    /// Height in pixels.
    pub fn height(&self) -> u16 {
        self.h
    }
}

/// A half-open pixel rectangle `[x0, x1) × [y0, y1)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct PixelRect {
    /// first column
    pub x0: u16,
    /// first row
    pub y0: u16,
    /// one past the last column
    pub x1: u16,
    /// one past the last row
    pub y1: u16,
}

impl PixelRect {
    /// True when it holds no pixel.
    pub fn is_empty(&self) -> bool {
        self.x0 >= self.x1 || self.y0 >= self.y1
    }
    /// Intersection.
    pub fn intersect(&self, o: &PixelRect) -> PixelRect {
        PixelRect {
            x0: self.x0.max(o.x0),
            y0: self.y0.max(o.y0),
            x1: self.x1.min(o.x1),
            y1: self.y1.min(o.y1),
        }
    }
    /// Whether pixel (x, y) is inside.
    pub fn contains(&self, x: u16, y: u16) -> bool {
        x >= self.x0 && x < self.x1 && y >= self.y0 && y < self.y1
    }

    /// The cells of the `b`-pixel grid (cells start at multiples of `b`; `b = 0` is taken as 1)
    /// that meet this rectangle, clipped to it, in raster order. This is the bounds-tile walk of
    /// the renderer, and the record order of frame-level golden vectors.
    pub fn cells(self, b: u16) -> Cells {
        let b = b.max(1);
        Cells {
            r: self,
            b,
            x: align_down(self.x0, b),
            y: align_down(self.y0, b),
        }
    }
}

impl PixelRect {
    /// The rows of the `b`-pixel grid (`b = 0` is taken as 1) that meet this rectangle, clipped
    /// to it, top to bottom: each is `[x0, x1) × [row start, row end)`; `row.cells(b)` over them
    /// yields exactly `self.cells(b)`, in the same order.
    pub fn rows(self, b: u16) -> impl Iterator<Item = PixelRect> {
        let r = self;
        PixelRect {
            x0: 0,
            x1: 1,
            ..self
        }
        .cells(b)
        .filter(move |_| !r.is_empty())
        .map(move |c| PixelRect {
            x0: r.x0,
            x1: r.x1,
            ..c
        })
    }
}

/// `x` rounded down to a multiple of `b ≥ 1` (`x − x mod b`, never below 0).
#[inline]
fn align_down(x: u16, b: u16) -> u16 {
    x.saturating_sub(x.checked_rem(b).unwrap_or(0))
}

/// Iterator of [`PixelRect::cells`].
#[derive(Clone, Debug)]
pub struct Cells {
    r: PixelRect,
    b: u16,
    x: u16,
    y: u16,
}

impl Iterator for Cells {
    type Item = PixelRect;
    fn next(&mut self) -> Option<PixelRect> {
        while !self.r.is_empty() && self.y < self.r.y1 {
            let cell = PixelRect {
                x0: self.x,
                y0: self.y,
                x1: self.x.saturating_add(self.b),
                y1: self.y.saturating_add(self.b),
            }
            .intersect(&self.r);
            self.x = self.x.saturating_add(self.b);
            if self.x >= self.r.x1 {
                self.x = align_down(self.r.x0, self.b);
                self.y = self.y.saturating_add(self.b);
            }
            if !cell.is_empty() {
                return Some(cell);
            }
        }
        None
    }
}

/// One sample of the table: sub-pixel position, lens point and time. Only [`Sample::new`]
/// builds one (or `Default`, all zero), so t ∈ [0, 1] and u, v ∈ [−1, 1] always hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Sample {
    sx: SubPixel,
    sy: SubPixel,
    u: Lens,
    v: Lens,
    t: Time,
}

impl Sample {
    /// The sample at sub-pixel (0, 0), lens centre, t = 0 (equal to `Sample::default()`).
    pub const ZERO: Sample = Sample {
        sx: SubPixel::ZERO,
        sy: SubPixel::ZERO,
        u: Lens::ZERO,
        v: Lens::ZERO,
        t: Time::ZERO,
    };

    /// Checked constructor: t in [0, 1] (raw 0..=65536), u and v in [−1, 1] (raw ±65536); the
    /// error names the coordinate and its raw bits. A `const fn`: in a `const` table an
    /// out-of-domain value fails the build (`match … { Err(_) => panic!() }` in const context).
    pub const fn new(
        sx: SubPixel,
        sy: SubPixel,
        u: Lens,
        v: Lens,
        t: Time,
    ) -> Result<Sample, Error> {
        let (tr, ur, vr) = (t.to_bits(), u.to_bits(), v.to_bits());
        if tr < 0 || tr > TUV_ONE {
            return Err(Error::SampleOutOfDomain {
                field: SampleField::T,
                raw: tr,
            });
        }
        if ur < -TUV_ONE || ur > TUV_ONE {
            return Err(Error::SampleOutOfDomain {
                field: SampleField::U,
                raw: ur,
            });
        }
        if vr < -TUV_ONE || vr > TUV_ONE {
            return Err(Error::SampleOutOfDomain {
                field: SampleField::V,
                raw: vr,
            });
        }
        Ok(Sample { sx, sy, u, v, t })
    }

    /// Sub-pixel x in [0, 1).
    pub const fn sx(&self) -> SubPixel {
        self.sx
    }
    /// Sub-pixel y in [0, 1), downward.
    pub const fn sy(&self) -> SubPixel {
        self.sy
    }
    /// Lens u in [−1, 1].
    pub const fn u(&self) -> Lens {
        self.u
    }
    /// Lens v in [−1, 1].
    pub const fn v(&self) -> Lens {
        self.v
    }
    /// Time in [0, 1].
    pub const fn t(&self) -> Time {
        self.t
    }
}

/// The caller's sample table: an N×N pixel block with S samples per pixel, repeated over the
/// screen. Sample `s` of pixel (x, y) is `samples[((y mod N)·N + (x mod N))·S + s]`.
#[derive(Clone, Copy, Debug)]
pub struct SamplePattern<'a> {
    block: u16,
    spp: u16,
    samples: &'a [Sample],
}

/// Largest block side and samples per pixel.
pub const MAX_PATTERN: u16 = 64;

impl<'a> SamplePattern<'a> {
    /// Checked constructor: 1 ≤ N, S ≤ 64 and `len = N²·S` (every [`Sample`] is in the domain
    /// by construction).
    pub fn new(block: u16, spp: u16, samples: &'a [Sample]) -> Result<Self, Error> {
        SamplePattern::new_with::<DefaultPrecision>(block, spp, samples)
    }

    /// Checked constructor for precision `P`: as [`SamplePattern::new`], and every t, u, v on
    /// `P`'s t/u/v grid.
    pub fn new_with<P: Precision>(
        block: u16,
        spp: u16,
        samples: &'a [Sample],
    ) -> Result<Self, Error> {
        // TUV_FRAC ∈ 2..=16 (sealed `Precision`), so the mask exists and has ≤ 14 bits.
        let grid = low_bits_mask(TUV_FRAC.saturating_sub(P::TUV_FRAC)).unwrap_or(0);
        let shape = Error::PatternShape {
            block,
            spp,
            len: samples.len(),
        };
        if block == 0 || spp == 0 || block > MAX_PATTERN || spp > MAX_PATTERN {
            return Err(shape);
        }
        // block, spp ≤ 64: the product ≤ 2^18 cannot overflow (checked anyway).
        let len = usize::from(block)
            .checked_mul(usize::from(block))
            .and_then(|x| x.checked_mul(usize::from(spp)));
        if len != Some(samples.len()) {
            return Err(shape);
        }
        for (index, s) in samples.iter().enumerate() {
            if [s.t, s.u, s.v].iter().any(|x| x.to_bits() & grid != 0) {
                return Err(Error::SampleOffGrid {
                    index,
                    frac: u8::try_from(P::TUV_FRAC).unwrap_or(u8::MAX),
                });
            }
        }
        Ok(SamplePattern {
            block,
            spp,
            samples,
        })
    }

    /// Samples per pixel.
    pub fn spp(&self) -> u16 {
        self.spp
    }
    /// Block side N.
    pub fn block(&self) -> u16 {
        self.block
    }
    /// The whole table.
    pub fn samples(&self) -> &'a [Sample] {
        self.samples
    }

    /// The samples of pixel (x, y) (a slice of length S).
    pub fn pixel(&self, x: u16, y: u16) -> &'a [Sample] {
        let (n, s) = (usize::from(self.block), usize::from(self.spp));
        // n, s ∈ 1..=64 (checked constructor): every step is in range; checked regardless.
        let start = usize::from(y)
            .checked_rem(n)
            .and_then(|r| r.checked_mul(n))
            .and_then(|r| r.checked_add(usize::from(x).checked_rem(n)?))
            .and_then(|i| i.checked_mul(s));
        start
            .and_then(|a| self.samples.get(a..a.checked_add(s)?))
            .unwrap_or(&[])
    }
}

/// A triangle with its flat color.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Prim {
    /// geometry
    pub tri: Triangle,
    /// color
    pub color: Rgb888,
}
