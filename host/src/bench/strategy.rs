//! One bounds strategy of the core over one frame, by its registry name
//! ([`uvt_core::bounds::registry::STRATEGIES`]; the strategies of `uvt bench-ste`, `uvt
//! converge`, `uvt fit`'s search and `uvt render --bounds`), at any precision, with its counters
//! and wall time.

use anyhow::{anyhow, Result};
use serde::Serialize;
use uvt_core::bounds::auto::Auto;
use uvt_core::bounds::registry::STRATEGIES;
use uvt_core::bounds::strategy::BoundsStrategy;
use uvt_core::{
    with_strategy, BboxScan, DepthCull, Engine, Full, General, NoZmax, Precision, SamplePattern,
    Triangle, Viewport,
};

use crate::frame::core_frame::run_core;
use crate::frame::counters::{Frame, FrameStats};
use crate::frame::opts::RunOpts;
use crate::scene::pattern::Pattern;

use super::m4_stages::per;

/// The strategies of `bench-ste`'s columns and of `uvt fit`'s search, in the registry's order:
/// every strategy of [`STRATEGIES`] but the bounding-box scan (the bench's baseline column
/// comes from every run's footprint counters; fit does not search it).
pub fn strategies() -> impl Iterator<Item = &'static str> + Clone {
    STRATEGIES.into_iter().filter(|n| *n != BboxScan.name())
}

/// The fixed strategies: every one of [`strategies`] but `auto`, the per-triangle choice among
/// them (the bench's "cheapest fixed" and `uvt auto-rule`'s hindsight bounds range over these).
pub fn fixed() -> impl Iterator<Item = &'static str> + Clone {
    strategies().filter(|n| *n != Auto::new().name())
}

/// One strategy's result on one row.
#[derive(Clone, Debug, Serialize)]
pub struct StratResult {
    /// strategy name
    pub name: &'static str,
    /// bounds-tile size
    pub tile: u8,
    /// counters
    pub stats: FrameStats,
    /// wall ms of the frame (no oracle); in `bench-ste`'s tile-1 runs the fastest of
    /// the frames [`timing`](super::ste_table::timing) takes
    pub ms: f64,
    /// the frame's whole modelled Cortex-M4F instructions, setup included (this run's counts
    /// times the row's measured instructions per call, [`super::m4_stages`]); `None` where no
    /// figures exist (other rows, other tiles)
    pub m4: Option<f64>,
}

impl StratResult {
    /// STE covered / tested.
    pub fn ste(&self) -> f64 {
        self.stats.ste()
    }
    /// Bounds ops per visited tile.
    pub fn ops_tile(&self) -> f64 {
        per(self.stats.ops_bounds, self.stats.tiles_visited)
    }
    /// Row-span ops (`BoundsStrategy::row_span`) per footprint tile (the same divisor as
    /// [`Self::ops_tile`], so tile + row is the strategy's whole tile-walk cost per tile).
    pub fn ops_row(&self) -> f64 {
        per(self.stats.ops_rows, self.stats.tiles_visited)
    }
    /// Setup ops (incl. the strategy's preparation) per submitted triangle.
    pub fn ops_setup(&self) -> f64 {
        per(self.stats.ops_setup, self.stats.triangles)
    }
    /// Predicate ops per tested sample.
    pub fn ops_predicate(&self) -> f64 {
        per(self.stats.ops_predicate, self.stats.samples_tested)
    }
    /// The whole modelled Cortex-M4F instructions (setup included) per covered sample.
    pub fn m4_per_covered(&self) -> Option<f64> {
        self.m4.map(|x| {
            if self.stats.samples_covered == 0 {
                0.0
            } else {
                x / self.stats.samples_covered as f64
            }
        })
    }
    /// The whole modelled Cortex-M4F instructions of this frame from per-call figures `pc`.
    pub fn m4_of(&self, pc: &super::m4_stages::PerCall) -> f64 {
        let s = &self.stats;
        pc.total(
            s.triangles,
            s.tiles_visited,
            s.samples_admitted,
            s.samples_tested,
        )
    }
    /// All per-tile, per-row, predicate and sample-test ops per covered sample.
    pub fn ops_per_covered(&self) -> f64 {
        let s = &self.stats;
        per(
            s.ops_bounds + s.ops_rows + s.ops_predicate + s.ops_sample,
            s.samples_covered,
        )
    }
}

/// Run strategy `name` (one of [`STRATEGIES`]) over a frame at the default precision, without
/// Zmax: its counters, wall time and resolved image (empty unless `o.image`).
pub fn run_strategy_image(
    name: &str,
    vp: Viewport,
    tris: &[Triangle],
    pattern: &Pattern,
    o: &RunOpts<'_>,
) -> Result<(StratResult, Vec<[u8; 3]>)> {
    run_strategy_at::<uvt_core::DefaultPrecision, NoZmax>(name, vp, tris, pattern, o)
}

/// [`run_strategy_image`] at precision `P` (`tris` and `pattern` on `P`'s grids) with Zmax
/// culling `Z`; an error names a strategy outside the registry.
pub fn run_strategy_at<P: Precision + Sync, Z: DepthCull>(
    name: &str,
    vp: Viewport,
    tris: &[Triangle],
    pattern: &Pattern,
    o: &RunOpts<'_>,
) -> Result<(StratResult, Vec<[u8; 3]>)> {
    with_strategy!(name, s => run_one::<_, P, Z>(s, vp, tris, pattern, o)).ok_or_else(|| {
        anyhow!(
            "unknown bounds strategy {name:?} (one of {})",
            STRATEGIES.join(", ")
        )
    })?
}

/// One frame of strategy `s` at precision `P` with Zmax culling `Z`: its counters, wall time
/// and image.
pub fn run_one<B: BoundsStrategy + Sync, P: Precision + Sync, Z: DepthCull>(
    s: B,
    vp: Viewport,
    tris: &[Triangle],
    pattern: &Pattern,
    o: &RunOpts<'_>,
) -> Result<(StratResult, Vec<[u8; 3]>)>
where
    B::Coeffs: Send + Sync,
{
    let name = s.name();
    let f = run_frame::<B, P, Z>(s, vp, tris, pattern, o)?;
    let r = StratResult {
        name,
        tile: o.tile,
        stats: f.stats,
        ms: f.time.as_secs_f64() * 1e3,
        m4: None,
    };
    Ok((r, f.image))
}

/// The core's frame ([`run_core`]: the core's own loop in bands) of the full unit's general
/// pipeline with strategy `s` at precision `P` and Zmax culling `Z`: the one instance per
/// strategy and precision that the bench, fit's search, converge and `uvt render` share.
pub fn run_frame<B: BoundsStrategy + Sync, P: Precision + Sync, Z: DepthCull>(
    s: B,
    vp: Viewport,
    tris: &[Triangle],
    pattern: &Pattern,
    o: &RunOpts<'_>,
) -> Result<Frame>
where
    B::Coeffs: Send + Sync,
{
    let engine = Engine::<General<B, P, Full>, Z>::new(s, vp);
    let table = SamplePattern::new_with::<P>(pattern.block, pattern.spp, &pattern.quant)
        .map_err(|e| anyhow!("sample table: {e}"))?;
    run_core(&engine, tris, &table, o).map_err(|e| anyhow!("{e}"))
}
