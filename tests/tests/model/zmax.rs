//! Zmax culling (`uvt_core::raster::zmax`): the depth floor is below every covered sample's
//! depth for triangles of every kind at every precision and pipeline; rendering with and without
//! Zmax gives bit-identical colors, depths and written counts on seeded occluding scenes (every
//! unit, precision and bounds-tile size), on every stress and example scene and on the bench's
//! occlusion rows, while Zmax does skip tiles; the core's loop over screen tiles (the no-heap
//! renderer) and over bands of one row of bounds tiles (the host's frame) skip the same tiles.
//! Seed: `UVT_SEED`; more cases with `UVT_EXTENSIVE=1`.

use uvt_core::config::formats::DEPTH_NEAR;
use uvt_core::config::registry::CONFIGS;
use uvt_core::{
    with_config, Bounded, DefaultPrecision, DefocusOnly, DepthCull, Exact, Full, Laine2011,
    MotionOnly, NoZmax, Ops, Pipeline, PipelineOf, PlanarPrecision, Precision, Prim, Raster,
    Rgb888, SamplePattern, ScreenPos, Select, StaticOnly, Stats, TileBuffer, Triangle, Unit,
    Viewport, Zmax,
};
use uvt_host::frame::opts::RunOpts;
use uvt_host::scene::file::Scene;
use uvt_host::scene::pattern::Pattern;
use uvt_tests::kinds::{make, ALL_KINDS, NP};
use uvt_tests::tiles::same_samples;
use uvt_tests::{cases, dump, dump_sample, random_samples, seed, snap_samples, snap_tri, Rng};

const CAP: usize = 64;

/// The renderer of (`P`, `U`) with Laine's bounds and Zmax culling `Z`.
type Zr<P, U, Z> = Raster<PipelineOf<Laine2011, P, U>, CAP, Z>;

/// A triangle of a random kind (every hard kind of `kinds.rs`) or, two times in three, a large
/// in-front-of-the-camera triangle at a random depth that occludes others: static, moving,
/// defocused or both, some rotating so that their orientation changes during the shutter.
fn occluder(rng: &mut Rng) -> Triangle {
    if rng.below(3) == 0 {
        let mut p = [0.0; NP];
        for x in p.iter_mut() {
            *x = rng.range(-1.0, 1.0);
        }
        return make(ALL_KINDS[rng.below(ALL_KINDS.len() as u64) as usize], &p);
    }
    let kind = rng.below(4);
    let (motion, defocus) = (kind & 1 != 0, kind & 2 != 0);
    let depth = rng.range(0.05, 0.95);
    let mut end = |moved: bool| {
        let spin = if moved { rng.range(-2.0, 2.0) } else { 0.0 };
        [0.0f64, 2.1, 4.2].map(|a| {
            let w = rng.range(0.6, 2.5);
            let z = (depth + if moved { rng.range(-0.2, 0.2) } else { 0.0 }) * w;
            let r = rng.range(0.6, 2.0);
            let coc = if defocus {
                rng.range(-0.08, 0.08) * w
            } else {
                0.0
            };
            uvt_tests::vtx(
                r * (a + spin).cos() * w,
                r * (a + spin).sin() * w,
                z,
                w,
                coc,
            )
        })
    };
    let t0 = end(false);
    let t1 = if motion { end(true) } else { t0 };
    Triangle::new(t0, t1).expect("occluder in the domain")
}

fn prims<P: Precision>(rng: &mut Rng, n: usize) -> Vec<Prim> {
    (0..n)
        .map(|i| Prim {
            tri: snap_tri::<P>(&occluder(rng)),
            color: Rgb888::new((i * 37) as u8, (i * 91) as u8, (i * 13 + 5) as u8),
        })
        .collect()
}

/// Every covered sample's depth is at least its triangle's floor, through the pipeline of
/// (`P`, `U`) on seeded triangles of every kind, at every pixel of a 12×12 viewport. Returns
/// (hits checked, hits on triangles with a floor above `DEPTH_NEAR`, the smallest
/// depth − floor seen on those, the smallest depth).
fn floor_holds<P: Precision, U: Unit>(name: &str, n: u32, salt: u64) -> (u64, u64, i64, i32)
where
    (P, U): Select<Laine2011>,
{
    floor_holds_on::<P, U>(name, n, salt, occluder)
}

/// [`floor_holds`] on triangles from `gen`.
fn floor_holds_on<P: Precision, U: Unit>(
    name: &str,
    n: u32,
    salt: u64,
    mut gen: impl FnMut(&mut Rng) -> Triangle,
) -> (u64, u64, i64, i32)
where
    (P, U): Select<Laine2011>,
{
    type L<P, U> = PipelineOf<Laine2011, P, U>;
    let pipe = <L<P, U> as Pipeline>::new(Laine2011);
    let vp = Viewport::new(12, 12).expect("vp");
    let mut rng = Rng(seed() ^ salt);
    let (mut hits, mut floored, mut slack, mut lowest) = (0u64, 0u64, i64::MAX, i32::MAX);
    for case in 0..n {
        let tri = snap_tri::<P>(&gen(&mut rng));
        if !U::accepts(tri.class()) {
            continue;
        }
        let samples = snap_samples::<P>(&random_samples(&mut rng, 4, 4));
        let pat = SamplePattern::new_with::<P>(4, 4, &samples).expect("pattern");
        let mut ops = Ops::default();
        let uvt_core::Outcome::Visible(e) = pipe.setup(&tri, vp, &mut ops) else {
            continue;
        };
        let floor = <L<P, U> as Pipeline>::depth_floor(&e, &mut ops);
        for py in 0..12u16 {
            for px in 0..12u16 {
                for s in pat.pixel(px, py) {
                    let pos = ScreenPos::of(px, py, s);
                    let Some(h) = <L<P, U> as Pipeline>::test(&e, pos, s, &mut ops) else {
                        continue;
                    };
                    hits += 1;
                    lowest = lowest.min(h.depth);
                    if floor > DEPTH_NEAR {
                        floored += 1;
                        slack = slack.min(i64::from(h.depth) - i64::from(floor));
                    }
                    assert!(
                        h.depth >= floor,
                        "{name}: case {case}, UVT_SEED={}: depth {} ({:#010x}) below the floor \
                         {floor} ({floor:#010x}) at {}\n{}",
                        seed(),
                        h.depth,
                        h.depth,
                        dump_sample(px, py, s),
                        dump(&tri)
                    );
                }
            }
        }
    }
    (hits, floored, slack, lowest)
}

#[test]
fn floor_is_below_every_covered_depth() {
    let n = cases(300, 3000);
    let check = |name: &str, r: (u64, u64, i64, i32), planar_static: bool| {
        assert!(r.0 > 1000, "{name}: too few hits ({})", r.0);
        if !planar_static {
            assert!(r.1 > r.0 / 4, "{name}: too few floored hits {r:?}");
            // Tight: some hit lies within 1/64 of the floor (a loose floor would pass the
            // inequality but cull nothing).
            assert!(r.2 < 1 << 18, "{name}: the floor is loose: {r:?}");
        }
    };
    // Every configuration of the registry on the full unit (salt = its index), then the
    // units with their own pipelines.
    for (i, e) in CONFIGS.iter().enumerate() {
        let name = format!("{}/full", e.name);
        let r = with_config!(e.config, P => floor_holds::<P, Full>(&name, n, 100 + i as u64))
            .expect("a registry configuration");
        check(&name, r, false);
    }
    check(
        "bounded-12-12-12-20/full",
        floor_holds::<Bounded<12, 12, 12, 20>, Full>("bounded-12-12-12-20/full", n, 4),
        false,
    );
    check(
        "bounded-16-16-16-20/motion-only",
        floor_holds::<DefaultPrecision, MotionOnly>("bounded/motion-only", n, 6),
        false,
    );
    check(
        "bounded-16-16-16-20/defocus-only",
        floor_holds::<DefaultPrecision, DefocusOnly>("bounded/defocus-only", n, 7),
        false,
    );
    // The static-only unit's planar test: no floor (documented), only the inequality.
    let r = floor_holds::<PlanarPrecision, StaticOnly>("planar/static-only", n, 8);
    assert!(r.0 > 1000 && r.1 == 0, "planar/static-only: {r:?}");
}

/// The rounding the floor widens for: triangles moving in depth with z = w/2 at every vertex
/// and both ends, so z/w = 1/2 exactly at the ends while the bounded datapath's rounded lerps
/// of z and w give z'/w' below 1/2 inside the shutter. Depths below 2^23 occur (a floor from
/// the end values alone, 2^23, would be above them) and the floor is below every one.
#[test]
fn floor_holds_where_the_lerp_rounds_below_the_ends() {
    let gen = |rng: &mut Rng| {
        let end = |w: f64| {
            [0.0f64, 2.1, 4.2].map(|a| {
                let w = (w * 32768.0).round() / 32768.0;
                uvt_tests::vtx(1.9 * a.cos() * w, 1.9 * a.sin() * w, w / 2.0, w, 0.0)
            })
        };
        let (w0, w1) = (rng.range(0.7, 1.5), rng.range(1.6, 3.0));
        Triangle::new(end(w0), end(w1)).expect("in the domain")
    };
    for (name, r) in [
        (
            "bounded-16-16-16-20",
            floor_holds_on::<DefaultPrecision, Full>("bounded", cases(40, 400), 9, gen),
        ),
        (
            "bounded/motion-only",
            floor_holds_on::<DefaultPrecision, MotionOnly>("motion-only", cases(40, 400), 10, gen),
        ),
    ] {
        assert!(r.1 > 1000, "{name}: {r:?}");
        // The smallest depth seen lies below 2^23 = the end values' z/w.
        assert!(
            r.3 < 1 << 23,
            "{name}: no depth below z/w = 1/2 was produced: {r:?}"
        );
    }
}

/// Render every screen tile of `vp` with and without Zmax; colors, depths and per-pixel
/// written counts must be equal, and the frame's written counts; Zmax never tests more.
/// Returns the tiles Zmax skipped.
fn same_with_zmax<P: Precision, U: Unit>(
    prims: &[Prim],
    vp: Viewport,
    pat: &SamplePattern<'_>,
    bt: u8,
) -> Result<(u64, u64), String>
where
    (P, U): Select<Laine2011>,
{
    fn make<P: Precision, U: Unit, Z: DepthCull>(
        prims: &[Prim],
        vp: Viewport,
    ) -> Result<Box<Zr<P, U, Z>>, String>
    where
        (P, U): Select<Laine2011>,
    {
        Raster::new(Laine2011, vp, prims)
            .map(Box::new)
            .map_err(|e| format!("{}: {e}", Z::NAME))
    }
    let mut off = make::<P, U, NoZmax>(prims, vp)?;
    let mut on = make::<P, U, Zmax>(prims, vp)?;
    let clear = Rgb888::new(1, 2, 3);
    let mut fa = Box::new(TileBuffer::<8, 8, 4>::new(clear));
    let mut fb = Box::new(TileBuffer::<8, 8, 4>::new(clear));
    for y0 in (0..vp.height()).step_by(8) {
        for x0 in (0..vp.width()).step_by(8) {
            off.render_tile(x0, y0, pat, bt, clear, &mut fa)
                .map_err(|e| format!("tile ({x0}, {y0}) without Zmax: {e}"))?;
            on.render_tile(x0, y0, pat, bt, clear, &mut fb)
                .map_err(|e| format!("tile ({x0}, {y0}) with Zmax: {e}"))?;
            for ty in 0..8usize {
                for tx in 0..8usize {
                    let (x, y) = (x0 as usize + tx, y0 as usize + ty);
                    let (a, b) = (fa.pixel_stats(tx, ty), fb.pixel_stats(tx, ty));
                    if a.written != b.written || b.tested > a.tested {
                        return Err(format!(
                            "pixel ({x}, {y}): written {} / {} tested {} / {} without / with Zmax",
                            a.written, b.written, a.tested, b.tested
                        ));
                    }
                }
            }
            same_samples(&fa, &fb, x0, y0, ("without Zmax", "with Zmax"))?;
        }
    }
    let (a, b): (Stats, Stats) = (off.stats, on.stats);
    if a.samples_written != b.samples_written
        || b.samples_tested > a.samples_tested
        || a.tiles_zculled != 0
        || a.ops.zmax != 0
    {
        return Err(format!("frame counters without {a:?}\nwith {b:?}"));
    }
    Ok((b.tiles_zculled, a.samples_tested - b.samples_tested))
}

/// Seeded occluding scenes (up to 24 triangles of every kind in random order) in odd viewports,
/// every bounds-tile size, at every unit and a range of precisions.
#[test]
fn seeded_scenes_render_identically_with_zmax() {
    fn at<P: Precision, U: Unit>(name: &str, n: u32, salt: u64)
    where
        (P, U): Select<Laine2011>,
    {
        let mut rng = Rng(seed() ^ salt);
        let (mut culled, mut saved) = (0, 0);
        for case in 0..n {
            let vp = Viewport::new(8 + rng.below(40) as u16, 8 + rng.below(40) as u16).expect("vp");
            let k = 2 + rng.below(23) as usize;
            let prims: Vec<Prim> = prims::<P>(&mut rng, k)
                .into_iter()
                .filter(|p| U::accepts(p.tri.class()))
                .collect();
            let samples = snap_samples::<P>(&random_samples(&mut rng, 4, 4));
            let pat = SamplePattern::new_with::<P>(4, 4, &samples).expect("pattern");
            let bt = [1u8, 2, 4, 8][rng.below(4) as usize];
            match same_with_zmax::<P, U>(&prims, vp, &pat, bt) {
                Ok((c, t)) => {
                    culled += c;
                    saved += t;
                }
                Err(e) => {
                    let tris: String = prims.iter().map(|p| dump(&p.tri)).collect();
                    panic!(
                        "{name}: case {case}, UVT_SEED={}, viewport {}x{}, bounds tile {bt}: \
                         {e}\n{tris}",
                        seed(),
                        vp.width(),
                        vp.height()
                    );
                }
            }
        }
        assert!(
            culled > 0 && saved > 0,
            "{name}: Zmax skipped {culled} tiles and saved {saved} sample tests"
        );
    }
    let n = cases(60, 600);
    // Every configuration of the registry on the full unit (salt = its index), then the other
    // units.
    for (i, e) in CONFIGS.iter().enumerate() {
        let name = format!("{}/full", e.name);
        with_config!(e.config, P => at::<P, Full>(&name, n / 2, 200 + i as u64))
            .expect("a registry configuration");
    }
    at::<DefaultPrecision, MotionOnly>("bounded/motion-only", n / 2, 15);
    at::<PlanarPrecision, MotionOnly>("planar/motion-only", n / 2, 16);
    at::<DefaultPrecision, DefocusOnly>("bounded/defocus-only", n / 2, 17);
    // The static-only unit has no floor (planar depth): identical, nothing skipped.
    let mut rng = Rng(seed() ^ 18);
    for _ in 0..n / 4 {
        let vp = Viewport::new(24, 24).expect("vp");
        let prims: Vec<Prim> = prims::<PlanarPrecision>(&mut rng, 12)
            .into_iter()
            .filter(|p| StaticOnly::accepts(p.tri.class()))
            .collect();
        let samples = snap_samples::<PlanarPrecision>(&random_samples(&mut rng, 4, 4));
        let pat = SamplePattern::new_with::<PlanarPrecision>(4, 4, &samples).expect("pattern");
        let c = same_with_zmax::<PlanarPrecision, StaticOnly>(&prims, vp, &pat, 2)
            .unwrap_or_else(|e| panic!("planar/static-only, UVT_SEED={}: {e}", seed()));
        assert_eq!(c, (0, 0));
    }
}

/// The core's frame with and without Zmax on `scene` at precision `P` with `strategy`: the same
/// image, never more tests; returns (tested without, tested with, tiles skipped).
fn frame_pair<P: Precision + Sync>(scene: &Scene, strategy: &str) -> (u64, u64, u64) {
    let (tris, pattern) = scene.inputs_at::<P>().expect("scene on the grid");
    let colors = scene.colors();
    let base = RunOpts {
        image: true,
        ..RunOpts::for_scene(scene, &colors)
    };
    let vp = scene.core_viewport();
    let (a, ia) = uvt_host::bench::strategy::run_strategy_at::<P, NoZmax>(
        strategy, vp, &tris, &pattern, &base,
    )
    .expect("a registry strategy");
    let (b, ib) =
        uvt_host::bench::strategy::run_strategy_at::<P, Zmax>(strategy, vp, &tris, &pattern, &base)
            .expect("a registry strategy");
    let diff = ia.iter().zip(&ib).position(|(x, y)| x != y);
    assert!(
        ia.len() == ib.len() && diff.is_none(),
        "{} ({strategy}, {}): images differ with Zmax at pixel {diff:?}",
        scene.name,
        std::any::type_name::<P>()
    );
    assert!(b.stats.samples_tested <= a.stats.samples_tested);
    (
        a.stats.samples_tested,
        b.stats.samples_tested,
        b.stats.tiles_zculled,
    )
}

fn scenes_in(dir: &str) -> Vec<Scene> {
    let d = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(dir);
    let mut files: Vec<_> = std::fs::read_dir(&d)
        .expect("scene folder")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    assert!(!files.is_empty(), "{}", d.display());
    files
        .iter()
        .map(|f| Scene::load(f).unwrap_or_else(|e| panic!("{}: {e:#}", f.display())))
        .collect()
}

/// Every stress and example scene renders the same image with and without Zmax, with every
/// strategy of the registry at the default precision and with Laine at the exact and planar
/// ones.
#[test]
fn stress_and_example_scenes_render_identically_with_zmax() {
    let mut scenes = scenes_in("../host/stress");
    scenes.extend(scenes_in("../host/scenes"));
    for s in &scenes {
        for name in uvt_core::bounds::registry::STRATEGIES {
            frame_pair::<DefaultPrecision>(s, name);
        }
        frame_pair::<Exact>(s, "laine2011");
        frame_pair::<PlanarPrecision>(s, "laine2011");
    }
}

/// The bench's occlusion rows (quick size): identical images, and Zmax skips tiles.
#[test]
fn occlusion_rows_render_identically_and_cull() {
    use uvt_host::scene::builtin::{bench_scene, Bench, Blur};
    for row in [Blur::Static, Blur::Both] {
        let s = bench_scene(Bench::Occluded, row, true);
        let (off, on, culled) = frame_pair::<DefaultPrecision>(&s, "laine2011");
        assert!(
            culled > 0 && on < off,
            "{}: tested {off} / {on}, {culled} tiles skipped",
            s.name
        );
    }
}

/// The core's loop over 8×8 screen tiles (the no-heap renderer) and over bands of one row of
/// bounds tiles (the host's frame) make the same Zmax decisions: on a stress scene with overlap, the same samples
/// tested and written, tiles skipped and Zmax operations (floors, register refreshes, tile
/// checks) with Zmax.
#[test]
fn screen_tiles_and_bands_skip_the_same_tiles() {
    let mut rng = Rng(seed() ^ 0x2a);
    let vp = Viewport::new(40, 24).expect("vp");
    let prims = prims::<DefaultPrecision>(&mut rng, 20);
    let tris: Vec<Triangle> = prims.iter().map(|p| p.tri).collect();
    let pattern = Pattern::new(uvt_host::scene::pattern::PatternKind::Random, 4, seed());
    let core_pat = pattern.core();
    let mut r = Raster::<PipelineOf<Laine2011, DefaultPrecision, Full>, CAP, Zmax>::new(
        Laine2011, vp, &prims,
    )
    .expect("renderer");
    r.render_with::<8, 8, 4>(&core_pat, 2, Rgb888::new(0, 0, 0), |_, _, _, _| {})
        .expect("render");
    let colors: Vec<[u8; 3]> = prims.iter().map(|_| [0, 0, 0]).collect();
    let o = RunOpts {
        vp: (40, 24),
        spp: 4,
        tile: 2,
        colors: &colors,
        clear: [0; 3],
        image: false,
        label: "zmax",
        oracle: None,
    };
    let f = uvt_host::bench::strategy::run_frame::<_, DefaultPrecision, Zmax>(
        Laine2011, vp, &tris, &pattern, &o,
    )
    .expect("frame");
    let core = (
        r.stats.samples_tested,
        r.stats.samples_written,
        r.stats.tiles_zculled,
        r.stats.ops.zmax,
    );
    let host = (
        f.stats.samples_tested,
        f.stats.samples_written,
        f.stats.tiles_zculled,
        f.stats.ops_zmax,
    );
    assert!(core.1 > 0, "UVT_SEED={}: nothing skipped", seed());
    assert_eq!(
        core,
        host,
        "UVT_SEED={}: (tested, written, skipped, zmax ops)",
        seed()
    );
}
