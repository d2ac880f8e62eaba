//! The static-specialised static-only unit (`uvt_core::units::static_only`) against the full unit at
//! the planar configuration (`PlanarPrecision`): the same image, depth and covered / written /
//! occluded counts on the demo prims and on seeded random static scenes (guard-band,
//! camera-plane-crossing, w = 0, sliver, domain-extreme and mesh triangles); its sample test
//! bit for bit the planar test at every probed position, its footprint and tile cull never
//! dropping a covered sample (brute force over whole viewports). Seed: `UVT_SEED`; more cases
//! with `UVT_EXTENSIVE=1`.

use uvt_core::raster::renderer::StaticRenderer;
use uvt_core::sample::planar;
use uvt_core::setup::Outcome;
use uvt_core::units::static_only::cull::static_tile;
use uvt_core::units::static_only::sample::static_test;
use uvt_core::units::static_only::setup::static_setup;
use uvt_core::{
    Bounded, Class, DefocusOnly, Error, Exact, Full, Laine2011, MotionOnly, PixelRect,
    PlanarPrecision, Prim, Renderer, Rgb888, SamplePattern, ScreenPos, Setup, StaticOnly,
    TileBuffer, Triangle, Viewport,
};
use uvt_demo as demo;
use uvt_tests::kinds::{make_static, STATIC_KINDS};
use uvt_tests::{c, cases, dump, planar_mesh, random_samples, seed, tri, Rng};

const CAP: usize = 96;

/// A static triangle reaching far into the guard band: one or two vertices at up to 2^13 NDC
/// off screen at small w, the others on screen.
fn guard_band(rng: &mut Rng) -> Triangle {
    let far = |rng: &mut Rng| {
        let w = rng.range(0.001, 0.05);
        let r = rng.range(10.0, 8000.0);
        let a = rng.range(0.0, std::f64::consts::TAU);
        [r * a.cos() * w, r * a.sin() * w, 0.5 * w, w, 0.0]
    };
    let near = |rng: &mut Rng| {
        let w = rng.range(1.0, 3.0);
        let (x, y) = (rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
        [x * w, y * w, 0.5 * w, w, 0.0]
    };
    let v = if rng.below(2) == 0 {
        [far(rng), near(rng), near(rng)]
    } else {
        [far(rng), far(rng), near(rng)]
    };
    tri(v, v)
}

/// Two triangles sharing an edge (opposite directions), every vertex at a pixel corner of `vp`
/// exactly (w = W·H/64, x = w·(2px/W − 1), y = w·(1 − 2py/H): exact raw values that the planar
/// rounding keeps), so edge values of exactly 0 — the fill rule — occur at the corner probes
/// and at sub-pixel 0 samples.
fn grid_pair(rng: &mut Rng, vp: Viewport) -> [Triangle; 2] {
    let (w, h) = (i32::from(vp.width()), i32::from(vp.height()));
    let wr = 1024 * w * h;
    let corner = |rng: &mut Rng| {
        let px = rng.below(w as u64 + 1) as i32;
        let py = rng.below(h as u64 + 1) as i32;
        uvt_core::Vertex {
            x: uvt_core::Coord::from_bits(1024 * h * (2 * px - w)),
            y: uvt_core::Coord::from_bits(1024 * w * (h - 2 * py)),
            z: uvt_core::Coord::from_bits(wr / 2),
            w: uvt_core::Coord::from_bits(wr),
            coc: c(0.0),
        }
    };
    let (a, b, p, q) = (corner(rng), corner(rng), corner(rng), corner(rng));
    [
        Triangle::new_static([a, b, p]).expect("grid triangle"),
        Triangle::new_static([b, a, q]).expect("grid triangle"),
    ]
}

/// A sample pattern (4×4 block, 4 spp) whose sub-pixel offsets are 0 or random per axis.
fn corner_samples(rng: &mut Rng) -> Vec<uvt_core::Sample> {
    let off = |rng: &mut Rng| {
        if rng.below(2) == 0 {
            0
        } else {
            rng.below(256) as u8
        }
    };
    (0..64)
        .map(|_| {
            let (sx, sy) = (off(rng), off(rng));
            uvt_tests::sample_raw(sx, sy, 0, 0, 0)
        })
        .collect()
}

/// What a scene holds, to check that the cases the test is for occurred.
#[derive(Default, Debug)]
struct Mix {
    crossing: usize,
    guard: usize,
    wzero: usize,
    grid: usize,
}

/// A seeded static scene of `n` triangles (or pairs) of every kind (and, every third scene, a
/// mesh).
fn scene(rng: &mut Rng, n: usize, vp: Viewport, mix: &mut Mix) -> Vec<Prim> {
    let kinds = STATIC_KINDS;
    let mut tris = Vec::new();
    for _ in 0..n {
        let t = match rng.below(8) {
            0 | 1 => {
                mix.guard += 1;
                guard_band(rng)
            }
            2 => {
                mix.grid += 1;
                let [a, b] = grid_pair(rng, vp);
                tris.push(a);
                b
            }
            _ => {
                let k = kinds[rng.below(kinds.len() as u64) as usize];
                let t = make_static(k, rng);
                let w = t.vertices(0).map(|v| v.w.to_bits());
                if w.iter().any(|&w| w > 0) && w.iter().any(|&w| w < 0) {
                    mix.crossing += 1;
                }
                if w.contains(&0) {
                    mix.wzero += 1;
                }
                t
            }
        };
        tris.push(t);
    }
    if rng.below(3) == 0 {
        tris.extend(planar_mesh(rng, 4, false, None));
    }
    tris.iter()
        .enumerate()
        .map(|(i, &t)| Prim {
            tri: t,
            color: Rgb888::new((i * 37) as u8, (i * 91) as u8, (i * 13 + 5) as u8),
        })
        .collect()
}

/// Render every screen tile of `vp` with the full unit and the static-specialised renderer at
/// the planar configuration; compare every sample's depth and color and every pixel's covered
/// and written counts, then the frame's covered / written / occluded counts. `Err` names the
/// first difference.
fn compare(prims: &[Prim], vp: Viewport, pat: &SamplePattern<'_>, bt: u8) -> Result<(), String> {
    let mut full = Box::new(
        Renderer::<Laine2011, CAP, PlanarPrecision, Full>::new(Laine2011, vp, prims)
            .map_err(|e| format!("full unit: {e}"))?,
    );
    let mut st = Box::new(
        StaticRenderer::<CAP>::new(Laine2011, vp, prims)
            .map_err(|e| format!("static unit: {e}"))?,
    );
    let clear = Rgb888::new(1, 2, 3);
    let mut fa = Box::new(TileBuffer::<8, 8, 4>::new(clear));
    let mut fb = Box::new(TileBuffer::<8, 8, 4>::new(clear));
    for y0 in (0..vp.height()).step_by(8) {
        for x0 in (0..vp.width()).step_by(8) {
            full.render_tile(x0, y0, pat, bt, clear, &mut fa)
                .map_err(|e| format!("full unit tile ({x0}, {y0}): {e}"))?;
            st.render_tile(x0, y0, pat, bt, clear, &mut fb)
                .map_err(|e| format!("static unit tile ({x0}, {y0}): {e}"))?;
            uvt_tests::tiles::same_tile(&fa, &fb, x0, y0, "static")?;
        }
    }
    uvt_tests::tiles::same_counts(full.stats, st.stats, "static")
}

/// The demo scene's static prims: the static-specialised path (what the static-only planar
/// M4 program runs) renders the checksum and covered counts of the full unit on the same prims.
#[test]
fn demo_prims_render_identically() {
    let full = demo::render::<PlanarPrecision, Full, StaticOnly>().expect("full");
    let st = demo::render::<PlanarPrecision, StaticOnly, StaticOnly>().expect("static");
    assert_eq!(
        st.checksum, full.checksum,
        "checksum: static {:#010x}, full {:#010x}",
        st.checksum, full.checksum
    );
    let key = |s: uvt_core::Stats| (s.samples_covered, s.samples_written, s.samples_occluded);
    assert_eq!(key(st.stats), key(full.stats), "covered/written/occluded");
    // The specialised path really ran: it tests fewer samples than the general one.
    assert!(
        st.stats.samples_tested < full.stats.samples_tested,
        "samples tested: static {}, full {}",
        st.stats.samples_tested,
        full.stats.samples_tested
    );
    let prims = demo::unit_prims::<StaticOnly>().expect("prims");
    let mut rng = Rng(seed());
    let samples = random_samples(&mut rng, 4, 4);
    let pat = SamplePattern::new(4, 4, &samples).expect("pattern");
    let vp = demo::viewport().expect("viewport");
    for bt in [1, 2, 4, 8] {
        if let Err(e) = compare(&prims, vp, &pat, bt) {
            panic!(
                "demo static prims, bounds tile {bt}, UVT_SEED={}: {e}",
                seed()
            );
        }
    }
}

/// Seeded random static scenes (guard band, camera-plane crossers, w = 0 vertices, slivers,
/// domain extremes, meshes with shared edges) in odd viewports and every bounds-tile size.
#[test]
fn seeded_static_scenes_render_identically() {
    let mut rng = Rng(seed());
    let mut mix = Mix::default();
    let n = cases(40, 400);
    for case in 0..n {
        let vp = Viewport::new(8 + rng.below(40) as u16, 8 + rng.below(40) as u16).expect("vp");
        let k = 1 + rng.below(8) as usize;
        let prims = scene(&mut rng, k, vp, &mut mix);
        let samples = if case % 2 == 0 {
            random_samples(&mut rng, 4, 4)
        } else {
            corner_samples(&mut rng)
        };
        let pat = SamplePattern::new(4, 4, &samples).expect("pattern");
        let bt = [1u8, 2, 4, 8][rng.below(4) as usize];
        if let Err(e) = compare(&prims, vp, &pat, bt) {
            let tris: String = prims.iter().map(|p| dump(&p.tri)).collect();
            panic!(
                "case {case}, UVT_SEED={}, viewport {}x{}, bounds tile {bt}: {e}\n{tris}",
                seed(),
                vp.width(),
                vp.height()
            );
        }
    }
    assert!(
        mix.crossing > 0 && mix.guard > 0 && mix.wzero > 0 && mix.grid > 0,
        "the scenes lacked a case: {mix:?}"
    );
}

/// Probe positions of one pixel: its four sub-pixel corners and two seeded ones.
fn probes(rng: &mut Rng, px: u16, py: u16) -> [ScreenPos; 6] {
    let at = |sx: u32, sy: u32| ScreenPos {
        xs: u32::from(px) * 256 + sx,
        ys: u32::from(py) * 256 + sy,
    };
    [
        at(0, 0),
        at(255, 0),
        at(0, 255),
        at(255, 255),
        at(rng.below(256) as u32, rng.below(256) as u32),
        at(rng.below(256) as u32, rng.below(256) as u32),
    ]
}

/// Brute force over whole viewports: at every probed position the static test returns the
/// planar test's result bit for bit (coverage and depth), and a covered position lies inside
/// the static footprint, in a bounds tile (1, 2, 4 and 8) the tile cull keeps.
#[test]
fn static_test_is_the_planar_test_and_nothing_covered_is_culled() {
    let mut rng = Rng(seed());
    let mut mix = Mix::default();
    let mut covered = 0u64;
    // Covered positions on setups whose depth takes the unsaturated path, and the others.
    let mut depth_paths = [0u64; 2];
    let n = cases(6, 60);
    for case in 0..n {
        let vp = Viewport::new(8 + rng.below(30) as u16, 8 + rng.below(30) as u16).expect("vp");
        for p in scene(&mut rng, 6, vp, &mut mix) {
            let t = p.tri;
            let planar = Setup::unculled::<PlanarPrecision>(&t, vp);
            let mut ops = uvt_core::Ops::default();
            let st = static_setup(&t, vp, &mut ops);
            assert_eq!(st.refused(), None, "a static triangle is accepted");
            for py in 0..vp.height() {
                for px in 0..vp.width() {
                    for pos in probes(&mut rng, px, py) {
                        let want = planar::test(&planar, pos, &mut uvt_core::Ops::default());
                        let ctx = || {
                            format!(
                                "case {case}, UVT_SEED={}, viewport {}x{}, position xs {} ys {} \
                                 ({:#x}, {:#x})\n{}",
                                seed(),
                                vp.width(),
                                vp.height(),
                                pos.xs,
                                pos.ys,
                                pos.xs,
                                pos.ys,
                                dump(&t)
                            )
                        };
                        let Outcome::Visible(s) = st else {
                            assert!(want.is_none(), "culled ({st:?}) but covered: {}", ctx());
                            continue;
                        };
                        let got = static_test(&s, pos);
                        assert_eq!(got, want, "static test against planar test: {}", ctx());
                        if want.is_none() {
                            continue;
                        }
                        covered += 1;
                        depth_paths[usize::from(s.depth_unsaturated())] += 1;
                        let f = s.footprint();
                        assert!(
                            (f.x0..f.x1).contains(&px) && (f.y0..f.y1).contains(&py),
                            "covered outside the footprint {f:?}: {}",
                            ctx()
                        );
                        for b in [1u16, 2, 4, 8] {
                            let (cx, cy) = (px - px % b, py - py % b);
                            let cell = PixelRect {
                                x0: cx,
                                y0: cy,
                                x1: (cx + b).min(vp.width()),
                                y1: (cy + b).min(vp.height()),
                            };
                            assert!(
                                static_tile(&s, cell, &mut ops),
                                "tile {cell:?} culled but covered: {}",
                                ctx()
                            );
                        }
                    }
                }
            }
        }
    }
    assert!(covered > 1000, "only {covered} covered positions probed");
    assert!(
        depth_paths.iter().all(|&n| n > 0),
        "covered positions per depth path (saturating, unsaturated): {depth_paths:?}"
    );
    assert!(
        mix.crossing > 0 && mix.guard > 0 && mix.grid > 0,
        "the scenes lacked a case: {mix:?}"
    );
}

/// Only static in-focus triangles: the demo scene's prim 1 (motion) is refused by name, by
/// the renderer and by setup.
#[test]
fn refuses_every_other_class() {
    let prims = demo::prims().expect("prims");
    let vp = demo::viewport().expect("viewport");
    let err = StaticRenderer::<8>::new(Laine2011, vp, &prims).err();
    assert_eq!(
        err,
        Some(Error::ClassNotInUnit {
            index: 1,
            class: Class::Motion,
            unit: "static-only"
        })
    );
    let mut ops = uvt_core::Ops::default();
    let classes: Vec<_> = prims
        .iter()
        .map(|p| static_setup(&p.tri, vp, &mut ops).refused())
        .collect();
    assert_eq!(
        classes,
        [
            None,
            Some(Class::Motion),
            Some(Class::Defocus),
            Some(Class::MotionDefocus),
            Some(Class::MotionDefocus),
            Some(Class::MotionDefocus),
            None
        ]
    );
}

/// The path is chosen by the types: the static-only unit at a planar precision only.
#[test]
fn specialised_only_at_planar_on_the_static_only_unit() {
    use uvt_tests::pipeline_name as name;
    assert_eq!(name::<PlanarPrecision, StaticOnly>(), "StaticRenderer");
    assert_eq!(name::<PlanarPrecision, Full>(), "Renderer");
    assert_eq!(name::<PlanarPrecision, MotionOnly>(), "MotionRenderer");
    assert_eq!(name::<PlanarPrecision, DefocusOnly>(), "Renderer");
    assert_eq!(name::<Bounded<16, 16, 16, 20>, StaticOnly>(), "Renderer");
    assert_eq!(name::<Exact, StaticOnly>(), "Renderer");
}

/// Domain corners: vertex components at 0, ±1 and ±2^29 raw (the checked maximum) in
/// viewports 1×1 … 2048×2048; setup, the tile cull over the whole viewport and its corner
/// cells, and the test at the viewport's corner positions run without overflow (the tests are
/// built with overflow checks) and the test equals the planar test there.
#[test]
fn domain_corners() {
    let vals = [0, 1, -1, 1 << 29, -(1 << 29), (1 << 29) - 1, 12345];
    let mut rng = Rng(seed());
    let vps = [(1, 1), (2048, 2048), (2048, 1), (1, 2048), (37, 5)];
    let mut visible = 0;
    for _ in 0..cases(3000, 30000) {
        let mut v = [uvt_core::Vertex::default(); 3];
        for p in v.iter_mut() {
            let mut pick =
                || uvt_core::Coord::from_bits(vals[rng.below(vals.len() as u64) as usize]);
            *p = uvt_core::Vertex {
                x: pick(),
                y: pick(),
                z: pick(),
                w: pick(),
                coc: c(0.0),
            };
        }
        let t = Triangle::new_static(v).expect("corner triangle in the domain");
        let (w, h) = vps[rng.below(vps.len() as u64) as usize];
        let vp = Viewport::new(w, h).expect("viewport");
        let mut ops = uvt_core::Ops::default();
        let out = static_setup(&t, vp, &mut ops);
        assert_eq!(out.refused(), None, "static");
        let Outcome::Visible(s) = out else {
            continue;
        };
        visible += 1;
        let planar = Setup::unculled::<PlanarPrecision>(&t, vp);
        let (xe, ye) = (u32::from(w) * 256 - 1, u32::from(h) * 256 - 1);
        for (xs, ys) in [(0, 0), (xe, 0), (0, ye), (xe, ye), (xe / 2, ye / 2)] {
            let pos = ScreenPos { xs, ys };
            let want = planar::test(&planar, pos, &mut uvt_core::Ops::default());
            assert_eq!(
                static_test(&s, pos),
                want,
                "viewport {w}x{h}, position ({xs}, {ys}) ({xs:#x}, {ys:#x}), UVT_SEED={}\n{}",
                seed(),
                dump(&t)
            );
        }
        let whole = PixelRect {
            x0: 0,
            y0: 0,
            x1: w,
            y1: h,
        };
        let last = PixelRect {
            x0: w - 1,
            y0: h - 1,
            x1: w,
            y1: h,
        };
        for cell in [whole, last] {
            let _ = static_tile(&s, cell, &mut ops);
        }
    }
    assert!(visible > 100, "only {visible} visible corner triangles");
}
