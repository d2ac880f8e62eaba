//! The Markdown tables of `uvt precision`: the sweep with the costs of each configuration
//! ([`table_md`]) and the stress cases ([`stress_md`]).

use uvt_core::config::registry::{Config, EXACT};

use super::costs::Costs;
use super::row::PrecRow;

/// Markdown table of a sweep, with the costs of each configuration ([`super::costs`]).
pub fn table_md(rows: &[PrecRow], costs: &Costs) -> String {
    let mut s = String::from(
        "| configuration | tile | decisions ≠ f64 (rate, max px) | d_q px (scene / 960×540) | ≠ stated in px: beyond own d_q / stated in clip space: count (largest δ clip units) | degenerate after rounding | beyond bound (max ratio) | violations | ε x/y/w raw | STE core / f64 | STE loss vs exact | depth err LSB max (mean) | time ÷ f64 | host ns setup/tile/sample | M4F insn setup/tile/sample | sample test DSP48E1 / MULT18X18D (model) | sample test Σ bit-products | synthesized |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let exact_name = EXACT.to_string();
    for r in rows {
        let exact = rows
            .iter()
            .find(|x| x.config == exact_name && x.tile == r.tile);
        let planar = Config::parse(&r.config).is_some_and(|c| c.planar());
        let loss = exact
            .map(|x| {
                format!(
                    "{:.2}%",
                    100.0 * (x.ste[0] - r.ste[0]) / x.ste[0].max(1e-12)
                )
            })
            .unwrap_or_else(|| "–".into());
        let c = costs.of(&r.config);
        s += &format!(
            "| {} | {} | {} ({:.1e}, {:.4}) | {:.4} / {} | {} | {} | {} ({:.2}) | {} | {}/{}/{} | {:.2}% / {:.2}% | {loss} | {:.0} ({:.1}) | {:.2} | {} | {} | {} | {} | {} |\n",
            r.config, r.tile, r.differ, r.differ as f64 / r.compared.max(1) as f64, r.max_differ_px,
            r.d_q[0], if planar { "per primitive".to_string() } else { format!("{:.4}", r.d_q[1]) }, by_statement(r), r.degenerate, r.beyond_bound, r.max_ratio, r.violations,
            r.eps_raw[0], r.eps_raw[1], r.eps_raw[2], 100.0 * r.ste[0], 100.0 * r.ste[1],
            r.depth_lsb[0], r.depth_lsb[1], r.time_ratio_median,
            c.host_ns, c.m4, c.dsp, c.bit_products, c.synth
        );
    }
    s += &costs.notes();
    s
}

/// A row's differing decisions by the statement covering them (`crate::config::dq`): those of
/// primitives stated in pixels beyond their own d_q, then the count stated in clip space only,
/// their largest backward error and, when some, how many belong to primitives about which the
/// clip statement says nothing (δ above 1/16 of the primitive's extent).
fn by_statement(r: &PrecRow) -> String {
    let clip = match (r.differ_clip, r.differ_clip_uninformative) {
        (0, _) => "0".to_string(),
        (n, 0) => format!("{n} ({:.1e})", r.max_clip),
        (n, u) => format!("{n} ({:.1e}; {u} say nothing)", r.max_clip),
    };
    format!("{} / {clip}", r.beyond_dq)
}

/// Markdown table of stress cases.
pub fn stress_md(rows: &[(String, usize, PrecRow)]) -> String {
    let mut s = String::from("| case | triangles | STE core / f64 | decisions ≠ f64 (rate) | of which w ≤ 0 | max distance px | ≠ stated in px: beyond own d_q / stated in clip space: count (largest δ clip units) | beyond bound (max ratio) | depth err LSB max | violations | covered but not written |
|---|---|---|---|---|---|---|---|---|---|---|
");
    for (name, n, r) in rows {
        s += &format!(
            "| {name} | {n} | {:.2}% / {:.2}% | {} ({:.1e}) | {} | {:.2e} | {} | {} ({:.2}) | {:.0} | {} | {} |
",
            100.0 * r.ste[0],
            100.0 * r.ste[1],
            r.differ,
            r.differ as f64 / r.compared.max(1) as f64,
            r.behind,
            r.max_differ_px,
            by_statement(r),
            r.beyond_bound,
            r.max_ratio,
            r.depth_lsb[0],
            r.violations,
            r.lost
        );
    }
    s
}
