//! Bounded sample-test records (`bsample_in.hex` / `bsample_out.hex`): self-contained inputs of
//! `uvt_core::bounded_eval` — both key frames of the triangle, its class, the viewport, the
//! configuration (offset shift, position and t/u/v fraction bits) and one sample (xs, ys, t, u,
//! v) — and its outputs: the rounded offsets a', b' per vertex, E' per edge, the orientation sign,
//! coverage and depth. The RTL unit `vectors/rtl/uvt_bsample.v` consumes exactly these fields.
//!
//! The committed sets use [`uvt_core::BoundedPrecision`] (`bounded-16-16-16-20`); [`Grid`] makes
//! sets of other configurations (inputs rounded down onto the configuration's grids) for the RTL
//! test of the unit's other parameter values.

use rand::{Rng, SeedableRng};
use serde::Serialize;
use uvt_core::config::registry::Config;
use uvt_core::config::unit::Full;
use uvt_core::sample::bounded;
use uvt_core::{
    setup, BoundedPrecision, Lens, Ops, Outcome, Precision, Sample, ScreenPos, Setup, SubPixel,
    Time, Triangle, Vertex, Viewport,
};

use crate::scene::builtin::random_tri;

use super::cases::named_cases;
use super::format::{to_text, Rec};

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
        let q = |vs: [Vertex; 3]| {
            vs.map(|v| Vertex::from_bits(v.bits().map(|b| Grid::floor(b, self.pos))))
        };
        Triangle::new(q(t.vertices(0)), q(t.vertices(1)))
            .expect("rounding down stays in the domain")
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

/// Input record.
pub fn enc_bsample_in(t: &Triangle, vp: Viewport, g: Grid, pos: ScreenPos, s: &Sample) -> Rec {
    let mut r = Rec::default();
    for time in 0..2 {
        for v in t.vertices(time) {
            for b in v.bits() {
                r = r.i32(b);
            }
        }
    }
    r.packed(&[(vp.width() as i64, 16), (vp.height() as i64, 16)])
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

/// Decode and validate an input record: every field goes through the core's checked
/// constructors; the class must be the triangle's, the configuration inside the proven ranges,
/// the inputs on its grids and the position inside the viewport. Errors name the field.
pub fn dec_bsample_in(w: &[u32]) -> Result<BsampleIn, String> {
    let g = |i: usize| w.get(i).copied().unwrap_or(0);
    let vert = |b: usize| {
        Vertex::from_bits([
            g(b) as i32,
            g(b + 1) as i32,
            g(b + 2) as i32,
            g(b + 3) as i32,
            g(b + 4) as i32,
        ])
    };
    let tri = Triangle::new([vert(0), vert(5), vert(10)], [vert(15), vert(20), vert(25)])
        .map_err(|e| format!("input triangle refused by the core: {e}"))?;
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
    let i = dec_bsample_in(w)?;
    // bounded_eval reads the setup's triangle, class and viewport only; the precision type
    // fixes nothing else here (the shift is the record's).
    let s = Setup::unculled::<BoundedPrecision>(&i.tri, i.vp);
    let e = bounded::eval(&s, i.grid.off, i.pos, &i.sample, &mut Ops::default())
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

/// What a bounded set exercises (counted by the generator, written to the manifest, asserted
/// non-zero by the tests).
#[derive(Clone, Debug, Default, Serialize)]
pub struct BCoverage {
    /// records
    pub records: u64,
    /// records per triangle class (static, motion, defocus, both)
    pub class: [u64; 4],
    /// covered samples
    pub covered: u64,
    /// some E'_k = 0 (the fill-rule tie key decides)
    pub ties: u64,
    /// some E'_k = 0 and covered
    pub ties_covered: u64,
    /// some vertex has w ≤ 0 at the sample's t (orientation from Σ E'·w)
    pub rare_path: u64,
    /// rare path and covered
    pub rare_covered: u64,
    /// depth saturated at the far end
    pub depth_far: u64,
    /// depth saturated at the near end
    pub depth_near: u64,
    /// samples at a viewport corner
    pub corners: u64,
}

/// Records of one bounded set, with what they cover.
#[derive(Default)]
pub struct BSet {
    /// input records
    pub inp: Vec<Rec>,
    /// output records
    pub out: Vec<Rec>,
    /// coverage counts
    pub cov: BCoverage,
}

/// w of vertex k at the sample's t, as `bounded.rs` step 1 forms it.
fn w_at(t: &Triangle, k: usize, s: &Sample) -> i64 {
    let (w0, w1) = (
        t.vertices(0)[k].w.to_bits() as i64,
        t.vertices(1)[k].w.to_bits() as i64,
    );
    let tt = s.t().to_bits() as i64;
    (w0 * 65536 + tt * (w1 - w0) + 32768) >> 16
}

impl BSet {
    /// Add one record (inputs moved onto `g`'s grids); returns the evaluation.
    pub fn push(
        &mut self,
        t: &Triangle,
        vp: Viewport,
        g: Grid,
        pos: ScreenPos,
        s: &Sample,
    ) -> uvt_core::BoundedEval {
        let (t, s) = (g.tri(t), g.sample(s));
        let input = enc_bsample_in(&t, vp, g, pos, &s);
        let (e, out) = run_bsample(&input.0).expect("generator records are valid");
        let c = &mut self.cov;
        c.records += 1;
        c.class[t.class().index()] += 1;
        let hit = e.hit.is_some();
        c.covered += hit as u64;
        if e.e.contains(&0) {
            c.ties += 1;
            c.ties_covered += hit as u64;
        }
        if (0..3).any(|k| w_at(&t, k, &s) <= 0) {
            c.rare_path += 1;
            c.rare_covered += hit as u64;
        }
        c.depth_far +=
            (e.hit.map(|h| h.depth) == Some(uvt_core::config::formats::DEPTH_FAR)) as u64;
        c.depth_near +=
            (e.hit.map(|h| h.depth) == Some(uvt_core::config::formats::DEPTH_NEAR)) as u64;
        let (sw, sh) = (256 * u32::from(vp.width()), 256 * u32::from(vp.height()));
        c.corners += ([0, sw - 1].contains(&pos.xs) && [0, sh - 1].contains(&pos.ys)) as u64;
        self.inp.push(input);
        self.out.push(out);
        e
    }
}

fn rand_sample(rng: &mut rand_pcg::Pcg64) -> Sample {
    Sample::new(
        SubPixel::ZERO,
        SubPixel::ZERO,
        Lens::from_bits(rng.gen_range(-65536..=65536)),
        Lens::from_bits(rng.gen_range(-65536..=65536)),
        Time::from_bits(rng.gen_range(0..=65536)),
    )
    .expect("drawn inside the domain")
}

/// The footprint of the setup at precision `P` in 1/256 px, or the whole viewport for a
/// culled triangle.
pub(super) fn area<P: Precision>(t: &Triangle, vp: Viewport) -> (u32, u32, u32, u32) {
    match setup::<P, Full>(t, vp, &mut Ops::default()) {
        Outcome::Visible(s) => {
            let f = s.footprint();
            (
                256 * f.x0 as u32,
                256 * f.y0 as u32,
                256 * f.x1 as u32,
                256 * f.y1 as u32,
            )
        }
        Outcome::Culled(_) | Outcome::Refused(_) => {
            (0, 0, 256 * vp.width() as u32, 256 * vp.height() as u32)
        }
    }
}

/// Unit-level records for `tris` (each with its viewport): per triangle random samples over its
/// footprint, the four viewport corners (t, u, v at their extremes too), and samples found by
/// search whose rounded edge value is 0 (ties) or whose vertex has w ≤ 0 while covered.
pub fn unit(tris: &[(Triangle, Viewport)], seed: u64, g: Grid) -> BSet {
    let mut rng = rand_pcg::Pcg64::seed_from_u64(seed ^ 0xb5a3_91e0);
    let mut set = BSet::default();
    let extreme = [(0, -65536, -65536), (65536, 65536, 65536), (32768, 0, 0)];
    for (t, vp) in tris {
        let (x0, y0, x1, y1) = area::<BoundedPrecision>(t, *vp);
        let (sw, sh) = (256 * vp.width() as u32, 256 * vp.height() as u32);
        for _ in 0..8 {
            let p = ScreenPos {
                xs: rng.gen_range(x0..x1),
                ys: rng.gen_range(y0..y1),
            };
            let s = rand_sample(&mut rng);
            set.push(t, *vp, g, p, &s);
        }
        for (i, (xs, ys)) in [(0, 0), (sw - 1, 0), (0, sh - 1), (sw - 1, sh - 1)]
            .into_iter()
            .enumerate()
        {
            let (tt, u, v) = extreme[i % 3];
            let s = Sample::new(
                SubPixel::ZERO,
                SubPixel::ZERO,
                Lens::from_bits(u),
                Lens::from_bits(v),
                Time::from_bits(tt),
            )
            .expect("extremes are in the domain");
            set.push(t, *vp, g, ScreenPos { xs, ys }, &s);
            let s = rand_sample(&mut rng);
            set.push(t, *vp, g, ScreenPos { xs, ys }, &s);
        }
        // Search (not recorded unless kept): ties, and covered samples of the rare path.
        let crossing =
            (0..3).any(|k| t.vertices(0)[k].w.to_bits() <= 0 || t.vertices(1)[k].w.to_bits() <= 0);
        let (mut ties, mut rare, mut hits) = (0, 0, 0);
        for _ in 0..400 {
            if ties >= 3 && hits >= 4 && (rare >= 3 || !crossing) {
                break;
            }
            let p = ScreenPos {
                xs: rng.gen_range(x0..x1),
                ys: rng.gen_range(y0..y1),
            };
            // Coarse positions (whole and half pixels) make exact ties likelier.
            let p = if rng.gen_bool(0.5) {
                ScreenPos {
                    xs: p.xs & !127,
                    ys: p.ys & !127,
                }
            } else {
                p
            };
            let s = rand_sample(&mut rng);
            let s = if rng.gen_bool(0.5) {
                Sample::new(
                    SubPixel::ZERO,
                    SubPixel::ZERO,
                    Lens::ZERO,
                    Lens::ZERO,
                    s.t(),
                )
                .expect("lens centre")
            } else {
                s
            };
            let probe = Setup::unculled::<BoundedPrecision>(&g.tri(t), *vp);
            let Some(e) = bounded::eval(&probe, g.off, p, &g.sample(&s), &mut Ops::default())
            else {
                continue;
            };
            let rare_hit = crossing
                && e.hit.is_some()
                && (0..3).any(|k| w_at(&g.tri(t), k, &g.sample(&s)) <= 0);
            let hit = e.hit.is_some() && hits < 4;
            if (e.e.contains(&0) && ties < 3) || (rare_hit && rare < 3) || hit {
                ties += e.e.contains(&0) as u32;
                rare += rare_hit as u32;
                hits += e.hit.is_some() as u32;
                set.push(t, *vp, g, p, &s);
            }
        }
    }
    set
}

/// Frame-level records: the triangles of a scene with the scene's own samples, at most
/// `per_tri` per triangle, evenly strided over its footprint's (pixel, sample) list.
pub fn frame(
    tris: &[Triangle],
    vp: Viewport,
    pattern: &uvt_core::SamplePattern<'_>,
    per_tri: usize,
) -> BSet {
    let mut set = BSet::default();
    for t in tris {
        let (x0, y0, x1, y1) = area::<BoundedPrecision>(t, vp);
        let mut all = Vec::new();
        for py in (y0 / 256) as u16..(y1 / 256) as u16 {
            for px in (x0 / 256) as u16..(x1 / 256) as u16 {
                for s in pattern.pixel(px, py) {
                    all.push((ScreenPos::of(px, py, s), *s));
                }
            }
        }
        let step = all.len().div_ceil(per_tri).max(1);
        for (p, s) in all.iter().step_by(step) {
            set.push(t, vp, Grid::DEFAULT, *p, s);
        }
    }
    set
}

/// A unit-level bounded set of configuration `g` (the named edge cases and 48 seeded random
/// triangles of every kind, inputs rounded onto `g`'s grids), written as `bsample_in.hex` and
/// `bsample_out.hex` into `dir`: the RTL test's vectors for the unit's other parameter values.
pub fn export_grid(dir: &std::path::Path, g: Grid, seed: u64) -> anyhow::Result<BCoverage> {
    let mut rng = rand_pcg::Pcg64::seed_from_u64(seed);
    let mut tris = Vec::new();
    for (_, list, side) in named_cases() {
        let vp = Viewport::new(side, side).map_err(|e| anyhow::anyhow!("{e}"))?;
        tris.extend(list.into_iter().map(|t| (t, vp)));
    }
    for i in 0..48u32 {
        let vp = Viewport::new([8u16, 17, 32, 61][i as usize % 4], 24)
            .map_err(|e| anyhow::anyhow!("{e}"))?;
        let t = random_tri(&mut rng, i % 6)
            .to_core()
            .map_err(|e| anyhow::anyhow!("{e}"))?;
        tris.push((t, vp));
    }
    let set = unit(&tris, seed, g);
    std::fs::create_dir_all(dir)?;
    for (name, recs) in [("bsample_in.hex", &set.inp), ("bsample_out.hex", &set.out)] {
        let p = dir.join(name);
        std::fs::write(&p, to_text(recs))
            .map_err(|e| anyhow::anyhow!("writing {}: {e}", p.display()))?;
    }
    Ok(set.cov)
}
