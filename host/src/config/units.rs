//! The unit variants (`uvt_core::config::unit`: full, motion-only, defocus-only, static-only) as the
//! host's cost tools see them: which classes each accepts, the smallest one a scene needs, and
//! the sample-test multipliers of each at a configuration ([`unit_sample_cost`], from the
//! multiplier model of [`super::multipliers`]).

use serde::Serialize;
use uvt_core::config::registry::Config;
use uvt_core::widths::stages::table;
use uvt_core::Unit as _;

use super::multipliers::{dsp48e1, ecp5, sample_cost};

/// The four units, widest first: name, has motion terms, has defocus terms.
pub const UNITS: [(&str, bool, bool); 4] = [
    (uvt_core::Full::NAME, true, true),
    (uvt_core::MotionOnly::NAME, true, false),
    (uvt_core::DefocusOnly::NAME, false, true),
    (uvt_core::StaticOnly::NAME, false, false),
];

/// The smallest unit accepting classes with (any motion, any defocus).
pub fn unit_for(motion: bool, defocus: bool) -> &'static str {
    UNITS
        .iter()
        .rev()
        .find(|u| (u.1 || !motion) && (u.2 || !defocus))
        .map_or(uvt_core::Full::NAME, |u| u.0)
}

/// (motion, defocus) terms of unit `name`.
pub fn unit_terms(name: &str) -> Option<(bool, bool)> {
    UNITS.iter().find(|u| u.0 == name).map(|u| (u.1, u.2))
}

/// The sample test's multipliers of one unit at one configuration.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct UnitCost {
    /// products
    pub products: u64,
    /// Σ count·a·b
    pub bit_products: u64,
    /// DSP48E1 (25 × 18) estimate
    pub dsp48e1: u64,
    /// ECP5 MULT18X18D estimate
    pub ecp5: u64,
}

/// Fields lerped by step 1 of the bounded test (x, y, w, z, CoC; `bounded.rs`).
const LERP_FIELDS: u32 = 5;

/// The sample-test cost of the unit with the given terms at a bounded `cfg`, from the width
/// table's `sample` rows restricted to the stages the unit has
/// (`core/src/sample/bounded/datapath.rs` `vertex`): `1 lerp` — x, y, w, z lerps when the unit
/// has motion, the CoC lerp only with motion and defocus (4 or 5 of the 5 fields; none without
/// motion: static and defocus-only triangles read the t0 values, the depth's z included);
/// `2 lens` only with defocus; offsets, edges, orientation (its rare path serves w ≤ 0
/// vertices, which static triangles have too) and depth in every unit. `None` for an exact
/// configuration (its rows are sized for the widest class; a per-unit table is not modelled) or
/// a lerp row whose count is not a multiple of the five fields.
pub fn unit_sample_cost(cfg: &Config, motion: bool, defocus: bool) -> Option<UnitCost> {
    cfg.off()?;
    let t = table(cfg);
    let mut c = UnitCost::default();
    for r in t.rows().filter(|r| r.stage == "sample") {
        for m in r.mul.iter().flatten() {
            let count = if r.signal.starts_with("1 lerp") {
                if m.count % LERP_FIELDS != 0 {
                    return None;
                }
                let fields = match (motion, defocus) {
                    (false, _) => 0,
                    (true, false) => 4,
                    (true, true) => 5,
                };
                m.count / LERP_FIELDS * fields
            } else if r.signal.starts_with("2 lens") {
                if defocus {
                    m.count
                } else {
                    0
                }
            } else {
                m.count
            };
            let n = u64::from(count);
            c.products += n;
            c.bit_products += n * u64::from(m.a) * u64::from(m.b);
            c.dsp48e1 += n * u64::from(dsp48e1(m.a, m.b));
            c.ecp5 += n * u64::from(ecp5(m.a, m.b));
        }
    }
    Some(c)
}

/// The full unit's sample-test cost at any configuration (the whole `sample` stage).
pub fn full_sample_cost(cfg: &Config) -> UnitCost {
    let s = sample_cost(cfg);
    UnitCost {
        products: s.products,
        bit_products: s.bit_products,
        dsp48e1: s.dsp48e1,
        ecp5: s.ecp5,
    }
}
