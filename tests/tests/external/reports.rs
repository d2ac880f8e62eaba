//! The committed Cortex-M figures are what their commands print with the pinned toolchain
//! (`rust-toolchain.toml`): `bash demo/m4_report.sh --units` always, and with `UVT_EXTENSIVE=1`
//! also `--units … planar-16-16-16-20` and `--sweep`, are run into temporary files and compared with `host/report/m4_units.json`,
//! `m4_units_planar.json` and `m4.json` field by field (host nanoseconds excepted: they are
//! timings); `bash demo/m4_report.sh`'s tables must appear in `docs/performance.md` row by row
//! (its host-ns column excepted) and its figures in README.md's headline rows. A figure that
//! moved — a new compiler, a changed workload — fails here until the files are regenerated.
//! (`uvt widths` against `core/README.md` is checked by `core/src/widths/mod.rs`, `uvt cost` against
//! its cost paragraph by `host/tests/cli/cost_text.rs`.)

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

/// Run `bash demo/m4_report.sh ARGS` from the repository root in `target/m4-test` (the outer
/// `cargo test` holds `target/`; `m4_qemu.rs` builds the same programs there); its standard
/// output. One run at a time with `m4_qemu.rs`'s builds (same test binary, same output paths).
fn m4_report(args: &[&str]) -> String {
    let _one = crate::m4_qemu::M4F
        .lock()
        .unwrap_or_else(|e| e.into_inner());
    let o = Command::new("bash")
        .current_dir(root())
        .arg("demo/m4_report.sh")
        .args(args)
        .env("CARGO_TARGET_DIR", root().join("target").join("m4-test"))
        .env_remove("UVT_M4_UNIT")
        .env_remove("UVT_M4_PREC")
        .output()
        .expect("run bash demo/m4_report.sh");
    assert!(
        o.status.success(),
        "m4_report.sh {args:?} failed:\n{}\n{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn json(p: &Path) -> Value {
    let t = std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    serde_json::from_str(&t).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// `v` without the keys that are not figures of the program (the command line that made it)
/// or are host timings.
fn figures(v: &Value) -> Value {
    match v {
        Value::Object(m) => Value::Object(
            m.iter()
                .filter(|(k, _)| !matches!(k.as_str(), "command" | "host_ns"))
                .map(|(k, x)| (k.clone(), figures(x)))
                .collect(),
        ),
        Value::Array(a) => Value::Array(a.iter().map(figures).collect()),
        x => x.clone(),
    }
}

/// Every differing leaf of two JSON values, as `path: committed → measured`.
fn differences(path: &str, a: &Value, b: &Value, out: &mut Vec<String>) {
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => {
            for k in x.keys().chain(y.keys().filter(|k| !x.contains_key(*k))) {
                let null = Value::Null;
                differences(
                    &format!("{path}.{k}"),
                    x.get(k).unwrap_or(&null),
                    y.get(k).unwrap_or(&null),
                    out,
                );
            }
        }
        (Value::Array(x), Value::Array(y)) if x.len() == y.len() => {
            for (i, (p, q)) in x.iter().zip(y).enumerate() {
                differences(&format!("{path}[{i}]"), p, q, out);
            }
        }
        (p, q) if p != q => out.push(format!("{path}: committed {p} → measured {q}")),
        _ => {}
    }
}

fn check_json(committed: &str, args: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("m4.json");
    let mut a = vec![args[0], out.to_str().unwrap()];
    a.extend_from_slice(&args[1..]);
    m4_report(&a);
    let mut diffs = Vec::new();
    differences(
        "",
        &figures(&json(&root().join(committed))),
        &figures(&json(&out)),
        &mut diffs,
    );
    assert!(
        diffs.is_empty(),
        "{committed} is not what `bash demo/m4_report.sh {}` prints; regenerate it:\n{}",
        args.join(" "),
        diffs.join("\n")
    );
}

/// The Markdown rows of `text`, each without the columns from its table's "host ns" header
/// cell on (a header is the row above a `|---` line).
fn rows_without_host(text: &str) -> Vec<String> {
    let lines: Vec<&str> = text.lines().collect();
    let mut keep = usize::MAX;
    let mut out = Vec::new();
    for (i, l) in lines.iter().enumerate() {
        if !l.starts_with('|') || l.starts_with("|---") {
            continue;
        }
        let cells: Vec<&str> = l.trim_matches('|').split('|').collect();
        if lines.get(i + 1).is_some_and(|n| n.starts_with("|---")) {
            keep = cells
                .iter()
                .position(|c| c.contains("host ns"))
                .unwrap_or(usize::MAX);
        }
        let n = keep.min(cells.len());
        out.push(format!("|{}|", cells[..n].join("|")));
    }
    out
}

/// The unit programs' figures (flash, RAM, stack, instructions per call, checksums): the cheap
/// one, always run.
#[test]
fn committed_unit_figures_are_what_m4_report_units_prints() {
    check_json("host/report/m4_units.json", &["--units"]);
}

/// The other three Cortex-M reports (about a minute more once built; a first build several):
/// with `UVT_EXTENSIVE=1`.
#[test]
fn committed_cortex_m_figures_are_what_the_commands_print() {
    if std::env::var("UVT_EXTENSIVE").as_deref() != Ok("1") {
        eprintln!("skipped: set UVT_EXTENSIVE=1 (m4_report.sh planar units, --sweep, default)");
        return;
    }
    check_json(
        "host/report/m4_units_planar.json",
        &["--units", "planar-16-16-16-20"],
    );
    check_json("host/report/m4.json", &["--sweep"]);
    // The default report's tables in docs/performance.md, row by row without host timings.
    let printed = m4_report(&[]);
    let doc = std::fs::read_to_string(root().join("docs/performance.md")).unwrap();
    let doc_rows = rows_without_host(&doc);
    let rows = rows_without_host(&printed);
    assert!(rows.len() >= 10, "{printed}");
    for r in &rows {
        assert!(
            doc_rows.contains(r),
            "docs/performance.md lacks the row {r} of `bash demo/m4_report.sh`; regenerate it"
        );
    }
    // README.md's headline rows carry the bounded stages' instructions and the program's size.
    let cell = |stage: &str, col: usize| -> String {
        printed
            .lines()
            .find(|l| l.starts_with(&format!("| {stage} |")))
            .and_then(|l| l.split('|').nth(col + 1).map(|c| c.trim().to_string()))
            .unwrap_or_else(|| panic!("no {stage} row in:\n{printed}"))
    };
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let m4 = format!(
        "{} / {} / {} (Cortex-M3: {} / {} / {})",
        cell("setup_bounded", 1),
        cell("bounds_bounded", 1),
        cell("sample_bounded", 1),
        cell("setup_bounded", 2),
        cell("bounds_bounded", 2),
        cell("sample_bounded", 2)
    );
    assert!(readme.contains(&m4), "README.md lacks {m4}");
    let flash = cell("flash: .vector_table + .text + .rodata", 1);
    let flash = flash.split_whitespace().next().unwrap();
    let stack = cell("RAM: peak stack (painted)", 1);
    let ram = cell("RAM: .data + .bss", 1);
    let size = format!("{flash} / {ram} / {stack} bytes");
    assert!(readme.contains(&size), "README.md lacks {size}");
}
