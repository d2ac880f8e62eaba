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
use uvt_core::{with_config, Laine2011, NoZmax, Precision, Triangle};

use crate::config::names;

use crate::frame::opts::RunOpts;
use crate::frame::reference::run_reference;
use crate::oracle::limit::{axis_aligned_limit, Limit, Method};
use crate::oracle::search::Effort;
use crate::scene::builtin::{bench_scene, Bench, Blur};
use crate::scene::pattern::Pattern;

use super::m4_stages::{per, M4Stages, Size};
use super::strategy::{run_strategy_at, strategies, StratResult};

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
    /// frames timed per strategy and for the reference, the fastest kept ([`timing`])
    pub rounds: usize,
    /// STE of the f64 reference (Laine 2011 in f64)
    pub f64: f64,
    /// wall ms of the f64 reference's frame (its own loop, `crate::frame::reference`; the
    /// fastest of as many frames as the row's strategies got, [`timing`])
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

/// Run the benchmark table at the default precision, the frames timed by `timing` (`bench-ste`:
/// [`timing`]; [`Timing::ONCE`] where only the counts matter); `sweep` adds the bounds-tile sweep
/// 1, 2, 4, 8; `effort` (low and high: dense points per pixel, face-search proposals per face)
/// adds the axis-aligned limit.
pub fn run_table(
    quick: bool,
    timing: Timing,
    scenes: &[Bench],
    rows: &[Blur],
    sweep: bool,
    effort: Option<[Effort; 2]>,
) -> anyhow::Result<Vec<BenchRow>> {
    let stages = stage_file().ok().flatten();
    rows_at::<uvt_core::DefaultPrecision>(quick, timing, scenes, rows, sweep, effort, stages)
}

/// The committed Cortex-M4F stage costs ([`super::m4_stages::committed`]).
pub fn stage_file() -> anyhow::Result<Option<&'static M4Stages>> {
    super::m4_stages::committed().map(Some)
}

/// [`run_table`] with the core at the configuration named `precision` (a name of the registry
/// or "default", [`names::precision`]); an unknown name is an error naming the valid ones.
pub fn run_table_at(
    precision: &str,
    quick: bool,
    timing: Timing,
    scenes: &[Bench],
    rows: &[Blur],
    sweep: bool,
    effort: Option<[Effort; 2]>,
) -> anyhow::Result<Vec<BenchRow>> {
    let cfg = names::precision("--precision", precision)?;
    run_table_of(cfg, quick, timing, scenes, rows, sweep, effort)
}

/// [`run_table`] with the core at configuration `cfg` (one of the registry's; `with_config!`
/// has every one).
pub fn run_table_of(
    cfg: Config,
    quick: bool,
    timing: Timing,
    scenes: &[Bench],
    rows: &[Blur],
    sweep: bool,
    effort: Option<[Effort; 2]>,
) -> anyhow::Result<Vec<BenchRow>> {
    let stages = stage_file()?;
    with_config!(cfg, P => rows_at::<P>(quick, timing, scenes, rows, sweep, effort, stages))
        .ok_or_else(|| anyhow::anyhow!("configuration {cfg} is not in the registry"))?
}

/// Frames timed per strategy (at bounds tile 1) and for the reference, the fastest kept: one
/// frame alone is at the mercy of the scheduler (single frames of one strategy vary by ±15–30%
/// on the 2-core machine). At least 5 rounds at the quick size, whose frames take tens of
/// milliseconds (with 3, one row's fastest core frame came out 1.06× the reference's where 10
/// frames each gave 0.85×), 2 at full size (up to ~45 s per frame); then more rounds, up to
/// [`Timing::max_rounds`], while the row's timed frames have taken less than
/// [`Timing::budget_s`] (the short rows get the most rounds). The budgets are 12 s / 60 s: with
/// 6 s / 30 s a full-size row of 2 s frames got 2 rounds, and two strategies doing the same work
/// (Laine 2011 and lens-t on dense defocus ×2, identical counts) came out 1644 and 1834 ms.
#[derive(Clone, Copy, Debug)]
pub struct Timing {
    /// rounds always taken
    pub min_rounds: usize,
    /// more rounds while the row's timed frames so far took less than this (seconds)
    pub budget_s: f64,
    /// at most this many rounds
    pub max_rounds: usize,
}

impl Timing {
    /// One frame per strategy (the tile sweep's runs; tests that read the counts only).
    pub const ONCE: Timing = Timing {
        min_rounds: 1,
        budget_s: 0.0,
        max_rounds: 1,
    };
}

/// The frames `bench-ste` times per row ([`Timing`]) at the quick or the full size.
pub fn timing(quick: bool) -> Timing {
    if quick {
        Timing {
            min_rounds: 5,
            budget_s: 12.0,
            max_rounds: 40,
        }
    } else {
        Timing {
            min_rounds: 2,
            budget_s: 60.0,
            max_rounds: 10,
        }
    }
}

/// The rows at precision `P`; `stages` (measured at the default configuration) gives the whole
/// Cortex-M4F cost of each tile-1 run at that configuration.
fn rows_at<P: Precision + Sync>(
    quick: bool,
    timing: Timing,
    scenes: &[Bench],
    rows: &[Blur],
    sweep: bool,
    effort: Option<[Effort; 2]>,
    stages: Option<&M4Stages>,
) -> anyhow::Result<Vec<BenchRow>> {
    let stages = stages.filter(|_| Config::of::<P>().same(&uvt_core::config::registry::DEFAULT));
    let mut out = Vec::new();
    let total = scenes.len() * rows.len();
    for &kind in scenes {
        for &row in rows {
            // Progress as plain lines on stderr (readable in logs, not only on a terminal).
            crate::log::line(&format!(
                "bench-ste: row {} of {total}: {kind:?} {}",
                out.len() + 1,
                row.label()
            ));
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
            // One untimed warm-up frame per row (Laine 2011) before anything
            // is timed: otherwise the first timed frame of a new scene pays the allocator's heap
            // growth (page faults over tens of MiB at full size) and whichever pipeline runs
            // first is penalised.
            run_strategy_at::<P, NoZmax>(
                Laine2011.name(),
                vp,
                &core_p,
                &pattern_p,
                &RunOpts {
                    tile: 1,
                    ..o.clone()
                },
            )?;
            // The frames are taken in rounds, every strategy once per round, so that a machine
            // slowing down or speeding up during a row does not favour the strategies run first;
            // `timed` rounds at least, more while the row's frames took less than `budget_s`.
            // Returns the strategies (fastest frame each) and the rounds taken.
            let at = |tile: u8, timed: Timing| -> anyhow::Result<(Vec<StratResult>, usize)> {
                let o = RunOpts { tile, ..o.clone() };
                let frame = |n: &str| run_strategy_at::<P, NoZmax>(n, vp, &core_p, &pattern_p, &o);
                let start = std::time::Instant::now();
                let mut out: Vec<StratResult> = strategies()
                    .map(|n| frame(n).map(|r| r.0))
                    .collect::<anyhow::Result<_>>()?;
                let mut rounds = 1;
                while rounds < timed.max_rounds
                    && (rounds < timed.min_rounds || start.elapsed().as_secs_f64() < timed.budget_s)
                {
                    for best in &mut out {
                        let (again, _) = frame(best.name)?;
                        best.ms = best.ms.min(again.ms);
                    }
                    rounds += 1;
                }
                Ok((out, rounds))
            };
            let (mut strategies, rounds) = at(1, timing)?;
            // The whole cost: this run's counts times the row's instructions per call.
            let stage_row = stages.and_then(|m| m.row(kind.name(), &row.name(), Size::of(quick)));
            for x in &mut strategies {
                x.m4 = stage_row
                    .and_then(|r| r.per_call(x.name))
                    .map(|pc| x.m4_of(&pc));
            }
            let tile_sweep = if sweep {
                let mut v = vec![strategies.clone()];
                for t in [2u8, 4, 8] {
                    v.push(at(t, Timing::ONCE)?.0);
                }
                v
            } else {
                Vec::new()
            };
            let r = run_reference(&s.tris, &pattern, &o);
            let f64_ms = (1..rounds)
                .map(|_| run_reference(&s.tris, &pattern, &o).time)
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
                rounds,
                f64: r.stats.ste(),
                f64_ms,
                limit,
                limit_ms,
                tile_sweep,
            });
        }
    }
    Ok(out)
}

fn name_of(r: &BenchRow) -> String {
    if r.row == Blur::Static {
        match r.scene {
            Bench::Game => "GAME",
            Bench::Dense => "DENSE",
            Bench::Occluded => "OCCLUDED",
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
        "\nCost per strategy (bounds tile 1×1, core {}): setup ops per triangle / ops per tile / row-span ops per tile / predicate ops per tested sample / all tile + row + predicate + sample-test ops per covered sample / core wall ms (\"per tile\": per bounds tile of the footprints, including the tiles a row span skips; the row-span ops of a row are spread over its tiles; core wall ms with no oracle, after one untimed warm-up frame per row, the fastest of the frames taken in rounds of every strategy once: at least {} rounds at the quick size, {} at full size, then more while the row's frames took less than {} s / {} s, at most {} / {} rounds; this run: {} rounds); Laine f64 ms = the f64 reference's frame, timed alike\n\n| Scene |",
        rows.first().map_or("-", |r| r.precision.as_str()),
        timing(true).min_rounds,
        timing(false).min_rounds,
        timing(true).budget_s,
        timing(false).budget_s,
        timing(true).max_rounds,
        timing(false).max_rounds,
        {
            let (lo, hi) = rows.iter().fold((usize::MAX, 0), |(lo, hi), r| {
                (lo.min(r.rounds), hi.max(r.rounds))
            });
            if lo == hi { lo.to_string() } else { format!("{lo}–{hi}") }
        }
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
    s += &whole_cost_md(rows);
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

/// Spearman's rank correlation of `a` and `b` (average ranks for ties; 0 for fewer than 2
/// values or a constant side).
pub fn spearman(a: &[f64], b: &[f64]) -> f64 {
    fn ranks(x: &[f64]) -> Vec<f64> {
        let mut idx: Vec<usize> = (0..x.len()).collect();
        idx.sort_by(|&i, &j| x[i].total_cmp(&x[j]));
        let mut r = vec![0.0; x.len()];
        let mut i = 0;
        while i < idx.len() {
            let mut j = i;
            while j + 1 < idx.len() && x[idx[j + 1]] == x[idx[i]] {
                j += 1;
            }
            for &k in &idx[i..=j] {
                r[k] = (i + j) as f64 / 2.0 + 1.0;
            }
            i = j + 1;
        }
        r
    }
    let n = a.len().min(b.len());
    if n < 2 {
        return 0.0;
    }
    let (ra, rb) = (ranks(&a[..n]), ranks(&b[..n]));
    let mean = (n as f64 + 1.0) / 2.0;
    let (mut sab, mut saa, mut sbb) = (0.0, 0.0, 0.0);
    for (x, y) in ra.iter().zip(&rb) {
        sab += (x - mean) * (y - mean);
        saa += (x - mean) * (x - mean);
        sbb += (y - mean) * (y - mean);
    }
    if saa == 0.0 || sbb == 0.0 {
        0.0
    } else {
        sab / (saa * sbb).sqrt()
    }
}

/// The whole-cost table: per strategy the modelled Cortex-M4F instructions per covered sample
/// with setup included and the core wall ms; `auto` against the cheapest fixed strategy and
/// Laine 2011; the rank correlation of whole cost and wall time per row and over every row (each
/// strategy's cost and time divided by Laine 2011's in the same row), beside the same for the
/// ops column without setup. Empty when no row has stage figures.
pub fn whole_cost_md(rows: &[BenchRow]) -> String {
    let with: Vec<&BenchRow> = rows
        .iter()
        .filter(|r| r.strategies.iter().all(|x| x.m4.is_some()))
        .collect();
    if with.is_empty() {
        return String::new();
    }
    let laine = Laine2011.name();
    let auto = uvt_core::bounds::auto::Auto::new().name();
    let mut s = String::from(
        "\nWhole cost per strategy (bounds tile 1×1): Cortex-M4F instructions per covered sample, setup included (this run's counts of triangles, tiles, samples through the box and predicate and sample tests, times the instructions per call measured on the row's own triangles at this size by `bash demo/m4_report.sh --strategies`, host/report/m4_strategies.json) / core wall ms; cheapest = the fixed strategy (every one but auto) with the fewest instructions; ρ = Spearman rank correlation over the row's strategies of whole instructions and wall ms (\"ops ρ\": of the cost table's ops per covered sample without setup, and wall ms)\n\n| Scene |"
    );
    for n in strategies() {
        s += &format!(" {n} |");
    }
    s += " cheapest fixed | auto ÷ cheapest | auto ÷ Laine (M4) | auto ÷ Laine (ms) | ρ | ops ρ |\n|---|";
    s += &"---|".repeat(strategies().count() + 6);
    s += "\n";
    let (mut all_m4, mut all_ms, mut all_ops) = (Vec::new(), Vec::new(), Vec::new());
    for r in &with {
        let m4 = |n: &str| r.strat(n).and_then(|x| x.m4_per_covered()).unwrap_or(0.0);
        let ms = |n: &str| r.strat(n).map_or(0.0, |x| x.ms);
        s += &format!("| {} |", name_of(r));
        for x in &r.strategies {
            s += &format!(" {:.0} / {:.0} |", x.m4_per_covered().unwrap_or(0.0), x.ms);
        }
        let cheapest = r
            .strategies
            .iter()
            .filter(|x| super::strategy::fixed().any(|f| f == x.name))
            .min_by(|a, b| {
                a.m4.unwrap_or(f64::MAX)
                    .total_cmp(&b.m4.unwrap_or(f64::MAX))
            });
        let (cn, cv) = cheapest.map_or(("-", 0.0), |x| (x.name, x.m4_per_covered().unwrap_or(0.0)));
        let (v_m4, v_ms, v_ops): (Vec<f64>, Vec<f64>, Vec<f64>) = (
            r.strategies.iter().map(|x| x.m4.unwrap_or(0.0)).collect(),
            r.strategies.iter().map(|x| x.ms).collect(),
            r.strategies.iter().map(|x| x.ops_per_covered()).collect(),
        );
        let (l_m4, l_ms, l_ops) = (
            r.strat(laine).and_then(|x| x.m4).unwrap_or(1.0),
            ms(laine),
            r.strat(laine).map_or(1.0, |x| x.ops_per_covered()),
        );
        all_m4.extend(v_m4.iter().map(|v| per_f(*v, l_m4)));
        all_ms.extend(v_ms.iter().map(|v| per_f(*v, l_ms)));
        all_ops.extend(v_ops.iter().map(|v| per_f(*v, l_ops)));
        s += &format!(
            " {cn} | {:.3} | {:.3} | {:.3} | {:.2} | {:.2} |\n",
            per_f(m4(auto), cv),
            per_f(m4(auto), m4(laine)),
            per_f(ms(auto), ms(laine)),
            spearman(&v_m4, &v_ms),
            spearman(&v_ops, &v_ms)
        );
    }
    s += &format!(
        "\nOver every row (each strategy's whole instructions and wall ms divided by Laine 2011's in its row, {} points): ρ = {:.2}; ops ρ = {:.2}.\n",
        all_m4.len(),
        spearman(&all_m4, &all_ms),
        spearman(&all_ops, &all_ms)
    );
    s
}
