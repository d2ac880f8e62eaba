//! What `uvt render` is asked and what it returns: the bounds strategy and precision of the core
//! ([`RenderOpts`]), the sample-level comparison with the reference ([`Decisions`]) and the three
//! frames with the JSON report ([`Rendered`]).

use anyhow::{anyhow, Result};

use crate::frame::compare::CoverageDiff;
use crate::frame::counters::Frame;

/// Bounds strategies of the core that `uvt render --bounds` accepts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Strategy {
    /// Laine et al. 2011 (u, v, t) bounds
    Laine2011,
    /// the bounding-box scan: every sample of the footprint
    Bbox,
}

impl Strategy {
    /// Every strategy by its command-line name.
    pub const NAMES: [(&'static str, Strategy); 2] =
        [("laine2011", Strategy::Laine2011), ("bbox", Strategy::Bbox)];

    /// The strategy called `name`; the error lists the accepted names.
    pub fn from_name(name: &str) -> Result<Strategy> {
        Self::NAMES
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, s)| *s)
            .ok_or_else(|| {
                anyhow!(
                    "unknown bounds strategy {name:?} (accepted: {})",
                    Self::NAMES.map(|n| n.0).join(", ")
                )
            })
    }

    /// The command-line name.
    pub fn name(self) -> &'static str {
        Self::NAMES
            .iter()
            .find(|(_, s)| *s == self)
            .map_or("?", |n| n.0)
    }
}

/// The precisions `uvt render --precision` accepts (`POS/TUV/BND` fraction bits): 16/16/16 is
/// the default configuration (`bounded-16-16-16-20`), the narrower ones run the exact test.
pub const RENDER_PRECISIONS: [(u32, u32, u32); 4] =
    [(6, 6, 2), (8, 8, 4), (12, 12, 8), (16, 16, 16)];

/// Precisions `uvt render --precision` accepts, as `POS/TUV/BND` fraction bits
/// ([`RENDER_PRECISIONS`]).
pub fn precision_from_name(name: &str) -> Result<(u32, u32, u32)> {
    let show = |c: &(u32, u32, u32)| format!("{}/{}/{}", c.0, c.1, c.2);
    RENDER_PRECISIONS
        .iter()
        .find(|c| show(c) == name)
        .copied()
        .ok_or_else(|| {
            anyhow!(
                "unknown precision {name:?} (accepted: {})",
                RENDER_PRECISIONS
                    .iter()
                    .map(show)
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        })
}

/// How `uvt render` runs the core.
#[derive(Clone, Copy, Debug)]
pub struct RenderOpts {
    /// bounds strategy of the "uvt fixed" pipeline
    pub bounds: Strategy,
    /// fraction bits (position, t/u/v, bounds) of the core
    pub precision: (u32, u32, u32),
    /// print one line per phase on stderr
    pub progress: bool,
}

impl Default for RenderOpts {
    fn default() -> Self {
        RenderOpts {
            bounds: Strategy::Laine2011,
            precision: (16, 16, 16),
            progress: false,
        }
    }
}

/// Sample-level comparison core vs reference. At the default precision it is
/// [`crate::frame::compare::compare`]; at another it comes from
/// [`crate::precision::measure::decisions`], which does not split the differences by side but adds
/// the conservativeness check.
#[derive(Clone, Copy, Debug, Default, serde::Serialize)]
pub struct Decisions {
    /// (triangle, sample) pairs compared
    pub compared: u64,
    /// pairs whose coverage differs
    pub differ: u64,
    /// covered by the core only (default precision only)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fixed_only: Option<u64>,
    /// covered by the reference only (default precision only)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub f64_only: Option<u64>,
    /// differences not explained by the derived quantization bound at this precision
    /// (`compare.rs`: some edge value or det within its bound; must be 0)
    pub beyond_bound: u64,
    /// largest distance (px) of a differing sample from the nearest edge
    pub max_distance_px: f64,
    /// largest per-sample quantization distance (px) among explained differences (default
    /// precision only)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_bound_px: Option<f64>,
    /// covered samples outside the core's own bounds (non-default precision only)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub violations: Option<u64>,
}

impl Decisions {
    /// The default precision's comparison ([`crate::frame::compare::compare`]).
    pub(super) fn from_diff(c: &CoverageDiff) -> Decisions {
        Decisions {
            compared: c.compared,
            differ: c.fixed_only + c.f64_only,
            fixed_only: Some(c.fixed_only),
            f64_only: Some(c.f64_only),
            beyond_bound: c.beyond_bound,
            max_distance_px: c.max_distance_px,
            max_bound_px: Some(c.max_bound_px),
            violations: None,
        }
    }
    /// Differences per compared pair.
    pub fn rate(&self) -> f64 {
        per(self.differ, self.compared)
    }
}

/// Results of `uvt render`.
pub struct Rendered {
    /// the core with the chosen bounds (default Laine 2011)
    pub fixed: Frame,
    /// the f64 reference
    pub f64: Frame,
    /// the core with the bounding-box scan
    pub bbox: Frame,
    /// sample-level comparison core vs reference
    pub coverage: Decisions,
    /// how the core ran
    pub opts: RenderOpts,
    /// the JSON report
    pub report: serde_json::Value,
}

/// `a / b`, 0 when `b` is 0.
pub(super) fn per(a: u64, b: u64) -> f64 {
    if b == 0 {
        0.0
    } else {
        a as f64 / b as f64
    }
}
