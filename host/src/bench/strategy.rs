//! One bounds strategy of the core over one frame, by name (the strategies of `uvt bench-ste`,
//! `uvt converge` and `uvt fit`'s search), at any precision, with its counters and wall time;
//! the configurations `--precision` accepts and their names.

use serde::Serialize;
use uvt_core::bounds::hyper::Hyper;
use uvt_core::bounds::lens_time::LensTime;
use uvt_core::bounds::registry::{best, hull, hull_edge, hull_lens, BEST_SLABS};
use uvt_core::bounds::strategy::BoundsStrategy;
use uvt_core::{Laine2011, Precision, Triangle, Viewport};

use crate::config::planar_static;
use crate::frame::counters::FrameStats;
use crate::frame::driver::{run, RunOpts};
use crate::frame::pipelines::Fixed;
use crate::scene::pattern::Pattern;

/// Strategy names in column order.
pub const STRATEGIES: [&str; 7] = [
    "laine2011",
    "hull",
    "lens-t",
    "hyper",
    "hull+lens-t",
    "hull+edge-t",
    "best",
];

/// The configurations `--precision` accepts (the session's names: `exact-P-T-B` is
/// `Prec<P, T, B>`, `bounded-P-T-B-O` is `Bounded<P, T, B, O>`), plus `default`.
pub const PRECISIONS: [&str; 8] = [
    "exact-16-16-16",
    "bounded-16-16-16-20",
    "bounded-16-16-16-22",
    "bounded-16-16-16-24",
    "bounded-12-12-12-24",
    "bounded-12-12-12-26",
    "bounded-8-8-8-28",
    planar_static::NAME,
];

/// The configuration name of precision `P` (`exact-P-T-B`, `bounded-P-T-B-O` or
/// `planar-P-T-B-O`).
pub fn precision_name<P: Precision>() -> String {
    let (p, t, b) = (P::POS_FRAC, P::TUV_FRAC, P::BOUND_FRAC);
    match P::OFFSET_SHIFT {
        None => format!("exact-{p}-{t}-{b}"),
        Some(o) if P::PLANAR => format!("planar-{p}-{t}-{b}-{o}"),
        Some(o) => format!("bounded-{p}-{t}-{b}-{o}"),
    }
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
    /// [`timing_runs`](super::ste_table::timing_runs) frames
    pub ms: f64,
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
    /// All per-tile, per-row, predicate and sample-test ops per covered sample.
    pub fn ops_per_covered(&self) -> f64 {
        let s = &self.stats;
        per(
            s.ops_bounds + s.ops_rows + s.ops_predicate + s.ops_sample,
            s.samples_covered,
        )
    }
}

/// `a / b`, 0 when `b` is 0.
pub(super) fn per(a: u64, b: u64) -> f64 {
    if b == 0 {
        0.0
    } else {
        a as f64 / b as f64
    }
}

/// Run strategy `name` over a frame: one of [`STRATEGIES`], "bbox", or "lens-t1", "lens-t2",
/// "lens-t8" (lens-slab time bounds with 1, 2, 8 slabs; "lens-t" has [`BEST_SLABS`]).
pub fn run_strategy(
    name: &str,
    vp: Viewport,
    tris: &[Triangle],
    pattern: &Pattern,
    o: &RunOpts<'_>,
) -> Option<StratResult> {
    run_strategy_image(name, vp, tris, pattern, o).map(|r| r.0)
}

/// [`run_strategy`] with the resolved image (empty unless `o.image`).
pub fn run_strategy_image(
    name: &str,
    vp: Viewport,
    tris: &[Triangle],
    pattern: &Pattern,
    o: &RunOpts<'_>,
) -> Option<(StratResult, Vec<[u8; 3]>)> {
    run_strategy_at::<uvt_core::DefaultPrecision>(name, vp, tris, pattern, o)
}

/// [`run_strategy_image`] at precision `P` (`tris` and `pattern` on `P`'s grids).
pub fn run_strategy_at<P: Precision + Sync>(
    name: &str,
    vp: Viewport,
    tris: &[Triangle],
    pattern: &Pattern,
    o: &RunOpts<'_>,
) -> Option<(StratResult, Vec<[u8; 3]>)> {
    fn go<B: BoundsStrategy + Sync, P: Precision + Sync>(
        s: B,
        vp: Viewport,
        tris: &[Triangle],
        pattern: &Pattern,
        o: &RunOpts<'_>,
    ) -> (StratResult, Vec<[u8; 3]>)
    where
        B::Coeffs: Send + Sync,
    {
        let name = s.name();
        let fixed = Fixed::<_, P> {
            prec: std::marker::PhantomData,
            strat: s,
            vp,
            tris,
            pattern,
        };
        let f = run(&fixed, pattern, o);
        let r = StratResult {
            name,
            tile: o.tile,
            stats: f.stats,
            ms: f.time.as_secs_f64() * 1e3,
        };
        (r, f.image)
    }
    Some(match name {
        "bbox" => go::<_, P>(uvt_core::BboxScan, vp, tris, pattern, o),
        "laine2011" => go::<_, P>(Laine2011, vp, tris, pattern, o),
        "hull" => go::<_, P>(hull(), vp, tris, pattern, o),
        "lens-t" => go::<_, P>(LensTime::<BEST_SLABS>, vp, tris, pattern, o),
        "lens-t1" => go::<_, P>(LensTime::<1>, vp, tris, pattern, o),
        "lens-t2" => go::<_, P>(LensTime::<2>, vp, tris, pattern, o),
        "lens-t8" => go::<_, P>(LensTime::<8>, vp, tris, pattern, o),
        "best" => go::<_, P>(best(), vp, tris, pattern, o),
        "hyper" => go::<_, P>(Hyper, vp, tris, pattern, o),
        "hull+lens-t" => go::<_, P>(hull_lens(), vp, tris, pattern, o),
        "hull+edge-t" => go::<_, P>(hull_edge(), vp, tris, pattern, o),
        _ => return None,
    })
}
