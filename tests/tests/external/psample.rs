//! The planar sample-test vectors (`psample_{in,out}.hex`, configuration `planar-16-16-16-20`)
//! and the RTL unit that consumes them (`vectors/rtl/uvt_psample.v`): the committed records
//! cover the edge cases they claim, the checker reports a changed or invalid record by file,
//! line and field (setup fields included: it re-runs the core's planar setup), and under Icarus
//! Verilog the unit reproduces every committed record bit for bit (DSP48E1 tiling; `frame_a`
//! with the ECP5 tiling too) while a flipped bit in a record of each kind — an expected output
//! field, or an input field the unit reads — is caught and reported with record and field.

use std::path::{Path, PathBuf};

use uvt_host::vectors::check::check;
use uvt_host::vectors::format::sha256;
use uvt_tests::icarus;

fn committed() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../vectors")
}

fn manifest(set: &str) -> serde_json::Value {
    serde_json::from_str(
        &std::fs::read_to_string(committed().join(set).join("manifest.json")).unwrap(),
    )
    .unwrap()
}

/// Compile the testbench with the unit's multipliers tiled for hard multipliers of `ports`
/// (25 × 18: DSP48E1; 18 × 18: ECP5).
fn build(dir: &Path, ports: (u32, u32)) -> PathBuf {
    let p = |k: &'static str, v: u32| (k, v.to_string());
    icarus::compile(
        &dir.join(format!("tbp-{}x{}.vvp", ports.0, ports.1)),
        &[
            p("tb_psample.DSP_A", ports.0),
            p("tb_psample.DSP_B", ports.1),
        ],
        &["uvt_mul.v", "uvt_psample.v", "tb_psample.v"],
    )
}

/// Run the bench on the psample files of `set`: vvp must exit 0.
fn run(tb: &Path, set: &Path) -> String {
    icarus::run_vectors(tb, set, "psample", &[])
}

/// Run the bench on the psample files of `set`, which must fail: vvp must exit non-zero.
fn run_failing(tb: &Path, set: &Path) -> String {
    icarus::run_vectors_failing(tb, set, "psample", &[])
}

/// Run the bench `tb` on committed set `set`, assert it passes every planar record of the set
/// (`what` names the build in the message), and return its output.
fn passes_set(tb: &Path, set: &str, what: &str) -> String {
    let out = run(tb, &committed().join(set));
    let n = manifest(set)["psample_coverage"]["records"]
        .as_u64()
        .unwrap();
    assert!(
        out.lines().any(|l| l == format!("PASS {n} records")),
        "{what} {set}: {out}"
    );
    out
}

fn records(set: &Path, file: &str) -> Vec<Vec<u32>> {
    std::fs::read_to_string(set.join(file))
        .unwrap()
        .lines()
        .map(|l| {
            l.split(' ')
                .map(|w| u32::from_str_radix(w, 16).unwrap())
                .collect()
        })
        .collect()
}

fn write_records(path: &Path, recs: &[Vec<u32>]) {
    let text: String = recs
        .iter()
        .map(|r| {
            r.iter()
                .map(|w| format!("{w:08x}"))
                .collect::<Vec<_>>()
                .join(" ")
                + "\n"
        })
        .collect();
    std::fs::write(path, text).unwrap();
}

/// The committed unit set holds every edge case it claims, each several times; degenerate
/// triangles are offered and dropped; the frame set `frame_a` has records of its static
/// triangles.
#[test]
fn committed_planar_records_cover_the_edge_cases() {
    let m = manifest("unit");
    assert_eq!(m["psample_config"]["name"], "planar-16-16-16-20");
    let c = &m["psample_coverage"];
    for key in [
        "covered",
        "ties",
        "ties_covered",
        "ties_b",
        "crossing",
        "crossing_covered",
        "w_zero",
        "shift15",
        "guard_band",
        "f_negative",
        "f_ge_63",
        "depth_far",
        "depth_near",
        "corners",
        "vp_2048",
        "sigma_negative",
    ] {
        assert!(
            c[key].as_u64().unwrap() >= 5,
            "unit set: {key} = {}",
            c[key]
        );
    }
    // Found by search: the unclamped depth at both sides of both clamps.
    for key in [
        "depth_at_far",
        "depth_past_far",
        "depth_at_near",
        "depth_past_near",
    ] {
        assert!(
            c[key].as_u64().unwrap() >= 3,
            "unit set: {key} = {}",
            c[key]
        );
    }
    assert!(c["culled_degenerate"].as_u64().unwrap() >= 1, "{c}");
    assert!(c["records"].as_u64().unwrap() >= 3000, "{c}");
    let sliver = m["psample_cases"]
        .as_array()
        .unwrap()
        .iter()
        .find(|g| g["name"].as_str().unwrap().starts_with("slivers"))
        .unwrap();
    let [a, b] = [0, 1].map(|i| sliver["records"][i].as_u64().unwrap());
    assert!(
        sliver["triangles"].as_u64().unwrap() * 12 > b - a,
        "the sliver group's degenerate triangle has no record: {sliver}"
    );
    assert!(
        manifest("frame_a")["psample_coverage"]["records"]
            .as_u64()
            .unwrap()
            >= 300
    );
}

fn copy_set(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap() {
        let p = e.unwrap().path();
        std::fs::copy(&p, to.join(p.file_name().unwrap())).unwrap();
    }
}

/// Replace word `word` of record `line` of `file` in a copied set, fixing the manifest's
/// checksum so that the record reaches the bit comparison.
fn set_word(set: &Path, file: &str, line: usize, word: usize, f: impl Fn(u32) -> u32) {
    let path = set.join(file);
    let text = std::fs::read_to_string(&path).unwrap();
    let mut recs = records(set, file);
    recs[line][word] = f(recs[line][word]);
    write_records(&path, &recs);
    let new = std::fs::read_to_string(&path).unwrap();
    let m = set.join("manifest.json");
    let mt = std::fs::read_to_string(&m)
        .unwrap()
        .replace(&sha256(text.as_bytes()), &sha256(new.as_bytes()));
    std::fs::write(m, mt).unwrap();
}

/// `uvt vectors check` names file, line and field of a changed planar output and of a setup
/// field that is not the core's planar setup, and refuses by name a record of a triangle the
/// planar setup culls and a position outside the viewport.
#[test]
fn checker_reports_a_changed_planar_record_by_field() {
    let dir = tempfile::tempdir().unwrap();
    let set = dir.path().join("frame_a");
    copy_set(&committed().join("frame_a"), &set);
    set_word(&set, "psample_out.hex", 3, 3, |w| w ^ 4); // e0, low word
    set_word(&set, "psample_in.hex", 5, 17, |w| w ^ 1); // n1_b
    for k in [1, 5, 9] {
        set_word(&set, "psample_in.hex", 7, k, |_| 0); // every y = 0: det P' = 0
    }
    set_word(&set, "psample_in.hex", 9, 26, |_| 32 * 256); // xs = 256·W
    let e = format!("{:#}", check(&set).unwrap_err());
    for want in [
        "psample_out.hex line 4 field e0: expected 0x",
        "psample_in.hex line 6 field n1_b: expected 0x",
        "psample_in.hex line 8: the planar setup culls this triangle (det P' = 0",
        "psample_in.hex line 10: fields xs = 8192, ys = ",
    ] {
        assert!(e.contains(want), "missing '{want}' in: {e}");
    }
}

/// The RTL unit reproduces every committed planar record (DSP48E1 tiling), and `frame_a` with
/// the ECP5 tiling.
#[test]
fn rtl_planar_unit_passes_every_committed_record() {
    let dir = tempfile::tempdir().unwrap();
    let tb = build(dir.path(), (25, 18));
    for set in ["unit", "frame_a", "frame_b"] {
        passes_set(&tb, set, "DSP48E1 tiling");
    }
    let ecp5 = build(dir.path(), (18, 18));
    passes_set(&ecp5, "frame_a", "ECP5 tiling");
}

/// The faster build (`PIPE = 1`: registers inside the products, as `vectors/rtl/pnr.sh`
/// measures it) is bit-identical at both tilings on frame_a (and the unit set under
/// `UVT_EXTENSIVE=1`), with latency 9; the default build's is 6.
#[test]
fn rtl_pipelined_planar_unit_passes_committed_records_with_its_latency() {
    let dir = tempfile::tempdir().unwrap();
    let p = |k: &'static str, v: u32| (k, v.to_string());
    let sets: &[&str] = if uvt_tests::extensive() {
        &["frame_a", "unit"]
    } else {
        &["frame_a"]
    };
    for ports in [(25, 18), (18, 18)] {
        let tb = icarus::compile(
            &dir.path()
                .join(format!("tbp-pipe-{}x{}.vvp", ports.0, ports.1)),
            &[
                p("tb_psample.DSP_A", ports.0),
                p("tb_psample.DSP_B", ports.1),
                p("tb_psample.PIPE", 1),
            ],
            &["uvt_mul.v", "uvt_psample.v", "tb_psample.v"],
        );
        for set in sets {
            let out = passes_set(&tb, set, &format!("PIPE = 1, {ports:?}"));
            assert!(out.lines().any(|l| l == "LATENCY 9 clocks"), "{out}");
        }
    }
    let out = run(&build(dir.path(), (25, 18)), &committed().join("frame_a"));
    assert!(out.lines().any(|l| l == "LATENCY 6 clocks"), "{out}");
}

/// The fastest build (`PIPE = 2`: every hard multiplier registered in and out, `uvt_mul` REG = 3,
/// and one wide carry chain per clock) is bit-identical on every committed planar record: at
/// the DSP48E1 tiling, and at the ECP5 tiling with `LUTW = 0` (`vectors/rtl/pnr.sh`'s
/// `psample-pipe2`) both behavioural (`MAP = 0`) and with every hard piece an instantiated
/// `MULT18X18D` (`MAP = 1`: `uvt_mult18.v`, simulated with `vectors/rtl/ecp5/MULT18X18D.v`); latency 8 + L2 +
/// L3, the products' clocks (3 + clog2 of their terms).
#[test]
fn rtl_planar_unit_pipe2_passes_every_committed_record() {
    let dir = tempfile::tempdir().unwrap();
    let p = |k: &'static str, v: u32| (k, v.to_string());
    // (ports, LUTW, MAP, latency): 25 × 18 at LUTW 8 has a 21 × 13 product of one term (L2 =
    // 3) and 32 × 32 of two hard pieces and 8 LUT rows (L3 = 7); 18 × 18 at LUTW 0 two and four
    // hard pieces (L2 = 4, L3 = 5).
    for (ports, lutw, map, lat) in [
        ((25, 18), 8, 0, 18),
        ((18, 18), 0, 0, 17),
        ((18, 18), 0, 1, 17),
    ] {
        let mut src = vec!["uvt_mul.v", "uvt_psample.v", "tb_psample.v"];
        if map == 1 {
            src.extend(["uvt_mult18.v", "ecp5/MULT18X18D.v"]);
        }
        let tb = icarus::compile(
            &dir.path().join(format!(
                "tbp-pipe2-{}x{}-l{lutw}-m{map}.vvp",
                ports.0, ports.1
            )),
            &[
                p("tb_psample.DSP_A", ports.0),
                p("tb_psample.DSP_B", ports.1),
                p("tb_psample.LUTW", lutw),
                p("tb_psample.PIPE", 2),
                p("tb_psample.MAP", map),
            ],
            &src,
        );
        for set in ["unit", "frame_a", "frame_b"] {
            let what = format!("PIPE = 2, {ports:?}, LUTW = {lutw}, MAP = {map}");
            let out = passes_set(&tb, set, &what);
            if set != "frame_b" {
                assert!(
                    out.lines().any(|l| l == format!("LATENCY {lat} clocks")),
                    "{what} {set}: {out}"
                );
            }
        }
    }
}

/// A predicate on an (input, output) record pair.
/// The directed groups (`host/src/vectors/psample_directed.rs`) are in the committed unit set:
/// for every j = 0..29 and both signs, a tie (E_k = 0) on an edge whose a is ±2^j and one on an
/// edge with a = 0 and b = ±2^j, covered for each sign; for every t = 1..58 an edge value
/// E_k = +2^t and one −2^t; covered samples whose depth exponent is below −33, saturated at
/// both ends; depths clamped at both ends at every shift f + 33 = 20..62 (near: ..61); a
/// covered depth of exactly 0 at every shift 4..19 (the range test's mask on the accumulator's
/// low bits). A unit's one-bit-off zero and sign tests of E, a and b meet these (docs/mutation.md).
#[test]
fn committed_planar_records_hold_the_directed_cases() {
    let set = committed().join("unit");
    let ins = records(&set, "psample_in.hex");
    let outs = records(&set, "psample_out.hex");
    let mut tie_a = std::collections::BTreeSet::new();
    let mut tie_b = std::collections::BTreeSet::new();
    let mut e_bits = std::collections::BTreeSet::new();
    let mut saturated = std::collections::BTreeSet::new();
    let mut clamped = std::collections::BTreeSet::new();
    let mut zero = std::collections::BTreeSet::new();
    for (i, o) in ins.iter().zip(&outs) {
        let covered = o[0] & 1 == 1;
        for k in 0..3 {
            let (a, b) = (i[13 + 3 * k] as i32, i[14 + 3 * k] as i32);
            let e = e_of(o, k);
            if e == 0 && a != 0 && a.unsigned_abs().is_power_of_two() {
                tie_a.insert((a.unsigned_abs().trailing_zeros(), a > 0, covered));
            }
            if e == 0 && a == 0 && b.unsigned_abs().is_power_of_two() {
                tie_b.insert((b.unsigned_abs().trailing_zeros(), b > 0, covered));
            }
            if e != 0 && e.unsigned_abs().is_power_of_two() {
                e_bits.insert((e.unsigned_abs().trailing_zeros(), e > 0));
            }
        }
        let f = (((i[22] >> 2) & 0xff) as u8) as i8;
        if covered && f < -33 {
            saturated.insert(o[1]);
        }
        if covered && [0x7fff_fffe, 0x8000_0000].contains(&o[1]) {
            clamped.insert((i32::from(f) + 33, o[1]));
        }
        if covered && o[1] == 0 {
            zero.insert(i32::from(f) + 33);
        }
    }
    for j in 0..=29u32 {
        for sign in [false, true] {
            for (name, got) in [("a", &tie_a), ("b (a = 0)", &tie_b)] {
                assert!(
                    got.contains(&(j, sign, true)),
                    "no covered tie on an edge whose {name} is {}2^{j}",
                    if sign { "+" } else { "-" }
                );
            }
        }
    }
    for t in 1..=58u32 {
        for sign in [false, true] {
            assert!(
                e_bits.contains(&(t, sign)),
                "no record with an edge value E = {}2^{t}",
                if sign { "+" } else { "-" }
            );
        }
    }
    assert!(
        saturated.contains(&0x7fff_fffe) && saturated.contains(&0x8000_0000),
        "covered samples with f < -33 and their depths: {saturated:x?}"
    );
    for amt in 20..=62 {
        for d in [0x7fff_fffe, 0x8000_0000] {
            if d == 0x8000_0000 && amt == 62 {
                continue; // c = −2^8 needs the slope 2^σ ≥ 2^8: amt ≤ 61
            }
            assert!(
                clamped.contains(&(amt, d)),
                "no covered sample clamped to {d:#x} at the depth shift f + 33 = {amt}"
            );
        }
    }
    for amt in 4..=19 {
        assert!(
            zero.contains(&amt),
            "no covered sample of depth 0 at the depth shift f + 33 = {amt}: {zero:?}"
        );
    }
}

type Kind = Box<dyn Fn(&[u32], &[u32]) -> bool>;

fn e_of(out: &[u32], k: usize) -> i64 {
    ((u64::from(out[2 + 2 * k]) << 32) | u64::from(out[3 + 2 * k])) as i64
}

/// One committed record of each kind (its line in the unit set): covered, not covered, a tie
/// (E_k = 0) covered, a clockwise triangle covered, a camera-plane crosser covered, depth
/// saturated far and near, the depth plane's f < 0 and f ≥ 63, a 2048-pixel viewport.
fn kinds(set: &Path) -> Vec<(&'static str, usize)> {
    let ins = records(set, "psample_in.hex");
    let outs = records(set, "psample_out.hex");
    let f_of = |i: &[u32]| (((i[22] >> 2) & 0xff) as u8) as i8;
    let tests: Vec<(&'static str, Kind)> = vec![
        ("covered", Box::new(|_, o| o[0] & 1 == 1)),
        ("not covered", Box::new(|_, o| o[0] & 1 == 0)),
        (
            "tie covered",
            Box::new(|_, o| o[0] & 1 == 1 && (0..3).any(|k| e_of(o, k) == 0)),
        ),
        (
            "clockwise covered",
            Box::new(|i, o| o[0] & 1 == 1 && i[22] & 3 == 3),
        ),
        (
            "crosser covered",
            Box::new(|i, o| o[0] & 1 == 1 && [3, 7, 11].iter().any(|&k| i[k] as i32 <= 0)),
        ),
        (
            "depth far",
            Box::new(|_, o| o[0] & 1 == 1 && o[1] == 0x7fff_fffe),
        ),
        (
            "depth near",
            Box::new(|_, o| o[0] & 1 == 1 && o[1] == 0x8000_0000),
        ),
        (
            "f < 0 covered",
            Box::new(move |i, o| o[0] & 1 == 1 && f_of(i) < 0),
        ),
        (
            "f >= 63 covered",
            Box::new(move |i, o| o[0] & 1 == 1 && f_of(i) >= 63),
        ),
        (
            "2048 viewport covered",
            Box::new(|i, o| o[0] & 1 == 1 && i[12] & 0xffff == 2048),
        ),
    ];
    tests
        .iter()
        .map(|(name, t)| {
            let line = ins
                .iter()
                .zip(&outs)
                .position(|(i, o)| t(i, o))
                .unwrap_or_else(|| panic!("no committed record of kind {name}"));
            (*name, line)
        })
        .collect()
}

/// A flipped bit in a record of each kind is caught: per kind, one of the expected output
/// fields (covered, depth, e0, e1, e2 in turn) is flipped and reported with record, field,
/// expected (the flipped value) and observed (the committed one); then inputs the unit reads
/// (a normal's c, σ, a position bit) are flipped and the records' outputs no longer match.
#[test]
fn rtl_planar_unit_catches_a_flipped_bit_of_each_kind() {
    let dir = tempfile::tempdir().unwrap();
    let tb = build(dir.path(), (25, 18));
    let unit = committed().join("unit");
    let picked = kinds(&unit);
    let (ins, outs) = (
        records(&unit, "psample_in.hex"),
        records(&unit, "psample_out.hex"),
    );
    let sub = dir.path().join("sub");
    std::fs::create_dir_all(&sub).unwrap();
    let mut si: Vec<Vec<u32>> = picked.iter().map(|&(_, l)| ins[l].clone()).collect();
    let mut so: Vec<Vec<u32>> = picked.iter().map(|&(_, l)| outs[l].clone()).collect();
    write_records(&sub.join("psample_in.hex"), &si);
    write_records(&sub.join("psample_out.hex"), &so);
    let out = run(&tb, &sub);
    assert!(
        out.lines()
            .any(|l| l == format!("PASS {} records", picked.len())),
        "the picked records unchanged: {out}"
    );
    // Output fields: (name, word, bit) in turn over the kinds.
    let fields = [
        ("covered", 0usize, 0u32),
        ("depth", 1, 5),
        ("e0", 3, 9),
        ("e1", 4, 30),
        ("e2", 7, 0),
    ];
    let mut want = Vec::new();
    for (r, (kind, _)) in picked.iter().enumerate() {
        let (name, word, bit) = fields[r % fields.len()];
        let old = so[r].clone();
        so[r][word] ^= 1 << bit;
        let show = |o: &[u32]| match name {
            "covered" => format!("{:016x}", o[0] & 1),
            "depth" => format!("{:016x}", o[1]),
            _ => {
                let k = usize::from(name.as_bytes()[1] - b'0');
                format!("{:016x}", e_of(o, k))
            }
        };
        want.push((
            *kind,
            format!(
                "MISMATCH record {r} (line {}) field {name}: expected {} observed {}",
                r + 1,
                show(&so[r]),
                show(&old)
            ),
        ));
    }
    write_records(&sub.join("psample_out.hex"), &so);
    let out = run_failing(&tb, &sub);
    for (kind, w) in &want {
        assert!(out.contains(w), "{kind}: missing '{w}' in: {out}");
    }
    assert!(
        out.contains(&format!("FAIL {} mismatching fields in", picked.len())),
        "{out}"
    );
    // Input fields the unit reads, on the first three picked records (covered, not covered,
    // tie): n0_c bit 0 changes E_0 by 256·W·H ≠ 0; σ's flip makes a covered record with every
    // E ≠ 0 uncovered (the tie record's flip is checked through its E below); xs bit 8 moves
    // the sample by one pixel and changes E_k by 512·H·a_k for an edge with a_k ≠ 0.
    let so: Vec<Vec<u32>> = picked.iter().map(|&(_, l)| outs[l].clone()).collect();
    write_records(&sub.join("psample_out.hex"), &so);
    si[0][15] ^= 1; // n0_c
    si[1][26] ^= 1 << 8; // xs
    si[2][22] ^= 2; // σ: 01 ↔ 11
    write_records(&sub.join("psample_in.hex"), &si);
    let out = run_failing(&tb, &sub);
    assert!(
        out.contains("MISMATCH record 0 (line 1) field e0: "),
        "n0_c flip: {out}"
    );
    assert!(
        out.contains("MISMATCH record 1 (line 2) field e"),
        "xs flip: {out}"
    );
    assert!(
        out.contains("MISMATCH record 2 (line 3) field covered: expected 0000000000000001 observed 0000000000000000"),
        "σ flip: {out}"
    );
    assert!(!out.contains("MISMATCH record 3 "), "{out}");
}

/// The bench in architectural mode (`-DUVT_ARCH_ONLY`: only covered and depth connected and
/// checked) passes the committed unit on every record of the unit set, and still catches a
/// flipped depth bit.
#[test]
fn rtl_planar_unit_passes_in_architectural_mode() {
    let dir = tempfile::tempdir().unwrap();
    let tb = icarus::compile_with(
        &dir.path().join("tb-arch.vvp"),
        &["UVT_ARCH_ONLY"],
        &[],
        &["uvt_mul.v", "uvt_psample.v", "tb_psample.v"],
    );
    let n = manifest("unit")["psample_coverage"]["records"]
        .as_u64()
        .unwrap();
    let out = run(&tb, &committed().join("unit"));
    assert!(
        out.contains(&format!("PASS {n} records (architectural: covered, depth)")),
        "{out}"
    );
    let bad = dir.path().join("bad");
    std::fs::create_dir(&bad).unwrap();
    for f in ["psample_in.hex", "psample_out.hex"] {
        std::fs::copy(committed().join("unit").join(f), bad.join(f)).unwrap();
    }
    let text = std::fs::read_to_string(bad.join("psample_out.hex")).unwrap();
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let hit = lines
        .iter()
        .position(|l| l.starts_with("00000001 "))
        .expect("a covered record");
    let mut w: Vec<String> = lines[hit].split(' ').map(str::to_string).collect();
    w[1] = format!("{:08x}", u32::from_str_radix(&w[1], 16).unwrap() ^ 1);
    lines[hit] = w.join(" ");
    std::fs::write(bad.join("psample_out.hex"), lines.join("\n") + "\n").unwrap();
    let out = run_failing(&tb, &bad);
    assert!(
        out.contains(&format!(
            "MISMATCH record {hit} (line {}) field depth",
            hit + 1
        )),
        "{out}"
    );
}
