//! The bounded sample-test vectors (`bsample_{in,out}.hex`) and the RTL unit that consumes them
//! (`vectors/rtl/uvt_bsample.v`): the committed records cover the edge cases they claim, the
//! checker reports a changed or invalid record by field, and under Icarus Verilog the unit
//! reproduces every committed record bit for bit, reproduces freshly generated records of other
//! configurations (its POS / TUV / OFF parameters), and a flipped expected bit is caught.
//!
//! `UVT_SEED` seeds the other configurations' records (printed on failure); `UVT_EXTENSIVE=1`
//! runs every configuration of the precision sweep instead of two.

use std::path::{Path, PathBuf};
use std::process::Command;

use uvt_host::vectors::bsample::{export_grid, Grid};
use uvt_host::vectors::check::check;
use uvt_host::vectors::format::sha256;

fn committed() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../vectors")
}

fn seed() -> u64 {
    std::env::var("UVT_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(7)
}

fn extensive() -> bool {
    std::env::var("UVT_EXTENSIVE").is_ok_and(|v| v == "1")
}

/// Compile the testbench for configuration `g` into `dir`.
fn build(dir: &Path, g: Grid) -> PathBuf {
    let tb = dir.join(format!("tb-{}.vvp", g.name()));
    let rtl = committed().join("rtl");
    let out = Command::new("iverilog")
        .args(["-g2005", "-Wall"])
        .arg(format!("-Ptb_bsample.POS={}", g.pos))
        .arg(format!("-Ptb_bsample.TUV={}", g.tuv))
        .arg(format!("-Ptb_bsample.OFF={}", g.off))
        .arg("-o")
        .arg(&tb)
        .arg(rtl.join("uvt_bsample.v"))
        .arg(rtl.join("tb_bsample.v"))
        .output()
        .expect("iverilog (Debian package iverilog; tests/run.sh installs it)");
    assert!(
        out.status.success() && out.stderr.is_empty(),
        "iverilog failed or warned for {}: {}",
        g.name(),
        String::from_utf8_lossy(&out.stderr)
    );
    tb
}

/// Run the compiled testbench on the bsample files of `set`.
fn run(tb: &Path, set: &Path) -> String {
    let n = std::fs::read_to_string(set.join("bsample_out.hex"))
        .unwrap()
        .lines()
        .count();
    let out = Command::new("vvp")
        .arg("-n")
        .arg(tb)
        .arg(format!("+IN={}", set.join("bsample_in.hex").display()))
        .arg(format!("+OUT={}", set.join("bsample_out.hex").display()))
        .arg(format!("+N={n}"))
        .output()
        .expect("vvp (Debian package iverilog)");
    assert!(
        out.status.success(),
        "vvp failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

fn coverage(set: &str) -> serde_json::Value {
    let m: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(committed().join(set).join("manifest.json")).unwrap(),
    )
    .unwrap();
    assert_eq!(m["bsample_config"]["name"], "bounded-16-16-16-20");
    m["bsample_coverage"].clone()
}

/// The committed unit set holds every edge case the brief names, each more than once.
#[test]
fn committed_bounded_records_cover_the_edge_cases() {
    let c = coverage("unit");
    for key in [
        "covered",
        "ties",
        "ties_covered",
        "rare_path",
        "rare_covered",
        "depth_far",
        "depth_near",
        "corners",
    ] {
        assert!(
            c[key].as_u64().unwrap() >= 5,
            "unit set: {key} = {}",
            c[key]
        );
    }
    for (k, n) in c["class"].as_array().unwrap().iter().enumerate() {
        assert!(
            n.as_u64().unwrap() >= 100,
            "unit set: class {k} has {n} records"
        );
    }
    let frames = coverage("frame_a")["records"].as_u64().unwrap()
        + coverage("frame_b")["records"].as_u64().unwrap();
    assert!(frames >= 1000, "{frames}");
}

fn copy_set(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap() {
        let p = e.unwrap().path();
        std::fs::copy(&p, to.join(p.file_name().unwrap())).unwrap();
    }
}

/// Replace word `word` of record `line` (0-based) of `file`; the manifest checksum is fixed
/// when `fix` (so the record reaches the bit comparison). Returns the old word.
fn set_word(set: &Path, file: &str, line: usize, word: usize, f: impl Fn(u32) -> u32) -> u32 {
    let path = set.join(file);
    let text = std::fs::read_to_string(&path).unwrap();
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    let mut words: Vec<String> = lines[line].split(' ').map(String::from).collect();
    let old = u32::from_str_radix(&words[word], 16).unwrap();
    words[word] = format!("{:08x}", f(old));
    lines[line] = words.join(" ");
    let new = lines.join("\n") + "\n";
    std::fs::write(&path, &new).unwrap();
    let m = set.join("manifest.json");
    let mt = std::fs::read_to_string(&m)
        .unwrap()
        .replace(&sha256(text.as_bytes()), &sha256(new.as_bytes()));
    std::fs::write(&m, mt).unwrap();
    old
}

/// The first record of `set`'s bsample_out.hex with coverage bit `covered`.
fn first_record(set: &Path, covered: bool) -> usize {
    std::fs::read_to_string(set.join("bsample_out.hex"))
        .unwrap()
        .lines()
        .position(|l| (u32::from_str_radix(&l[..8], 16).unwrap() & 1 == 1) == covered)
        .expect("such a record")
}

/// `uvt vectors check` names file, line and field of a changed bounded output, and refuses an
/// input record whose class does not match its triangle.
#[test]
fn checker_reports_a_changed_bounded_record_by_field() {
    let dir = tempfile::tempdir().unwrap();
    let set = dir.path().join("frame_b");
    copy_set(&committed().join("frame_b"), &set);
    let r = first_record(&set, true);
    set_word(&set, "bsample_out.hex", r, 9, |w| w ^ 4); // e0, low word
    let cfg = first_record(&set, false);
    set_word(&set, "bsample_in.hex", cfg, 31, |w| w ^ 1); // class
    let e = format!("{:#}", check(&set).unwrap_err());
    assert!(
        e.contains(&format!(
            "bsample_out.hex line {} field e0: expected 0x",
            r + 1
        )),
        "{e}"
    );
    assert!(
        e.contains(&format!("bsample_in.hex line {}: field class =", cfg + 1)),
        "{e}"
    );
}

/// The RTL unit reproduces every committed bounded record (bounded-16-16-16-20), and a flipped
/// bit in an expected depth and in an expected a' is reported with record, field and values.
#[test]
fn rtl_sample_test_unit_passes_every_committed_record() {
    let dir = tempfile::tempdir().unwrap();
    let tb = build(dir.path(), Grid::DEFAULT);
    for set in ["unit", "frame_a", "frame_b"] {
        let out = run(&tb, &committed().join(set));
        let n = coverage(set)["records"].as_u64().unwrap();
        assert!(out.contains(&format!("PASS {n} records")), "{set}: {out}");
    }
    let bad = dir.path().join("bad");
    copy_set(&committed().join("frame_a"), &bad);
    let hit = first_record(&bad, true);
    let depth = set_word(&bad, "bsample_out.hex", hit, 1, |w| w ^ (1 << 7));
    let miss = first_record(&bad, false);
    let a1 = set_word(&bad, "bsample_out.hex", miss, 4, |w| w ^ 1);
    let out = run(&tb, &bad);
    assert!(
        out.contains(&format!(
            "MISMATCH record {hit} (line {}) field depth: expected {:016x} observed {:016x}",
            hit + 1,
            depth ^ (1 << 7),
            depth
        )),
        "{out}"
    );
    assert!(
        out.contains(&format!(
            "MISMATCH record {miss} (line {}) field a1: expected {:016x} observed {:016x}",
            miss + 1,
            a1 ^ 1,
            a1
        )),
        "{out}"
    );
    assert!(out.contains("inputs (bsample_in words 0..36): "), "{out}");
    assert!(out.contains("FAIL 2 mismatching fields in"), "{out}");
}

/// The unit's parameters: records of other configurations of the sweep, generated now by the
/// core on the configuration's grids, pass the unit built with that configuration; a record of
/// another configuration is refused by name.
#[test]
fn rtl_sample_test_unit_matches_other_configurations() {
    let all = [
        (16, 16, 22),
        (16, 16, 24),
        (12, 12, 24),
        (12, 12, 26),
        (8, 8, 28),
        (16, 16, 32),
    ];
    let picked: Vec<_> = if extensive() {
        all.to_vec()
    } else {
        vec![(12, 12, 24), (8, 8, 28)]
    };
    let seed = seed();
    let dir = tempfile::tempdir().unwrap();
    for (pos, tuv, off) in picked {
        let g = Grid { off, pos, tuv };
        let set = dir.path().join(g.name());
        let cov = export_grid(&set, g, seed).unwrap();
        assert!(cov.covered >= 20 && cov.ties > 0, "{}: {cov:?}", g.name());
        let tb = build(dir.path(), g);
        let out = run(&tb, &set);
        assert!(
            out.contains(&format!("PASS {} records", cov.records)),
            "{} (UVT_SEED={seed}): {out}",
            g.name()
        );
        // The default set through this configuration's unit: refused, naming the configuration.
        if g != Grid::DEFAULT {
            let out = run(&tb, &committed().join("frame_b"));
            assert!(
                out.contains("MISMATCH record 0 (line 1): configuration off_shift 20 pos_frac 16 tuv_frac 16"),
                "{out}"
            );
        }
    }
}
