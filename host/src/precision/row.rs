//! One row of `uvt precision`'s table ([`PrecRow`]: the errors and costs of one configuration at
//! one bounds-tile size), the configurations swept by default ([`CONFIGS`]) and the documented
//! d_q.
//!
//! Per configuration (`exact-P-T-B` = `Prec<P, T, B>`, the exact sample test;
//! `bounded-P-T-B-O` = `Bounded<P, T, B, O>`, the hardware-width test of `core/src/sample/bounded/`)
//! the scene's exact f64 triangles are rounded to the position grid, the pattern's t/u/v to the
//! t/u/v grid (sub-pixel stays 8 bits), and the core runs at that precision. The reference always
//! runs on the exact values.
//!
//! **d_q** (the documented distance within which a decision may differ because of the bounded
//! datapath's rounding): the bounded test is exact on vertices perturbed by at most
//! `k/2 + 2^(O−1)/(256·E)` raw in x (E = W) and y (E = H) and `1/2` raw in w (`bounded.rs`,
//! class both: k = 3). A vertex in view (|x/w| ≤ 1) at depth w therefore moves on screen by at
//! most `(k/2 + 1/2 + 2^(O−1)/(256·E))·E/(2^17·w)` px = `(2E + 2^(O−9))/(2^17·w)` px per axis;
//! both axes move together, so d_q is the Euclidean length of the two at w = 1 (0 for the exact
//! test; before issue 24 it was their maximum, which a 45° edge can exceed). It covers the datapath's rounding
//! only: the inputs' rounding to the position and t/u/v grids adds its own (bounded per sample
//! by `compare.rs`'s rigorous check, which here includes the perturbation as an extra position
//! rounding).
//!
//! **Every differing decision is counted under its primitive's error statement**
//! (`crate::config::dq`: the input rounding and the datapath perturbation together, per
//! primitive): *beyond d_q* counts those of primitives stated in pixels that lie farther than the
//! primitive's own d_q from an edge (must be 0); the others are stated in clip space only (a
//! vertex can reach the camera plane) and are counted with their largest backward error δ, those
//! whose δ is not small against the primitive (`crate::config::dq::Statement::informative`)
//! apart; `compare.rs`'s per-sample check (*beyond bound*) tests the clip
//! statement on every differing decision.

use serde::Serialize;

use crate::config::names::{swept_count, swept_names};

/// What `uvt precision` runs without `--configs`, read from the registry: the precision sweep
/// (`uvt_core::config::registry::sweep`: exact, then bounded from the default down to the
/// narrowest), then the planar static configuration (`registry::PLANAR`).
pub const CONFIGS: [&str; swept_count(true)] = swept_names(true);

/// The documented d_q (module docs) of offset shift `off` on a `w`×`h` viewport, px at w = 1.
pub fn d_q_px(off: Option<u32>, w: u16, h: u16) -> f64 {
    let Some(o) = off else { return 0.0 };
    let at = |e: f64| (2.0 * e + 2f64.powi(o as i32 - 9)) / 131072.0;
    // x and y move together: the Euclidean length of the two axes' bounds.
    at(w as f64).hypot(at(h as f64))
}

/// Errors and costs of one configuration at one bounds-tile size, summed over the scenes.
#[derive(Clone, Debug, Default, Serialize, serde::Deserialize)]
#[serde(default)]
pub struct PrecRow {
    /// configuration name (`exact-16-16-16`, `bounded-16-16-16-20`, …); an old report's
    /// `[POS, TUV, BND]` reads as `exact-POS-TUV-BND` (the exact test in the wide containers)
    #[serde(deserialize_with = "config_name")]
    pub config: String,
    /// bounds-tile size
    pub tile: u8,
    /// median over frames of (core wall time / reference wall time) in the same run
    pub time_ratio_median: f64,
    /// core operations per setup, per tile, per sample test
    pub ops: [f64; 3],
    /// (triangle, sample) decisions compared
    pub compared: u64,
    /// decisions differing from the reference
    pub differ: u64,
    /// largest distance (px) of a differing sample from the nearest edge
    pub max_differ_px: f64,
    /// differing samples that no input rounding at this precision explains
    /// (`compare::check_sample`; must be 0)
    pub beyond_bound: u64,
    /// largest quantization-check ratio of a differing sample (≤ 1 when `beyond_bound` is 0)
    pub max_ratio: f64,
    /// differing samples of triangles with a vertex at w ≤ 0 at either end of the shutter
    /// (checked like all others)
    pub behind: u64,
    /// bound slack (core width − reference width) mean and max, per axis t, u, v
    pub slack_mean: [f64; 3],
    /// max slack per axis
    pub slack_max: [f64; 3],
    /// STE of the core and of the reference (sums over frames)
    pub ste: [f64; 2],
    /// depth error of samples both cover, in LSBs of the I8F24 depth: max, mean
    pub depth_lsb: [f64; 2],
    /// samples the core covers but its own setup/footprint/bounds exclude (must be 0)
    pub violations: u64,
    /// smallest outward margin on the exact (reference) bounds so that every sample the core
    /// covers is inside, per axis t, u, v
    pub eps_measured: [f64; 3],
    /// samples the core covers outside the reference's footprint or in a tile the reference
    /// skips (no finite t/u/v margin covers these)
    pub eps_outside: u64,
    /// the analytic conservative epsilon (class both, largest over the scenes' viewports): ε_x,
    /// ε_y, ε_w raw clip units
    pub eps_raw: [u32; 3],
    /// documented d_q (px at w = 1) at the scenes' viewports (largest) and at 960×540
    pub d_q: [f64; 2],
    /// differing decisions of primitives stated in pixels farther than their own d_q from an
    /// edge (`crate::config::dq`; must be 0)
    pub beyond_dq: u64,
    /// differing decisions of primitives stated in clip space only (the others are stated in
    /// pixels)
    pub differ_clip: u64,
    /// the largest backward error δ (clip units) of such a primitive
    pub max_clip: f64,
    /// of `differ_clip`, those of primitives whose δ is above 1/16 of their own clip extent
    /// (`crate::config::dq::Statement::informative`: the statement says nothing about them)
    pub differ_clip_uninformative: u64,
    /// primitives the reference draws and the core does not, and the other way round
    /// (`crate::compare::pass::Comparison::lost`, `gained`)
    pub prims_lost_gained: [u64; 2],
    /// triangles the configuration culls as degenerate that the default does not (the planar
    /// configuration's vertex rounding: `crate::config::planar_static::degenerate`)
    pub degenerate: u64,
    /// covered samples whose framebuffer slot was still empty and that were not written (counted by
    /// [`lost_samples`](super::measure::lost_samples), independently of the core's counters; must
    /// be 0)
    pub lost: u64,
    #[serde(skip)]
    pub(super) times: Vec<f64>,
    #[serde(skip)]
    pub(super) slack_n: u64,
    #[serde(skip)]
    pub(super) depth_n: u64,
    #[serde(skip)]
    pub(super) counts: [u64; 5],
}

/// A configuration name, or an old report's `[POS, TUV, BND]` as `exact-POS-TUV-BND`.
fn config_name<'de, D: serde::Deserializer<'de>>(d: D) -> Result<String, D::Error> {
    use serde::Deserialize;
    match serde_json::Value::deserialize(d)? {
        serde_json::Value::String(s) => Ok(s),
        serde_json::Value::Array(a) if a.len() == 3 && a.iter().all(|x| x.is_u64()) => {
            Ok(format!("exact-{}-{}-{}", a[0], a[1], a[2]))
        }
        v => Err(serde::de::Error::custom(format!(
            "config: expected a name or [POS, TUV, BND], found {v}"
        ))),
    }
}

/// Turns a row's sums into its figures (medians, means, STE) once every scene is in.
pub(super) fn finish(a: &mut PrecRow) {
    a.times.sort_by(|x, y| x.total_cmp(y));
    a.time_ratio_median = a.times.get(a.times.len() / 2).copied().unwrap_or(0.0);
    for k in 0..3 {
        a.slack_mean[k] /= a.slack_n.max(1) as f64;
    }
    a.depth_lsb[1] /= a.depth_n.max(1) as f64;
    let [tested, covered, rtested, rcovered, _] = a.counts;
    a.ste = [
        covered as f64 / tested.max(1) as f64,
        rcovered as f64 / rtested.max(1) as f64,
    ];
}

/// Indices of the Pareto front of `points` (x = cost, y = error; lower is better in both): no
/// other point is at most as costly and at most as wrong, and better in one.
pub fn pareto(points: &[(f64, f64)]) -> Vec<usize> {
    (0..points.len())
        .filter(|&i| {
            !points.iter().enumerate().any(|(j, q)| {
                j != i
                    && q.0 <= points[i].0
                    && q.1 <= points[i].1
                    && (q.0 < points[i].0 || q.1 < points[i].1)
            })
        })
        .collect()
}
