//! The motion-specialised motion-only unit (`uvt_core::units::motion_only::setup`) against the full unit at
//! the same bounded configuration: the same image, depth and covered / written / occluded
//! counts on the demo prims and on seeded random scenes of every hard kind made motion-only
//! (moving, static, camera-plane crossers, w = 0 vertices, slivers flipping orientation, domain
//! extremes with huge motion, shared edges, samples on the t grid incl. T = 2^15, 2048-pixel
//! viewports); its sample test bit for bit the bounded test at every probed input; its slab
//! boxes never dropping a covered sample (brute force over whole viewports); refusal of the
//! other classes. Seed: `UVT_SEED`; more cases with `UVT_EXTENSIVE=1`.

use uvt_core::config::registry::{CONFIGS, DEFAULT};
use uvt_core::sample::bounded;
use uvt_core::setup::Outcome;
use uvt_core::units::motion_only::cull::slab_of;
use uvt_core::units::motion_only::sample::motion_test;
use uvt_core::units::motion_only::setup::{motion_setup, SLABS};
use uvt_core::{
    with_config, Bounded, Class, DefaultPrecision, DefocusOnly, Error, Exact, Full, Laine2011,
    MotionOnly, MotionRenderer, Ops, PlanarPrecision, Precision, Prim, Renderer, Rgb888, Sample,
    SamplePattern, ScreenPos, Select, Setup, StaticOnly, TileBuffer, Triangle, Viewport,
};
use uvt_demo as demo;
use uvt_tests::kinds::{make, Kind, ALL_KINDS, NP};
use uvt_tests::{
    c, cases, dump, dump_sample, random_samples, sample_raw, seed, snap_samples, snap_tri, Rng,
};

const CAP: usize = 64;

/// A triangle of `kind` from fresh parameters with every CoC set to 0 (static or motion class).
fn motion_kind(kind: Kind, rng: &mut Rng) -> Triangle {
    let mut p = [0.0; NP];
    for x in p.iter_mut() {
        *x = rng.range(-1.0, 1.0);
    }
    let t = make(kind, &p);
    let strip = |mut v: [uvt_core::Vertex; 3]| {
        for x in v.iter_mut() {
            x.coc = c(0.0);
        }
        v
    };
    Triangle::new(strip(t.vertices(0)), strip(t.vertices(1))).expect("triangle in the domain")
}

/// Two moving triangles sharing an edge (the same two vertices at both ends, opposite
/// directions): samples on the shared edge go to exactly one of them.
fn shared_pair(rng: &mut Rng) -> [Triangle; 2] {
    let mut v = || {
        let w0 = rng.range(0.5, 3.0);
        let w1 = rng.range(0.5, 3.0);
        let (x, y) = (rng.range(-1.2, 1.2), rng.range(-1.2, 1.2));
        let (dx, dy) = (rng.range(-0.5, 0.5), rng.range(-0.5, 0.5));
        (
            uvt_tests::vtx(x * w0, y * w0, 0.5 * w0, w0, 0.0),
            uvt_tests::vtx((x + dx) * w1, (y + dy) * w1, 0.5 * w1, w1, 0.0),
        )
    };
    let (a, b, p, q) = (v(), v(), v(), v());
    [
        Triangle::new([a.0, b.0, p.0], [a.1, b.1, p.1]).expect("pair"),
        Triangle::new([b.0, a.0, q.0], [b.1, a.1, q.1]).expect("pair"),
    ]
}

/// A sample table whose t is on a coarse grid (quarters: T = 2^15 among them, the general
/// datapath) and whose sub-pixel offsets are 0 or random.
fn grid_samples(rng: &mut Rng) -> Vec<Sample> {
    (0..64)
        .map(|_| {
            let sx = if rng.below(2) == 0 {
                0
            } else {
                rng.below(256) as u8
            };
            let sy = if rng.below(2) == 0 {
                0
            } else {
                rng.below(256) as u8
            };
            sample_raw(sx, sy, 0, 0, 16384 * rng.below(5) as i32)
        })
        .collect()
}

/// What a scene holds, to check that the cases the test is for occurred.
#[derive(Default, Debug)]
struct Mix {
    kinds: [usize; 8],
    pairs: usize,
}

/// A seeded motion-only scene of `n` triangles of every kind, and shared-edge pairs.
fn scene(rng: &mut Rng, n: usize, mix: &mut Mix) -> Vec<Prim> {
    let mut tris = Vec::new();
    for _ in 0..n {
        if rng.below(6) == 0 {
            mix.pairs += 1;
            tris.extend(shared_pair(rng));
            continue;
        }
        let k = rng.below(ALL_KINDS.len() as u64) as usize;
        mix.kinds[k] += 1;
        tris.push(motion_kind(ALL_KINDS[k], rng));
    }
    tris.iter()
        .enumerate()
        .map(|(i, &t)| Prim {
            tri: t,
            color: Rgb888::new((i * 37) as u8, (i * 91) as u8, (i * 13 + 5) as u8),
        })
        .collect()
}

/// Render the screen tiles of `vp` whose top-left is in `tiles` (all when `None`) with the
/// full unit and the motion-specialised renderer at precision `P`; compare every sample's
/// depth and color and every pixel's covered and written counts, then (whole frames) the
/// covered / written / occluded counts. `Err` names the first difference.
fn compare<P: Precision>(
    prims: &[Prim],
    vp: Viewport,
    pat: &SamplePattern<'_>,
    bt: u8,
    tiles: Option<&[(u16, u16)]>,
) -> Result<(), String>
where
    (P, Full): Select<Laine2011>,
    (P, MotionOnly): Select<Laine2011>,
{
    let mut full = Box::new(
        Renderer::<Laine2011, CAP, P, Full>::new(Laine2011, vp, prims)
            .map_err(|e| format!("full unit: {e}"))?,
    );
    let mut mo = Box::new(
        MotionRenderer::<CAP, P>::new(Laine2011, vp, prims)
            .map_err(|e| format!("motion unit: {e}"))?,
    );
    let clear = Rgb888::new(1, 2, 3);
    let mut fa = Box::new(TileBuffer::<8, 8, 4>::new(clear));
    let mut fb = Box::new(TileBuffer::<8, 8, 4>::new(clear));
    let all: Vec<(u16, u16)> = (0..vp.height())
        .step_by(8)
        .flat_map(|y| (0..vp.width()).step_by(8).map(move |x| (x, y)))
        .collect();
    for &(x0, y0) in tiles.unwrap_or(&all) {
        full.render_tile(x0, y0, pat, bt, clear, &mut fa)
            .map_err(|e| format!("full unit tile ({x0}, {y0}): {e}"))?;
        mo.render_tile(x0, y0, pat, bt, clear, &mut fb)
            .map_err(|e| format!("motion unit tile ({x0}, {y0}): {e}"))?;
        uvt_tests::tiles::same_tile(&fa, &fb, x0, y0, "motion")?;
    }
    if tiles.is_none() {
        uvt_tests::tiles::same_counts(full.stats, mo.stats, "motion")?;
    }
    Ok(())
}

/// The demo scene's motion-only prims at the default and the planar configuration: the
/// motion-specialised path (what the motion-only M4 program runs) renders the checksum and
/// covered counts of the full unit on the same prims, and every sample of every tile the same
/// with a random pattern and every bounds-tile size.
#[test]
fn demo_prims_render_identically() {
    fn at<P: Precision>(name: &str)
    where
        (P, Full): Select<Laine2011>,
        (P, MotionOnly): Select<Laine2011>,
    {
        let full = demo::render::<P, Full, MotionOnly>().expect("full");
        let mo = demo::render::<P, MotionOnly, MotionOnly>().expect("motion");
        assert_eq!(
            mo.checksum, full.checksum,
            "{name}: checksum: motion {:#010x}, full {:#010x}",
            mo.checksum, full.checksum
        );
        let key = |s: uvt_core::Stats| (s.samples_covered, s.samples_written, s.samples_occluded);
        assert_eq!(
            key(mo.stats),
            key(full.stats),
            "{name}: covered/written/occluded"
        );
        let prims = demo::unit_prims::<MotionOnly>().expect("prims");
        let mut rng = Rng(seed());
        let samples = random_samples(&mut rng, 4, 4);
        let pat = SamplePattern::new(4, 4, &samples).expect("pattern");
        let vp = demo::viewport().expect("viewport");
        for bt in [1, 2, 4, 8] {
            if let Err(e) = compare::<P>(&prims, vp, &pat, bt, None) {
                panic!(
                    "{name}: demo prims, bounds tile {bt}, UVT_SEED={}: {e}",
                    seed()
                );
            }
        }
    }
    at::<DefaultPrecision>("bounded-16-16-16-20");
    at::<PlanarPrecision>("planar-16-16-16-20");
}

/// Seeded random motion-only scenes of every kind in odd viewports, every bounds-tile size,
/// random and t-grid patterns (T = 2^15: the general datapath), at every bounded and planar
/// configuration of the registry (triangles and samples snapped to its grids).
#[test]
fn seeded_motion_scenes_render_identically() {
    fn run<P: Precision>(name: &str, n: u32, salt: u64)
    where
        (P, Full): Select<Laine2011>,
        (P, MotionOnly): Select<Laine2011>,
    {
        let mut rng = Rng(seed() ^ salt);
        let mut mix = Mix::default();
        for case in 0..n {
            let vp = Viewport::new(8 + rng.below(40) as u16, 8 + rng.below(40) as u16).expect("vp");
            let k = 1 + rng.below(8) as usize;
            // On P's grids (snapping keeps shared vertices shared).
            let prims: Vec<Prim> = scene(&mut rng, k, &mut mix)
                .into_iter()
                .map(|p| Prim {
                    tri: snap_tri::<P>(&p.tri),
                    ..p
                })
                .collect();
            let samples = snap_samples::<P>(&if case % 2 == 0 {
                random_samples(&mut rng, 4, 4)
            } else {
                grid_samples(&mut rng)
            });
            let pat = SamplePattern::new_with::<P>(4, 4, &samples).expect("pattern");
            let bt = [1u8, 2, 4, 8][rng.below(4) as usize];
            if let Err(e) = compare::<P>(&prims, vp, &pat, bt, None) {
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
        assert!(
            mix.kinds.iter().all(|&k| k > 0) && mix.pairs > 0,
            "{name}: every kind and shared pairs occurred: {mix:?}"
        );
    }
    // Every configuration of the registry with a bounded test (the motion-only unit's own
    // pipeline runs there), the default with the most cases.
    for (i, e) in CONFIGS
        .iter()
        .enumerate()
        .filter(|(_, e)| e.config.off().is_some())
    {
        let n = if e.config == DEFAULT {
            cases(200, 2000)
        } else {
            cases(60, 600)
        };
        with_config!(e.config, P => run::<P>(e.name, n, i as u64))
            .expect("a registry configuration");
    }
}

/// 2048-pixel viewport sides (the general datapath at S = 20 for every sample): random tiles
/// of seeded scenes render the same.
#[test]
fn wide_viewports_render_identically() {
    let mut rng = Rng(seed() ^ 0x2048);
    let mut mix = Mix::default();
    for case in 0..cases(12, 80) {
        let vp = if case % 2 == 0 {
            Viewport::new(2048, 16 + rng.below(32) as u16)
        } else {
            Viewport::new(16 + rng.below(32) as u16, 2048)
        }
        .expect("vp");
        let n = 1 + rng.below(6) as usize;
        let prims = scene(&mut rng, n, &mut mix);
        let samples = random_samples(&mut rng, 4, 4);
        let pat = SamplePattern::new(4, 4, &samples).expect("pattern");
        let tiles: Vec<(u16, u16)> = (0..24)
            .map(|_| {
                let x = rng.below(u64::from(vp.width() / 8)) as u16 * 8;
                let y = rng.below(u64::from(vp.height() / 8)) as u16 * 8;
                (x, y)
            })
            .collect();
        if let Err(e) = compare::<DefaultPrecision>(&prims, vp, &pat, 2, Some(&tiles)) {
            let tris: String = prims.iter().map(|p| dump(&p.tri)).collect();
            panic!(
                "case {case}, UVT_SEED={}, viewport {}x{}: {e}\n{tris}",
                seed(),
                vp.width(),
                vp.height()
            );
        }
    }
}

/// A random sample, biased to the datapath boundaries: T ∈ {0, 2^15 − 1, 2^15, 2^15 + 1,
/// 2^16} and sub-pixel 0 or 255 half of the time.
fn edge_sample(rng: &mut Rng) -> Sample {
    let t = match rng.below(4) {
        0 => [0, 32767, 32768, 32769, 65536][rng.below(5) as usize],
        _ => rng.below(65537) as i32,
    };
    let sub = |rng: &mut Rng| match rng.below(4) {
        0 => 0,
        1 => 255,
        _ => rng.below(256) as u8,
    };
    sample_raw(sub(rng), sub(rng), 0, 0, t)
}

/// The sample test bit for bit against the bounded test of the unculled setup, and the slab
/// boxes conservative: at every probed (position, sample) of every seeded triangle, the hit and
/// depth are equal, and a covered sample lies in its slab's box of a visible setup. Whole
/// viewports (every pixel, 4 samples each) for viewports up to 48², random positions in
/// 2048-pixel ones.
#[test]
fn sample_test_is_bounded_test_and_slab_boxes_conservative() {
    fn run<P: Precision>(name: &str, n: u32, salt: u64)
    where
        (P, Full): Select<Laine2011>,
        (P, MotionOnly): Select<Laine2011>,
    {
        let mut rng = Rng(seed() ^ salt);
        let mut hits = 0u64;
        let mut mix = Mix::default();
        for case in 0..n {
            let wide = case % 8 == 7;
            let vp = if wide {
                Viewport::new(2048 - rng.below(2) as u16, 2048 - rng.below(2) as u16)
            } else {
                Viewport::new(1 + rng.below(48) as u16, 1 + rng.below(48) as u16)
            }
            .expect("vp");
            let tris: Vec<Triangle> = scene(&mut rng, 1, &mut mix).iter().map(|p| p.tri).collect();
            for tri in tris {
                let full = Setup::unculled::<P>(&tri, vp);
                let out = motion_setup::<P>(&tri, vp, &mut Ops::default());
                if let Some(c) = out.refused() {
                    panic!("{name}: refused class {c:?}");
                }
                let mut probe = |px: u16, py: u16, s: &Sample| {
                    let pos = ScreenPos::of(px, py, s);
                    let want = bounded::test::<P, Full>(&full, pos, s, &mut Ops::default());
                    let Some(h) = want else {
                        if let Outcome::Visible(m) = &out {
                            let got = motion_test::<P>(m, pos, s);
                            assert!(got.is_none(), "{name}: motion covers, bounded does not");
                        }
                        return;
                    };
                    hits += 1;
                    let fail = |what: &str| {
                        panic!(
                            "{name}: case {case}, UVT_SEED={}, viewport {}x{}, pixel ({px}, \
                             {py}), sample {}: {what}; bounded depth {} ({:#010x})\n{}",
                            seed(),
                            vp.width(),
                            vp.height(),
                            dump_sample(px, py, s),
                            h.depth,
                            h.depth,
                            dump(&tri)
                        )
                    };
                    let Outcome::Visible(m) = &out else {
                        fail("covered sample of a triangle culled as outside");
                        return;
                    };
                    let j = slab_of(s.t().to_bits());
                    if !m.slab(j).is_some_and(|b| b.contains(px, py)) {
                        fail(&format!(
                            "covered sample outside slab {j}'s box {:?}",
                            m.slab(j)
                        ));
                    }
                    match motion_test::<P>(m, pos, s) {
                        Some(g) if g == h => {}
                        g => fail(&format!("motion test {g:?}")),
                    }
                };
                if wide {
                    for _ in 0..4000 {
                        let (px, py) = (
                            rng.below(u64::from(vp.width())) as u16,
                            rng.below(u64::from(vp.height())) as u16,
                        );
                        probe(px, py, &edge_sample(&mut rng));
                    }
                } else {
                    for py in 0..vp.height() {
                        for px in 0..vp.width() {
                            for _ in 0..4 {
                                probe(px, py, &edge_sample(&mut rng));
                            }
                        }
                    }
                }
            }
        }
        assert!(
            hits > 1000,
            "{name}: too few covered samples probed: {hits}"
        );
    }
    run::<DefaultPrecision>("bounded-16-16-16-20", cases(1000, 10000), 3);
    run::<Bounded<16, 16, 16, 32>>("bounded-16-16-16-32", cases(200, 2000), 4);
}

/// Extreme inputs: every vertex at ±2^13 (huge motion across the guard band), w = 0 at both
/// ends, a vertex crossing w = 0 exactly at T = 2^15: whole-viewport brute force on a
/// 64 × 64 viewport, every pixel's samples at T of the general and fast datapath.
#[test]
fn domain_corners_are_exact_and_conservative() {
    let lim = (1i64 << 29) as f64 / 65536.0;
    let v = |x: f64, y: f64, w: f64| uvt_tests::vtx(x, y, 0.25 * w, w, 0.0);
    let cases = [
        (
            [v(-lim, -lim, lim), v(lim, -lim, lim), v(0.0, lim, lim)],
            [v(lim, lim, lim), v(-lim, lim, lim), v(0.0, -lim, lim)],
        ),
        (
            [v(-1.0, -1.0, 0.0), v(1.0, -1.0, 1.0), v(0.0, 1.0, 1.0)],
            [v(-1.0, -1.0, 0.0), v(1.0, 0.5, 1.0), v(0.5, 1.0, 1.0)],
        ),
        (
            [v(-1.0, -1.0, 1.0), v(1.0, -1.0, 1.0), v(0.0, 1.0, 1.0)],
            [v(-1.0, -1.0, -1.0), v(1.0, -1.0, 1.0), v(0.0, 1.0, 1.0)],
        ),
        (
            [v(-lim, 0.0, 1.0), v(lim, 0.0, 1.0), v(0.0, lim, lim)],
            [v(-lim, 0.0, -lim), v(lim, 0.0, 1.0), v(0.0, -lim, lim)],
        ),
    ];
    let vp = Viewport::new(64, 64).expect("vp");
    let ts = [0, 1, 32767, 32768, 32769, 49152, 65535, 65536];
    for (i, (a, b)) in cases.iter().enumerate() {
        let tri = Triangle::new(*a, *b).expect("corner triangle");
        let full = Setup::unculled::<DefaultPrecision>(&tri, vp);
        let out = motion_setup::<DefaultPrecision>(&tri, vp, &mut Ops::default());
        assert_eq!(out.refused(), None, "class");
        let mut hits = 0;
        for py in 0..64u16 {
            for px in 0..64u16 {
                for (k, &t) in ts.iter().enumerate() {
                    let s = sample_raw((k * 37) as u8, (k * 91) as u8, 0, 0, t);
                    let pos = ScreenPos::of(px, py, &s);
                    let want = bounded::test::<DefaultPrecision, Full>(
                        &full,
                        pos,
                        &s,
                        &mut Ops::default(),
                    );
                    let got = match &out {
                        Outcome::Visible(m) => {
                            let in_box = m.slab(slab_of(t)).is_some_and(|b| b.contains(px, py));
                            assert!(
                                want.is_none() || in_box,
                                "case {i}: covered ({px}, {py}) t {t} outside its slab box"
                            );
                            motion_test::<DefaultPrecision>(m, pos, &s)
                        }
                        Outcome::Culled(_) | Outcome::Refused(_) => None,
                    };
                    hits += u32::from(want.is_some());
                    assert_eq!(
                        got,
                        want,
                        "case {i}: pixel ({px}, {py}), t {t}\n{}",
                        dump(&tri)
                    );
                }
            }
        }
        assert!(i == 1 || hits > 0, "case {i}: no covered sample probed");
    }
}

/// Every slab box of a camera-plane crosser that has w ≤ 0 and w > 0 corners is the whole
/// viewport, and `slab_of` maps the shutter onto the slabs as documented.
#[test]
fn slab_of_and_crossers() {
    assert_eq!(SLABS, 4);
    let want = [
        (0, 0),
        (16383, 0),
        (16384, 1),
        (32767, 1),
        (32768, 2),
        (49152, 3),
        (65535, 3),
        (65536, 3),
    ];
    for (t, j) in want {
        assert_eq!(slab_of(t), j, "slab_of({t})");
    }
    let v = |x: f64, y: f64, w: f64| uvt_tests::vtx(x, y, 0.25 * w, w, 0.0);
    let tri = Triangle::new(
        [v(-0.3, -0.3, 1.0), v(0.3, -0.3, 1.0), v(0.0, 0.3, 1.0)],
        [v(-0.3, -0.3, -1.0), v(0.3, -0.3, -1.0), v(0.0, 0.3, -1.0)],
    )
    .expect("crosser");
    let vp = Viewport::new(40, 24).expect("vp");
    let Outcome::Visible(m) = motion_setup::<DefaultPrecision>(&tri, vp, &mut Ops::default())
    else {
        panic!("crosser culled");
    };
    // w(t) = 1 − 2t: front for t < 1/2 (slabs 0, 1 — slab 1's end at t = 1/2 has w = 0: the
    // viewport), behind for t > 1/2 (slab 3: empty; slab 2 starts at w = 0: the viewport).
    let all = uvt_core::PixelRect {
        x0: 0,
        y0: 0,
        x1: 40,
        y1: 24,
    };
    assert!(
        m.slab(0).is_some_and(|b| b != all && !b.is_empty()),
        "{:?}",
        m.slab(0)
    );
    assert_eq!(m.slab(1), Some(all));
    assert_eq!(m.slab(2), Some(all));
    assert!(m.slab(3).is_some_and(|b| b.is_empty()), "{:?}", m.slab(3));
}

/// Other classes are refused with `ClassNotInUnit` naming the first such primitive, before
/// anything is set up; the path is selected for bounded precisions on the motion-only unit
/// only.
#[test]
fn refuses_other_classes_and_is_selected_at_compile_time() {
    let prims = demo::prims().expect("prims");
    let vp = demo::viewport().expect("vp");
    let err = MotionRenderer::<8, DefaultPrecision>::new(Laine2011, vp, &prims).err();
    assert_eq!(
        err,
        Some(Error::ClassNotInUnit {
            index: 2,
            class: Class::Defocus,
            unit: "motion-only"
        })
    );
    assert_eq!(
        err.map(|e| e.to_string()).as_deref(),
        Some("primitive 2: class defocus is not accepted by the motion-only unit")
    );
    let both: Vec<Prim> = prims[3..].to_vec();
    assert_eq!(
        MotionRenderer::<8, PlanarPrecision>::new(Laine2011, vp, &both).err(),
        Some(Error::ClassNotInUnit {
            index: 0,
            class: Class::MotionDefocus,
            unit: "motion-only"
        })
    );
    assert_eq!(
        motion_setup::<DefaultPrecision>(&prims[2].tri, vp, &mut Ops::default()).refused(),
        Some(Class::Defocus)
    );
    use uvt_tests::pipeline_name as name;
    assert_eq!(name::<DefaultPrecision, MotionOnly>(), "MotionRenderer");
    assert_eq!(name::<PlanarPrecision, MotionOnly>(), "MotionRenderer");
    assert_eq!(
        name::<Bounded<16, 16, 16, 32>, MotionOnly>(),
        "MotionRenderer"
    );
    assert_eq!(name::<Exact, MotionOnly>(), "Renderer");
    assert_eq!(name::<DefaultPrecision, Full>(), "Renderer");
    assert_eq!(name::<DefaultPrecision, StaticOnly>(), "Renderer");
    assert_eq!(name::<DefaultPrecision, DefocusOnly>(), "Renderer");
}
