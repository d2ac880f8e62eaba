//! `uvt units`: the unit-variant table at one configuration — what each variant accepts, its
//! Cortex-M4F figures ([`super::m4`]), its sample-test multiplier estimate
//! ([`crate::config::units`]) and the synthesized counts of the RTL unit ([`super::synth`]).

use std::path::Path;

use uvt_core::config::registry::Config;
use uvt_core::Class;

use crate::config::units::{unit_sample_cost, UnitCost, UNITS};

use super::m4::M4Unit;
use super::synth::SynthUnit;

/// Markdown: the unit-variant table (`uvt units`) at configuration `cfg`, with the RTL unit
/// variants' synthesized counts (`synth`, the `"units"` of `synth_path`) where they were
/// synthesized at `cfg`.
pub fn units_md(
    cfg: &Config,
    m4: Option<&[M4Unit]>,
    m4_path: &Path,
    synth: Option<&[SynthUnit]>,
    synth_path: &Path,
) -> String {
    let mut s = format!(
        "Unit variants at `{cfg}`: sample-test multipliers from the width table's `sample` rows restricted to the unit's stages (`uvt cost --config {cfg}`), Cortex-M4F figures from `{}`, synthesized counts of the RTL unit (`vectors/rtl/uvt_bsample.v`, Yosys) from `{}`.\n\n| unit | accepts | flash bytes | RAM bytes (.data+.bss / stack) | M4F insn setup / tile / sample | sample test DSP48E1 estimate | synthesized DSP48E1 / LUT / FF | MULT18X18D estimate | synthesized MULT18X18D / LUT4 / FF | Σ bit-products | products |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
        m4_path.display(),
        synth_path.display()
    );
    for (name, motion, defocus) in UNITS {
        let acc: Vec<&str> = [
            Class::Static,
            Class::Motion,
            Class::Defocus,
            Class::MotionDefocus,
        ]
        .into_iter()
        .filter(|c| (motion || !c.motion()) && (defocus || !c.defocus()))
        .map(Class::name)
        .collect();
        let row = m4.and_then(|m| m.iter().find(|u| u.unit == name));
        let nm = "not measured".to_string();
        let (flash, ram, insn) = match row {
            Some(u) => (
                u.flash.to_string(),
                format!("{} / {}", u.ram, u.stack),
                format!("{:.0} / {:.0} / {:.0}", u.setup, u.bounds, u.sample),
            ),
            None => (nm.clone(), nm.clone(), nm),
        };
        let c = unit_sample_cost(cfg, motion, defocus);
        let f = |g: fn(&UnitCost) -> u64| {
            c.as_ref()
                .map_or("not modelled (exact)".into(), |c| g(c).to_string())
        };
        let syn = synth.and_then(|v| {
            v.iter()
                .find(|u| u.unit == name && u.name == cfg.to_string())
        });
        let (sx, se) = syn.map_or(("not synthesized".into(), "not synthesized".into()), |u| {
            (
                format!("{} / {} / {}", u.xilinx.dsp48e1, u.xilinx.lut, u.xilinx.ff),
                format!("{} / {} / {}", u.ecp5.mult18x18d, u.ecp5.lut4, u.ecp5.ff),
            )
        });
        s += &format!(
            "| {name} | {} | {flash} | {ram} | {insn} | {} | {sx} | {} | {se} | {} | {} |\n",
            acc.join(", "),
            f(|c| c.dsp48e1),
            f(|c| c.ecp5),
            f(|c| c.bit_products),
            f(|c| c.products)
        );
    }
    if !synth.is_some_and(|v| v.iter().any(|u| u.name == cfg.to_string())) {
        s += &format!(
            "\nsynthesized: none at `{cfg}` in `{}` (`bash vectors/rtl/synth.sh` synthesizes every unit at the default configuration).\n",
            synth_path.display()
        );
    }
    if m4.is_none() {
        s += &format!(
            "\nflash, RAM and M4F instructions: not measured (`{}` absent; `bash demo/m4_report.sh --units` writes it).\n",
            m4_path.display()
        );
    }
    s
}
