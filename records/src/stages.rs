//! Input record → core → expected output record, per stage. The exporter writes what these
//! return; the checker runs them again on the files' inputs and compares bit for bit.

use embedded_graphics_core::pixelcolor::RgbColor;
use uvt_core::bounds::laine::LaineCoeffs;
use uvt_core::bounds::strategy::BoundsStrategy;
use uvt_core::config::registry::{self, Config};
use uvt_core::config::unit::Full;
use uvt_core::sample::exact;
use uvt_core::{
    resolve_colors, setup, with_config, Cull, Interval, Laine2011, Lens, Ops, Outcome, PixelRect,
    Rgb888, Sample, ScreenPos, Setup, SubPixel, Time, Triangle, UvtBox, Vertex, Viewport,
};

use crate::format::Rec;

/// The 30 words of a triangle (both key frames, vertices 0..2, x y z w CoC each): the first words
/// of a setup and of a bounded sample-test record.
pub fn tri_words(t: &Triangle) -> Rec {
    let mut r = Rec::default();
    for time in 0..2 {
        for v in t.vertices(time) {
            for b in v.bits() {
                r = r.i32(b);
            }
        }
    }
    r
}

/// The packed configuration word of a setup input record ([`crate::format::CONFIG_FIELDS`]).
pub fn config_word(c: Config) -> Rec {
    let datapath = match (c.off(), c.planar()) {
        (None, _) => 0,
        (Some(_), false) => 1,
        (Some(_), true) => 2,
    };
    Rec::default().packed(&[
        (datapath, 2),
        (c.pos() as i64, 5),
        (c.tuv() as i64, 5),
        (c.bnd() as i64, 5),
        (c.off().unwrap_or(0) as i64, 6),
    ])
}

/// The configuration of a packed configuration word: an error naming the word's fields unless
/// it is one of the registry's ([`registry::CONFIGS`]).
pub fn dec_config(w: u32) -> Result<Config, String> {
    let f = |bit: u32, width: u32| (w >> bit) & ((1 << width) - 1);
    let (dp, pos, tuv, bnd, off) = (f(0, 2), f(2, 5), f(7, 5), f(12, 5), f(17, 6));
    let name = match dp {
        0 => format!("exact-{pos}-{tuv}-{bnd}"),
        1 => format!("bounded-{pos}-{tuv}-{bnd}-{off}"),
        2 => format!("planar-{pos}-{tuv}-{bnd}-{off}"),
        _ => format!("datapath 3 (none)-{pos}-{tuv}-{bnd}-{off}"),
    };
    let known = (w >> 23 == 0 && (dp != 0 || off == 0))
        .then(|| Config::parse(&name))
        .flatten()
        .filter(|c| registry::name_of(*c).is_some());
    known.ok_or_else(|| {
        format!(
            "configuration word {w:#010x} ({name}) is not a registry configuration (one of {})",
            registry::CONFIGS
                .iter()
                .map(|e| e.name)
                .collect::<Vec<_>>()
                .join(", ")
        )
    })
}

/// Input record of a triangle and viewport, set up at configuration `c`.
pub fn enc_setup_in(t: &Triangle, vp: Viewport, c: Config) -> Rec {
    let mut r = tri_words(t).packed(&[(vp.width() as i64, 16), (vp.height() as i64, 16)]);
    r.0.extend(config_word(c).0);
    r
}

/// Decode a setup input record: triangle, viewport, configuration.
pub fn dec_setup_in(w: &[u32]) -> Result<(Triangle, Viewport, Config), String> {
    let g = |i: usize| w.get(i).copied().unwrap_or(0) as i32;
    let vert = |base: usize| {
        Vertex::from_bits([g(base), g(base + 1), g(base + 2), g(base + 3), g(base + 4)])
    };
    let t0 = [vert(0), vert(5), vert(10)];
    let t1 = [vert(15), vert(20), vert(25)];
    let cfg = dec_config(w.get(31).copied().unwrap_or(0))?;
    // On the configuration's position grid: `new_with` refuses an off-grid coordinate by name.
    let tri = with_config!(cfg, P => Triangle::new_with::<P>(t0, t1))
        .ok_or_else(|| format!("{cfg}: not a registry configuration"))?
        .map_err(|e| format!("input triangle refused by the core at {cfg}: {e}"))?;
    let vw = w.get(30).copied().unwrap_or(0);
    let vp = Viewport::new(vw as u16, (vw >> 16) as u16)
        .map_err(|e| format!("input viewport refused: {e}"))?;
    Ok((tri, vp, cfg))
}

/// Setup and Laine coefficients of a setup input record (None if culled), plus the output
/// record: the core's setup at the record's configuration.
pub fn run_setup(w: &[u32]) -> Result<(Option<(Setup, LaineCoeffs)>, Rec), String> {
    let (tri, vp, cfg) = dec_setup_in(w)?;
    let mut ops = Ops::default();
    let out = with_config!(cfg, P => setup::<P, Full>(&tri, vp, &mut ops))
        .ok_or_else(|| format!("{cfg}: not a registry configuration"))?;
    let (vis, cull) = match out {
        Outcome::Visible(s) => (Some((s, Laine2011.prepare::<Full>(&s, &mut ops))), 0),
        Outcome::Culled(Cull::Outside) => (None, 1),
        Outcome::Culled(Cull::Degenerate) => (None, 2),
        Outcome::Refused(_) => unreachable!("the full unit accepts every class"),
    };
    let mut r = Rec::default();
    let Some((s, c)) = &vis else {
        r = r.packed(&[(0, 1), (cull, 2)]);
        return Ok((None, pad(r, 108)));
    };
    let b = |o: bool| o as i64;
    r = r.packed(&[
        (1, 1),
        (0, 2),
        (s.class().index() as i64, 2),
        (b(s.axes()[0].lo.is_some()), 1),
        (b(s.axes()[0].hi.is_some()), 1),
        (b(s.axes()[1].lo.is_some()), 1),
        (b(s.axes()[1].hi.is_some()), 1),
        (b(c.lens()[0].is_some()), 1),
        (b(c.lens()[1].is_some()), 1),
        (b(c.dual()[0].is_some()), 1),
        (b(c.dual()[1].is_some()), 1),
    ]);
    let fp = s.footprint();
    r = r
        .packed(&[(fp.x0 as i64, 16), (fp.y0 as i64, 16)])
        .packed(&[(fp.x1 as i64, 16), (fp.y1 as i64, 16)])
        .i32(s.span().lo())
        .i32(s.span().hi());
    for a in &s.axes() {
        for side in [a.lo, a.hi] {
            let v = side.unwrap_or([0, 0]);
            r = r.i64(v[0]).i64(v[1]);
        }
    }
    let eps = s.eps();
    r = r.i32(eps.x()[0]).i32(eps.x()[1]).i32(eps.w());
    for l in &c.lens() {
        for side in [l.and_then(|l| l.lo), l.and_then(|l| l.hi)] {
            r = match side {
                Some(sd) => r
                    .i64(sd.base)
                    .i64(sd.c.d())
                    .i128(sd.c.r_up())
                    .i128(sd.c.r_dn()),
                None => pad_n(r, 12),
            };
        }
    }
    for d in &c.dual() {
        r = match d {
            Some(d) => {
                let mut r = r.i32(d.xi[0] as i32).i32(d.xi[1] as i32);
                for m in [&d.lo, &d.hi] {
                    for t in m {
                        r = r.i64(t[0]).i64(t[1]);
                    }
                }
                r
            }
            None => pad_n(r, 18),
        };
    }
    Ok((vis, r))
}

fn pad_n(mut r: Rec, n: usize) -> Rec {
    r.0.extend(std::iter::repeat(0).take(n));
    r
}

fn pad(mut r: Rec, total: usize) -> Rec {
    r.0.resize(total, 0);
    r
}

/// Bounds input record.
pub fn enc_bounds_in(tri: u32, cell: PixelRect) -> Rec {
    Rec::default()
        .u32(tri)
        .packed(&[(cell.x0 as i64, 16), (cell.y0 as i64, 16)])
        .packed(&[(cell.x1 as i64, 16), (cell.y1 as i64, 16)])
}

/// Look a setup up by triangle index.
pub type SetupLookup<'a> = &'a dyn Fn(u32) -> Result<(Setup, LaineCoeffs), String>;

/// Bounds of a tile: output record and the box.
pub fn run_bounds(setups: SetupLookup<'_>, w: &[u32]) -> Result<(Option<UvtBox>, Rec), String> {
    let (s, c) = setups(w.first().copied().unwrap_or(0))?;
    let g = |i: usize| w.get(i).copied().unwrap_or(0);
    let cell = PixelRect {
        x0: g(1) as u16,
        y0: (g(1) >> 16) as u16,
        x1: g(2) as u16,
        y1: (g(2) >> 16) as u16,
    };
    let fp = s.footprint();
    if cell.is_empty() || cell.intersect(&fp) != cell {
        return Err(format!(
            "tile {cell:?} is not a non-empty part of the footprint {fp:?}"
        ));
    }
    let b = Laine2011.tile::<Full>(&s, &c, cell, &mut Ops::default());
    let r = match b {
        Some(b) => Rec::default()
            .packed(&[(1, 1)])
            .i32(b.u.lo())
            .i32(b.u.hi())
            .i32(b.v.lo())
            .i32(b.v.hi())
            .i32(b.t.lo())
            .i32(b.t.hi()),
        None => pad(Rec::default().packed(&[(0, 1)]), 7),
    };
    Ok((b, r))
}

/// Interval-check input record.
pub fn enc_select_in(b: &UvtBox, u: i32, v: i32, t: i32) -> Rec {
    Rec::default()
        .i32(b.u.lo())
        .i32(b.u.hi())
        .i32(b.v.lo())
        .i32(b.v.hi())
        .i32(b.t.lo())
        .i32(b.t.hi())
        .i32(u)
        .i32(v)
        .i32(t)
}

/// The per-sample interval check (is the sample's (u, v, t) inside the tile's box?). The box
/// is validated through `Interval::new`; an out-of-domain one is refused naming its fields.
pub fn run_select(w: &[u32]) -> Result<Rec, String> {
    let g = |i: usize| w.get(i).copied().unwrap_or(0) as i32;
    let iv = |name: &str, k: usize| {
        Interval::new(g(k), g(k + 1))
            .map_err(|e| format!("fields {name}_lo, {name}_hi refused by the core: {e}"))
    };
    let b = UvtBox {
        u: iv("u", 0)?,
        v: iv("v", 2)?,
        t: iv("t", 4)?,
    };
    Ok(Rec::default().packed(&[(b.contains(g(6), g(7), g(8)) as i64, 1)]))
}

/// Sample-test input record.
pub fn enc_sample_in(tri: u32, px: u16, py: u16, s: &Sample) -> Rec {
    Rec::default()
        .u32(tri)
        .packed(&[(px as i64, 16), (py as i64, 16)])
        .packed(&[(s.sx().to_bits() as i64, 8), (s.sy().to_bits() as i64, 8)])
        .i32(s.u().to_bits())
        .i32(s.v().to_bits())
        .i32(s.t().to_bits())
}

/// Decode a sample-test input record: (tri, px, py, sample). The sample goes through the
/// checked `Sample::new`; an out-of-domain t, u or v is refused naming the field and raw value.
pub fn dec_sample_in(w: &[u32]) -> Result<(u32, u16, u16, Sample), String> {
    let g = |i: usize| w.get(i).copied().unwrap_or(0);
    let s = Sample::new(
        SubPixel::from_bits(g(2) as u8),
        SubPixel::from_bits((g(2) >> 8) as u8),
        Lens::from_bits(g(3) as i32),
        Lens::from_bits(g(4) as i32),
        Time::from_bits(g(5) as i32),
    )
    .map_err(|e| format!("input sample refused by the core: {e}"))?;
    Ok((g(0), g(1) as u16, (g(1) >> 16) as u16, s))
}

/// The sample test: output record (coverage, depth, exact edge values, determinant).
pub fn run_sample(setups: SetupLookup<'_>, w: &[u32]) -> Result<(Option<i32>, Rec), String> {
    let (tri, px, py, smp) = dec_sample_in(w)?;
    let (s, _) = setups(tri)?;
    if s.prec().offset_shift().is_some() {
        return Err(format!(
            "sample records are the exact sample test: triangle {tri} is set up at a bounded or planar configuration (its sample test has bsample / psample records)"
        ));
    }
    if px >= s.viewport().width() || py >= s.viewport().height() {
        return Err(format!("pixel ({px},{py}) outside the viewport"));
    }
    let e = exact::eval::<Full>(&s, ScreenPos::of(px, py, &smp), &smp, &mut Ops::default());
    let mut r = Rec::default()
        .packed(&[(e.hit.is_some() as i64, 1), (e.det.signum() as i64, 2)])
        .i32(e.hit.map_or(0, |h| h.depth));
    for x in e.e.iter().chain(std::iter::once(&e.det)) {
        let (hi, lo) = x.parts();
        r = r.wide(hi, lo);
    }
    Ok((e.hit.map(|h| h.depth), r))
}

/// Resolve input record of S colors.
pub fn enc_resolve_in(colors: &[Rgb888]) -> Rec {
    colors.iter().fold(Rec::default(), |r, c| {
        r.packed(&[(c.b() as i64, 8), (c.g() as i64, 8), (c.r() as i64, 8)])
    })
}

/// Resolve: the average color.
pub fn run_resolve(w: &[u32]) -> Rec {
    let colors: Vec<Rgb888> = w
        .iter()
        .map(|x| Rgb888::new((x >> 16) as u8, (x >> 8) as u8, *x as u8))
        .collect();
    let c = resolve_colors(&colors);
    Rec::default().packed(&[(c.b() as i64, 8), (c.g() as i64, 8), (c.r() as i64, 8)])
}
