//! What `uvt render` is asked and what it returns: the bounds strategy and precision of the core
//! ([`RenderOpts`]) and the three frames with the sample-level comparison and the JSON report
//! ([`Rendered`]).

use uvt_core::bounds::strategy::BoundsStrategy;
use uvt_core::config::registry::{Config, DEFAULT};
use uvt_core::{BboxScan, Laine2011};

use crate::compare::pass::Comparison;
use crate::frame::counters::Frame;

/// How `uvt render` runs the core.
#[derive(Clone, Copy, Debug)]
pub struct RenderOpts {
    /// bounds strategy of the "uvt fixed" pipeline: a name of
    /// `uvt_core::bounds::registry::STRATEGIES` (`crate::config::names::strategy` parses it)
    pub bounds: &'static str,
    /// the core's configuration: one of the registry's (`crate::config::names::precision`
    /// parses it)
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

/// Results of `uvt render`.
pub struct Rendered {
    /// the core with the chosen bounds (default Laine 2011)
    pub fixed: Frame,
    /// the f64 reference
    pub f64: Frame,
    /// the core with the bounding-box scan
    pub bbox: Frame,
    /// the sample-level comparison core vs reference ([`crate::compare::pass`])
    pub coverage: Comparison,
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
