//! The registered multiplier of the units' `PIPE = 2` builds (`vectors/rtl/uvt_mul.v` `REG = 3`:
//! every hard piece with input, pipeline and output registers, a LUT chunk's rows as terms, a
//! registered adder tree) streams the exact product, one pair per clock, at the operand widths
//! and LUT chunk limits the units use, in its behavioural form (`MAP = 0`) and as instantiated
//! ECP5 MULT18X18D primitives (`MAP = 1`, `uvt_mult18.v` on the model
//! `vectors/rtl/ecp5/MULT18X18D.v`), with the same tiling; a latency below its tree's depth does
//! not elaborate; and a mutated adder, primitive model or pin wiring is caught.

use std::path::Path;

use uvt_tests::icarus;
use uvt_tests::{extensive, seed};

/// (AW, BW, LW, LAT): the products of the units (the planar unit's 21 × 13 and 32 × 32, the
/// bounded sample test's 31 × 31, 62 × 31, 13 × 32 and 18 × 32, the bounds unit's 46 × 17 and
/// 59 × 82) with and without a LUT chunk, each at its smallest latency (3 + the tree's levels).
const CASES: [(u32, u32, u32, u32); 10] = [
    (18, 18, 0, 3),
    (21, 13, 8, 6),
    (32, 32, 0, 5),
    (31, 31, 17, 8),
    (62, 31, 0, 6),
    (62, 31, 17, 9),
    (13, 32, 8, 7),
    (18, 32, 0, 4),
    (46, 17, 0, 5),
    (59, 82, 8, 8),
];

fn sources(map: u32) -> Vec<&'static str> {
    let mut s = vec!["uvt_mul.v", "tb_mul.v"];
    if map == 1 {
        s.extend(["uvt_mult18.v", "ecp5/MULT18X18D.v"]);
    }
    s
}

fn params(a: u32, b: u32, lw: u32, lat: u32, map: u32) -> Vec<(&'static str, String)> {
    let p = |k: &'static str, v: u32| (k, v.to_string());
    vec![
        p("tb_mul.AW", a),
        p("tb_mul.BW", b),
        p("tb_mul.PA", 18),
        p("tb_mul.PB", 18),
        p("tb_mul.LW", lw),
        p("tb_mul.REG", 3),
        p("tb_mul.LAT", lat),
        p("tb_mul.MAP", map),
    ]
}

fn pass_line(out: &str) -> Option<&str> {
    out.lines().find(|l| l.starts_with("PASS "))
}

#[test]
fn registered_multiplier_streams_the_exact_product_in_both_forms() {
    let seed = seed();
    let nr = if extensive() { 20_000 } else { 500 };
    let dir = tempfile::tempdir().unwrap();
    for (a, b, lw, lat) in CASES {
        let mut lines = Vec::new();
        // The combinational form's tiling, for comparison.
        let p = |k: &'static str, v: u32| (k, v.to_string());
        let tb0 = icarus::compile(
            &dir.path().join(format!("mul-{a}x{b}-{lw}-comb.vvp")),
            &[
                p("tb_mul.AW", a),
                p("tb_mul.BW", b),
                p("tb_mul.PA", 18),
                p("tb_mul.PB", 18),
                p("tb_mul.LW", lw),
            ],
            &["uvt_mul.v", "tb_mul.v"],
        );
        let out = icarus::run(&tb0, &["+NR=1".to_string()]);
        let comb = pass_line(&out).expect("PASS").to_string();
        let tiling = comb.split(": ").nth(1).expect("tiling").to_string();
        for map in [0, 1] {
            let tb = icarus::compile(
                &dir.path().join(format!("mul-{a}x{b}-{lw}-{map}.vvp")),
                &params(a, b, lw, lat, map),
                &sources(map),
            );
            let out = icarus::run(&tb, &[format!("+SEED={seed}"), format!("+NR={nr}")]);
            let line = pass_line(&out).unwrap_or_else(|| {
                panic!("{a} × {b}, LW = {lw}, LAT = {lat}, MAP = {map} (UVT_SEED={seed}): {out}")
            });
            assert!(
                line.starts_with(&format!("PASS {} products", 36 + nr)) && line.ends_with(&tiling),
                "{a} × {b}, LW = {lw}, MAP = {map}: '{line}', the combinational form tiles as '{tiling}'"
            );
            lines.push(line.to_string());
        }
        assert_eq!(
            lines[0], lines[1],
            "{a} × {b}, LW = {lw}: MAP 0 and 1 differ"
        );
    }
}

/// LAT one clock below 3 + the tree's levels does not elaborate (the named error module).
#[test]
fn registered_multiplier_refuses_a_latency_below_its_tree() {
    let dir = tempfile::tempdir().unwrap();
    for (a, b, lw, lat) in [(32, 32, 0, 5), (59, 82, 8, 8), (18, 18, 0, 3)] {
        let o = std::process::Command::new("iverilog")
            .args(["-g2005", "-o"])
            .arg(dir.path().join("short.vvp"))
            .args(
                params(a, b, lw, lat - 1, 0)
                    .iter()
                    .map(|(k, v)| format!("-P{k}={v}")),
            )
            .args(sources(0).iter().map(|s| icarus::rtl_dir().join(s)))
            .output()
            .expect("iverilog");
        let text =
            String::from_utf8_lossy(&o.stderr).to_string() + &String::from_utf8_lossy(&o.stdout);
        assert!(
            !o.status.success() && text.contains("uvt_mul_LAT_below_3_plus_tree_levels"),
            "{a} × {b}, LAT = {}: {text}",
            lat - 1
        );
    }
}

/// A copy of `file` (in `vectors/rtl`) with `from` replaced by `to` (exactly once) in `dir`.
fn mutant(dir: &Path, file: &str, from: &str, to: &str) -> String {
    let text = std::fs::read_to_string(icarus::rtl_dir().join(file)).unwrap();
    assert_eq!(
        text.matches(from).count(),
        1,
        "{file}: '{from}' not found once"
    );
    let out = dir.join(file.replace('/', "-"));
    std::fs::write(&out, text.replace(from, to)).unwrap();
    out.to_str().unwrap().to_string()
}

/// Each mutation makes the streamed check fail (vvp exits non-zero): the tree's wired low bits of
/// the lower-shifted operand dropped, the model's pipeline register skipped, two pins of the instance swapped.
#[test]
fn registered_multiplier_bench_catches_a_mutated_adder_model_or_wiring() {
    let dir = tempfile::tempdir().unwrap();
    let rtl = |f: &str| icarus::rtl_dir().join(f).to_str().unwrap().to_string();
    let runs: [(&str, &str, &str, u32); 3] = [
        ("uvt_mul.v", "ua[Z-1:0] | ub[Z-1:0]", "ub[Z-1:0]", 0),
        ("ecp5/MULT18X18D.v", "orr <= RP ? pr : m;", "orr <= m;", 1),
        (
            "uvt_mult18.v",
            ".A0(a[0]), .A1(a[1])",
            ".A0(a[1]), .A1(a[0])",
            1,
        ),
    ];
    for (file, from, to, map) in runs {
        let m = mutant(dir.path(), file, from, to);
        let srcs: Vec<String> = sources(map)
            .iter()
            .map(|s| if *s == file { m.clone() } else { rtl(s) })
            .collect();
        let srcs: Vec<&str> = srcs.iter().map(String::as_str).collect();
        let tb = icarus::compile(
            &dir.path()
                .join(format!("mutant-{map}-{}.vvp", file.replace('/', "-"))),
            &params(62, 31, 17, 9, map),
            &srcs,
        );
        let out = icarus::run_failing(&tb, &["+NR=200".to_string()]);
        assert!(out.contains("MISMATCH"), "{file}: '{from}' → '{to}': {out}");
    }
}
