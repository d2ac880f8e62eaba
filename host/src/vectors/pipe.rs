//! `uvt vectors gen`, `ver` and `decode`: the seeded streams on standard output, the check of
//! a DUT runner's input+output pairs from standard input, and one record decoded field by field
//! with the model's answer beside it. Record meanings come from `uvt-records` ([`kind`]), the
//! one codec the C library uses too.

use std::io::{BufRead, Write};

use anyhow::{anyhow, bail, Result};
use uvt_core::coverage::Counts;
use uvt_records::coverage;
use uvt_records::format::{parse, to_text};
use uvt_records::kind::{self, Kind};
use uvt_records::stream::{Shard, Stream};

/// Write records `shard.range(count)` of `stream` to `out`, one line each; the records written.
/// With `cov`, the bins the model's test takes on each record are added to it
/// ([`uvt_records::coverage`]).
pub fn gen(
    out: &mut impl Write,
    stream: &Stream,
    count: u64,
    shard: Shard,
    mut cov: Option<&mut Counts>,
) -> Result<u64> {
    let r = shard.range(count);
    let n = r.end - r.start;
    let mut buf = String::new();
    for i in r {
        let rec = stream.record(i);
        if let Some(c) = cov.as_deref_mut() {
            coverage::record(stream.kind(), &rec.0 .0, c)
                .map_err(|e| anyhow!("record {i}: {e}"))?;
        }
        buf += &to_text(std::slice::from_ref(&rec.0));
        if buf.len() > 1 << 16 {
            out.write_all(buf.as_bytes())?;
            buf.clear();
        }
    }
    out.write_all(buf.as_bytes())?;
    out.flush()?;
    Ok(n)
}

/// What `ver` found.
#[derive(Debug, Default)]
pub struct Verified {
    /// pairs read
    pub pairs: u64,
    /// pairs whose output differs from the model's
    pub mismatches: u64,
    /// the first 20 mismatches, each naming the line, every differing field and the input
    pub msgs: Vec<String>,
}

/// Read input+output record pairs of `kind` from `input`, one pair per line (the input record's
/// words, then the output record's, as `uvt vectors gen` writes words: 8 hex digits separated
/// by one space; `spp` samples per resolve record), run the model on each input and compare
/// (every field, or the architectural ones with `arch_only`). A malformed line or an input the
/// model refuses is an error naming the line.
/// With `cov`, the bins the model's test takes on each input are added to it.
pub fn ver(
    input: impl BufRead,
    kind: Kind,
    spp: u32,
    arch_only: bool,
    mut cov: Option<&mut Counts>,
) -> Result<Verified> {
    if kind.needs_setup() {
        bail!(
            "{}_in records name a triangle of a setup_in file: check them with `uvt vectors check`",
            kind.name()
        );
    }
    let (wi, wo) = (kind.words_in(spp) as usize, kind.words_out() as usize);
    let only = if arch_only {
        kind.architectural()
    } else {
        None
    };
    let mut v = Verified::default();
    for (i, line) in input.lines().enumerate() {
        let line = line?;
        let at = format!("stdin line {}", i + 1);
        let words = parse(&line, (wi + wo) as u32, &at)
            .map_err(|e| {
                anyhow!(
                    "{e} ({wi} input + {wo} output words of a {} pair)",
                    kind.name()
                )
            })?
            .remove(0);
        let (inp, obs) = words.split_at(wi);
        let exp = kind::run(kind, inp, None).map_err(|e| anyhow!("{at}: input refused: {e}"))?;
        if let Some(c) = cov.as_deref_mut() {
            coverage::record(kind, inp, c).map_err(|e| anyhow!("{at}: {e}"))?;
        }
        v.pairs += 1;
        let d = kind::diff(&format!("{}_out", kind.name()), &exp.0, obs, only);
        if !d.is_empty() {
            v.mismatches += 1;
            if v.msgs.len() < 20 {
                v.msgs.push(format!(
                    "{at} (pair {}): {}\n  input {}",
                    v.pairs - 1,
                    d.join("\n  "),
                    to_text(&[uvt_records::format::Rec(inp.to_vec())]).trim_end()
                ));
            }
        }
    }
    Ok(v)
}

/// `ver`'s count check: `pairs` read against `expected` (`--count`), or at least one without
/// it — a runner that died before writing anything must not pass. The error names both numbers.
pub fn check_count(pairs: u64, expected: Option<u64>, kind: &str) -> Result<()> {
    match expected {
        Some(n) if n != pairs => bail!(
            "{pairs} {kind} pairs on stdin, --count says {n}: the runner lost or added records"
        ),
        None if pairs == 0 => bail!(
            "no {kind} pairs on stdin: the runner wrote nothing (give --count N to require N)"
        ),
        _ => Ok(()),
    }
}

/// What `decode` shows: the text, and whether a given output differs from the model's.
#[derive(Debug)]
pub struct Decoded {
    /// the fields, the model's output and the differing fields
    pub text: String,
    /// an input+output pair was given and its output is not the model's
    pub differs: bool,
}

/// Decode record words of `what` — a file stem (`bsample_in`, `psample_out`, …) or a kind name
/// (`bsample`: the words are an input record, an output record, or an input record followed by
/// an output record) — field by field; for an input record, also the model's output, and for a
/// pair, the fields in which the given output differs from the model's. `words` are hex words
/// (arguments may hold several, separated by spaces).
pub fn decode(what: &str, words: &[String]) -> Result<Decoded> {
    let ws: Vec<u32> = words
        .iter()
        .flat_map(|a| a.split_whitespace())
        .map(|h| {
            u32::from_str_radix(h.trim_start_matches("0x"), 16)
                .map_err(|e| anyhow!("`{h}` is not a hex word: {e}"))
        })
        .collect::<Result<_>>()?;
    let (name, side) = match what.rsplit_once('_') {
        Some((k, s @ ("in" | "out"))) => (k, Some(s)),
        _ => (what, None),
    };
    let kind = Kind::parse(name).map_err(|e| anyhow!(e))?;
    let spp = if kind == Kind::Resolve {
        ws.len() as u32
    } else {
        0
    };
    let (wi, wo) = (kind.words_in(spp) as usize, kind.words_out() as usize);
    let n = ws.len();
    let side = match side {
        Some(s) => s,
        None if n == wi => "in",
        None if n == wo => "out",
        None if n == wi + wo => "pair",
        None => bail!(
            "{n} words: a {name}_in record has {wi}, a {name}_out record {wo}, a pair {}",
            wi + wo
        ),
    };
    let want = match side {
        "in" => wi,
        "out" => wo,
        _ => wi + wo,
    };
    if n != want && kind != Kind::Resolve {
        bail!("{n} words: a {name}_{side} record has {want}");
    }
    let mut s = String::new();
    let lines = |title: &str, file: &str, w: &[u32]| {
        format!("{title}\n  {}\n", kind::decode(file, w).join("\n  "))
    };
    let done = |text: String, differs: bool| Ok(Decoded { text, differs });
    if side == "out" {
        s += &lines(&format!("{name}_out"), &format!("{name}_out"), &ws);
        return done(s, false);
    }
    let inp = &ws[..wi.min(n)];
    s += &lines(&format!("{name}_in"), &format!("{name}_in"), inp);
    if kind.needs_setup() {
        s += "(the model's output needs the setup_in record this one names: `uvt vectors check`)\n";
        return done(s, false);
    }
    let mut differs = false;
    match kind::run(kind, inp, None) {
        Err(e) => s += &format!("the model refuses this input: {e}\n"),
        Ok(exp) => {
            s += &lines(
                &format!("{name}_out (the model)"),
                &format!("{name}_out"),
                &exp.0,
            );
            if side == "pair" {
                let d = kind::diff(&format!("{name}_out"), &exp.0, &ws[wi..], None);
                differs = !d.is_empty();
                s += &if d.is_empty() {
                    "the given output is the model's\n".to_string()
                } else {
                    format!("the given output differs:\n  {}\n", d.join("\n  "))
                };
            }
        }
    }
    done(s, differs)
}
