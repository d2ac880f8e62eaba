//! Bounded sample-test records (`bsample_in.hex` / `bsample_out.hex`): self-contained inputs of
//! `uvt_core::bounded_eval` — both key frames of the triangle, its class, the viewport, the
//! configuration (offset shift, position and t/u/v fraction bits) and one sample (xs, ys, t, u,
//! v) — and its outputs: the rounded offsets a', b' per vertex, E' per edge, the orientation sign,
//! coverage and depth. The RTL unit `vectors/rtl/uvt_bsample.v` consumes exactly these fields.
//!
//! The committed sets use [`uvt_core::BoundedPrecision`] (`bounded-16-16-16-20`); [`Grid`] makes
//! sets of other configurations (inputs rounded down onto the configuration's grids) for the RTL
//! test of the unit's other parameter values.

use serde::Serialize;
use uvt_core::config::registry::Config;
use uvt_core::sample::bounded;
use uvt_core::{
    BoundedPrecision, Lens, Ops, Sample, ScreenPos, Setup, SubPixel, Time, Triangle, Vertex,
    Viewport,
};

use crate::format::Rec;

/// A bounded configuration: offset shift and the fraction bits of positions and t/u/v.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Grid {
    /// offset-grid shift (20..=32)
    pub off: u32,
    /// position and CoC fraction bits (2..=16)
    pub pos: u32,
    /// t, u, v fraction bits (2..=16)
    pub tuv: u32,
}

impl Grid {
    /// The committed sets' configuration: [`BoundedPrecision`]'s grids
    /// (`bounded-16-16-16-20`).
    pub const DEFAULT: Grid = Grid::of(Config::of::<BoundedPrecision>());
    /// The grid of bounded configuration `c` (B = P here); a compile-time error for another.
    const fn of(c: Config) -> Grid {
        match c.off() {
            Some(off) if !c.planar() && c.bnd() == c.pos() => Grid {
                off,
                pos: c.pos(),
                tuv: c.tuv(),
            },
            _ => panic!("not a bounded configuration with B = P"),
        }
    }
    /// The grid of a bounded or planar configuration `c` (a planar one's bounded test: the
    /// moving and defocused classes' grid); an error naming it for an exact configuration.
    pub fn from_config(c: Config) -> Result<Grid, String> {
        match c.off() {
            Some(off) => Ok(Grid {
                off,
                pos: c.pos(),
                tuv: c.tuv(),
            }),
            None => Err(format!(
                "{c}: an exact configuration has no bounded sample test (a bounded or planar configuration has)"
            )),
        }
    }
    /// The configuration's name (`bounded-P-T-B-O`, B = P here).
    pub fn name(&self) -> String {
        format!(
            "bounded-{}-{}-{}-{}",
            self.pos, self.tuv, self.pos, self.off
        )
    }
    /// `v` rounded down onto a grid of `16 − frac` zero low bits (stays in the domain: 2^29 is
    /// on every grid and rounding down moves −2^29 nowhere).
    fn floor(v: i32, frac: u32) -> i32 {
        let k = 16 - frac;
        (v >> k) << k
    }
    /// The triangle with every coordinate on the position grid.
    pub fn tri(&self, t: &Triangle) -> Triangle {
        on_grid(t, self.pos)
    }
    /// The sample with t, u, v on the t/u/v grid (t rounded down, u and v toward −∞: −1 is on
    /// every grid).
    pub fn sample(&self, s: &Sample) -> Sample {
        let f = |x: i32| Grid::floor(x, self.tuv);
        Sample::new(
            s.sx(),
            s.sy(),
            Lens::from_bits(f(s.u().to_bits())),
            Lens::from_bits(f(s.v().to_bits())),
            Time::from_bits(f(s.t().to_bits())),
        )
        .expect("rounding down keeps t, u, v in the domain")
    }
}

/// Triangle `t` with every coordinate rounded down onto the grid of `pos` fraction bits (2..=16).
pub fn on_grid(t: &Triangle, pos: u32) -> Triangle {
    let q = |vs: [Vertex; 3]| vs.map(|v| Vertex::from_bits(v.bits().map(|b| Grid::floor(b, pos))));
    Triangle::new(q(t.vertices(0)), q(t.vertices(1))).expect("rounding down stays in the domain")
}

/// Input record.
pub fn enc_bsample_in(t: &Triangle, vp: Viewport, g: Grid, pos: ScreenPos, s: &Sample) -> Rec {
    crate::stages::tri_words(t)
        .packed(&[(vp.width() as i64, 16), (vp.height() as i64, 16)])
        .packed(&[
            (t.class().index() as i64, 2),
            (g.off as i64, 6),
            (g.pos as i64, 5),
            (g.tuv as i64, 5),
        ])
        .u32(pos.xs)
        .u32(pos.ys)
        .i32(s.t().to_bits())
        .i32(s.u().to_bits())
        .i32(s.v().to_bits())
}

/// A decoded input record.
pub struct BsampleIn {
    /// triangle (both key frames)
    pub tri: Triangle,
    /// viewport
    pub vp: Viewport,
    /// configuration
    pub grid: Grid,
    /// screen position in 1/256 px
    pub pos: ScreenPos,
    /// t, u, v (sub-pixel fields unused: the position is `pos`)
    pub sample: Sample,
}

/// The triangle of an input record (words 0..30, both key frames), through the core's checked
/// constructor.
fn dec_tri(w: &[u32]) -> Result<Triangle, String> {
    let g = |i: usize| w.get(i).copied().unwrap_or(0) as i32;
    let vert = |b: usize| Vertex::from_bits([g(b), g(b + 1), g(b + 2), g(b + 3), g(b + 4)]);
    Triangle::new([vert(0), vert(5), vert(10)], [vert(15), vert(20), vert(25)])
        .map_err(|e| format!("input triangle refused by the core: {e}"))
}

/// The class index (bit 0 motion, bit 1 defocus) of an input record's triangle: what its
/// `class` field must hold.
pub fn triangle_class(w: &[u32]) -> Result<u32, String> {
    Ok(dec_tri(w)?.class().index() as u32)
}

/// Decode and validate an input record: every field goes through the core's checked
/// constructors; the class must be the triangle's, the configuration inside the proven ranges,
/// the inputs on its grids and the position inside the viewport. Errors name the field.
pub fn dec_bsample_in(w: &[u32]) -> Result<BsampleIn, String> {
    let g = |i: usize| w.get(i).copied().unwrap_or(0);
    let tri = dec_tri(w)?;
    let vp = Viewport::new(g(30) as u16, (g(30) >> 16) as u16)
        .map_err(|e| format!("input viewport refused: {e}"))?;
    let cfg = g(31);
    let (class, off, pos, tuv) = (cfg & 3, (cfg >> 2) & 63, (cfg >> 8) & 31, (cfg >> 13) & 31);
    let want = tri.class().index() as u32;
    if class != want {
        return Err(format!(
            "field class = {class}, but the triangle's class is {want} ({:?})",
            tri.class()
        ));
    }
    if !(uvt_core::config::precision::OFFSET_SHIFT_MIN
        ..=uvt_core::config::precision::OFFSET_SHIFT_MAX)
        .contains(&off)
    {
        return Err(format!("field off_shift = {off} outside 20..=32"));
    }
    for (name, f) in [("pos_frac", pos), ("tuv_frac", tuv)] {
        if !(2..=16).contains(&f) {
            return Err(format!("field {name} = {f} outside 2..=16"));
        }
    }
    let grid = Grid { off, pos, tuv };
    let sample = Sample::new(
        SubPixel::ZERO,
        SubPixel::ZERO,
        Lens::from_bits(g(35) as i32),
        Lens::from_bits(g(36) as i32),
        Time::from_bits(g(34) as i32),
    )
    .map_err(|e| format!("input sample refused by the core: {e}"))?;
    if grid.tri(&tri) != tri {
        return Err(format!(
            "triangle not on the {pos}-fraction-bit position grid"
        ));
    }
    if grid.sample(&sample) != sample {
        return Err(format!("t, u or v not on the {tuv}-fraction-bit grid"));
    }
    let p = ScreenPos {
        xs: g(32),
        ys: g(33),
    };
    let (sw, sh) = (256 * u32::from(vp.width()), 256 * u32::from(vp.height()));
    if p.xs >= sw || p.ys >= sh {
        return Err(format!(
            "fields xs = {}, ys = {}: outside the {}×{} viewport (xs < {sw}, ys < {sh})",
            p.xs,
            p.ys,
            vp.width(),
            vp.height()
        ));
    }
    Ok(BsampleIn {
        tri,
        vp,
        grid,
        pos: p,
        sample,
    })
}

/// The bounded sample test of an input record: the output record.
pub fn run_bsample(w: &[u32]) -> Result<(uvt_core::BoundedEval, Rec), String> {
    run_bsample_probed(w, &mut uvt_core::coverage::NoProbe)
}

/// [`run_bsample`], the test's decision paths reported to `pr` (`uvt_core::coverage`).
pub fn run_bsample_probed(
    w: &[u32],
    pr: &mut impl uvt_core::coverage::Probe,
) -> Result<(uvt_core::BoundedEval, Rec), String> {
    let i = dec_bsample_in(w)?;
    // bounded_eval reads the setup's triangle, class and viewport only; the precision type
    // fixes nothing else here (the shift is the record's).
    let s = Setup::unculled::<BoundedPrecision>(&i.tri, i.vp);
    let e = bounded::eval_probed(&s, i.grid.off, i.pos, &i.sample, &mut Ops::default(), pr)
        .ok_or("bounded_eval refused the record (position or shift out of range)")?;
    let mut r = Rec::default()
        .packed(&[(e.hit.is_some() as i64, 1), (e.det_sign, 2)])
        .i32(e.hit.map_or(0, |h| h.depth));
    for (a, b) in e.ab {
        // |a'|, |b'| < 2^30 for shifts ≥ 20 (bounded.rs step 4).
        r = r.i32(a as i32).i32(b as i32);
    }
    for x in e.e {
        r = r.i64(x);
    }
    Ok((e, r))
}
