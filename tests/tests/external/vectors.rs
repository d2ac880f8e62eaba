//! Golden vectors: the committed set matches the core bit for bit; a fresh export with the
//! documented arguments reproduces it byte for byte (so any change in the core's bits fails here
//! until the vectors are regenerated on purpose); damage is caught with a clear message; frame
//! vectors agree with the renderer; and an RTL unit consumes them under Icarus Verilog.

use std::path::{Path, PathBuf};

use uvt_host::vectors;
use uvt_host::vectors::check::check;
use uvt_host::vectors::format::sha256;
use uvt_tests::icarus;

fn committed() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../vectors")
}

const SETS: [&str; 4] = ["unit", "unit_exact", "frame_a", "frame_b"];

fn copy_set(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap() {
        let p = e.unwrap().path();
        std::fs::copy(&p, to.join(p.file_name().unwrap())).unwrap();
    }
}

#[test]
fn committed_vectors_match_the_core() {
    let c = check(&committed()).unwrap_or_else(|e| panic!("{e:#}"));
    assert_eq!(c.sets.len(), 4);
    assert!(c.records > 20_000, "{c:?}");
}

#[test]
fn regenerated_vectors_are_byte_identical() {
    let dir = tempfile::tempdir().unwrap();
    vectors::committed::export_default(dir.path(), vectors::committed::DEFAULT_SEED, None).unwrap();
    for set in SETS {
        for e in std::fs::read_dir(dir.path().join(set)).unwrap() {
            let p = e.unwrap().path();
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            let fresh = std::fs::read(&p).unwrap();
            let old = std::fs::read(committed().join(set).join(&name)).unwrap_or_default();
            assert!(
                fresh == old,
                "vectors/{set}/{name} differs from a fresh export: the core's bits (or the format) changed. \
                 If that is intended, regenerate with `cargo run --release -p uvt-host -- vectors export --out vectors` and commit."
            );
        }
    }
    // Deterministic: a second export is identical too.
    let again = tempfile::tempdir().unwrap();
    vectors::committed::export_default(again.path(), vectors::committed::DEFAULT_SEED, None)
        .unwrap();
    let a = std::fs::read(dir.path().join("unit_exact/sample_out.hex")).unwrap();
    let b = std::fs::read(again.path().join("unit_exact/sample_out.hex")).unwrap();
    assert_eq!(sha256(&a), sha256(&b));
}

#[test]
fn truncated_or_corrupted_file_is_caught_by_its_checksum() {
    let dir = tempfile::tempdir().unwrap();
    let set = dir.path().join("unit");
    copy_set(&committed().join("unit"), &set);
    let f = set.join("bounds_out.hex");
    let text = std::fs::read_to_string(&f).unwrap();
    std::fs::write(&f, &text[..text.len() / 2]).unwrap();
    let e = format!("{:#}", check(&set).unwrap_err());
    assert!(
        e.contains("bounds_out.hex") && e.contains("corrupted or truncated"),
        "{e}"
    );
}

#[test]
fn a_changed_bit_is_reported_with_file_line_and_field() {
    let dir = tempfile::tempdir().unwrap();
    let set = dir.path().join("unit_exact");
    copy_set(&committed().join("unit_exact"), &set);
    // Change the depth (word 1) of the first covered sample, and fix the manifest checksum so
    // the change reaches the bit comparison.
    let text = std::fs::read_to_string(set.join("sample_out.hex")).unwrap();
    let (idx, line) = text
        .lines()
        .enumerate()
        .find(|(_, l)| l.starts_with("00000003") || l.starts_with("00000007"))
        .expect("a covered sample");
    let depth = u32::from_str_radix(line.split(' ').nth(1).unwrap(), 16).unwrap();
    corrupt_word(&set, "sample_out.hex", idx, 1, depth ^ 1);
    let e = format!("{:#}", check(&set).unwrap_err());
    assert!(
        e.contains(&format!("sample_out.hex line {} field depth", idx + 1))
            && e.contains("expected 0x")
            && e.contains("observed 0x"),
        "{e}"
    );
}

/// Replace word `word` of record `line` (0-based) of `file` in a copied set, fixing the manifest
/// checksum so the record reaches the core.
fn corrupt_word(set: &Path, file: &str, line: usize, word: usize, value: u32) {
    let f = set.join(file);
    let text = std::fs::read_to_string(&f).unwrap();
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let mut words: Vec<String> = lines[line].split(' ').map(String::from).collect();
    words[word] = format!("{value:08x}");
    lines[line] = words.join(" ");
    let new = lines.join("\n") + "\n";
    std::fs::write(&f, &new).unwrap();
    let m = set.join("manifest.json");
    let mt = std::fs::read_to_string(&m)
        .unwrap()
        .replace(&sha256(text.as_bytes()), &sha256(new.as_bytes()));
    std::fs::write(&m, mt).unwrap();
}

/// Decoded input records go through the core's checked constructors: an out-of-domain sample
/// (t = 256, which reached 2^70 products in the sample test before) or interval is refused with
/// file, record and field, not fed to the core.
#[test]
fn out_of_domain_input_records_are_refused_with_file_record_and_field() {
    let dir = tempfile::tempdir().unwrap();
    let set = dir.path().join("unit_exact");
    copy_set(&committed().join("unit_exact"), &set);
    // sample_in word 5 is t (raw I16F16): 256.0.
    corrupt_word(&set, "sample_in.hex", 2, 5, 256 << 16);
    // select_in word 0 is u_lo: -2.0.
    corrupt_word(&set, "select_in.hex", 4, 0, (-131072i32) as u32);
    let e = format!("{:#}", check(&set).unwrap_err());
    assert!(
        e.contains(
            "sample_in.hex line 3: input sample refused by the core: sample t = raw 0x01000000"
        ),
        "{e}"
    );
    assert!(
        e.contains(
            "select_in.hex line 5: fields u_lo, u_hi refused by the core: interval [0xfffe0000"
        ),
        "{e}"
    );
}

/// Frame vectors' resolved pixels (trace) equal `uvt render`'s image of the same scene at the
/// same configuration: the committed sets (the default configuration) and fresh exports at an
/// exact, a coarse bounded and the planar configuration; every traced sample outside its
/// tile's box is uncovered; the manifest names the configuration.
#[test]
fn frame_vectors_agree_with_the_renderer() {
    use uvt_core::config::registry::{find, DEFAULT};
    use uvt_host::render::{opts::RenderOpts, scene_render::render_with};
    let fresh = tempfile::tempdir().unwrap();
    let mut runs = vec![(committed(), DEFAULT)];
    for name in ["exact-8-8-4", "bounded-8-8-8-28", "planar-16-16-16-20"] {
        let cfg = find(name).unwrap();
        let dir = fresh.path().join(name);
        vectors::committed::export_default(&dir, vectors::committed::DEFAULT_SEED, Some(cfg))
            .unwrap();
        runs.push((dir, cfg));
    }
    for (root, cfg) in runs {
        for (set, text) in [
            ("frame_a", vectors::committed::FRAME_A),
            ("frame_b", vectors::committed::FRAME_B),
        ] {
            let s = uvt_host::scene::file::Scene::parse(text, set, Path::new(".")).unwrap();
            let o = RenderOpts {
                precision: cfg,
                ..RenderOpts::default()
            };
            let image = render_with(&s, &o).unwrap().fixed.image;
            let dir = root.join(set);
            let m: serde_json::Value =
                serde_json::from_str(&std::fs::read_to_string(dir.join("manifest.json")).unwrap())
                    .unwrap();
            assert_eq!(m["config"], cfg.to_string(), "{}", dir.display());
            let trace = std::fs::read_to_string(dir.join("trace.jsonl")).unwrap();
            let mut n = 0;
            for line in trace.lines().filter(|l| l.contains("\"type\":\"pixel\"")) {
                let v: serde_json::Value = serde_json::from_str(line).unwrap();
                let (x, y) = (
                    v["px"].as_u64().unwrap() as usize,
                    v["py"].as_u64().unwrap() as usize,
                );
                let rgb: Vec<u8> = v["rgb"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|c| c.as_u64().unwrap() as u8)
                    .collect();
                assert_eq!(
                    rgb,
                    image[y * s.viewport.0 as usize + x].to_vec(),
                    "{set} at {cfg}: pixel ({x},{y})"
                );
                n += 1;
            }
            assert_eq!(n, 32 * 32);
            for line in trace.lines().filter(|l| l.contains("\"type\":\"sample\"")) {
                let v: serde_json::Value = serde_json::from_str(line).unwrap();
                assert!(
                    v["inside"].as_bool().unwrap() || !v["covered"].as_bool().unwrap(),
                    "{set} at {cfg}: {line}"
                );
            }
        }
    }
}

fn iverilog(set: &Path, tb: &Path) -> String {
    icarus::run_vectors(tb, set, "select", &[])
}

#[test]
fn rtl_interval_check_passes_every_exported_record() {
    let dir = tempfile::tempdir().unwrap();
    let tb = icarus::compile(
        &dir.path().join("tb.vvp"),
        &[],
        &["uvt_interval_check.v", "tb_interval_check.v"],
    );
    for set in SETS {
        let out = iverilog(&committed().join(set), &tb);
        assert!(out.contains("PASS"), "{set}: {out}");
    }
    // The testbench can fail: flip one expected bit in a copy.
    let bad = dir.path().join("bad");
    copy_set(&committed().join("frame_a"), &bad);
    let f = bad.join("select_out.hex");
    let t = std::fs::read_to_string(&f).unwrap();
    let flipped = if t.starts_with("00000001") {
        t.replacen("00000001", "00000000", 1)
    } else {
        t.replacen("00000000", "00000001", 1)
    };
    std::fs::write(&f, flipped).unwrap();
    let out = icarus::run_vectors_failing(&tb, &bad, "select", &[]);
    assert!(
        out.contains("FAIL 1 of") && out.contains("MISMATCH line 1"),
        "{out}"
    );
}

/// vectors/README.md carries the current bit-layout tables.
#[test]
fn readme_layout_tables_are_current() {
    let readme = std::fs::read_to_string(committed().join("README.md")).unwrap();
    for st in vectors::format::STAGES {
        for io in ["in", "out"] {
            let spp = if st == "resolve" { 4 } else { 0 };
            let table = vectors::format::layout_md(&format!("{st}_{io}"), spp);
            assert!(readme.contains(&table), "vectors/README.md lacks the current layout of {st}_{io}; paste `uvt vectors layout`");
        }
    }
}
