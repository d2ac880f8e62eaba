//! The mutation sample (docs/mutation.md): mutants 1..50 of the mutation list of each reference
//! unit's default build (`uvt_bsample.v`, `uvt_psample.v`, `uvt_bounds.v`, `uvt_mul.v`; Yosys
//! `mutate`, all behind one select input, one Verilator build per unit) judged again by the
//! committed vector sets and compared, mutant by mutant, with the committed results
//! (`host/report/mutation/<build>.jsonl`): a change that weakens the vectors (a mutant a set
//! killed now lives, or dies later) or RTL changed without a new report fails, naming the
//! mutant. And the comparison can fail: with the `unit/` set taken away, the sample differs.
//! Runs `python -m uvt.mutation check` in the Python module's venv (see `cocotb.rs`); needs
//! yosys and verilator (tests/run.sh installs both).

use std::path::Path;
use std::process::Command;

use uvt_tests::ffi;

fn check(repo: &Path, work: &Path, extra: &[&str]) -> (bool, String) {
    let report = ffi::root().join("host/report/mutation.json");
    let o = Command::new(super::cocotb::venv_python())
        .current_dir(ffi::root())
        .args(["-m", "uvt.mutation", "check", "--repo"])
        .arg(repo)
        .arg("--work")
        .arg(work)
        .arg("--json")
        .arg(&report)
        .args(extra)
        .output()
        .expect("python -m uvt.mutation");
    (
        o.status.success(),
        String::from_utf8_lossy(&o.stdout).into_owned() + &String::from_utf8_lossy(&o.stderr),
    )
}

#[test]
fn committed_vectors_kill_the_sampled_mutants_as_the_report_says() {
    let work = tempfile::tempdir().unwrap();
    let (ok, out) = check(&ffi::root(), work.path(), &[]);
    assert!(ok && out.contains("PASS: 0 differences"), "{out}");
}

#[test]
fn a_weakened_vector_set_fails_the_sample() {
    // A checkout whose psample records are frame_a's alone: the mutants unit/ killed are now
    // killed later or not at all.
    let repo = tempfile::tempdir().unwrap();
    let root = ffi::root();
    let rtl = repo.path().join("vectors/rtl");
    std::fs::create_dir_all(&rtl).unwrap();
    for e in std::fs::read_dir(root.join("vectors/rtl"))
        .unwrap()
        .flatten()
    {
        if e.path().is_file() {
            std::fs::copy(e.path(), rtl.join(e.file_name())).unwrap();
        }
    }
    let fa = repo.path().join("vectors/frame_a");
    std::fs::create_dir_all(&fa).unwrap();
    for f in ["psample_in.hex", "psample_out.hex"] {
        std::fs::copy(root.join("vectors/frame_a").join(f), fa.join(f)).unwrap();
    }
    let work = tempfile::tempdir().unwrap();
    let (ok, out) = check(
        repo.path(),
        work.path(),
        &["--builds", "psample", "--sample", "12"],
    );
    assert!(
        !ok && out.contains("committed {'killed_by': 'unit'") && out.contains("FAIL"),
        "{out}"
    );
}
