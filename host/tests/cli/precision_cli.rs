//! `uvt precision --quick` end to end on a tiny size: at least six configurations with the M4
//! and DSP columns filled, a non-flat cost axis, the plot written; a bad cost file is refused
//! with its path before any sweeping.

use std::process::Command;

use uvt_core::config::registry::PLANAR;

fn uvt(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_uvt"))
        .args(args)
        .output()
        .expect("run uvt")
}

#[test]
fn precision_quick_prints_the_sweep_with_costs() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("p");
    let m4 = concat!(env!("CARGO_MANIFEST_DIR"), "/report/m4.json");
    let none = dir.path().join("no-synth.json");
    let o = uvt(&[
        "precision",
        "--quick",
        "--shrink",
        "8",
        "--out",
        out.to_str().unwrap(),
        "--m4",
        m4,
        "--synth",
        none.to_str().unwrap(),
    ]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success(),
        "{text}\n{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let header = text.lines().next().unwrap();
    let cols: Vec<&str> = header.split('|').map(str::trim).collect();
    let col = |name: &str| {
        cols.iter()
            .position(|c| c.starts_with(name))
            .unwrap_or_else(|| panic!("no column {name:?} in {header}"))
    };
    let (m4c, dspc, cfgc) = (
        col("M4F insn"),
        col("sample test DSP48E1"),
        col("configuration"),
    );
    let rows: Vec<Vec<&str>> = text
        .lines()
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(|l| l.split('|').map(str::trim).collect())
        .collect();
    let mut names: Vec<&str> = rows.iter().map(|r| r[cfgc]).collect();
    names.dedup();
    assert!(names.len() >= 6, "configurations: {names:?}");
    let mut dsp = Vec::new();
    for r in &rows {
        if r[cfgc] == PLANAR.to_string() {
            // `m4_report.sh --sweep` (host/report/m4.json) does not build the planar
            // configuration: its M4 cell says so ("–"); its model DSP cell is checked below.
            assert_eq!(r[m4c], "–", "planar M4 cell");
        } else {
            let m: Vec<f64> = r[m4c].split('/').map(|x| x.parse().unwrap()).collect();
            assert!(
                m.len() == 3 && m.iter().all(|&x| x > 0.0),
                "M4 cell {:?}",
                r[m4c]
            );
        }
        dsp.push(
            r[dspc]
                .split('/')
                .next()
                .unwrap()
                .trim()
                .parse::<u64>()
                .unwrap(),
        );
    }
    let (lo, hi) = (dsp.iter().min().unwrap(), dsp.iter().max().unwrap());
    assert!(hi > &(2 * lo), "the DSP axis is flat: {dsp:?}");
    let svg = std::fs::read_to_string(out.join("precision.svg")).unwrap();
    assert!(svg.contains("Pareto front") && svg.contains("DSP48E1"));
    assert!(svg.contains("Cortex-M4F instructions"));
    for f in ["precision.md", "precision.json"] {
        assert!(out.join(f).exists(), "{f}");
    }
}

#[test]
fn precision_refuses_a_bad_cost_file() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("m4.json");
    std::fs::write(&bad, "{\"configs\": 3}").unwrap();
    let out = dir.path().join("p");
    let o = uvt(&[
        "precision",
        "--quick",
        "--out",
        out.to_str().unwrap(),
        "--m4",
        bad.to_str().unwrap(),
    ]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(err.contains(bad.to_str().unwrap()), "{err}");
    assert!(!out.exists(), "nothing written");
}

#[test]
fn widths_and_cost_commands() {
    let o = uvt(&["widths", "--config", "bounded-8-8-8-28"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success());
    assert!(text.contains("Configuration `bounded-8-8-8-28`"), "{text}");
    let o = uvt(&["widths", "--config", "bounded-16-16-16-19"]);
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("bounded-16-16-16-19"));
    // The width table and the cost model cover the exact and bounded datapaths: a planar name
    // is refused by all three commands, naming what they cover and the bounded base.
    let pl = PLANAR.to_string();
    for args in [
        &["widths", "--config", &pl][..],
        &["cost", "--config", &pl][..],
        &["units", "--config", &pl][..],
    ] {
        let o = uvt(args);
        let e = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success(), "{args:?}");
        assert!(
            e.contains(&pl)
                && e.contains("exact-P-T-B, bounded-P-T-B-O")
                && e.contains(&PLANAR.bounded_base().to_string()),
            "{args:?}: {e}"
        );
        assert!(o.stdout.is_empty(), "{args:?}");
    }
    // Any in-range name, in or out of the registry.
    let o = uvt(&["cost", "--config", "bounded-10-12-9-23"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = uvt(&["cost"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success());
    assert!(
        text.contains(
            "| exact-16-16-16 | sample | 60 | 161895 | 414 (100.0% of exact) + 12648 LUT bits"
        ),
        "{text}"
    );
}
