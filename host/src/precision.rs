//! `uvt precision`: the same core at several precisions against the f64 reference — run time,
//! operation counts, decision errors, bound slack, STE loss, depth error, conservativeness, and
//! the conservative epsilon — over the benchmark scenes and every bounds-tile size.
//!
//! Per configuration of [`CONFIGS`] (`exact-P-T-B` = `Prec<P, T, B>`, the exact sample test;
//! `bounded-P-T-B-O` = `Bounded<P, T, B, O>`, the hardware-width test of `core/src/bounded.rs`)
//! the scene's exact f64 triangles are rounded to the position grid, the pattern's t/u/v to the
//! t/u/v grid (sub-pixel stays 8 bits), and the core runs at that precision. The reference always
//! runs on the exact values.
//!
//! **d_q** (the documented distance within which a decision may differ because of the bounded
//! datapath's rounding): the bounded test is exact on vertices perturbed by at most
//! `k/2 + 2^(O−1)/(256·E)` raw in x (E = W) and y (E = H) and `1/2` raw in w (`bounded.rs`,
//! class both: k = 3). A vertex in view (|x/w| ≤ 1) at depth w therefore moves on screen by at
//! most `(k/2 + 1/2 + 2^(O−1)/(256·E))·E/(2^17·w)` px = `(2E + 2^(O−9))/(2^17·w)` px; d_q is its
//! maximum over the two axes at w = 1 (0 for the exact test). It covers the datapath's rounding
//! only: the inputs' rounding to the position and t/u/v grids adds its own (bounded per sample
//! by `compare.rs`'s rigorous check, which here includes the perturbation as an extra position
//! rounding). *beyond d_q* counts differing decisions of triangles with every w ≥ 1 that lie
//! farther than d_q (at the scene's viewport) from an edge.

use std::time::Duration;

use rayon::prelude::*;
use serde::Serialize;
use uvt_core::bounds::strategy::BoundsStrategy;
use uvt_core::{
    sample_test, Bounded, Laine2011, Ops, Outcome, PixelRect, Prec, Precision, ScreenPos, Setup,
    Triangle,
};

use crate::compare::{check_sample_eps, eps_of, Rounding};
use crate::frame::{run, Fixed, Reference, RunOpts};
use crate::pattern::Pattern;
use crate::reference;
use crate::scene::Scene;
use crate::scenes::{bench, Bench, Row};

/// The swept configurations (session names, `crate::cost::SWEEP`): exact, then bounded from the
/// default candidate down to the narrowest; then the planar static configuration
/// (`crate::planar::NAME`).
pub const CONFIGS: [&str; 8] = {
    let s = crate::cost::SWEEP;
    [
        s[0],
        s[1],
        s[2],
        s[3],
        s[4],
        s[5],
        s[6],
        crate::planar::NAME,
    ]
};

/// Run `one::<P>` for configuration `ci` of [`CONFIGS`].
fn one_at(ci: usize, s: &Scene, accs: &mut [PrecRow]) {
    match ci {
        0 => one::<Prec<16, 16, 16>>(s, accs),
        1 => one::<Bounded<16, 16, 16, 20>>(s, accs),
        2 => one::<Bounded<16, 16, 16, 22>>(s, accs),
        3 => one::<Bounded<16, 16, 16, 24>>(s, accs),
        4 => one::<Bounded<12, 12, 12, 24>>(s, accs),
        5 => one::<Bounded<12, 12, 12, 26>>(s, accs),
        6 => one::<Bounded<8, 8, 8, 28>>(s, accs),
        _ => one::<uvt_core::PlanarPrecision>(s, accs),
    }
}

/// The documented d_q (module docs) of offset shift `off` on a `w`×`h` viewport, px at w = 1.
pub fn d_q_px(off: Option<u32>, w: u16, h: u16) -> f64 {
    let Some(o) = off else { return 0.0 };
    let at = |e: f64| (2.0 * e + 2f64.powi(o as i32 - 9)) / 131072.0;
    at(w as f64).max(at(h as f64))
}

/// Errors and costs of one configuration at one bounds-tile size, summed over the scenes.
#[derive(Clone, Debug, Default, Serialize, serde::Deserialize)]
#[serde(default)]
pub struct PrecRow {
    /// configuration name (`exact-16-16-16`, `bounded-16-16-16-20`, …); an old report's
    /// `[POS, TUV, BND]` reads as `exact-POS-TUV-BND` (the exact test in the wide containers)
    #[serde(deserialize_with = "config_name")]
    pub config: String,
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
    /// the analytic conservative epsilon (class both, largest over the scenes' viewports): ε_x,
    /// ε_y, ε_w raw clip units
    pub eps_raw: [u32; 3],
    /// documented d_q (px at w = 1) at the scenes' viewports (largest) and at 960×540
    pub d_q: [f64; 2],
    /// differing decisions of triangles with every w ≥ 1 farther than d_q from an edge (the
    /// planar configuration: of triangles with a per-primitive d_q, farther than it)
    pub beyond_dq: u64,
    /// triangles the configuration culls as degenerate that the default does not (the planar
    /// configuration's vertex rounding: `crate::planar::degenerate`)
    pub degenerate: u64,
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

/// A configuration name, or an old report's `[POS, TUV, BND]` as `exact-POS-TUV-BND`.
fn config_name<'de, D: serde::Deserializer<'de>>(d: D) -> Result<String, D::Error> {
    use serde::Deserialize;
    match serde_json::Value::deserialize(d)? {
        serde_json::Value::String(s) => Ok(s),
        serde_json::Value::Array(a) if a.len() == 3 && a.iter().all(|x| x.is_u64()) => {
            Ok(format!("exact-{}-{}-{}", a[0], a[1], a[2]))
        }
        v => Err(serde::de::Error::custom(format!(
            "config: expected a name or [POS, TUV, BND], found {v}"
        ))),
    }
}

/// Which configurations, scenes and rows a sweep covers.
pub struct Sweep {
    /// configurations (names of [`CONFIGS`]; others are skipped)
    pub configs: Vec<&'static str>,
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
    let chosen: Vec<(usize, &str)> = CONFIGS
        .iter()
        .enumerate()
        .filter(|(_, c)| sw.configs.contains(c))
        .map(|(i, c)| (i, *c))
        .collect();
    for (n, &(ci, cfg)) in chosen.iter().enumerate() {
        let mut accs: Vec<PrecRow> = sw
            .tiles
            .iter()
            .map(|&tile| PrecRow {
                config: cfg.to_string(),
                tile,
                ..Default::default()
            })
            .collect();
        for (k, &kind) in sw.scenes.iter().enumerate() {
            for (r, &row) in sw.rows.iter().enumerate() {
                // Progress as plain lines on stderr (readable in logs, not only on a terminal).
                let per = sw.scenes.len() * sw.rows.len();
                eprintln!(
                    "precision: row {} of {}: {cfg} {kind:?} {}",
                    n * per + k * sw.rows.len() + r + 1,
                    chosen.len() * per,
                    row.label()
                );
                let s = shrink(bench(kind, row, true), sw.shrink);
                one_at(ci, &s, &mut accs);
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
    if P::PLANAR {
        let (n, stat) = crate::planar::degenerate(s);
        eprintln!(
            "precision: {}: {n} of {stat} static triangles degenerate after the planar rounding",
            s.name
        );
    }
    let eps = uvt_core::Eps::of(P::OFFSET_SHIFT, uvt_core::Class::MotionDefocus, vp);
    let e3 = [eps.x()[0], eps.x()[1], eps.w()].map(i32::unsigned_abs);
    for acc in accs.iter_mut() {
        for (a, e) in acc.eps_raw.iter_mut().zip(e3) {
            *a = (*a).max(e);
        }
        if P::PLANAR {
            // Per primitive (`crate::planar`): the largest over the scenes' primitives with a
            // bound; no single figure at 960×540 (0, shown as "per primitive").
            acc.d_q = [acc.d_q[0].max(planar_dq(s).0), 0.0];
            acc.degenerate += crate::planar::degenerate(s).0;
        } else {
            acc.d_q = [
                acc.d_q[0].max(d_q_px(P::OFFSET_SHIFT, s.viewport.0, s.viewport.1)),
                d_q_px(P::OFFSET_SHIFT, 960, 540),
            ];
        }
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
    errors::<P>(s, &core, &pat, accs, 1.0);
}

/// Per-triangle brute force over the union of both footprints: coverage, distance and depth
/// once; bounds slack, violations and epsilon for every tile size of `accs`.
///
/// `dq_scale` scales the planar configuration's per-primitive d_q (1 in every report; tests
/// halve it to show that a measured difference beyond it is caught).
fn errors<P: Precision + Sync>(
    s: &Scene,
    core: &[Triangle],
    pat: &Pattern,
    accs: &mut [PrecRow],
    dq_scale: f64,
) {
    let vp = s.core_viewport();
    let v = s.viewport;
    let tiles: Vec<u16> = accs.iter().map(|a| a.tile as u16).collect();
    let prim_dq = if P::PLANAR {
        planar_dq(s).1
    } else {
        Vec::new()
    };
    let parts: Vec<Vec<PrecRow>> = s
        .tris
        .par_iter()
        .zip(core.par_iter())
        .enumerate()
        .map(|(i, (st, ct))| {
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
            // The planar configuration: the primitive's own d_q (none: not counted); otherwise
            // the configuration's d_q at w = 1 for triangles with every w ≥ 1.
            let (d_q, front) = if P::PLANAR {
                match prim_dq.get(i).copied().flatten() {
                    Some(d) => (d * dq_scale, true),
                    None => (0.0, false),
                }
            } else {
                (
                    d_q_px(P::OFFSET_SHIFT, v.0, v.1),
                    st.t0.iter().chain(st.t1.iter()).all(|q| q[3] >= 1.0),
                )
            };
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
                            a[0].beyond_dq += u64::from(front && d > d_q);
                            let c = check_sample_eps(st, v, x, y, e[2], e[3], e[4], &rounding, eps);
                            a[0].max_ratio = a[0].max_ratio.max(c.ratio);
                            a[0].beyond_bound += u64::from(c.ratio > 1.0);
                            a[0].behind += u64::from(c.behind);
                        }
                        if let (Some(h), Some(z)) = (hf, hr) {
                            if h.depth != uvt_core::config::formats::DEPTH_FAR && z.abs() < 128.0 {
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
            acc.beyond_dq += cov.beyond_dq;
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

/// The planar configuration's d_q per primitive of `s` (`crate::planar::prim_dq`; `None`: no
/// screen-space bound) and the largest of them.
pub fn planar_dq(s: &Scene) -> (f64, Vec<Option<f64>>) {
    let v: Vec<Option<f64>> = s
        .tris
        .iter()
        .map(|t| {
            let c = t.to_core().ok()?;
            let class = c.class();
            crate::planar::prim_dq(t, &c, class, s.viewport, 1.0)
        })
        .collect();
    let m = v.iter().flatten().fold(0.0f64, |a, &b| a.max(b));
    (m, v)
}

/// Markdown table of a sweep, with the costs of each configuration (`crate::precision_cost`).
pub fn table_md(rows: &[PrecRow], costs: &crate::precision_cost::Costs) -> String {
    let mut s = String::from(
        "| configuration | tile | decisions ≠ f64 (rate, max px) | d_q px (scene / 960×540) | beyond d_q (w ≥ 1; planar: per primitive) | degenerate after rounding | beyond bound (max ratio) | violations | ε x/y/w raw | STE core / f64 | STE loss vs exact | depth err LSB max (mean) | time ÷ f64 | host ns setup/tile/sample | M4F insn setup/tile/sample | sample test DSP48E1 / MULT18X18D (model) | sample test Σ bit-products | synthesized |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let exact = rows
            .iter()
            .find(|x| x.config == CONFIGS[0] && x.tile == r.tile);
        let loss = exact
            .map(|x| {
                format!(
                    "{:.2}%",
                    100.0 * (x.ste[0] - r.ste[0]) / x.ste[0].max(1e-12)
                )
            })
            .unwrap_or_else(|| "–".into());
        let c = costs.of(&r.config);
        s += &format!(
            "| {} | {} | {} ({:.1e}, {:.4}) | {:.4} / {} | {} | {} | {} ({:.2}) | {} | {}/{}/{} | {:.2}% / {:.2}% | {loss} | {:.0} ({:.1}) | {:.2} | {} | {} | {} | {} | {} |\n",
            r.config, r.tile, r.differ, r.differ as f64 / r.compared.max(1) as f64, r.max_differ_px,
            r.d_q[0], if r.config == crate::planar::NAME { "per primitive".to_string() } else { format!("{:.4}", r.d_q[1]) }, r.beyond_dq, r.degenerate, r.beyond_bound, r.max_ratio, r.violations,
            r.eps_raw[0], r.eps_raw[1], r.eps_raw[2], 100.0 * r.ste[0], 100.0 * r.ste[1],
            r.depth_lsb[0], r.depth_lsb[1], r.time_ratio_median,
            c.host_ns, c.m4, c.dsp, c.bit_products, c.synth
        );
    }
    s += &costs.notes();
    s
}

/// Indices of the Pareto front of `points` (x = cost, y = error; lower is better in both): no
/// other point is at most as costly and at most as wrong, and better in one.
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

/// One stress case at the default precision: STE, decisions against f64, conservativeness.
pub fn stress_row(scene: &Scene) -> PrecRow {
    let mut acc = [PrecRow {
        config: CONFIGS[1].to_string(),
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
                        let empty = fb.depth(0, 0, si)
                            == Some(uvt_core::config::formats::DEPTH_EMPTY)
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
    errors::<P>(scene, core, pat, &mut acc, 1.0);
    let [mut row] = acc;
    finish(&mut row);
    row
}

/// [`decisions`] at the planar static configuration with its per-primitive d_q scaled by
/// `dq_scale` (1: the documented d_q; `beyond_dq` counts the differing decisions of primitives
/// with a d_q farther than the scaled d_q from the nearest edge), and the degenerate count.
pub fn planar_decisions(scene: &Scene, dq_scale: f64) -> anyhow::Result<PrecRow> {
    type P = uvt_core::PlanarPrecision;
    let (core, pat) = crate::fit_confirm::inputs::<P>(scene)?;
    let mut acc = [PrecRow {
        config: crate::planar::NAME.to_string(),
        tile: scene.tile,
        d_q: [planar_dq(scene).0, 0.0],
        degenerate: crate::planar::degenerate(scene).0,
        ..Default::default()
    }];
    errors::<P>(scene, &core, &pat, &mut acc, dq_scale);
    let [mut row] = acc;
    finish(&mut row);
    Ok(row)
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
