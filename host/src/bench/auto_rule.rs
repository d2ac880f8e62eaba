//! `uvt auto-rule`: derive the rule of the `auto` bounds strategy (`uvt_core::bounds::auto`)
//! from measured costs, and write it as `core/src/bounds/auto/rule.rs`.
//!
//! For every triangle of every row of the Cortex-M4F stage file
//! ([`super::m4_stages`]: the bench rows' own triangles at both sizes, every `every`-th: about
//! as many triangles per row at either size) and every [`Pick`], the host runs the stage
//! workload (`uvt_demo::workload::stage_one`: the same counts the Cortex-M4F saw) and models the
//! triangle's instructions as its counts times the pick's per-call instructions **on that row**
//! (a tile, an admit or a sample test costs differently on the two sizes and the two scenes:
//! figures pooled over a class's rows put game motion ×2 at full size at 0.87× Laine 2011's,
//! the row's own at 0.97×); it also counts the samples each pick tests and the samples `best`
//! tests. Per class, the rule is a tier (Laine 2011 below one area of the triangle's own
//! extent, `Auto::area`, the hull from it, hull+edge-t from a second, larger or equal area,
//! with a travel limit of [`TRAVEL_LIMITS`] or none: hull+edge-t only for triangles whose own
//! extent is at most that many times their own box at the shutter's start, `Auto::start_area`,
//! the hull for the others), chosen among every pair of areas that split the class's triangles
//! and every limit by, in turn:
//!
//! 1. the most rows **within the cost cap**: modelled instructions at most [`COST_CAP`] × the
//!    row's cheapest pick's alone;
//! 2. the most rows that keep the class's sample-test efficiency at least [`STE_FLOOR`] of
//!    `best`'s (tested samples ≤ `best`'s ÷ [`STE_FLOOR`]; covered samples are the same for every
//!    strategy);
//! 3. the most rows at most Laine 2011's alone;
//! 4. the least total over all rows; on a tie the larger areas (more Laine 2011, then more hull)
//!    and no travel limit (no start box to compute).
//!
//! Cost comes first (the bench holds `auto` to 1.05× the cheapest fixed strategy on every row),
//! then the efficiency the bench asks on the game rows, then Laine 2011: on the dense defocus
//! rows no tier is measurably below it (the hull pays on too few of their triangles), and
//! holding them to it would take the hull off the game defocus rows' large triangles. The
//! rule's source names every row with its cost ratios, and whether it is within the cap and
//! holds the floor.
//!
//! Beside each row it gives what no rule can beat, with hindsight over every fixed strategy
//! ([`super::hindsight`], on the same models): every triangle on its cheapest, ÷ Laine 2011's
//! alone — where that is 1.000, no per-triangle choice of these strategies is below Laine 2011
//! on the row — and the most sample-test efficiency ÷ `best`'s any per-triangle choice reaches
//! within [`GOAL_CAP`] × the row's cheapest fixed strategy alone — where that is under 0.90, the
//! bench's efficiency goal and its cost goal cannot both hold on the row.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use uvt_core::bounds::auto::{Auto, Pick, Tier};
use uvt_core::config::class::Class;
use uvt_core::setup::{setup, Outcome};
use uvt_core::stats::Ops;
use uvt_core::units::select::PipelineOf;
use uvt_core::{with_strategy, BoundsStrategy, DefaultPrecision, Full, Sample, SamplePattern};
use uvt_demo::workload::{stage_one, Workload};

use super::hindsight::{least_cost, least_tested_within, Choice};
use super::m4_stages::{M4Stages, PerCall};
use super::strategy::fixed;
use super::workload::bench_workload;
use crate::scene::builtin::{Bench, Blur};

/// The least share of `best`'s sample-test efficiency the rule keeps on every row of a class where
/// some tier reaches it (module docs). 92%, above the 90% the bench holds `auto` to: the model
/// counts every `every`-th triangle of a row, so a rule that met 90% in the model exactly (game
/// motion, 0.900) measured 89.7% on the whole row.
pub const STE_FLOOR: f64 = 0.92;

/// The most a row may cost with the rule, as a multiple of its cheapest pick alone (module docs).
/// 1.03, below the 1.05 the bench holds `auto` to: the model prices every `every`-th triangle
/// of a row with the row's average per-call figures, and `auto` adds its own pick to each setup.
pub const COST_CAP: f64 = 1.03;

/// The bench's goal for `auto`'s whole instructions on every row: at most 1.05 × the cheapest
/// fixed strategy's; the hindsight bounds are taken at it (module docs).
pub const GOAL_CAP: f64 = 1.05;

/// The limits tried for a tier's `edge_travel` (own extent ÷ own box at the shutter's start
/// that keeps hull+edge-t), no limit first: on a tie the rule reads no start box.
pub const TRAVEL_LIMITS: [u32; 10] = [u32::MAX, 1, 2, 3, 4, 5, 6, 8, 12, 16];

/// One triangle: its class, row (index in the stage file), area (`Auto::area`) and area at
/// the shutter's start (`Auto::start_area`), modelled instructions and tested samples per pick
/// and per fixed strategy ([`super::strategy::fixed`] order), and the samples `best` tests.
#[derive(Clone, Debug)]
struct TriModel {
    class: usize,
    row: usize,
    area: u32,
    start: u32,
    cost: [f64; 3],
    tested: [f64; 3],
    fixed: Vec<Choice>,
    best_tested: f64,
}

/// The chosen tier of one class with the totals that chose it.
#[derive(Clone, Debug)]
pub struct ClassRule {
    /// the tier
    pub tier: Tier,
    /// triangles of the class
    pub triangles: usize,
    /// modelled instructions with the tier, with Laine 2011 alone, with each pick alone
    pub with_rule: f64,
    /// each pick alone ([`Pick::ALL`] order)
    pub alone: [f64; 3],
    /// the class's triangles per row, with the rule
    pub rows: Vec<RowFit>,
}

/// A class's triangles on one row of the stage file, with the rule.
#[derive(Clone, Debug)]
pub struct RowFit {
    /// scene and row (`game motion`)
    pub row: String,
    /// modelled instructions with the rule ÷ with Laine 2011 alone
    pub cost_vs_laine: f64,
    /// modelled instructions with the rule ÷ with the row's cheapest pick alone
    pub cost_vs_cheapest: f64,
    /// whether the rule keeps the row within the cost cap (module docs)
    pub within: bool,
    /// sample-test efficiency with the rule ÷ `best`'s
    pub ste_vs_best: f64,
    /// whether the rule keeps [`STE_FLOOR`] of `best`'s efficiency on the row
    pub held: bool,
    /// with hindsight, every triangle on its cheapest fixed strategy: modelled instructions ÷
    /// Laine 2011's alone (no per-triangle choice costs less)
    pub least_vs_laine: f64,
    /// with hindsight, the most sample-test efficiency ÷ `best`'s of any per-triangle choice of
    /// fixed strategies within [`GOAL_CAP`] × the row's cheapest fixed strategy alone (an upper
    /// bound: [`least_tested_within`]; `None` if a triangle had no figures)
    pub most_ste_vs_best: Option<f64>,
}

/// Per-triangle models of one workload.
fn models(
    row: usize,
    w: &Workload<'_>,
    per: &BTreeMap<(String, String), PerCall>,
) -> anyhow::Result<Vec<TriModel>> {
    type P = DefaultPrecision;
    let samples: Vec<Sample> = w.samples().collect::<Result<_, _>>().map_err(anyhow_of)?;
    let h = w.header();
    let pattern = SamplePattern::new_with::<P>(h.block, h.spp, &samples)
        .map_err(|e| anyhow::anyhow!("workload sample table: {e}"))?;
    let bt = u16::from(h.bounds_tile);
    let tris: Vec<_> = w
        .triangles::<P>()
        .collect::<Result<_, _>>()
        .map_err(anyhow_of)?;
    let mut out: Vec<TriModel> = tris
        .iter()
        .map(|t| TriModel {
            class: t.class().index(),
            row,
            area: 0,
            start: 0,
            cost: [0.0; 3],
            tested: [0.0; 3],
            fixed: Vec::new(),
            best_tested: 0.0,
        })
        .collect();
    let best_name = uvt_core::bounds::registry::best().name();
    for name in fixed() {
        let done = with_strategy!(name, s => {
            let pipe = <PipelineOf<_, P, Full> as uvt_core::Pipeline>::new(s);
            for (m, tri) in out.iter_mut().zip(&tris) {
                let t = stage_one(&pipe, tri, h.vp, bt, &pattern, &mut || 0);
                let class = Class::ALL[m.class].name().to_string();
                let pc = per
                    .get(&(name.to_string(), class.clone()))
                    .ok_or_else(|| anyhow::anyhow!("no figures for {name} on class {class}"))?;
                let c = &t.cost;
                m.fixed.push(Choice {
                    cost: pc.total(c.triangles, c.tiles, c.admits, c.tested),
                    tested: c.tested as f64,
                });
            }
            Ok::<(), anyhow::Error>(())
        });
        done.ok_or_else(|| anyhow::anyhow!("{name} is not a registry strategy"))??;
    }
    let at = |n: &str| {
        fixed()
            .position(|f| f == n)
            .ok_or_else(|| anyhow::anyhow!("{n} is not a fixed strategy"))
    };
    let picks = Pick::ALL.map(|p| at(p.name()));
    let best_at = at(best_name)?;
    for m in &mut out {
        for (k, p) in picks.iter().enumerate() {
            let x = m.fixed[*p.as_ref().map_err(|e| anyhow::anyhow!("{e}"))?];
            m.cost[k] = x.cost;
            m.tested[k] = x.tested;
        }
        m.best_tested = m.fixed[best_at].tested;
    }
    // The area the rule ranks by: the core's own (`Auto::area`).
    for (m, tri) in out.iter_mut().zip(&tris) {
        if let Outcome::Visible(s) = setup::<P, Full>(tri, h.vp, &mut Ops::default()) {
            m.area = Auto::area(&s);
            m.start = Auto::start_area(&s, &mut Ops::default());
        }
    }
    Ok(out)
}

fn anyhow_of(e: uvt_demo::workload::FormatError) -> anyhow::Error {
    anyhow::anyhow!("{e}")
}

/// Prefix sums over `tris` (in order) of `f`, restricted to the triangles of `row` when given.
fn prefix(tris: &[TriModel], row: Option<usize>, f: impl Fn(usize, &TriModel) -> f64) -> Vec<f64> {
    let mut p = Vec::with_capacity(tris.len() + 1);
    p.push(0.0);
    for (i, t) in tris.iter().enumerate() {
        let x = if row.map_or(true, |r| r == t.row) {
            f(i, t)
        } else {
            0.0
        };
        p.push(p[p.len() - 1] + x);
    }
    p
}

/// A tier's ranking (module docs): rows within the cost cap, held to the floor, at most Laine
/// 2011's; then the total, negated (more is better throughout).
type Goal = ([usize; 3], f64);

/// Whether goal `c` ranks above `g` (the total by more than a relative 1e-6).
fn beats(c: &Goal, g: &Goal) -> bool {
    c.0 > g.0 || (c.0 == g.0 && c.1 > g.1 + 1e-6 * g.1.abs())
}

/// Per row of a class (stage-file index), with hindsight over every fixed strategy (module
/// docs; the same at every tier, so computed once): every triangle on its cheapest, and the
/// fewest samples tested within [`GOAL_CAP`] × the row's cheapest fixed strategy alone.
type RowHindsight = BTreeMap<usize, (f64, Option<f64>)>;

/// [`RowHindsight`] of `tris`.
fn hindsight(tris: &[TriModel]) -> RowHindsight {
    let mut rows: BTreeMap<usize, Vec<Vec<Choice>>> = BTreeMap::new();
    for t in tris {
        rows.entry(t.row).or_default().push(t.fixed.clone());
    }
    rows.into_iter()
        .map(|(row, choices)| {
            let alone = (0..choices.first().map_or(0, Vec::len))
                .map(|k| {
                    choices
                        .iter()
                        .filter_map(|c| c.get(k))
                        .map(|x| x.cost)
                        .sum()
                })
                .fold(f64::INFINITY, f64::min);
            let fewest = least_tested_within(&choices, GOAL_CAP * alone * (1.0 + 1e-9));
            (row, (least_cost(&choices), fewest))
        })
        .collect()
}

/// The best tier of one class's triangles over every limit of [`TRAVEL_LIMITS`] (module docs):
/// [`best_tier_at`] at each, the first of the best kept.
fn best_tier(tris: &mut [TriModel]) -> ClassRule {
    let alone: [f64; 3] = [0, 1, 2].map(|k| tris.iter().map(|t| t.cost[k]).sum());
    let hind = hindsight(tris);
    let mut best: Option<(ClassRule, Goal)> = None;
    for k in TRAVEL_LIMITS {
        let c = best_tier_at(tris, k, &hind);
        if best.as_ref().map_or(true, |b| beats(&c.1, &b.1)) {
            best = Some(c);
        }
    }
    let (mut r, _) = best.unwrap_or_else(|| best_tier_at(tris, u32::MAX, &hind));
    r.alone = alone;
    r
}

/// The best tier of one class's triangles at `edge_travel` (module docs): with the triangles
/// sorted by area, Laine 2011 on the first `i`, the hull on the next up to `j`, hull+edge-t
/// (the hull where the travel limit turns it off, `Tier::pick_travel`) on the rest, for every
/// `i ≤ j` at a change of area (or an end); the most rows within the cost cap, then held to
/// [`STE_FLOOR`], then at most Laine 2011's, then the least total.
fn best_tier_at(tris: &mut [TriModel], edge_travel: u32, hind: &RowHindsight) -> (ClassRule, Goal) {
    tris.sort_by_key(|t| t.area);
    let limited = Tier {
        hull_from: u32::MAX,
        edge_from: 0,
        edge_travel,
    };
    // The upper pick per triangle: hull+edge-t, or the hull past the travel limit.
    let upper: Vec<usize> = tris
        .iter()
        .map(|t| match limited.pick_travel(t.area, t.start) {
            Pick::HullEdge => 2,
            _ => 1,
        })
        .collect();
    let cost_of = |t: &TriModel, u: usize, k: usize| if k == 2 { t.cost[u] } else { t.cost[k] };
    let tested_of =
        |t: &TriModel, u: usize, k: usize| if k == 2 { t.tested[u] } else { t.tested[k] };
    let n = tris.len();
    let alone: [f64; 3] = [0, 1, 2].map(|k| {
        tris.iter()
            .zip(&upper)
            .map(|(t, &u)| cost_of(t, u, k))
            .sum()
    });
    let mut rows: Vec<usize> = tris.iter().map(|t| t.row).collect();
    rows.sort_unstable();
    rows.dedup();
    // Prefix sums per pick k over the first i triangles: instructions (all rows, and per row)
    // and tested samples per row (rows of the class in stage-file order).
    let cost: [Vec<f64>; 3] = [0, 1, 2].map(|k| prefix(tris, None, |i, t| cost_of(t, upper[i], k)));
    let per_row = |f: &dyn Fn(&TriModel, usize, usize) -> f64| -> Vec<[Vec<f64>; 3]> {
        rows.iter()
            .map(|&r| [0, 1, 2].map(|k| prefix(tris, Some(r), |i, t| f(t, upper[i], k))))
            .collect()
    };
    let row_cost = per_row(&cost_of);
    let tested = per_row(&tested_of);
    // Per row: Laine 2011's instructions, the cheapest pick's alone (each pick on every
    // triangle, the travel limit aside), the cap (COST_CAP × the cheapest's), and the most
    // tested samples that keep STE_FLOOR of best's efficiency.
    let laine: Vec<f64> = row_cost.iter().map(|p| p[0][n]).collect();
    let cheapest: Vec<f64> = rows
        .iter()
        .map(|&r| {
            [0, 1, 2]
                .map(|k| {
                    tris.iter()
                        .filter(|t| t.row == r)
                        .map(|t| t.cost[k])
                        .sum::<f64>()
                })
                .into_iter()
                .fold(f64::INFINITY, f64::min)
        })
        .collect();
    let cap: Vec<f64> = cheapest
        .iter()
        .map(|&c| COST_CAP * c * (1.0 + 1e-9))
        .collect();
    let allowed: Vec<f64> = rows
        .iter()
        .map(|&r| {
            let best: f64 = tris
                .iter()
                .filter(|t| t.row == r)
                .map(|t| t.best_tested)
                .sum();
            best / STE_FLOOR
        })
        .collect();
    // Where a threshold can fall (a threshold cannot split equal areas), largest first.
    let cuts: Vec<usize> = (0..=n)
        .rev()
        .filter(|&i| i == 0 || i == n || tris[i].area != tris[i - 1].area)
        .collect();
    let area_at = |i: usize| if i == n { u32::MAX } else { tris[i].area };
    let split =
        |p: &[Vec<f64>; 3], i: usize, j: usize| p[0][i] + (p[1][j] - p[1][i]) + (p[2][n] - p[2][j]);
    let within = |r: usize, i: usize, j: usize| split(&row_cost[r], i, j) <= cap[r];
    let held = |r: usize, i: usize, j: usize| split(&tested[r], i, j) <= allowed[r];
    let below = |r: usize, i: usize, j: usize| split(&row_cost[r], i, j) <= laine[r] * (1.0 + 1e-9);
    // Rows within the cap, held to the floor, at most Laine 2011's; then the total (negated:
    // more is better throughout).
    let goal = |i: usize, j: usize| -> Goal {
        let count = |f: &dyn Fn(usize) -> bool| (0..rows.len()).filter(|&r| f(r)).count();
        (
            [
                count(&|r| within(r, i, j)),
                count(&|r| held(r, i, j)),
                count(&|r| below(r, i, j)),
            ],
            -split(&cost, i, j),
        )
    };
    // (n, n) is Laine 2011 alone; on a tie the earlier candidate (larger areas) stays.
    let (mut i, mut j) = (n, n);
    let mut g = goal(n, n);
    for &a in &cuts {
        for &b in cuts.iter().filter(|&&b| b >= a) {
            let c = goal(a, b);
            if beats(&c, &g) {
                (i, j, g) = (a, b, c);
            }
        }
    }
    let fits = rows
        .iter()
        .enumerate()
        .map(|(r, &row)| {
            let (least, fewest) = hind.get(&row).copied().unwrap_or((0.0, None));
            let best = allowed[r] * STE_FLOOR;
            let t = split(&tested[r], i, j);
            let c = split(&row_cost[r], i, j);
            let ratio = |d: f64| if d > 0.0 { c / d } else { 1.0 };
            RowFit {
                // best_tier names a row by its stage-file index (`derive` names it).
                row: row.to_string(),
                cost_vs_laine: ratio(laine[r]),
                cost_vs_cheapest: ratio(cheapest[r]),
                within: within(r, i, j),
                ste_vs_best: if t > 0.0 {
                    allowed[r] * STE_FLOOR / t
                } else {
                    1.0
                },
                held: held(r, i, j),
                least_vs_laine: if laine[r] > 0.0 {
                    least / laine[r]
                } else {
                    1.0
                },
                most_ste_vs_best: fewest.map(|f| if f > 0.0 { best / f } else { 1.0 }),
            }
        })
        .collect();
    let edge_from = area_at(j);
    (
        ClassRule {
            tier: Tier {
                hull_from: if i == j { u32::MAX } else { area_at(i) },
                edge_from,
                // A limit without hull+edge-t picks nothing: none.
                edge_travel: if edge_from == u32::MAX {
                    u32::MAX
                } else {
                    edge_travel
                },
            },
            triangles: n,
            with_rule: -g.1,
            alone,
            rows: fits,
        },
        g,
    )
}

/// Derive the rule from the stage file `m4` (module docs).
pub fn derive(m4: &M4Stages) -> anyhow::Result<[ClassRule; 4]> {
    let mut by_class: [Vec<TriModel>; 4] = Default::default();
    for (k, r) in m4.rows.iter().enumerate() {
        let kind = Bench::from_name(&r.scene)?;
        let row = Blur::from_name(&r.row)?;
        crate::log::line(&format!(
            "auto-rule: {} {} ({})",
            r.scene,
            r.row,
            r.size.name()
        ));
        let per = r.per_class();
        let bytes = bench_workload(kind, row, r.size.is_quick(), r.every)?;
        let w = Workload::parse(&bytes).map_err(anyhow_of)?;
        for m in models(k, &w, &per)? {
            by_class[m.class].push(m);
        }
    }
    let names: Vec<String> = m4
        .rows
        .iter()
        .map(|r| format!("{} {} ({})", r.scene, r.row, r.size.name()))
        .collect();
    Ok(by_class.map(|mut v| {
        let mut rule = best_tier(&mut v);
        for f in &mut rule.rows {
            if let Some(name) = f.row.parse::<usize>().ok().and_then(|k| names.get(k)) {
                f.row = name.clone();
            }
        }
        rule
    }))
}

/// The source of `core/src/bounds/auto/rule.rs` for `rules`, derived from the file at `from`.
pub fn rule_source(rules: &[ClassRule; 4], from: &str) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "//! The rule of the `auto` bounds strategy (`mod.rs`), per triangle class. Generated by\n\
         //! `uvt auto-rule` from\n\
         //! `{from}`\n\
         //! (Cortex-M4F instructions per stage and strategy on the bench rows' own triangles at\n\
         //! both sizes); do not edit. Modelled instructions over those triangles, per class\n\
         //! (millions): with the rule, and with Laine 2011, hull, hull+edge-t alone.\n//!"
    );
    let _ = writeln!(
        s,
        "//! | class | triangles | rule | with the rule | laine2011 | hull | hull+edge-t |"
    );
    let _ = writeln!(s, "//! |---|---|---|---|---|---|---|");
    for (c, r) in Class::ALL.iter().zip(rules) {
        let from =
            |p: Pick, px: u32| (px != u32::MAX).then(|| format!("{} from {px} px", p.name()));
        let parts: Vec<String> = [
            from(
                Pick::Hull,
                if r.tier.hull_from < r.tier.edge_from {
                    r.tier.hull_from
                } else {
                    u32::MAX
                },
            ),
            from(Pick::HullEdge, r.tier.edge_from).map(|e| {
                if r.tier.reads_travel() {
                    format!("{e} (own extent ≤ {}× its start box)", r.tier.edge_travel)
                } else {
                    e
                }
            }),
        ]
        .into_iter()
        .flatten()
        .collect();
        let rule = if parts.is_empty() {
            Pick::Laine.name().to_string()
        } else {
            parts.join(", ")
        };
        let _ = writeln!(
            s,
            "//! | {} | {} | {rule} | {:.1} | {:.1} | {:.1} | {:.1} |",
            c.name(),
            r.triangles,
            r.with_rule / 1e6,
            r.alone[0] / 1e6,
            r.alone[1] / 1e6,
            r.alone[2] / 1e6
        );
    }
    let _ = writeln!(
        s,
        "//!\n//! Per class and row, with the rule: modelled instructions ÷ Laine 2011's alone and ÷ the\n\
         //! row's cheapest pick's alone (cap: {COST_CAP} × the cheapest's),\n\
         //! and sample-test efficiency ÷ `best`'s (floor: at least {:.0}% of `best`'s). Beside them\n\
         //! what no rule can beat, with hindsight over every fixed strategy (`host/src/bench/\n\
         //! hindsight.rs`): every triangle on its cheapest, ÷ Laine 2011's alone (\"least ÷\n\
         //! Laine\"), and the most STE ÷ `best`'s of any choice within {GOAL_CAP} × the row's\n\
         //! cheapest fixed strategy alone, the bench's goal (\"most STE ÷ best\", an upper bound).\n//!\n\
         //! | class | row | instructions ÷ Laine 2011 | ÷ cheapest pick | cap | STE ÷ best | floor | least ÷ Laine | most STE ÷ best |\n\
         //! |---|---|---|---|---|---|---|---|---|",
        STE_FLOOR * 100.0
    );
    for (c, r) in Class::ALL.iter().zip(rules) {
        for f in &r.rows {
            let floor = if f.held { "held" } else { "not held" };
            let cap = if f.within { "within" } else { "over" };
            let _ = writeln!(
                s,
                "//! | {} | {} | {:.3} | {:.3} | {cap} | {:.3} | {floor} | {:.3} | {} |",
                c.name(),
                f.row,
                f.cost_vs_laine,
                f.cost_vs_cheapest,
                f.ste_vs_best,
                f.least_vs_laine,
                f.most_ste_vs_best
                    .map_or("-".to_string(), |v| format!("{v:.3}"))
            );
        }
    }
    let _ = writeln!(s, "\nuse crate::bounds::auto::tier::Tier;\n");
    let _ = writeln!(
        s,
        "/// One tier per class ([`crate::config::class::Class::index`] order)."
    );
    let _ = writeln!(s, "pub const RULE: [Tier; 4] = [");
    let px = |v: u32| {
        if v == u32::MAX {
            "u32::MAX".to_string()
        } else {
            v.to_string()
        }
    };
    for r in rules {
        let _ = writeln!(
            s,
            "    Tier {{\n        hull_from: {},\n        edge_from: {},\n        edge_travel: {},\n    }},",
            px(r.tier.hull_from),
            px(r.tier.edge_from),
            px(r.tier.edge_travel)
        );
    }
    s += "];\n";
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A triangle of row `row` at `area` px: instructions and tested samples per pick, and the
    /// samples `best` tests.
    fn tri(row: usize, area: u32, cost: [f64; 3], tested: [f64; 3], best: f64) -> TriModel {
        TriModel {
            class: 1,
            row,
            area,
            start: 0,
            cost,
            tested,
            // The fixed strategies: the three picks stand in for them.
            fixed: (0..3)
                .map(|k| Choice {
                    cost: cost[k],
                    tested: tested[k],
                })
                .collect(),
            best_tested: best,
        }
    }

    /// Row 0's least-total tier: the hull from 20 px.
    const LEAST_TOTAL: Tier = Tier {
        hull_from: 20,
        edge_from: u32::MAX,
        edge_travel: u32::MAX,
    };

    /// Row 0: the least total takes the hull from 20 px (57 instructions) but tests 260 samples,
    /// over best's 150 ÷ STE_FLOOR; hull+edge-t everywhere tests 150 and costs 59, under Laine 2011's 60.
    fn row0() -> Vec<TriModel> {
        vec![
            tri(0, 10, [10.0, 11.0, 11.0], [100.0, 80.0, 50.0], 50.0),
            tri(0, 20, [20.0, 19.0, 19.0], [100.0, 80.0, 50.0], 50.0),
            tri(0, 30, [30.0, 28.0, 29.0], [100.0, 80.0, 50.0], 50.0),
        ]
    }

    #[test]
    fn the_floor_takes_a_dearer_tier_that_keeps_best_s_efficiency() {
        let mut t = row0();
        let r = best_tier(&mut t);
        assert_eq!(
            r.tier,
            Tier {
                hull_from: u32::MAX,
                edge_from: 10,
                edge_travel: u32::MAX,
            },
            "{r:?}"
        );
        assert_eq!(r.with_rule, 59.0);
        assert!(
            r.rows[0].held && (r.rows[0].ste_vs_best - 1.0).abs() < 1e-12,
            "{r:?}"
        );
        assert!(
            (r.rows[0].cost_vs_laine - 59.0 / 60.0).abs() < 1e-12,
            "{r:?}"
        );
    }

    #[test]
    fn hindsight_gives_the_cheapest_mix_and_the_most_efficiency_within_the_goal() {
        // Every triangle on its cheapest: 10 + 19 + 28 = 57 of Laine 2011's 60. Within 1.05 ×
        // the cheapest fixed strategy alone (the hull, 58: 60.9), hull+edge-t everywhere (59,
        // testing best's 150) is reachable.
        let mut t = row0();
        let r = best_tier(&mut t);
        assert!(
            (r.rows[0].least_vs_laine - 57.0 / 60.0).abs() < 1e-12,
            "{r:?}"
        );
        assert!(
            (r.rows[0].most_ste_vs_best.unwrap() - 1.0).abs() < 1e-12,
            "{r:?}"
        );
        // hull+edge-t dearer by 2 per triangle (65): the hull everywhere (58, 240 tests), then
        // the steps to hull+edge-t at the best rate (15 samples per instruction, on two
        // triangles) for the 2.9 instructions left: 240 − 2.9 × 15 = 196.5 tested (the budget's
        // 1e-9 slack aside).
        for x in &mut t {
            x.cost[2] += 2.0;
            x.fixed[2].cost += 2.0;
        }
        let r = best_tier(&mut t);
        let want = 150.0 / (240.0 - 2.9 * 15.0);
        assert!(
            (r.rows[0].most_ste_vs_best.unwrap() - want).abs() < 1e-6,
            "{r:?} want {want}"
        );
    }

    #[test]
    fn without_a_floor_within_reach_the_least_total_stays() {
        // hull+edge-t dearer: everywhere 61 > Laine 2011's 60, so no tier holds the floor.
        let mut t = row0();
        for x in &mut t {
            x.cost[2] += 1.0;
        }
        let r = best_tier(&mut t);
        assert_eq!(r.tier, LEAST_TOTAL, "{r:?}");
        assert_eq!(r.with_rule, 57.0);
        assert!(!r.rows[0].held, "{r:?}");
    }

    #[test]
    fn holding_one_row_never_makes_another_dearer_than_laine() {
        // Row 1's large triangle costs twice Laine 2011's with hull+edge-t: every tier that
        // holds row 0 puts it there, so row 0 stays unheld and the least total is taken.
        let mut t = row0();
        t.push(tri(1, 40, [10.0, 10.0, 20.0], [10.0, 10.0, 10.0], 10.0));
        let r = best_tier(&mut t);
        assert_eq!(r.tier, LEAST_TOTAL, "{r:?}");
        assert!(!r.rows[0].held && r.rows[1].held, "{r:?}");
        assert!(r.rows[1].cost_vs_laine <= 1.0, "{r:?}");
    }

    #[test]
    fn the_cost_cap_comes_before_the_floor() {
        // The hull costs half Laine 2011's; hull+edge-t alone holds the floor (50 tested, best's
        // 50) but costs 1.2× the hull's, over COST_CAP: the hull everywhere, the floor not held.
        let mut t: Vec<TriModel> = (1..=3)
            .map(|k| tri(0, 10 * k, [100.0, 50.0, 60.0], [100.0, 80.0, 50.0], 50.0))
            .collect();
        let r = best_tier(&mut t);
        assert_eq!(
            r.tier,
            Tier {
                hull_from: 10,
                edge_from: u32::MAX,
                edge_travel: u32::MAX,
            },
            "{r:?}"
        );
        assert!(r.rows[0].within && !r.rows[0].held, "{r:?}");
        assert!((r.rows[0].cost_vs_cheapest - 1.0).abs() < 1e-12, "{r:?}");
        // Within the cap (hull+edge-t at 1.02× the hull's), the floor takes hull+edge-t.
        for x in &mut t {
            x.cost[2] = 51.0;
        }
        let r = best_tier(&mut t);
        assert_eq!(r.tier.edge_from, 10, "{r:?}");
        assert!(r.rows[0].within && r.rows[0].held, "{r:?}");
    }
}
