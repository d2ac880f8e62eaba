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
    /// flash bytes of the unit's own code: flash − the harness's flash
    #[serde(default)]
    pub unit_flash: Option<u64>,
    /// instructions per sample test, one decimal
    #[serde(default)]
    pub sample_raw: Option<f64>,
    /// per sample test net of the measuring loop (`sample_raw` − the loop alone)
    #[serde(default)]
    pub sample_net: Option<f64>,
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
    /// per sample test, one decimal
    #[serde(default)]
    pub sample_raw: Option<f64>,
    /// per sample test net of the measuring loop
    #[serde(default)]
    pub sample_net: Option<f64>,
}

/// The program with no unit code linked (`harness` of `m4_units.json`).
#[derive(Clone, Debug, Deserialize, Serialize)]
pub struct M4Harness {
    /// flash bytes
    pub flash: u64,
}

#[derive(Deserialize)]
struct M4Units {
    #[serde(default)]
    harness: Option<M4Harness>,
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
    let f = parse(path)?;
    Ok(Some((f.units, f.full_on_unit_prims)))
}

fn parse(path: &Path) -> Result<M4Units> {
    let text =
        std::fs::read_to_string(path).with_context(|| format!("cannot read {}", path.display()))?;
    let f: M4Units = serde_json::from_str(&text).with_context(|| {
        format!(
            "{}: not an m4_report.sh --units JSON ({{\"units\":[{{\"unit\":…,\"flash\":…}}]}})",
            path.display()
        )
    })?;
    Ok(f)
}

/// The Markdown tables of docs/units.md for `m4_units.json` at `path` (`uvt m4-units`): per
/// unit program its flash (and the unit's own, flash − harness), RAM and stack, instructions per
/// call and the sample test net of the measuring loop, each against the full unit; then the
/// full unit on each narrower unit's triangles (the same work). Fails naming the file when it
/// lacks the harness, the full unit or a unit's one-decimal figures (an older `--units` run).
pub fn programs_md(path: &Path) -> Result<String> {
    let f = parse(path)?;
    let missing = |what: &str| {
        anyhow::anyhow!(
            "{}: no {what} (run `bash demo/m4_report.sh --units` again)",
            path.display()
        )
    };
    let harness = f.harness.as_ref().ok_or_else(|| missing("harness"))?;
    let full = f
        .units
        .iter()
        .find(|u| u.unit == "full")
        .ok_or_else(|| missing("full unit"))?;
    let net = |u: &M4Unit| -> Result<(u64, f64, f64)> {
        let uf = u
            .flash
            .checked_sub(harness.flash)
            .ok_or_else(|| missing("unit flash above the harness"))?;
        match (u.unit_flash, u.sample_raw, u.sample_net) {
            (Some(f), Some(r), Some(n)) if f == uf => Ok((f, r, n)),
            (Some(f), Some(_), Some(_)) => Err(anyhow::anyhow!(
                "{}: unit {}: unit_flash {f} is not flash {} − harness {}",
                path.display(),
                u.unit,
                u.flash,
                harness.flash
            )),
            _ => Err(missing(&format!("one-decimal figures of unit {}", u.unit))),
        }
    };
    let pct = |a: f64, b: f64| 100.0 * a / b;
    let (full_uf, _, full_net) = net(full)?;
    let mut s = String::from(
        "| unit | flash bytes (% of full) | unit flash: flash − harness (% of full) | RAM / peak stack bytes | setup / tile bounds / sample test | sample test net of the loop (% of full) | checksum |\n|---|---|---|---|---|---|---|\n",
    );
    for u in &f.units {
        let (uf, raw, n) = net(u)?;
        s += &format!(
            "| {} | {} ({:.1}%) | {uf} ({:.1}%) | {} / {} | {:.0} / {:.0} / {raw:.1} | {n:.1} ({:.1}%) | {} |\n",
            u.unit,
            u.flash,
            pct(u.flash as f64, full.flash as f64),
            pct(uf as f64, full_uf as f64),
            u.ram,
            u.stack,
            u.setup,
            u.bounds,
            pct(n, full_net),
            u.checksum
        );
    }
    if !f.full_on_unit_prims.is_empty() {
        s += "\n| triangles of | that unit: setup / tile / sample (net) | full unit: setup / tile / sample (net) |\n|---|---|---|\n";
        for o in &f.full_on_unit_prims {
            let u = f
                .units
                .iter()
                .find(|u| u.unit == o.prims)
                .ok_or_else(|| missing(&format!("unit {}", o.prims)))?;
            let (_, raw, n) = net(u)?;
            let (oraw, onet) = o.sample_raw.zip(o.sample_net).ok_or_else(|| {
                missing(&format!(
                    "one-decimal figures of the full unit on {}",
                    o.prims
                ))
            })?;
            s += &format!(
                "| {} | {:.0} / {:.0} / {raw:.1} ({n:.1}) | {:.0} / {:.0} / {oraw:.1} ({onet:.1}) |\n",
                o.prims, u.setup, u.bounds, o.setup, o.bounds
            );
        }
    }
    Ok(s)
}
