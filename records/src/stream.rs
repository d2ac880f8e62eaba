//! Seeded input-record streams, in the TestFloat tradition: record `i` of the stream of (kind,
//! configuration, seed) is a function of those and `i` alone (its own generator, seeded by
//! mixing the seed with `i`), so any part of a stream is made without the rest. `uvt vectors gen`
//! writes a stream, the C library's `uvt_gen` gives one record of it to a testbench, and a
//! [`Shard`] is a contiguous block of indices: the shards of a stream, concatenated in order, are
//! the stream byte for byte.
//!
//! Every record goes through the core's checked constructors and the same generator for every
//! consumer. The triangles come in named families ([`FAMILIES`]), drawn per record: the four
//! classes, camera-plane crossers, a vertex at w = 0, slivers, fill-rule ties (a static triangle
//! with a vertical edge through a sample position, so that an edge value is 0 in exact
//! arithmetic) and domain-size coordinates; a targeting stream adds directed families
//! ([`DIRECTED`]). Viewports are drawn from 1×1 to 2048×2048; a sample
//! lies inside the triangle's projected box half the time, anywhere in the viewport (its corners
//! included) otherwise; t, u and v reach their extremes.

use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;
use uvt_core::config::registry::{self, Config};
use uvt_core::{
    Lens, PlanarPrecision, Sample, ScreenPos, Setup, SubPixel, Time, Triangle, Vertex, Viewport,
};

use crate::bsample::{enc_bsample_in, on_grid, Grid};
use crate::format::Rec;
use crate::kind::{Kind, MAX_SPP};
use crate::psample::{enc_psample_in, static_of};
use crate::stages::{enc_resolve_in, enc_select_in, enc_setup_in};
use uvt_core::coverage::{Bin, Counts};

/// The triangle families of a stream, in the order of their codes.
pub const FAMILIES: [&str; 9] = [
    "static", "motion", "defocus", "both", "crosser", "w_zero", "sliver", "tie", "huge",
];

/// The families a targeting stream ([`Stream::targeting`]) draws besides [`FAMILIES`], coded
/// after them: cases built for a decision the plain families reach too rarely. `tie_horizontal`:
/// a static triangle with a horizontal edge through the sample (an edge value 0 with a = 0, the
/// planar fill rule decided by b). `depth_extreme`: a static triangle whose depth plane has an
/// extreme exponent: a large triangle with depths of a few LSB (the planar depth's shift capped
/// at 63), or a sliver with depths up to ±8000 (negative exponents: the scaled depth, zero and
/// saturated).
pub const DIRECTED: [&str; 2] = ["tie_horizontal", "depth_extreme"];

/// The name of family code `fam` ([`FAMILIES`], then [`DIRECTED`]).
fn family_name(fam: usize) -> &'static str {
    FAMILIES
        .iter()
        .chain(DIRECTED.iter())
        .nth(fam)
        .copied()
        .unwrap_or("static")
}

/// A contiguous part `k` of `m` (1 ≤ k ≤ m) of a stream: of `count` records, indices
/// `⌊count·(k−1)/m⌋ .. ⌊count·k/m⌋`. Fields private; [`Shard::new`] and [`Shard::parse`] check.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    k: u64,
    m: u64,
}

impl Shard {
    /// The whole stream (1/1).
    pub const ALL: Shard = Shard { k: 1, m: 1 };
    /// Part `k` of `m`; an error unless 1 ≤ k ≤ m.
    pub fn new(k: u64, m: u64) -> Result<Shard, String> {
        if (1..=m).contains(&k) {
            Ok(Shard { k, m })
        } else {
            Err(format!("shard {k}/{m}: need 1 ≤ K ≤ M"))
        }
    }
    /// Parse `K/M`.
    pub fn parse(s: &str) -> Result<Shard, String> {
        let (k, m) = s
            .split_once('/')
            .ok_or_else(|| format!("shard `{s}`: expected K/M, e.g. 3/8"))?;
        let n = |x: &str| {
            x.trim()
                .parse::<u64>()
                .map_err(|e| format!("shard `{s}`: `{x}` is not a count: {e}"))
        };
        Shard::new(n(k)?, n(m)?)
    }
    /// The record indices of this part of a stream of `count` records (u128 products: exact).
    pub fn range(&self, count: u64) -> core::ops::Range<u64> {
        let at = |j: u64| (u128::from(count) * u128::from(j) / u128::from(self.m)) as u64;
        at(self.k - 1)..at(self.k)
    }
}

/// A seeded stream of input records of one kind and configuration.
#[derive(Clone, Copy, Debug)]
pub struct Stream {
    kind: Kind,
    grid: Option<Grid>,
    setup: Config,
    spp: u32,
    seed: u64,
    /// the bins the stream is biased toward ([`Stream::targeting`]; none: plain draws)
    targets: [bool; Bin::COUNT],
}

/// Candidates drawn per record of a targeting stream before it gives up on its targets.
pub const TARGET_TRIES: u32 = 64;

impl Stream {
    /// The stream of `kind` at configuration `config` (a registry name; `None`: the kind's
    /// default — the registry's default for setup and the bounded test, the planar
    /// configuration for the planar test), `spp` samples per resolve record, seed `seed`. Errors name what is refused:
    /// a kind whose records name a triangle of a set (bounds, sample), a configuration the kind's
    /// records are not made at, an spp outside 1..=64.
    pub fn new(kind: Kind, config: Option<&str>, seed: u64, spp: u32) -> Result<Stream, String> {
        let cfg = match config {
            None => None,
            Some(n) => Some(registry::find(n).ok_or_else(|| {
                format!(
                    "unknown configuration `{n}` (one of {})",
                    registry::CONFIGS
                        .iter()
                        .map(|e| e.name)
                        .collect::<Vec<_>>()
                        .join(", ")
                )
            })?),
        };
        let only = |want: Config| match cfg {
            Some(c) if c != want => Err(format!(
                "{} records are made at {want} only, not {c}",
                kind.name()
            )),
            _ => Ok(()),
        };
        let grid = match kind {
            Kind::Bounds | Kind::Sample => {
                return Err(format!(
                    "a {}_in record names its triangle by index in a setup_in file: no self-contained stream (use `uvt vectors export`)",
                    kind.name()
                ))
            }
            Kind::Bsample => Some(Grid::from_config(cfg.unwrap_or(registry::DEFAULT))?),
            Kind::Psample => {
                only(registry::PLANAR)?;
                None
            }
            Kind::Setup => None,
            Kind::Select | Kind::Resolve => {
                if let Some(c) = cfg {
                    return Err(format!(
                        "{} records have no configuration (not {c})",
                        kind.name()
                    ));
                }
                None
            }
        };
        if !(1..=MAX_SPP).contains(&spp) {
            return Err(format!("spp {spp} outside 1..={MAX_SPP}"));
        }
        Ok(Stream {
            kind,
            grid,
            setup: cfg.unwrap_or(registry::DEFAULT),
            spp,
            seed,
            targets: [false; Bin::COUNT],
        })
    }
    /// The stream biased toward the bins named in `bins` (`uvt_core::coverage::Bin` names of
    /// this kind; empty: the stream itself): record i is the first of up to [`TARGET_TRIES`]
    /// candidates, drawn in turn from record i's own generator (its families [`FAMILIES`] and
    /// [`DIRECTED`]), on which the model's test takes one of the bins (the last candidate if
    /// none does). Record i still depends only
    /// on the kind, configuration, seed, i and the target list, so shards concatenate to the
    /// whole stream. Unknown bins, bins of another kind and unreachable bins are refused.
    pub fn targeting(mut self, bins: &[String]) -> Result<Stream, String> {
        for name in bins {
            let b = Bin::from_name(name).ok_or_else(|| {
                format!(
                    "unknown bin `{name}` (`uvt vectors coverage` lists the bins of {})",
                    self.kind.name()
                )
            })?;
            if b.kind() != self.kind.name() {
                return Err(format!(
                    "bin `{name}` is of {} records, not {}",
                    b.kind(),
                    self.kind.name()
                ));
            }
            if let Some(why) = b.unreachable() {
                return Err(format!("bin `{name}` is unreachable: {why}"));
            }
            if let Some(t) = self.targets.get_mut(b.index()) {
                *t = true;
            }
        }
        Ok(self)
    }
    /// The record kind.
    pub fn kind(&self) -> Kind {
        self.kind
    }
    /// The configuration the records are of (`None`: the kind has none).
    pub fn config(&self) -> Option<String> {
        match self.kind {
            Kind::Bsample => self.grid.map(|g| g.name()),
            Kind::Psample => Some(registry::PLANAR.to_string()),
            Kind::Setup => Some(self.setup.to_string()),
            _ => None,
        }
    }
    /// Input record `index` of the stream and the family of its triangle (`None` for kinds
    /// without one).
    pub fn record(&self, index: u64) -> (Rec, Option<&'static str>) {
        let mut rng = Pcg64::seed_from_u64(mix(self.seed, index));
        if !self.targets.contains(&true) {
            return self.draw(&mut rng);
        }
        let mut last = self.draw(&mut rng);
        for _ in 1..TARGET_TRIES {
            if self.hits_target(&last.0) {
                break;
            }
            last = self.draw(&mut rng);
        }
        last
    }
    /// Whether the model's test takes one of the target bins on input record `r`.
    fn hits_target(&self, r: &Rec) -> bool {
        let mut c = Counts::default();
        crate::coverage::record(self.kind, &r.0, &mut c).is_ok()
            && c.n
                .iter()
                .zip(self.targets.iter())
                .any(|(&n, &t)| t && n > 0)
    }
    /// One record drawn from `rng` (the plain stream's record i is the first draw of its
    /// generator).
    fn draw(&self, rng: &mut Pcg64) -> (Rec, Option<&'static str>) {
        let directed = self.targets.contains(&true);
        match self.kind {
            Kind::Select => (select_record(rng), None),
            Kind::Resolve => {
                let colors: Vec<_> = (0..self.spp)
                    .map(|_| uvt_core::Rgb888::new(rng.gen(), rng.gen(), rng.gen()))
                    .collect();
                (enc_resolve_in(&colors), None)
            }
            Kind::Setup => {
                let (fam, t, vp, _) = draw(rng, None, false, directed);
                let t = on_grid(&t, self.setup.pos());
                (enc_setup_in(&t, vp, self.setup), Some(family_name(fam)))
            }
            Kind::Psample => loop {
                // A triangle the planar setup culls (det P' = 0) has no record: draw again (the
                // same generator, so the record stays a function of the index).
                let (fam, t, vp, pos) = draw(rng, None, true, directed);
                let t = static_of(&t);
                if let Some(pl) = Setup::unculled::<PlanarPrecision>(&t, vp).planar() {
                    break (enc_psample_in(&t, vp, &pl, pos), Some(family_name(fam)));
                }
            },
            // `new` made a grid for every bounded stream and refused the other kinds.
            _ => {
                let g = self.grid.unwrap_or(Grid::DEFAULT);
                let (fam, t, vp, pos) = draw(rng, Some(g), false, directed);
                let s = g.sample(&tuv(rng));
                (enc_bsample_in(&t, vp, g, pos, &s), Some(family_name(fam)))
            }
        }
    }
}

/// SplitMix64 of the seed and the index: the generator of record `index`.
fn mix(seed: u64, index: u64) -> u64 {
    let mut z = seed
        .wrapping_mul(0x9E37_79B9_7F4A_7C15)
        .wrapping_add(index)
        .wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A raw I16F16 coordinate of `v`, rounded to nearest and clamped to the core's ±2^13.
fn raw(v: f64) -> i32 {
    (v * 65536.0)
        .round()
        .clamp(-(1 << 29) as f64, (1 << 29) as f64) as i32
}

/// A viewport: mostly small, sometimes up to 2048, sometimes a 1-pixel side or the limit.
fn viewport(rng: &mut Pcg64) -> Viewport {
    let mut side = || -> u16 {
        match rng.gen_range(0..10) {
            0 => 1,
            1 => 2048,
            2 | 3 => rng.gen_range(257..=2048),
            _ => rng.gen_range(2..=256),
        }
    };
    let (w, h) = (side(), side());
    Viewport::new(w, h).unwrap_or_else(|_| unreachable!("sides are in 1..=2048"))
}

/// t, u, v in their domains, at an extreme one time in eight each.
fn tuv(rng: &mut Pcg64) -> Sample {
    let mut pick = |lo: i32, hi: i32| match rng.gen_range(0..8) {
        0 => lo,
        1 => hi,
        _ => rng.gen_range(lo..=hi),
    };
    let (t, u, v) = (pick(0, 65536), pick(-65536, 65536), pick(-65536, 65536));
    Sample::new(
        SubPixel::ZERO,
        SubPixel::ZERO,
        Lens::from_bits(u),
        Lens::from_bits(v),
        Time::from_bits(t),
    )
    .unwrap_or_else(|_| unreachable!("drawn inside the domain"))
}

/// A family, a triangle (on `grid` when given; static when `stat`), its viewport and a
/// sample position.
fn draw(
    rng: &mut Pcg64,
    grid: Option<Grid>,
    stat: bool,
    directed: bool,
) -> (usize, Triangle, Viewport, ScreenPos) {
    let families = FAMILIES.len() + if directed { DIRECTED.len() } else { 0 };
    loop {
        let vp = viewport(rng);
        let fam = rng.gen_range(0..families);
        let (ends, tie) = family(rng, fam, vp, stat);
        let q = |e: [[f64; 5]; 3]| e.map(|v| Vertex::from_bits(v.map(raw)));
        let Ok(t) = Triangle::new(q(ends[0]), q(ends[1])) else {
            continue;
        };
        let t = match grid {
            Some(g) => g.tri(&t),
            None => t,
        };
        let pos = tie.unwrap_or_else(|| position(rng, &t, vp));
        return (fam, t, vp, pos);
    }
}

/// Both key frames of a triangle of family `fam` (clip coordinates, CoC), and for a tie the
/// sample position on its vertical edge.
fn family(
    rng: &mut Pcg64,
    fam: usize,
    vp: Viewport,
    stat: bool,
) -> ([[[f64; 5]; 3]; 2], Option<ScreenPos>) {
    let mut r = |lo: f64, hi: f64| rng.gen_range(lo..hi);
    let (motion, defocus) = match fam {
        1 => (true, false),
        2 => (false, true),
        3 | 5 | 6 => (fam != 6 || r(0.0, 1.0) < 0.5, r(0.0, 1.0) < 0.5),
        _ => (false, false),
    };
    let (motion, defocus) = (motion && !stat, defocus && !stat);
    match family_name(fam) {
        "crosser" => {
            let mut p = || {
                let w = r(-3.0, 3.0);
                [r(-3.0, 3.0), r(-3.0, 3.0), r(-1.2, 1.2) * w, w, 0.0]
            };
            let t0 = [p(), p(), p()];
            let t1 = if stat { t0 } else { [p(), p(), p()] };
            return ([t0, t1], None);
        }
        "huge" => {
            let mut p = || [0; 4].map(|_| r(-8000.0, 8000.0));
            let mut v = || {
                let [x, y, z, w] = p();
                [x, y, z, w, 0.0]
            };
            let t0 = [v(), v(), v()];
            return ([t0, t0], None);
        }
        "tie" => {
            // w = 1: the screen x of clip x = 512·k/65536 is k·W + 128·W in 1/256 px, exact.
            let k = r(-100.0, 100.0).round();
            let xa = 512.0 * k / 65536.0;
            let (ya, yb) = (r(-0.9, 0.0), r(0.05, 0.9));
            let xb = xa + if r(0.0, 1.0) < 0.5 { -1.0 } else { 1.0 } * r(0.05, 0.9);
            let yc = r(-0.9, 0.9);
            let mut v = |x: f64, y: f64| [x, y, r(0.0, 1.0), 1.0, 0.0];
            let t0 = [v(xa, ya), v(xa, yb), v(xb, yc)];
            let w = i64::from(vp.width());
            let xs = k as i64 * w + 128 * w;
            // y on the edge: the record's y is in 1/256 px from the top
            let yn = r(ya, yb);
            let ys = ((1.0 - yn) * 128.0 * f64::from(vp.height())).floor() as i64;
            return ([t0, t0], on_screen(xs, ys, vp));
        }
        "tie_horizontal" => {
            // w = 1: the screen y of clip y = 512·k/65536 is (128 − k)·H in 1/256 px from the
            // top, exact; the sample on that row, its x inside the edge's span.
            let k = r(-100.0, 100.0).round();
            let ya = 512.0 * k / 65536.0;
            let (xa, xb) = (r(-0.9, 0.0), r(0.05, 0.9));
            let yc = ya + if r(0.0, 1.0) < 0.5 { -1.0 } else { 1.0 } * r(0.05, 0.9);
            let xc = r(-0.9, 0.9);
            let mut v = |x: f64, y: f64| [x, y, r(0.0, 1.0), 1.0, 0.0];
            let t0 = [v(xa, ya), v(xb, ya), v(xc, yc)];
            let h = i64::from(vp.height());
            let ys = (128 - k as i64) * h;
            let xn = r(xa, xb);
            let xs = ((1.0 + xn) * 128.0 * f64::from(vp.width())).floor() as i64;
            return ([t0, t0], on_screen(xs, ys, vp));
        }
        "depth_extreme" => {
            let t0 = if r(0.0, 1.0) < 0.5 {
                // large (w up to 8000, the vertices rounded by up to 15 bits), depths of a few
                // LSB of either sign: D large, Zv small
                let w = r(2000.0, 8000.0);
                let mut v = || {
                    let z = r(-3.0, 3.0) / 65536.0;
                    [r(-0.95, 0.95) * w, r(-0.95, 0.95) * w, z, w, 0.0]
                };
                [v(), v(), v()]
            } else {
                // a sliver (w = 1), its third vertex a few LSB off the line of the other two,
                // |z| from 4000 to 8000 of either sign: D small, Zv large
                let (x0, y0) = (r(-0.9, 0.9), r(-0.9, 0.9));
                let (dx, dy) = (r(-0.05, 0.05), r(-0.05, 0.05));
                let l = r(-0.5, 1.5);
                let off = r(-4.0, 4.0) / 65536.0;
                let mut z = || r(4000.0, 8000.0) * if r(0.0, 1.0) < 0.5 { -1.0 } else { 1.0 };
                [
                    [x0, y0, z(), 1.0, 0.0],
                    [x0 + dx, y0 + dy, z(), 1.0, 0.0],
                    [x0 + l * dx + off, y0 + l * dy, z(), 1.0, 0.0],
                ]
            };
            return ([t0, t0], None);
        }
        _ => {}
    }
    let (cx, cy, w, s) = (r(-1.2, 1.2), r(-1.2, 1.2), r(0.5, 6.0), r(0.05, 0.8));
    let (mx, my, mw, mz) = (r(-1.5, 1.5), r(-1.5, 1.5), r(-0.5, 0.5), r(-0.2, 0.2));
    let (a, b) = (r(-0.15, 0.15), r(-0.3, 0.3));
    let c = |w: f64| if defocus { a * w + b } else { 0.0 };
    // depth z/w per vertex: mostly in [0, 1], one triangle in four beyond a depth clamp (±128)
    let (zc, zs) = match r(0.0, 8.0) as u32 {
        0 => (r(100.0, 300.0), r(0.0, 50.0)), // beyond the far clamp (z/w ≥ 128)
        1 => (-r(100.0, 300.0), r(0.0, 50.0)), // beyond the near clamp
        _ => (r(-0.1, 1.1), r(0.0, 0.3)),
    };
    let mut pts = [[0.0; 4]; 3];
    for p in &mut pts {
        *p = [
            cx + s * r(-1.0, 1.0),
            cy + s * r(-1.0, 1.0),
            w * (1.0 + 0.3 * r(-1.0, 1.0)),
            zc + zs * r(-1.0, 1.0),
        ];
    }
    if family_name(fam) == "sliver" {
        // vertex 2 on the line of 0 and 1, moved off it by a few LSB
        let l = r(-0.5, 1.5);
        let (p0, p1) = (pts[0], pts[1]);
        pts[2] = core::array::from_fn(|i| p0[i] + l * (p1[i] - p0[i]));
        pts[2][0] += r(-4.0, 4.0) / 65536.0;
    }
    let mut ends = [[[0.0; 5]; 3]; 2];
    for (k, &[nx, ny, wk, zk]) in pts.iter().enumerate() {
        ends[0][k] = [nx * wk, ny * wk, zk * wk, wk, c(wk)];
        let w1 = wk * (1.0 + mw);
        ends[1][k] = if motion {
            [(nx + mx) * w1, (ny + my) * w1, (zk + mz) * w1, w1, c(w1)]
        } else {
            ends[0][k]
        };
    }
    if family_name(fam) == "w_zero" {
        let k = rng.gen_range(0..3);
        ends[0][k][3] = 0.0;
        if !motion {
            ends[1][k][3] = 0.0;
        }
    }
    (ends, None)
}

/// The sample position (`xs`, `ys`) in 1/256 px, if it lies in `vp` (a tie family's sample on
/// its edge; `None`: the record takes a drawn position instead).
fn on_screen(xs: i64, ys: i64, vp: Viewport) -> Option<ScreenPos> {
    let ok = |v: i64, lim: u16| (0..256 * i64::from(lim)).contains(&v);
    // In 0..256·2048: both fit u32.
    (ok(xs, vp.width()) && ok(ys, vp.height())).then_some(ScreenPos {
        xs: xs as u32,
        ys: ys as u32,
    })
}

/// A sample position: inside the projected box of the t0 vertices (all w > 0) half the time,
/// a viewport corner one time in eight, anywhere in the viewport otherwise.
fn position(rng: &mut Pcg64, t: &Triangle, vp: Viewport) -> ScreenPos {
    let (sw, sh) = (256 * u32::from(vp.width()), 256 * u32::from(vp.height()));
    let any = |rng: &mut Pcg64| ScreenPos {
        xs: rng.gen_range(0..sw),
        ys: rng.gen_range(0..sh),
    };
    match rng.gen_range(0..8) {
        0 => ScreenPos {
            xs: if rng.gen() { 0 } else { sw - 1 },
            ys: if rng.gen() { 0 } else { sh - 1 },
        },
        1..=4 => {
            let v = t.vertices(0);
            if v.iter().any(|v| v.w.to_bits() <= 0) {
                return any(rng);
            }
            let scr = |v: &Vertex, i: usize| {
                let [x, y, _, w, _] = v.bits().map(f64::from);
                let n = if i == 0 { x / w } else { -y / w };
                (n + 1.0) * 128.0 * f64::from(if i == 0 { vp.width() } else { vp.height() })
            };
            let lim = [f64::from(sw - 1), f64::from(sh - 1)];
            let mut c = [0u32; 2];
            for (i, c) in c.iter_mut().enumerate() {
                let vs = v.map(|v| scr(&v, i));
                let lo = vs
                    .iter()
                    .copied()
                    .fold(f64::MAX, f64::min)
                    .clamp(0.0, lim[i]);
                let hi = vs
                    .iter()
                    .copied()
                    .fold(f64::MIN, f64::max)
                    .clamp(0.0, lim[i]);
                *c = rng.gen_range(lo..=hi) as u32;
            }
            ScreenPos { xs: c[0], ys: c[1] }
        }
        _ => any(rng),
    }
}

/// An interval-check record: a box in the domain and a sample whose coordinates are each on a
/// face, one step outside it, inside the box or anywhere in the domain.
fn select_record(rng: &mut Pcg64) -> Rec {
    let mut iv = |lo: i32, hi: i32| {
        let (a, b) = (rng.gen_range(lo..=hi), rng.gen_range(lo..=hi));
        let (a, b) = (a.min(b), a.max(b));
        let x = match rng.gen_range(0..10) {
            0 => a,
            1 => b,
            2 => (a - 1).max(lo),
            3 => (b + 1).min(hi),
            4..=8 => rng.gen_range(a..=b),
            _ => rng.gen_range(lo..=hi),
        };
        (uvt_core::Interval::new(a, b), x)
    };
    let (u, x_u) = iv(-65536, 65536);
    let (v, x_v) = iv(-65536, 65536);
    let (t, x_t) = iv(0, 65536);
    match (u, v, t) {
        (Ok(u), Ok(v), Ok(t)) => enc_select_in(&uvt_core::UvtBox { u, v, t }, x_u, x_v, x_t),
        _ => unreachable!("lo ≤ hi inside the domain"),
    }
}
