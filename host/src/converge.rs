//! `uvt converge`: image error against run time. Renders a scene with every bounds strategy at
//! 1, 2, 4, 8, 16, 32 and 64 spp and reports the RMSE of the resolved image against a high-spp
//! f64 reference (the f64 pipeline at 64 spp with `REF_FRAMES` independent sample tables,
//! averaged), beside the core's wall time and its number of sample tests; writes
//! `converge.md`, `converge.json` and a log-log plot `converge.svg` (error against time, one
//! curve per strategy). Bounds never change coverage, so at equal spp every strategy has the
//! same image and error: the curves differ only in how much work that error costs.

use std::path::{Path, PathBuf};

use anyhow::{anyhow, Result};
use serde::Serialize;
use uvt_core::bounds::registry::{hull_edge, hull_lens, STRATEGIES};
use uvt_core::bounds::strategy::BoundsStrategy;

use crate::bench::strategy::{run_strategy_image, StratResult};
use crate::frame::opts::RunOpts;
use crate::frame::reference::run_reference;
use crate::scene::file::Scene;
use crate::scene::pattern::Pattern;

/// Sample counts of the sweep.
pub const SPP_STEPS: [u16; 7] = [1, 2, 4, 8, 16, 32, 64];

/// Strategies of the sweep: every strategy of the registry
/// ([`uvt_core::bounds::registry::STRATEGIES`], in its order) but the hull compositions
/// `hull+lens-t` and `hull+edge-t` (one curve per colour of the plot: six).
pub fn strategies() -> impl Iterator<Item = &'static str> + Clone {
    let left_out = [hull_lens().name(), hull_edge().name()];
    STRATEGIES
        .into_iter()
        .filter(move |n| !left_out.contains(n))
}
/// Independent 64-spp f64 frames averaged into the reference (256 spp in all).
pub const REF_FRAMES: u64 = 4;

/// One point of the sweep.
#[derive(Clone, Debug, Serialize)]
pub struct Point {
    /// strategy
    pub strategy: &'static str,
    /// samples per pixel
    pub spp: u16,
    /// RMSE of the resolved 8-bit RGB image against the reference (0..255 units)
    pub rmse: f64,
    /// core wall ms (median of the repeats)
    pub ms: f64,
    /// sample tests
    pub tested: u64,
    /// samples covered
    pub covered: u64,
    /// whole modelled Cortex-M4F instructions of the frame, setup included (its counts times
    /// the strategy's per-call figures pooled over the bench rows,
    /// [`crate::bench::m4_stages::M4Stages::pooled`]); `None` for a strategy the stage harness
    /// does not measure (the bounding-box scan, not a bench strategy)
    pub m4: Option<f64>,
}

/// Run the sweep on `scene` (its own pattern kind and seed; the viewport, tile and colors as in
/// the scene). `repeats` ≥ 1 frames per point, the median time is kept.
pub fn sweep(scene: &Scene, repeats: usize) -> Result<Vec<Point>> {
    let colors = scene.colors();
    let core = scene.core_tris()?;
    let vp = scene.core_viewport();
    let base = RunOpts {
        image: true,
        ..RunOpts::for_scene(scene, &colors)
    };
    let (w, h) = (scene.viewport.0 as usize, scene.viewport.1 as usize);
    let mut reference = vec![[0.0f64; 3]; w * h];
    for k in 0..REF_FRAMES {
        let pat = Pattern::new(scene.pattern, 64, scene.seed ^ (0x05ee_df64 + k));
        let f = run_reference(
            &scene.tris,
            &pat,
            &RunOpts {
                spp: 64,
                ..base.clone()
            },
        );
        for (acc, px) in reference.iter_mut().zip(&f.image) {
            for c in 0..3 {
                acc[c] += px[c] as f64 / REF_FRAMES as f64;
            }
        }
    }
    let stages = crate::bench::m4_stages::committed()?;
    let mut out = Vec::new();
    for spp in SPP_STEPS {
        let pat = Pattern::new(scene.pattern, spp, scene.seed);
        let o = RunOpts {
            spp,
            ..base.clone()
        };
        for name in strategies() {
            let mut runs: Vec<(StratResult, Vec<[u8; 3]>)> = Vec::new();
            for _ in 0..repeats.max(1) {
                let (r, img) = run_strategy_image(name, vp, &core, &pat, &o)?;
                runs.push((r, img));
            }
            runs.sort_by(|a, b| a.0.ms.total_cmp(&b.0.ms));
            let (r, img) = &runs[runs.len() / 2];
            let se: f64 = img
                .iter()
                .zip(&reference)
                .map(|(p, q)| (0..3).map(|c| (p[c] as f64 - q[c]).powi(2)).sum::<f64>())
                .sum();
            out.push(Point {
                strategy: name,
                spp,
                rmse: (se / (3 * w * h) as f64).sqrt(),
                ms: r.ms,
                tested: r.stats.samples_tested,
                covered: r.stats.samples_covered,
                m4: stages.pooled(name).map(|c| {
                    c.total(
                        r.stats.triangles,
                        r.stats.tiles_visited,
                        r.stats.samples_admitted,
                        r.stats.samples_tested,
                    )
                }),
            });
        }
    }
    Ok(out)
}

/// The sweep as a Markdown table: one row per spp, per strategy ms / sample tests / whole
/// Cortex-M4F instructions (millions, setup included).
pub fn table_md(points: &[Point]) -> String {
    let mut s = String::from("| spp | RMSE (0..255) |");
    for n in strategies() {
        s += &format!(" {n} ms / tests / M4 Minsn |");
    }
    s += "\n|---|---|";
    s += &"---|".repeat(strategies().count());
    s += "\n";
    for spp in SPP_STEPS {
        let row: Vec<&Point> = points.iter().filter(|p| p.spp == spp).collect();
        let Some(first) = row.first() else { continue };
        s += &format!("| {spp} | {:.3} |", first.rmse);
        for n in strategies() {
            if let Some(p) = row.iter().find(|p| p.strategy == n) {
                let m4 = p.m4.map_or("–".to_string(), |m| format!("{:.1}", m / 1e6));
                s += &format!(" {:.0} / {} / {m4} |", p.ms, p.tested);
            }
        }
        s += "\n";
    }
    s
}

/// Log-log plot of RMSE against core wall time, one curve per strategy.
pub fn plot_svg(points: &[Point], title: &str, path: &Path) -> Result<()> {
    use plotters::prelude::*;
    let e = |e: &dyn std::fmt::Display| anyhow!("plot {}: {e}", path.display());
    let (tmin, tmax) = points
        .iter()
        .fold((f64::MAX, 0.0f64), |(a, b), p| (a.min(p.ms), b.max(p.ms)));
    let (emin, emax) = points.iter().fold((f64::MAX, 0.0f64), |(a, b), p| {
        (a.min(p.rmse), b.max(p.rmse))
    });
    let root = SVGBackend::new(path, (760, 500)).into_drawing_area();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 18))
        .margin(16)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(
            (tmin.max(1e-3) / 1.5..tmax * 1.5).log_scale(),
            (emin.max(1e-3) / 1.3..emax * 1.3).log_scale(),
        )
        .map_err(|x| e(&x))?;
    chart
        .configure_mesh()
        .x_desc("core wall time per frame, ms (log)")
        .y_desc("RMSE vs f64 reference, 0..255 (log)")
        .draw()
        .map_err(|x| e(&x))?;
    let colors = [BLACK, BLUE, RED, GREEN, MAGENTA, CYAN];
    for (n, c) in strategies().zip(colors) {
        let pts: Vec<(f64, f64)> = points
            .iter()
            .filter(|p| p.strategy == n)
            .map(|p| (p.ms.max(1e-3), p.rmse.max(1e-3)))
            .collect();
        chart
            .draw_series(LineSeries::new(pts.clone(), c.stroke_width(2)))
            .map_err(|x| e(&x))?
            .label(n)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], c));
        chart
            .draw_series(pts.iter().map(|&p| Circle::new(p, 3, c.filled())))
            .map_err(|x| e(&x))?;
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(|x| e(&x))?;
    root.present().map_err(|x| e(&x))?;
    Ok(())
}

/// Write `converge.md`, `converge.json`, `converge.svg` into `out`; returns the paths.
pub fn write(points: &[Point], scene: &Scene, out: &Path) -> Result<Vec<PathBuf>> {
    std::fs::create_dir_all(out).map_err(|x| anyhow!("creating {}: {x}", out.display()))?;
    let md = out.join("converge.md");
    let json = out.join("converge.json");
    let svg = out.join("converge.svg");
    let head = format!(
        "# uvt converge — {} ({}×{}, {} triangles, bounds tile {})\n\nReference: f64 pipeline, {} independent 64-spp frames averaged. Same image for every strategy at equal spp; times are the core's wall time on this machine; M4 Minsn = whole modelled Cortex-M4F instructions of the frame in millions, setup included (the frame's counts times each strategy's instructions per call on the bench rows' own triangles, `host/report/m4_strategies.json`).\n\n",
        scene.name,
        scene.viewport.0,
        scene.viewport.1,
        scene.tris.len(),
        scene.tile,
        REF_FRAMES
    );
    let write = |p: &Path, s: String| {
        std::fs::write(p, s).map_err(|x| anyhow!("writing {}: {x}", p.display()))
    };
    write(&md, head + &table_md(points))?;
    write(&json, serde_json::to_string_pretty(points)? + "\n")?;
    plot_svg(
        points,
        &format!("uvt converge: {} — error against time", scene.name),
        &svg,
    )?;
    Ok(vec![md, json, svg])
}
