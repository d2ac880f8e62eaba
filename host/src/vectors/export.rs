//! `uvt vectors export`: the unit-level set (seeded random inputs and named edge cases) and
//! frame-level sets (every stage of a whole small frame, with a decoded `trace.jsonl`).

use std::collections::BTreeMap;
use std::path::Path;

use anyhow::{anyhow, Context, Result};
use embedded_graphics_core::pixelcolor::RgbColor;
use rand::{Rng, SeedableRng};
use serde_json::json;
use uvt_core::bounds::any::AnyStrategy;
use uvt_core::bounds::laine::LaineCoeffs;
use uvt_core::bounds::strategy::BoundsStrategy;
use uvt_core::config::registry::Config;
use uvt_core::config::unit::Full;
use uvt_core::raster::zmax::NoRegisters;
use uvt_core::{
    with_config, with_strategy, Engine, Fate, General, Laine2011, Lens, NoZmax, Observer,
    PixelRect, Precision, Prim, RegionBuffer, Rgb888, Sample, SamplePattern, Seen, Setup, Stats,
    SubPixel, Time, Triangle, UvtBox, Viewport,
};

use crate::scene::builtin::random_tri;
use crate::scene::file::Scene;

use super::bsample::{on_grid, BCoverage, BSet, Grid};
use super::cases::{base_tri, named_cases, tri};
use super::format::{layout, sha256, to_text, Rec, FORMAT_VERSION, STAGES};
use super::psample::{PCase, PCoverage, PSet};
use super::stages::*;
use super::{bsample, bsample_directed, planar_cases, psample, psample_directed};
/// Samples per pixel of the unit-level resolve records.
pub const UNIT_RESOLVE_SPP: u32 = 16;
/// A named range of setup records.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Case {
    /// what it exercises
    pub name: String,
    /// first and last setup record (inclusive)
    pub setup_records: [usize; 2],
}
/// The records of one vector set, by file.
pub struct Set {
    /// records per file name (`setup_in`, …)
    pub files: BTreeMap<String, Vec<Rec>>,
    /// named cases
    pub cases: Vec<Case>,
    /// decoded trace (frame sets)
    pub trace: Option<String>,
    /// the scene (frame sets)
    pub scene: Option<String>,
    /// resolve width
    pub spp: u32,
    /// setups by triangle index
    setups: Vec<Option<(Setup, LaineCoeffs)>>,
    /// triangles and viewports by index (the bounded records' sources)
    tris: Vec<(Triangle, Viewport)>,
    /// what the bounded sample-test records cover
    pub bcov: Option<BCoverage>,
    /// what the planar sample-test records cover
    pub pcov: Option<PCoverage>,
    /// named groups of the planar records
    pub pcases: Vec<PCase>,
    /// the configuration of the setup, bounds and per-sample records
    pub config: Config,
    /// the bounds strategy of the frame (a name of
    /// [`STRATEGIES`](uvt_core::bounds::registry::STRATEGIES)); `laine2011`, the RTL bounds
    /// unit's, for a unit-level set
    pub strategy: &'static str,
}
impl Set {
    fn new(config: Config, spp: u32) -> Set {
        Set {
            files: BTreeMap::new(),
            cases: Vec::new(),
            trace: None,
            scene: None,
            spp,
            setups: Vec::new(),
            tris: Vec::new(),
            bcov: None,
            pcov: None,
            pcases: Vec::new(),
            config,
            strategy: Laine2011.name(),
        }
    }
    fn push(&mut self, file: &str, r: Rec) {
        self.files.entry(file.into()).or_default().push(r);
    }
    fn tri(&mut self, t: &Triangle, vp: Viewport) -> Result<u32> {
        let input = enc_setup_in(t, vp, self.config);
        let (s, out) = run_setup(&input.0).map_err(|e| anyhow!(e))?;
        self.push("setup_in", input);
        self.push("setup_out", out);
        self.setups.push(s);
        self.tris.push((*t, vp));
        Ok(self.setups.len() as u32 - 1)
    }
    fn bounded(&mut self, b: BSet) {
        self.files.insert("bsample_in".into(), b.inp);
        self.files.insert("bsample_out".into(), b.out);
        self.bcov = Some(b.cov);
    }
    fn planar(&mut self, p: PSet) {
        self.files.insert("psample_in".into(), p.inp);
        self.files.insert("psample_out".into(), p.out);
        self.pcov = Some(p.cov);
        self.pcases = p.cases;
    }
    fn lookup(&self) -> impl Fn(u32) -> Result<(Setup, LaineCoeffs), String> + '_ {
        move |i| {
            self.setups
                .get(i as usize)
                .copied()
                .flatten()
                .ok_or_else(|| format!("triangle {i} is culled or missing"))
        }
    }
    fn bounds(&mut self, i: u32, cell: PixelRect) -> Result<Option<UvtBox>> {
        let input = enc_bounds_in(i, cell);
        let (b, out) = run_bounds(&self.lookup(), &input.0).map_err(|e| anyhow!(e))?;
        self.push("bounds_in", input);
        self.push("bounds_out", out);
        Ok(b)
    }
    fn select(&mut self, b: &UvtBox, s: &Sample) -> bool {
        let input = enc_select_in(b, s.u().to_bits(), s.v().to_bits(), s.t().to_bits());
        let out = run_select(&input.0).expect("a box built by the core passes Interval::new");
        let inside = out.0.first() == Some(&1);
        self.push("select_in", input);
        self.push("select_out", out);
        inside
    }
    fn sample(&mut self, i: u32, px: u16, py: u16, s: &Sample) -> Result<Option<i32>> {
        let input = enc_sample_in(i, px, py, s);
        let (d, out) = run_sample(&self.lookup(), &input.0).map_err(|e| anyhow!(e))?;
        self.push("sample_in", input);
        self.push("sample_out", out);
        Ok(d)
    }
    fn resolve(&mut self, colors: &[Rgb888]) -> Rgb888 {
        let input = enc_resolve_in(colors);
        let out = run_resolve(&input.0);
        self.push("resolve_in", input);
        let w = out.0.first().copied().unwrap_or(0);
        self.push("resolve_out", out);
        Rgb888::new((w >> 16) as u8, (w >> 8) as u8, w as u8)
    }
}
fn random_sample(rng: &mut rand_pcg::Pcg64, b: Option<&UvtBox>) -> Sample {
    let mut pick = |lo: i32, hi: i32| rng.gen_range(lo..=hi);
    let (u, vv, t) = match b {
        Some(b) => (
            pick(b.u.lo(), b.u.hi()),
            pick(b.v.lo(), b.v.hi()),
            pick(b.t.lo(), b.t.hi()),
        ),
        None => (pick(-65536, 65536), pick(-65536, 65536), pick(0, 65536)),
    };
    Sample::new(
        SubPixel::from_bits(rng.gen()),
        SubPixel::from_bits(rng.gen()),
        Lens::from_bits(u),
        Lens::from_bits(vv),
        Time::from_bits(t),
    )
    .expect("drawn inside the domain or a core box")
}
/// Seeded random triangles of the unit set on large viewports: their dual-space lines and the
/// bounds unit's divider operands reach the high bits (`uvt_bounds.v`'s restoring divider), which
/// the small viewports' leave at 0 (docs/mutation.md).
pub const LARGE_VIEWPORT_TRIANGLES: u32 = 480;

/// The viewport sides (width; the height 3 less) of [`LARGE_VIEWPORT_TRIANGLES`].
pub const LARGE_SIDES: [u16; 2] = [1024, 2045];

/// The kinds (`random_tri`) of [`LARGE_VIEWPORT_TRIANGLES`]: moving, moving and defocused, huge.
pub const LARGE_KINDS: [u32; 3] = [1, 3, 5];

/// `n` seeded random triangles (`random_tri`), triangle `i` of kind and on the viewport
/// `shape(i) = (width, height, kind)`, rounded onto the configuration's position grid, as the
/// named case `name`.
fn random_group(
    set: &mut Set,
    rng: &mut rand_pcg::Pcg64,
    n: u32,
    shape: impl Fn(u32) -> (u16, u16, u32),
    name: String,
) -> Result<()> {
    let first = set.setups.len();
    for i in 0..n {
        let (w, h, kind) = shape(i);
        let vp = Viewport::new(w, h).map_err(|e| anyhow!("{e}"))?;
        let t = random_tri(rng, kind)
            .to_core()
            .map_err(|e| anyhow!("{e}"))?;
        set.tri(&on_grid(&t, set.config.pos()), vp)?;
    }
    set.cases.push(Case {
        name,
        setup_records: [first, set.setups.len() - 1],
    });
    Ok(())
}

/// Per visible triangle of `tris` (setup record indices): every tile size, `per` tiles inside
/// its footprint; per non-empty tile four interval checks and, at an exact configuration with
/// `samples`, three sample tests inside the box.
fn tiles(
    set: &mut Set,
    tris: core::ops::Range<u32>,
    rng: &mut rand_pcg::Pcg64,
    per: usize,
    samples: bool,
) -> Result<()> {
    let exact = samples && set.config.off().is_none();
    for i in tris {
        let Some((s, _)) = set.setups[i as usize] else {
            continue;
        };
        let fp = s.footprint();
        for bt in [1u16, 2, 4, 8] {
            for _ in 0..per {
                let x = rng.gen_range(fp.x0..fp.x1);
                let y = rng.gen_range(fp.y0..fp.y1);
                let cell = PixelRect {
                    x0: x - x % bt,
                    y0: y - y % bt,
                    x1: x - x % bt + bt,
                    y1: y - y % bt + bt,
                }
                .intersect(&fp);
                let Some(b) = set.bounds(i, cell)? else {
                    continue;
                };
                for k in 0..4 {
                    let smp = random_sample(rng, if k % 2 == 0 { Some(&b) } else { None });
                    set.select(&b, &smp);
                }
                for _ in 0..3 {
                    let smp = random_sample(rng, Some(&b));
                    let (px, py) = (
                        rng.gen_range(cell.x0..cell.x1),
                        rng.gen_range(cell.y0..cell.y1),
                    );
                    if exact {
                        set.sample(i, px, py, &smp)?;
                    }
                }
            }
        }
    }
    Ok(())
}

/// The unit-level set at configuration `cfg`: setup, bounds and interval-check records of its
/// setups (triangles rounded down onto its position grid); the exact sample test's records at an
/// exact configuration; at a bounded or planar one its bounded test's records (`bsample_*`) and
/// the planar static unit's (`psample_*`, configuration planar-16-16-16-20); resolve records.
pub fn unit(seed: u64, cfg: Config) -> Result<Set> {
    let mut rng = rand_pcg::Pcg64::seed_from_u64(seed);
    let mut set = Set::new(cfg, UNIT_RESOLVE_SPP);
    let exact = cfg.off().is_none();
    let start = |set: &Set| set.setups.len();
    for (name, list, side) in named_cases() {
        let first = start(&set);
        let vp = Viewport::new(side, side).map_err(|e| anyhow!("{e}"))?;
        for t in list {
            set.tri(&on_grid(&t, cfg.pos()), vp)?;
        }
        set.cases.push(Case {
            name: name.into(),
            setup_records: [first, set.setups.len() - 1],
        });
    }
    random_group(
        &mut set,
        &mut rng,
        180,
        |i| {
            let side = [8u16, 17, 32, 61][i as usize % 4];
            (side, side + 3, i % 6)
        },
        format!("seeded random (seed {seed}): static, moving, defocused, both, crossing, huge"),
    )?;
    // Per visible triangle: every tile size, a few tiles; per non-empty tile, interval checks and
    // sample tests inside the box.
    let n = set.setups.len() as u32;
    tiles(&mut set, 0..n, &mut rng, 3, true)?;
    // Ties: samples exactly on the shared edge x = 0 (column 16, sub-pixel 0) for both triangles.
    let tie = set
        .cases
        .iter()
        .find(|c| c.name.starts_with("shared-edge"))
        .map(|c| c.setup_records)
        .unwrap_or([0, 0]);
    for py in 10..22u16 {
        for u in [-65536, 0, 65536] {
            let smp = Sample::new(
                SubPixel::from_bits(0),
                SubPixel::from_bits((py * 37 % 256) as u8),
                Lens::from_bits(u),
                Lens::from_bits(0),
                Time::from_bits(0),
            )
            .expect("u in [-1, 1]");
            for i in (tie[0]..=tie[1]).filter(|_| exact) {
                set.sample(i as u32, 16, py, &smp)?;
            }
        }
    }
    // Triangles on large viewports and their tiles (their own stream, after everything above:
    // the records before them stay as they were).
    let before = set.tris.len();
    let first = start(&set);
    let mut lrng = rand_pcg::Pcg64::seed_from_u64(seed ^ 0x1a7e_0004);
    random_group(
        &mut set,
        &mut lrng,
        LARGE_VIEWPORT_TRIANGLES,
        |i| {
            let side = LARGE_SIDES[i as usize % LARGE_SIDES.len()];
            (side, side - 3, LARGE_KINDS[i as usize % LARGE_KINDS.len()])
        },
        format!(
            "seeded random on large viewports (sides {LARGE_SIDES:?}, seed {seed} ^ 0x1a7e_0004): moving, moving and defocused, huge; one tile of each size, without sample tests"
        ),
    )?;
    let n = set.setups.len() as u32;
    tiles(&mut set, first as u32..n, &mut lrng, 1, false)?;
    // Bounded sample-test records: every triangle above but those on large viewports, plus depth
    // saturation at both ends.
    let mut btris = set.tris[..before].to_vec();
    let vp32 = Viewport::new(32, 32).map_err(|e| anyhow!("{e}"))?;
    for z in [8000.0, -8000.0, 200.0, -129.0] {
        let big = base_tri().map(|v| [v[0], v[1], z, v[3], v[4]]);
        btris.push((tri(big, big), vp32));
    }
    if !exact {
        let g = Grid::from_config(cfg).map_err(|e| anyhow!(e))?;
        let mut b = bsample::unit(&btris, seed, g);
        // then the tie-key records (their own stream, after the set above)
        let mut trng = rand_pcg::Pcg64::seed_from_u64(seed ^ 0x7e1e_0003);
        bsample_directed::tie_keys(&mut b, &mut trng, g);
        set.bounded(b);
    }
    // Resolve: random colors, and the rounding edges (all 0, all 255, exact halves).
    let colors = |rng: &mut rand_pcg::Pcg64| {
        (0..UNIT_RESOLVE_SPP)
            .map(|_| Rgb888::new(rng.gen(), rng.gen(), rng.gen()))
            .collect::<Vec<_>>()
    };
    for _ in 0..120 {
        let c = colors(&mut rng);
        set.resolve(&c);
    }
    let n = UNIT_RESOLVE_SPP as usize;
    set.resolve(&vec![Rgb888::new(0, 0, 0); n]);
    set.resolve(&vec![Rgb888::new(255, 255, 255); n]);
    let half: Vec<Rgb888> = (0..n)
        .map(|i| {
            if i < n / 2 {
                Rgb888::new(1, 255, 3)
            } else {
                Rgb888::new(0, 0, 0)
            }
        })
        .collect();
    set.resolve(&half);
    if exact {
        return Ok(set);
    }
    // Planar sample-test records (its own random stream, after everything above): the t0 frame
    // of every triangle above (CoC dropped: static), the planar configuration's named cases,
    // depth saturation as for the bounded records, and domain-end random triangles.
    let mut prng = rand_pcg::Pcg64::seed_from_u64(seed ^ 0x9a7a_0002);
    let mut groups = vec![(
        "the t0 frames of the setup and bounded records' triangles (named cases, seeded random, depth saturation), CoC dropped".to_string(),
        btris
            .iter()
            .map(|(t, vp)| (psample::static_of(t), *vp))
            .collect::<Vec<_>>(),
    )];
    for (name, list, side) in planar_cases::named_cases() {
        let vp = Viewport::new(side, side).map_err(|e| anyhow!("{e}"))?;
        groups.push((name.into(), list.into_iter().map(|t| (t, vp)).collect()));
    }
    groups.push((
        format!("domain-end random static triangles and viewports (seed {seed})"),
        planar_cases::domain_random(&mut prng, 120),
    ));
    let mut pset = psample::unit(&groups, seed);
    let first = pset.inp.len();
    psample::boundary_search(&mut pset, &mut prng, 3);
    pset.cases.push(PCase {
        name: "found by search: unclamped depth at 2^31 − 2, 2^31 − 1, −2^31, −2^31 − 1; f ≥ 63 with |acc| ≥ 2^62".into(),
        triangles: 0,
        records: [first, pset.inp.len()],
    });
    let first = pset.inp.len();
    psample_directed::single_bit_edges(&mut pset, &mut prng);
    pset.cases.push(PCase {
        name: "single-bit edges: a or b (a = 0) = ±2^j, j = 0..29, exact vertices; samples on the edge (E = 0) and 2^q steps off it; E = ±2^t, t = 1..58".into(),
        triangles: psample_directed::EDGE_CASES as usize * psample_directed::BITS.count()
            + psample_directed::E_CASES as usize * psample_directed::E_BITS.count(),
        records: [first, pset.inp.len()],
    });
    let first = pset.inp.len();
    psample_directed::depth_boundaries(&mut pset, &mut prng);
    pset.cases.push(PCase {
        name: "depth at the range's ends at every shift f + 33 = 20..62: exact planes z/w = c + s·x/w, the accumulator one bit at the range test's mask boundary, c·2^24 = 2^31, −2^32, 2^32".into(),
        triangles: psample_directed::SHIFTS.count() * psample_directed::BOUNDARY_DEPTHS.len(),
        records: [first, pset.inp.len()],
    });
    let first = pset.inp.len();
    psample_directed::saturated_depth(&mut pset, &mut prng);
    pset.cases.push(PCase {
        name: "depth exponent below −33 (the scaled depth saturated): det 1, normals near 2^28, a vertex at w = 0, the centre sample on vertex 2 (fill rule)".into(),
        triangles: psample_directed::SATURATED,
        records: [first, pset.inp.len()],
    });
    let first = pset.inp.len();
    psample_directed::zero_depth(&mut pset, &mut prng);
    pset.cases.push(PCase {
        name: "depth exactly 0 at every shift f + 33 = 4..19 (the range test's mask on the accumulator's low bits): det 1, z_2 = 0, the centre sample on vertex 2".into(),
        triangles: psample_directed::SMALL_SHIFTS.count() * psample_directed::ZERO_PER_SHIFT,
        records: [first, pset.inp.len()],
    });
    set.planar(pset);
    Ok(set)
}
/// A frame-level set at configuration `cfg` with bounds strategy `strategy` (a name of
/// [`STRATEGIES`](uvt_core::bounds::registry::STRATEGIES)): every stage of one frame as `uvt
/// render --precision CFG --bounds STRATEGY` runs it at the scene's samples per pixel, bounds
/// tile and viewport (triangles rounded onto its position grid, samples onto its t/u/v grid;
/// 8×8 screen tiles in raster order; triangles in submission order; bounds tiles aligned to the
/// bounds-tile grid and clipped to footprint ∩ screen tile), plus `trace.jsonl`. Every sample
/// inside a tile's box gets the configuration's sample-test record: `sample_*` at an exact
/// configuration, `bsample_*` at a bounded one, `psample_*` (static triangles) and `bsample_*`
/// (the others) at a planar one. A bounded configuration's set also has the planar static
/// unit's records of the frame's static triangles (`psample_*`, up to 320 per triangle).
///
/// Bounds records (`bounds_*`) are those of the RTL bounds unit, which implements Laine 2011:
/// they are written, and checked against the walk, only when `strategy` is `laine2011`; with
/// any other strategy the `tile` lines carry the box the strategy's walk computed and the set
/// has no bounds records ([`write`]'s manifest says so). The interval-check records stay box
/// containment; the core's admission must equal it for a strategy whose tile is its box alone
/// (its `Tile` type is [`UvtBox`], whose predicate admits everything, as Laine 2011's), and
/// imply it for one with a per-sample predicate (it admits fewer samples than its box holds);
/// the trace's `sample` lines of such a strategy also say whether the sample was `admitted`
/// (tested).
pub fn frame(scene: &Scene, scene_json: &str, cfg: Config, strategy: &str) -> Result<Set> {
    with_config!(cfg, P => frame_at::<P>(scene, scene_json, cfg, strategy))
        .ok_or_else(|| anyhow!("configuration {cfg} is not in the registry"))?
}

/// Whether strategy `_s`'s tiles are their box alone (no per-sample predicate).
fn box_only<B: BoundsStrategy>(_s: &B) -> bool
where
    B::Tile: 'static,
{
    std::any::TypeId::of::<B::Tile>() == std::any::TypeId::of::<UvtBox>()
}

fn frame_at<P: Precision>(
    scene: &Scene,
    scene_json: &str,
    cfg: Config,
    strategy: &str,
) -> Result<Set> {
    let unknown = || {
        anyhow!(
            "unknown bounds strategy {strategy:?} (accepted: {})",
            uvt_core::bounds::registry::STRATEGIES.join(", ")
        )
    };
    let any = AnyStrategy::named(strategy).ok_or_else(unknown)?;
    let box_only = with_strategy!(strategy, s => box_only(&s)).ok_or_else(unknown)?;
    let laine = any.name() == Laine2011.name();
    let (core, pattern) = scene.inputs_at::<P>()?;
    let vp = scene.core_viewport();
    let spp = usize::from(scene.spp);
    let mut set = Set::new(cfg, u32::from(scene.spp));
    set.strategy = any.name();
    set.scene = Some(scene_json.into());
    let grid = Grid::from_config(cfg).ok();
    let (mut bset, mut pset) = (BSet::default(), PSet::default());
    let mut trace = String::new();
    for (i, t) in core.iter().enumerate() {
        set.tri(t, vp)?;
        let rec = match &set.setups[i] {
            Some((s, _)) => {
                json!({"type": "setup", "tri": i, "class": format!("{:?}", s.class()), "footprint": [s.footprint().x0, s.footprint().y0, s.footprint().x1, s.footprint().y1],
                "span": [s.span().lo() as f64 / 65536.0, s.span().hi() as f64 / 65536.0],
                "eps": [s.eps().x()[0] as f64 / 65536.0, s.eps().x()[1] as f64 / 65536.0, s.eps().w() as f64 / 65536.0]})
            }
            None => {
                let o = uvt_core::setup::<P, Full>(t, vp, &mut Default::default());
                json!({"type": "setup", "tri": i, "culled": match o { uvt_core::Outcome::Culled(uvt_core::Cull::Degenerate) => "degenerate", _ => "outside" }})
            }
        };
        trace += &(rec.to_string() + "\n");
    }
    let colors: Vec<Rgb888> = scene
        .tris
        .iter()
        .map(|t| Rgb888::new(t.color[0], t.color[1], t.color[2]))
        .collect();
    let clear = Rgb888::new(24, 24, 32);
    let q = SamplePattern::new_with::<P>(pattern.block, pattern.spp, &pattern.quant)
        .map_err(|e| anyhow!("sample table: {e}"))?;
    // The frame is the core's loop (the strategy, by name as `uvt render` takes it, at P on the
    // full unit) per 8×8 screen tile, as `uvt_core::Raster` runs it; the trace watches it and
    // writes every stage's records.
    let engine = Engine::<General<AnyStrategy, P, Full>, NoZmax>::new(any, vp);
    let mut stats = Stats::default();
    let mut drawn = Vec::new();
    for (i, (t, &color)) in core.iter().zip(&colors).enumerate() {
        if let Some(d) = engine
            .setup(i, &Prim { tri: *t, color }, &mut stats)
            .map_err(|e| anyhow!("{e}"))?
        {
            drawn.push(d);
        }
    }
    // One screen tile's samples (depth and colour), the scene's spp per pixel.
    let mut depth = vec![0i32; 8 * 8 * spp];
    let mut color = vec![clear; 8 * 8 * spp];
    for y0 in (0..vp.height()).step_by(8) {
        for x0 in (0..vp.width()).step_by(8) {
            let screen = PixelRect {
                x0,
                y0,
                x1: (x0 + 8).min(vp.width()),
                y1: (y0 + 8).min(vp.height()),
            };
            let n = usize::from(screen.x1 - x0) * usize::from(screen.y1 - y0) * spp;
            let mut fb = RegionBuffer::new(
                screen,
                scene.spp,
                clear,
                &mut depth[..n],
                &mut color[..n],
                &mut [],
            )
            .map_err(|e| anyhow!("{e}"))?;
            let mut tr = Tracer {
                set: &mut set,
                trace: &mut trace,
                core: &core,
                vp,
                cfg,
                grid,
                bset: &mut bset,
                pset: &mut pset,
                laine,
                box_only,
                bounds: None,
                failed: None,
            };
            engine
                .render_region(
                    drawn.iter(),
                    screen,
                    &q,
                    scene.tile,
                    &mut fb,
                    &mut NoRegisters,
                    &mut stats,
                    &mut tr,
                )
                .map_err(|e| anyhow!("{e}"))?;
            if let Some(e) = tr.failed {
                return Err(e);
            }
            for py in screen.y0..screen.y1 {
                for px in screen.x0..screen.x1 {
                    let (tx, ty) = ((px - x0) as usize, (py - y0) as usize);
                    let cs: Vec<Rgb888> = (0..spp)
                        .map(|s| fb.sample_color(tx, ty, s).unwrap_or(clear))
                        .collect();
                    let c = set.resolve(&cs);
                    trace +=
                        &(json!({"type": "pixel", "px": px, "py": py, "rgb": [c.r(), c.g(), c.b()]})
                            .to_string() + "\n");
                }
            }
        }
    }
    set.trace = Some(trace);
    if grid.is_some() {
        set.bounded(bset);
        if !cfg.planar() {
            pset = psample::frame(&core, vp, &q, 320);
        }
        set.planar(pset);
    }
    Ok(set)
}

/// The frame trace's observer of the core's loop: per bounds tile its bounds record (Laine 2011
/// only; checked against the tile the walk computed) and a `tile` line; per sample of a kept
/// tile — the culled ones too (the loop tests them for it, [`Observer::CULLED_SAMPLES`]) — its
/// interval check record (checked against the tile's admission: equal for a box-only
/// strategy, implied by it otherwise), the configuration's sample-test record for a sample
/// inside the box (checked against the loop's hit) and a `sample` line. The first mismatch is
/// kept and ends the export.
struct Tracer<'a> {
    set: &'a mut Set,
    trace: &'a mut String,
    core: &'a [Triangle],
    vp: Viewport,
    cfg: Config,
    grid: Option<Grid>,
    bset: &'a mut BSet,
    pset: &'a mut PSet,
    /// the strategy is Laine 2011: bounds records are written and checked
    laine: bool,
    /// the strategy's tiles are their box alone: admission equals box containment
    box_only: bool,
    /// the current kept tile's box
    bounds: Option<UvtBox>,
    failed: Option<anyhow::Error>,
}

impl Tracer<'_> {
    fn cell(&mut self, tri: u32, cell: PixelRect, fate: Fate) -> Result<()> {
        let b = match fate {
            Fate::Kept { bounds } => Some(bounds),
            Fate::Skipped | Fate::Zculled => None,
        };
        if self.laine {
            let rec = self.set.bounds(tri, cell)?;
            if rec != b {
                return Err(anyhow!(
                    "triangle {tri}, tile {cell:?}: the bounds record gives {rec:?}, the core's walk {b:?}"
                ));
            }
        }
        let f = |r: i32| r as f64 / 65536.0;
        *self.trace += &(json!({"type": "tile", "tri": tri, "rect": [cell.x0, cell.y0, cell.x1, cell.y1],
        "bounds": b.map(|b| json!({"u": [f(b.u.lo()), f(b.u.hi())], "v": [f(b.v.lo()), f(b.v.hi())], "t": [f(b.t.lo()), f(b.t.hi())]}))}).to_string() + "\n");
        self.bounds = b;
        Ok(())
    }

    fn sample(
        &mut self,
        tri: u32,
        px: u16,
        py: u16,
        si: usize,
        smp: &Sample,
        seen: Seen,
    ) -> Result<()> {
        let b = self
            .bounds
            .ok_or_else(|| anyhow!("a sample outside a kept tile"))?;
        let inside = self.set.select(&b, smp);
        let agrees = if self.box_only {
            inside == seen.admitted
        } else {
            inside || !seen.admitted
        };
        if !agrees {
            return Err(anyhow!(
                "triangle {tri}, pixel ({px},{py}), sample {si}: the interval record gives {inside}, the core's admission {}",
                seen.admitted
            ));
        }
        let pos = uvt_core::ScreenPos::of(px, py, smp);
        let hit = seen.hit.map(|h| h.depth);
        let i = tri as usize;
        if inside {
            let t = self
                .core
                .get(i)
                .ok_or_else(|| anyhow!("triangle {tri} missing"))?;
            let rec = match self.grid {
                None => self.set.sample(tri, px, py, smp)?,
                Some(_) if self.set.setups[i].is_some_and(|(s, _)| s.planar().is_some()) => self
                    .pset
                    .push(t, self.vp, pos)
                    .and_then(|e| e.hit)
                    .map(|h| h.depth),
                Some(g) => self.bset.push(t, self.vp, g, pos, smp).hit.map(|h| h.depth),
            };
            if rec != hit {
                return Err(anyhow!(
                    "triangle {i}, pixel ({px},{py}), sample {si}: the record gives {rec:?}, the core's sample test at {} {hit:?}",
                    self.cfg
                ));
            }
        }
        let f = |r: i32| r as f64 / 65536.0;
        let mut line = json!({"type": "sample", "tri": i, "px": px, "py": py, "s": si,
        "x": px as f64 + smp.sx().to_bits() as f64 / 256.0, "y": py as f64 + smp.sy().to_bits() as f64 / 256.0,
        "u": f(smp.u().to_bits()), "v": f(smp.v().to_bits()), "t": f(smp.t().to_bits()),
        "inside": inside, "covered": hit.is_some(), "depth": hit.map(|d| d as f64 / 16777216.0)});
        if !self.box_only {
            line["admitted"] = json!(seen.admitted);
        }
        *self.trace += &(line.to_string() + "\n");
        Ok(())
    }
}

impl Observer for Tracer<'_> {
    const CULLED_SAMPLES: bool = true;
    fn cell(&mut self, tri: u32, cell: PixelRect, fate: Fate) {
        if self.failed.is_none() {
            self.failed = Tracer::cell(self, tri, cell, fate).err();
        }
    }
    fn sample(&mut self, tri: u32, px: u16, py: u16, si: usize, s: &Sample, seen: Seen) {
        if self.failed.is_none() {
            self.failed = Tracer::sample(self, tri, px, py, si, s, seen).err();
        }
    }
}

/// Write a set into `dir` (created): hex files, manifest, trace and scene. Files are written to
/// temporary names first and renamed at the end.
pub fn write(set: &Set, dir: &Path, kind: &str, seed: u64) -> Result<()> {
    std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let mut outputs: Vec<(String, String)> = Vec::new();
    let mut files = serde_json::Map::new();
    for stage in STAGES {
        for io in ["in", "out"] {
            let name = format!("{stage}_{io}");
            let recs = set.files.get(&name).cloned().unwrap_or_default();
            let l = layout(&name, set.spp);
            let text = to_text(&recs);
            files.insert(format!("{name}.hex"), json!({"records": recs.len(), "words_per_record": l.words, "sha256": sha256(text.as_bytes()), "fields": l.fields}));
            outputs.push((format!("{name}.hex"), text));
        }
    }
    if let Some(t) = &set.trace {
        files.insert(
            "trace.jsonl".into(),
            json!({"records": t.lines().count(), "sha256": sha256(t.as_bytes())}),
        );
        outputs.push(("trace.jsonl".into(), t.clone()));
    }
    if let Some(s) = &set.scene {
        outputs.push(("scene.json".into(), s.clone()));
    }
    // The two "core" strings name the functions as the committed vector sets name them (kept
    // byte for byte, format version unchanged): today `uvt_core::sample::bounded::eval` and
    // `uvt_core::sample::planar::eval`.
    let manifest = json!({
        "format": "uvt-vectors", "format_version": FORMAT_VERSION, "generator": format!("uvt {}", env!("CARGO_PKG_VERSION")),
        "kind": kind, "seed": seed, "resolve_spp": set.spp, "word_bits": 32,
        "notes": "one record per line; words are 8 hex digits separated by a space; two's complement; a field wider than 32 bits spans whole words, most significant first; value = raw / 2^frac",
        "config": set.config.to_string(),
        "cases": set.cases, "files": files,
    });
    let mut manifest = manifest;
    // Absent for Laine 2011 (the committed sets' strategy, their bytes unchanged): its bounds
    // records are written.
    if set.strategy != Laine2011.name() {
        manifest["bounds_strategy"] = json!(set.strategy);
        manifest["bounds_records"] = json!(format!(
            "none: the RTL bounds unit (vectors/rtl/uvt_bounds.v) implements laine2011; the trace's tile lines carry the boxes of {}",
            set.strategy
        ));
    }
    if let (Some(cov), Ok(g)) = (&set.bcov, Grid::from_config(set.config)) {
        manifest["bsample_config"] = json!({"name": g.name(), "grid": g, "core": format!("uvt_core::bounded_eval at {}", g.name())});
        manifest["bsample_coverage"] = json!(cov);
    }
    if let Some(cov) = &set.pcov {
        manifest["psample_config"] = json!({"name": psample::CONFIG, "core": "uvt_core::planar::planar_eval on the planar setup of uvt_core::PlanarPrecision = Planar<16, 16, 16, 20> (static triangles; culled ones have no record)"});
        manifest["psample_coverage"] = json!(cov);
        manifest["psample_cases"] = json!(set.pcases);
    }
    outputs.push((
        "manifest.json".into(),
        serde_json::to_string_pretty(&manifest)? + "\n",
    ));
    let mut tmp = Vec::new();
    for (name, text) in &outputs {
        let t = dir.join(format!(".{name}.tmp"));
        std::fs::write(&t, text).with_context(|| format!("writing {}", t.display()))?;
        tmp.push((t, dir.join(name)));
    }
    for (t, d) in tmp {
        std::fs::rename(&t, &d).with_context(|| format!("renaming to {}", d.display()))?;
    }
    Ok(())
}
