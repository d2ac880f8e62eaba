//! Unit variants (`uvt_core::config::unit`): each variant renders every primitive list it accepts
//! bit-identically to the full unit at the same precision — every sample's colour and depth, every
//! pixel's counters and the renderer's `Stats` (operation counts included) — with every strategy
//! of the registry (`STRATEGIES`) at every configuration of the registry (`CONFIGS`) on the demo
//! scene and seeded random triangles, and with Laine 2011 at the default, exact and planar
//! configurations on the large scenes. Scenes: the built-in benchmark scenes (quick
//! size) and the default scene of `host/src/scene/builtin.rs`, the demo scene, and seeded random
//! triangles per class (`UVT_SEED`; more in `UVT_EXTENSIVE=1` mode), each filtered to the classes
//! the variant accepts. And a primitive a variant cannot handle is refused with
//! `Error::ClassNotInUnit` naming index, class and unit.

use embedded_graphics_core::pixelcolor::RgbColor;
use uvt_core::bounds::any::AnyStrategy;
use uvt_core::bounds::registry::STRATEGIES;
use uvt_core::config::registry::{Config, CONFIGS, DEFAULT, EXACT, PLANAR};
use uvt_core::input::SamplePattern;
use uvt_core::{
    with_config, BoundsStrategy, DefaultPrecision, DefocusOnly, Error, Exact, Full, General,
    Laine2011, MotionOnly, PixelStats, PlanarPrecision, Precision, Prim, Raster, Renderer, Rgb888,
    Select, StaticOnly, Stats, TileBuffer, Triangle, Unit, Viewport,
};
use uvt_demo as demo;
use uvt_host::scene::builtin::{self, Bench, Blur};
use uvt_host::scene::file::Scene;
use uvt_host::scene::pattern::Pattern;
use uvt_tests::{snap_samples, snap_tri};
/// Most visible triangles a test scene has (the quick game scenes have ≈ 2 600).
const CAP: usize = 4096;
/// Everything a render produces: per sample (colour, depth) in tile-walk order, per pixel
/// counters, and the renderer's counters.
#[derive(PartialEq, Eq)]
struct Out {
    samples: Vec<([u8; 3], i32)>,
    pixels: Vec<PixelStats>,
    stats: Stats,
}
/// Render `prims` with the general pipeline on unit `U` at precision `P` with strategy `strat`
/// (the unit's missing effects compiled out; `Renderer` itself runs the static-only and
/// motion-only units' own pipelines at planar and bounded precisions, `static_unit.rs` and
/// `motion_unit.rs`), 8×8 screen tiles, reading every sample of every tile back.
fn render<B: BoundsStrategy, P: Precision, U: Unit, const S: usize>(
    strat: B,
    prims: &[Prim],
    vp: Viewport,
    pat: &SamplePattern<'_>,
    bt: u8,
) -> Result<Out, Error> {
    let mut r = Box::new(Raster::<General<B, P, U>, CAP>::new(strat, vp, prims)?);
    let clear = Rgb888::new(7, 8, 9);
    let mut fb = Box::new(TileBuffer::<8, 8, S>::new(clear));
    let mut out = Out {
        samples: Vec::new(),
        pixels: Vec::new(),
        stats: Stats::default(),
    };
    for y0 in (0..vp.height()).step_by(8) {
        for x0 in (0..vp.width()).step_by(8) {
            r.render_tile(x0, y0, pat, bt, clear, &mut fb)?;
            for ty in 0..8 {
                for tx in 0..8 {
                    out.pixels.push(fb.pixel_stats(tx, ty));
                    for s in 0..S {
                        let c = fb.sample_color(tx, ty, s).unwrap_or(clear);
                        let d = fb.depth(tx, ty, s).unwrap_or(0);
                        out.samples.push(([c.r(), c.g(), c.b()], d));
                    }
                }
            }
        }
    }
    out.stats = r.stats;
    Ok(out)
}

/// `prims` filtered to the classes `U` accepts.
fn accepted<U: Unit>(prims: &[Prim]) -> Vec<Prim> {
    prims
        .iter()
        .filter(|p| U::accepts(p.tri.class()))
        .copied()
        .collect()
}

/// The variant `U` against `Full` at precision `P` with strategy `strat` on the prims `U`
/// accepts. Returns how many prims were compared.
fn same_as_full<B: BoundsStrategy + Copy, P: Precision, U: Unit, const S: usize>(
    strat: B,
    what: &str,
    prims: &[Prim],
    vp: Viewport,
    pat: &SamplePattern<'_>,
    bt: u8,
) -> usize {
    let mine = accepted::<U>(prims);
    let ctx = format!(
        "{what}: unit {} vs full at {} with {} ({} of {} prims; UVT_SEED={})",
        U::NAME,
        Config::of::<P>(),
        strat.name(),
        mine.len(),
        prims.len(),
        uvt_tests::seed()
    );
    let want = render::<B, P, Full, S>(strat, &mine, vp, pat, bt)
        .unwrap_or_else(|e| panic!("{ctx}: full: {e}"));
    let got =
        render::<B, P, U, S>(strat, &mine, vp, pat, bt).unwrap_or_else(|e| panic!("{ctx}: {e}"));
    if let Some(i) = (0..want.samples.len()).find(|&i| want.samples.get(i) != got.samples.get(i)) {
        let (wc, wd) = want.samples[i];
        let (gc, gd) = got.samples.get(i).copied().unwrap_or(([0; 3], 0));
        panic!(
            "{ctx}: sample {i} (tile-walk order, {S} per pixel) differs: expected colour {wc:?} depth {wd} ({wd:#010x}), observed colour {gc:?} depth {gd} ({gd:#010x})"
        );
    }
    if let Some(i) = (0..want.pixels.len()).find(|&i| want.pixels.get(i) != got.pixels.get(i)) {
        panic!(
            "{ctx}: pixel counters {i} differ: expected {:?}, observed {:?}",
            want.pixels[i],
            got.pixels.get(i)
        );
    }
    assert_eq!(
        want.stats, got.stats,
        "{ctx}: renderer counters differ (expected full's, observed the variant's)"
    );
    assert_eq!(want.samples.len(), got.samples.len(), "{ctx}: sample count");
    mine.len()
}

/// Every variant against `Full` with strategy `strat` at precision `P`; the prims compared per
/// variant (motion-only, defocus-only, static-only).
fn variants_at<B: BoundsStrategy + Copy, P: Precision, const S: usize>(
    strat: B,
    what: &str,
    prims: &[Prim],
    vp: Viewport,
    pat: &SamplePattern<'_>,
    bt: u8,
) -> [usize; 3] {
    [
        same_as_full::<B, P, MotionOnly, S>(strat, what, prims, vp, pat, bt),
        same_as_full::<B, P, DefocusOnly, S>(strat, what, prims, vp, pat, bt),
        same_as_full::<B, P, StaticOnly, S>(strat, what, prims, vp, pat, bt),
    ]
}

/// Every variant against `Full` at every configuration of the registry (`CONFIGS`; the table
/// snapped to each one's t/u/v grid, the triangles to its position grid) with every strategy
/// of the registry (`STRATEGIES`, as `AnyStrategy`) when `every` — else, for the large scenes,
/// with Laine 2011 at the default, exact and planar configurations; returns the prims compared
/// per variant at the default configuration.
fn all_variants<const S: usize>(
    what: &str,
    prims: &[Prim],
    vp: Viewport,
    pat: &SamplePattern<'_>,
    bt: u8,
    every: bool,
) -> [usize; 3] {
    let mut n = [0; 3];
    let chosen = |c: &Config| every || [DEFAULT, EXACT, PLANAR].contains(c);
    for e in CONFIGS.iter().filter(|e| chosen(&e.config)) {
        let k = with_config!(e.config, P => {
            let snapped: Vec<Prim> = prims
                .iter()
                .map(|p| Prim { tri: snap_tri::<P>(&p.tri), ..*p })
                .collect();
            let table: Vec<_> = (0..pat.block() as usize * pat.block() as usize)
                .flat_map(|px| {
                    let (x, y) = ((px % pat.block() as usize) as u16, (px / pat.block() as usize) as u16);
                    pat.pixel(x, y).to_vec()
                })
                .collect();
            let samples = snap_samples::<P>(&table);
            let sp = SamplePattern::new_with::<P>(pat.block(), pat.spp(), &samples)
                .expect("snapped table");
            let what = format!("{what} at {}", e.name);
            if every {
                let mut k = [0; 3];
                for name in STRATEGIES {
                    let s = AnyStrategy::named(name).expect("a registry strategy");
                    k = variants_at::<_, P, S>(s, &what, &snapped, vp, &sp, bt);
                }
                k
            } else {
                variants_at::<_, P, S>(Laine2011, &what, &snapped, vp, &sp, bt)
            }
        })
        .expect("a registry configuration");
        if e.config == DEFAULT {
            n = k;
        }
    }
    n
}

fn scene_prims(scene: &Scene) -> Vec<Prim> {
    let tris = scene.core_tris().expect("built-in scene converts");
    tris.iter()
        .zip(scene.colors())
        .map(|(t, c)| Prim {
            tri: *t,
            color: Rgb888::new(c[0], c[1], c[2]),
        })
        .collect()
}

fn check_scene(scene: &Scene) -> [usize; 3] {
    let prims = scene_prims(scene);
    let pattern = Pattern::new(scene.pattern, scene.spp, scene.seed);
    let pat = pattern.core();
    let vp = scene.core_viewport();
    match scene.spp {
        16 => all_variants::<16>(&scene.name, &prims, vp, &pat, scene.tile, false),
        4 => all_variants::<4>(&scene.name, &prims, vp, &pat, scene.tile, false),
        other => panic!("{}: spp {other} not instantiated", scene.name),
    }
}

/// Large renderers live on a thread with a big stack (the `heapless` setup list is built on
/// the stack before it is boxed).
fn big_stack(f: impl FnOnce() + Send + 'static) {
    std::thread::Builder::new()
        .stack_size(256 << 20)
        .spawn(f)
        .expect("spawn")
        .join()
        .unwrap_or_else(|e| std::panic::resume_unwind(e));
}

/// The game scene's static, motion and defocus rows, ×1 and ×2 (quick size). Its "both" rows
/// and the default scene (a panning camera with a thin lens) are all motion + defocus: no
/// narrower unit accepts any of their triangles.
#[test]
fn builtin_scenes_render_identically_on_every_accepting_unit() {
    big_stack(|| {
        for row in [
            Blur::Static,
            Blur::Motion,
            Blur::Motion2,
            Blur::Defocus,
            Blur::Defocus2,
        ] {
            let scene = builtin::bench_scene(Bench::Game, row, true);
            let n = check_scene(&scene);
            // Each row is one class: the matching variants see every triangle, the others none.
            let t = scene.tris.len();
            let want = match row {
                Blur::Static => [t, t, t],
                Blur::Motion | Blur::Motion2 => [t, 0, 0],
                _ => [0, t, 0],
            };
            assert_eq!(
                n, want,
                "{}: prims per variant (motion-only, defocus-only, static-only)",
                scene.name
            );
        }
        let scene = builtin::default_scene();
        assert!(
            scene_prims(&scene)
                .iter()
                .all(|p| p.tri.class() == uvt_core::Class::MotionDefocus),
            "the default scene is no longer all motion + defocus: add it to the comparison"
        );
    });
}

/// The demo scene (`uvt_core::demo`), its prims filtered per variant.
#[test]
fn demo_scene_renders_identically_on_every_accepting_unit() {
    big_stack(|| {
        let prims = demo::prims().unwrap();
        let pat = SamplePattern::new(4, 4, &demo::SAMPLES).unwrap();
        let n = all_variants::<4>(
            "demo",
            &prims,
            demo::viewport().unwrap(),
            &pat,
            demo::BOUNDS_TILE,
            true,
        );
        // prims: 0 static, 1 motion, 2 defocus, 3–5 both, 6 static (culled)
        assert_eq!(
            n,
            [3, 3, 2],
            "demo prims per variant (motion-only, defocus-only, static-only)"
        );
    });
}

/// Seeded random triangles of every class (kinds 0–5 of `builtin::random_tri`: static,
/// motion, defocus, both, camera-plane crossing, huge), filtered per variant.
#[test]
fn random_triangles_render_identically_on_every_accepting_unit() {
    big_stack(|| {
        let seed = uvt_tests::seed();
        let mut rng = uvt_tests::Rng(seed ^ 0x7a21);
        let vp = Viewport::new(40, 24).unwrap();
        let pattern = Pattern::new(uvt_host::scene::pattern::PatternKind::Random, 4, seed);
        let pat = pattern.core();
        let mut totals = [0usize; 3];
        for case in 0..uvt_tests::cases(6, 60) {
            let prims: Vec<Prim> = (0..24)
                .map(|i| {
                    let kind = (i % 6) as u32;
                    let t = builtin::random_tri(&mut rng, kind)
                        .to_core()
                        .expect("random triangle in the domain");
                    Prim {
                        tri: t,
                        color: Rgb888::new(40 * kind as u8, 255 - i as u8, (case * 31) as u8),
                    }
                })
                .collect();
            let bt = [1u8, 2, 4, 8][case as usize % 4];
            let n = all_variants::<4>(
                &format!("random case {case} (bounds tile {bt})"),
                &prims,
                vp,
                &pat,
                bt,
                true,
            );
            for (t, k) in totals.iter_mut().zip(n) {
                *t += k;
            }
        }
        assert!(
            totals.iter().all(|&k| k > 0),
            "some variant compared no random triangle: {totals:?}"
        );
    });
}

fn moving() -> Triangle {
    let [a, b, c] = demo::prims().unwrap()[0].tri.vertices(0);
    let mut moved = [a, b, c];
    moved[2].x = uvt_core::Coord::from_bits(moved[2].x.to_bits() + 1);
    Triangle::new([a, b, c], moved).unwrap()
}

fn defocused() -> Triangle {
    let mut v = demo::prims().unwrap()[0].tri.vertices(0);
    v[1].coc = uvt_core::Coord::from_bits(1);
    Triangle::new_static(v).unwrap()
}

/// One moving triangle (one raw LSB of one x) in a static-only renderer and one defocused
/// triangle (CoC of one raw LSB) in a motion-only renderer are refused, naming index, class
/// and unit; the full unit renders both.
#[test]
fn a_class_outside_the_unit_is_refused() {
    let vp = demo::viewport().unwrap();
    let still = demo::prims().unwrap()[0];
    let prims = [
        still,
        Prim {
            tri: moving(),
            color: still.color,
        },
    ];
    let err =
        Renderer::<Laine2011, 4, DefaultPrecision, StaticOnly>::new(Laine2011, vp, &prims).err();
    let want = Error::ClassNotInUnit {
        index: 1,
        class: uvt_core::Class::Motion,
        unit: "static-only",
    };
    assert_eq!(err, Some(want));
    assert_eq!(
        want.to_string(),
        "primitive 1: class motion is not accepted by the static-only unit"
    );
    let prims = [
        Prim {
            tri: defocused(),
            color: still.color,
        },
        still,
    ];
    let err = Renderer::<Laine2011, 4, Exact, MotionOnly>::new(Laine2011, vp, &prims).err();
    assert_eq!(
        err,
        Some(Error::ClassNotInUnit {
            index: 0,
            class: uvt_core::Class::Defocus,
            unit: "motion-only",
        })
    );
    assert!(Renderer::<Laine2011, 4, DefaultPrecision, Full>::new(Laine2011, vp, &prims).is_ok());
    assert!(
        Renderer::<Laine2011, 4, DefaultPrecision, DefocusOnly>::new(Laine2011, vp, &prims).is_ok()
    );
}

/// The demo scene: prim 0 static, 1 motion, 2 defocus, 3–5 motion + defocus, 6 static
/// (culled). On every precision kind — where `Renderer` runs the general pipeline and where it
/// runs a unit's own (static-only at planar, motion-only at bounded and planar) — each unit
/// refuses the first prim it cannot handle, naming index, class and unit, before any setup.
#[test]
fn renderer_refuses_the_first_class_outside_the_unit() {
    fn at<P>()
    where
        (P, Full): Select<Laine2011>,
        (P, MotionOnly): Select<Laine2011>,
        (P, DefocusOnly): Select<Laine2011>,
        (P, StaticOnly): Select<Laine2011>,
    {
        let prims = demo::prims().unwrap();
        let vp = demo::viewport().unwrap();
        let err = |e: Error| (e, e.to_string());
        let st = Renderer::<Laine2011, 8, P, StaticOnly>::new(Laine2011, vp, &prims);
        let mo = Renderer::<Laine2011, 8, P, MotionOnly>::new(Laine2011, vp, &prims);
        let de = Renderer::<Laine2011, 8, P, DefocusOnly>::new(Laine2011, vp, &prims);
        let full = Renderer::<Laine2011, 8, P, Full>::new(Laine2011, vp, &prims);
        assert!(full.is_ok());
        let cases = [
            (
                st.err(),
                1,
                uvt_core::Class::Motion,
                "static-only",
                "primitive 1: class motion is not accepted by the static-only unit",
            ),
            (
                mo.err(),
                2,
                uvt_core::Class::Defocus,
                "motion-only",
                "primitive 2: class defocus is not accepted by the motion-only unit",
            ),
            (
                de.err(),
                1,
                uvt_core::Class::Motion,
                "defocus-only",
                "primitive 1: class motion is not accepted by the defocus-only unit",
            ),
        ];
        for (got, index, class, unit, msg) in cases {
            let want = Error::ClassNotInUnit { index, class, unit };
            assert_eq!(got.map(err), Some((want, msg.to_string())), "unit {unit}");
        }
    }
    at::<DefaultPrecision>();
    at::<Exact>();
    at::<PlanarPrecision>();
}
