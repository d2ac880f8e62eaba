//! What `uvt render` is asked and what it returns: the bounds strategy and precision of the core
//! ([`RenderOpts`]), the sample-level comparison with the reference ([`Decisions`]) and the three
//! frames with the JSON report ([`Rendered`]).

use uvt_core::bounds::strategy::BoundsStrategy;
use uvt_core::config::registry::{Config, DEFAULT};
use uvt_core::{BboxScan, Laine2011};

use crate::frame::compare::CoverageDiff;
use crate::frame::counters::Frame;

/// How `uvt render` runs the core.
#[derive(Clone, Copy, Debug)]
pub struct RenderOpts {
    /// bounds strategy of the "uvt fixed" pipeline: a name of
    /// `uvt_core::bounds::registry::STRATEGIES` (`crate::config::names::strategy` parses it)
    pub bounds: &'static str,
    /// the core's configuration: one of the registry's (`crate::config::names::precision`
    /// parses it; [`DEFAULT`] runs the default comparison, any other the measured one of
    /// [`Decisions`])
    pub precision: Config,
    /// print one line per phase on stderr
    pub progress: bool,
}

impl Default for RenderOpts {
    fn default() -> Self {
        RenderOpts {
            bounds: Laine2011.name(),
            precision: DEFAULT,
            progress: false,
        }
    }
}

/// The report's name of bounds strategy `name`: "Laine 2011" and "bounding-box scan" for those
/// two, the registry name for the others.
pub fn bounds_label(name: &str) -> &str {
    if name == Laine2011.name() {
        "Laine 2011"
    } else if name == BboxScan.name() {
        "bounding-box scan"
    } else {
        name
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
