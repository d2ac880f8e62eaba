//! The cocotb testbenches of the two sample-test units (`vectors/cocotb`): `uvt_bsample.v` and
//! `uvt_psample.v` under Icarus Verilog, checked sample by sample against the model, the `uvt`
//! Python module (`py/`). The committed RTL passes with non-zero coverage counts; a corrupted
//! expected output (`UVT_CORRUPT`) and a mutated copy of the RTL (the fill-rule tie-break
//! reversed; the planar fill rule of clockwise triangles reversed) fail, naming the field. The
//! pyuvm scoreboard example (`test_bsample_uvm.py`, architectural ports only) likewise.
//!
//! The Python environment: `target/py-venv` when it exists (the venv of the Python module's
//! step in `tests/run.sh`, holding `uvt`), with `vectors/cocotb/requirements.txt` (exact
//! versions: cocotb, pyuvm) installed into it on the first run. Otherwise `target/cocotb-venv`,
//! made here: the module's requirements (py/requirements.txt, when present),
//! `vectors/cocotb/requirements.txt`, then `pip install ./py` (a release build of the module:
//! minutes), redone when the requirements or the sources the module is built from (`py/`,
//! `core/`, `records/`, `host/`, `ffi/`, `Cargo.lock`) change. pip needs PyPI on the first
//! run. Builds and results go to temporary folders.
//! `UVT_SEED` seeds the stimulus (printed on failure); `UVT_EXTENSIVE=1` runs 10× the samples.

use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

use uvt_tests::{extensive, ffi, seed};

fn cocotb_dir() -> PathBuf {
    ffi::root().join("vectors/cocotb")
}

/// Run `python -m pip install -q ARGS` in the workspace root; panics with pip's output.
fn pip(python: &Path, venv: &Path, args: &[&str]) {
    let o = Command::new(python)
        .current_dir(ffi::root())
        .args(["-m", "pip", "install", "-q", "--disable-pip-version-check"])
        .args(args)
        .output()
        .expect("pip");
    assert!(
        o.status.success(),
        "pip install {} into {} failed (the cocotb tests need PyPI on their first run, and \
         `pip install ./py` needs the Rust toolchain and maturin). pip said:\n{}{}",
        args.join(" "),
        venv.display(),
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
}

/// A hash of the files the Python module is built from (paths and contents; `target` folders
/// and Python caches left out), so that a changed module is reinstalled.
fn module_sources_hash() -> String {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let Ok(rd) = std::fs::read_dir(dir) else {
            return;
        };
        for e in rd.flatten() {
            let p = e.path();
            let name = e.file_name();
            let name = name.to_string_lossy();
            if name == "target" || name == "__pycache__" || name.starts_with('.') {
                continue;
            }
            if p.is_dir() {
                walk(&p, out);
            } else {
                out.push(p);
            }
        }
    }
    let root = ffi::root();
    let mut files = Vec::new();
    for d in ["py", "core", "records", "host", "ffi"] {
        walk(&root.join(d), &mut files);
    }
    files.push(root.join("Cargo.lock"));
    files.push(root.join("Cargo.toml"));
    files.sort();
    let mut h = DefaultHasher::new();
    for f in &files {
        f.strip_prefix(&root).unwrap_or(f).hash(&mut h);
        std::fs::read(f).unwrap_or_default().hash(&mut h);
    }
    format!("{:016x}", h.finish())
}

/// The Python to run the benches with (see the module's comment), after installing what is
/// missing or out of date.
pub(super) fn venv_python() -> PathBuf {
    static PY: OnceLock<PathBuf> = OnceLock::new();
    PY.get_or_init(|| {
        let target = std::env::var("CARGO_TARGET_DIR")
            .map(PathBuf::from)
            .unwrap_or_else(|_| ffi::root().join("target"));
        let reqs = cocotb_dir().join("requirements.txt");
        let want = std::fs::read_to_string(&reqs).expect("vectors/cocotb/requirements.txt");
        let reqs_arg = reqs.to_string_lossy().into_owned();

        // The Python module's venv (tests/run.sh): it holds uvt; add the cocotb packages.
        let py_venv = target.join("py-venv");
        let python = py_venv.join("bin/python");
        if python.is_file() {
            let stamp = py_venv.join("uvt-cocotb-requirements.txt");
            if std::fs::read_to_string(&stamp).ok().as_deref() != Some(&want) {
                pip(&python, &py_venv, &["-r", &reqs_arg]);
                std::fs::write(&stamp, &want).expect("venv stamp");
            }
            return python;
        }

        // Our own venv with the module built from ./py.
        let venv = target.join("cocotb-venv");
        let python = venv.join("bin/python");
        let stamp = venv.join("uvt-requirements.txt");
        let want = format!("{want}\n# uvt module sources: {}\n", module_sources_hash());
        if python.is_file() && std::fs::read_to_string(&stamp).ok().as_deref() == Some(&want) {
            return python;
        }
        let _ = std::fs::remove_dir_all(&venv);
        let o = Command::new("python3")
            .arg("-m")
            .arg("venv")
            .arg(&venv)
            .output()
            .expect("python3 (CPython 3 with the venv module; Debian: python3-venv)");
        assert!(
            o.status.success(),
            "python3 -m venv {} failed (Debian: apt-get install python3-venv): {}{}",
            venv.display(),
            String::from_utf8_lossy(&o.stdout),
            String::from_utf8_lossy(&o.stderr)
        );
        let py_reqs = ffi::root().join("py/requirements.txt");
        if py_reqs.is_file() {
            pip(&python, &venv, &["-r", &py_reqs.to_string_lossy()]);
        }
        pip(&python, &venv, &["-r", &reqs_arg]);
        pip(&python, &venv, &["./py"]);
        std::fs::write(&stamp, &want).expect("venv stamp");
        python
    })
    .clone()
}

/// Run the cocotb test on the RTL of `rtl` (None: the committed `vectors/rtl`) with `n` samples
/// and the extra variables `vars`; (passed, whole output). Build products go to a temporary
/// folder.
fn run(rtl: Option<&Path>, n: u32, vars: &[(&str, String)]) -> (bool, String) {
    run_unit("bsample", rtl, n, vars)
}

/// [`run`] for `unit` (`bsample`: `test_bsample.py` on `uvt_bsample.v`; `psample`:
/// `test_psample.py` on `uvt_psample.v`; `bsample_uvm`: the pyuvm example `test_bsample_uvm.py`
/// on `uvt_bsample.v`).
fn run_unit(unit: &str, rtl: Option<&Path>, n: u32, vars: &[(&str, String)]) -> (bool, String) {
    let python = venv_python();
    let build = tempfile::tempdir().unwrap();
    let mut cmd = Command::new(python);
    cmd.arg(cocotb_dir().join("run.py"))
        .args(["--unit", unit])
        .arg("--build-dir")
        .arg(build.path())
        .env("UVT_SEED", seed().to_string())
        .env("UVT_COCOTB_N", n.to_string())
        .env_remove("UVT_CORRUPT")
        .env_remove("UVT_ARCH_ONLY")
        .env_remove("WAVES");
    if let Some(r) = rtl {
        cmd.arg("--rtl").arg(r);
    }
    for (k, v) in vars {
        cmd.env(k, v);
    }
    let o = cmd.output().expect("run.py");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    (o.status.success() && text.contains("PASS=1 FAIL=0"), text)
}

/// The counts of the "UVT_COCOTB_COVERAGE key=value …" line.
fn coverage(out: &str) -> Vec<(String, u64)> {
    let line = out
        .lines()
        .find_map(|l| l.split_once("UVT_COCOTB_COVERAGE ").map(|(_, r)| r))
        .unwrap_or_else(|| panic!("no UVT_COCOTB_COVERAGE line in:\n{out}"));
    line.split_whitespace()
        .filter_map(|kv| kv.split_once('='))
        .map(|(k, v)| (k.to_string(), v.parse().expect("count")))
        .collect()
}

#[test]
fn committed_rtl_matches_the_model() {
    let n = if extensive() { 4000 } else { 400 };
    let (ok, out) = run(None, n, &[]);
    assert!(ok, "cocotb test failed (UVT_SEED={}):\n{out}", seed());
    let cov = coverage(&out);
    let get = |k: &str| cov.iter().find(|(n, _)| n == k).map_or(0, |(_, v)| *v);
    assert_eq!(get("samples"), u64::from(n), "{out}");
    for k in [
        "covered",
        "ties",
        "rare_path",
        "randomised",
        "bubbles",
        "class0",
        "class1",
        "class2",
        "class3",
    ] {
        assert!(
            get(k) > 0,
            "coverage count {k} is 0 (UVT_SEED={}): {cov:?}",
            seed()
        );
    }
}

#[test]
fn corrupted_model_output_is_caught() {
    // Flip a bit of sample 25's expected depth; arch-only mode still compares depth.
    let (ok, out) = run(
        None,
        40,
        &[("UVT_CORRUPT", "25".into()), ("UVT_ARCH_ONLY", "1".into())],
    );
    assert!(!ok, "a corrupted expected output passed:\n{out}");
    assert!(
        out.contains(&format!("MISMATCH seed {} sample 25", seed())) && out.contains("field depth"),
        "the failure does not name sample 25's depth:\n{out}"
    );
}

#[test]
fn mutated_rtl_is_caught() {
    let dir = tempfile::tempdir().unwrap();
    let rtl = ffi::root().join("vectors/rtl");
    std::fs::copy(rtl.join("uvt_mul.v"), dir.path().join("uvt_mul.v")).unwrap();
    let src = std::fs::read_to_string(rtl.join("uvt_bsample.v")).unwrap();
    // The fill-rule tie key of an edge with E' = 0: reverse its comparison of b'.
    let (from, to) = (
        "assign key_n[3+i] = (bi > bj) ||",
        "assign key_n[3+i] = (bi < bj) ||",
    );
    assert_eq!(
        src.matches(from).count(),
        1,
        "uvt_bsample.v changed: the mutation `{from}` no longer matches once"
    );
    std::fs::write(dir.path().join("uvt_bsample.v"), src.replace(from, to)).unwrap();
    let (ok, out) = run(Some(dir.path()), 200, &[]);
    assert!(!ok, "the mutated RTL passed (UVT_SEED={}):\n{out}", seed());
    assert!(
        out.contains("MISMATCH seed") && out.contains("field covered"),
        "the failure does not name the covered field:\n{out}"
    );
}

/// The planar unit (`test_psample.py` on `uvt_psample.v`): the committed RTL matches the model on
/// 600 samples (6000 with `UVT_EXTENSIVE=1`) with non-zero counts of what they exercise; a
/// corrupted expected depth and a mutated unit (the fill rule of clockwise triangles reversed)
/// fail, naming the field.
#[test]
fn planar_unit_matches_and_its_mutant_and_a_corrupted_output_are_caught() {
    let n = if extensive() { 6000 } else { 600 };
    let (ok, out) = run_unit("psample", None, n, &[]);
    assert!(
        ok,
        "cocotb psample test failed (UVT_SEED={}):\n{out}",
        seed()
    );
    let cov = coverage(&out);
    let get = |k: &str| cov.iter().find(|(n, _)| n == k).map_or(0, |(_, v)| *v);
    assert_eq!(get("samples"), u64::from(n), "{out}");
    for k in ["covered", "ties", "clockwise", "randomised", "bubbles"] {
        assert!(
            get(k) > 0,
            "coverage count {k} is 0 (UVT_SEED={}): {cov:?}",
            seed()
        );
    }
    let (ok, out) = run_unit("psample", None, 40, &[("UVT_CORRUPT", "25".into())]);
    assert!(
        !ok && out.contains("sample 25") && out.contains("field depth"),
        "{out}"
    );
    let dir = tempfile::tempdir().unwrap();
    let rtl = ffi::root().join("vectors/rtl");
    std::fs::copy(rtl.join("uvt_mul.v"), dir.path().join("uvt_mul.v")).unwrap();
    let src = std::fs::read_to_string(rtl.join("uvt_psample.v")).unwrap();
    let (from, to) = (
        "wire fill = s4_neg ? (ak < 0 ||",
        "wire fill = s4_neg ? (ak > 0 ||",
    );
    assert_eq!(
        src.matches(from).count(),
        1,
        "uvt_psample.v changed: `{from}` no longer matches once"
    );
    std::fs::write(dir.path().join("uvt_psample.v"), src.replace(from, to)).unwrap();
    let (ok, out) = run_unit("psample", Some(dir.path()), 300, &[]);
    assert!(
        !ok && out.contains("MISMATCH seed") && out.contains("field covered"),
        "{out}"
    );
}

/// Architectural mode touches only the architectural ports (docs/rtl.md, "Wiring your own
/// unit"): a unit with no edge ports — `tests/rtl/wrap_bsample.v` around the committed unit,
/// named `uvt_bsample` as `run.py --rtl` takes it — passes with `UVT_ARCH_ONLY=1`.
#[test]
fn arch_only_mode_needs_only_the_architectural_ports() {
    let dir = tempfile::tempdir().unwrap();
    let rtl = ffi::root().join("vectors/rtl");
    std::fs::copy(rtl.join("uvt_mul.v"), dir.path().join("uvt_mul.v")).unwrap();
    let unit = std::fs::read_to_string(rtl.join("uvt_bsample.v"))
        .unwrap()
        .replace("module uvt_bsample", "module uvt_bsample_ref");
    let wrapper = std::fs::read_to_string(ffi::root().join("tests/rtl/wrap_bsample.v"))
        .unwrap()
        .replace("module wrap_bsample", "module uvt_bsample")
        .replace("    uvt_bsample unit (", "    uvt_bsample_ref unit (");
    assert!(wrapper.contains("uvt_bsample_ref unit ("), "{wrapper}");
    std::fs::write(dir.path().join("uvt_bsample.v"), unit + "\n" + &wrapper).unwrap();
    let (ok, out) = run(Some(dir.path()), 100, &[("UVT_ARCH_ONLY", "1".into())]);
    assert!(ok, "UVT_SEED={}:\n{out}", seed());
}

/// The pyuvm scoreboard example (`test_bsample_uvm.py` on `uvt_bsample.v`, architectural ports
/// only): the committed unit passes 300 samples (3000 with `UVT_EXTENSIVE=1`) with every class,
/// covered samples and ties counted and every sample's result in; a corrupted expected depth and
/// the mutated unit (the fill-rule tie key reversed) fail in the scoreboard, naming the sample
/// and the field.
#[test]
fn pyuvm_scoreboard_passes_and_catches_a_mutant_and_a_corrupted_output() {
    let n = if extensive() { 3000 } else { 300 };
    let (ok, out) = run_unit("bsample_uvm", None, n, &[]);
    assert!(ok, "pyuvm test failed (UVT_SEED={}):\n{out}", seed());
    assert!(out.contains(&format!("PASS {n} samples")), "{out}");
    let cov = coverage(&out);
    let get = |k: &str| cov.iter().find(|(n, _)| n == k).map_or(0, |(_, v)| *v);
    assert_eq!(get("samples"), u64::from(n), "{out}");
    assert_eq!(get("results"), u64::from(n), "{out}");
    for k in [
        "covered",
        "ties",
        "rare_path",
        "bubbles",
        "class0",
        "class1",
        "class2",
        "class3",
    ] {
        assert!(
            get(k) > 0,
            "coverage count {k} is 0 (UVT_SEED={}): {cov:?}",
            seed()
        );
    }

    let (ok, out) = run_unit("bsample_uvm", None, 40, &[("UVT_CORRUPT", "25".into())]);
    assert!(!ok, "a corrupted expected output passed:\n{out}");
    assert!(
        out.contains(&format!("MISMATCH seed {} sample 25", seed())) && out.contains("field depth"),
        "the failure does not name sample 25's depth:\n{out}"
    );

    let dir = tempfile::tempdir().unwrap();
    let rtl = ffi::root().join("vectors/rtl");
    std::fs::copy(rtl.join("uvt_mul.v"), dir.path().join("uvt_mul.v")).unwrap();
    let src = std::fs::read_to_string(rtl.join("uvt_bsample.v")).unwrap();
    let (from, to) = (
        "assign key_n[3+i] = (bi > bj) ||",
        "assign key_n[3+i] = (bi < bj) ||",
    );
    assert_eq!(
        src.matches(from).count(),
        1,
        "uvt_bsample.v changed: `{from}`"
    );
    std::fs::write(dir.path().join("uvt_bsample.v"), src.replace(from, to)).unwrap();
    let (ok, out) = run_unit("bsample_uvm", Some(dir.path()), 200, &[]);
    assert!(!ok, "the mutated unit passed (UVT_SEED={}):\n{out}", seed());
    assert!(
        out.contains("MISMATCH seed") && out.contains("field covered"),
        "the failure does not name the covered field:\n{out}"
    );
}
