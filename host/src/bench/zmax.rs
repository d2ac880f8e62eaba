//! `uvt bench-zmax`: every bounds strategy with and without Zmax culling
//! (`uvt_core::raster::zmax`) on the occlusion rows (the game street behind a near fence,
//! [`Bench::Occluded`]) and, for contrast, the game rows without the fence: sample tests, tiles
//! skipped, the whole operation count (setup, tiles, rows, predicates, sample tests and Zmax's
//! own floors, reads and comparisons), the whole Cortex-M4F instructions (the same parts, each
//! count times its instructions per call measured on the Cortex-M4F: the occlusion rows' own
//! triangles in `host/report/m4_zmax.json`, the game rows' in `host/report/m4_strategies.json`,
//! Zmax's calls from the occlusion rows) and wall time, each pair checked for an identical image.

use anyhow::{bail, Result};
use serde::Serialize;
use uvt_core::{NoZmax, Precision, Zmax};

use crate::frame::opts::RunOpts;
use crate::scene::builtin::{bench_scene, Bench, Blur};
use crate::scene::pattern::Pattern;

use super::m4_stages::{committed, committed_zmax, PerCall, Size, ZmaxPerCall};
use super::strategy::{run_strategy_at, strategies, StratResult};

/// The rows: the occluded street and the open street, static, motion, defocus and both.
pub const ROWS: [(Bench, Blur); 8] = [
    (Bench::Occluded, Blur::Static),
    (Bench::Occluded, Blur::Motion),
    (Bench::Occluded, Blur::Defocus),
    (Bench::Occluded, Blur::Both),
    (Bench::Game, Blur::Static),
    (Bench::Game, Blur::Motion),
    (Bench::Game, Blur::Defocus),
    (Bench::Game, Blur::Both),
];

/// One strategy on one row, without and with Zmax.
#[derive(Clone, Debug, Serialize)]
pub struct Pair {
    /// without Zmax
    pub off: StratResult,
    /// with Zmax
    pub on: StratResult,
}

impl Pair {
    /// Sample tests saved by Zmax, as a fraction of those without it.
    pub fn saved(&self) -> f64 {
        1.0 - ratio(self.on.stats.samples_tested, self.off.stats.samples_tested)
    }
    /// Kept bounds tiles Zmax skipped, as a fraction of the kept tiles.
    pub fn culled(&self) -> f64 {
        let s = &self.on.stats;
        ratio(s.tiles_zculled, s.tiles_visited - s.tiles_skipped)
    }
}

/// Every strategy's pair on one row.
#[derive(Clone, Debug, Serialize)]
pub struct ZmaxRow {
    /// scene
    pub scene: Bench,
    /// row
    pub row: Blur,
    /// viewport
    pub viewport: (u16, u16),
    /// triangles
    pub triangles: usize,
    /// per strategy, in the bench's order
    pub pairs: Vec<Pair>,
}

fn ratio(a: u64, b: u64) -> f64 {
    if b == 0 {
        0.0
    } else {
        a as f64 / b as f64
    }
}

/// Whole operations of a run: setup (incl. the strategy's preparation), tiles, rows,
/// predicates, sample tests and Zmax.
pub fn whole_ops(r: &StratResult) -> u64 {
    let s = &r.stats;
    s.ops_setup + s.ops_bounds + s.ops_rows + s.ops_predicate + s.ops_sample + s.ops_zmax
}

/// The per-call Cortex-M4F figures of `name` on row (`kind`, `row`) at `size` and Zmax's: the
/// row's own at that size where measured (the occlusion rows in `m4_zmax.json`, the game rows in `m4_strategies.json`),
/// Zmax's pooled over the occlusion rows where the row has none.
fn per_call(kind: Bench, row: Blur, size: Size, name: &str) -> Result<(PerCall, ZmaxPerCall)> {
    let (z, file) = (committed_zmax()?, committed()?);
    let src = if kind == Bench::Occluded { z } else { file };
    let Some(r) = src.row(kind.name(), &row.name(), size) else {
        bail!(
            "no Cortex-M4F figures for row {} {} at the {} size",
            kind.name(),
            row.name(),
            size.name()
        );
    };
    let (Some(pc), Some(zc)) = (
        r.per_call(name),
        r.zmax_per_call().or_else(|| z.zmax_pooled()),
    ) else {
        bail!(
            "no Cortex-M4F figures for {name} on {} {}",
            kind.name(),
            row.name()
        );
    };
    Ok((pc, zc))
}

/// The whole Cortex-M4F instructions of run `r` (with or without Zmax).
fn m4_whole(r: &StratResult, (pc, zc): &(PerCall, ZmaxPerCall), zmax: bool) -> f64 {
    let s = &r.stats;
    let own = if zmax {
        let visible = s.by_class.iter().sum();
        zc.total(
            visible,
            s.tiles_visited - s.tiles_skipped,
            s.samples_written,
        )
    } else {
        0.0
    };
    r.m4_of(pc) + own
}

/// Run every row at precision `P` (`quick`: the quarter size). Fails if an image differs with
/// Zmax, or Zmax tests more samples than without it, or a row lacks its Cortex-M4F figures.
pub fn run_rows<P: Precision + Sync>(quick: bool) -> Result<Vec<ZmaxRow>> {
    let mut out = Vec::new();
    for (kind, row) in ROWS {
        let s = bench_scene(kind, row, quick);
        let (tris, pattern): (_, Pattern) = s.inputs_at::<P>()?;
        let colors = s.colors();
        let mut pairs = Vec::new();
        for name in strategies() {
            let o = RunOpts {
                image: true,
                ..RunOpts::for_scene(&s, &colors)
            };
            let vp = s.core_viewport();
            // Each side twice, the faster frame kept (the first warms the caches); the
            // counters and the image of both are the same (deterministic).
            let faster = |x: (StratResult, Vec<[u8; 3]>), y: (StratResult, Vec<[u8; 3]>)| {
                if y.0.ms < x.0.ms {
                    y
                } else {
                    x
                }
            };
            let go = || run_strategy_at::<P, NoZmax>(name, vp, &tris, &pattern, &o);
            let (mut off, a) = faster(go()?, go()?);
            let go = || run_strategy_at::<P, Zmax>(name, vp, &tris, &pattern, &o);
            let (mut on, b) = faster(go()?, go()?);
            let pc = per_call(kind, row, Size::of(quick), name)?;
            off.m4 = Some(m4_whole(&off, &pc, false));
            on.m4 = Some(m4_whole(&on, &pc, true));
            if a != b {
                let at = a.iter().zip(&b).position(|(x, y)| x != y);
                bail!(
                    "{} {name}: the image differs with Zmax (first pixel {at:?})",
                    s.name
                );
            }
            if on.stats.samples_tested > off.stats.samples_tested {
                bail!("{} {name}: Zmax tested more samples", s.name);
            }
            pairs.push(Pair { off, on });
        }
        out.push(ZmaxRow {
            scene: kind,
            row,
            viewport: s.viewport,
            triangles: s.tris.len(),
            pairs,
        });
    }
    Ok(out)
}

/// The Markdown table: per row and strategy, samples tested without / with Zmax and the saving,
/// kept tiles skipped, the ratio of whole ops with / without, whole Cortex-M4F instructions
/// without / with per covered sample of the run without Zmax (the same visible work; with Zmax
/// fewer samples are covered because fewer are tested) and their ratio, and wall ms (the faster
/// of two frames each).
pub fn table_md(rows: &[ZmaxRow]) -> String {
    let mut s = String::from(
        "| row | strategy | tested | tested, Zmax | saved | tiles skipped | ops ratio | \
         M4 / covered | M4 / covered, Zmax | M4 ratio | ms | ms, Zmax | image |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n",
    );
    for r in rows {
        for (i, p) in r.pairs.iter().enumerate() {
            let label = if i == 0 {
                format!("{} {}", r.scene.name(), r.row.label())
            } else {
                String::new()
            };
            let cov = p.off.stats.samples_covered.max(1) as f64;
            let (a, b) = (whole_ops(&p.off) as f64, whole_ops(&p.on) as f64);
            let (ma, mb) = (p.off.m4.unwrap_or(0.0), p.on.m4.unwrap_or(0.0));
            s += &format!(
                "| {label} | {} | {} | {} | {:.1}% | {:.1}% | {:.3} | {:.0} | {:.0} | {:.3} | {:.1} | {:.1} | same |\n",
                p.off.name,
                p.off.stats.samples_tested,
                p.on.stats.samples_tested,
                100.0 * p.saved(),
                100.0 * p.culled(),
                b / a.max(1.0),
                ma / cov,
                mb / cov,
                mb / ma.max(1.0),
                p.off.ms,
                p.on.ms,
            );
        }
    }
    s
}
