//! `uvt bench-ste`: the STE table in the layout of Laine 2011 Table 1 for the 'game' and 'dense'
//! scenes in seven rows each — columns bbox scan, every bounds strategy of the core (Laine 2011,
//! swept-hull culling, lens-slab time bounds, bilinear (u, t)/(v, t) surfaces, hull + lens slabs,
//! hull + edge-direction time bounds, the combined best = hull + edge-direction t + surfaces), the
//! f64 reference and the axis-aligned limit ([`crate::oracle`]) at two efforts — plus the cost of
//! each strategy (ops per tile, per-sample predicate ops, wall time without the oracle) and a
//! second table over bounds-tile sizes 1, 2, 4, 8. The core runs at one precision per table
//! (`--precision`, a configuration of `uvt_core::config::registry`; default: the core's default
//! configuration): the scene rounded
//! to its position grid, the pattern to its t/u/v grid; a `bounded-…` precision runs the bounded
//! sample test with every strategy widened by its conservative epsilon; a `planar-…` one runs
//! the planar static test on static triangles (`crate::config::planar_static`; the bounded test on
//! the others) with the per-triangle epsilon. The f64 reference stays on the exact inputs; the
//! axis-aligned limit runs on the scene at 16 position fraction bits with the core's default sample
//! test (`uvt_core::setup`, `uvt_core::sample_test`).

use std::time::Duration;

use serde::Serialize;
use uvt_core::bounds::registry::best;
use uvt_core::bounds::strategy::BoundsStrategy;
use uvt_core::config::registry::Config;
use uvt_core::{with_config, Laine2011, Precision, Triangle};

use crate::config::names;

use crate::frame::driver::{run, RunOpts};
use crate::frame::pipelines::Reference;
use crate::oracle::limit::{axis_aligned_limit, Limit, Method};
use crate::oracle::search::Effort;
use crate::scene::builtin::{bench_scene, Bench, Blur};
use crate::scene::pattern::Pattern;

use super::strategy::{per, run_strategy_at, strategies, StratResult};

/// The two efforts of the axis-aligned limit (dense points per pixel, face-search proposals per
/// face; each effort then ends with the line pushes of [`crate::oracle::limit::Method::Lines3`]);
/// the second continues the first. With the centre-line seeds and line pushes, 16 and 64 proposals
/// per face ask about 9% more points than the plain clip search's 32 and 128 did on quick 'dense
/// both ×2' and converge where it did not (gap 6.0% → 2.5%, every covered pattern sample inside the
/// high-effort box; every 16th triangle, measured with the search alone).
pub const ORACLE_EFFORT: [Effort; 2] = [
    Effort {
        density: 16,
        steps: 16,
    },
    Effort {
        density: 64,
        steps: 64,
    },
];

/// Parse the limit's two efforts `D0:S0,D1:S1` (dense points per pixel, proposals per face; the
/// second effort continues the first, so `D1 ≥ D0`, `D1 ≤ 65536`); the message names what is
/// wrong.
pub fn parse_effort(text: &str) -> Result<[Effort; 2], String> {
    let parts: Vec<&str> = text.split(',').collect();
    let [a, b] = parts[..] else {
        return Err(format!(
            "expected two efforts D0:S0,D1:S1, found {}",
            parts.len()
        ));
    };
    let one = |p: &str| -> Result<Effort, String> {
        let (d, st) = p
            .split_once(':')
            .ok_or_else(|| format!("effort {p:?} is not DENSITY:STEPS"))?;
        let num = |x: &str, what: &str| {
            x.trim()
                .parse::<u32>()
                .map_err(|e| format!("{what} {x:?} in {p:?}: {e}"))
        };
        Ok(Effort {
            density: num(d, "density")?,
            steps: num(st, "steps")?,
        })
    };
    let (e0, e1) = (one(a)?, one(b)?);
    if e1.density < e0.density || e1.density > 65536 || e0.density == 0 {
        return Err(format!(
            "densities must satisfy 1 ≤ D0 ≤ D1 ≤ 65536, found {} and {}",
            e0.density, e1.density
        ));
    }
    Ok([e0, e1])
}

fn per_f(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        0.0
    } else {
        a / b
    }
}

/// One row of the table.
#[derive(Clone, Debug, Serialize)]
pub struct BenchRow {
    /// the core's configuration (its registry name)
    pub precision: String,
    /// scene
    pub scene: Bench,
    /// row
    pub row: Blur,
    /// triangles submitted
    pub triangles: usize,
    /// average covered area of a visible triangle, pixels (covered samples / spp / visible)
    pub avg_area_px: f64,
    /// STE of the bounding-box scan
    pub bbox: f64,
    /// every strategy of [`strategies`] at bounds tile 1, in its order
    pub strategies: Vec<StratResult>,
    /// STE of the f64 reference (Laine 2011 in f64)
    pub f64: f64,
    /// wall ms of the f64 reference's frame (same frame driver, no oracle; the fastest of
    /// [`timing_runs`] frames)
    pub f64_ms: f64,
    /// the axis-aligned limit at bounds tile 1 (all zero when not requested)
    pub limit: Limit,
    /// wall ms of the limit's dense sampling (not part of any strategy's time)
    pub limit_ms: f64,
    /// `tile_sweep[i]`: every strategy at bounds tile 2^i (1, 2, 4, 8)
    pub tile_sweep: Vec<Vec<StratResult>>,
}

impl BenchRow {
    /// The result of strategy `name` at tile 1.
    pub fn strat(&self, name: &str) -> Option<&StratResult> {
        self.strategies.iter().find(|s| s.name == name)
    }
}

/// Run the benchmark table at the default precision; `sweep` adds the bounds-tile sweep 1, 2, 4,
/// 8; `effort` (low and high: dense points per pixel, face-search proposals per face) adds the
/// axis-aligned limit.
pub fn run_table(
    quick: bool,
    scenes: &[Bench],
    rows: &[Blur],
    sweep: bool,
    effort: Option<[Effort; 2]>,
) -> Vec<BenchRow> {
    rows_at::<uvt_core::DefaultPrecision>(quick, scenes, rows, sweep, effort)
}

/// [`run_table`] with the core at the configuration named `precision` (a name of the registry
/// or "default", [`names::precision`]); an unknown name is an error naming the valid ones.
pub fn run_table_at(
    precision: &str,
    quick: bool,
    scenes: &[Bench],
    rows: &[Blur],
    sweep: bool,
    effort: Option<[Effort; 2]>,
) -> anyhow::Result<Vec<BenchRow>> {
    let cfg = names::precision("--precision", precision)?;
    run_table_of(cfg, quick, scenes, rows, sweep, effort)
}

/// [`run_table`] with the core at configuration `cfg` (one of the registry's; `with_config!`
/// has every one).
pub fn run_table_of(
    cfg: Config,
    quick: bool,
    scenes: &[Bench],
    rows: &[Blur],
    sweep: bool,
    effort: Option<[Effort; 2]>,
) -> anyhow::Result<Vec<BenchRow>> {
    with_config!(cfg, P => rows_at::<P>(quick, scenes, rows, sweep, effort))
        .ok_or_else(|| anyhow::anyhow!("configuration {cfg} is not in the registry"))
}

/// Frames timed per strategy (at bounds tile 1) and for the reference, the fastest kept: 5 at the
/// quick size, whose frames take tens of milliseconds (with 3, one row's fastest core frame came
/// out 1.06× the reference's where 10 frames each gave 0.85×), 2 at full size (up to ~25 s per
/// frame): one frame alone is at the mercy of the scheduler.
pub fn timing_runs(quick: bool) -> usize {
    if quick {
        5
    } else {
        2
    }
}

fn rows_at<P: Precision + Sync>(
    quick: bool,
    scenes: &[Bench],
    rows: &[Blur],
    sweep: bool,
    effort: Option<[Effort; 2]>,
) -> Vec<BenchRow> {
    let mut out = Vec::new();
    let total = scenes.len() * rows.len();
    for &kind in scenes {
        for &row in rows {
            // Progress as plain lines on stderr (readable in logs, not only on a terminal).
            eprintln!(
                "bench-ste: row {} of {total}: {kind:?} {}",
                out.len() + 1,
                row.label()
            );
            let s = bench_scene(kind, row, quick);
            let pattern = Pattern::new(s.pattern, s.spp, s.seed);
            let core = s.core_tris().expect("built-in scene converts");
            // The core's inputs on P's grids (the same values at 16 fraction bits).
            let core_p: Vec<Triangle> = s
                .tris
                .iter()
                .map(|t| t.to_core_with::<P>().expect("built-in scene converts"))
                .collect();
            let pattern_p = pattern.with_tuv(P::TUV_FRAC);
            let vp = s.core_viewport();
            let colors = s.colors();
            let o = RunOpts::for_scene(&s, &colors);
            // Wall times of the tile-1 runs (the cost table's) and of the reference: the fastest
            // of `runs` frames each (the counts are the same every time).
            let runs = timing_runs(quick);
            // One untimed warm-up frame per row (Laine 2011) before anything
            // is timed: otherwise the first timed frame of a new scene pays the allocator's heap
            // growth (page faults over tens of MiB at full size) and whichever pipeline runs
            // first is penalised.
            let _ = run_strategy_at::<P>(
                Laine2011.name(),
                vp,
                &core_p,
                &pattern_p,
                &RunOpts {
                    tile: 1,
                    ..o.clone()
                },
            );
            let at = |tile: u8, runs: usize| -> Vec<StratResult> {
                strategies()
                    .filter_map(|n| {
                        let o = RunOpts { tile, ..o.clone() };
                        let mut best = run_strategy_at::<P>(n, vp, &core_p, &pattern_p, &o)?.0;
                        for _ in 1..runs {
                            let again = run_strategy_at::<P>(n, vp, &core_p, &pattern_p, &o)?.0;
                            best.ms = best.ms.min(again.ms);
                        }
                        Some(best)
                    })
                    .collect()
            };
            let strategies = at(1, runs);
            let tile_sweep = if sweep {
                let mut v = vec![strategies.clone()];
                v.extend([2u8, 4, 8].iter().map(|&t| at(t, 1)));
                v
            } else {
                Vec::new()
            };
            let reference = Reference {
                vp: s.viewport,
                tris: &s.tris,
                pattern: &pattern,
            };
            let r = run(&reference, &pattern, &o);
            let f64_ms = (1..runs)
                .map(|_| run(&reference, &pattern, &o).time)
                .fold(r.time, Duration::min)
                .as_secs_f64()
                * 1e3;
            let start = std::time::Instant::now();
            let limit = match effort {
                Some(d) => axis_aligned_limit(&core, vp, &pattern, 1, d, Method::Lines3),
                None => Limit::default(),
            };
            let limit_ms = start.elapsed().as_secs_f64() * 1e3;
            let st = &strategies[0].stats;
            let visible: u64 = st.by_class.iter().sum();
            out.push(BenchRow {
                precision: Config::of::<P>().to_string(),
                scene: kind,
                row,
                triangles: s.tris.len(),
                avg_area_px: per(st.samples_covered, visible * s.spp as u64),
                bbox: st.ste_bbox(),
                strategies,
                f64: r.stats.ste(),
                f64_ms,
                limit,
                limit_ms,
                tile_sweep,
            });
        }
    }
    out
}

fn name_of(r: &BenchRow) -> String {
    if r.row == Blur::Static {
        match r.scene {
            Bench::Game => "GAME",
            Bench::Dense => "DENSE",
        }
        .to_string()
    } else {
        format!("  {}", r.row.label())
    }
}

/// The tables as Markdown, STE in percent: STE per strategy with the axis-aligned limit, the cost
/// per strategy, and (when swept) STE per bounds-tile size.
pub fn table_md(rows: &[BenchRow]) -> String {
    let [e0, e1] = rows.first().map_or(ORACLE_EFFORT, |r| r.limit.effort);
    let method = rows.first().map_or(Method::Lines3, |r| r.limit.method);
    // `--no-limit`: the limit was not computed, so its columns are left out (not shown as 0).
    let with_limit = rows
        .iter()
        .any(|r| r.limit.effort != [Effort::default(); 2]);
    let label = |e: Effort| format!("{}/px + {} steps", e.density, e.steps);
    let limit_head = if with_limit {
        format!(
            " axis-aligned limit ({}), effort {} | limit, effort {} | gap | covered samples outside the limit box (effort 1 / 2) | best ÷ limit |",
            method.label(),
            label(e0),
            label(e1)
        )
    } else {
        String::new()
    };
    let prec = rows.first().map_or(String::new(), |r| r.precision.clone());
    // The STE columns: the bbox scan (from the counters), then every strategy of the bench.
    let laine = Laine2011.name();
    let head: String = strategies()
        .map(|n| {
            if n == laine {
                " Laine 2011 |".to_string()
            } else {
                format!(" {n} |")
            }
        })
        .collect();
    let cols = strategies().count();
    let mut s = format!(
        "Core precision {prec}\n\nSTE (%), bounds tile 1×1\n\n| Scene | Bbox scan |{head} Laine f64 |{limit_head} avg area px |\n|---|---|{}---|{}---|\n",
        "---|".repeat(cols),
        if with_limit { "---|---|---|---|---|" } else { "" }
    );
    let ste = |r: &BenchRow, n: &str| r.strat(n).map_or(0.0, |x| 100.0 * x.ste());
    let best_name = best().name();
    for r in rows {
        let cells: String = strategies()
            .map(|n| format!(" {:.2} |", ste(r, n)))
            .collect();
        s += &format!(
            "| {} | {:.2} |{cells} {:.2} |{} {:.2} |\n",
            name_of(r),
            100.0 * r.bbox,
            100.0 * r.f64,
            if with_limit {
                let (l0, l1) = (r.limit.ste(0), r.limit.ste(1));
                format!(
                    " {:.2} | {:.2} | {:.2}% | {:.3}% / {:.3}% | {:.0}% |",
                    100.0 * l0,
                    100.0 * l1,
                    100.0 * per_f(l0 - l1, l1),
                    100.0 * per(r.limit.missed[0], r.limit.covered),
                    100.0 * per(r.limit.missed[1], r.limit.covered),
                    100.0 * per_f(ste(r, best_name) / 100.0, l1)
                )
            } else {
                String::new()
            },
            r.avg_area_px
        );
    }
    s += &format!(
        "\nCost per strategy (bounds tile 1×1, core {}): setup ops per triangle / ops per tile / row-span ops per tile / predicate ops per tested sample / all tile + row + predicate + sample-test ops per covered sample / core wall ms (\"per tile\": per bounds tile of the footprints, including the tiles a row span skips; the row-span ops of a row are spread over its tiles; core wall ms with no oracle, after one untimed warm-up frame per row, the fastest of {} frames at the quick size, {} at full size); Laine f64 ms = the f64 reference's frame, timed alike\n\n| Scene |",
        rows.first().map_or("-", |r| r.precision.as_str()),
        timing_runs(true),
        timing_runs(false)
    );
    for n in strategies() {
        s += &format!(" {n} |");
    }
    s += " Laine f64 ms |";
    s += if with_limit {
        " limit ms (search) |\n|---|"
    } else {
        "\n|---|"
    };
    s += &"---|".repeat(cols + 1 + usize::from(with_limit));
    s += "\n";
    for r in rows {
        s += &format!("| {} |", name_of(r));
        for x in &r.strategies {
            s += &format!(
                " {:.0} / {:.1} / {:.1} / {:.1} / {:.0} / {:.0} |",
                x.ops_setup(),
                x.ops_tile(),
                x.ops_row(),
                x.ops_predicate(),
                x.ops_per_covered(),
                x.ms
            );
        }
        s += &format!(" {:.0} |", r.f64_ms);
        s += &if with_limit {
            format!(" {:.0} |\n", r.limit_ms)
        } else {
            "\n".to_string()
        };
    }
    if rows.iter().any(|r| !r.tile_sweep.is_empty()) {
        s += "\nSTE (%) by bounds-tile size 1 / 2 / 4 / 8\n\n| Scene |";
        for n in strategies() {
            s += &format!(" {n} |");
        }
        s += "\n|---|";
        s += &"---|".repeat(cols);
        s += "\n";
        for r in rows.iter().filter(|r| !r.tile_sweep.is_empty()) {
            s += &format!("| {} |", name_of(r));
            for k in 0..cols {
                let v: Vec<String> = r
                    .tile_sweep
                    .iter()
                    .map(|t| {
                        t.get(k)
                            .map_or("-".into(), |x| format!("{:.2}", 100.0 * x.ste()))
                    })
                    .collect();
                s += &format!(" {} |", v.join(" / "));
            }
            s += "\n";
        }
    }
    s
}
