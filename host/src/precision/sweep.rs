//! `uvt precision`: the same core at several precisions against the f64 reference — run time,
//! operation counts, decision errors, bound slack, STE loss, depth error, conservativeness, and
//! the conservative epsilon — over the benchmark scenes and every bounds-tile size.

use std::time::Duration;

use uvt_core::config::registry::{CONFIGS, DEFAULT};
use uvt_core::{with_config, Laine2011, NoZmax, Precision, Triangle};

use crate::bench::strategy::run_frame;
use crate::config::planar_static;
use crate::frame::opts::RunOpts;
use crate::frame::reference::run_reference;
use crate::scene::builtin::{bench_scene, Bench, Blur};
use crate::scene::file::Scene;
use crate::scene::pattern::Pattern;
use crate::scene::tri::DOMAIN;

use super::measure::{errors, lost_samples, planar_dq};
use super::row::{d_q_px, finish, PrecRow};

/// Which configurations, scenes and rows a sweep covers.
pub struct Sweep {
    /// configurations (registry names, run in the registry's order; others are skipped;
    /// `super::row::CONFIGS` is the default selection)
    pub configs: Vec<&'static str>,
    /// scenes
    pub scenes: Vec<Bench>,
    /// rows
    pub rows: Vec<Blur>,
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
                .all(|v| v.iter().all(|x| x.abs() <= DOMAIN))
        });
    }
    s
}

/// Run the sweep.
pub fn sweep(sw: &Sweep) -> anyhow::Result<Vec<PrecRow>> {
    let mut rows: Vec<PrecRow> = Vec::new();
    let chosen: Vec<_> = CONFIGS
        .iter()
        .filter(|e| sw.configs.contains(&e.name))
        .collect();
    for (n, e) in chosen.iter().enumerate() {
        let cfg = e.name;
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
                crate::log::line(&format!(
                    "precision: row {} of {}: {cfg} {kind:?} {}",
                    n * per + k * sw.rows.len() + r + 1,
                    chosen.len() * per,
                    row.label()
                ));
                let s = shrink(bench_scene(kind, row, true), sw.shrink);
                with_config!(e.config, P => one::<P>(&s, &mut accs)).transpose()?;
            }
        }
        for a in accs.iter_mut() {
            finish(a);
        }
        rows.extend(accs);
    }
    Ok(rows)
}

/// One scene at precision `P` for every tile size of `accs` (each row's `tile`).
fn one<P: Precision + Sync>(s: &Scene, accs: &mut [PrecRow]) -> anyhow::Result<()> {
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
        let (n, stat) = planar_static::degenerate(s);
        crate::log::line(&format!(
            "precision: {}: {n} of {stat} static triangles degenerate after the planar rounding",
            s.name
        ));
    }
    let eps = uvt_core::Eps::of(P::OFFSET_SHIFT, uvt_core::Class::MotionDefocus, vp);
    let e3 = [eps.x()[0], eps.x()[1], eps.w()].map(i32::unsigned_abs);
    for acc in accs.iter_mut() {
        for (a, e) in acc.eps_raw.iter_mut().zip(e3) {
            *a = (*a).max(e);
        }
        if P::PLANAR {
            // Per primitive (`crate::config::planar_static`): the largest over the scenes'
            // primitives with a bound; no single figure at 960×540 (0, shown as "per primitive").
            acc.d_q = [acc.d_q[0].max(planar_dq(s).0), 0.0];
            acc.degenerate += planar_static::degenerate(s).0;
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
        // Time both in the same run, alternating, three times each; keep the medians.
        let mut tf: Vec<Duration> = Vec::new();
        let mut tr: Vec<Duration> = Vec::new();
        let mut last = None;
        for _ in 0..3 {
            let f = run_frame::<_, P, NoZmax>(Laine2011, vp, &core, &pat, &o)?;
            let r = run_reference(&s.tris, &base, &o);
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
    Ok(())
}

/// One stress case at the default precision: STE, decisions against f64, conservativeness.
pub fn stress_row(scene: &Scene) -> anyhow::Result<PrecRow> {
    let mut acc = [PrecRow {
        config: DEFAULT.to_string(),
        tile: scene.tile,
        ..Default::default()
    }];
    one::<uvt_core::DefaultPrecision>(scene, &mut acc)?;
    let [mut row] = acc;
    finish(&mut row);
    row.lost = lost_samples(scene)?.1;
    Ok(row)
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
