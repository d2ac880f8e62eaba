//! The per-unit entries of `host/report/synth.json` (`bash vectors/rtl/synth.sh`): each unit
//! variant of the RTL sample test (`vectors/rtl/uvt_bsample.v` with `MOTION`, `DEFOCUS`)
//! synthesized at the default configuration, which `uvt units` shows beside the cost model's
//! per-unit estimate (`crate::config::units::unit_sample_cost`), and the static-only unit at the
//! planar static configuration (`vectors/rtl/uvt_psample.v`, run `static-only@planar-16-16-16-20`),
//! shown beside `crate::config::planar_static::unit_cost` ([`planar_md`]), and the per-tile bounds
//! unit (`vectors/rtl/uvt_bounds.v`, run `bounds@bounded-16-16-16-20`) beside the width table's
//! `bounds/tile` multipliers ([`bounds_md`]). The per-configuration entries (`"configs"`) are read
//! by `crate::precision::costs`.

use std::path::Path;

use anyhow::{Context, Result};
use serde::Deserialize;

/// Yosys `synth_xilinx` (xc7) counts of one run.
#[derive(Clone, Debug, Deserialize, PartialEq, Eq)]
pub struct Xilinx {
    /// DSP48E1 cells
    pub dsp48e1: u64,
    /// LUT1..LUT6 cells
    pub lut: u64,
    /// flip-flops (FDCE, FDPE, FDRE, FDSE)
    pub ff: u64,
}

/// Yosys `synth_ecp5` counts of one run.
#[derive(Clone, Debug, Deserialize, PartialEq, Eq)]
pub struct Ecp5 {
    /// MULT18X18D cells
    pub mult18x18d: u64,
    /// LUT4 cells
    pub lut4: u64,
    /// TRELLIS_FF cells
    pub ff: u64,
}

/// One unit variant synthesized at one configuration.
#[derive(Clone, Debug, Deserialize, PartialEq, Eq)]
pub struct SynthUnit {
    /// unit name (`full`, `motion-only`, `defocus-only`, `static-only`; `bounds`: the
    /// per-tile bounds unit, not a sample test)
    pub unit: String,
    /// configuration name
    pub name: String,
    /// Xilinx 7-series counts
    pub xilinx: Xilinx,
    /// ECP5 counts
    pub ecp5: Ecp5,
}

#[derive(Deserialize)]
struct File {
    #[serde(default)]
    units: Vec<SynthUnit>,
}

/// The unit entries of `synth.json` at `path`: `None` if the file is absent, an empty list if it
/// has no `"units"`; a file that exists but does not parse is an error naming it.
pub fn load_units(path: &Path) -> Result<Option<Vec<SynthUnit>>> {
    if !path.exists() {
        return Ok(None);
    }
    let text =
        std::fs::read_to_string(path).with_context(|| format!("cannot read {}", path.display()))?;
    let f: File = serde_json::from_str(&text).with_context(|| {
        format!(
            "{}: not a vectors/rtl/synth.sh JSON ({{\"units\":[{{\"unit\":…,\"name\":…,\"xilinx\":{{\"dsp48e1\":…}},…}}]}})",
            path.display()
        )
    })?;
    Ok(Some(f.units))
}

/// Markdown: the static-only unit at the planar static configuration — the cost model's sample-test
/// estimate (`crate::config::planar_static::unit_cost`) beside the synthesized counts of
/// `vectors/rtl/uvt_psample.v` (`synth`, the `"units"` of `synth_path`), "not synthesized" without
/// its entry.
pub fn planar_md(synth: Option<&[SynthUnit]>, synth_path: &Path) -> String {
    let name = uvt_core::config::registry::PLANAR.to_string();
    let mut s = format!(
        "\nStatic-only unit at the planar static configuration `{name}` (`uvt_core::units::static_only`; RTL `vectors/rtl/uvt_psample.v`, synthesized counts from `{}`; the other units at `{name}` carry the bounded unit beside the planar test and have no RTL of their own):\n\n| unit | sample test DSP48E1 estimate | synthesized DSP48E1 / LUT / FF | MULT18X18D estimate | synthesized MULT18X18D / LUT4 / FF | Σ bit-products | products |\n|---|---|---|---|---|---|---|\n",
        synth_path.display()
    );
    let c = crate::config::planar_static::unit_cost(false, false).unwrap_or_default();
    let syn = synth.and_then(|v| v.iter().find(|u| u.unit == "static-only" && u.name == name));
    let (sx, se) = syn.map_or(("not synthesized".into(), "not synthesized".into()), |u| {
        (
            format!("{} / {} / {}", u.xilinx.dsp48e1, u.xilinx.lut, u.xilinx.ff),
            format!("{} / {} / {}", u.ecp5.mult18x18d, u.ecp5.lut4, u.ecp5.ff),
        )
    });
    s += &format!(
        "| static-only | {} | {sx} | {} | {se} | {} | {} |\n",
        c.dsp48e1, c.ecp5, c.bit_products, c.products
    );
    if syn.is_none() {
        s += &format!(
            "\nsynthesized: none at `{name}` in `{}` (`bash vectors/rtl/synth.sh -k static-only@{name}`).\n",
            synth_path.display()
        );
    }
    s
}

/// Markdown: the per-tile bounds unit at the default configuration — the width table's
/// `bounds/tile` multipliers (`crate::config::multipliers::stage_costs`) beside the synthesized
/// counts of `vectors/rtl/uvt_bounds.v` (`synth`, the `"units"` of `synth_path`), "not
/// synthesized" without its entry.
pub fn bounds_md(synth: Option<&[SynthUnit]>, synth_path: &Path) -> String {
    let cfg =
        uvt_core::config::registry::Config::of::<uvt_core::config::precision::DefaultPrecision>();
    let name = cfg.to_string();
    let mut s = format!(
        "\nPer-tile bounds unit at `{name}` (`Laine2011::tile`; RTL `vectors/rtl/uvt_bounds.v`, synthesized counts from `{}`). The estimate is the width table's `bounds/tile` rows (`uvt cost --config {name}`: 4 lens products, each bounding line once at the end its slope picks, 16 products, as `dual_t` and the RTL); `synth_ecp5` trims 3 pieces of each lens product that reach none of the bits read:\n\n| unit | bounds/tile DSP48E1 estimate | synthesized DSP48E1 / LUT / FF | MULT18X18D estimate | synthesized MULT18X18D / LUT4 / FF | Σ bit-products | products |\n|---|---|---|---|---|---|---|\n",
        synth_path.display()
    );
    let c = crate::config::multipliers::stage_costs(&cfg)
        .into_iter()
        .find(|g| g.stage == "bounds/tile")
        .unwrap_or_default();
    let syn = synth.and_then(|v| v.iter().find(|u| u.unit == "bounds" && u.name == name));
    let (sx, se) = syn.map_or(("not synthesized".into(), "not synthesized".into()), |u| {
        (
            format!("{} / {} / {}", u.xilinx.dsp48e1, u.xilinx.lut, u.xilinx.ff),
            format!("{} / {} / {}", u.ecp5.mult18x18d, u.ecp5.lut4, u.ecp5.ff),
        )
    });
    s += &format!(
        "| bounds | {} | {sx} | {} | {se} | {} | {} |\n",
        c.dsp48e1, c.ecp5, c.bit_products, c.products
    );
    if syn.is_none() {
        s += &format!(
            "\nsynthesized: none at `{name}` in `{}` (`bash vectors/rtl/synth.sh -k bounds@{name}`).\n",
            synth_path.display()
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::units::{unit_sample_cost, UNITS};
    use uvt_core::config::registry::Config;

    /// The table row `bounds_md` / `planar_md` print for a unit: estimates beside `syn`.
    fn table_row(
        unit: &str,
        dsp: impl std::fmt::Display,
        ecp5: impl std::fmt::Display,
        syn: &SynthUnit,
    ) -> String {
        format!(
            "| {unit} | {dsp} | {} / {} / {} | {ecp5} | {} / {} / {} |",
            syn.xilinx.dsp48e1,
            syn.xilinx.lut,
            syn.xilinx.ff,
            syn.ecp5.mult18x18d,
            syn.ecp5.lut4,
            syn.ecp5.ff
        )
    }

    fn committed() -> (&'static str, Vec<SynthUnit>) {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/report/synth.json");
        (path, load_units(Path::new(path)).unwrap().unwrap())
    }

    /// Every unit variant is synthesized at the default configuration, and the cost model's
    /// per-unit sample-test estimate equals the synthesized count for both families (the model
    /// leaves out exactly the multipliers the RTL's generate blocks leave out).
    #[test]
    fn unit_estimates_equal_synthesis() {
        let (path, units) = committed();
        let def = Config::of::<uvt_core::config::precision::DefaultPrecision>();
        for (name, motion, defocus) in UNITS {
            let syn = units
                .iter()
                .find(|u| u.unit == name && u.name == def.to_string())
                .unwrap_or_else(|| panic!("{path}: no unit {name} at {def}"));
            let est = unit_sample_cost(&def, motion, defocus).unwrap();
            assert_eq!(
                (est.dsp48e1, est.ecp5),
                (syn.xilinx.dsp48e1, syn.ecp5.mult18x18d),
                "{name} at {def}: estimate (DSP48E1, MULT18X18D) against synthesized ({path})"
            );
        }
    }

    /// The static-only unit at the planar static configuration (`uvt_psample.v`) is synthesized,
    /// and the cost model's estimate (`crate::config::planar_static::unit_cost`: 3 direction
    /// products 21 × 13, 9 edge and 3 depth products 32 × 32) equals the synthesized hard
    /// multipliers for both families; `uvt units` shows both.
    #[test]
    fn planar_static_unit_estimate_equals_synthesis() {
        let (path, units) = committed();
        let name = uvt_core::config::registry::PLANAR.to_string();
        let syn = units
            .iter()
            .find(|u| u.unit == "static-only" && u.name == name)
            .unwrap_or_else(|| panic!("{path}: no unit static-only at {name}"));
        let est = crate::config::planar_static::unit_cost(false, false).unwrap();
        assert_eq!(
            (est.dsp48e1, est.ecp5),
            (syn.xilinx.dsp48e1, syn.ecp5.mult18x18d),
            "static-only at {name}: estimate (DSP48E1, MULT18X18D) against synthesized ({path})"
        );
        let md = planar_md(Some(&units), Path::new(path));
        let row = table_row("static-only", est.dsp48e1, est.ecp5, syn);
        assert!(md.contains(&row), "{md}");
        assert!(planar_md(None, Path::new(path)).contains("not synthesized"));
    }

    /// The full unit's entry is the default configuration's full-unit run (`"configs"`), and a
    /// narrower unit never synthesizes to more hard multipliers or flip-flops than the full one
    /// (the sample-test units; the bounds unit is another stage).
    #[test]
    fn full_unit_entry_is_the_default_configuration_run() {
        let (path, units) = committed();
        let v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
        let def = Config::of::<uvt_core::config::precision::DefaultPrecision>().to_string();
        let cfg = v["configs"]
            .as_array()
            .unwrap()
            .iter()
            .find(|c| c["name"] == def.as_str())
            .unwrap_or_else(|| panic!("{path}: no configuration {def}"));
        let full = units
            .iter()
            .find(|u| u.unit == "full")
            .unwrap_or_else(|| panic!("{path}: no full unit"));
        assert_eq!(Some(full.xilinx.dsp48e1), cfg["xilinx"]["dsp48e1"].as_u64());
        assert_eq!(Some(full.xilinx.lut), cfg["xilinx"]["lut"].as_u64());
        assert_eq!(Some(full.xilinx.ff), cfg["xilinx"]["ff"].as_u64());
        assert_eq!(
            Some(full.ecp5.mult18x18d),
            cfg["ecp5"]["mult18x18d"].as_u64()
        );
        assert_eq!(Some(full.ecp5.lut4), cfg["ecp5"]["lut4"].as_u64());
        for u in units.iter().filter(|u| u.unit != "bounds") {
            // LUTs are left out: ABC's mapping is not monotonic in the logic removed (Yosys
            // 0.23's ECP5 motion-only unit maps to 7 LUT4 more than the full one).
            assert!(
                u.xilinx.dsp48e1 <= full.xilinx.dsp48e1
                    && u.xilinx.ff <= full.xilinx.ff
                    && u.ecp5.mult18x18d <= full.ecp5.mult18x18d
                    && u.ecp5.ff <= full.ecp5.ff,
                "{path}: {u:?} against {full:?}"
            );
        }
    }

    /// The bounds unit (`uvt_bounds.v`, run `bounds@` the default) is synthesized, and its hard
    /// multipliers are the tiling rule applied to its products: per lens side one signed 59 × 82
    /// product (4), per bounding line one 45 × 17 and one 46 × 17 (8 lines). The unit reads only
    /// the low 82 bits of a lens product; `synth_ecp5` removes the 3 of its 15 pieces that reach
    /// no lower bit (17-bit chunks at 34 × 51, 34 × 68 and 17 × 68), `synth_xilinx` keeps every
    /// DSP48E1. The width table's `bounds/tile` estimate counts the same products (its magnitude
    /// widths 44 × 13 and 45 × 13 tile as the RTL's signed 45 × 17 and 46 × 17): the same hard
    /// multipliers before `synth_ecp5`'s trimming; `uvt units` shows both.
    #[test]
    fn bounds_unit_tiles_its_products_as_the_model_counts() {
        use crate::config::multipliers::{dsp48e1_tiling, ecp5_tiling, stage_costs, Tiling};
        let (path, units) = committed();
        let cfg = Config::of::<uvt_core::config::precision::DefaultPrecision>();
        let name = cfg.to_string();
        let syn = units
            .iter()
            .find(|u| u.unit == "bounds" && u.name == name)
            .unwrap_or_else(|| panic!("{path}: no unit bounds at {name}"));
        let rtl = |t: fn(u32, u32) -> Tiling| {
            u64::from(4 * t(59, 82).hard + 8 * t(45, 17).hard + 8 * t(46, 17).hard)
        };
        assert_eq!(
            (rtl(dsp48e1_tiling), rtl(ecp5_tiling) - 4 * 3),
            (syn.xilinx.dsp48e1, syn.ecp5.mult18x18d),
            "bounds at {name}: the RTL's products tiled (DSP48E1, MULT18X18D) against synthesized ({path})"
        );
        let est = stage_costs(&cfg)
            .into_iter()
            .find(|g| g.stage == "bounds/tile")
            .unwrap();
        assert_eq!(
            (est.dsp48e1, est.ecp5, est.products),
            (rtl(dsp48e1_tiling), rtl(ecp5_tiling), 4 + 16),
            "the bounds/tile estimate is not the RTL's products: {est:?}"
        );
        let md = bounds_md(Some(&units), Path::new(path));
        let row = table_row("bounds", est.dsp48e1, est.ecp5, syn);
        assert!(md.contains(&row), "{md}");
        assert!(bounds_md(None, Path::new(path)).contains("not synthesized"));
    }

    /// An absent file is `None`; a file that is not the script's JSON is refused by name.
    #[test]
    fn bad_file_is_refused_by_name() {
        let dir = tempfile::tempdir().unwrap();
        assert!(load_units(&dir.path().join("none.json")).unwrap().is_none());
        let bad = dir.path().join("bad-synth.json");
        std::fs::write(&bad, r#"{"units": [{"unit": "full"}]}"#).unwrap();
        let e = format!("{:#}", load_units(&bad).unwrap_err());
        assert!(e.contains("bad-synth.json"), "{e}");
    }
}
