//! The hardware multiplier cost of a configuration, from the width table `uvt_core::widths`
//! derives (one multiplier per product of two variables on the stage's worst-case path, fully
//! parallel: one setup per triangle, one tile per clock, one sample test per clock; constant
//! scalings by 2^k are wiring, divides are not multipliers and are listed by the width table).
//!
//! **Tiling.** A signed a × b product on hard multipliers splits each operand into pieces: the
//! top piece keeps the sign, the lower pieces are unsigned. The partial products are summed in
//! the fabric or the cascade (not counted).
//! - **DSP48E1** (Xilinx 7-series): one 25 × 18 two's-complement multiplier, no unsigned mode,
//!   so an unsigned lower piece takes `port − 1` bits. Pieces of an n-bit operand on a port of
//!   width p: `1` if n ≤ p, else `1 + ceil((n − p)/(p − 1))`; the count is the better of the two
//!   orientations, `min(pieces(a, 25)·pieces(b, 18), pieces(b, 25)·pieces(a, 18))`.
//!   Hand cases (tested): 25×18 → 1, 26×18 → 2, 32×32 → 4, 64×64 → 12.
//! - **ECP5 MULT18X18D** (Lattice): 18 × 18 with a signedness control per input, so lower pieces
//!   use all 18 bits unsigned: `ceil(a/18)·ceil(b/18)`. Hand cases: 18×18 → 1, 19×18 → 2,
//!   36×36 → 4, 37×36 → 6.

use serde::Serialize;
use uvt_core::widths::{table, Config, Mul};

/// The sweep of `uvt precision` (session names): exact first, then bounded from the default
/// candidate down to the narrowest.
pub const SWEEP: [&str; 7] = [
    "exact-16-16-16",
    "bounded-16-16-16-20",
    "bounded-16-16-16-22",
    "bounded-16-16-16-24",
    "bounded-12-12-12-24",
    "bounded-12-12-12-26",
    "bounded-8-8-8-28",
];

/// Pieces of an `n`-bit signed operand on a two's-complement port of width `p` (top piece
/// signed `p` bits, lower pieces unsigned `p − 1` bits).
pub fn pieces_signed_port(n: u32, p: u32) -> u32 {
    if n <= p {
        1
    } else {
        1 + (n - p).div_ceil(p - 1)
    }
}

/// DSP48E1 (25 × 18 signed) count of one a × b signed product.
pub fn dsp48e1(a: u32, b: u32) -> u32 {
    let one = pieces_signed_port(a, 25) * pieces_signed_port(b, 18);
    let two = pieces_signed_port(b, 25) * pieces_signed_port(a, 18);
    one.min(two)
}

/// ECP5 MULT18X18D count of one a × b signed product.
pub fn ecp5(a: u32, b: u32) -> u32 {
    a.div_ceil(18) * b.div_ceil(18)
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
}

/// Every stage's cost of `cfg`.
pub fn stages(cfg: &Config) -> Vec<StageCost> {
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
            s.dsp48e1 += c * u64::from(dsp48e1(a, b));
            s.ecp5 += c * u64::from(ecp5(a, b));
        }
    }
    out
}

/// The sample test's cost of `cfg` (what `uvt precision` reports).
pub fn sample_cost(cfg: &Config) -> StageCost {
    stages(cfg)
        .into_iter()
        .find(|s| s.stage == "sample")
        .unwrap_or_default()
}

/// Markdown: every multiplier of every stage of `cfg`, with the totals.
pub fn cost_md(cfg: &Config) -> String {
    let mut s = format!(
        "Multipliers of `{cfg}` (from `uvt widths --config {cfg}`):\n\n| stage | signal | a × b bits | count | bit-products | DSP48E1 | MULT18X18D |\n|---|---|---|---|---|---|---|\n"
    );
    let st = stages(cfg);
    for g in &st {
        for (sig, a, b, n) in &g.muls {
            s += &format!(
                "| {} | {sig} | {a} × {b} | {n} | {} | {} | {} |\n",
                g.stage,
                u64::from(*n) * u64::from(a * b),
                n * dsp48e1(*a, *b),
                n * ecp5(*a, *b)
            );
        }
        s += &format!(
            "| **{}** | total | | {} | {} | {} | {} |\n",
            g.stage, g.products, g.bit_products, g.dsp48e1, g.ecp5
        );
    }
    s
}

/// Markdown: the totals per configuration of the sweep and stage, with the sample test's DSP
/// figure against the exact configuration's.
pub fn summary_md() -> String {
    let mut s = String::from("| configuration | stage | products | Σ bit-products | DSP48E1 | MULT18X18D |\n|---|---|---|---|---|---|\n");
    let exact = Config::parse(SWEEP[0]).map(|c| sample_cost(&c).dsp48e1);
    for name in SWEEP {
        let Some(cfg) = Config::parse(name) else {
            continue;
        };
        for g in stages(&cfg) {
            let rel = match (g.stage.as_str(), exact) {
                ("sample", Some(e)) if e > 0 => {
                    format!(" ({:.1}% of exact)", 100.0 * g.dsp48e1 as f64 / e as f64)
                }
                _ => String::new(),
            };
            s += &format!(
                "| {name} | {} | {} | {} | {}{rel} | {} |\n",
                g.stage, g.products, g.bit_products, g.dsp48e1, g.ecp5
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
        assert_eq!(dsp48e1(25, 18), 1);
        assert_eq!(dsp48e1(18, 25), 1);
        assert_eq!(dsp48e1(26, 18), 2);
        assert_eq!(dsp48e1(25, 19), 2);
        assert_eq!(dsp48e1(32, 32), 4);
        // 64: three pieces on the 25-bit port (25 + 24 + 24 ≥ 64 with one signed top), four on
        // the 18-bit port (18 + 17·3 ≥ 64).
        assert_eq!(pieces_signed_port(64, 25), 3);
        assert_eq!(pieces_signed_port(64, 18), 4);
        assert_eq!(dsp48e1(64, 64), 12);
        assert_eq!(dsp48e1(2, 2), 1);
    }

    #[test]
    fn ecp5_hand_cases() {
        assert_eq!(ecp5(18, 18), 1);
        assert_eq!(ecp5(19, 18), 2);
        assert_eq!(ecp5(36, 36), 4);
        assert_eq!(ecp5(37, 36), 6);
    }

    /// The exact configuration's sample test costs what the issue estimates (~430 DSP48), the
    /// bounded ones less, and narrower offsets never cost more.
    #[test]
    fn sweep_costs_fall_with_the_widths() {
        let cost: Vec<StageCost> = SWEEP
            .iter()
            .map(|n| sample_cost(&Config::parse(n).unwrap()))
            .collect();
        let exact = cost[0].dsp48e1;
        assert!(
            (400..=520).contains(&exact),
            "exact sample test {exact} DSP48E1"
        );
        for (n, c) in SWEEP.iter().zip(&cost).skip(1) {
            assert!(c.dsp48e1 < exact / 2, "{n}: {c:?}");
            assert!(c.bit_products < cost[0].bit_products / 3, "{n}: {c:?}");
        }
        // Offsets 20 → 22 → 24 at the same grids: bit-products strictly fall.
        assert!(cost[1].bit_products > cost[2].bit_products);
        assert!(cost[2].bit_products > cost[3].bit_products);
    }
}
