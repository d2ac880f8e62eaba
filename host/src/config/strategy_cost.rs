//! The hardware figure of every bounds strategy, stage by stage (`uvt cost --strategies`): the
//! core's operator inventory (`uvt_core::widths::strategies`, operand widths derived from the
//! domain constants) weighted by width — multipliers tiled onto DSP48E1 / MULT18X18D by the rule
//! of [`crate::config::multipliers`], adders and comparators as bits, dividers as the
//! subtractor bits of a restoring divider (`quot` steps of `den + 1` bits).
//!
//! Per stage and item (triangle, bounds tile, row span, sample), on the worst-case path of a
//! triangle of the given class: a unit that finishes one item per clock instantiates these
//! operators; an iterative one runs them as this much work per item.

use crate::config::multipliers::{dsp48e1_tiling, ecp5_tiling, LUT_CHUNK};
use uvt_core::bounds::registry::STRATEGIES;
use uvt_core::config::class::Class;
use uvt_core::config::registry::Config;
use uvt_core::widths::ops::{Inventory, OpKind, Stage};
use uvt_core::widths::strategies::inventory;

/// One stage of one strategy for one class, weighted by width.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Figure {
    /// operations (the inventory's count)
    pub ops: u64,
    /// products of two variables
    pub products: u64,
    /// Σ count·a·b
    pub bit_products: u64,
    /// Σ count·DSP48E1(a, b)
    pub dsp48e1: u64,
    /// LUT bits of the DSP48E1 tiling's top chunks
    pub dsp48e1_lut_bits: u64,
    /// Σ count·MULT18X18D(a, b)
    pub ecp5: u64,
    /// LUT bits of the MULT18X18D tiling's top chunks
    pub ecp5_lut_bits: u64,
    /// Σ count·bits of adders and subtractors
    pub add_bits: u64,
    /// Σ count·bits of comparators, min and max
    pub cmp_bits: u64,
    /// dividers
    pub divides: u64,
    /// Σ count·quot·(den + 1): a restoring divider's subtractor bits
    pub div_bits: u64,
}

/// The figure of `stage` of inventory `inv` for a triangle of class `c`.
pub fn figure(inv: &Inventory, stage: Stage, c: Class) -> Figure {
    let mut f = Figure::default();
    for o in inv.ops().filter(|o| o.stage == stage && o.classes.has(c)) {
        let n = u64::from(o.count);
        f.ops += n;
        match o.kind {
            OpKind::Mul { a, b } => {
                let (x, l) = (dsp48e1_tiling(a, b), ecp5_tiling(a, b));
                f.products += n;
                f.bit_products += n * u64::from(a) * u64::from(b);
                f.dsp48e1 += n * u64::from(x.hard);
                f.dsp48e1_lut_bits += n * u64::from(x.lut_bits);
                f.ecp5 += n * u64::from(l.hard);
                f.ecp5_lut_bits += n * u64::from(l.lut_bits);
            }
            OpKind::Add { bits } => f.add_bits += n * u64::from(bits),
            OpKind::Cmp { bits } => f.cmp_bits += n * u64::from(bits),
            OpKind::Div { den, quot } => {
                f.divides += n;
                f.div_bits += n * u64::from(quot) * u64::from(den + 1);
            }
        }
    }
    f
}

/// The inventory of registry strategy `name` at `cfg` (every name of `STRATEGIES` has one; a
/// test checks it).
pub fn strategy_inventory(name: &str, cfg: &Config) -> Inventory {
    inventory(name, cfg).unwrap_or_default()
}

/// " + N" LUT bits, or nothing for 0.
fn lut(n: u64) -> String {
    match n {
        0 => String::new(),
        n => format!(" + {n}"),
    }
}

/// Markdown: per strategy and stage the width-weighted figure for a motion + defocus triangle
/// (the general unit's worst class), then the per-triangle and per-tile DSP48E1 by class.
pub fn strategies_md(cfg: &Config) -> String {
    let both = Class::MotionDefocus;
    let mut s = format!(
        "Bounds strategies at `{cfg}`, per item of each stage on the worst-case path of a motion + defocus triangle (`uvt cost --strategies --config {cfg}`; operators from `core/src/widths/strategies/`, multipliers tiled as `vectors/rtl/uvt_mul.v`, top chunks ≤ {LUT_CHUNK} bits in LUTs; dividers as restoring subtractor bits). Per triangle: the strategy's own preparation (setup's shared part excluded); per tile: its bounds; per row: its row span; per sample: its predicate.\n\n| strategy | stage | ops | products | Σ bit-products | DSP48E1 (+ LUT bits) | MULT18X18D (+ LUT bits) | adder bits | compare bits | dividers (subtractor bits) |\n|---|---|---|---|---|---|---|---|---|---|\n"
    );
    for name in STRATEGIES {
        let inv = strategy_inventory(name, cfg);
        let mut any = false;
        for stage in Stage::ALL {
            let f = figure(&inv, stage, both);
            if f.ops == 0 {
                continue;
            }
            any = true;
            s += &format!(
                "| {name} | {} | {} | {} | {} | {}{} | {}{} | {} | {} | {} ({}) |\n",
                stage.name(),
                f.ops,
                f.products,
                f.bit_products,
                f.dsp48e1,
                lut(f.dsp48e1_lut_bits),
                f.ecp5,
                lut(f.ecp5_lut_bits),
                f.add_bits,
                f.cmp_bits,
                f.divides,
                f.div_bits
            );
        }
        if !any {
            s += &format!("| {name} | – | 0 | 0 | 0 | 0 | 0 | 0 | 0 | 0 (0) |\n");
        }
    }
    s += "\nDSP48E1 per triangle / per tile / per sample (predicate), by class (static, motion, defocus, motion + defocus):\n\n| strategy | static | motion | defocus | motion + defocus |\n|---|---|---|---|---|\n";
    for name in STRATEGIES {
        let inv = strategy_inventory(name, cfg);
        s += &format!("| {name} |");
        for c in Class::ALL {
            let [a, b, d] = [Stage::Triangle, Stage::Tile, Stage::Predicate]
                .map(|st| figure(&inv, st, c).dsp48e1);
            s += &format!(" {a} / {b} / {d} |");
        }
        s += "\n";
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::multipliers::stage_costs;
    use uvt_core::config::precision::{BoundedPrecision, Exact};

    /// Every registry strategy has an inventory that fits its capacity.
    #[test]
    fn every_strategy_has_an_inventory() {
        let cfg = Config::of::<BoundedPrecision>();
        for name in STRATEGIES {
            let inv = inventory(name, &cfg).unwrap_or_else(|| panic!("{name}: no inventory"));
            assert!(inv.is_complete(), "{name}: inventory over capacity");
        }
        assert!(inventory("laine", &cfg).is_none());
    }

    /// One door: Laine 2011's per-tile multipliers are the width table's `bounds/tile` row
    /// (`uvt cost --config`), at the exact and the default configuration.
    #[test]
    fn laine_tile_is_the_width_table_bounds_tile() {
        for cfg in [Config::of::<Exact>(), Config::of::<BoundedPrecision>()] {
            let f = figure(
                &strategy_inventory("laine2011", &cfg),
                Stage::Tile,
                Class::MotionDefocus,
            );
            let g = stage_costs(&cfg)
                .into_iter()
                .find(|g| g.stage == "bounds/tile")
                .expect("bounds/tile row");
            assert_eq!(
                (f.products, f.bit_products, f.dsp48e1, f.ecp5),
                (g.products, g.bit_products, g.dsp48e1, g.ecp5),
                "{cfg}"
            );
        }
    }

    /// bbox has no bounds hardware; every other strategy has per-tile multipliers on a
    /// motion + defocus triangle (an empty or missing inventory fails).
    #[test]
    fn every_bounds_strategy_has_tile_multipliers() {
        let cfg = Config::of::<BoundedPrecision>();
        let dsp = |n: &str, st: Stage| {
            figure(&strategy_inventory(n, &cfg), st, Class::MotionDefocus).dsp48e1
        };
        assert_eq!(dsp("bbox", Stage::Tile) + dsp("bbox", Stage::Triangle), 0);
        for n in STRATEGIES.iter().filter(|n| **n != "bbox") {
            assert!(dsp(n, Stage::Tile) > 0, "{n}");
        }
    }
}
