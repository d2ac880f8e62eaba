//! A closed pipe ends `uvt` quietly: with its standard error (and standard output) going to a
//! pipe whose reader has gone — `uvt render 2>&1 | head -1` — it neither panics (exit status 101,
//! "failed printing to stderr") nor stops early because of the lost progress lines.

use std::process::{Command, Stdio};

/// A small render of the built-in scene: progress lines on stderr, the report on stdout.
fn render_args(out: &std::path::Path) -> Vec<String> {
    ["render", "--viewport", "32x18", "--spp", "4", "--out"]
        .iter()
        .map(|s| s.to_string())
        .chain([out.to_string_lossy().into_owned()])
        .collect()
}

#[test]
fn a_closed_pipe_ends_uvt_quietly() {
    let dir = tempfile::tempdir().unwrap();
    // stdout and stderr into one pipe whose reader reads a line and exits.
    let o = Command::new("bash")
        .arg("-c")
        .arg(r#""$@" 2>&1 | head -1; exit "${PIPESTATUS[0]}""#)
        .arg("bash")
        .arg(env!("CARGO_BIN_EXE_uvt"))
        .args(render_args(&dir.path().join("a")))
        .output()
        .expect("bash");
    let (out, err) = (
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr),
    );
    assert!(
        o.status.code() != Some(101) && !err.contains("panicked") && !out.contains("panicked"),
        "uvt render 2>&1 | head -1: {:?}\n{out}{err}",
        o.status
    );
    assert!(out.starts_with("render: [1/4]"), "{out}");
    // Only stderr closed (its reader dropped before uvt writes): the render runs to the end,
    // writes its files and its report, and exits 0.
    let out_dir = dir.path().join("b");
    let mut child = Command::new(env!("CARGO_BIN_EXE_uvt"))
        .args(render_args(&out_dir))
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("uvt");
    drop(child.stderr.take());
    let o = child.wait_with_output().unwrap();
    let report = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success() && report.contains("wrote "),
        "uvt render with a closed stderr: {:?}\n{report}",
        o.status
    );
    assert!(out_dir.join("report.json").exists());
    // Both closed: a quiet exit, no panic.
    let mut child = Command::new(env!("CARGO_BIN_EXE_uvt"))
        .args(render_args(&dir.path().join("c")))
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("uvt");
    drop(child.stdout.take());
    drop(child.stderr.take());
    let status = child.wait().unwrap();
    assert!(
        status.success(),
        "uvt render with stdout and stderr closed: {status:?}"
    );
}
