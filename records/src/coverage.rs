//! Coverage of records: the bins (`uvt_core::coverage::Bin`) that the core's sample tests
//! report while deciding the records — the one counting every door uses (`uvt vectors gen|ver
//! --coverage`, `uvt vectors coverage`, `uvt_coverage` in the C library, `uvt.coverage` in
//! Python, the campaign's summary).

use uvt_core::coverage::{Bin, Counts};

use crate::kind::Kind;
use crate::{bsample, psample};

/// Whether records of `kind` have bins (the kinds whose test reports them).
pub fn has_bins(kind: Kind) -> bool {
    Bin::ALL.iter().any(|b| b.kind() == kind.name())
}

/// The bins of `kind`, in [`Bin::ALL`]'s order (empty for a kind without bins).
pub fn bins(kind: Kind) -> impl Iterator<Item = Bin> {
    Bin::ALL
        .iter()
        .copied()
        .filter(move |b| b.kind() == kind.name())
}

/// Add to `counts` the bins the core's test takes deciding input record `input` of `kind`.
/// An error for a kind without bins or a record the core refuses (as [`crate::kind::run`]).
pub fn record(kind: Kind, input: &[u32], counts: &mut Counts) -> Result<(), String> {
    match kind {
        Kind::Bsample => bsample::run_bsample_probed(input, counts).map(|_| ()),
        Kind::Psample => psample::run_psample_probed(input, counts).map(|_| ()),
        _ => Err(format!(
            "records of kind {} have no coverage bins (kinds with bins: {})",
            kind.name(),
            Bin::KINDS.join(", ")
        )),
    }
}

/// The counts of every record of `records` (each `words` words long) of `kind`; the error
/// names the first refused record by its index.
pub fn records<'a>(
    kind: Kind,
    records: impl IntoIterator<Item = &'a [u32]>,
) -> Result<Counts, String> {
    let mut c = Counts::default();
    for (i, r) in records.into_iter().enumerate() {
        record(kind, r, &mut c).map_err(|e| format!("record {i}: {e}"))?;
    }
    Ok(c)
}

/// `counts` as JSON text: per bin of `kind` its name, count and, for an unreachable bin, the
/// reason — `{"kind": ..., "bins": [{"bin": ..., "count": ..., "unreachable": ...}, ...]}`.
pub fn json(kind: Kind, counts: &Counts) -> String {
    let rows: Vec<String> = bins(kind)
        .map(|b| {
            let why = b.unreachable().map_or(String::new(), |w| {
                format!(", \"unreachable\": {}", quote(w))
            });
            format!(
                "{{\"bin\": \"{}\", \"count\": {}{why}}}",
                b.name(),
                counts.get(b)
            )
        })
        .collect();
    format!(
        "{{\"kind\": \"{}\", \"bins\": [{}]}}",
        kind.name(),
        rows.join(", ")
    )
}

/// `counts` as text: one line per reachable bin of `kind` (`name count`), then the unreachable
/// ones apart with their reasons, and the reachable bins not hit.
pub fn text(kind: Kind, counts: &Counts) -> String {
    let mut out = String::new();
    let mut unhit = Vec::new();
    for b in bins(kind).filter(|b| b.unreachable().is_none()) {
        out.push_str(&format!("{:<34} {}\n", b.name(), counts.get(b)));
        if counts.get(b) == 0 {
            unhit.push(b.name());
        }
    }
    for b in bins(kind) {
        if let Some(w) = b.unreachable() {
            out.push_str(&format!(
                "unreachable {} ({} hits): {w}\n",
                b.name(),
                counts.get(b)
            ));
        }
    }
    if !unhit.is_empty() {
        out.push_str(&format!("not hit: {}\n", unhit.join(", ")));
    }
    out
}

/// A JSON string literal of `s` (quotes and backslashes escaped; the reasons are ASCII text).
fn quote(s: &str) -> String {
    format!("\"{}\"", s.replace('\\', "\\\\").replace('"', "\\\""))
}
