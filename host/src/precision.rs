//! `uvt precision`: the same core at several precisions against the f64 reference — run time,
//! operation counts, decision errors, bound slack, STE loss, depth error, conservativeness, and
//! the conservative epsilon — over the benchmark scenes and every bounds-tile size.
//!
//! Per configuration `Prec<POS, TUV, BND>` the scene's exact f64 triangles are rounded to the
//! position grid, the pattern's t/u/v to the t/u/v grid (sub-pixel stays 8 bits), and the core
//! runs at that precision. The reference always runs on the exact values.

use std::time::Duration;

use rayon::prelude::*;
use serde::Serialize;
use uvt_core::bounds::BoundsStrategy;
use uvt_core::{
    sample_test, Laine2011, Ops, Outcome, PixelRect, Prec, Precision, ScreenPos, Setup, Triangle,
};

use crate::compare::{check_sample_eps, eps_of, Rounding};
use crate::frame::{run, Fixed, Reference, RunOpts};
use crate::pattern::Pattern;
use crate::reference;
use crate::scene::Scene;
use crate::scenes::{bench, Bench, Row};

/// The swept configurations (position, t/u/v, bound fraction bits), narrow to the default.
pub const CONFIGS: [(u32, u32, u32); 4] = [(6, 6, 2), (8, 8, 4), (12, 12, 8), (16, 16, 16)];

/// Errors and costs of one configuration at one bounds-tile size, summed over the scenes.
#[derive(Clone, Debug, Default, Serialize, serde::Deserialize)]
#[serde(default)]
pub struct PrecRow {
    /// fraction bits (position, t/u/v, bounds)
    pub config: (u32, u32, u32),
    /// bounds-tile size
    pub tile: u8,
    /// median over frames of (core wall time / reference wall time) in the same run
    pub time_ratio_median: f64,
    /// core operations per setup, per tile, per sample test
    pub ops: [f64; 3],
    /// (triangle, sample) decisions compared
    pub compared: u64,
    /// decisions differing from the reference
    pub differ: u64,
    /// largest distance (px) of a differing sample from the nearest edge
    pub max_differ_px: f64,
    /// differing samples that no input rounding at this precision explains
    /// (`compare::check_sample`; must be 0)
    pub beyond_bound: u64,
    /// largest quantization-check ratio of a differing sample (≤ 1 when `beyond_bound` is 0)
    pub max_ratio: f64,
    /// differing samples of triangles with a vertex at w ≤ 0 at either end of the shutter
    /// (checked like all others)
    pub behind: u64,
    /// bound slack (core width − reference width) mean and max, per axis t, u, v
    pub slack_mean: [f64; 3],
    /// max slack per axis
    pub slack_max: [f64; 3],
    /// STE of the core and of the reference (sums over frames)
    pub ste: [f64; 2],
    /// depth error of samples both cover, in LSBs of the I8F24 depth: max, mean
    pub depth_lsb: [f64; 2],
    /// samples the core covers but its own setup/footprint/bounds exclude (must be 0)
    pub violations: u64,
    /// smallest outward margin on the exact (reference) bounds so that every sample the core
    /// covers is inside, per axis t, u, v
    pub eps_measured: [f64; 3],
    /// samples the core covers outside the reference's footprint or in a tile the reference
    /// skips (no finite t/u/v margin covers these)
    pub eps_outside: u64,
    /// covered samples whose framebuffer slot was still empty and that were not written
    /// (counted by [`lost_samples`], independently of the core's counters; must be 0)
    pub lost: u64,
    #[serde(skip)]
    times: Vec<f64>,
    #[serde(skip)]
    slack_n: u64,
    #[serde(skip)]
    depth_n: u64,
    #[serde(skip)]
    counts: [u64; 5],
}

/// Which scenes and rows a sweep covers.
pub struct Sweep {
    /// scenes
    pub scenes: Vec<Bench>,
    /// rows
    pub rows: Vec<Row>,
    /// tile sizes
    pub tiles: Vec<u8>,
    /// reduce each benchmark scene's resolution by this factor beyond the quick size
    pub shrink: u16,
}

fn shrink(mut s: Scene, f: u16) -> Scene {
    if f > 1 {
        // Crop: keep the centre of the clip-space view by scaling x, y (zoom in) — simpler and
        // exact: a smaller viewport of the same triangles shows a smaller (centre) region.
        s.viewport = (s.viewport.0 / f, s.viewport.1 / f);
        for t in s.tris.iter_mut() {
            for v in t.t0.iter_mut().chain(t.t1.iter_mut()) {
                v[0] *= f as f64;
                v[1] *= f as f64;
                v[4] *= f as f64;
            }
        }
        s.tris.retain(|t| {
            t.t0.iter()
                .chain(t.t1.iter())
                .all(|v| v.iter().all(|x| x.abs() <= crate::scene::DOMAIN))
        });
    }
    s
}

/// Run the sweep.
pub fn sweep(sw: &Sweep) -> Vec<PrecRow> {
    let mut rows: Vec<PrecRow> = Vec::new();
    for (ci, &cfg) in CONFIGS.iter().enumerate() {
        let mut accs: Vec<PrecRow> = sw
            .tiles
            .iter()
            .map(|&tile| PrecRow {
                config: cfg,
                tile,
                ..Default::default()
            })
            .collect();
        for (k, &kind) in sw.scenes.iter().enumerate() {
            for (r, &row) in sw.rows.iter().enumerate() {
                // Progress as plain lines on stderr (readable in logs, not only on a terminal).
                let per = sw.scenes.len() * sw.rows.len();
                eprintln!(
                    "precision: row {} of {}: {}/{}/{} {kind:?} {}",
                    ci * per + k * sw.rows.len() + r + 1,
                    CONFIGS.len() * per,
                    cfg.0,
                    cfg.1,
                    cfg.2,
                    row.label()
                );
                let s = shrink(bench(kind, row, true), sw.shrink);
                match ci {
                    0 => one::<Prec<6, 6, 2>>(&s, &mut accs),
                    1 => one::<Prec<8, 8, 4>>(&s, &mut accs),
                    2 => one::<Prec<12, 12, 8>>(&s, &mut accs),
                    _ => one::<Prec<16, 16, 16>>(&s, &mut accs),
                }
            }
        }
        for a in accs.iter_mut() {
            finish(a);
        }
        rows.extend(accs);
    }
    rows
}

fn finish(a: &mut PrecRow) {
    a.times.sort_by(|x, y| x.total_cmp(y));
    a.time_ratio_median = a.times.get(a.times.len() / 2).copied().unwrap_or(0.0);
    for k in 0..3 {
        a.slack_mean[k] /= a.slack_n.max(1) as f64;
    }
    a.depth_lsb[1] /= a.depth_n.max(1) as f64;
    let [tested, covered, rtested, rcovered, _] = a.counts;
    a.ste = [
        covered as f64 / tested.max(1) as f64,
        rcovered as f64 / rtested.max(1) as f64,
    ];
}

/// One scene at precision `P` for every tile size of `accs` (each row's `tile`).
fn one<P: Precision + Sync>(s: &Scene, accs: &mut [PrecRow]) {
    let base = Pattern::new(s.pattern, s.spp, s.seed);
    let pat = base.with_tuv(P::TUV_FRAC);
    let core: Vec<Triangle> = s
        .tris
        .iter()
        .map(|t| t.to_core_with::<P>().expect("bench scene in the domain"))
        .collect();
    let vp = s.core_viewport();
    let colors = s.colors();
    for acc in accs.iter_mut() {
        let o = RunOpts {
            tile: acc.tile,
            ..RunOpts::for_scene(s, &colors)
        };
        let fixed = Fixed::<_, P> {
            prec: std::marker::PhantomData,
            strat: Laine2011,
            vp,
            tris: &core,
            pattern: &pat,
        };
        // Time both in the same run, alternating, three times each; keep the medians.
        let mut tf: Vec<Duration> = Vec::new();
        let mut tr: Vec<Duration> = Vec::new();
        let mut last = None;
        for _ in 0..3 {
            let f = run(&fixed, &pat, &o);
            let r = run(
                &Reference {
                    vp: s.viewport,
                    tris: &s.tris,
                    pattern: &base,
                },
                &pat,
                &o,
            );
            tf.push(f.time);
            tr.push(r.time);
            last = Some((f, r));
        }
        tf.sort();
        tr.sort();
        acc.times
            .push(tf[1].as_secs_f64() / tr[1].as_secs_f64().max(1e-9));
        let (f, r) = last.expect("ran");
        let per = |a: u64, b: u64| if b == 0 { 0.0 } else { a as f64 / b as f64 };
        let n = acc.times.len() as f64;
        let ops = [
            per(f.stats.ops_setup, f.stats.triangles),
            per(f.stats.ops_bounds, f.stats.tiles_visited),
            per(f.stats.ops_sample, f.stats.samples_tested),
        ];
        for (a, o) in acc.ops.iter_mut().zip(ops) {
            *a += (o - *a) / n;
        }
        acc.counts[0] += f.stats.samples_tested;
        acc.counts[1] += f.stats.samples_covered;
        acc.counts[2] += r.stats.samples_tested;
        acc.counts[3] += r.stats.samples_covered;
    }
    errors::<P>(s, &core, &pat, accs);
}

/// Per-triangle brute force over the union of both footprints: coverage, distance and depth
/// once; bounds slack, violations and epsilon for every tile size of `accs`.
fn errors<P: Precision + Sync>(s: &Scene, core: &[Triangle], pat: &Pattern, accs: &mut [PrecRow]) {
    let vp = s.core_viewport();
    let v = s.viewport;
    let tiles: Vec<u16> = accs.iter().map(|a| a.tile as u16).collect();
    let parts: Vec<Vec<PrecRow>> = s
        .tris
        .par_iter()
        .zip(core.par_iter())
        .map(|(st, ct)| {
            let mut a: Vec<PrecRow> = tiles.iter().map(|_| PrecRow::default()).collect();
            let mut ops = Ops::default();
            let fx = match uvt_core::setup_with::<P>(ct, vp, &mut ops) {
                Outcome::Visible(x) => Some((x, Laine2011.prepare(&x, &mut ops))),
                Outcome::Culled(_) => None,
            };
            let rf = reference::setup::setup(st, v).ok();
            let Some(region) = crate::compare::footprint_union(
                fx.as_ref().map(|x| x.0.footprint()),
                rf.as_ref().map(|x| x.footprint),
            ) else {
                return a;
            };
            // P's own sample test (exact or bounded) and its perturbation in the bound.
            let full = Setup::unculled_with::<P>(ct, vp);
            let eps = eps_of(&full);
            let rounding = Rounding::at(P::POS_FRAC, P::TUV_FRAC);
            let cell_of = |px: u16, py: u16, fp: PixelRect, bt: u16| {
                PixelRect {
                    x0: px - px % bt,
                    y0: py - py % bt,
                    x1: px - px % bt + bt,
                    y1: py - py % bt + bt,
                }
                .intersect(&fp)
            };
            let mut boxes = Vec::with_capacity(tiles.len());
            for py in region.y0..region.y1 {
                for px in region.x0..region.x1 {
                    boxes.clear();
                    for (ti, &bt) in tiles.iter().enumerate() {
                        let fbox = fx.as_ref().and_then(|(x, c)| {
                            x.footprint().contains(px, py).then(|| {
                                Laine2011.tile(x, c, cell_of(px, py, x.footprint(), bt), &mut ops)
                            })
                        });
                        let rbox = rf.as_ref().and_then(|x| {
                            x.footprint.contains(px, py).then(|| {
                                reference::bounds::tile(x, cell_of(px, py, x.footprint, bt))
                            })
                        });
                        // Slack, once per cell (at its top-left pixel inside the region).
                        let first_x = px % bt == 0 || px == region.x0;
                        let first_y = py % bt == 0 || py == region.y0;
                        if let (true, true, Some(Some(fb)), Some(Some(rb))) =
                            (first_x, first_y, fbox, rbox)
                        {
                            let w = [(fb.t, rb.t), (fb.u, rb.u), (fb.v, rb.v)];
                            for (k, (fi, ri)) in w.iter().enumerate() {
                                let d = (fi.hi() - fi.lo()) as f64 / 65536.0 - (ri.1 - ri.0);
                                a[ti].slack_mean[k] += d;
                                a[ti].slack_max[k] = a[ti].slack_max[k].max(d);
                            }
                            a[ti].slack_n += 1;
                        }
                        boxes.push((fbox, rbox));
                    }
                    for si in 0..pat.spp as usize {
                        let idx = pat.index(px, py, si);
                        let (q, e) = (&pat.quant[idx], &pat.exact[idx]);
                        let hf = sample_test(&full, ScreenPos::of(px, py, q), q, &mut ops);
                        let (x, y) = (px as f64 + e[0], py as f64 + e[1]);
                        let hr = reference::sample::sample_test(st, v, x, y, e[2], e[3], e[4]);
                        // Tile-independent measures go into row 0 and are copied when merging.
                        a[0].compared += 1;
                        if hf.is_some() != hr.is_some() {
                            a[0].differ += 1;
                            let d =
                                reference::sample::edge_distance_px(st, v, x, y, e[2], e[3], e[4]);
                            a[0].max_differ_px = a[0].max_differ_px.max(d);
                            let c = check_sample_eps(st, v, x, y, e[2], e[3], e[4], &rounding, eps);
                            a[0].max_ratio = a[0].max_ratio.max(c.ratio);
                            a[0].beyond_bound += u64::from(c.ratio > 1.0);
                            a[0].behind += u64::from(c.behind);
                        }
                        if let (Some(h), Some(z)) = (hf, hr) {
                            if h.depth != uvt_core::formats::DEPTH_FAR && z.abs() < 128.0 {
                                let err = (h.depth as f64 - z * 16777216.0).abs();
                                a[0].depth_lsb[0] = a[0].depth_lsb[0].max(err);
                                a[0].depth_lsb[1] += err;
                                a[0].depth_n += 1;
                            }
                        }
                        if hf.is_none() {
                            continue;
                        }
                        let (u, vv, t) = (q.u().to_bits(), q.v().to_bits(), q.t().to_bits());
                        for (ti, (fbox, rbox)) in boxes.iter().enumerate() {
                            match fbox {
                                Some(Some(b)) if b.contains(u, vv, t) => {}
                                _ => a[ti].violations += 1,
                            }
                            match rbox {
                                Some(Some(rb)) => {
                                    let s3 = [
                                        t as f64 / 65536.0,
                                        u as f64 / 65536.0,
                                        vv as f64 / 65536.0,
                                    ];
                                    let r3 = [rb.t, rb.u, rb.v];
                                    for k in 0..3 {
                                        let out = (r3[k].0 - s3[k]).max(s3[k] - r3[k].1).max(0.0);
                                        a[ti].eps_measured[k] = a[ti].eps_measured[k].max(out);
                                    }
                                }
                                _ => a[ti].eps_outside += 1,
                            }
                        }
                    }
                }
            }
            a
        })
        .collect();
    for part in parts {
        let cov = part[0].clone();
        for (acc, p) in accs.iter_mut().zip(part) {
            acc.compared += cov.compared;
            acc.differ += cov.differ;
            acc.max_differ_px = acc.max_differ_px.max(cov.max_differ_px);
            acc.beyond_bound += cov.beyond_bound;
            acc.max_ratio = acc.max_ratio.max(cov.max_ratio);
            acc.behind += cov.behind;
            acc.depth_lsb[0] = acc.depth_lsb[0].max(cov.depth_lsb[0]);
            acc.depth_lsb[1] += cov.depth_lsb[1];
            acc.depth_n += cov.depth_n;
            for k in 0..3 {
                acc.slack_mean[k] += p.slack_mean[k];
                acc.slack_max[k] = acc.slack_max[k].max(p.slack_max[k]);
                acc.eps_measured[k] = acc.eps_measured[k].max(p.eps_measured[k]);
            }
            acc.slack_n += p.slack_n;
            acc.violations += p.violations;
            acc.eps_outside += p.eps_outside;
        }
    }
}

/// Markdown table of a sweep.
pub fn table_md(rows: &[PrecRow]) -> String {
    let mut s = String::from(
        "| pos/tuv/bnd bits | tile | time ÷ f64 | ops setup/tile/sample | decisions ≠ f64 (rate, max px) | beyond bound (max ratio) | slack t/u/v mean (max) | STE core / f64 | depth err LSB max (mean) | violations | ε t/u/v measured | outside exact bounds | core margin | analytic ε (sample part) |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        s += &format!(
            "| {}/{}/{} | {} | {:.2} | {:.0}/{:.0}/{:.0} | {} ({:.1e}, {:.3}) | {} ({:.2}) | {:.4}/{:.4}/{:.4} ({:.4}/{:.4}/{:.4}) | {:.2}% / {:.2}% | {:.0} ({:.1}) | {} | {:.1e}/{:.1e}/{:.1e} | {} | 2^-{} | 2^-{} |\n",
            r.config.0, r.config.1, r.config.2, r.tile, r.time_ratio_median, r.ops[0], r.ops[1], r.ops[2],
            r.differ, r.differ as f64 / r.compared.max(1) as f64, r.max_differ_px, r.beyond_bound, r.max_ratio,
            r.slack_mean[0], r.slack_mean[1], r.slack_mean[2], r.slack_max[0], r.slack_max[1], r.slack_max[2],
            100.0 * r.ste[0], 100.0 * r.ste[1], r.depth_lsb[0], r.depth_lsb[1], r.violations,
            r.eps_measured[0], r.eps_measured[1], r.eps_measured[2], r.eps_outside, r.config.1, r.config.1 + 1
        );
    }
    s
}

/// One point per configuration (bounds tile 1): x = median time relative to f64, y = rate of
/// decisions differing from f64. Returns the indices on the Pareto front (no other point is
/// both faster and more accurate).
pub fn pareto(points: &[(f64, f64)]) -> Vec<usize> {
    (0..points.len())
        .filter(|&i| {
            !points.iter().enumerate().any(|(j, q)| {
                j != i
                    && q.0 <= points[i].0
                    && q.1 <= points[i].1
                    && (q.0 < points[i].0 || q.1 < points[i].1)
            })
        })
        .collect()
}

/// SVG plot of error against run time, Pareto front marked.
pub fn plot_svg(rows: &[PrecRow], path: &std::path::Path) -> anyhow::Result<()> {
    use plotters::prelude::*;
    let pts: Vec<((u32, u32, u32), f64, f64)> = rows
        .iter()
        .filter(|r| r.tile == 1)
        .map(|r| {
            (
                r.config,
                r.time_ratio_median,
                (r.differ as f64 / r.compared.max(1) as f64).max(1e-9),
            )
        })
        .collect();
    let front = pareto(&pts.iter().map(|p| (p.1, p.2)).collect::<Vec<_>>());
    let xmax = pts.iter().map(|p| p.1).fold(0.0, f64::max) * 1.2 + 0.1;
    let (ymin, ymax) = pts
        .iter()
        .fold((f64::MAX, 0.0f64), |(a, b), p| (a.min(p.2), b.max(p.2)));
    let root = SVGBackend::new(path, (720, 480)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| anyhow::anyhow!("{e}"))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "uvt precision: error against run time (bounds tile 1)",
            ("sans-serif", 18),
        )
        .margin(16)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..xmax, (ymin / 2.0..ymax * 2.0).log_scale())
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    chart
        .configure_mesh()
        .x_desc("median wall time per frame / f64 reference")
        .y_desc("sample decisions differing from f64 (rate)")
        .y_label_formatter(&|y| format!("{y:.0e}"))
        .draw()
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    let mut fp: Vec<(f64, f64)> = front.iter().map(|&i| (pts[i].1, pts[i].2)).collect();
    fp.sort_by(|a, b| a.0.total_cmp(&b.0));
    chart
        .draw_series(LineSeries::new(fp, &RED))
        .map_err(|e| anyhow::anyhow!("{e}"))?
        .label("Pareto front");
    chart
        .draw_series(pts.iter().enumerate().map(|(i, p)| {
            let style = if front.contains(&i) {
                RED.filled()
            } else {
                BLUE.filled()
            };
            EmptyElement::at((p.1, p.2))
                + Circle::new((0, 0), 5, style)
                + Text::new(
                    format!("{}/{}/{}", p.0 .0, p.0 .1, p.0 .2),
                    if i % 2 == 0 { (8, -16) } else { (-64, 6) },
                    ("sans-serif", 13),
                )
        }))
        .map_err(|e| anyhow::anyhow!("{e}"))?;
    root.present().map_err(|e| anyhow::anyhow!("{e}"))?;
    Ok(())
}

/// One stress case at the default precision: STE, decisions against f64, conservativeness.
pub fn stress_row(scene: &Scene) -> PrecRow {
    let mut acc = [PrecRow {
        config: (16, 16, 16),
        tile: scene.tile,
        ..Default::default()
    }];
    one::<uvt_core::DefaultPrecision>(scene, &mut acc);
    let [mut row] = acc;
    finish(&mut row);
    row.lost = lost_samples(scene).1;
    row
}

/// Covered samples that reach an empty framebuffer slot, and of those the ones not written:
/// `(reached_empty, lost)`. Counted independently of the core's counters: every pixel gets its
/// own cleared core `TileBuffer`; the triangles run in submission order over every sample of
/// their footprint (no bounds: coverage is the sample test's alone); a covered sample whose slot
/// still holds the clear value (depth and color) must afterwards hold its depth and color.
pub fn lost_samples(scene: &Scene) -> (u64, u64) {
    let pat = Pattern::new(scene.pattern, scene.spp, scene.seed);
    let vp = scene.core_viewport();
    let mut ops = Ops::default();
    let setups: Vec<Setup> = scene
        .tris
        .iter()
        .map(|t| t.to_core().expect("loaded scene is in the domain"))
        .filter_map(|t| match uvt_core::setup(&t, vp, &mut ops) {
            Outcome::Visible(s) => Some(s),
            Outcome::Culled(_) => None,
        })
        .collect();
    let black = uvt_core::Rgb888::new(0, 0, 0);
    let white = uvt_core::Rgb888::new(255, 255, 255);
    let spp = usize::from(pat.spp);
    (0..vp.height())
        .into_par_iter()
        .map(|py| {
            let (mut reached, mut lost) = (0u64, 0u64);
            let mut fb = uvt_core::TileBuffer::<1, 1, 64>::new(black);
            let mut ops = Ops::default();
            for px in 0..vp.width() {
                fb.clear(black);
                for s in setups.iter().filter(|s| s.footprint().contains(px, py)) {
                    for si in 0..spp {
                        let q = &pat.quant[pat.index(px, py, si)];
                        let pos = ScreenPos::of(px, py, q);
                        let Some(h) = uvt_core::sample_test(s, pos, q, &mut ops) else {
                            continue;
                        };
                        let empty = fb.depth(0, 0, si) == Some(uvt_core::formats::DEPTH_EMPTY)
                            && fb.sample_color(0, 0, si) == Some(black);
                        let _ = fb.write(0, 0, si, white, h.depth);
                        if empty {
                            reached += 1;
                            let written = fb.depth(0, 0, si) == Some(h.depth)
                                && fb.sample_color(0, 0, si) == Some(white);
                            lost += u64::from(!written);
                        }
                    }
                }
            }
            (reached, lost)
        })
        .reduce(|| (0, 0), |a, b| (a.0 + b.0, a.1 + b.1))
}

/// The core's decisions at precision `P` (triangles `core`, table `pat` quantized to `P`) against
/// the f64 reference on every footprint sample, with the quantization distance at `P` and the
/// conservativeness check at the scene's tile size (used by `uvt render --precision`).
pub fn decisions<P: Precision + Sync>(scene: &Scene, core: &[Triangle], pat: &Pattern) -> PrecRow {
    let mut acc = [PrecRow {
        tile: scene.tile,
        ..Default::default()
    }];
    errors::<P>(scene, core, pat, &mut acc);
    let [mut row] = acc;
    finish(&mut row);
    row
}

/// Markdown table of stress cases.
pub fn stress_md(rows: &[(String, usize, PrecRow)]) -> String {
    let mut s = String::from("| case | triangles | STE core / f64 | decisions ≠ f64 (rate) | of which w ≤ 0 | max distance px | beyond bound (max ratio) | depth err LSB max | violations | covered but not written |
|---|---|---|---|---|---|---|---|---|---|
");
    for (name, n, r) in rows {
        s += &format!(
            "| {name} | {n} | {:.2}% / {:.2}% | {} ({:.1e}) | {} | {:.2e} | {} ({:.2}) | {:.0} | {} | {} |
",
            100.0 * r.ste[0],
            100.0 * r.ste[1],
            r.differ,
            r.differ as f64 / r.compared.max(1) as f64,
            r.behind,
            r.max_differ_px,
            r.beyond_bound,
            r.max_ratio,
            r.depth_lsb[0],
            r.violations,
            r.lost
        );
    }
    s
}

/// Load every scene of a stress folder (sorted by name).
pub fn stress_scenes(dir: &std::path::Path) -> anyhow::Result<Vec<Scene>> {
    use anyhow::Context;
    let mut paths: Vec<_> = std::fs::read_dir(dir)
        .with_context(|| format!("cannot read stress folder {}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    paths.sort();
    paths.iter().map(|p| Scene::load(p)).collect()
}
