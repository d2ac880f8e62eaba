//! The model as a DPI-C scoreboard and in a Verilator C++ harness (`vectors/dpi`): the C library
//! (`uvt_tests::ffi::lib()`) linked into Verilator testbenches of the two sample-test units.
//!
//! - `tb_dpi_bsample.sv` and `tb_dpi_psample.sv` run at the default seed (`UVT_SEED`) on
//!   [`samples`] samples — 10^6 per unit (about 10 s bounded, 5 s planar on the idle 2-core
//!   machine), 10^8 with `UVT_EXTENSIVE=1`: they PASS and exercised covered samples, fill-rule
//!   ties and (bounded) triangles with a vertex at w <= 0.
//! - A flipped bit of the model's expected output (`+CORRUPT=k`) fails, naming the field; with
//!   `+ARCH_ONLY=1` a corrupted edge value passes (only covered and depth are compared).
//! - The faster builds of each unit, `PIPE = 1` and `PIPE = 2` with `MAP = 1` (ECP5 MULT18X18D
//!   instances and their model), at 18 × 18 ports as `vectors/rtl/pnr.sh` builds them: the same
//!   [`samples`] give the default build's PASS line (every count) after a longer latency, which
//!   the bench measures and checks against the unit's `LAT`; a flipped bit fails.
//! - The example output of `vectors/dpi/README.md` (the bounded bench's PASS line, a MISMATCH
//!   and its FAIL line) is what the commands shown there print.
//! - A mutated copy of the RTL (the bounded unit's fill-rule tie key reversed, the planar unit's
//!   fill rule for clockwise triangles reversed) fails.
//! - `harness.cpp` (no DPI) passes on a short run and prints its rates, and fails on a corrupted
//!   expected depth and on the bounded unit with its tie key reversed.
//!
//! Verilator (Debian's 5.006) must be installed: `tests/run.sh` installs it. Every build goes
//! into a temporary folder.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use uvt_tests::{extensive, ffi, icarus, seed};

/// Samples of a full run of a unit's bench: 10^6; 10^8 in extensive mode.
fn samples(_unit: &str) -> u64 {
    if extensive() {
        100_000_000
    } else {
        1_000_000
    }
}

fn dpi_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../vectors/dpi")
}

/// Run `verilator` with `args` in `dir`; panics with its output if it fails.
fn verilate(dir: &Path, args: &[String]) {
    let t = Instant::now();
    let o = Command::new("verilator")
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap_or_else(|e| {
            panic!("verilator: {e} (Debian package verilator; tests/run.sh installs it)")
        });
    assert!(
        o.status.success(),
        "verilator {args:?} failed: {}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    eprintln!(
        "built {} in {:.1} s",
        dir.display(),
        t.elapsed().as_secs_f64()
    );
}

/// The flags every build shares: the RTL parsed as Verilog-2005 (it names a wire `inside`),
/// its lint waivers, the library and what Rust's std needs from the C library.
fn common(top: &str, mdir: &Path) -> Vec<String> {
    let lib = ffi::lib();
    vec![
        "-j".into(),
        "2".into(),
        "+1364-2005ext+v".into(),
        "--top-module".into(),
        top.into(),
        "--Mdir".into(),
        mdir.display().to_string(),
        dpi_dir().join("rtl.vlt").display().to_string(),
        lib.static_lib.display().to_string(),
        "-LDFLAGS".into(),
        "-lpthread -ldl -lm".into(),
    ]
}

/// A build of a unit: the unit's parameters, set on the bench's top (`-G`), which passes them on.
type Params = Vec<(String, u32)>;

/// The faster builds of `unit`, those `vectors/rtl/pnr.sh` places on the ECP5 (read from its
/// unit table): `PIPE = 1` (units psample-pipe1, bsample) and `PIPE = 2` with every hard piece
/// an instantiated MULT18X18D (`MAP = 1`; units psample-pipe2, bsample-pipe2). The bounded
/// units' configuration parameters (POS, TUV, OFF: the default configuration, as pnr.rs checks)
/// are the bench's own and are left out.
fn pipelined(unit: &str) -> [Params; 2] {
    let names = if unit == "bsample" {
        ["bsample", "bsample-pipe2"]
    } else {
        ["psample-pipe1", "psample-pipe2"]
    };
    names.map(|n| {
        icarus::pnr_params(n)
            .into_iter()
            .filter(|(k, _)| !["POS", "TUV", "OFF"].contains(&k.as_str()))
            .collect()
    })
}

/// `PIPE=2 MAP=1`, "default" for none.
fn name(params: &[(String, u32)]) -> String {
    if params.is_empty() {
        return "default".into();
    }
    params
        .iter()
        .map(|(k, v)| format!("{k}={v}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// Verilate and build the DPI testbench of `unit` ("bsample", "psample") with the unit's RTL
/// `rtl` and the build `params` into `dir` (a folder per build); the executable. `MAP = 1` adds
/// the MULT18X18D instance (`uvt_mult18.v`) and the primitive's model (`mult18x18d.sv`).
fn build_bench(dir: &Path, unit: &str, rtl: &Path, params: &[(String, u32)]) -> PathBuf {
    let tag: String = params.iter().map(|(k, v)| format!("_{k}{v}")).collect();
    let mdir = dir.join(format!("obj_{unit}{tag}"));
    let mut args: Vec<String> = ["--binary", "--timing", "-o", "tb"]
        .map(String::from)
        .to_vec();
    args.extend(common(&format!("tb_dpi_{unit}"), &mdir));
    args.extend(params.iter().map(|(k, v)| format!("-G{k}={v}")));
    for f in ["uvt_dpi.sv", &format!("tb_dpi_{unit}.sv")] {
        args.push(dpi_dir().join(f).display().to_string());
    }
    args.push(icarus::rtl_dir().join("uvt_mul.v").display().to_string());
    if params.iter().any(|(k, v)| k == "MAP" && *v == 1) {
        args.push(format!("-I{}", icarus::rtl_dir().join("ecp5").display()));
        args.push(icarus::rtl_dir().join("uvt_mult18.v").display().to_string());
        args.push(dpi_dir().join("mult18x18d.sv").display().to_string());
    }
    args.push(rtl.display().to_string());
    verilate(dir, &args);
    mdir.join("tb")
}

/// Run `exe` with `args`: whether it exited with success, and its standard output.
fn run(exe: &Path, args: &[String]) -> (bool, String) {
    let t = Instant::now();
    let o = Command::new(exe)
        .args(args)
        .output()
        .expect("run testbench");
    let out = String::from_utf8_lossy(&o.stdout).into_owned();
    eprintln!(
        "{} {args:?}: {:.1} s\n{}",
        exe.display(),
        t.elapsed().as_secs_f64(),
        out.lines()
            .filter(|l| !l.starts_with("- "))
            .collect::<Vec<_>>()
            .join("\n")
    );
    (o.status.success(), out)
}

fn bench(tb: &Path, extra: &[&str]) -> String {
    let mut args = vec![format!("+SEED={}", seed())];
    args.extend(extra.iter().map(|s| s.to_string()));
    run(tb, &args).1
}

/// The line of `out` that starts with `start` ("PASS ", "LATENCY ").
fn line<'a>(out: &'a str, start: &str) -> &'a str {
    out.lines()
        .find(|l| l.starts_with(start))
        .unwrap_or_else(|| panic!("no {start}line in:\n{out}"))
}

/// The depth latency of the LATENCY line ("LATENCY 6 clocks", "LATENCY edge 11 depth 46
/// clocks"): its last number.
fn latency(out: &str) -> u32 {
    let l = line(out, "LATENCY ");
    l.split(' ')
        .filter_map(|w| w.parse().ok())
        .next_back()
        .unwrap_or_else(|| panic!("no latency in `{l}`"))
}

/// The count before `what` on the PASS line ("PASS 10 samples, 3 covered, …").
fn count(out: &str, what: &str) -> u64 {
    let line = line(out, "PASS ");
    line.trim_start_matches("PASS ")
        .split(", ")
        .find_map(|p| p.strip_suffix(&format!(" {what}")))
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("no `<n> {what}` in `{line}`"))
}

fn assert_fail(out: &str, field: &str) {
    assert!(
        out.lines().any(|l| l.starts_with("FAIL seed")) && !out.contains("\nPASS"),
        "expected FAIL, got:\n{out}"
    );
    assert!(
        out.lines()
            .any(|l| l.starts_with("MISMATCH") && l.contains(&format!("field {field}"))),
        "the mismatch does not name field {field}:\n{out}"
    );
    assert!(
        out.contains("  input ") && out.contains("  expected ") && out.contains("  observed "),
        "no input/expected/observed words:\n{out}"
    );
}

/// A copy of `uvt_<unit>.v` in `dir` with `from` replaced by `to` (asserted to occur once).
fn mutant(dir: &Path, unit: &str, from: &str, to: &str) -> PathBuf {
    let src = std::fs::read_to_string(icarus::rtl_dir().join(format!("uvt_{unit}.v"))).unwrap();
    assert_eq!(
        src.matches(from).count(),
        1,
        "mutation `{from}` not found once in uvt_{unit}.v"
    );
    let path = dir.join(format!("uvt_{unit}.v"));
    std::fs::write(&path, src.replace(from, to)).unwrap();
    path
}

fn pass_and_corrupt(unit: &str, counts: &[&str]) {
    let dir = tempfile::tempdir().unwrap();
    let rtl = icarus::rtl_dir().join(format!("uvt_{unit}.v"));
    let tb = build_bench(dir.path(), unit, &rtl, &[]);
    let n = samples(unit);
    let out = bench(&tb, &[&format!("+N={n}")]);
    assert_eq!(count(&out, "samples"), n, "{out}");
    for what in counts {
        assert!(count(&out, what) > 0, "no {what} exercised: {out}");
    }
    // A corrupted expected output: depth (word 1) and an edge value (word 2 or 8: e0's high
    // word), the latter invisible to an architectural compare.
    let e0 = if unit == "bsample" { "8" } else { "2" };
    assert_fail(&bench(&tb, &["+N=3000", "+CORRUPT=1234"]), "depth");
    let corrupt_e = ["+N=3000", "+CORRUPT=1234", &format!("+CORRUPT_WORD={e0}")];
    assert_fail(&bench(&tb, &corrupt_e), "e0");
    let arch: Vec<&str> = corrupt_e.iter().copied().chain(["+ARCH_ONLY=1"]).collect();
    assert_eq!(count(&bench(&tb, &arch), "samples"), 3000);
    if unit == "bsample" {
        readme_examples(&tb);
    }
    // The faster builds: the same samples give the same PASS line (every count: the records are
    // the same), after a longer latency (the bench checks it against the unit's LAT); a
    // corrupted expected depth fails.
    for params in pipelined(unit) {
        let tb = build_bench(dir.path(), unit, &rtl, &params);
        let p = bench(&tb, &[&format!("+N={n}")]);
        let build = name(&params);
        assert_eq!(
            line(&p, "PASS "),
            line(&out, "PASS "),
            "{unit} {build}: not the default build's PASS line:\n{p}"
        );
        assert!(
            latency(&p) > latency(&out),
            "{unit} {build}: latency {} clocks, the default build's {}: the parameters did not \
             reach the unit",
            latency(&p),
            latency(&out)
        );
        assert_fail(&bench(&tb, &["+N=3000", "+CORRUPT=1234"]), "depth");
    }
}

/// vectors/dpi/README.md's example output of the bounded bench is what its commands print now:
/// the PASS line of `+SEED=1 +N=100000` and the MISMATCH and FAIL lines of `+SEED=1 +N=1000
/// +CORRUPT=500`, each a line of the README as it stands.
fn readme_examples(tb: &Path) {
    let path = dpi_dir().join("README.md");
    let readme = std::fs::read_to_string(&path).unwrap();
    let has = |line: &str| readme.lines().any(|r| r == line);
    for (args, starts) in [
        (&["+SEED=1", "+N=100000"][..], &["PASS "][..]),
        (
            &["+SEED=1", "+N=1000", "+CORRUPT=500"][..],
            &["MISMATCH ", "FAIL "][..],
        ),
    ] {
        let args: Vec<String> = args.iter().map(|a| a.to_string()).collect();
        let out = run(tb, &args).1;
        for start in starts {
            let line = out
                .lines()
                .find(|l| l.starts_with(start))
                .unwrap_or_else(|| panic!("no {start}line in the output of {args:?}:\n{out}"));
            assert!(
                has(line),
                "{}: its example output of `tb {}` is not what the bench prints now; the line is\n{line}",
                path.display(),
                args.join(" ")
            );
        }
    }
}

fn mutated(unit: &str, from: &str, to: &str, field: &str) {
    let dir = tempfile::tempdir().unwrap();
    let rtl = mutant(dir.path(), unit, from, to);
    let tb = build_bench(dir.path(), unit, &rtl, &[]);
    assert_fail(&bench(&tb, &[&format!("+N={}", samples(unit))]), field);
}

#[test]
fn bsample_dpi_passes_at_every_build_and_catches_a_corrupted_model_output() {
    pass_and_corrupt("bsample", &["covered", "ties", "w<=0"]);
}

#[test]
fn psample_dpi_passes_at_every_build_and_catches_a_corrupted_model_output() {
    pass_and_corrupt("psample", &["covered", "ties"]);
}

#[test]
fn bsample_dpi_catches_a_reversed_tie_key() {
    mutated(
        "bsample",
        "(~k_pos & ~k_neg & k_gt))",
        "(~k_pos & ~k_neg & k_lt))",
        "covered",
    );
}

#[test]
fn psample_dpi_catches_a_reversed_fill_rule() {
    mutated(
        "psample",
        "wire fill = s4_neg ? (ak < 0 ||",
        "wire fill = s4_neg ? (ak > 0 ||",
        "covered",
    );
}

/// Build `harness.cpp` with the bounded unit `rtl` into `dir`; the executable.
fn build_harness(dir: &Path, rtl: &Path) -> PathBuf {
    let mdir = dir.join("obj_harness");
    let lib = ffi::lib();
    let mut args: Vec<String> = ["--cc", "--exe", "--build", "-o", "harness", "-CFLAGS"]
        .map(String::from)
        .to_vec();
    args.push(format!("-I{}", lib.include.display()));
    args.extend(common("uvt_bsample", &mdir));
    args.push(icarus::rtl_dir().join("uvt_mul.v").display().to_string());
    args.push(rtl.display().to_string());
    args.push(dpi_dir().join("harness.cpp").display().to_string());
    verilate(dir, &args);
    mdir.join("harness")
}

/// The C++ harness passes on the committed unit and prints its rates; a corrupted expected
/// depth (its fifth argument) fails, naming the field and the words.
#[test]
fn cpp_harness_passes_and_catches_a_corrupted_model_output() {
    let dir = tempfile::tempdir().unwrap();
    let h = build_harness(dir.path(), &icarus::rtl_dir().join("uvt_bsample.v"));
    let (ok, out) = run(&h, &[seed(), 20_000, 2_000, 64].map(|n| n.to_string()));
    assert!(ok && out.contains("\nPASS 20000 samples, "), "{out}");
    for rate in ["model-typed", "model-record", "rtl-harness"] {
        assert!(
            out.contains(&format!("RATE {rate} ")),
            "no {rate} rate:\n{out}"
        );
    }
    let (ok, out) = run(&h, &[seed(), 3_000, 10, 4, 1234].map(|n| n.to_string()));
    assert!(!ok, "a corrupted expected depth passed:\n{out}");
    assert_fail(&out, "depth");
}

/// The C++ harness fails on the bounded unit with its fill-rule tie key reversed.
#[test]
fn cpp_harness_catches_a_reversed_tie_key() {
    let dir = tempfile::tempdir().unwrap();
    let rtl = mutant(
        dir.path(),
        "bsample",
        "(~k_pos & ~k_neg & k_gt))",
        "(~k_pos & ~k_neg & k_lt))",
    );
    let h = build_harness(dir.path(), &rtl);
    let (ok, out) = run(&h, &[seed(), 100_000, 10, 4].map(|n| n.to_string()));
    assert!(!ok, "the mutated unit passed:\n{out}");
    assert_fail(&out, "covered");
}
