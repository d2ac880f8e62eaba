//! The Cortex-M4F figures of the unit programs (`m4_units.json`, written by
//! `bash demo/m4_report.sh --units`): flash, RAM, stack and instructions per stage of
//! each unit variant, which `uvt units` and `uvt fit` show beside the multiplier estimates.

use std::path::Path;

use anyhow::{Context, Result};
use serde::{Deserialize, Serialize};

/// One unit of `m4_units.json` (`demo/m4_report.sh --units`).
#[derive(Clone, Debug, Deserialize, Serialize)]
pub struct M4Unit {
    /// unit name
    pub unit: String,
    /// flash bytes (.vector_table + .text + .rodata)
    pub flash: u64,
    /// .text bytes
    pub text: u64,
    /// RAM bytes (.data + .bss)
    pub ram: u64,
    /// peak stack bytes
    pub stack: u64,
    /// Cortex-M4F instructions per setup
    pub setup: f64,
    /// per tile bounds
    pub bounds: f64,
    /// per sample test
    pub sample: f64,
    /// image checksum
    pub checksum: String,
}

/// The full unit's instructions on the primitives a narrower unit accepts
/// (`full_on_unit_prims` of `m4_units.json`): the same work as that unit's row.
#[derive(Clone, Debug, Deserialize, Serialize)]
pub struct M4FullOn {
    /// the narrower unit whose primitives the full unit rendered
    pub prims: String,
    /// instructions per setup
    pub setup: f64,
    /// per tile bounds
    pub bounds: f64,
    /// per sample test
    pub sample: f64,
}

#[derive(Deserialize)]
struct M4Units {
    units: Vec<M4Unit>,
    #[serde(default)]
    full_on_unit_prims: Vec<M4FullOn>,
}

/// `m4_units.json`: the units and the full unit's instructions on each narrower unit's
/// primitives.
pub type M4Data = (Vec<M4Unit>, Vec<M4FullOn>);

/// Read `m4_units.json` if it exists (`None` if absent); a file that exists but does not parse
/// is an error naming it.
pub fn load_m4_units(path: &Path) -> Result<Option<M4Data>> {
    if !path.exists() {
        return Ok(None);
    }
    let text =
        std::fs::read_to_string(path).with_context(|| format!("cannot read {}", path.display()))?;
    let f: M4Units = serde_json::from_str(&text).with_context(|| {
        format!(
            "{}: not an m4_report.sh --units JSON ({{\"units\":[{{\"unit\":…,\"flash\":…}}]}})",
            path.display()
        )
    })?;
    Ok(Some((f.units, f.full_on_unit_prims)))
}
