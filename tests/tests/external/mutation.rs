//! The mutation sample (docs/mutation.md): mutants 1..50 of the mutation list of each reference
//! unit's default build (`uvt_bsample.v`, `uvt_psample.v`, `uvt_bounds.v`, `uvt_mul.v`; Yosys
//! `mutate`, all behind one select input, one Verilator build per unit) judged again by the
//! committed vector sets and compared, mutant by mutant, with the committed results
//! (`host/report/mutation/<build>.jsonl`): a change that weakens the vectors (a mutant a set
//! killed now lives, or dies later) or RTL changed without a new report fails, naming the
//! mutant. And the comparison can fail: with the `unit/` set taken away, the sample differs.
//! Both provers (`python -m uvt.mutation prove --engine abc|sat`) prove two mutants of the
//! multiplier the committed report has proven equivalent and find inputs that tell two killed
//! ones apart.
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

#[test]
fn both_provers_prove_equivalent_mutants_and_refute_killed_ones() {
    for engine in ["abc", "sat"] {
        prove_four(engine);
    }
}

fn prove_four(engine: &str) {
    // A report of four mul31 mutants, each a survivor: 3 and 15 proven equivalent in the
    // committed report, 1 and 2 killed by the bench's pairs there.
    let dir = tempfile::tempdir().unwrap();
    let per = dir.path().join("mutation");
    std::fs::create_dir_all(&per).unwrap();
    let root = ffi::root();
    let text = std::fs::read_to_string(root.join("host/report/mutation/mul31.jsonl")).unwrap();
    let mut rows = Vec::new();
    for line in text.lines() {
        let mut r: serde_json::Value = serde_json::from_str(line).unwrap();
        let id = r["id"].as_u64().unwrap();
        let want = match id {
            3 | 15 => "proven",
            1 | 2 => "differs",
            _ => continue,
        };
        assert_eq!(
            (r["killed_by"].is_null(), r["equivalent"].as_str()),
            (want == "proven", (want == "proven").then_some("proven")),
            "committed mul31 mutant {id}"
        );
        let o = r.as_object_mut().unwrap();
        for k in [
            "equivalent",
            "killed_by",
            "record",
            "field",
            "records_to_kill",
        ] {
            o.remove(k);
        }
        o.insert("killed_by".into(), serde_json::Value::Null);
        rows.push(serde_json::to_string(&r).unwrap() + "\n");
    }
    std::fs::write(per.join("mul31.jsonl"), rows.concat()).unwrap();
    let o = Command::new(super::cocotb::venv_python())
        .current_dir(&root)
        .args(["-m", "uvt.mutation", "prove", "--engine", engine])
        .args(["--builds", "mul31", "--json"])
        .arg(dir.path().join("mutation.json"))
        .arg("--work")
        .arg(dir.path().join("work"))
        .output()
        .expect("python -m uvt.mutation prove");
    let out = String::from_utf8_lossy(&o.stdout).into_owned() + &String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{out}");
    let got = std::fs::read_to_string(per.join("mul31.jsonl")).unwrap();
    let mut verdicts: Vec<(u64, String)> = got
        .lines()
        .map(|l| {
            let r: serde_json::Value = serde_json::from_str(l).unwrap();
            (
                r["id"].as_u64().unwrap(),
                r["equivalent"].as_str().unwrap_or("none").to_string(),
            )
        })
        .collect();
    verdicts.sort();
    let want: Vec<(u64, String)> = [
        (1, "differs"),
        (2, "differs"),
        (3, "proven"),
        (15, "proven"),
    ]
    .iter()
    .map(|&(i, v)| (i, v.to_string()))
    .collect();
    assert_eq!(verdicts, want, "--engine {engine}: {out}");
}
