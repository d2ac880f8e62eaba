//! `uvt vectors check DIR`: every file against its manifest (SHA-256, record count, words per
//! record), then the core re-run on every input record and compared bit for bit with the
//! expected output. A difference is reported with file, line, field, expected and observed (hex
//! and decoded).

use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Context, Result};
use serde_json::Value;
use uvt_core::bounds::laine::LaineCoeffs;
use uvt_core::Setup;

use super::format::{layout, parse, sha256, show_field, STAGES};
use super::stages::*;

/// What a successful check covered.
#[derive(Debug, Default)]
pub struct Checked {
    /// sets checked
    pub sets: Vec<PathBuf>,
    /// records compared
    pub records: u64,
}

/// Check `dir`: a set (has `manifest.json`) or a folder of sets.
pub fn check(dir: &Path) -> Result<Checked> {
    let mut out = Checked::default();
    if dir.join("manifest.json").exists() {
        out.records += check_set(dir)?;
        out.sets.push(dir.into());
        return Ok(out);
    }
    let mut subs: Vec<PathBuf> = std::fs::read_dir(dir)
        .with_context(|| format!("cannot read {}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.join("manifest.json").exists())
        .collect();
    subs.sort();
    if subs.is_empty() {
        bail!("{}: no manifest.json here or in its folders", dir.display());
    }
    for s in subs {
        out.records += check_set(&s)?;
        out.sets.push(s);
    }
    Ok(out)
}

fn check_set(dir: &Path) -> Result<u64> {
    let mpath = dir.join("manifest.json");
    let m: Value = serde_json::from_str(
        &std::fs::read_to_string(&mpath)
            .with_context(|| format!("cannot read {}", mpath.display()))?,
    )
    .map_err(|e| anyhow!("{}: malformed manifest: {e}", mpath.display()))?;
    if m["format"] != "uvt-vectors" || m["format_version"] != super::format::FORMAT_VERSION {
        bail!(
            "{}: not a uvt-vectors manifest of format version {}",
            mpath.display(),
            super::format::FORMAT_VERSION
        );
    }
    let spp = m["resolve_spp"].as_u64().unwrap_or(0) as u32;
    let files = m["files"]
        .as_object()
        .ok_or_else(|| anyhow!("{}: no files", mpath.display()))?;
    // 1. Integrity: every listed file present, checksum, shape.
    let mut data = std::collections::BTreeMap::new();
    for (name, info) in files {
        let p = dir.join(name);
        let text = std::fs::read_to_string(&p)
            .with_context(|| format!("{}: missing or unreadable", p.display()))?;
        let want = info["sha256"].as_str().unwrap_or("");
        let got = sha256(text.as_bytes());
        if want != got {
            bail!("{}: SHA-256 {got} does not match the manifest's {want}: the file is corrupted or truncated", p.display());
        }
        if let Some(stem) = name.strip_suffix(".hex") {
            let words = layout(stem, spp).words;
            if info["words_per_record"].as_u64() != Some(words as u64) {
                bail!(
                    "{}: manifest says {} words per record, this uvt's layout has {words}",
                    p.display(),
                    info["words_per_record"]
                );
            }
            let recs = parse(&text, words, &p.display().to_string()).map_err(|e| anyhow!(e))?;
            if info["records"].as_u64() != Some(recs.len() as u64) {
                bail!(
                    "{}: {} records, the manifest says {}",
                    p.display(),
                    recs.len(),
                    info["records"]
                );
            }
            data.insert(stem.to_string(), recs);
        }
    }
    let get = |n: &str| data.get(n).cloned().unwrap_or_default();
    // 2. Bits: re-run the core on every input.
    let mut setups: Vec<Option<(Setup, LaineCoeffs)>> = Vec::new();
    let mut diffs = Diffs::new(dir, spp);
    let (si, so) = (get("setup_in"), get("setup_out"));
    for (line, (i, o)) in si.iter().zip(&so).enumerate() {
        match run_setup(i) {
            Ok((s, r)) => {
                diffs.cmp("setup_out", line, o, &r.0);
                setups.push(s);
            }
            Err(e) => diffs.fail("setup_in", line, &e),
        }
    }
    let lookup = |i: u32| {
        setups
            .get(i as usize)
            .copied()
            .flatten()
            .ok_or_else(|| format!("triangle {i} is culled or missing in setup_in"))
    };
    for (line, (i, o)) in get("bounds_in").iter().zip(&get("bounds_out")).enumerate() {
        match run_bounds(&lookup, i) {
            Ok((_, r)) => diffs.cmp("bounds_out", line, o, &r.0),
            Err(e) => diffs.fail("bounds_in", line, &e),
        }
    }
    for (line, (i, o)) in get("select_in").iter().zip(&get("select_out")).enumerate() {
        match run_select(i) {
            Ok(r) => diffs.cmp("select_out", line, o, &r.0),
            Err(e) => diffs.fail("select_in", line, &e),
        }
    }
    for (line, (i, o)) in get("sample_in").iter().zip(&get("sample_out")).enumerate() {
        match run_sample(&lookup, i) {
            Ok((_, r)) => diffs.cmp("sample_out", line, o, &r.0),
            Err(e) => diffs.fail("sample_in", line, &e),
        }
    }
    for (line, (i, o)) in get("bsample_in")
        .iter()
        .zip(&get("bsample_out"))
        .enumerate()
    {
        match super::bsample::run_bsample(i) {
            Ok((_, r)) => diffs.cmp("bsample_out", line, o, &r.0),
            Err(e) => diffs.fail("bsample_in", line, &e),
        }
    }
    for (line, (i, o)) in get("psample_in")
        .iter()
        .zip(&get("psample_out"))
        .enumerate()
    {
        match super::psample::run_psample(i) {
            Ok((inp, _, r)) => {
                diffs.cmp("psample_in", line, i, &inp.0);
                diffs.cmp("psample_out", line, o, &r.0);
            }
            Err(e) => diffs.fail("psample_in", line, &e),
        }
    }
    for (line, (i, o)) in get("resolve_in")
        .iter()
        .zip(&get("resolve_out"))
        .enumerate()
    {
        diffs.cmp("resolve_out", line, o, &run_resolve(i).0);
    }
    for stage in STAGES {
        let (a, b) = (
            get(&format!("{stage}_in")).len(),
            get(&format!("{stage}_out")).len(),
        );
        if a != b {
            diffs.msgs.push(format!(
                "{}: {stage}_in has {a} records but {stage}_out {b}",
                dir.display()
            ));
        }
    }
    if diffs.msgs.is_empty() {
        Ok(diffs.compared)
    } else {
        bail!("{} difference(s):\n{}", diffs.count, diffs.msgs.join("\n"))
    }
}

struct Diffs<'a> {
    dir: &'a Path,
    spp: u32,
    msgs: Vec<String>,
    count: u64,
    compared: u64,
}

impl<'a> Diffs<'a> {
    fn new(dir: &'a Path, spp: u32) -> Self {
        Diffs {
            dir,
            spp,
            msgs: Vec::new(),
            count: 0,
            compared: 0,
        }
    }
    fn fail(&mut self, file: &str, line: usize, e: &str) {
        self.count += 1;
        if self.msgs.len() < 20 {
            self.msgs.push(format!(
                "{}/{file}.hex line {}: {e}",
                self.dir.display(),
                line + 1
            ));
        }
    }
    /// Compare the file's expected record with the core's, field by field.
    fn cmp(&mut self, file: &str, line: usize, expected: &[u32], observed: &[u32]) {
        self.compared += 1;
        if expected == observed {
            return;
        }
        self.count += 1;
        if self.msgs.len() >= 20 {
            return;
        }
        let l = layout(file, self.spp);
        for f in &l.fields {
            let (a, b) = (show_field(f, expected), show_field(f, observed));
            if a != b {
                self.msgs.push(format!(
                    "{}/{file}.hex line {} field {}: expected {a}, observed {b}",
                    self.dir.display(),
                    line + 1,
                    f.name
                ));
                return;
            }
        }
        self.msgs.push(format!(
            "{}/{file}.hex line {}: records differ",
            self.dir.display(),
            line + 1
        ));
    }
}
