//! The bounded sample-test vectors (`bsample_{in,out}.hex`) and the RTL unit that consumes them
//! (`vectors/rtl/uvt_bsample.v`): the committed records cover the edge cases they claim, the
//! checker reports a changed or invalid record by field, and under Icarus Verilog the unit
//! reproduces every committed record bit for bit, reproduces freshly generated records of other
//! configurations (its POS / TUV / OFF parameters), and a flipped expected bit is caught; each
//! unit variant (its MOTION / DEFOCUS parameters) does the same on the classes it accepts.
//!
//! `UVT_SEED` seeds the other configurations' records (printed on failure); `UVT_EXTENSIVE=1`
//! runs every configuration of the precision sweep instead of two.

use std::path::{Path, PathBuf};

use uvt_host::vectors::bsample::{export_grid, Grid};
use uvt_host::vectors::check::check;
use uvt_host::vectors::format::sha256;
use uvt_tests::icarus;

fn committed() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../vectors")
}

use uvt_tests::{extensive, seed};

/// Compile the testbench for configuration `g` into `dir`, with the unit's multipliers tiled
/// for hard multipliers of `ports` (25 × 18: DSP48E1, the default; 18 × 18: ECP5).
fn build_with(dir: &Path, g: Grid, ports: (u32, u32)) -> PathBuf {
    build_unit(dir, g, ports, (true, true))
}

/// Compile the testbench of the unit variant with `terms` = (motion, defocus) (the RTL's
/// `MOTION`, `DEFOCUS`; (true, true) is the full unit) for configuration `g` into `dir`.
fn build_unit(dir: &Path, g: Grid, ports: (u32, u32), terms: (bool, bool)) -> PathBuf {
    let p = |k: &'static str, v: u32| (k, v.to_string());
    icarus::compile(
        &dir.join(format!(
            "tb-{}-{}x{}-{}{}.vvp",
            g.name(),
            ports.0,
            ports.1,
            u8::from(terms.0),
            u8::from(terms.1)
        )),
        &[
            p("tb_bsample.POS", g.pos),
            p("tb_bsample.TUV", g.tuv),
            p("tb_bsample.OFF", g.off),
            p("tb_bsample.DSP_A", ports.0),
            p("tb_bsample.DSP_B", ports.1),
            p("tb_bsample.MOTION", u32::from(terms.0)),
            p("tb_bsample.DEFOCUS", u32::from(terms.1)),
        ],
        &["uvt_mul.v", "uvt_bsample.v", "tb_bsample.v"],
    )
}

/// Compile the testbench for configuration `g` into `dir` (DSP48E1 tiling).
fn build(dir: &Path, g: Grid) -> PathBuf {
    build_with(dir, g, (25, 18))
}

/// Run the compiled testbench on the bsample files of `set`: vvp must exit 0.
fn run(tb: &Path, set: &Path) -> String {
    icarus::run_vectors(tb, set, "bsample", &[])
}

/// Run the compiled testbench on the bsample files of `set`, which must fail: vvp must exit
/// non-zero (the bench's FAIL ends with `$fatal`).
fn run_failing(tb: &Path, set: &Path) -> String {
    icarus::run_vectors_failing(tb, set, "bsample", &[])
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

/// The tie-key group (`host/src/vectors/bsample_directed.rs`) is in the committed unit set: per
/// edge index, ties (E'_k = 0) whose key compares the ends' b' (a' = 0 at both: a column), their
/// a' (b' = 0 at both: a row) and a vertex on the sample (a' = b' = 0), each both covered and
/// not, under both orientations; ties the rounding makes (a' = 0 at both ends of an edge whose
/// exact x differs); and vertex ties against an end whose b' is ±2^j for j = 2..13. The fill rule's key meets them all (docs/mutation.md).
#[test]
fn committed_bounded_records_hold_the_tie_keys() {
    let set = committed().join("unit");
    let read = |f: &str| -> Vec<Vec<u32>> {
        std::fs::read_to_string(set.join(f))
            .unwrap()
            .lines()
            .map(|l| {
                l.split_whitespace()
                    .map(|w| u32::from_str_radix(w, 16).unwrap())
                    .collect()
            })
            .collect()
    };
    let (ins, outs) = (read("bsample_in.hex"), read("bsample_out.hex"));
    let mut seen = std::collections::BTreeSet::new();
    let mut bits = std::collections::BTreeSet::new();
    let mut rounded = 0;
    for (i, o) in ins.iter().zip(&outs) {
        let e = |k: usize| (u64::from(o[8 + 2 * k]) << 32) | u64::from(o[9 + 2 * k]);
        let (a, b) = (
            |k: usize| o[2 + 2 * k] as i32,
            |k: usize| o[3 + 2 * k] as i32,
        );
        let (covered, sign) = (o[0] & 1, (o[0] >> 1) & 3);
        for k in 0..3 {
            if e(k) != 0 {
                continue;
            }
            let (p, q) = ((k + 1) % 3, (k + 2) % 3);
            let kind = if (a(p), b(p)) == (0, 0) || (a(q), b(q)) == (0, 0) {
                // the other end's b' a single bit (the bits kind)
                let other = if (a(p), b(p)) == (0, 0) { q } else { p };
                if b(other).unsigned_abs().is_power_of_two() {
                    bits.insert((b(other).unsigned_abs().trailing_zeros(), b(other) > 0));
                }
                "vertex"
            } else if a(p) == 0 && a(q) == 0 {
                // the ends' exact x/w differ (t0 frame: x at words 0, 5, 10, w at 3, 8, 13)
                let x = |v: usize, u: usize| {
                    i64::from(i[5 * v] as i32) * i64::from(i[5 * u + 3] as i32)
                        != i64::from(i[5 * u] as i32) * i64::from(i[5 * v + 3] as i32)
                };
                rounded += x(p, q) as u32;
                "column"
            } else if b(p) == 0 && b(q) == 0 {
                "row"
            } else {
                continue;
            };
            seen.insert((kind, k, covered, sign));
        }
    }
    for kind in ["column", "row", "vertex"] {
        for k in 0..3 {
            for covered in [0, 1] {
                for sign in [1, 3] {
                    assert!(
                        seen.contains(&(kind, k, covered, sign)),
                        "no {kind} tie on edge {k} with covered = {covered}, det sign {sign}"
                    );
                }
            }
        }
    }
    assert!(rounded >= 20, "ties the rounding makes: {rounded}");
    for j in 2..=13 {
        for sign in [false, true] {
            assert!(
                bits.contains(&(j, sign)),
                "no tie at a vertex on the sample against an end whose b' is {}2^{j}",
                if sign { "+" } else { "-" }
            );
        }
    }
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
    let out = run_failing(&tb, &bad);
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
            let out = run_failing(&tb, &committed().join("frame_b"));
            assert!(
                out.contains("MISMATCH record 0 (line 1): configuration off_shift 20 pos_frac 16 tuv_frac 16"),
                "{out}"
            );
        }
    }
}

/// `uvt_mul.v` (every product of the unit) is the exact signed product at every operand-width
/// pair of the bounded configurations' width tables — corner operands and `UVT_SEED`-seeded
/// random ones — and tiles each pair into the hard multipliers and LUT bits that the cost model
/// (`uvt_host::cost`) counts, for the DSP48E1 (25 × 18) and ECP5 (18 × 18) ports.
#[test]
fn rtl_multiplier_is_exact_and_tiles_as_the_cost_model_counts() {
    use uvt_core::config::registry;
    use uvt_core::widths::stages::table;
    use uvt_host::config::multipliers::{dsp48e1_tiling, ecp5_tiling, Tiling};
    let mut pairs: Vec<(u32, u32)> = Vec::new();
    for entry in registry::sweep().filter(|e| e.config.off().is_some() && !e.config.planar()) {
        for r in table(&entry.config).rows().filter(|r| r.stage == "sample") {
            for m in r.mul.iter().flatten() {
                if !pairs.contains(&(m.a, m.b)) {
                    pairs.push((m.a, m.b));
                }
            }
        }
    }
    // The unit's own widths where they differ from the table: gx·w with a 22-bit gx (any
    // 20-bit xs; the table's 21 bits hold the in-viewport range).
    pairs.push((22, 31));
    assert!(pairs.len() >= 15, "{pairs:?}");
    let seed = seed();
    let nr = if extensive() { 20_000 } else { 300 };
    let dir = tempfile::tempdir().unwrap();
    for &(a, b) in &pairs {
        for (ports, model) in [
            ((25, 18), dsp48e1_tiling(a, b)),
            ((18, 18), ecp5_tiling(a, b)),
        ] {
            let p = |k: &'static str, v: u32| (k, v.to_string());
            let tb = icarus::compile(
                &dir.path().join(format!("mul-{a}x{b}-{}.vvp", ports.0)),
                &[
                    p("tb_mul.AW", a),
                    p("tb_mul.BW", b),
                    p("tb_mul.PA", ports.0),
                    p("tb_mul.PB", ports.1),
                ],
                &["uvt_mul.v", "tb_mul.v"],
            );
            let out = icarus::run(&tb, &[format!("+SEED={seed}"), format!("+NR={nr}")]);
            let Tiling { hard, lut_bits } = model;
            let want = format!(
                "PASS {} products {a}x{b}: {hard} hard multipliers, {lut_bits} LUT bits",
                36 + nr
            );
            assert!(
                out.contains(&want),
                "{a} × {b} on {ports:?} ports (UVT_SEED={seed}): expected '{want}', got: {out}"
            );
        }
    }
}

/// The pipelined forms of `uvt_mul.v` (`REG` = 1, 2: registered terms, a LUT chunk's rows
/// summed four at a time, as the units' `PIPE = 1` builds use them) are the exact product with
/// the same tiling as the combinational form, at the LUT chunk limits the place-and-route units
/// use: 17 bits (up to 15 rows in 4 terms) on the ECP5 ports for the sample test's pairs, and
/// 8 bits for the bounds unit's 59 × 82 product (17 terms: the three-level group sum).
#[test]
fn rtl_pipelined_multiplier_is_exact_and_tiles_as_the_combinational_one() {
    let seed = seed();
    let nr = if extensive() { 20_000 } else { 300 };
    let dir = tempfile::tempdir().unwrap();
    let p = |k: &'static str, v: u32| (k, v.to_string());
    let pairs = [
        (18, 32),
        (18, 31),
        (13, 32),
        (22, 31),
        (31, 31),
        (62, 31),
        (25, 31),
    ];
    let runs = pairs.iter().map(|&(a, b)| (a, b, 17)).chain([(59, 82, 8)]);
    for (a, b, lw) in runs {
        let mut lines = Vec::new();
        for reg in 0..3 {
            let tb = icarus::compile(
                &dir.path().join(format!("mul-{a}x{b}-{lw}-{reg}.vvp")),
                &[
                    p("tb_mul.AW", a),
                    p("tb_mul.BW", b),
                    p("tb_mul.PA", 18),
                    p("tb_mul.PB", 18),
                    p("tb_mul.LW", lw),
                    p("tb_mul.REG", reg),
                ],
                &["uvt_mul.v", "tb_mul.v"],
            );
            let out = icarus::run(&tb, &[format!("+SEED={seed}"), format!("+NR={nr}")]);
            let pass = out
                .lines()
                .find(|l| l.starts_with("PASS "))
                .unwrap_or_else(|| {
                    panic!("{a} × {b}, LW = {lw}, REG = {reg} (UVT_SEED={seed}): {out}")
                });
            lines.push(pass.to_string());
        }
        assert!(
            lines.iter().all(|l| *l == lines[0]),
            "{a} × {b}, LW = {lw}: REG 0, 1, 2 tile differently: {lines:?}"
        );
        assert!(lines[0].contains("LUT bits (swap"), "{}", lines[0]);
        assert!(
            !lines[0].contains(", 0 LUT bits"),
            "{a} × {b}: no LUT chunk: {}",
            lines[0]
        );
    }
}

/// The unit with its multipliers tiled for the ECP5's 18 × 18 ports is bit-identical too (the
/// frame_b set; every set under `UVT_EXTENSIVE=1`).
#[test]
fn rtl_sample_test_unit_with_ecp5_tiling_passes_committed_records() {
    let dir = tempfile::tempdir().unwrap();
    let tb = build_with(dir.path(), Grid::DEFAULT, (18, 18));
    let sets: &[&str] = if extensive() {
        &["unit", "frame_a", "frame_b"]
    } else {
        &["frame_b"]
    };
    for set in sets {
        let out = run(&tb, &committed().join(set));
        let n = coverage(set)["records"].as_u64().unwrap();
        assert!(out.contains(&format!("PASS {n} records")), "{set}: {out}");
    }
}

/// The faster build (`PIPE = 1`: registers inside every product and in the wide adder stages,
/// as `vectors/rtl/pnr.sh` places and routes it) is bit-identical with the ECP5 tiling at the
/// LUT chunk limits pnr.sh builds, 8 and 17 bits (frame_b; every set under `UVT_EXTENSIVE=1`,
/// and the DSP48E1 tiling on frame_a), with the latencies the docs state, 23 and 63 clocks;
/// the default build's are 11 and 46, with 17-bit LUT chunks too (every 16th record of frame_b;
/// all of them under `UVT_EXTENSIVE=1`: the serial LUT rows make this build slow in Icarus).
#[test]
fn rtl_pipelined_unit_passes_committed_records_with_its_latency() {
    let dir = tempfile::tempdir().unwrap();
    let p = |k: &'static str, v: u32| (k, v.to_string());
    let unit = |ports: (u32, u32), lutw: u32, pipe: u32| {
        icarus::compile(
            &dir.path()
                .join(format!("tb-pipe{pipe}-{}x{}-{lutw}.vvp", ports.0, ports.1)),
            &[
                p("tb_bsample.DSP_A", ports.0),
                p("tb_bsample.DSP_B", ports.1),
                p("tb_bsample.LUTW", lutw),
                p("tb_bsample.PIPE", pipe),
            ],
            &["uvt_mul.v", "uvt_bsample.v", "tb_bsample.v"],
        )
    };
    let mut runs = vec![((18, 18), 8, "frame_b"), ((18, 18), 17, "frame_b")];
    if extensive() {
        runs.extend([
            ((18, 18), 8, "unit"),
            ((18, 18), 8, "frame_a"),
            ((18, 18), 17, "unit"),
            ((25, 18), 8, "frame_a"),
        ]);
    }
    // Every checked record passes, and the first result came `latency` clocks after its input.
    let passes = |out: &str, n: u64, latency: &str, what: &str| {
        assert!(out.contains(&format!("PASS {n} records")), "{what}: {out}");
        assert!(
            out.lines()
                .any(|l| l == format!("LATENCY {latency} clocks")),
            "{what}: {out}"
        );
    };
    for (ports, lutw, set) in runs {
        let out = run(&unit(ports, lutw, 1), &committed().join(set));
        let n = coverage(set)["records"].as_u64().unwrap();
        passes(
            &out,
            n,
            "edge 23 depth 63",
            &format!("{ports:?} LUTW {lutw} {set}"),
        );
    }
    // The default build's latency, on every 40th record of frame_b; with 17-bit LUT chunks
    // (pnr.sh's bsample-lut17) on every 16th.
    for (tb, stride) in [
        (build(dir.path(), Grid::DEFAULT), 40),
        (unit((18, 18), 17, 0), if extensive() { 1 } else { 16 }),
    ] {
        let out = icarus::run_vectors(
            &tb,
            &committed().join("frame_b"),
            "bsample",
            &[format!("+STRIDE={stride}")],
        );
        let n = coverage("frame_b")["records"].as_u64().unwrap();
        passes(
            &out,
            n.div_ceil(stride),
            "edge 11 depth 46",
            &format!("stride {stride}"),
        );
    }
}

/// Its latency: "edge E depth D" (the bench's LATENCY line).
const PIPE2_LATENCY: &str = "edge 41 depth 87";

/// The build that closes timing (`PIPE = 2`: every product `uvt_mul.v` `REG = 3`, at most one
/// wide carry chain between registers; the parameters of `pnr.sh bsample-pipe2`: ECP5 18 × 18
/// ports, its LUT chunk limit and Karatsuba) reproduces every committed record with its latency, in
/// behavioural form (`MAP = 0`) and with every hard piece an instantiated MULT18X18D (`MAP = 1`,
/// simulated with the primitive's model `vectors/rtl/ecp5/MULT18X18D.v`). The six runs (two
/// builds, three sets) go in parallel.
#[test]
fn rtl_pipe2_unit_passes_every_committed_record() {
    let dir = tempfile::tempdir().unwrap();
    // pnr.sh's unit bsample-pipe2 (its configuration, ports, LUT chunk limit, KARA, PIPE), at
    // MAP = 0 and 1.
    let build = icarus::pnr_params("bsample-pipe2");
    let names: Vec<String> = build
        .iter()
        .map(|(k, _)| format!("tb_bsample.{k}"))
        .collect();
    let tbs: Vec<(u32, PathBuf)> = [0, 1]
        .into_iter()
        .map(|map| {
            let mut srcs = vec!["uvt_mul.v", "uvt_bsample.v", "tb_bsample.v"];
            if map == 1 {
                srcs.extend(["uvt_mult18.v", "ecp5/MULT18X18D.v"]);
            }
            let tb = icarus::compile(
                &dir.path().join(format!("tb-pipe2-map{map}.vvp")),
                &names
                    .iter()
                    .zip(&build)
                    .map(|(n, (k, v))| (n.as_str(), if k == "MAP" { map } else { *v }.to_string()))
                    .collect::<Vec<_>>(),
                &srcs,
            );
            (map, tb)
        })
        .collect();
    std::thread::scope(|sc| {
        let runs: Vec<_> = tbs
            .iter()
            .flat_map(|(map, tb)| {
                ["unit", "frame_a", "frame_b"]
                    .map(|set| sc.spawn(move || (*map, set, run(tb, &committed().join(set)))))
            })
            .collect();
        for r in runs {
            let (map, set, out) = r.join().unwrap();
            let n = coverage(set)["records"].as_u64().unwrap();
            assert!(
                out.contains(&format!("PASS {n} records")),
                "MAP {map} {set}: {out}"
            );
            assert!(
                out.lines()
                    .any(|l| l == format!("LATENCY {PIPE2_LATENCY} clocks")),
                "MAP {map} {set}: {out}"
            );
        }
    });
}

/// Whether the unit with `terms` = (motion, defocus) accepts class index `class` (bit 0
/// motion, bit 1 defocus: static, motion, defocus, both).
fn accepts(terms: (bool, bool), class: usize) -> bool {
    (terms.0 || class & 1 == 0) && (terms.1 || class & 2 == 0)
}

/// The testbench's last line for a set whose records per class are `per_class`.
fn pass_line(terms: (bool, bool), per_class: &serde_json::Value) -> String {
    let (mut run, mut skip) = (0, 0);
    for (k, n) in per_class.as_array().unwrap().iter().enumerate() {
        let n = n.as_u64().unwrap();
        if accepts(terms, k) {
            run += n;
        } else {
            skip += n;
        }
    }
    match skip {
        0 => format!("PASS {run} records"),
        _ => format!("PASS {run} records, {skip} skipped (class not in the unit)"),
    }
}

/// The first record of `set` of class `class` with coverage bit `covered`.
fn first_of_class(set: &Path, class: u32, covered: bool) -> usize {
    let ins = std::fs::read_to_string(set.join("bsample_in.hex")).unwrap();
    let outs = std::fs::read_to_string(set.join("bsample_out.hex")).unwrap();
    ins.lines()
        .zip(outs.lines())
        .position(|(i, o)| {
            let cfg = u32::from_str_radix(i.split(' ').nth(31).unwrap(), 16).unwrap();
            let cov = u32::from_str_radix(&o[..8], 16).unwrap() & 1 == 1;
            cfg & 3 == class && cov == covered
        })
        .expect("such a record")
}

/// Each narrow unit variant (`uvt_bsample.v` with `MOTION`/`DEFOCUS` cleared) reproduces every
/// committed record of the classes it accepts, skips and counts the others (the totals per class
/// from the manifests), and reports a flipped expected bit in a record of its widest class while
/// a flipped bit in a record of a class it lacks is skipped, not compared.
#[test]
fn rtl_unit_variants_pass_the_committed_records_of_their_classes() {
    let dir = tempfile::tempdir().unwrap();
    // (name, terms, the class whose record is corrupted, a class the unit lacks)
    for (name, terms, widest, lacks) in [
        ("motion-only", (true, false), 1, 2),
        ("defocus-only", (false, true), 2, 1),
        ("static-only", (false, false), 0, 3),
    ] {
        let tb = build_unit(dir.path(), Grid::DEFAULT, (25, 18), terms);
        for set in ["unit", "frame_a", "frame_b"] {
            let out = run(&tb, &committed().join(set));
            let want = pass_line(terms, &coverage(set)["class"]);
            assert!(
                out.lines().any(|l| l == want),
                "{name} on {set}: expected '{want}', got: {out}"
            );
        }
        let bad = dir.path().join(format!("bad-{name}"));
        copy_set(&committed().join("unit"), &bad);
        let hit = first_of_class(&bad, widest, true);
        let other = first_of_class(&bad, lacks, true);
        // Only the records up to both corrupted ones (the testbench reads the files alone).
        for f in ["bsample_in.hex", "bsample_out.hex"] {
            let t = std::fs::read_to_string(bad.join(f)).unwrap();
            let keep: Vec<&str> = t.lines().take(hit.max(other) + 1).collect();
            std::fs::write(bad.join(f), keep.join("\n") + "\n").unwrap();
        }
        let depth = set_word(&bad, "bsample_out.hex", hit, 1, |w| w ^ (1 << 3));
        set_word(&bad, "bsample_out.hex", other, 1, |w| w ^ (1 << 3));
        let out = run_failing(&tb, &bad);
        assert!(
            out.contains(&format!(
                "MISMATCH record {hit} (line {}) field depth: expected {:016x} observed {:016x}",
                hit + 1,
                depth ^ (1 << 3),
                depth
            )),
            "{name}: {out}"
        );
        assert!(
            !out.contains(&format!("MISMATCH record {other} ")),
            "{name}: {out}"
        );
        assert!(
            out.contains("FAIL 1 mismatching fields in"),
            "{name}: {out}"
        );
    }
}

/// Wiring your own unit: the bench built with `-DUVT_DUT=replay3_bsample -DUVT_ARCH_ONLY` takes
/// a unit with the architectural ports only (covered and depth out) and 3 clocks of latency
/// (`tests/rtl/replay3_bsample.v`, which replays the expected outputs) and passes every record
/// of a set; a flipped depth bit of that unit is reported by record and field; and the committed
/// unit passes in architectural mode too (its internal edge ports left unconnected).
#[test]
fn the_bench_takes_your_own_unit_in_architectural_mode() {
    let dir = tempfile::tempdir().unwrap();
    let replay = uvt_tests::ffi::root().join("tests/rtl/replay3_bsample.v");
    let tb = uvt_tests::icarus::compile_with(
        &dir.path().join("tb-replay.vvp"),
        &["UVT_DUT=replay3_bsample", "UVT_ARCH_ONLY"],
        &[],
        &[replay.to_str().unwrap(), "tb_bsample.v"],
    );
    let set = committed().join("unit");
    let n = coverage("unit")["records"].as_u64().unwrap();
    let out = run(&tb, &set);
    assert!(
        out.contains(&format!("PASS {n} records (architectural: covered, depth)")),
        "{out}"
    );
    let hit = first_record(&set, true);
    let bad = uvt_tests::icarus::run_vectors_failing(
        &tb,
        &set,
        "bsample",
        &[format!("+REPLAY_FLIP={hit}")],
    );
    assert!(
        bad.contains(&format!(
            "MISMATCH record {hit} (line {}) field depth",
            hit + 1
        )) && bad.contains("FAIL 1 mismatching fields"),
        "{bad}"
    );
    let arch = uvt_tests::icarus::compile_with(
        &dir.path().join("tb-arch.vvp"),
        &["UVT_ARCH_ONLY"],
        &[],
        &["uvt_mul.v", "uvt_bsample.v", "tb_bsample.v"],
    );
    let out = run(&arch, &committed().join("frame_a"));
    let n = coverage("frame_a")["records"].as_u64().unwrap();
    assert!(
        out.contains(&format!("PASS {n} records (architectural: covered, depth)")),
        "{out}"
    );
}

/// docs/rtl.md's command for checking one's own unit, run as it stands there (from the
/// repository root, on `tests/rtl/replay3_bsample.v`), passes with exit status 0; the same
/// command with `tests/rtl/wrap_bsample.v` — a wrapper that instantiates the committed unit,
/// which needs `uvt_mul.v` too — in its place passes as well (on frame_a, for time).
#[test]
fn the_documented_own_unit_command_passes() {
    let root = uvt_tests::ffi::root();
    let doc = std::fs::read_to_string(root.join("docs/rtl.md")).unwrap();
    let block = doc
        .split("```sh\n")
        .skip(1)
        .map(|b| b.split("```").next().unwrap())
        .find(|b| b.contains("-DUVT_DUT=replay3_bsample"))
        .expect("docs/rtl.md: the own-unit command (with -DUVT_DUT=replay3_bsample)");
    let dir = tempfile::tempdir().unwrap();
    let wrapped = block
        .replace("replay3_bsample", "wrap_bsample")
        .replace("vectors/unit/", "vectors/frame_a/");
    for (script, n) in [
        (
            block.to_string(),
            coverage("unit")["records"].as_u64().unwrap(),
        ),
        (wrapped, coverage("frame_a")["records"].as_u64().unwrap()),
    ] {
        let o = std::process::Command::new("bash")
            .arg("-ec")
            .arg(&script)
            .current_dir(&root)
            .env("TMPDIR", dir.path())
            .output()
            .expect("bash");
        let out =
            String::from_utf8_lossy(&o.stdout).into_owned() + &String::from_utf8_lossy(&o.stderr);
        assert!(
            o.status.success()
                && out.contains(&format!("PASS {n} records (architectural: covered, depth)")),
            "{script}\n{:?}: {out}",
            o.status
        );
    }
}
