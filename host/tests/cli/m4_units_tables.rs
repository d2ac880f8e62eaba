//! docs/units.md's Cortex-M4F unit-program tables are `uvt m4-units` of the committed reports:
//! the blocks `m4-units`, `m4-units-same` (of `host/report/m4_units.json`) and
//! `m4-units-planar`, `m4-units-planar-same` (of `host/report/m4_units_planar.json`) equal the
//! first and second table the command prints. A report regenerated without splicing, or a
//! figure edited by hand, fails here; `bash host/report/regen.sh --only m4-units` puts it back.

use std::path::{Path, PathBuf};

use uvt_host::fit::m4::programs_md;
use uvt_host::splice::blocks;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The body of the block `name` of docs/units.md.
fn block(page: &str, name: &str) -> String {
    let b = blocks(page)
        .expect("docs/units.md's blocks")
        .into_iter()
        .find(|b| b.name == name)
        .unwrap_or_else(|| panic!("docs/units.md has no block {name}"));
    let lines: Vec<&str> = page.lines().collect();
    lines[b.begin..b.end - 1].join("\n")
}

#[test]
fn docs_unit_tables_are_the_committed_reports() {
    let page = std::fs::read_to_string(root().join("docs/units.md")).expect("docs/units.md");
    for (json, name) in [
        ("host/report/m4_units.json", "m4-units"),
        ("host/report/m4_units_planar.json", "m4-units-planar"),
    ] {
        let md = programs_md(&root().join(json)).unwrap_or_else(|e| panic!("{json}: {e:#}"));
        let tables: Vec<&str> = md.split("\n\n").map(str::trim_end).collect();
        assert_eq!(tables.len(), 2, "{json}: two tables expected:\n{md}");
        for (got_block, table) in [
            (name.to_string(), tables[0]),
            (format!("{name}-same"), tables[1]),
        ] {
            let doc = block(&page, &got_block);
            assert_eq!(
                doc.trim_end(),
                table,
                "docs/units.md block {got_block} differs from `uvt m4-units {json}` \
                 (bash host/report/regen.sh --only {name})"
            );
        }
    }
}

/// A report without the one-decimal figures (an older `--units` run) is refused, naming the file.
#[test]
fn a_report_without_the_net_figures_is_refused() {
    let dir = std::env::temp_dir().join(format!("uvt-m4-units-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let f = dir.join("old.json");
    std::fs::write(
        &f,
        r#"{"harness": {"flash": 100}, "units": [{"unit": "full", "flash": 200, "text": 1, "ram": 12, "stack": 4, "setup": 1, "bounds": 1, "sample": 1, "checksum": "0x0"}]}"#,
    )
    .expect("write");
    let e = format!("{:#}", programs_md(&f).expect_err("no net figures"));
    assert!(
        e.contains("old.json") && e.contains("one-decimal figures of unit full"),
        "{e}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
