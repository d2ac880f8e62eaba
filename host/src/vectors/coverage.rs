//! `uvt vectors coverage`: per kind with bins, every bin of the model's registry
//! (`uvt_core::coverage`) with its count over the committed sets and over a seeded stream,
//! then over a directed stream biased toward the bins the plain one hits fewer than
//! [`GOAL`] times (`Stream::targeting`). The counting is `uvt_records::coverage`'s, as in every
//! other door.

use std::path::Path;
use std::time::Instant;

use anyhow::{anyhow, Result};
use uvt_core::coverage::{Bin, Counts};
use uvt_records::coverage;
use uvt_records::format::parse;
use uvt_records::kind::Kind;
use uvt_records::stream::Stream;

use super::committed::SETS;

/// Hits per reachable bin that a stream of 10^6 records should reach.
pub const GOAL: u32 = 100;

/// What `report` found: the text table and the JSON report.
pub struct Report {
    /// one table per kind
    pub text: String,
    /// the report as JSON
    pub json: String,
}

/// The counts of every committed record of `kind` under `dir` (sets without the file count 0).
pub fn committed(dir: &Path, kind: Kind) -> Result<Counts> {
    let mut total = Counts::default();
    for set in SETS {
        let path = dir.join(set).join(format!("{}_in.hex", kind.name()));
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue;
        };
        let recs = parse(&text, kind.words_in(0), &format!("{}_in", kind.name()))
            .map_err(|e| anyhow!("{}: {e}", path.display()))?;
        let c = coverage::records(kind, recs.iter().map(Vec::as_slice))
            .map_err(|e| anyhow!("{}: {e}", path.display()))?;
        total.add(&c);
    }
    Ok(total)
}

/// The counts of records 0..`count` of `stream`.
pub fn stream(s: &Stream, count: u64) -> Result<Counts> {
    let mut c = Counts::default();
    for i in 0..count {
        coverage::record(s.kind(), &s.record(i).0 .0, &mut c)
            .map_err(|e| anyhow!("stream record {i}: {e}"))?;
    }
    Ok(c)
}

/// The report over the committed sets under `dir` and `count` stream records of seed `seed`.
pub fn report(dir: &Path, count: u64, seed: u64) -> Result<Report> {
    let mut text = String::new();
    let mut kinds = Vec::new();
    for name in Bin::KINDS {
        let kind = Kind::parse(name).map_err(|e| anyhow!(e))?;
        let com = committed(dir, kind)?;
        let plain = Stream::new(kind, None, seed, 16).map_err(|e| anyhow!(e))?;
        let t0 = Instant::now();
        let st = stream(&plain, count)?;
        let plain_s = t0.elapsed().as_secs_f64();
        let targets: Vec<String> = coverage::bins(kind)
            .filter(|b| b.unreachable().is_none() && st.get(*b) < GOAL)
            .map(|b| b.name().to_string())
            .collect();
        let directed = plain.targeting(&targets).map_err(|e| anyhow!(e))?;
        let t0 = Instant::now();
        let dir_c = if targets.is_empty() {
            st
        } else {
            stream(&directed, count)?
        };
        let dir_s = t0.elapsed().as_secs_f64();
        text.push_str(&format!(
            "{name}: committed sets, {count} stream records of seed {seed} ({plain_s:.1} s), the same directed at the bins under {GOAL} ({dir_s:.1} s)\n"
        ));
        text.push_str(&format!(
            "{:<34} {:>10} {:>10} {:>10}\n",
            "bin", "committed", "stream", "directed"
        ));
        let mut rows = Vec::new();
        for b in coverage::bins(kind) {
            let (c, s, d) = (com.get(b), st.get(b), dir_c.get(b));
            if b.unreachable().is_none() {
                text.push_str(&format!("{:<34} {c:>10} {s:>10} {d:>10}\n", b.name()));
            }
            let why = b.unreachable().map_or(String::new(), |w| {
                format!(", \"unreachable\": {}", quote(w))
            });
            rows.push(format!(
                "      {{\"bin\": \"{}\", \"committed\": {c}, \"stream\": {s}, \"directed\": {d}{why}}}",
                b.name()
            ));
        }
        for b in coverage::bins(kind) {
            if let Some(w) = b.unreachable() {
                text.push_str(&format!("unreachable {}: {w}\n", b.name()));
            }
        }
        text.push('\n');
        kinds.push(format!(
            "    {{\"kind\": \"{name}\", \"stream_seconds\": {plain_s:.1}, \"directed_seconds\": {dir_s:.1}, \"directed_targets\": [{}],\n     \"bins\": [\n{}\n    ]}}",
            targets.iter().map(|t| format!("\"{t}\"")).collect::<Vec<_>>().join(", "),
            rows.join(",\n")
        ));
    }
    let json = format!(
        "{{\n  \"command\": \"uvt vectors coverage --count {count} --seed {seed}\",\n  \"goal\": {GOAL},\n  \"sets\": [{}],\n  \"kinds\": [\n{}\n  ]\n}}\n",
        SETS.iter().map(|s| format!("\"{s}\"")).collect::<Vec<_>>().join(", "),
        kinds.join(",\n")
    );
    Ok(Report { text, json })
}

/// A JSON string literal of `s`.
fn quote(s: &str) -> String {
    format!("\"{}\"", s.replace('\\', "\\\\").replace('"', "\\\""))
}
