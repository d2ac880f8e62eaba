//! `uvt fit`'s driver and report: runs the selection of [`super::select`], the search and the
//! confirmation of [`super::confirm`], and writes Markdown and JSON.

use std::path::Path;

use anyhow::{anyhow, Result};
use serde::Serialize;
use uvt_core::config::registry::{self, DEFAULT, PLANAR};
use uvt_core::Class;

use crate::config::planar_static;
use crate::config::units::{full_sample_cost, unit_for, unit_sample_cost, unit_terms, UnitCost};
use crate::scene::file::Scene;

use super::confirm::{confirm, Confirm};
use super::m4::{M4Data, M4Unit};
use super::search::{search_strategies, StratCost};
use crate::compare::pass::failing_md;
use crate::config::dq::{px_text, Tolerance};

use super::select::{classes, config_fits, narrowest, ConfigFit, DEFAULT_TOLERANCE_PX};

/// Everything `uvt fit` found.
#[derive(Clone, Debug, Serialize)]
pub struct Fit {
    /// scene name
    pub scene: String,
    /// viewport
    pub viewport: (u16, u16),
    /// the tolerance (px) and where it came from
    pub tolerance_px: f64,
    /// "given" or "default (1/32 px)"
    pub tolerance_source: String,
    /// the tolerance's clip form (clip units) for the primitives stated in clip space only, and
    /// where it came from
    pub tolerance_clip: f64,
    /// "given (--clip-tolerance)" or "2·τ/max(W, H)"
    pub tolerance_clip_source: String,
    /// primitives per class: static, motion, defocus, motion+defocus
    pub class_counts: [u64; 4],
    /// the chosen unit
    pub unit: String,
    /// d_q of every configuration
    pub configs: Vec<ConfigFit>,
    /// primitives stated in clip space only at the chosen configuration (a vertex can reach the
    /// camera plane; `crate::config::dq`)
    pub clip_primitives: Vec<usize>,
    /// static triangles that the planar configuration's vertex rounding makes degenerate
    /// (culled; the default does not cull them) and the static triangles:
    /// `crate::config::planar_static::degenerate`
    pub planar_degenerate: (u64, u64),
    /// the chosen configuration
    pub config: String,
    /// every strategy and tile size tried
    pub strategies: Vec<StratCost>,
    /// the chosen strategy
    pub strategy: String,
    /// the chosen bounds-tile size
    pub tile: u8,
    /// the sample test's width factor used in the cost
    pub width_factor: f64,
    /// the confirmation
    pub confirm: Confirm,
    /// sample-test cost of the chosen unit and configuration
    pub sample_cost: UnitCost,
    /// sample-test cost of the full unit at the default configuration
    pub sample_cost_full_default: UnitCost,
    /// M4 figures of the chosen unit and of the full unit (`m4_units.json`), if measured
    pub m4: Option<[M4Unit; 2]>,
    /// the M4 file read (or looked for)
    pub m4_path: String,
    /// every confirmation holds
    pub ok: bool,
}

/// Run `uvt fit` on a loaded scene. Errors: an unreachable tolerance, a scene outside the core's
/// domain. A failed confirmation is not an error here: `ok` is false.
///
/// `m4`/`m4_path`: the unit programs at the default configuration (`m4_units.json`); the full
/// unit's row always comes from it. `m4_planar`/`m4_planar_path`: the unit programs at the
/// planar configuration (`m4_report.sh --units OUT planar-16-16-16-20`); the chosen unit's row
/// comes from it when the planar configuration is chosen (not measured if absent), so the M4
/// figures are always those of the configuration named beside them.
pub fn fit(
    scene: &Scene,
    tolerance: Option<f64>,
    clip_tolerance: Option<f64>,
    m4: Option<M4Data>,
    m4_path: &Path,
    m4_planar: Option<M4Data>,
    m4_planar_path: &Path,
) -> Result<Fit> {
    let (tol, source) = match tolerance {
        Some(t) => (t, "given (--tolerance)".to_string()),
        None => (DEFAULT_TOLERANCE_PX, "default (1/32 px)".to_string()),
    };
    let tol_full = Tolerance::new(tol, clip_tolerance, scene.viewport);
    let clip_source = if clip_tolerance.is_some() {
        "given (--clip-tolerance)"
    } else {
        "2·τ/max(W, H): τ px for a vertex at w = 1"
    }
    .to_string();
    let cls = classes(scene)?;
    let mut counts = [0u64; 4];
    for c in &cls {
        counts[c.index()] += 1;
    }
    let unit = unit_for(
        cls.iter().any(|c| c.motion()),
        cls.iter().any(|c| c.defocus()),
    );
    let terms = unit_terms(unit).ok_or_else(|| anyhow!("unknown unit {unit}"))?;
    let fits = config_fits(scene, terms, &tol_full)?;
    let chosen = narrowest(&fits, &tol_full)?.clone();
    let cfg = registry::find(&chosen.config)
        .ok_or_else(|| anyhow!("not a configuration of the registry: {}", chosen.config))?;
    let planar = cfg.planar();
    let sample_cost = if planar {
        planar_static::unit_cost(terms.0, terms.1)
            .ok_or_else(|| anyhow!("no cost model for {}", chosen.config))?
    } else {
        unit_sample_cost(&cfg, terms.0, terms.1).unwrap_or_else(|| full_sample_cost(&cfg))
    };
    let width = sample_cost.bit_products as f64 / (sample_cost.products.max(1) as f64 * 1024.0);
    let strategies = search_strategies(scene, cfg, width)
        .ok_or_else(|| anyhow!("configuration {} has no precision type", chosen.config))??;
    // Highest score; the first (earlier strategy, smaller tile) wins ties.
    let best = strategies
        .iter()
        .fold(None::<&StratCost>, |b, s| match b {
            Some(b) if b.score >= s.score => Some(b),
            _ => Some(s),
        })
        .ok_or_else(|| anyhow!("no strategy ran"))?
        .clone();
    let conf = confirm(
        scene,
        cfg,
        &best.strategy,
        best.tile,
        unit,
        &tol_full,
        &chosen.statements,
    )
    .ok_or_else(|| anyhow!("cannot confirm {} / {}", chosen.config, best.strategy))??;
    // The full unit's instructions on this unit's primitives when measured (same work), else
    // on the full demo; flash and RAM are the programs'.
    let find = |rows: &[M4Unit], n: &str| rows.iter().find(|r| r.unit == n).cloned();
    let unit_row = if planar {
        m4_planar.as_ref().and_then(|(rows, _)| find(rows, unit))
    } else {
        m4.as_ref().and_then(|(rows, _)| find(rows, unit))
    };
    let m4 = m4.and_then(|(rows, on)| {
        let mut full = find(&rows, "full")?;
        if let Some(o) = on.iter().find(|o| o.prims == unit) {
            (full.setup, full.bounds, full.sample) = (o.setup, o.bounds, o.sample);
        }
        Some([unit_row?, full])
    });
    let m4_path = if planar {
        format!(
            "`{}` (this unit, at {cfg}) and `{}` (the full unit, at {DEFAULT})",
            m4_planar_path.display(),
            m4_path.display()
        )
    } else {
        format!("`{}`", m4_path.display())
    };
    let ok = conf.ok();
    Ok(Fit {
        scene: scene.name.clone(),
        viewport: scene.viewport,
        tolerance_px: tol,
        tolerance_source: source,
        tolerance_clip: tol_full.clip,
        tolerance_clip_source: clip_source,
        class_counts: counts,
        unit: unit.to_string(),
        configs: fits,
        clip_primitives: chosen.clip_primitives.clone(),
        planar_degenerate: planar_static::degenerate(scene),
        config: chosen.config,
        strategies,
        strategy: best.strategy,
        tile: best.tile,
        width_factor: width,
        confirm: conf,
        sample_cost,
        sample_cost_full_default: full_sample_cost(&DEFAULT),
        m4,
        m4_path,
        ok,
    })
}

fn yes(b: bool) -> &'static str {
    if b {
        "yes"
    } else {
        "**NO**"
    }
}

fn saved(mine: f64, full: f64) -> String {
    if full > 0.0 {
        format!("{:.1}%", 100.0 * (full - mine) / full)
    } else {
        "–".into()
    }
}

/// The Markdown report.
pub fn fit_md(f: &Fit) -> String {
    let names = [
        Class::Static,
        Class::Motion,
        Class::Defocus,
        Class::MotionDefocus,
    ]
    .map(Class::name);
    let mut s = format!(
        "# uvt fit: {} ({}×{})\n\nTolerance: {} px, {}; in clip space (primitives stated in clip space only): {:.3e} clip units, {}.\n\n## Unit\n\n| class | primitives |\n|---|---|\n",
        f.scene, f.viewport.0, f.viewport.1, f.tolerance_px, f.tolerance_source, f.tolerance_clip, f.tolerance_clip_source
    );
    for (n, c) in names.iter().zip(f.class_counts) {
        s += &format!("| {n} | {c} |\n");
    }
    s += &format!(
        "\nSmallest unit accepting every class: **{}**.\n\n## Configuration\n\nError statement per configuration (`host/src/config/dq.rs`): every primitive has a backward error δ in clip units; wherever every vertex stays in front of the camera, also a documented error distance d_q in pixels, which it is held to however large. Largest d_q over the primitives stated in pixels, largest δ over those stated in clip space only and δ's largest share of such a primitive's own clip extent (at most 1/16 says something; –: none), sample-test cost of the {} unit:\n\n| configuration | d_q px | worst primitive | δ clip units (clip-space primitives) | worst primitive | δ / extent | meets {} px / {:.3e} clip | DSP48E1 | Σ bit-products |\n|---|---|---|---|---|---|---|---|---|\n",
        f.unit, f.unit, f.tolerance_px, f.tolerance_clip
    );
    for c in &f.configs {
        let (d, b) = c.unit_cost.as_ref().map_or(
            ("not modelled (exact)".to_string(), "–".to_string()),
            |u| (u.dsp48e1.to_string(), u.bit_products.to_string()),
        );
        let idx = |i: Option<usize>| i.map_or("–".into(), |i| i.to_string());
        s += &format!(
            "| {} | {} | {} | {} | {} | {} | {} | {d} | {b} |\n",
            c.config,
            c.d_q_px.map_or("–".into(), px_text),
            idx(c.worst_primitive),
            c.clip.map_or("–".into(), |d| format!("{d:.3e}")),
            idx(c.worst_clip_primitive),
            c.clip_share.map_or("–".into(), |d| format!("{d:.3e}")),
            if c.meets { "yes" } else { "no" }
        );
    }
    if !f.clip_primitives.is_empty() {
        s += &format!(
            "\nPrimitives stated in clip space only at {} (a vertex can reach the camera plane): {:?}. Each of their decisions equals the exact decision of the primitive with every vertex moved by at most its δ, which is at most 1/16 of the primitive's own clip extent.\n",
            f.config, f.clip_primitives
        );
    }
    s += &format!(
        "\n`{PLANAR}`: {} of {} static triangles become degenerate after the vertex rounding (culled: they cover no sample at that configuration; the default configuration renders them).\n",
        f.planar_degenerate.0,
        f.planar_degenerate.1
    );
    s += &format!(
        "\nNarrowest configuration meeting the tolerance: **{}**.\n\n## Bounds strategy and tile size\n\nCost = whole Cortex-M4F instructions, setup included: this frame's triangles, tiles, samples of kept tiles and sample tests times the strategy's instructions per call, measured on the bench rows' own triangles (`host/report/m4_strategies.json`, `bash demo/m4_report.sh --strategies`; default configuration, tile 1); score = covered samples per instruction. Ops cost = setup ops + tile ops + predicate ops + sample tests × ops per test × width factor {:.3} (`host/src/fit/search.rs`).\n\n| strategy | tile | STE | tested | covered | setup ops | tile ops | predicate ops | ops/test | ops cost | M4 instructions | score |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n",
        f.config, f.width_factor
    );
    for r in &f.strategies {
        let mark = if r.strategy == f.strategy && r.tile == f.tile {
            " **←**"
        } else {
            ""
        };
        s += &format!(
            "| {}{mark} | {} | {:.2}% | {} | {} | {} | {} | {} | {:.1} | {:.0} | {:.0} | {:.3e} |\n",
            r.strategy,
            r.tile,
            100.0 * r.ste,
            r.tested,
            r.covered,
            r.ops_setup,
            r.ops_tile,
            r.ops_predicate,
            r.ops_per_test,
            r.ops_cost,
            r.cost,
            r.score
        );
    }
    let c = &f.confirm;
    s += &format!(
        "\nChosen: **{}**, bounds tile **{}**.\n\n## Confirmation (unit {}, {}, {}, tile {})\n\n| check | result | holds |\n|---|---|---|\n",
        f.strategy, f.tile, f.unit, f.config, f.strategy, f.tile
    );
    s += &format!(
        "| conservativeness violations (covered samples outside the bounds) | {} | {} |\n",
        c.violations,
        yes(c.violations == 0)
    );
    s += &format!(
        "| decisions ≠ f64 of primitives stated in pixels: beyond their own d_q | {} of {} differing | {} |\n",
        c.beyond_statement,
        c.differ_px,
        yes(c.beyond_statement == 0)
    );
    s += &format!(
        "| decisions ≠ f64 of primitives stated in pixels: beyond {} px (max distance px) | {} of {} differing ({:.6}) | {} |\n",
        f.tolerance_px,
        c.beyond_tolerance,
        c.differ_px,
        c.max_distance_px,
        yes(c.beyond_tolerance == 0)
    );
    s += &format!(
        "| decisions ≠ f64 of primitives stated in clip space only: not explained by a {:.3e}-clip-unit vertex move (largest δ {:.3e}; distance from an edge, not bounded: {:.6} px) | {} of {} differing | {} |\n",
        f.tolerance_clip,
        c.max_clip,
        c.max_distance_clip_px,
        c.beyond_tolerance_clip,
        c.differ_clip,
        yes(c.beyond_tolerance_clip == 0)
    );
    s += &format!(
        "| primitives with a decision beyond the bound, their statement or the tolerance (named below); covered samples {} against the f64 reference's {}; primitives lost {}, drawn where the reference draws nothing {} | {} of {} | {} |\n",
        c.covered[0],
        c.covered[1],
        c.lost_gained[0],
        c.lost_gained[1],
        c.failing.len(),
        f.class_counts.iter().sum::<u64>(),
        yes(c.failing.is_empty())
    );
    s += &format!(
        "| decisions ≠ f64 no rounding explains (`host/src/compare/bound.rs` check) | {} of {} compared | {} |\n",
        c.beyond_bound,
        c.compared,
        yes(c.beyond_bound == 0)
    );
    s += &format!(
        "| image and every sample identical to the full unit (same widths, strategy, tile) | {} | {} |\n",
        c.renderer_error.clone().unwrap_or_else(|| format!(
            "tested {} covered {}",
            c.unit_tested_covered[0], c.unit_tested_covered[1]
        )),
        yes(c.identical_to_full == Some(true))
    );
    if let Some(x) = &c.specialised {
        s += &format!(
            "| every sample and the image identical to the full unit with the unit's specialised renderer (`{}`, its own tile cull; the renderer of its Cortex-M program) | {} | {} |\n",
            x.renderer,
            x.error.clone().unwrap_or_else(|| format!(
                "tested {} covered {}",
                x.tested_covered[0], x.tested_covered[1]
            )),
            yes(x.identical_to_full == Some(true))
        );
    }
    s += &failing_md(&c.failing);
    let (m, d) = (&f.sample_cost, &f.sample_cost_full_default);
    s += &format!(
        "\n## Saved against the full unit at {DEFAULT}\n\n| figure | {} unit, {} | full unit, {DEFAULT} | saved |\n|---|---|---|---|\n| sample test DSP48E1 (model) | {} | {} | {} |\n| sample test MULT18X18D (model) | {} | {} | {} |\n| sample test Σ bit-products | {} | {} | {} |\n",
        f.unit,
        f.config,
        m.dsp48e1,
        d.dsp48e1,
        saved(m.dsp48e1 as f64, d.dsp48e1 as f64),
        m.ecp5,
        d.ecp5,
        saved(m.ecp5 as f64, d.ecp5 as f64),
        m.bit_products,
        d.bit_products,
        saved(m.bit_products as f64, d.bit_products as f64)
    );
    match &f.m4 {
        Some([u, full]) => {
            for (n, a, b) in [
                ("M4F instructions per setup", u.setup, full.setup),
                ("M4F instructions per tile", u.bounds, full.bounds),
                ("M4F instructions per sample test", u.sample, full.sample),
                ("flash bytes", u.flash as f64, full.flash as f64),
                ("RAM bytes (.data + .bss)", u.ram as f64, full.ram as f64),
            ] {
                s += &format!("| {n} | {a:.0} | {b:.0} | {} |\n", saved(a, b));
            }
            s += &format!(
                "\nM4F figures from {} (measured at the configuration named there; the full unit's instructions on the primitives this unit accepts where the file has them, `full_on_unit_prims`).\n",
                f.m4_path
            );
        }
        None => {
            s += &format!(
                "| M4F instructions per setup / tile / sample, flash | not measured | not measured | – |\n\nM4F figures: not measured ({} absent or without these units; `bash demo/m4_report.sh --units [FILE {PLANAR}]` writes it).\n",
                f.m4_path
            )
        }
    }
    s += &format!(
        "\n**Confirmation: {}.**\n",
        if f.ok { "passed" } else { "FAILED" }
    );
    s
}
