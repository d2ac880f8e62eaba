//! Shared helpers for uvt's integration tests: float-to-fixed builders (test side only), a seeded
//! RNG, random sample tables, and the brute-force checkers for conservativeness and
//! watertightness. Failures are reported as strings with the inputs in decimal and raw hex.

pub mod ffi;
pub mod icarus;
pub mod kinds;
pub mod tiles;

use uvt_core::bounds::strategy::{BoundsStrategy, TileBounds};
use uvt_core::config::unit::Full;
use uvt_core::{
    Coord, Lens, Outcome, PixelRect, Sample, SamplePattern, ScreenPos, Setup, Stats, SubPixel,
    Time, Triangle, Vertex, Viewport,
};

pub use uvt_testkit::{cases, extensive, seed, Rng, EXTENSIVE_VAR, SEED_VAR};
// The one seeded RNG and its switches (`UVT_SEED`, `UVT_EXTENSIVE`), shared with the core's
// unit tests.

/// I16F16 from f64, rounded to nearest and clamped to the declared domain.
pub fn c(v: f64) -> Coord {
    let lim = (1i64 << 29) as f64;
    Coord::from_bits((v * 65536.0).round().clamp(-lim, lim) as i32)
}

/// A vertex from f64 clip coordinates and CoC.
pub fn vtx(x: f64, y: f64, z: f64, w: f64, coc: f64) -> Vertex {
    Vertex {
        x: c(x),
        y: c(y),
        z: c(z),
        w: c(w),
        coc: c(coc),
    }
}

/// A triangle from two f64 vertex arrays `[x, y, z, w, coc]`.
pub fn tri(t0: [[f64; 5]; 3], t1: [[f64; 5]; 3]) -> Triangle {
    let mk = |a: [f64; 5]| vtx(a[0], a[1], a[2], a[3], a[4]);
    Triangle::new(t0.map(mk), t1.map(mk)).expect("test triangle inside the domain")
}

/// Raw dump of a triangle, decimal and hex, for failure messages.
pub fn dump(t: &Triangle) -> String {
    let mut s = String::new();
    for time in 0..2 {
        for (k, v) in t.vertices(time).iter().enumerate() {
            let b = v.bits();
            s += &format!(
                "  t{time} v{k}: x {:.6} y {:.6} z {:.6} w {:.6} c {:.6}  raw [{:#010x} {:#010x} {:#010x} {:#010x} {:#010x}]\n",
                v.x.to_num::<f64>(), v.y.to_num::<f64>(), v.z.to_num::<f64>(), v.w.to_num::<f64>(),
                v.coc.to_num::<f64>(), b[0], b[1], b[2], b[3], b[4]
            );
        }
    }
    s
}

/// A sample from raw bits (sub-pixel x, y; u, v, t), through the checked `Sample::new`; panics
/// (test helper) naming the value if it is outside the domain.
pub fn sample_raw(sx: u8, sy: u8, u: i32, v: i32, t: i32) -> Sample {
    Sample::new(
        SubPixel::from_bits(sx),
        SubPixel::from_bits(sy),
        Lens::from_bits(u),
        Lens::from_bits(v),
        Time::from_bits(t),
    )
    .unwrap_or_else(|e| panic!("test sample ({sx}, {sy}, {u}, {v}, {t}): {e}"))
}

/// A random sample table (block × block pixels × spp), quantized to the core's formats.
pub fn random_samples(rng: &mut Rng, block: u16, spp: u16) -> Vec<Sample> {
    (0..block as usize * block as usize * spp as usize)
        .map(|_| {
            sample_raw(
                rng.below(256) as u8,
                rng.below(256) as u8,
                rng.below(2 * 65536 + 1) as i32 - 65536,
                rng.below(2 * 65536 + 1) as i32 - 65536,
                rng.below(65537) as i32,
            )
        })
        .collect()
}

/// A sample table on a coarse grid (sub-pixel 0 or 1/2, u/v/t on quarters) that lands samples
/// exactly on edges and vertices of meshes built on a matching grid.
pub fn grid_samples(rng: &mut Rng, block: u16, spp: u16) -> Vec<Sample> {
    let q = |rng: &mut Rng, lo: i32| {
        Lens::from_bits(lo + rng.below(5) as i32 * 16384 * if lo < 0 { 2 } else { 1 })
    };
    (0..block as usize * block as usize * spp as usize)
        .map(|_| {
            let sx = if rng.below(2) == 0 { 0 } else { 128 };
            let sy = if rng.below(2) == 0 { 0 } else { 128 };
            let (u, v, t) = (q(rng, -65536), q(rng, -65536), q(rng, 0));
            sample_raw(sx, sy, u.to_bits(), v.to_bits(), t.to_bits())
        })
        .collect()
}

/// The 2 × 2-pixel, 8-spp table of the conservativeness tests for a pattern seed: every third
/// seed the coarse grid of [`grid_samples`] (samples exactly on edges and vertices), else random.
pub fn mixed_samples(pat_seed: u64) -> Vec<Sample> {
    let mut rng = Rng(pat_seed);
    if pat_seed % 3 == 0 {
        grid_samples(&mut rng, 2, 8)
    } else {
        random_samples(&mut rng, 2, 8)
    }
}

/// Describe a sample for failure messages.
pub fn dump_sample(px: u16, py: u16, s: &Sample) -> String {
    format!(
        "pixel ({px},{py}) sx {} sy {} u {:.6} ({:#x}) v {:.6} ({:#x}) t {:.6} ({:#x})",
        s.sx().to_bits(),
        s.sy().to_bits(),
        s.u().to_num::<f64>(),
        s.u().to_bits(),
        s.v().to_num::<f64>(),
        s.v().to_bits(),
        s.t().to_num::<f64>(),
        s.t().to_bits()
    )
}

/// Brute-force conservativeness check of one triangle for one bounds strategy and tile size:
/// every sample of the viewport that the sample test covers must be (1) in a non-culled
/// triangle, (2) inside the footprint, and (3) inside its bounds tile's (u, v, t) intervals.
/// Returns the number of covered samples, or a description of the first violation.
pub fn check_conservative<B: BoundsStrategy>(
    strat: &B,
    t: &Triangle,
    vp: Viewport,
    pat: &SamplePattern<'_>,
    bt: u16,
) -> Result<u64, String> {
    check_conservative_with::<B, uvt_core::DefaultPrecision>(strat, t, vp, pat, bt)
}

/// [`check_conservative`] at precision `P` (triangle and samples must be on `P`'s grids).
pub fn check_conservative_with<B: BoundsStrategy, P: uvt_core::Precision>(
    strat: &B,
    t: &Triangle,
    vp: Viewport,
    pat: &SamplePattern<'_>,
    bt: u16,
) -> Result<u64, String> {
    check_conservative_scaled::<B, P>(strat, t, vp, pat, bt, (1, 1))
}

/// [`check_conservative_with`] with the bounded test's conservative epsilon scaled by
/// `scale = (num, den)` ≤ 1 (`uvt_core::setup_scaled`; measurement of the smallest margin).
pub fn check_conservative_scaled<B: BoundsStrategy, P: uvt_core::Precision>(
    strat: &B,
    t: &Triangle,
    vp: Viewport,
    pat: &SamplePattern<'_>,
    bt: u16,
    scale: (u32, u32),
) -> Result<u64, String> {
    let mut ops = Default::default();
    let full = Setup::unculled::<P>(t, vp);
    let out = uvt_core::setup_scaled::<P>(t, vp, scale.0, scale.1, &mut ops);
    let visible = match out {
        Outcome::Visible(s) => Some((s, strat.prepare::<Full>(&s, &mut ops))),
        Outcome::Culled(_) | Outcome::Refused(_) => None,
    };
    let mut covered = 0;
    for py in 0..vp.height() {
        for px in 0..vp.width() {
            // The bounds tile containing this pixel, clipped to the footprint (as the renderer).
            let tile_box = visible.as_ref().map(|(s, co)| {
                let cell = PixelRect {
                    x0: px - px % bt,
                    y0: py - py % bt,
                    x1: px - px % bt + bt,
                    y1: py - py % bt + bt,
                }
                .intersect(&s.footprint());
                (
                    s.footprint().contains(px, py),
                    if cell.is_empty() {
                        None
                    } else {
                        // Row → span → tile, as the renderer walks (`uvt_core::walk_tiles`).
                        let row = PixelRect {
                            x0: s.footprint().x0,
                            x1: s.footprint().x1,
                            ..cell
                        };
                        let span = strat.row_span(s, co, row, bt, &mut ops);
                        if span.admits(&cell) {
                            strat.span_tile::<uvt_core::Full>(s, co, &span, cell, &mut ops)
                        } else {
                            None
                        }
                    },
                )
            });
            for (si, smp) in pat.pixel(px, py).iter().enumerate() {
                let hit = uvt_core::sample::test::<P, uvt_core::Full>(
                    &full,
                    ScreenPos::of(px, py, smp),
                    smp,
                    &mut ops,
                );
                if hit.is_none() {
                    continue;
                }
                covered += 1;
                let why = match &tile_box {
                    None => Some(format!("setup culled it ({out:?})")),
                    Some((false, _)) => Some("pixel outside the footprint".to_string()),
                    Some((true, None)) => Some(format!("{}x{bt} tile bounds empty", bt)),
                    Some((true, Some(b))) => (!b.admits(
                        smp.u().to_bits(),
                        smp.v().to_bits(),
                        smp.t().to_bits(),
                        &mut ops,
                    ))
                    .then(|| format!("outside tile bounds {b:?}")),
                };
                if let Some(why) = why {
                    let fp = visible.as_ref().map(|(s, _)| s.footprint());
                    return Err(format!(
                        "conservativeness violated ({}, tile {bt}): {why}\n  sample {si}: {}\n  footprint {fp:?}\n  viewport {}x{}\n{}",
                        strat.name(), dump_sample(px, py, smp), vp.width(), vp.height(), dump(t)
                    ));
                }
            }
        }
    }
    Ok(covered)
}

/// [`check_conservative_with`] for every strategy of the registry
/// (`uvt_core::bounds::registry::STRATEGIES`, each as `AnyStrategy`: its own code) at precision
/// `P`: the covered samples (the same for every strategy), or the first violation.
pub fn check_every_strategy<P: uvt_core::Precision>(
    t: &Triangle,
    vp: Viewport,
    pat: &SamplePattern<'_>,
    bt: u16,
) -> Result<u64, String> {
    let mut covered = 0;
    for name in uvt_core::bounds::registry::STRATEGIES {
        let s = uvt_core::bounds::any::AnyStrategy::named(name)
            .ok_or_else(|| format!("{name}: not in the registry"))?;
        covered = check_conservative_with::<_, P>(&s, t, vp, pat, bt)?;
    }
    Ok(covered)
}

/// Count, for every sample of the viewport, how many of `tris` cover it with `P`'s sample test
/// (exact or bounded; no bounds involved).
pub fn coverage_counts_with<P: uvt_core::Precision>(
    tris: &[Triangle],
    vp: Viewport,
    pat: &SamplePattern<'_>,
) -> Vec<u8> {
    let setups: Vec<Setup> = tris.iter().map(|t| Setup::unculled::<P>(t, vp)).collect();
    let mut ops = Default::default();
    let mut out = Vec::new();
    for py in 0..vp.height() {
        for px in 0..vp.width() {
            for smp in pat.pixel(px, py) {
                let pos = ScreenPos::of(px, py, smp);
                out.push(
                    setups
                        .iter()
                        .filter(|s| {
                            uvt_core::sample::test::<P, uvt_core::Full>(s, pos, smp, &mut ops)
                                .is_some()
                        })
                        .count() as u8,
                );
            }
        }
    }
    out
}

/// A planar mesh covering far more than the screen at every (t, u, v): a jittered grid of
/// `g×g` vertices on a tilted plane in front of the camera, moved at t = 1 by a small rotation,
/// translation and depth scale, with CoC = a·w + b per vertex (`coc = None`: in focus).
/// Shared vertices are bit-identical in every triangle that uses them.
pub fn planar_mesh(
    rng: &mut Rng,
    g: usize,
    motion: bool,
    coc: Option<(f64, f64)>,
) -> Vec<Triangle> {
    let span = 3.6;
    let step = span / (g - 1) as f64;
    let w0 = rng.range(1.0, 4.0);
    let (ax, ay) = (rng.range(-0.15, 0.15), rng.range(-0.15, 0.15));
    let (rot, tx, ty, sz) = if motion {
        (
            rng.range(-0.08, 0.08),
            rng.range(-0.1, 0.1) * w0,
            rng.range(-0.1, 0.1) * w0,
            rng.range(0.9, 1.1),
        )
    } else {
        (0.0, 0.0, 0.0, 1.0)
    };
    let mut verts = Vec::new();
    for j in 0..g {
        for i in 0..g {
            let jx = rng.range(-0.1, 0.1) * step;
            let jy = rng.range(-0.1, 0.1) * step;
            let (nx, ny) = (
                -span / 2.0 + i as f64 * step + jx,
                -span / 2.0 + j as f64 * step + jy,
            );
            let w = w0 * (1.0 + ax * nx + ay * ny);
            let (x, y, z) = (nx * w, ny * w, 0.5 * w);
            let (cr, sr) = (rot.cos(), rot.sin());
            let (x1, y1, w1) = (cr * x - sr * y + tx, sr * x + cr * y + ty, w * sz);
            let cc = |w: f64| coc.map_or(0.0, |(a, b)| a * w + b);
            verts.push(([x, y, z, w, cc(w)], [x1, y1, 0.5 * w1, w1, cc(w1)]));
        }
    }
    let mut tris = Vec::new();
    for j in 0..g - 1 {
        for i in 0..g - 1 {
            let id = |a: usize, b: usize| verts[b * g + a];
            let (a, b, cq, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            // alternate the diagonal so both shared-edge directions occur
            let quads = if (i + j) % 2 == 0 {
                [[a, b, cq], [a, cq, d]]
            } else {
                [[a, b, d], [b, cq, d]]
            };
            for q in quads {
                tris.push(tri(
                    q.map(|v| v.0),
                    q.map(|v| if motion || coc.is_some() { v.1 } else { v.0 }),
                ));
            }
        }
    }
    tris
}

/// STE of one strategy over a triangle list rendered with the real render loop, at the exact
/// configuration (`Exact`): the tighter strategies (hull, lens slabs, surfaces) do not carry
/// the bounded test's epsilon yet and fall back to Laine's box at a `Bounded` precision (the
/// default), so their gains are measured on the exact test.
pub fn render_stats<B: BoundsStrategy>(
    strat: B,
    prims: &[uvt_core::Prim],
    vp: Viewport,
    pat: &SamplePattern<'_>,
    bt: u8,
) -> Stats {
    let mut r = Box::new(
        uvt_core::Renderer::<B, 16, uvt_core::Exact>::new(strat, vp, prims)
            .expect("setup (at most 16 visible triangles)"),
    );
    match pat.spp() {
        4 => r.render_with::<8, 8, 4>(pat, bt, uvt_core::Rgb888::new(0, 0, 0), |_, _, _, _| {}),
        16 => r.render_with::<8, 8, 16>(pat, bt, uvt_core::Rgb888::new(0, 0, 0), |_, _, _, _| {}),
        other => panic!("render_stats: spp {other} not instantiated"),
    }
    .expect("render");
    r.stats
}

/// Round a triangle's coordinates to nearest on `P`'s position grid.
pub fn snap_tri<P: uvt_core::Precision>(t: &Triangle) -> Triangle {
    let step = 1i64 << (16 - P::POS_FRAC);
    let q = |c: Coord| {
        Coord::from_bits(
            (((c.to_bits() as i64 + step / 2).div_euclid(step)) * step).clamp(-(1 << 29), 1 << 29)
                as i32,
        )
    };
    let v = |x: Vertex| Vertex {
        x: q(x.x),
        y: q(x.y),
        z: q(x.z),
        w: q(x.w),
        coc: q(x.coc),
    };
    Triangle::new_with::<P>(t.vertices(0).map(v), t.vertices(1).map(v))
        .expect("snapped triangle on the grid")
}

/// Round samples' t, u, v to nearest on `P`'s grid.
pub fn snap_samples<P: uvt_core::Precision>(s: &[Sample]) -> Vec<Sample> {
    let step = 1i32 << (16 - P::TUV_FRAC);
    let q = |x: Lens, lo: i32| {
        Lens::from_bits((((x.to_bits() + step / 2).div_euclid(step)) * step).clamp(lo, 65536))
    };
    s.iter()
        .map(|x| {
            sample_raw(
                x.sx().to_bits(),
                x.sy().to_bits(),
                q(x.u(), -65536).to_bits(),
                q(x.v(), -65536).to_bits(),
                q(x.t(), 0).to_bits(),
            )
        })
        .collect()
}

/// The name of the pipeline `uvt_core::units::select` picks for precision `P` on unit `U`
/// (`Renderer`: the general one; `StaticRenderer`, `MotionRenderer`: the units' own).
pub fn pipeline_name<P, U>() -> &'static str
where
    (P, U): uvt_core::Select<uvt_core::Laine2011>,
{
    <uvt_core::PipelineOf<uvt_core::Laine2011, P, U> as uvt_core::Pipeline>::NAME
}
