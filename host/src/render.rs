//! `uvt render`: one scene with the core (Laine bounds and the bounding-box scan) and with the f64
//! reference; PNGs, a Markdown and a JSON report. Files are written to temporary names and
//! renamed, so a failed run leaves no half-written output.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use serde_json::json;
use uvt_core::{BboxScan, Laine2011};

use crate::compare::{compare, CoverageDiff};
use crate::frame::{run, Fixed, Frame, FrameStats, Reference, RunOpts};
use crate::pattern::Pattern;
use crate::scene::Scene;

/// Results of `uvt render`.
pub struct Rendered {
    /// the core with Laine 2011 bounds
    pub fixed: Frame,
    /// the f64 reference
    pub f64: Frame,
    /// the core with the bounding-box scan
    pub bbox: Frame,
    /// sample-level comparison core vs reference
    pub coverage: CoverageDiff,
    /// the JSON report
    pub report: serde_json::Value,
}

/// Render a scene with all pipelines.
pub fn render(scene: &Scene) -> Result<Rendered> {
    let pattern = Pattern::new(scene.pattern, scene.spp, scene.seed);
    let core = scene.core_tris()?;
    let vp = scene.core_viewport();
    let colors = scene.colors();
    let opts = |label| RunOpts {
        clear: [24, 24, 32],
        image: true,
        label,
        ..RunOpts::for_scene(scene, &colors)
    };
    let fixed = run(
        &Fixed::new(Laine2011, vp, &core, &pattern),
        &pattern,
        &RunOpts {
            oracle: Some(&scene.tris),
            ..opts("uvt fixed")
        },
    );
    let f64 = run(
        &Reference {
            vp: scene.viewport,
            tris: &scene.tris,
            pattern: &pattern,
        },
        &pattern,
        &opts("uvt f64"),
    );
    let bbox = run(
        &Fixed::new(BboxScan, vp, &core, &pattern),
        &pattern,
        &opts("bbox scan"),
    );
    let coverage = compare(&scene.tris, &core, vp, &pattern);
    let report = report_json(scene, &fixed, &f64, &bbox, &coverage);
    Ok(Rendered {
        fixed,
        f64,
        bbox,
        coverage,
        report,
    })
}

fn per(a: u64, b: u64) -> f64 {
    if b == 0 {
        0.0
    } else {
        a as f64 / b as f64
    }
}

fn frame_json(f: &Frame) -> serde_json::Value {
    let mut v = serde_json::to_value(f.stats).unwrap_or_default();
    v["wall_ms"] = json!(f.time.as_secs_f64() * 1e3);
    v["ste"] = json!(f.stats.ste());
    v
}

/// Pixels whose resolved colors differ, and the largest channel difference.
pub fn image_diff(a: &[[u8; 3]], b: &[[u8; 3]]) -> (u64, u8) {
    let mut n = 0;
    let mut m = 0;
    for (p, q) in a.iter().zip(b) {
        let d = (0..3).map(|k| p[k].abs_diff(q[k])).max().unwrap_or(0);
        if d > 0 {
            n += 1;
        }
        m = m.max(d);
    }
    (n, m)
}

fn report_json(
    s: &Scene,
    fixed: &Frame,
    f64: &Frame,
    bbox: &Frame,
    cov: &CoverageDiff,
) -> serde_json::Value {
    let st: &FrameStats = &fixed.stats;
    let visible: u64 = st.by_class.iter().sum();
    let (npix, maxd) = image_diff(&fixed.image, &f64.image);
    json!({
        "format": "uvt-render-report", "version": 1,
        "scene": s.name, "viewport": [s.viewport.0, s.viewport.1], "spp": s.spp, "tile": s.tile,
        "pattern": s.pattern, "seed": s.seed, "triangles": s.tris.len(),
        "classes": {"static": st.by_class[0], "motion": st.by_class[1], "defocus": st.by_class[2], "motion_defocus": st.by_class[3],
                     "culled_outside": st.culled_outside, "culled_degenerate": st.culled_degenerate},
        "fixed": frame_json(fixed), "f64": frame_json(f64), "bbox_scan": frame_json(bbox),
        "ste": {"bbox_scan": bbox.stats.ste(), "uvt_fixed": st.ste(), "uvt_f64": f64.stats.ste(), "oracle": st.ste_oracle()},
        "ops": {"setup_per_triangle": per(st.ops_setup, visible + st.culled_outside + st.culled_degenerate),
                 "bounds_per_tile": per(st.ops_bounds, st.tiles_visited),
                 "sample_per_test": per(st.ops_sample, st.samples_tested)},
        "image_diff_fixed_vs_f64": {"pixels": npix, "max_channel": maxd},
        "coverage_fixed_vs_f64": cov,
    })
}

fn pct(x: f64) -> String {
    format!("{:.2}%", 100.0 * x)
}

/// The Markdown report.
pub fn report_md(r: &Rendered) -> String {
    let j = &r.report;
    let row = |name: &str, f: &Frame, ste: f64| {
        format!(
            "| {name} | {} | {} | {} | {} | {} | {:.1} |\n",
            f.stats.tiles_visited,
            f.stats.tiles_skipped,
            f.stats.samples_tested,
            f.stats.samples_covered,
            pct(ste),
            f.time.as_secs_f64() * 1e3
        )
    };
    let c = &r.coverage;
    let mut s = format!(
        "# uvt render report: {}\n\n{}×{} px, {} spp, bounds tile {}, pattern {} (seed {}), {} triangles.\n\n",
        j["scene"].as_str().unwrap_or(""), j["viewport"][0], j["viewport"][1], j["spp"], j["tile"], j["pattern"].as_str().unwrap_or(""), j["seed"], j["triangles"]
    );
    s += &format!(
        "Triangles by class (core): static {}, motion {}, defocus {}, motion+defocus {}; culled outside {}, degenerate {}.\n\n",
        j["classes"]["static"], j["classes"]["motion"], j["classes"]["defocus"], j["classes"]["motion_defocus"],
        j["classes"]["culled_outside"], j["classes"]["culled_degenerate"]
    );
    s += "| pipeline | tiles visited | tiles skipped | samples tested | samples covered | STE | wall ms |\n|---|---|---|---|---|---|---|\n";
    s += &row("bbox scan (core)", &r.bbox, r.bbox.stats.ste());
    s += &row(
        "uvt fixed (core, Laine 2011)",
        &r.fixed,
        r.fixed.stats.ste(),
    );
    s += &row("uvt f64 (reference)", &r.f64, r.f64.stats.ste());
    s += &format!(
        "| oracle box (covered samples + dense points) | | | {} | {} | {} | |\n\n",
        r.fixed.stats.oracle_tested,
        r.fixed.stats.samples_covered,
        pct(r.fixed.stats.ste_oracle())
    );
    s += &format!(
        "Operations (core): {:.0} per triangle setup, {:.1} per tile bounds, {:.1} per sample test (Laine 2011: ~500 / ~40 / ~25).\n\n",
        j["ops"]["setup_per_triangle"].as_f64().unwrap_or(0.0), j["ops"]["bounds_per_tile"].as_f64().unwrap_or(0.0), j["ops"]["sample_per_test"].as_f64().unwrap_or(0.0)
    );
    s += &format!(
        "Core vs f64 reference: {} (triangle, sample) pairs compared, {} covered by the core only, {} by the reference only \
         (rate {:.2e}); largest distance of a differing sample from an edge {:.2e} px; beyond the documented quantization \
         distance: {}. Resolved images differ in {} pixels (max channel difference {}).\n",
        c.compared, c.fixed_only, c.f64_only, c.rate(), c.max_distance_px, c.beyond_bound,
        j["image_diff_fixed_vs_f64"]["pixels"], j["image_diff_fixed_vs_f64"]["max_channel"]
    );
    s
}

fn heat_color(x: f64) -> [u8; 3] {
    // black → blue → red → yellow → white
    let stops = [
        [0.0, 0.0, 0.0],
        [0.1, 0.2, 0.9],
        [0.9, 0.1, 0.1],
        [1.0, 0.9, 0.1],
        [1.0, 1.0, 1.0],
    ];
    let f = x.clamp(0.0, 1.0) * (stops.len() - 1) as f64;
    let i = (f.floor() as usize).min(stops.len() - 2);
    let a = f - i as f64;
    [0, 1, 2].map(|k| ((stops[i][k] * (1.0 - a) + stops[i + 1][k] * a) * 255.0) as u8)
}

fn png(path: &Path, w: u16, h: u16, px: &[[u8; 3]]) -> Result<()> {
    let buf: Vec<u8> = px.iter().flatten().copied().collect();
    let img = image::RgbImage::from_raw(w as u32, h as u32, buf).context("image size")?;
    img.save_with_format(path, image::ImageFormat::Png)
        .with_context(|| format!("writing {}", path.display()))
}

/// Write all outputs into `dir` (created if needed); temp names, then renames.
pub fn write(r: &Rendered, scene: &Scene, dir: &Path) -> Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let (w, h) = scene.viewport;
    let diff: Vec<[u8; 3]> = r
        .fixed
        .image
        .iter()
        .zip(&r.f64.image)
        .map(|(a, b)| {
            let d = (0..3).map(|k| a[k].abs_diff(b[k])).max().unwrap_or(0);
            if d == 0 {
                [0, 0, 0]
            } else {
                [255, (255 - d.saturating_mul(4)).min(200), 0]
            }
        })
        .collect();
    let maxh = r.fixed.heat.iter().copied().max().unwrap_or(1).max(1) as f64;
    let heat: Vec<[u8; 3]> = r
        .fixed
        .heat
        .iter()
        .map(|&n| heat_color(n as f64 / maxh))
        .collect();
    type Writer<'a> = Box<dyn Fn(&Path) -> Result<()> + 'a>;
    let files: Vec<(&str, Writer<'_>)> = vec![
        (
            "fixed.png",
            Box::new(|p: &Path| png(p, w, h, &r.fixed.image)),
        ),
        ("f64.png", Box::new(|p: &Path| png(p, w, h, &r.f64.image))),
        ("diff.png", Box::new(|p: &Path| png(p, w, h, &diff))),
        ("heat.png", Box::new(|p: &Path| png(p, w, h, &heat))),
        (
            "report.json",
            Box::new(|p: &Path| {
                Ok(std::fs::write(
                    p,
                    serde_json::to_string_pretty(&r.report)? + "\n",
                )?)
            }),
        ),
        (
            "report.md",
            Box::new(|p: &Path| Ok(std::fs::write(p, report_md(r))?)),
        ),
    ];
    let mut tmp = Vec::new();
    for (name, f) in &files {
        let t = dir.join(format!(".{name}.tmp"));
        if let Err(e) = f(&t) {
            for t in tmp.iter().chain(std::iter::once(&t)) {
                let _ = std::fs::remove_file(t);
            }
            return Err(e);
        }
        tmp.push(t);
    }
    let mut out = Vec::new();
    for ((name, _), t) in files.iter().zip(tmp) {
        let dst = dir.join(name);
        std::fs::rename(&t, &dst).with_context(|| format!("renaming to {}", dst.display()))?;
        out.push(dst);
    }
    Ok(out)
}
