//! The per-tile bounds RTL unit (`vectors/rtl/uvt_bounds.v`, `Laine2011::tile` at BND = TUV =
//! 16) under Icarus Verilog with its bench `tb_bounds.v`: it reproduces every committed
//! `bounds_out.hex` record of the unit, frame_a and frame_b sets from their `bounds_in.hex` and
//! `setup_out.hex` records; a flipped bit of an expected output is reported with record, field,
//! expected and observed; mutants of the unit (the lens solve's ceiling bit, the divider's
//! remainder bit, the bounding line's tile end) fail. The bench's setup_out offsets are taken from
//! each set's manifest, so the test follows the record format. The `PIPE = 1` and `PIPE = 2`
//! builds (the latter at `MAP = 0` and on MULT18X18D primitives, `MAP = 1`) give the same records. `UVT_EXTENSIVE=1` adds the ECP5
//! tiling (18 × 18) and unknowns on the data ports during bubbles on every set, `unit_exact/`
//! included (290 s on the loaded 2-core machine; the default run 65 s).

use std::path::{Path, PathBuf};

use uvt_tests::{extensive, icarus};

const SOURCES: [&str; 3] = ["uvt_mul.v", "uvt_bounds.v", "tb_bounds.v"];

fn committed() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../vectors")
}

fn manifest(set: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(set.join("manifest.json")).unwrap()).unwrap()
}

/// The bench's format parameters of a set: words per setup_out record and the first words of
/// the lens and dual coefficient blocks, from the manifest's layout.
fn format_params(set: &Path) -> Vec<(&'static str, String)> {
    let m = manifest(set);
    let f = &m["files"]["setup_out.hex"];
    let word = |name: &str| {
        f["fields"]
            .as_array()
            .unwrap()
            .iter()
            .find(|x| x["name"] == name)
            .unwrap_or_else(|| panic!("setup_out.hex has no field {name}"))["word"]
            .as_u64()
            .unwrap()
            .to_string()
    };
    vec![
        (
            "tb_bounds.SW",
            f["words_per_record"].as_u64().unwrap().to_string(),
        ),
        ("tb_bounds.LENS_AT", word("lens_x_lo_base")),
        ("tb_bounds.DUAL_AT", word("dual_x_xi_a")),
    ]
}

fn records(set: &Path) -> usize {
    manifest(set)["files"]["bounds_out.hex"]["records"]
        .as_u64()
        .unwrap() as usize
}

/// Compile the bench with the unit at `unit` (a file name in `vectors/rtl` or an absolute path).
fn build(dir: &Path, name: &str, unit: &str) -> PathBuf {
    let srcs = [SOURCES[0], unit, SOURCES[2]];
    icarus::compile(
        &dir.join(format!("{name}.vvp")),
        &format_params(&committed().join("unit")),
        &srcs,
    )
}

/// Run the bench on `set`: vvp must exit 0.
fn run(tb: &Path, set: &Path, extra: &[&str]) -> String {
    icarus::run(tb, &args(set, extra))
}

/// Run the bench on `set`, which must fail: vvp must exit non-zero.
fn run_failing(tb: &Path, set: &Path) -> String {
    icarus::run_failing(tb, &args(set, &[]))
}

fn args(set: &Path, extra: &[&str]) -> Vec<String> {
    let mut args = vec![format!("+SET={}", set.display())];
    args.extend(extra.iter().map(|s| s.to_string()));
    args
}

fn lines(path: &Path) -> Vec<String> {
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .map(str::to_string)
        .collect()
}

/// A set in `to` of the records `keep` of `from` (setup_out.hex whole).
fn subset(from: &Path, to: &Path, keep: &[usize]) {
    std::fs::create_dir_all(to).unwrap();
    std::fs::copy(from.join("setup_out.hex"), to.join("setup_out.hex")).unwrap();
    for f in ["bounds_in.hex", "bounds_out.hex"] {
        let l = lines(&from.join(f));
        let text: String = keep.iter().map(|&r| l[r].clone() + "\n").collect();
        std::fs::write(to.join(f), text).unwrap();
    }
}

#[test]
fn rtl_bounds_unit_passes_every_committed_record() {
    let dir = tempfile::tempdir().unwrap();
    let tb = build(dir.path(), "tb", "uvt_bounds.v");
    for set in ["unit", "frame_a", "frame_b"] {
        let path = committed().join(set);
        assert_eq!(
            format_params(&path),
            format_params(&committed().join("unit")),
            "{set}: another setup_out format than the unit set's"
        );
        let out = run(&tb, &path, &[]);
        let n = records(&path);
        assert!(
            out.lines()
                .any(|l| l.starts_with(&format!("PASS {n} records ("))),
            "{set}: {out}"
        );
    }
}

/// The `PIPE = 1` build (stage 26 split, latency 27, the faster clock of docs/rtl.md "Placed and
/// routed speed") with the ECP5 tiling passes every record of frame_a with unknowns on the data
/// ports during bubbles (`UVT_EXTENSIVE=1`: of the unit set too).
#[test]
fn rtl_bounds_unit_pipe1_passes_the_committed_records() {
    let dir = tempfile::tempdir().unwrap();
    let mut params = format_params(&committed().join("unit"));
    params.extend([
        ("tb_bounds.DSP_A", "18".to_string()),
        ("tb_bounds.PIPE", "1".to_string()),
    ]);
    let tb = icarus::compile(&dir.path().join("tb-pipe1.vvp"), &params, &SOURCES);
    let sets: &[&str] = if extensive() {
        &["frame_a", "unit"]
    } else {
        &["frame_a"]
    };
    for set in sets {
        let path = committed().join(set);
        let n = records(&path);
        let out = run(&tb, &path, &["+JUNK=1", "+BUBBLES=50"]);
        assert!(
            out.lines()
                .any(|l| l.starts_with(&format!("PASS {n} records ("))),
            "PIPE = 1, {set}: {out}"
        );
    }
}

/// The `PIPE = 2` build (every product `REG = 3` inside `uvt_mul.v`, every wide carry chain in
/// a clock of its own, latency 34) with the ECP5 tiling, behavioural (`MAP = 0`) or on
/// instantiated MULT18X18D primitives (`MAP = 1`, with their model `ecp5/MULT18X18D.v`), on the
/// sets `sets` with bubbles, and on frame_a with unknowns on the data ports during bubbles too
/// when `junk`.
fn pipe2_passes(map: u32, sets: &[&str], junk: bool) {
    let dir = tempfile::tempdir().unwrap();
    let mut params = format_params(&committed().join("unit"));
    params.extend([
        ("tb_bounds.DSP_A", "18".to_string()),
        ("tb_bounds.PIPE", "2".to_string()),
        ("tb_bounds.MAP", map.to_string()),
    ]);
    let srcs: &[&str] = if map == 1 {
        &[
            "uvt_mul.v",
            "uvt_mult18.v",
            "ecp5/MULT18X18D.v",
            "uvt_bounds.v",
            "tb_bounds.v",
        ]
    } else {
        &SOURCES
    };
    let tb = icarus::compile(
        &dir.path().join(format!("tb-pipe2-map{map}.vvp")),
        &params,
        srcs,
    );
    let mut runs: Vec<(&str, &[&str])> = sets.iter().map(|s| (*s, &["+BUBBLES=10"][..])).collect();
    if junk {
        runs.push(("frame_a", &["+JUNK=1", "+BUBBLES=50", "+SEED=5"]));
    }
    for (set, extra) in runs {
        let path = committed().join(set);
        let n = records(&path);
        let out = run(&tb, &path, extra);
        assert!(
            out.lines()
                .any(|l| l.starts_with(&format!("PASS {n} records ("))),
            "PIPE = 2, MAP = {map}, {set} {extra:?}: {out}"
        );
    }
}

/// `PIPE = 2`, `MAP = 0` passes every record of the unit, frame_a and frame_b sets (`unit_exact/`
/// too and unknowns on the data ports with `UVT_EXTENSIVE=1`).
#[test]
fn rtl_bounds_unit_pipe2_passes_every_committed_record() {
    if extensive() {
        pipe2_passes(0, &["unit", "unit_exact", "frame_a", "frame_b"], true);
    } else {
        pipe2_passes(0, &["unit", "frame_a", "frame_b"], false);
    }
}

/// `PIPE = 2`, `MAP = 1` (pnr.sh's `bounds-pipe2`) passes every record of frame_a (a slower
/// simulation: the 96 primitives' models; `UVT_EXTENSIVE=1`: every set, and unknowns on the
/// data ports).
#[test]
fn rtl_bounds_unit_pipe2_on_mult18x18d_passes_the_committed_records() {
    if extensive() {
        pipe2_passes(1, &["unit", "unit_exact", "frame_a", "frame_b"], true);
    } else {
        pipe2_passes(1, &["frame_a"], false);
    }
}

/// `UVT_EXTENSIVE=1`: the unit with the ECP5 tiling passes every set (`unit_exact/` too: the
/// exact configuration's tiles, the same per-tile arithmetic), and every set passes with unknowns
/// on the data ports during half the clocks (`+JUNK=1 +BUBBLES=50`).
#[test]
fn rtl_bounds_unit_extensive() {
    if !extensive() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let tb = build(dir.path(), "tb", "uvt_bounds.v");
    let mut params = format_params(&committed().join("unit"));
    params.extend([("tb_bounds.DSP_A", "18".to_string())]);
    let ecp5 = icarus::compile(&dir.path().join("tb-ecp5.vvp"), &params, &SOURCES);
    for set in ["unit", "unit_exact", "frame_a", "frame_b"] {
        let path = committed().join(set);
        let n = records(&path);
        for (tb, extra) in [
            (&ecp5, &[][..]),
            (&tb, &["+JUNK=1", "+BUBBLES=50", "+SEED=3"][..]),
        ] {
            let out = run(tb, &path, extra);
            assert!(
                out.lines()
                    .any(|l| l.starts_with(&format!("PASS {n} records ("))),
                "{set} {extra:?}: {out}"
            );
        }
    }
}

/// Unknowns on every data port during the bubbles (`+JUNK=1`) change no result, the bench takes
/// the unit by macro, and a flipped
/// bit of an expected field is reported by record, field, expected and observed (hex and
/// decimal) — the nonempty bit of one record, the low bit of t_lo of another.
#[test]
fn rtl_bounds_bench_reports_a_flipped_bit() {
    let dir = tempfile::tempdir().unwrap();
    let tb = build(dir.path(), "tb", "uvt_bounds.v");
    let from = committed().join("frame_a");
    let n = records(&from);
    let out = run(&tb, &from, &["+JUNK=1", "+SEED=7", "+BUBBLES=50"]);
    assert!(
        out.lines()
            .any(|l| l.starts_with(&format!("PASS {n} records ("))),
        "{out}"
    );
    // Your own unit by macro (`-DUVT_DUT=…`: no parameters passed), here the committed one.
    let own = icarus::compile_with(
        &dir.path().join("tb-own.vvp"),
        &["UVT_DUT=uvt_bounds"],
        &format_params(&from),
        &SOURCES,
    );
    let out = run(&own, &from, &[]);
    assert!(
        out.lines()
            .any(|l| l.starts_with(&format!("PASS {n} records ("))),
        "-DUVT_DUT=uvt_bounds: {out}"
    );
    let set = dir.path().join("flipped");
    subset(&from, &set, &(0..n).collect::<Vec<_>>());
    let path = set.join("bounds_out.hex");
    let mut recs: Vec<Vec<u32>> = lines(&path)
        .iter()
        .map(|l| {
            l.split(' ')
                .map(|w| u32::from_str_radix(w, 16).unwrap())
                .collect()
        })
        .collect();
    let nonempty: Vec<usize> = (0..n).filter(|&r| recs[r][0] == 1).collect();
    let (a, b) = (nonempty[3], nonempty[nonempty.len() - 2]);
    let (old_a, old_b) = (recs[a][0], recs[b][5]);
    recs[a][0] ^= 1;
    recs[b][5] ^= 1;
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
    std::fs::write(&path, text).unwrap();
    let out = run_failing(&tb, &set);
    let want = |r: usize, field: &str, exp: u32, obs: u32| {
        format!(
            "MISMATCH record {r} (line {}) field {field}: expected {exp:08x} ({}) observed {obs:08x} ({})",
            r + 1,
            exp as i32,
            obs as i32
        )
    };
    for w in [
        want(a, "nonempty", old_a ^ 1, old_a),
        want(b, "t_lo", old_b ^ 1, old_b),
    ] {
        assert!(out.contains(&w), "missing '{w}' in: {out}");
    }
    assert!(
        out.contains(&format!("FAIL 2 mismatching fields in {n} records")),
        "{out}"
    );
}

/// A copy of `uvt_bounds.v` in `dir` with `from` replaced by `to` (asserted to occur once).
fn mutant(dir: &Path, name: &str, from: &str, to: &str) -> PathBuf {
    let src = std::fs::read_to_string(icarus::rtl_dir().join("uvt_bounds.v")).unwrap();
    assert_eq!(
        src.matches(from).count(),
        1,
        "mutation `{from}` not found once in uvt_bounds.v"
    );
    let path = dir.join(format!("{name}.v"));
    std::fs::write(&path, src.replace(from, to)).unwrap();
    path
}

/// Mutants fail on a quarter of the unit set's records with lens or dual coefficients: the lens
/// solve without its ceiling bit (`mul_shr64`'s `up`), the time solve without the divider's
/// remainder bit (`frac_div`'s), and each bounding line evaluated at the other tile end.
#[test]
fn rtl_bounds_mutants_fail() {
    let dir = tempfile::tempdir().unwrap();
    let unit = committed().join("unit");
    let setups: Vec<u32> = lines(&unit.join("setup_out.hex"))
        .iter()
        .map(|l| u32::from_str_radix(l.split(' ').next().unwrap(), 16).unwrap())
        .collect();
    // flags: lens_x, lens_y (bits 9, 10), dual_x, dual_y (bits 11, 12)
    let keep: Vec<usize> = lines(&unit.join("bounds_in.hex"))
        .iter()
        .enumerate()
        .filter(|(_, l)| {
            let tri = u32::from_str_radix(l.split(' ').next().unwrap(), 16).unwrap();
            setups[tri as usize] >> 9 & 0xf != 0
        })
        .map(|(r, _)| r)
        .step_by(4)
        .collect();
    let set = dir.path().join("subset");
    subset(&unit, &set, &keep);
    let tb = build(dir.path(), "tb", "uvt_bounds.v");
    let out = run(&tb, &set, &[]);
    assert!(
        out.contains(&format!("PASS {} records (", keep.len())),
        "{out}"
    );
    // (mutant, replaced text, replacement, the fields one of whose mismatches must be reported)
    let mutants: [(&str, &str, &str, &[&str]); 3] = [
        (
            "no_lens_ceil",
            "(s4_up && s4_p[63:0] != 64'd0)",
            "1'b0",
            &["u_hi", "v_hi"],
        ),
        ("no_div_ceil", "q + (rem[LW*16 +: LW] != 0)", "q", &["t_hi"]),
        (
            "far_end",
            "wire pick_lo = (!s2_sl[DW]) == (k < 2);",
            "wire pick_lo = s2_sl[DW] == (k < 2);",
            &["t_lo", "t_hi"],
        ),
    ];
    for (name, from, to, fields) in mutants {
        let rtl = mutant(dir.path(), name, from, to);
        let tb = build(dir.path(), &format!("tb_{name}"), rtl.to_str().unwrap());
        let out = run_failing(&tb, &set);
        assert!(
            out.lines().any(|l| l.starts_with("MISMATCH record ")
                && fields
                    .iter()
                    .any(|f| l.contains(&format!("field {f}: expected"))))
                && out.contains("FAIL "),
            "mutant {name} ({from} → {to}) was not caught: {out}"
        );
    }
}
