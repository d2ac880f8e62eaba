//! `uvt vectors gen | runner | uvt vectors ver` and `uvt vectors decode`: a stream's shards
//! concatenate to the stream byte for byte; pairs whose outputs are the model's pass `ver`, a
//! flipped output bit fails it naming the line and the field (in both modes where the field is
//! architectural, only in full mode where it is internal) and so do fewer pairs than fed (none,
//! or not `--count`); `decode` shows a record's fields and the model's answer and exits non-zero
//! when a given output differs from it; bad input is refused with a reason and a non-zero exit.
//! `UVT_SEED` seeds the streams (printed on failure).

use std::io::Write;
use std::process::{Command, Output, Stdio};

use uvt_records::format::{parse, to_text, Rec};
use uvt_records::kind::{self, Kind};

fn seed() -> u64 {
    std::env::var("UVT_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1)
}

fn uvt(args: &[&str], stdin: Option<&str>) -> Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_uvt"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("uvt");
    let mut i = c.stdin.take().unwrap();
    if let Some(s) = stdin {
        i.write_all(s.as_bytes()).unwrap();
    }
    drop(i);
    c.wait_with_output().unwrap()
}

fn text(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned() + &String::from_utf8_lossy(&o.stderr)
}

/// The pairs a runner would write: each input with the model's output appended.
fn pairs(kind: Kind, inputs: &str) -> Vec<(Vec<u32>, Vec<u32>)> {
    let w = kind.words_in(16);
    parse(inputs, w, "gen")
        .unwrap()
        .into_iter()
        .map(|i| {
            let o = kind::run(kind, &i, None).unwrap().0;
            (i, o)
        })
        .collect()
}

fn lines(p: &[(Vec<u32>, Vec<u32>)]) -> String {
    let recs: Vec<Rec> = p
        .iter()
        .map(|(i, o)| Rec([i.clone(), o.clone()].concat()))
        .collect();
    to_text(&recs)
}

#[test]
fn shards_concatenate_to_the_stream() {
    let s = seed().to_string();
    for kind in ["bsample", "psample", "select", "resolve", "setup"] {
        let whole = uvt(
            &["vectors", "gen", kind, "--count", "500", "--seed", &s],
            None,
        );
        assert!(whole.status.success(), "{}", text(&whole));
        assert_eq!(String::from_utf8_lossy(&whole.stdout).lines().count(), 500);
        let mut joined = Vec::new();
        for k in 1..=3 {
            let shard = format!("{k}/3");
            let o = uvt(
                &[
                    "vectors", "gen", kind, "--count", "500", "--seed", &s, "--shard", &shard,
                ],
                None,
            );
            assert!(o.status.success(), "{}", text(&o));
            joined.extend_from_slice(&o.stdout);
        }
        assert!(
            joined == whole.stdout,
            "UVT_SEED={s} {kind}: the 3 shards do not concatenate to the stream"
        );
    }
}

#[test]
fn ver_passes_the_models_pairs_and_names_a_flipped_field() {
    let s = seed().to_string();
    for (kind, arch_field, internal_word) in [
        (Kind::Bsample, 1usize, 9usize), // depth; e0's low word
        (Kind::Psample, 1, 3),           // depth; e0's low word
    ] {
        let name = kind.name();
        let g = uvt(
            &["vectors", "gen", name, "--count", "2000", "--seed", &s],
            None,
        );
        let mut p = pairs(kind, &String::from_utf8_lossy(&g.stdout));
        let ok = uvt(&["vectors", "ver", name], Some(&lines(&p)));
        assert!(ok.status.success(), "UVT_SEED={s} {name}: {}", text(&ok));
        assert!(text(&ok).contains("PASS 2000"), "{}", text(&ok));
        // a covered sample's depth flipped: both modes fail, naming line and field
        let r = p
            .iter()
            .position(|(_, o)| o[0] & 1 == 1)
            .expect("a covered sample");
        p[r].1[arch_field] ^= 1 << 5;
        for mode in [
            &["vectors", "ver", name][..],
            &["vectors", "ver", name, "--arch-only"][..],
        ] {
            let bad = uvt(mode, Some(&lines(&p)));
            let t = text(&bad);
            assert!(
                !bad.status.success(),
                "UVT_SEED={s} {mode:?}: a flipped depth passed"
            );
            assert!(
                t.contains(&format!("stdin line {}", r + 1)) && t.contains("field depth"),
                "{t}"
            );
        }
        p[r].1[arch_field] ^= 1 << 5;
        // an internal edge value flipped: full mode fails, architectural mode passes
        p[r].1[internal_word] ^= 1;
        let full = uvt(&["vectors", "ver", name], Some(&lines(&p)));
        assert!(
            !full.status.success() && text(&full).contains("field e0"),
            "{}",
            text(&full)
        );
        let arch = uvt(&["vectors", "ver", name, "--arch-only"], Some(&lines(&p)));
        assert!(arch.status.success(), "{}", text(&arch));
    }
}

#[test]
fn decode_shows_the_fields_and_the_models_answer() {
    let g = uvt(
        &["vectors", "gen", "bsample", "--count", "1", "--seed", "5"],
        None,
    );
    let line = String::from_utf8_lossy(&g.stdout).trim().to_string();
    let d = uvt(&["vectors", "decode", "bsample_in", &line], None);
    let t = text(&d);
    assert!(d.status.success(), "{t}");
    for want in [
        "t0_v0_x = 0x",
        "off_shift = ",
        "bsample_out (the model)",
        "depth = ",
    ] {
        assert!(t.contains(want), "{want} missing: {t}");
    }
    let p = pairs(Kind::Bsample, &format!("{line}\n"));
    let mut o = p[0].1.clone();
    o[10] ^= 0x100; // e1
    let words: Vec<String> = p[0]
        .0
        .iter()
        .chain(&o)
        .map(|w| format!("{w:08x}"))
        .collect();
    let mut args = vec!["vectors", "decode", "bsample"];
    args.extend(words.iter().map(String::as_str));
    let bad = uvt(&args, None);
    let t = text(&bad);
    assert!(
        t.contains("the given output differs") && t.contains("field e1"),
        "{t}"
    );
    assert!(
        !bad.status.success() && t.contains("differs from the model's"),
        "a pair whose output differs from the model's exited 0: {t}"
    );
    // the model's own pair: the same decode, exit 0
    let words: Vec<String> = p[0]
        .0
        .iter()
        .chain(&p[0].1)
        .map(|w| format!("{w:08x}"))
        .collect();
    let mut args = vec!["vectors", "decode", "bsample"];
    args.extend(words.iter().map(String::as_str));
    let good = uvt(&args, None);
    assert!(
        good.status.success() && text(&good).contains("the given output is the model's"),
        "{}",
        text(&good)
    );
}

#[test]
fn ver_fails_on_fewer_pairs_than_expected() {
    let g = uvt(
        &["vectors", "gen", "bsample", "--count", "5", "--seed", "3"],
        None,
    );
    let p = pairs(Kind::Bsample, &String::from_utf8_lossy(&g.stdout));
    // a dead runner: nothing on stdin
    let empty = uvt(&["vectors", "ver", "bsample"], Some(""));
    assert!(
        !empty.status.success() && text(&empty).contains("no bsample pairs on stdin"),
        "an empty stdin passed: {}",
        text(&empty)
    );
    assert!(!text(&empty).contains("PASS"), "{}", text(&empty));
    // a runner that lost records: fewer pairs than --count
    let short = uvt(
        &["vectors", "ver", "bsample", "--count", "6"],
        Some(&lines(&p)),
    );
    assert!(
        !short.status.success()
            && text(&short).contains("5 bsample pairs on stdin, --count says 6"),
        "{}",
        text(&short)
    );
    let zero = uvt(&["vectors", "ver", "bsample", "--count", "5"], Some(""));
    assert!(!zero.status.success(), "{}", text(&zero));
    // the expected number: pass
    for args in [
        &["vectors", "ver", "bsample", "--count", "5"][..],
        &["vectors", "ver", "bsample"][..],
    ] {
        let ok = uvt(args, Some(&lines(&p)));
        assert!(
            ok.status.success() && text(&ok).contains("PASS 5 bsample pairs"),
            "{args:?}: {}",
            text(&ok)
        );
    }
    // --count 0 accepts an empty stdin (nothing was fed)
    let none = uvt(&["vectors", "ver", "bsample", "--count", "0"], Some(""));
    assert!(none.status.success(), "{}", text(&none));
}

#[test]
fn bad_input_is_refused_with_a_reason() {
    for (args, stdin, want) in [
        (
            &["vectors", "gen", "bounds", "--count", "3"][..],
            None,
            "setup_in",
        ),
        (
            &["vectors", "gen", "nope", "--count", "3"][..],
            None,
            "unknown record kind",
        ),
        (
            &[
                "vectors",
                "gen",
                "psample",
                "--count",
                "3",
                "--config",
                "bounded-16-16-16-20",
            ][..],
            None,
            "planar-16-16-16-20",
        ),
        (
            &[
                "vectors", "gen", "bsample", "--count", "3", "--shard", "4/3",
            ][..],
            None,
            "1 ≤ K ≤ M",
        ),
        (
            &["vectors", "ver", "bsample"][..],
            Some("0000 1111\n"),
            "stdin line 1",
        ),
        (&["vectors", "decode", "bsample", "12"][..], None, "1 words"),
        (
            &["vectors", "decode", "bsample_in", "zz"][..],
            None,
            "not a hex word",
        ),
    ] {
        let o = uvt(args, stdin);
        assert!(!o.status.success(), "{args:?} succeeded");
        assert!(text(&o).contains(want), "{args:?}: {}", text(&o));
    }
}
