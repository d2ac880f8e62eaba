//! The seeded streams: every record is accepted by the model (`kind::run`), every triangle family
//! and the hard cases occur (covered samples, fill-rule ties, a vertex at w ≤ 0, viewport
//! corners), records are a function of (seed, index) alone, and shards concatenate to the stream.
//! `UVT_SEED` picks the seed (printed on failure); `UVT_EXTENSIVE=1` draws 100× more records.

use uvt_records::kind::{self, Kind};
use uvt_records::stream::{Shard, Stream, FAMILIES};

fn seed() -> u64 {
    std::env::var("UVT_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1)
}

fn count() -> u64 {
    if std::env::var("UVT_EXTENSIVE").as_deref() == Ok("1") {
        300_000
    } else {
        3_000
    }
}

#[test]
fn every_record_is_accepted_and_the_hard_cases_occur() {
    let seed = seed();
    for (kind, config) in [
        (Kind::Bsample, None),
        (Kind::Bsample, Some("bounded-8-8-8-28")),
        (Kind::Bsample, Some("planar-16-16-16-20")),
        (Kind::Psample, None),
        (Kind::Setup, None),
        (Kind::Setup, Some("exact-8-8-4")),
        (Kind::Setup, Some("planar-16-16-16-20")),
        (Kind::Select, None),
        (Kind::Resolve, None),
    ] {
        let s = Stream::new(kind, config, seed, 16).expect("stream");
        let (mut fams, mut covered, mut ties, mut inside) = ([0u64; 9], 0, 0, 0);
        let mut depths = std::collections::BTreeSet::new();
        for i in 0..count() {
            let (r, fam) = s.record(i);
            if let Some(f) = fam {
                fams[FAMILIES.iter().position(|x| *x == f).unwrap()] += 1;
            }
            let out = kind::run(kind, &r.0, None).unwrap_or_else(|e| {
                panic!(
                    "UVT_SEED={seed} {kind:?} {config:?} record {i} refused: {e}\n  words {:08x?}",
                    r.0
                )
            });
            match kind {
                Kind::Bsample => {
                    covered += u64::from(out.0[0] & 1);
                    depths.insert(out.0[1] as i32);
                    ties +=
                        u64::from((0..3).any(|k| out.0[8 + 2 * k] == 0 && out.0[9 + 2 * k] == 0));
                }
                Kind::Psample => {
                    covered += u64::from(out.0[0] & 1);
                    ties += u64::from(
                        (0..3).any(|k| out.0[1 + 2 * k + 1] == 0 && out.0[2 + 2 * k + 1] == 0),
                    );
                }
                Kind::Select => inside += u64::from(out.0[0] & 1),
                _ => {}
            }
        }
        eprintln!("{kind:?} {config:?}: families {fams:?}, covered {covered}, ties {ties}, inside {inside}");
        if matches!(kind, Kind::Bsample | Kind::Setup) {
            assert!(
                fams.iter().all(|&n| n > 0),
                "UVT_SEED={seed} {kind:?}: a family never drawn: {fams:?}"
            );
        }
        if matches!(kind, Kind::Bsample | Kind::Psample) {
            assert!(
                covered > count() / 20,
                "UVT_SEED={seed} {kind:?} {config:?}: {covered} covered"
            );
            assert!(
                ties > 0,
                "UVT_SEED={seed} {kind:?} {config:?}: no fill-rule tie (E = 0)"
            );
        }
        if kind == Kind::Bsample {
            let (far, near) = (
                uvt_core::config::formats::DEPTH_FAR,
                uvt_core::config::formats::DEPTH_NEAR,
            );
            assert!(
                depths.len() as u64 > covered / 2 && depths.contains(&far) && depths.contains(&near),
                "UVT_SEED={seed} {config:?}: {} distinct depths in {covered} covered samples, far {} near {}",
                depths.len(),
                depths.contains(&far),
                depths.contains(&near)
            );
        }
        if kind == Kind::Select {
            assert!(
                inside > count() / 10 && inside < count() * 9 / 10,
                "inside {inside}"
            );
        }
    }
}

#[test]
fn records_depend_on_seed_and_index_only_and_shards_concatenate() {
    let s = Stream::new(Kind::Bsample, None, seed(), 16).unwrap();
    let all: Vec<_> = (0..1000).map(|i| s.record(i).0).collect();
    // backwards, and from a second stream value: the same records
    let again = Stream::new(Kind::Bsample, None, seed(), 16).unwrap();
    for i in (0..1000).rev() {
        assert_eq!(again.record(i).0, all[i as usize], "record {i}");
    }
    for m in [1, 2, 3, 7, 1000, 1001] {
        let joined: Vec<u64> = (1..=m)
            .flat_map(|k| Shard::new(k, m).unwrap().range(1000))
            .collect();
        assert_eq!(joined, (0..1000).collect::<Vec<_>>(), "shards of {m}");
    }
    assert!(
        Shard::parse("0/3").is_err() && Shard::parse("4/3").is_err() && Shard::parse("x").is_err()
    );
    let other = Stream::new(Kind::Bsample, None, seed() + 1, 16).unwrap();
    assert_ne!(other.record(0).0, all[0]);
}

#[test]
fn refusals_name_the_reason() {
    for (k, c, want) in [
        (Kind::Bounds, None, "setup_in"),
        (Kind::Sample, None, "setup_in"),
        (
            Kind::Psample,
            Some("bounded-16-16-16-20"),
            "planar-16-16-16-20",
        ),
        (Kind::Bsample, Some("exact-16-16-16"), "exact configuration"),
        (
            Kind::Bsample,
            Some("bounded-1-2-3"),
            "unknown configuration",
        ),
        (
            Kind::Select,
            Some("bounded-16-16-16-20"),
            "no configuration",
        ),
    ] {
        let e = Stream::new(k, c, 1, 16).unwrap_err();
        assert!(e.contains(want), "{k:?} {c:?}: {e}");
    }
    assert!(Stream::new(Kind::Resolve, None, 1, 0).is_err());
}
