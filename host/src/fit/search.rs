//! The strategy and tile-size search of `uvt fit` (on the bench machinery's counters) and the
//! scene's inputs on a configuration's grids.
//!
//! **Cost of a bounds strategy and tile size** (from the bench machinery's counters, one frame
//! of the scene at the chosen configuration): the whole Cortex-M4F instructions, setup included —
//! triangles × instructions per setup + visited tiles × per tile + samples of kept tiles × per
//! sample through the box and predicate + sample tests × per test, the per-call figures of the
//! strategy measured on the bench rows' own triangles and pooled over them
//! ([`crate::bench::m4_stages`], the same figures `bench-ste`'s whole-cost table uses; measured
//! at the default configuration and bounds tile 1). Beside it, the width-weighted ops figure:
//! `setup ops + tile-bounds ops + per-sample predicate ops + sample tests × s`, with `s` the
//! counted operations per sample test times the sample test's width factor
//! `Σ bit-products / (products · 32 · 32)` of the chosen unit and configuration. Every strategy
//! covers the same samples (bounds are conservative), so the score — covered samples per
//! instruction — ranks by whole cost; ties go to the earlier strategy of
//! [`crate::bench::strategy::strategies`] (the registry's order) and the smaller tile.

use serde::Serialize;
use uvt_core::config::registry::Config;
use uvt_core::{with_config, NoZmax, Precision, Triangle};

use crate::bench::strategy::{run_strategy_at, strategies};
use crate::frame::opts::RunOpts;
use crate::scene::file::Scene;
use crate::scene::pattern::Pattern;

use super::select::TILES;

/// One strategy and tile size of the search.
#[derive(Clone, Debug, Serialize)]
pub struct StratCost {
    /// strategy name
    pub strategy: String,
    /// bounds-tile size
    pub tile: u8,
    /// STE (covered / tested)
    pub ste: f64,
    /// samples covered
    pub covered: u64,
    /// samples tested
    pub tested: u64,
    /// setup ops (incl. the strategy's preparation)
    pub ops_setup: u64,
    /// tile-bounds ops
    pub ops_tile: u64,
    /// per-sample predicate ops
    pub ops_predicate: u64,
    /// counted ops per sample test
    pub ops_per_test: f64,
    /// width-weighted ops (module docs)
    pub ops_cost: f64,
    /// whole Cortex-M4F instructions, setup included (module docs)
    pub cost: f64,
    /// covered samples per instruction of `cost`
    pub score: f64,
}

/// Run every strategy at every tile size at configuration `config`; `width` is the sample
/// test's width factor. `None` for a configuration outside the registry.
pub fn search_strategies(
    scene: &Scene,
    config: Config,
    width: f64,
) -> Option<anyhow::Result<Vec<StratCost>>> {
    with_config!(config, P => search_at::<P>(scene, width))
}

fn search_at<P: Precision + Sync>(scene: &Scene, width: f64) -> anyhow::Result<Vec<StratCost>> {
    let (core, pat) = inputs::<P>(scene)?;
    let colors = scene.colors();
    let mut out = Vec::new();
    for name in strategies() {
        for tile in TILES {
            let o = RunOpts {
                tile,
                ..RunOpts::for_scene(scene, &colors)
            };
            let (r, _) =
                run_strategy_at::<P, NoZmax>(name, scene.core_viewport(), &core, &pat, &o)?;
            let s = &r.stats;
            let per_test = s.ops_sample as f64 / s.samples_tested.max(1) as f64;
            let ops_cost = (s.ops_setup + s.ops_bounds + s.ops_predicate) as f64
                + s.samples_tested as f64 * per_test * width;
            let cost = crate::bench::m4_stages::committed()?
                .pooled(name)
                .ok_or_else(|| anyhow::anyhow!("no Cortex-M4F stage figures for {name}"))?
                .total(
                    s.triangles,
                    s.tiles_visited,
                    s.samples_admitted,
                    s.samples_tested,
                );
            out.push(StratCost {
                strategy: name.to_string(),
                tile,
                ste: s.ste(),
                covered: s.samples_covered,
                tested: s.samples_tested,
                ops_setup: s.ops_setup,
                ops_tile: s.ops_bounds,
                ops_predicate: s.ops_predicate,
                ops_per_test: per_test,
                ops_cost,
                cost,
                score: s.samples_covered as f64 / cost.max(1.0),
            });
        }
    }
    Ok(out)
}

/// The scene's core triangles and sample table on `P`'s grids ([`Scene::inputs_at`]).
pub(crate) fn inputs<P: Precision>(scene: &Scene) -> anyhow::Result<(Vec<Triangle>, Pattern)> {
    scene.inputs_at::<P>()
}
