//! The hardware multiplier cost of a configuration, from the width table `uvt_core::widths`
//! derives (one multiplier per product of two variables on the stage's worst-case path, fully
//! parallel: one setup per triangle, one tile per clock, one sample test per clock; constant
//! scalings by 2^k are wiring, divides are not multipliers and are listed by the width table).
//!
//! **Tiling** — the rule the RTL's `vectors/rtl/uvt_mul.v` instantiates, so that the estimate
//! counts the hard multipliers the synthesized unit really has. Hard multipliers are signed
//! only, with ports `pa × pb` (DSP48E1: 25 × 18; ECP5 MULT18X18D used the same way: 18 × 18).
//! - An n-bit signed operand on a p-bit port is one piece if n ≤ p; otherwise
//!   `k = ceil((n − p)/(p − 1))` unsigned low chunks of `p − 1` bits and a signed top chunk of
//!   `h = n − k·(p − 1)` bits. Every pair of pieces is one hard multiplier.
//! - A top chunk of at most [`LUT_CHUNK`] bits may instead be multiplied by the whole other
//!   operand in LUTs (a shift-and-add of `h` rows of `m + 1`-bit adders, `m` the other
//!   operand's width), which removes that chunk's row of hard multipliers. At most one operand's
//!   top chunk goes to LUTs.
//! - Of both orientations and the three options (no LUT chunk, a's top, b's top), the one with
//!   the fewest hard multipliers is taken, ties broken by fewer LUT bits (`h·m`).
//!
//! The LUT cost is reported as LUT bits `h·m` (the rows' partial-product bits); the adders are
//! about `h·(m + 1)` LUT6 with carry chains (Yosys 0.23 on a lone `uvt_mul`: 18 × 32 → one
//! DSP48E1 and 169 LUTs, the 8 × 32 LUT chunk included). Summing the partial products (fabric or
//! cascade) is not counted. Hand cases (tested): 25×18 → 1, 26×18 → 1 + LUT 2×18, 32×32 → 2 +
//! LUT 8×32, 31×31 → 2 + LUT 7×31, 62×31 → 4 + LUT 7×62, 64×64 → 12.

use serde::Serialize;
use uvt_core::config::registry::{self, Config, EXACT};
use uvt_core::widths::row::Mul;
use uvt_core::widths::stages::table;

/// Widest top chunk multiplied in LUTs instead of a row of hard multipliers.
pub const LUT_CHUNK: u32 = 8;

/// Hard multipliers and LUT bits of one product (see the module docs' tiling rule).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, serde::Deserialize)]
pub struct Tiling {
    /// hard multipliers (one per pair of pieces)
    pub hard: u32,
    /// LUT partial-product bits `h·m` of the top chunk multiplied in LUTs (0 if none)
    pub lut_bits: u32,
}

/// Unsigned low chunks of an `n`-bit signed operand on a `p`-bit signed port (`p ≥ 2`).
pub fn low_chunks(n: u32, p: u32) -> u32 {
    if n <= p {
        0
    } else {
        (n - p).div_ceil(p - 1)
    }
}

/// The tiling of a signed `a × b` product on signed `pa × pb` hard multipliers, top chunks of
/// at most `lut` bits allowed in LUTs (the rule of `vectors/rtl/uvt_mul.v`).
pub fn tiling(a: u32, b: u32, pa: u32, pb: u32, lut: u32) -> Tiling {
    let mut best: Option<Tiling> = None;
    for (x, y) in [(a, b), (b, a)] {
        let (kx, ky) = (low_chunks(x, pa), low_chunks(y, pb));
        let (hx, hy) = (x - kx * (pa - 1), y - ky * (pb - 1));
        let mut opts = vec![Tiling {
            hard: (kx + 1) * (ky + 1),
            lut_bits: 0,
        }];
        if kx > 0 && hx <= lut {
            opts.push(Tiling {
                hard: kx * (ky + 1),
                lut_bits: hx * y,
            });
        }
        if ky > 0 && hy <= lut {
            opts.push(Tiling {
                hard: (kx + 1) * ky,
                lut_bits: hy * x,
            });
        }
        for o in opts {
            if best.map_or(true, |b| (o.hard, o.lut_bits) < (b.hard, b.lut_bits)) {
                best = Some(o);
            }
        }
    }
    best.unwrap_or_default()
}

/// DSP48E1 (25 × 18 signed) tiling of one a × b signed product.
pub fn dsp48e1_tiling(a: u32, b: u32) -> Tiling {
    tiling(a, b, 25, 18, LUT_CHUNK)
}

/// DSP48E1 count of one a × b signed product.
pub fn dsp48e1(a: u32, b: u32) -> u32 {
    dsp48e1_tiling(a, b).hard
}

/// ECP5 MULT18X18D tiling of one a × b signed product (the RTL's ECP5 build: 18 × 18 signed).
pub fn ecp5_tiling(a: u32, b: u32) -> Tiling {
    tiling(a, b, 18, 18, LUT_CHUNK)
}

/// ECP5 MULT18X18D count of one a × b signed product.
pub fn ecp5(a: u32, b: u32) -> u32 {
    ecp5_tiling(a, b).hard
}

/// The multipliers and their cost of one stage of one configuration.
#[derive(Clone, Debug, Default, Serialize, serde::Deserialize)]
pub struct StageCost {
    /// stage name (`setup`, `bounds/tri`, `bounds/tile`, `sample`)
    pub stage: String,
    /// (signal, operand a bits, operand b bits, count)
    pub muls: Vec<(String, u32, u32, u32)>,
    /// number of products
    pub products: u64,
    /// Σ count·a·b
    pub bit_products: u64,
    /// Σ count·DSP48E1(a, b)
    pub dsp48e1: u64,
    /// Σ count·MULT18X18D(a, b)
    pub ecp5: u64,
    /// Σ count·LUT bits of the DSP48E1 tiling (top chunks multiplied in LUTs)
    #[serde(default)]
    pub dsp48e1_lut_bits: u64,
    /// Σ count·LUT bits of the MULT18X18D tiling
    #[serde(default)]
    pub ecp5_lut_bits: u64,
}

/// Every stage's cost of `cfg`.
pub fn stage_costs(cfg: &Config) -> Vec<StageCost> {
    let t = table(cfg);
    let mut out: Vec<StageCost> = Vec::new();
    for r in t.rows() {
        for m in r.mul.iter().flatten() {
            let Mul { a, b, count } = *m;
            let i = match out.iter().position(|s| s.stage == r.stage) {
                Some(i) => i,
                None => {
                    out.push(StageCost {
                        stage: r.stage.to_string(),
                        ..Default::default()
                    });
                    out.len() - 1
                }
            };
            let s = &mut out[i];
            let c = u64::from(count);
            s.muls.push((r.signal.to_string(), a, b, count));
            s.products += c;
            s.bit_products += c * u64::from(a) * u64::from(b);
            let (x, l) = (dsp48e1_tiling(a, b), ecp5_tiling(a, b));
            s.dsp48e1 += c * u64::from(x.hard);
            s.ecp5 += c * u64::from(l.hard);
            s.dsp48e1_lut_bits += c * u64::from(x.lut_bits);
            s.ecp5_lut_bits += c * u64::from(l.lut_bits);
        }
    }
    out
}

/// The sample test's cost of `cfg` (what `uvt precision` reports).
pub fn sample_cost(cfg: &Config) -> StageCost {
    stage_costs(cfg)
        .into_iter()
        .find(|s| s.stage == "sample")
        .unwrap_or_default()
}

/// Markdown: every multiplier of every stage of `cfg`, with the totals.
pub fn cost_md(cfg: &Config) -> String {
    let mut s = format!(
        "Multipliers of `{cfg}` (from `uvt widths --config {cfg}`; tiling of `vectors/rtl/uvt_mul.v`, top chunks ≤ {LUT_CHUNK} bits in LUTs):\n\n| stage | signal | a × b bits | count | bit-products | DSP48E1 (+ LUT bits) | MULT18X18D (+ LUT bits) |\n|---|---|---|---|---|---|---|\n"
    );
    let st = stage_costs(cfg);
    for g in &st {
        for (sig, a, b, n) in &g.muls {
            let (x, l) = (dsp48e1_tiling(*a, *b), ecp5_tiling(*a, *b));
            s += &format!(
                "| {} | {sig} | {a} × {b} | {n} | {} | {}{} | {}{} |\n",
                g.stage,
                u64::from(*n) * u64::from(a * b),
                n * x.hard,
                lut_note(n * x.lut_bits),
                n * l.hard,
                lut_note(n * l.lut_bits),
            );
        }
        s += &format!(
            "| **{}** | total | | {} | {} | {}{} | {}{} |\n",
            g.stage,
            g.products,
            g.bit_products,
            g.dsp48e1,
            lut_note(g.dsp48e1_lut_bits),
            g.ecp5,
            lut_note(g.ecp5_lut_bits)
        );
    }
    s
}

/// " + N LUT bits", or nothing for 0.
fn lut_note<T: Into<u64>>(n: T) -> String {
    match n.into() {
        0 => String::new(),
        n => format!(" + {n} LUT bits"),
    }
}

/// Markdown: the totals per configuration of the sweep and stage, with the sample test's DSP
/// figure against the exact configuration's.
pub fn summary_md() -> String {
    let mut s = String::from("| configuration | stage | products | Σ bit-products | DSP48E1 (+ LUT bits) | MULT18X18D (+ LUT bits) |\n|---|---|---|---|---|---|\n");
    let exact = sample_cost(&EXACT).dsp48e1;
    for e in registry::sweep() {
        let (name, cfg) = (e.name, e.config);
        for g in stage_costs(&cfg) {
            let rel = match (g.stage.as_str(), exact) {
                ("sample", e) if e > 0 => {
                    format!(" ({:.1}% of exact)", 100.0 * g.dsp48e1 as f64 / e as f64)
                }
                _ => String::new(),
            };
            s += &format!(
                "| {name} | {} | {} | {} | {}{rel}{} | {}{} |\n",
                g.stage,
                g.products,
                g.bit_products,
                g.dsp48e1,
                lut_note(g.dsp48e1_lut_bits),
                g.ecp5,
                lut_note(g.ecp5_lut_bits)
            );
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dsp48e1_hand_cases() {
        let t = |hard, lut_bits| Tiling { hard, lut_bits };
        assert_eq!(dsp48e1_tiling(25, 18), t(1, 0));
        assert_eq!(dsp48e1_tiling(18, 25), t(1, 0));
        // 26 on the 25-bit port: a 24-bit unsigned low chunk and a 2-bit top chunk in LUTs.
        assert_eq!(dsp48e1_tiling(26, 18), t(1, 2 * 18));
        assert_eq!(dsp48e1_tiling(18, 32), t(1, 8 * 18));
        assert_eq!(dsp48e1_tiling(32, 32), t(2, 8 * 32));
        assert_eq!(dsp48e1_tiling(31, 31), t(2, 7 * 31));
        // 62 × 31: the 31-bit operand on the 25-bit port (24 + 7, the 7 in LUTs), 62 bits on
        // the 18-bit port (17·3 + 11): four DSPs, 7 × 62 LUT bits.
        assert_eq!(dsp48e1_tiling(62, 31), t(4, 7 * 62));
        // 25 × 31: 25 on the 25-bit port, 31 = 17 + 14 on the 18-bit port (14 > 8: no LUT).
        assert_eq!(dsp48e1_tiling(25, 31), t(2, 0));
        // 64: 25-bit port 24 + 24 + 16, 18-bit port 17·3 + 13: no chunk ≤ 8 bits.
        assert_eq!(low_chunks(64, 25), 2);
        assert_eq!(low_chunks(64, 18), 3);
        assert_eq!(dsp48e1_tiling(64, 64), t(12, 0));
        assert_eq!(dsp48e1_tiling(2, 2), t(1, 0));
        // Without LUT chunks the old all-DSP tiling: 26 × 18 → 2, 32 × 32 → 4.
        assert_eq!(tiling(26, 18, 25, 18, 0).hard, 2);
        assert_eq!(tiling(32, 32, 25, 18, 0).hard, 4);
    }

    #[test]
    fn ecp5_hand_cases() {
        let t = |hard, lut_bits| Tiling { hard, lut_bits };
        assert_eq!(ecp5_tiling(18, 18), t(1, 0));
        assert_eq!(ecp5_tiling(19, 18), t(1, 2 * 18));
        // 32 = 17 + 15 on an 18-bit port (15 > 8): 2 × 1.
        assert_eq!(ecp5_tiling(32, 18), t(2, 0));
        assert_eq!(ecp5_tiling(36, 36), t(6, 2 * 36));
    }

    /// The default configuration's sample test costs at most a quarter of the exact one's DSP48E1
    /// estimate, both by the same tiling (issue 10's goal).
    #[test]
    fn default_sample_test_is_at_most_a_quarter_of_exact() {
        let exact = sample_cost(&EXACT).dsp48e1;
        let def =
            sample_cost(&Config::of::<uvt_core::config::precision::DefaultPrecision>()).dsp48e1;
        assert!(4 * def <= exact, "default {def} DSP48E1, exact {exact}");
    }

    /// The exact configuration's sample test costs what the issue estimates (~430 DSP48), the
    /// bounded ones less, and narrower offsets never cost more.
    #[test]
    fn sweep_costs_fall_with_the_widths() {
        let cost: Vec<StageCost> = registry::sweep().map(|e| sample_cost(&e.config)).collect();
        let exact = cost[0].dsp48e1;
        assert!(
            (400..=520).contains(&exact),
            "exact sample test {exact} DSP48E1"
        );
        for (n, c) in registry::sweep().map(|e| e.name).zip(&cost).skip(1) {
            assert!(c.dsp48e1 < exact / 2, "{n}: {c:?}");
            assert!(c.bit_products < cost[0].bit_products / 3, "{n}: {c:?}");
        }
        // Offsets 20 → 22 → 24 at the same grids: bit-products strictly fall.
        assert!(cost[1].bit_products > cost[2].bit_products);
        assert!(cost[2].bit_products > cost[3].bit_products);
    }

    /// The estimate is within 25% of the synthesized count (`host/report/synth.json`, made by
    /// `bash vectors/rtl/synth.sh`) for every synthesized configuration and both families.
    #[test]
    fn estimate_is_within_a_quarter_of_synthesis() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/report/synth.json");
        let v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
        let configs = v["configs"].as_array().unwrap();
        assert!(
            configs.len() >= 4,
            "{path}: {} configurations",
            configs.len()
        );
        for c in configs {
            let name = c["name"].as_str().unwrap();
            let model = sample_cost(&Config::parse(name).unwrap());
            for (fam, key, est) in [
                ("xilinx", "dsp48e1", model.dsp48e1),
                ("ecp5", "mult18x18d", model.ecp5),
            ] {
                let syn = c[fam][key].as_u64().unwrap();
                assert!(
                    4 * est.abs_diff(syn) <= syn,
                    "{name} {key}: estimate {est}, synthesized {syn} ({path})"
                );
            }
        }
    }
}
