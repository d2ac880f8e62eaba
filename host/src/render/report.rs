//! The reports of `uvt render`: `report.json` (every counter; what a pipeline does not count is
//! null) and `report.md`, which names each image and what it shows, defines STE, tiles skipped
//! and the oracle, and says what each wall time covers.

use serde_json::json;

use crate::compare::pass::Comparison;
use crate::frame::counters::{Frame, FrameStats};
use crate::frame::oracle::ORACLE_POINTS;
use crate::scene::file::Scene;

use super::opts::{bounds_label, per, RenderOpts, Rendered};

/// One frame's counters; the operation counters are null for the f64 reference, which counts
/// none (0 would read as "no operations").
fn frame_json(f: &Frame, ops: bool) -> serde_json::Value {
    let mut v = serde_json::to_value(f.stats).unwrap_or_default();
    if !ops {
        for k in ["ops_setup", "ops_bounds", "ops_sample"] {
            v[k] = serde_json::Value::Null;
        }
    }
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

pub(crate) fn report_json(
    s: &Scene,
    o: &RenderOpts,
    fixed: &Frame,
    f64: &Frame,
    bbox: &Frame,
    cov: &Comparison,
) -> serde_json::Value {
    let st: &FrameStats = &fixed.stats;
    let (npix, maxd) = image_diff(&fixed.image, &f64.image);
    json!({
        "format": "uvt-render-report", "version": 1,
        "scene": s.name, "viewport": [s.viewport.0, s.viewport.1], "spp": s.spp, "tile": s.tile,
        "pattern": s.pattern, "seed": s.seed, "triangles": s.tris.len(),
        "bounds": o.bounds, "precision": o.precision.to_string(),
        "classes": {"static": st.by_class[0], "motion": st.by_class[1], "defocus": st.by_class[2], "motion_defocus": st.by_class[3],
                     "culled_outside": st.culled_outside, "culled_degenerate": st.culled_degenerate},
        "fixed": frame_json(fixed, true), "f64": frame_json(f64, false), "bbox_scan": frame_json(bbox, true),
        "ste": {"bbox_scan": bbox.stats.ste(), "uvt_fixed": st.ste(), "uvt_f64": f64.stats.ste(), "oracle": st.ste_oracle()},
        "ops": {"setup_per_triangle": per(st.ops_setup, st.triangles),
                 "bounds_per_tile": per(st.ops_bounds, st.tiles_visited),
                 "sample_per_test": per(st.ops_sample, st.samples_tested)},
        "image_diff_fixed_vs_f64": {"pixels": npix, "max_channel": maxd},
        "coverage_fixed_vs_f64": coverage_json(cov),
    })
}

/// The comparison as the report holds it, with its violations summed over the tile sizes.
fn coverage_json(cov: &Comparison) -> serde_json::Value {
    let mut v = json!(cov);
    v["violations"] = json!(cov.violations());
    v
}

fn pct(x: f64) -> String {
    format!("{:.2}%", 100.0 * x)
}

/// The Markdown report: what each image shows, the terms, the table, what each time covers.
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
    let bounds = bounds_label(r.opts.bounds);
    let mut s = format!(
        "# uvt render report: {}\n\n{}×{} px, {} spp, bounds tile {}, pattern {} (seed {}), {} triangles; \
         core at configuration {} (fraction bits of position, t/u/v, bounds[, offset-grid shift of the bounded sample test]) with {bounds} bounds.\n\n",
        j["scene"].as_str().unwrap_or(""), j["viewport"][0], j["viewport"][1], j["spp"], j["tile"],
        j["pattern"].as_str().unwrap_or(""), j["seed"], j["triangles"], j["precision"].as_str().unwrap_or("")
    );
    let vp = (
        j["viewport"][0].as_u64().unwrap_or(0) as u16,
        j["viewport"][1].as_u64().unwrap_or(0) as u16,
    );
    let k = super::diff::scale_for(vp.0, vp.1);
    let enlarged = if k > 1 {
        format!(" Both maps are enlarged ×{k} (each scene pixel a {k}×{k} block).")
    } else {
        String::new()
    };
    s += &format!("## Images\n\n\
        - `fixed.png`: the frame rendered by the fixed-point core (the golden model), each pixel the \
          average of its samples.\n\
        - `f64.png`: the same frame rendered by the independent f64 reference on the exact (unrounded) inputs.\n\
        - `diff.png`: per pixel the largest R, G, B difference of the two images: black where they agree, \
          1 to 255 levels from dark red through red and yellow to white, every larger difference strictly \
          brighter; the legend below the map gives the scale's numbers.\n\
        - `heat.png`: sample tests per pixel of the core with its bounds, black (none) through blue, red and \
          yellow to white (the maximum); the legend below the map gives the scale's numbers.{enlarged}\n\n");
    s += &format!(
        "Triangles by class (core): static {}, motion {}, defocus {}, motion+defocus {}; culled outside {}, degenerate {}.\n\n",
        j["classes"]["static"], j["classes"]["motion"], j["classes"]["defocus"], j["classes"]["motion_defocus"],
        j["classes"]["culled_outside"], j["classes"]["culled_degenerate"]
    );
    s += "## Pipelines\n\n\
        | pipeline | tiles visited | tiles skipped | samples tested | samples covered | STE | wall ms |\n|---|---|---|---|---|---|---|\n";
    s += &row("bbox scan (core)", &r.bbox, r.bbox.stats.ste());
    s += &row(
        &format!("uvt fixed (core, {bounds})"),
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
        "- **STE** (sample test efficiency) = samples covered ÷ samples tested: the share of sample tests \
          that find coverage; higher means tighter bounds.\n\
        - **Tiles visited**: bounds tiles ({t}×{t} px cells of a triangle's screen footprint) for which bounds were \
          computed; **tiles skipped**: those whose (u, v, t) bounds came out empty, so none of their samples was tested.\n\
        - **Oracle**: per tile, the tightest axis-aligned (u, v, t) box around the samples the core covered there and \
          around {n} dense points of the tile that the exact triangle covers; counting the samples inside it estimates \
          from above what any axis-aligned bound could reach. It is computed during the core's frame.\n\
        - **Wall ms**: wall-clock time of each pipeline's whole frame on this machine (setup, bounds, sample tests, \
          depth test and resolve, in parallel over bands: the core's one row of bounds tiles high, the reference's 8 rows). The core's time includes the oracle's dense \
          sampling; the comparison below is not included in any of them. Host timings of a reference model, \
          not of hardware.\n\n",
        t = j["tile"],
        n = ORACLE_POINTS
    );
    let ops = |k: &str| j["ops"][k].as_f64().unwrap_or(0.0);
    s += &format!(
        "Operations (core, counted by uvt-core): {:.0} per triangle setup, {:.1} per tile bounds, {:.1} per sample \
         test (Laine 2011: ~500 / ~40 / ~25). The f64 reference counts no operations (null in report.json).\n\n",
        ops("setup_per_triangle"), ops("bounds_per_tile"), ops("sample_per_test")
    );
    s += &format!(
        "## Core vs f64 reference\n\n{} (triangle, sample) pairs compared over every footprint sample \
         (`host/src/compare/pass.rs`), {} differ ({} covered by the core only, {} by the reference only; \
         rate {:.2e}); largest distance of a differing sample from an edge {:.2e} px; not explained by the \
         derived quantization bound at this precision (must be 0): {}. By error statement \
         (`host/src/config/dq.rs`): {} of primitives stated in pixels (their largest d_q {} px, farthest \
         from an edge {:.2e} px), {} of them farther than the primitive's own d_q from an edge (must be 0); {} of primitives stated in clip space only \
         (largest backward error δ {:.3e} clip units; {} of primitives whose δ is above 1/16 of their own \
         clip extent, about which the statement says nothing). Per primitive: the core covers {} samples, \
         the reference {}; {} primitives the reference draws are lost, {} drawn where the reference \
         draws nothing; {} primitives have a decision beyond the bound or their statement (must be 0; \
         named in report.json, `coverage_fixed_vs_f64.failing`). Covered samples outside the core's own bounds \
         ({bounds}, bounds tile {}): {} (must be 0). Resolved images differ in {} pixels (max channel \
         difference {}).\n",
        c.compared, c.differ, c.fixed_only, c.f64_only, c.rate(), c.max_distance_px, c.beyond_bound,
        c.differ_px, crate::config::dq::px_text(c.max_dq_px), c.max_distance_stated_px, c.beyond_statement, c.differ_clip, c.max_clip, c.differ_clip_uninformative,
        c.core_covered, c.reference_covered, c.lost, c.gained, c.failing.len(), j["tile"], c.violations(),
        j["image_diff_fixed_vs_f64"]["pixels"], j["image_diff_fixed_vs_f64"]["max_channel"]
    );
    s += &crate::compare::pass::failing_md(&c.failing);
    s
}
