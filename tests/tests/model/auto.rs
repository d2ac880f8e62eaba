//! The per-triangle strategy `auto` (`core/src/bounds/auto/`): conservative like every
//! strategy it picks — proptest and a seeded-random sweep (`UVT_SEED`, printed on failure;
//! `UVT_EXTENSIVE=1` for many more cases), each case a whole-viewport brute force against the
//! sample test at the exact and bounded precisions (the default OFF = 20 and the coarse OFF = 28,
//! where a missing epsilon term fails), every triangle kind and bounds-tile size — with the
//! registry's rule and with rules that force every pick and split by area; the same counters and
//! ops as the strategy it picks (the variants carry that strategy's values unchanged); and the
//! tier's threshold on its boundary.

use proptest::prelude::*;
use uvt_core::bounds::auto::{Auto, Pick, Tier, CHECK_OPS, PICK_OPS, RULE, TRAVEL_OPS};
use uvt_core::bounds::registry::{hull, hull_edge};
use uvt_core::{Bounded, BoundsStrategy, Exact, Laine2011, Prim, SamplePattern, Viewport};
use uvt_tests::kinds::{make, params, Kind, ALL_KINDS, NP};
use uvt_tests::*;

/// Every class takes `heavy` from `from_px` pixels on.
const fn all(heavy: Pick, from_px: u32) -> Auto {
    Auto::with_rule([Tier::from(heavy, from_px); 4])
}

/// The rules of the brute force: the registry's, each pick forced, and area splits (two of
/// them with all three picks, one with travel limits).
fn rules() -> [Auto; 7] {
    [
        Auto::new(),
        all(Pick::Laine, u32::MAX),
        all(Pick::Hull, 0),
        all(Pick::HullEdge, 0),
        all(Pick::Hull, 30),
        Auto::with_rule([
            Tier::from(Pick::Hull, 12),
            Tier {
                hull_from: 10,
                edge_from: 40,
                edge_travel: u32::MAX,
            },
            Tier::from(Pick::Hull, 60),
            Tier {
                hull_from: 6,
                edge_from: 20,
                edge_travel: u32::MAX,
            },
        ]),
        Auto::with_rule([1, 2, 3, 4].map(|k| Tier {
            hull_from: 4 * k,
            edge_from: 10 * k,
            edge_travel: k,
        })),
    ]
}

fn check_at<P: uvt_core::Precision>(
    t: &uvt_core::Triangle,
    pat: &SamplePattern<'_>,
) -> Result<u64, String> {
    let vp = Viewport::new(24, 20).unwrap();
    let mut covered = 0;
    for bt in [1u16, 2, 4, 8] {
        for a in rules() {
            covered += check_conservative_with::<_, P>(&a, t, vp, pat, bt)?;
        }
    }
    Ok(covered)
}

fn check_case(kind: Kind, p: &[f64; NP], pat_seed: u64) -> Result<u64, String> {
    let samples = mixed_samples(pat_seed);
    let pat = SamplePattern::new(2, 8, &samples).unwrap();
    let t = make(kind, p);
    Ok(check_at::<Exact>(&t, &pat)?
        + check_at::<uvt_core::BoundedPrecision>(&t, &pat)?
        + check_at::<Bounded<16, 16, 16, 28>>(&t, &pat)?)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(24, 1000), failure_persistence: None, ..ProptestConfig::default() })]
    #[test]
    fn auto_conservative(p in params(), pat_seed in any::<u64>(), k in 0usize..8) {
        if let Err(msg) = check_case(ALL_KINDS[k], &p, pat_seed) {
            prop_assert!(false, "{}", msg);
        }
    }
}

/// Seeded random sweep over every kind (cycled); must cover samples, or it proves nothing.
#[test]
fn auto_conservative_seeded_random() {
    let seed = seed();
    let mut rng = Rng(seed ^ 0xa070);
    let mut covered = 0u64;
    for case in 0..cases(32, 1500) {
        let k = (case % 8) as usize;
        let mut p = [0.0; NP];
        p.iter_mut().for_each(|x| *x = rng.range(-1.0, 1.0));
        match check_case(ALL_KINDS[k], &p, rng.next_u64()) {
            Ok(c) => covered += c,
            Err(msg) => panic!(
                "{msg}\n  kind {:?}, case {case}, rerun with UVT_SEED={seed}",
                ALL_KINDS[k]
            ),
        }
    }
    assert!(
        covered > 1000,
        "only {covered} covered samples (seed {seed})"
    );
}

/// With a pick forced, `auto` renders with exactly the counters and ops of that strategy (its
/// setup ops plus the choice's: `CHECK_OPS` where the footprint check decides — Laine 2011 at
/// every area — and `PICK_OPS` more where it does not): tiles visited and skipped, samples tested and covered,
/// bounds, row and predicate ops — on every kind, tile sizes 1 and 4.
#[test]
fn forced_pick_is_that_strategy() {
    let seed = seed();
    let mut rng = Rng(seed ^ 0xa071);
    let vp = Viewport::new(24, 20).unwrap();
    let samples = random_samples(&mut rng, 2, 16);
    let pat = SamplePattern::new(2, 16, &samples).unwrap();
    let mut picked = [0u64; 3];
    for case in 0..cases(64, 2000) {
        let k = (case % 8) as usize;
        let mut p = [0.0; NP];
        p.iter_mut().for_each(|x| *x = rng.range(-1.0, 1.0));
        let prims = [Prim {
            tri: make(ALL_KINDS[k], &p),
            color: uvt_core::Rgb888::new(255, 255, 255),
        }];
        for bt in [1u8, 4] {
            let pairs = [
                (
                    render_stats(all(Pick::Laine, u32::MAX), &prims, vp, &pat, bt),
                    render_stats(Laine2011, &prims, vp, &pat, bt),
                ),
                (
                    render_stats(all(Pick::Hull, 0), &prims, vp, &pat, bt),
                    render_stats(hull(), &prims, vp, &pat, bt),
                ),
                (
                    render_stats(all(Pick::HullEdge, 0), &prims, vp, &pat, bt),
                    render_stats(hull_edge(), &prims, vp, &pat, bt),
                ),
            ];
            for (i, (a, s)) in pairs.iter().enumerate() {
                let visible: u64 = s.by_class.iter().sum();
                let mut want = *s;
                let choice = if i == 0 {
                    CHECK_OPS
                } else {
                    CHECK_OPS + PICK_OPS
                };
                want.ops.setup += choice * visible;
                assert_eq!(
                    *a, want,
                    "auto forced to {:?} differs from it: kind {:?}, case {case}, tile {bt}, rerun with UVT_SEED={seed}",
                    Pick::ALL[i], ALL_KINDS[k]
                );
                picked[i] += a.samples_tested;
            }
        }
    }
    assert!(
        picked.iter().all(|&n| n > 0),
        "a pick tested nothing: {picked:?}"
    );
}

/// The tier on its boundaries: below `hull_from` Laine 2011, from it the hull, from `edge_from`
/// hull+edge-t; `u32::MAX` turns a pick off; `edge_from ≤ hull_from` leaves the hull out.
#[test]
fn tier_threshold_boundary() {
    let t = Tier {
        hull_from: 23,
        edge_from: 57,
        edge_travel: u32::MAX,
    };
    assert_eq!(t.pick(0), Pick::Laine);
    assert_eq!(t.pick(22), Pick::Laine);
    assert_eq!(t.pick(23), Pick::Hull);
    assert_eq!(t.pick(56), Pick::Hull);
    assert_eq!(t.pick(57), Pick::HullEdge);
    assert_eq!(t.pick(u32::MAX - 1), Pick::HullEdge);
    let edge = Tier::from(Pick::HullEdge, 57);
    assert_eq!(
        (edge.pick(56), edge.pick(57)),
        (Pick::Laine, Pick::HullEdge)
    );
    let low_edge = Tier {
        hull_from: 30,
        edge_from: 10,
        edge_travel: u32::MAX,
    };
    assert_eq!(
        (low_edge.pick(9), low_edge.pick(10), low_edge.pick(40)),
        (Pick::Laine, Pick::HullEdge, Pick::HullEdge)
    );
    assert_eq!(Tier::LAINE.pick(u32::MAX - 1), Pick::Laine);
    assert_eq!(Tier::from(Pick::Hull, u32::MAX), Tier::LAINE);
    assert_eq!(Auto::new().name(), "auto");
    // The travel limit: hull+edge-t while area ≤ edge_travel × start, the hull past it; below
    // edge_from it changes nothing; no limit reads no start box.
    let lim = Tier {
        hull_from: 23,
        edge_from: 57,
        edge_travel: 3,
    };
    assert!(lim.reads_travel() && !t.reads_travel());
    assert_eq!(lim.pick_travel(60, 20), Pick::HullEdge);
    assert_eq!(lim.pick_travel(61, 20), Pick::Hull);
    assert_eq!(lim.pick_travel(57, 19), Pick::HullEdge);
    assert_eq!(lim.pick_travel(58, 19), Pick::Hull);
    assert_eq!(lim.pick_travel(56, 1), Pick::Hull);
    assert_eq!(lim.pick_travel(22, 0), Pick::Laine);
    assert_eq!(lim.pick_travel(u32::MAX - 1, u32::MAX), Pick::HullEdge);
    assert_eq!(t.pick_travel(u32::MAX - 1, 0), Pick::HullEdge);
    let none = Tier {
        edge_travel: 0,
        ..lim
    };
    assert_eq!(none.pick_travel(u32::MAX - 1, u32::MAX), Pick::Hull);
}

/// Seeded triangles of every kind (cycled; `rng` from `seed`, 400 cases, 20 000 extensive)
/// that are visible on a 200 × 200 viewport at the exact precision: (case, kind index,
/// triangle, setup).
fn seeded_setups(
    seed: u64,
) -> impl Iterator<Item = (usize, usize, uvt_core::Triangle, uvt_core::Setup)> {
    let mut rng = Rng(seed);
    let vp = Viewport::new(200, 200).unwrap();
    (0..cases(400, 20_000) as usize).filter_map(move |case| {
        let k = case % 8;
        let mut p = [0.0; NP];
        p.iter_mut().for_each(|x| *x = rng.range(-1.0, 1.0));
        let t = make(ALL_KINDS[k], &p);
        match uvt_core::setup::setup::<Exact, uvt_core::Full>(&t, vp, &mut Default::default()) {
            uvt_core::setup::Outcome::Visible(s) => Some((case, k, t, s)),
            _ => None,
        }
    })
}

/// The travel limit (`Tier::edge_travel`): on every kind (seeded, `UVT_SEED`) the pick is the
/// tier's at `Auto::area` and `Auto::start_area`; the start box's area is at most the own
/// extent's (the start vertices are among the vertices the own extent holds) and below it on
/// moving triangles; and the choice's setup ops are `CHECK_OPS + PICK_OPS`, plus the start
/// boxes' own and `TRAVEL_OPS` when the area picks hull+edge-t.
#[test]
fn the_travel_limit_reads_the_start_box() {
    let seed = seed();
    let (mut smaller, mut limited, mut kept) = (0u32, 0u32, 0u32);
    for (case, k, t, s) in seeded_setups(seed ^ 0x7a4e) {
        let a = Auto::area(&s);
        let mut start_ops = uvt_core::Ops::default();
        let st = Auto::start_area(&s, &mut start_ops);
        assert!(
            st <= a,
            "kind {:?} case {case}: start area {st} ({st:#x}) over the own extent's {a} ({a:#x}), rerun with UVT_SEED={seed}\n{}",
            ALL_KINDS[k],
            dump(&t)
        );
        smaller += u32::from(st < a && s.class().motion());
        for travel in [0, 1, 2, 4, 16, u32::MAX] {
            for edge_from in [0, a, a.saturating_add(1)] {
                let tier = Tier {
                    hull_from: 0,
                    edge_from,
                    edge_travel: travel,
                };
                let auto = Auto::with_rule([tier; 4]);
                let want = tier.pick_travel(a, st);
                assert_eq!(
                    auto.pick(&s),
                    want,
                    "kind {:?} case {case}: tier {tier:?}, area {a}, start {st}, rerun with UVT_SEED={seed}",
                    ALL_KINDS[k]
                );
                let mut got = uvt_core::Ops::default();
                let _ = auto.prepare::<uvt_core::Full>(&s, &mut got);
                let mut base = uvt_core::Ops::default();
                match want {
                    Pick::Laine => drop(Laine2011.prepare::<uvt_core::Full>(&s, &mut base)),
                    Pick::Hull => drop(hull().prepare::<uvt_core::Full>(&s, &mut base)),
                    Pick::HullEdge => drop(hull_edge().prepare::<uvt_core::Full>(&s, &mut base)),
                }
                let mut choice = CHECK_OPS + PICK_OPS;
                if tier.reads_travel() && tier.pick(a) == Pick::HullEdge {
                    choice += start_ops.setup + TRAVEL_OPS;
                }
                assert_eq!(
                    got.setup,
                    base.setup + choice,
                    "kind {:?} case {case}: tier {tier:?}: setup ops {} against {} + {choice}, rerun with UVT_SEED={seed}",
                    ALL_KINDS[k],
                    got.setup,
                    base.setup
                );
                limited += u32::from(tier.pick(a) == Pick::HullEdge && want == Pick::Hull);
                kept += u32::from(tier.reads_travel() && want == Pick::HullEdge);
            }
        }
    }
    assert!(
        smaller > 0 && limited > 0 && kept > 0,
        "a case never occurred: start below the area {smaller}, limited {limited}, kept {kept}"
    );
}

/// The committed rule is what `uvt auto-rule` derives from the committed stage file: deriving
/// it again gives `core/src/bounds/auto/rule.rs` byte for byte (a rule edited by hand, or stage
/// figures re-measured without regenerating the rule, fails).
#[test]
fn committed_rule_is_derived_from_the_committed_stage_costs() {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    let stages = uvt_host::bench::m4_stages::committed().expect("committed stage figures");
    let rules = uvt_host::bench::auto_rule::derive(stages).expect("derive");
    let want =
        uvt_host::bench::auto_rule::rule_source(&rules, uvt_host::bench::m4_stages::DEFAULT_PATH);
    let have = std::fs::read_to_string(format!("{root}/core/src/bounds/auto/rule.rs")).unwrap();
    assert!(
        have == want,
        "core/src/bounds/auto/rule.rs is not the derived rule; regenerate with `uvt auto-rule`.\nderived:\n{want}"
    );
    for (r, d) in RULE.iter().zip(&rules) {
        assert_eq!(*r, d.tier);
    }
}

/// The footprint check (`Auto::pick` answers Laine 2011 before the own extent when the
/// footprint is below both of the tier's areas) never changes a pick: on every kind (seeded,
/// `UVT_SEED`), at tiers whose areas sit at, just above and just below the triangle's own area
/// and its footprint's, the pick is the tier's at `Auto::area`, and the area is at most the
/// footprint's.
#[test]
fn the_footprint_check_never_changes_the_pick() {
    let seed = seed();
    let mut early = 0u32;
    for (case, k, _, s) in seeded_setups(seed ^ 0xf007) {
        let f = s.footprint();
        let fp = u32::from(f.x1 - f.x0) * u32::from(f.y1 - f.y0);
        let a = Auto::area(&s);
        assert!(
            a <= fp,
            "kind {:?} case {case}: area {a} ({a:#x}) over the footprint's {fp} ({fp:#x}), rerun with UVT_SEED={seed}",
            ALL_KINDS[k]
        );
        let at = [a, fp]
            .into_iter()
            .flat_map(|v| [v.saturating_sub(1), v, v + 1]);
        for h in at.clone().chain([0, u32::MAX]) {
            for e in at.clone().chain([0, u32::MAX]) {
                let tier = Tier {
                    hull_from: h,
                    edge_from: e,
                    edge_travel: u32::MAX,
                };
                let got = Auto::with_rule([tier; 4]).pick(&s);
                let want = tier.pick(a);
                assert_eq!(
                    got, want,
                    "kind {:?} case {case}: tier {tier:?}, area {a}, footprint {fp}, rerun with UVT_SEED={seed}",
                    ALL_KINDS[k]
                );
                early += u32::from(fp < h.min(e));
            }
        }
    }
    assert!(early > 0, "the footprint check never decided");
}

/// A set-up triangle (exact precision, every class) on a 200 × 200 viewport, and its
/// footprint's area.
fn set_up(t: &uvt_core::Triangle) -> (uvt_core::Setup, u32) {
    let vp = Viewport::new(200, 200).unwrap();
    match uvt_core::setup::setup::<Exact, uvt_core::Full>(t, vp, &mut Default::default()) {
        uvt_core::setup::Outcome::Visible(s) => {
            let f = s.footprint();
            let fp = u32::from(f.x1 - f.x0) * u32::from(f.y1 - f.y0);
            (s, fp)
        }
        o => panic!("not visible: {o:?}\n{}", dump(t)),
    }
}

/// A 2 px right triangle at the viewport's centre (w = 1), moving `dx` in x over the shutter,
/// with CoC `coc` (clip units: 0.2 spreads it ±20 px on the 200 px viewport); `x0` moves it.
fn small(x0: f64, coc: f64, dx: f64) -> uvt_core::Triangle {
    let at = |d: f64| {
        [
            [x0 + d, 0.0, 0.5, 1.0, coc],
            [x0 + d + 0.02, 0.0, 0.5, 1.0, coc],
            [x0 + d, 0.02, 0.5, 1.0, coc],
        ]
    };
    tri(at(0.0), at(dx))
}

/// `Auto::area` ranks a triangle by its own extent: the footprint's area without defocus
/// (static, motion: travel included), a few pixels for a 2 px triangle with a ±20 px CoC whose
/// footprint is over 40 × 40, its travel's box (not the CoC's) when it also moves, the footprint
/// side where the viewport clamps the footprint, and the footprint's area where a side is
/// unbounded (the triangle crosses the camera plane).
#[test]
fn area_is_the_own_extent_without_the_coc() {
    let (s, fp) = set_up(&small(0.0, 0.0, 0.0));
    assert_eq!((Auto::area(&s), s.class()), (fp, uvt_core::Class::Static));
    let (s, fp) = set_up(&small(0.0, 0.0, 0.3));
    assert!(fp > 30 * 3, "travel footprint {fp}");
    assert_eq!((Auto::area(&s), s.class()), (fp, uvt_core::Class::Motion));
    let (s, fp) = set_up(&small(0.0, 0.2, 0.0));
    let a = Auto::area(&s);
    assert_eq!(s.class(), uvt_core::Class::Defocus);
    assert!(
        fp >= 40 * 40 && (1..=16).contains(&a),
        "area {a}, footprint {fp}"
    );
    let (moving, travel) = set_up(&small(0.0, 0.0, 0.3));
    let (s, fp) = set_up(&small(0.0, 0.2, 0.3));
    let a = Auto::area(&s);
    assert_eq!(moving.class(), uvt_core::Class::Motion);
    assert!(
        fp > 2 * travel && a.abs_diff(travel) <= travel / 4,
        "area {a}, footprint {fp}, travel box {travel}"
    );
    // At the left edge (x0 = −1: column 0) the footprint is clamped to the viewport; the own
    // side (about 3 px) is less, never more than the footprint's.
    let (s, fp) = set_up(&small(-1.0, 0.2, 0.0));
    let a = Auto::area(&s);
    let f = s.footprint();
    assert!(
        f.x0 == 0 && a <= fp && (1..=16).contains(&a),
        "area {a}, footprint {f:?}"
    );
    // A vertex behind the camera: the crossing sides are unbounded, so the footprint is taken.
    let behind = tri(
        [
            [0.0, 0.0, 0.5, 1.0, 0.2],
            [0.02, 0.0, 0.5, 1.0, 0.2],
            [0.0, 0.02, 0.5, -0.5, 0.2],
        ],
        [
            [0.0, 0.0, 0.5, 1.0, 0.2],
            [0.02, 0.0, 0.5, 1.0, 0.2],
            [0.0, 0.02, 0.5, -0.5, 0.2],
        ],
    );
    let (s, fp) = set_up(&behind);
    let open = s.axes().map(|b| b.lo.is_none() || b.hi.is_none());
    println!(
        "axes unbounded: {open:?}, area {}, footprint {fp}",
        Auto::area(&s)
    );
    assert!(open.iter().all(|&o| o), "axes {:?}", s.axes());
    assert_eq!(Auto::area(&s), fp);
}
