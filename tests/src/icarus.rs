//! The Icarus Verilog runner shared by the RTL tests (`tests/tests/external/bsample.rs`,
//! `tests/tests/external/vectors.rs`): compile a testbench with `iverilog -g2005 -Wall` (a warning is a
//! failure) and run it with `vvp` on a vector file pair. Both tools come from the Debian package
//! `iverilog`, which `tests/run.sh` installs.

use std::path::{Path, PathBuf};
use std::process::Command;

/// `vectors/rtl`, the committed Verilog.
pub fn rtl_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../vectors/rtl")
}

/// Compile `sources` (file names in `vectors/rtl`) with the parameter overrides `params`
/// (`("tb_bsample.OFF", "24")` → `-Ptb_bsample.OFF=24`) into `out`. Panics with iverilog's
/// output if it fails or warns.
pub fn compile(out: &Path, params: &[(&str, String)], sources: &[&str]) -> PathBuf {
    compile_with(out, &[], params, sources)
}

/// [`compile`] with macro definitions (`"UVT_ARCH_ONLY"`, `"UVT_DUT=my_unit"` → `-D…`); a source
/// given as an absolute path is taken as it is (a unit outside `vectors/rtl`).
pub fn compile_with(
    out: &Path,
    defines: &[&str],
    params: &[(&str, String)],
    sources: &[&str],
) -> PathBuf {
    let rtl = rtl_dir();
    let mut cmd = Command::new("iverilog");
    cmd.args(["-g2005", "-Wall"]);
    for d in defines {
        cmd.arg(format!("-D{d}"));
    }
    for (k, v) in params {
        cmd.arg(format!("-P{k}={v}"));
    }
    cmd.arg("-o").arg(out);
    for s in sources {
        cmd.arg(rtl.join(s));
    }
    let o = cmd
        .output()
        .expect("iverilog (Debian package iverilog; tests/run.sh installs it)");
    assert!(
        o.status.success() && o.stderr.is_empty() && o.stdout.is_empty(),
        "iverilog failed or warned for {sources:?} {params:?}: {}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    out.to_path_buf()
}

/// Run the compiled testbench `tb` with the plusargs `args` (`"+SEED=7"`); its standard output.
/// Panics with vvp's output if it exits non-zero (a bench's FAIL ends with `$fatal`).
pub fn run(tb: &Path, args: &[String]) -> String {
    let (ok, out) = vvp(tb, args);
    assert!(ok, "vvp {} {args:?} exited non-zero: {out}", tb.display());
    out
}

/// Run the compiled testbench `tb` that must fail: panics unless vvp exits non-zero (a bench's
/// FAIL ends with `$fatal`); its standard output.
pub fn run_failing(tb: &Path, args: &[String]) -> String {
    let (ok, out) = vvp(tb, args);
    assert!(
        !ok,
        "vvp {} {args:?} exited 0 on a failing run: {out}",
        tb.display()
    );
    out
}

/// vvp's exit status (success or not) and its standard output followed by its error output.
fn vvp(tb: &Path, args: &[String]) -> (bool, String) {
    let o = Command::new("vvp")
        .arg("-n")
        .arg(tb)
        .args(args)
        .output()
        .expect("vvp (Debian package iverilog; tests/run.sh installs it)");
    (
        o.status.success(),
        String::from_utf8_lossy(&o.stdout).into_owned() + &String::from_utf8_lossy(&o.stderr),
    )
}

/// `+IN`, `+OUT`, `+N` of the vector pair `{stem}_in.hex` / `{stem}_out.hex` of `set` (`+N` = the
/// output file's line count), then `extra`.
fn vector_args(set: &Path, stem: &str, extra: &[String]) -> Vec<String> {
    let out = set.join(format!("{stem}_out.hex"));
    let n = std::fs::read_to_string(&out)
        .unwrap_or_else(|e| panic!("{}: {e}", out.display()))
        .lines()
        .count();
    let mut args = vec![
        format!("+IN={}", set.join(format!("{stem}_in.hex")).display()),
        format!("+OUT={}", out.display()),
        format!("+N={n}"),
    ];
    args.extend_from_slice(extra);
    args
}

/// [`run`] the testbench `tb` on the vector pair `{stem}_in.hex` / `{stem}_out.hex` of `set`
/// (`+IN`, `+OUT`, `+N` = the output file's line count, then `extra`).
pub fn run_vectors(tb: &Path, set: &Path, stem: &str, extra: &[String]) -> String {
    run(tb, &vector_args(set, stem, extra))
}

/// [`run_failing`] on a vector pair as [`run_vectors`] runs it: vvp must exit non-zero.
pub fn run_vectors_failing(tb: &Path, set: &Path, stem: &str, extra: &[String]) -> String {
    run_failing(tb, &vector_args(set, stem, extra))
}

/// The build parameters of the unit `name` in `vectors/rtl/pnr.sh`'s unit table (the line
/// `    NAME) echo "top|sources|P=V …|…"`), in the order written: the one definition of each
/// placed-and-routed build, which the benches that run the same build read. Panics if the
/// table has no such unit.
pub fn pnr_params(name: &str) -> Vec<(String, u32)> {
    let script = rtl_dir().join("pnr.sh");
    let text = std::fs::read_to_string(&script).unwrap();
    let head = format!("    {name}) echo \"");
    let line = text
        .lines()
        .find(|l| l.starts_with(&head))
        .unwrap_or_else(|| panic!("{}: no unit {name}", script.display()));
    let fields: Vec<&str> = line[head.len()..].split('|').collect();
    fields
        .get(2)
        .unwrap_or_else(|| panic!("{}: unit {name}: {line}", script.display()))
        .split_whitespace()
        .map(|p| {
            let (k, v) = p.split_once('=').expect("P=V");
            (k.to_string(), v.parse().expect("a number"))
        })
        .collect()
}
