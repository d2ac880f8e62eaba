//! `uvt auto-rule`: derive the rule of the `auto` bounds strategy (`uvt_core::bounds::auto`)
//! from measured costs, and write it as `core/src/bounds/auto/rule.rs`.
//!
//! For every triangle of every row of the Cortex-M4F stage file
//! ([`super::m4_stages`]: the quick bench rows' own triangles, every `every`-th) and every
//! [`Pick`], the host runs the stage workload (`uvt_demo::workload::stage_one`: the same
//! counts the Cortex-M4F saw) and models the triangle's instructions as its counts times the
//! pick's per-call instructions for the triangle's class (pooled over the rows). Per class, the
//! rule is the tier (Laine 2011 below one footprint area, the hull from it, hull+edge-t from a
//! second, larger or equal area) with the least total over all rows, every pair of areas that
//! split the class's triangles tried; on a tie the larger areas (more Laine 2011, then more hull).

use std::collections::BTreeMap;
use std::fmt::Write as _;

use uvt_core::bounds::auto::{Pick, Tier};
use uvt_core::config::class::Class;
use uvt_core::units::select::PipelineOf;
use uvt_core::{with_strategy, DefaultPrecision, Full, Sample, SamplePattern};
use uvt_demo::workload::{stage_one, Workload};

use super::m4_stages::{M4Stages, PerCall};
use super::workload::bench_workload;
use crate::scene::builtin::{Bench, Blur};

/// One triangle: its class, footprint area and modelled instructions per pick.
#[derive(Clone, Copy, Debug)]
struct TriModel {
    class: usize,
    area: u32,
    cost: [f64; 3],
}

/// The chosen tier of one class with the totals that chose it.
#[derive(Clone, Copy, Debug)]
pub struct ClassRule {
    /// the tier
    pub tier: Tier,
    /// triangles of the class
    pub triangles: usize,
    /// modelled instructions with the tier, with Laine 2011 alone, with each pick alone
    pub with_rule: f64,
    /// each pick alone ([`Pick::ALL`] order)
    pub alone: [f64; 3],
}

/// Per-triangle models of one workload.
fn models(
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
            area: 0,
            cost: [0.0; 3],
        })
        .collect();
    for (k, pick) in Pick::ALL.iter().enumerate() {
        let done = with_strategy!(pick.name(), s => {
            let pipe = <PipelineOf<_, P, Full> as uvt_core::Pipeline>::new(s);
            for (m, tri) in out.iter_mut().zip(&tris) {
                let t = stage_one(&pipe, tri, h.vp, bt, &pattern, &mut || 0);
                let class = Class::ALL[m.class].name().to_string();
                let pc = per
                    .get(&(pick.name().to_string(), class.clone()))
                    .ok_or_else(|| anyhow::anyhow!("no figures for {} on class {class}", pick.name()))?;
                let c = &t.cost;
                m.cost[k] = pc.total(c.triangles, c.tiles, c.admits, c.tested);
                if let Some(fp) = t.footprint {
                    m.area = u32::from(fp.x1 - fp.x0) * u32::from(fp.y1 - fp.y0);
                }
            }
            Ok::<(), anyhow::Error>(())
        });
        done.ok_or_else(|| anyhow::anyhow!("{} is not a registry strategy", pick.name()))??;
    }
    Ok(out)
}

fn anyhow_of(e: uvt_demo::workload::FormatError) -> anyhow::Error {
    anyhow::anyhow!("{e}")
}

/// The best tier of one class's triangles (module docs): with the triangles sorted by area,
/// Laine 2011 on the first `i`, the hull on the next up to `j`, hull+edge-t on the rest, for every
/// `i ≤ j` at a change of area (or an end).
fn best_tier(tris: &mut [TriModel]) -> ClassRule {
    tris.sort_by_key(|t| t.area);
    let n = tris.len();
    let alone: [f64; 3] = [0, 1, 2].map(|k| tris.iter().map(|t| t.cost[k]).sum());
    // prefix[k][i]: pick k's total over the first i triangles.
    let prefix: [Vec<f64>; 3] = [0, 1, 2].map(|k| {
        let mut p = Vec::with_capacity(n + 1);
        p.push(0.0);
        for t in tris.iter() {
            p.push(p[p.len() - 1] + t.cost[k]);
        }
        p
    });
    // Where a threshold can fall (a threshold cannot split equal areas), largest first.
    let cuts: Vec<usize> = (0..=n)
        .rev()
        .filter(|&i| i == 0 || i == n || tris[i].area != tris[i - 1].area)
        .collect();
    let area_at = |i: usize| if i == n { u32::MAX } else { tris[i].area };
    let mut best = ClassRule {
        tier: Tier::LAINE,
        triangles: n,
        with_rule: alone[0],
        alone,
    };
    for &i in &cuts {
        for &j in cuts.iter().filter(|&&j| j >= i) {
            let total =
                prefix[0][i] + (prefix[1][j] - prefix[1][i]) + (prefix[2][n] - prefix[2][j]);
            // Strictly less: on a tie the earlier candidate (larger areas) stays.
            if total < best.with_rule - 1e-6 * best.with_rule.abs() {
                best.tier = Tier {
                    hull_from: if i == j { u32::MAX } else { area_at(i) },
                    edge_from: area_at(j),
                };
                best.with_rule = total;
            }
        }
    }
    best
}

/// Derive the rule from the stage file `m4` (module docs).
pub fn derive(m4: &M4Stages) -> anyhow::Result<[ClassRule; 4]> {
    let per = m4.per_class();
    let mut by_class: [Vec<TriModel>; 4] = Default::default();
    for r in &m4.rows {
        let kind = Bench::from_name(&r.scene)?;
        let row = Blur::from_name(&r.row)?;
        eprintln!("auto-rule: {} {}", r.scene, r.row);
        let bytes = bench_workload(kind, row, true, r.every)?;
        let w = Workload::parse(&bytes).map_err(anyhow_of)?;
        for m in models(&w, &per)? {
            by_class[m.class].push(m);
        }
    }
    Ok(by_class.map(|mut v| best_tier(&mut v)))
}

/// The source of `core/src/bounds/auto/rule.rs` for `rules`, derived from the file at `from`.
pub fn rule_source(rules: &[ClassRule; 4], from: &str) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "//! The rule of the `auto` bounds strategy (`mod.rs`), per triangle class. Generated by\n\
         //! `uvt auto-rule` from\n\
         //! `{from}`\n\
         //! (Cortex-M4F instructions per stage and strategy on the quick bench rows' own\n\
         //! triangles); do not edit. Modelled instructions over those triangles, per class\n\
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
            from(Pick::HullEdge, r.tier.edge_from),
        ]
        .into_iter()
        .flatten()
        .collect();
        let rule = if parts.is_empty() {
            "laine2011".to_string()
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
            "    Tier {{\n        hull_from: {},\n        edge_from: {},\n    }},",
            px(r.tier.hull_from),
            px(r.tier.edge_from)
        );
    }
    s += "];\n";
    s
}
