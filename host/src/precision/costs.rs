//! The cost side of `uvt precision`: per configuration the hardware multiplier model
//! ([`crate::config::multipliers`], from the width table), the Cortex-M4F instructions and host ns
//! per stage from `m4_report.sh --sweep`'s JSON (`host/report/m4.json`), and, when R's synthesis
//! script has written `host/report/synth.json`, the synthesized figures beside the model, with the
//! placed-and-routed clock of `host/report/pnr.json` beside it (`bash vectors/rtl/pnr.sh`, read
//! from the folder of `synth.json`) and its table of the units; and the
//! plot of error against hardware cost and against M4 instructions with the Pareto front marked.

use std::path::{Path, PathBuf};

use anyhow::Context;
use serde::Deserialize;
use uvt_core::config::registry::Config;

use crate::config::multipliers::sample_cost;
use crate::config::planar_static;

use super::row::{pareto, PrecRow};

/// One configuration of `m4.json`.
#[derive(Clone, Debug, Deserialize)]
pub struct M4Row {
    /// configuration name
    pub name: String,
    /// Cortex-M4F instructions per setup (with the Laine coefficients)
    pub setup: f64,
    /// per 2×2 tile's bounds
    pub bounds: f64,
    /// per sample test
    pub sample: f64,
    /// host ns per setup, tile bounds, sample test (the same program on the host)
    pub host_ns: [f64; 3],
}

/// `m4.json` as `m4_report.sh --sweep` writes it.
#[derive(Clone, Debug, Deserialize)]
pub struct M4File {
    /// the command that made it
    pub command: String,
    /// what was measured where
    pub target: String,
    /// one row per configuration
    pub configs: Vec<M4Row>,
}

/// The cost sources of a report.
#[derive(Clone, Debug, Default)]
pub struct Costs {
    /// the M4 file and its path, if present
    pub m4: Option<(PathBuf, M4File)>,
    /// `synth.json` (R's format) and its path, if present
    pub synth: Option<(PathBuf, serde_json::Value)>,
    /// `pnr.json` (`vectors/rtl/pnr.sh`, beside `synth.json`) and its path, if present
    pub pnr: Option<(PathBuf, serde_json::Value)>,
}

/// The cost cells of one configuration (formatted; "–" where no figure exists).
pub struct CostCells {
    /// host ns setup/tile/sample
    pub host_ns: String,
    /// M4F instructions setup/tile/sample
    pub m4: String,
    /// model DSP48E1 / MULT18X18D of the sample test
    pub dsp: String,
    /// model Σ bit-products of the sample test
    pub bit_products: String,
    /// synthesized figures
    pub synth: String,
}

impl Costs {
    /// Read `m4`, `synth` and the `pnr.json` in `synth`'s folder if they exist; a file that
    /// exists but does not parse is an error naming it.
    pub fn load(m4: &Path, synth: &Path) -> anyhow::Result<Costs> {
        let pnr_path = synth.with_file_name("pnr.json");
        let m4 = if m4.exists() {
            let text = std::fs::read_to_string(m4)
                .with_context(|| format!("cannot read {}", m4.display()))?;
            let f: M4File = serde_json::from_str(&text)
                .with_context(|| format!("{}: not an m4_report.sh --sweep JSON", m4.display()))?;
            Some((m4.to_path_buf(), f))
        } else {
            None
        };
        let synth = if synth.exists() {
            let text = std::fs::read_to_string(synth)
                .with_context(|| format!("cannot read {}", synth.display()))?;
            let v: serde_json::Value = serde_json::from_str(&text)
                .with_context(|| format!("{}: not JSON", synth.display()))?;
            anyhow::ensure!(
                v.get("configs").is_some_and(|c| c.is_array()),
                "{}: no \"configs\" array",
                synth.display()
            );
            Some((synth.to_path_buf(), v))
        } else {
            None
        };
        let pnr = if pnr_path.exists() {
            let text = std::fs::read_to_string(&pnr_path)
                .with_context(|| format!("cannot read {}", pnr_path.display()))?;
            let v: serde_json::Value = serde_json::from_str(&text)
                .with_context(|| format!("{}: not JSON", pnr_path.display()))?;
            anyhow::ensure!(
                v.get("units").is_some_and(|c| c.is_array()),
                "{}: no \"units\" array",
                pnr_path.display()
            );
            Some((pnr_path, v))
        } else {
            None
        };
        Ok(Costs { m4, synth, pnr })
    }

    /// The placed-and-routed units of `pnr.json` built at configuration `name`.
    fn pnr_units(&self, name: &str) -> Vec<&serde_json::Value> {
        self.pnr
            .as_ref()
            .and_then(|(_, v)| v["units"].as_array())
            .map(|a| a.iter().filter(|u| u["config"] == name).collect())
            .unwrap_or_default()
    }

    /// Markdown: the table of the placed-and-routed units of `pnr.json` (empty without it).
    pub fn pnr_md(&self) -> String {
        let Some((p, v)) = &self.pnr else {
            return String::new();
        };
        let mut s = format!(
            "\nPlaced and routed for a Lattice ECP5 ({}; `{}`, {}, seed {}; from `{}`):\n\n| unit | top | configuration | target MHz | Fmax MHz | latency (clocks) | results/s | results/s per MULT18X18D | MULT18X18D | TRELLIS_COMB (LUT4, carry) | TRELLIS_FF | of them the harness's | critical path (from → to) | nextpnr options |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
            v["device"].as_str().unwrap_or("?"),
            v["script"].as_str().unwrap_or("?"),
            v["nextpnr"].as_str().unwrap_or("?"),
            v["seed"],
            p.display()
        );
        let used = |u: &serde_json::Value, c: &str| {
            let r = &u["resources"][c];
            format!("{} / {}", r["used"], r["available"])
        };
        for u in v["units"].as_array().into_iter().flatten() {
            s += &format!(
                "| {} | `{}` | {} | {} | {:.1} | {} | {:.1} M ({}) | {} | {} | {} | {} | {} | `{}` → `{}` ({:.2} ns) | {} |\n",
                u["unit"].as_str().unwrap_or("?"),
                u["top"].as_str().unwrap_or("?"),
                u["config"].as_str().unwrap_or("?"),
                u["target_mhz"],
                u["fmax_mhz"].as_f64().unwrap_or(f64::NAN),
                u["latency"]
                    .as_u64()
                    .map_or("?".to_string(), |n| n.to_string()),
                u["results_per_second"].as_f64().unwrap_or(f64::NAN) / 1e6,
                u["result"].as_str().unwrap_or("results"),
                u["results_per_second_per_mult18x18d"]
                    .as_f64()
                    .map_or("–".to_string(), |r| format!("{:.2} M", r / 1e6)),
                used(u, "MULT18X18D"),
                used(u, "TRELLIS_COMB"),
                used(u, "TRELLIS_FF"),
                // In context the counts include pnr.sh's harness (one flip-flop per input and
                // output bit); out of context there is none.
                u["harness"]["TRELLIS_FF"]
                    .as_u64()
                    .map_or("–".to_string(), |n| format!("{n} FF")),
                u["critical_path"]["from"].as_str().unwrap_or("?"),
                u["critical_path"]["to"].as_str().unwrap_or("?"),
                u["critical_path"]["ns"].as_f64().unwrap_or(f64::NAN),
                match u["nextpnr_args"].as_str() {
                    Some(a) if !a.is_empty() => format!("`{a}`"),
                    _ => "–".to_string(),
                },
            );
        }
        s
    }

    /// The M4 row of configuration `name`.
    pub fn m4_row(&self, name: &str) -> Option<&M4Row> {
        self.m4.as_ref()?.1.configs.iter().find(|r| r.name == name)
    }

    /// The cells of configuration `name`.
    pub fn of(&self, name: &str) -> CostCells {
        let dash = || "–".to_string();
        let m4 = self.m4_row(name);
        // (DSP48E1, MULT18X18D, Σ bit-products) of the full unit's sample test; the planar
        // configuration's full unit carries the bounded datapath and the planar test
        // (`crate::config::planar_static::unit_cost`).
        let model = Config::parse(name).and_then(|c| {
            if c.planar() {
                planar_static::unit_cost(true, true).map(|c| (c.dsp48e1, c.ecp5, c.bit_products))
            } else {
                let c = sample_cost(&c);
                Some((c.dsp48e1, c.ecp5, c.bit_products))
            }
        });
        let synth = self.synth.as_ref().and_then(|(_, v)| {
            let c = v["configs"]
                .as_array()?
                .iter()
                .find(|c| c["name"] == name)?;
            let n = |x: &serde_json::Value| x.as_u64().map_or("?".into(), |n| n.to_string());
            Some(format!(
                "DSP48E1 {} LUT {} FF {}; ECP5 MULT18X18D {} LUT4 {}",
                n(&c["xilinx"]["dsp48e1"]),
                n(&c["xilinx"]["lut"]),
                n(&c["xilinx"]["ff"]),
                n(&c["ecp5"]["mult18x18d"]),
                n(&c["ecp5"]["lut4"])
            ))
        });
        let pnr: Vec<String> = self
            .pnr_units(name)
            .iter()
            .map(|u| {
                format!(
                    "ECP5 P&R {}: {:.1} MHz, {:.1} M {}s/s",
                    u["unit"].as_str().unwrap_or("?"),
                    u["fmax_mhz"].as_f64().unwrap_or(f64::NAN),
                    u["results_per_second"].as_f64().unwrap_or(f64::NAN) / 1e6,
                    u["result"].as_str().unwrap_or("result")
                )
            })
            .collect();
        let synth = match (synth, pnr.is_empty()) {
            (s, true) => s,
            (Some(s), false) => Some(format!("{s}; {}", pnr.join("; "))),
            (None, false) => Some(pnr.join("; ")),
        };
        CostCells {
            host_ns: m4.map_or_else(dash, |r| {
                format!(
                    "{:.0}/{:.0}/{:.0}",
                    r.host_ns[0], r.host_ns[1], r.host_ns[2]
                )
            }),
            m4: m4.map_or_else(dash, |r| {
                format!("{:.0}/{:.0}/{:.0}", r.setup, r.bounds, r.sample)
            }),
            dsp: model.map_or_else(dash, |c| format!("{} / {}", c.0, c.1)),
            bit_products: model.map_or_else(dash, |c| c.2.to_string()),
            synth: synth.unwrap_or_else(dash),
        }
    }

    /// The notes under the table: where each cost comes from.
    pub fn notes(&self) -> String {
        let mut s = String::from(
            "\nCost columns: *DSP48E1 / MULT18X18D* and *Σ bit-products* are the multiplier model of `host/src/config/multipliers.rs` for the sample test (from the width table of `core/src/widths/stages.rs`; `uvt cost --config NAME` lists every product).",
        );
        match &self.m4 {
            Some((p, f)) => {
                s += &format!(
                    " *M4F insn* and *host ns* per setup / 2×2 tile bounds / sample test from `{}` ({}; made by `{}`).",
                    p.display(),
                    f.target,
                    f.command
                )
            }
            None => s += " *M4F insn* and *host ns*: no M4 JSON (run `bash demo/m4_report.sh --sweep`).",
        }
        match &self.synth {
            Some((p, v)) => {
                s += &format!(
                    " *synthesized*: `{}` (yosys {}).",
                    p.display(),
                    v["yosys"].as_str().unwrap_or("?")
                )
            }
            None => s += " *synthesized*: no `synth.json`.",
        }
        if let Some((p, _)) = &self.pnr {
            s += &format!(
                " *ECP5 P&R*: Fmax and results per second of the placed-and-routed unit at that configuration, from `{}` (table below).",
                p.display()
            );
        }
        s + "\n" + &self.pnr_md()
    }
}

/// SVG plot, bounds tile 1: decision-difference rate against the sample test's DSP48E1 estimate
/// (left) and against its Cortex-M4F instructions (right, when the M4 JSON exists), each with
/// its Pareto front marked.
pub fn plot_svg(rows: &[PrecRow], costs: &Costs, path: &Path) -> anyhow::Result<()> {
    use plotters::prelude::*;
    let e = |x: DrawingAreaErrorKind<_>| anyhow::anyhow!("{x}");
    let pts: Vec<(&str, f64, Option<f64>, f64)> = rows
        .iter()
        .filter(|r| r.tile == 1)
        .filter_map(|r| {
            let dsp = Config::parse(&r.config).map(|c| sample_cost(&c).dsp48e1)?;
            Some((
                r.config.as_str(),
                dsp as f64,
                costs.m4_row(&r.config).map(|m| m.sample),
                (r.differ as f64 / r.compared.max(1) as f64).max(1e-9),
            ))
        })
        .collect();
    anyhow::ensure!(!pts.is_empty(), "no bounds-tile-1 rows to plot");
    let root = SVGBackend::new(path, (1280, 520)).into_drawing_area();
    root.fill(&WHITE).map_err(e)?;
    let panels = root.split_evenly((1, 2));
    let (ymin, ymax) = pts
        .iter()
        .fold((f64::MAX, 0.0f64), |(a, b), p| (a.min(p.3), b.max(p.3)));
    let axes: [(&str, Vec<(usize, f64)>); 2] = [
        (
            "sample test DSP48E1 (model, host/src/config/multipliers.rs)",
            pts.iter().enumerate().map(|(i, p)| (i, p.1)).collect(),
        ),
        (
            "Cortex-M4F instructions per sample test (m4.json)",
            pts.iter()
                .enumerate()
                .filter_map(|(i, p)| p.2.map(|x| (i, x)))
                .collect(),
        ),
    ];
    for (panel, (xdesc, xs)) in panels.iter().zip(axes.iter()) {
        if xs.is_empty() {
            continue;
        }
        let xmax = xs.iter().map(|p| p.1).fold(0.0, f64::max) * 1.15;
        let mut chart = ChartBuilder::on(panel)
            .caption(format!("error against {xdesc}"), ("sans-serif", 15))
            .margin(14)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(0.0..xmax, (ymin / 3.0..ymax * 3.0).log_scale())
            .map_err(e)?;
        chart
            .configure_mesh()
            .x_desc(*xdesc)
            .y_desc("decisions differing from f64 (rate)")
            .y_label_formatter(&|y| format!("{y:.0e}"))
            .draw()
            .map_err(e)?;
        let xy: Vec<(f64, f64)> = xs.iter().map(|&(i, x)| (x, pts[i].3)).collect();
        let front = pareto(&xy);
        let mut fp: Vec<(f64, f64)> = front.iter().map(|&k| xy[k]).collect();
        fp.sort_by(|a, b| a.0.total_cmp(&b.0));
        chart
            .draw_series(LineSeries::new(fp, &RED))
            .map_err(e)?
            .label("Pareto front")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 16, y)], RED));
        chart
            .draw_series(xs.iter().enumerate().map(|(k, &(i, x))| {
                let style = if front.contains(&k) {
                    RED.filled()
                } else {
                    BLUE.filled()
                };
                EmptyElement::at((x, pts[i].3))
                    + Circle::new((0, 0), 5, style)
                    + Text::new(
                        pts[i].0.to_string(),
                        if k % 2 == 0 { (8, -14) } else { (8, 6) },
                        ("sans-serif", 11),
                    )
            }))
            .map_err(e)?;
        chart
            .configure_series_labels()
            .border_style(BLACK)
            .draw()
            .map_err(e)?;
    }
    root.present().map_err(e)?;
    Ok(())
}
