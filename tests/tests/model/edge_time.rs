//! Edge-direction time bounds (`core/src/bounds/edge_time.rs`): conservativeness of
//! `EdgeTime` on Laine 2011 and of the compositions `hull_edge()` and `best()` — proptest and a
//! seeded-random sweep (`UVT_SEED`, printed on failure; `UVT_EXTENSIVE=1` for many more cases),
//! each case a whole-viewport brute force against the sample test — at the exact precision and at
//! bounded precisions (the default OFF = 20 and the coarse OFF = 24, 28, where a missing epsilon
//! term fails), on motion-only triangles of every kind (the CoC removed; camera-plane crossing,
//! w = 0 vertices, slivers, domain extremes) and on the unmodified kinds (which pass through);
//! a hand-picked direction; and a known case the edge bound must tighten (it fails without it).

use proptest::prelude::*;
use uvt_core::bounds::edge_time::EdgeTime;
use uvt_core::bounds::registry::{best, hull_edge};
use uvt_core::config::unit::Full;
use uvt_core::{
    setup, Bounded, BoundsStrategy, Exact, Laine2011, Outcome, PixelRect, SamplePattern,
    TileBounds, Triangle, Vertex, Viewport,
};
use uvt_tests::kinds::{make, params, Kind, ALL_KINDS, NP};
use uvt_tests::*;

/// The triangle without its CoC: motion-only (or static) whatever the kind.
fn no_coc(t: &Triangle) -> Triangle {
    let f = |v: Vertex| Vertex {
        coc: Default::default(),
        ..v
    };
    Triangle::new(t.vertices(0).map(f), t.vertices(1).map(f)).expect("same triangle, CoC 0")
}

fn edge_t() -> EdgeTime<Laine2011> {
    EdgeTime::new(Laine2011, "edge-t")
}

/// Whether the edge bound is active for `t` at precision `P` (a motion-only triangle with an
/// oblique edge that setup keeps).
fn active<P: uvt_core::Precision>(t: &Triangle, vp: Viewport) -> bool {
    let mut ops = Default::default();
    match setup::<P, Full>(t, vp, &mut ops) {
        Outcome::Visible(s) => edge_t().prepare::<Full>(&s, &mut ops).edge().is_some(),
        Outcome::Culled(_) | Outcome::Refused(_) => false,
    }
}

/// Brute force of every strategy with the edge bound at precision `P`, tile sizes 1, 2, 4, 8;
/// returns (covered samples, whether the edge bound was active).
fn check_at<P: uvt_core::Precision>(
    t: &Triangle,
    pat: &SamplePattern<'_>,
) -> Result<(u64, bool), String> {
    let vp = Viewport::new(24, 20).unwrap();
    let mut covered = 0;
    for bt in [1u16, 2, 4, 8] {
        covered = check_conservative_with::<_, P>(&edge_t(), t, vp, pat, bt)?;
        check_conservative_with::<_, P>(&hull_edge(), t, vp, pat, bt)?;
        check_conservative_with::<_, P>(&best(), t, vp, pat, bt)?;
    }
    Ok((covered, active::<P>(t, vp)))
}

/// One case: the motion-only version of the kind's triangle at the exact and the bounded
/// precisions, and the unmodified triangle at the default; (covered, edge-bound-active count).
fn check_case(kind: Kind, p: &[f64; NP], pat_seed: u64) -> Result<(u64, u64), String> {
    let samples = mixed_samples(pat_seed);
    let pat = SamplePattern::new(2, 8, &samples).unwrap();
    let m = no_coc(&make(kind, p));
    let mut covered = 0;
    let mut act = 0;
    for r in [
        check_at::<Exact>(&m, &pat)?,
        check_at::<uvt_core::BoundedPrecision>(&m, &pat)?,
        check_at::<Bounded<16, 16, 16, 24>>(&m, &pat)?,
        check_at::<Bounded<16, 16, 16, 28>>(&m, &pat)?,
        check_at::<Exact>(&make(kind, p), &pat)?,
        check_at::<uvt_core::BoundedPrecision>(&make(kind, p), &pat)?,
    ] {
        covered += r.0;
        act += u64::from(r.1);
    }
    Ok((covered, act))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(48, 1500), failure_persistence: None, ..ProptestConfig::default() })]
    #[test]
    fn edge_time_conservative(p in params(), pat_seed in any::<u64>(), k in 0usize..8) {
        if let Err(msg) = check_case(ALL_KINDS[k], &p, pat_seed) {
            prop_assert!(false, "{}", msg);
        }
    }
}

/// Seeded random sweep over every kind (cycled); must exercise coverage and the edge bound on
/// the moving, crossing and sliver kinds, or it proves nothing.
#[test]
fn edge_time_conservative_seeded_random() {
    let seed = seed();
    let mut rng = Rng(seed ^ 0xed9e);
    let (mut covered, mut act) = (0u64, [0u64; 8]);
    for case in 0..cases(48, 2000) {
        let k = (case % 8) as usize;
        let mut p = [0.0; NP];
        p.iter_mut().for_each(|x| *x = rng.range(-1.0, 1.0));
        match check_case(ALL_KINDS[k], &p, rng.next_u64()) {
            Ok((c, a)) => {
                covered += c;
                act[k] += a;
            }
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
    for k in [Kind::Moving, Kind::Crossing, Kind::Sliver] {
        let i = ALL_KINDS
            .iter()
            .position(|x| format!("{x:?}") == format!("{k:?}"))
            .unwrap();
        assert!(
            act[i] > 0,
            "edge bound never active on kind {k:?} (seed {seed}): {act:?}"
        );
    }
}

/// A triangle with vertices at pixel positions (ξ, η) (w = 1 at both ends), moved by
/// (dξ, dη) pixels over the shutter, on viewport `vp`.
fn px_tri(vp: Viewport, v: [(f64, f64); 3], d: (f64, f64)) -> Triangle {
    let (w, h) = (f64::from(vp.width()), f64::from(vp.height()));
    let clip = |(x, y): (f64, f64)| [2.0 * x / w - 1.0, 1.0 - 2.0 * y / h, 0.5, 1.0, 0.0];
    let t0 = v.map(clip);
    let t1 = v.map(|(x, y)| clip((x + d.0, y + d.1)));
    tri(t0, t1)
}

/// Hand-picked: a right triangle whose hypotenuse runs at 45° on screen gets n = ±(256, 256)
/// (the normal of that edge, quantized), and one with legs only on the axes and a 45° edge the
/// other way gets ±(256, −256); a triangle whose edges are all axis-aligned gets no edge bound
/// (there is no right triangle without a hypotenuse, so a degenerate one: a static triangle).
#[test]
fn edge_direction_hand_picked() {
    let vp = Viewport::new(64, 64).unwrap();
    let dir = |t: &Triangle| {
        let mut ops = Default::default();
        let Outcome::Visible(s) = setup::<Exact, Full>(t, vp, &mut ops) else {
            panic!("visible")
        };
        edge_t().prepare::<Full>(&s, &mut ops).edge().map(|e| e.n())
    };
    // Legs (10,10)–(30,10) and (10,10)–(10,30): hypotenuse (30,10)–(10,30), direction (−1, 1),
    // normal ∝ (1, 1).
    let a = px_tri(vp, [(10.0, 10.0), (30.0, 10.0), (10.0, 30.0)], (8.0, 3.0));
    let n = dir(&a).expect("edge bound on a moving right triangle");
    assert!(n == [256, 256] || n == [-256, -256], "n = {n:?}");
    // Hypotenuse (10,10)–(30,30): normal ∝ (1, −1).
    let b = px_tri(vp, [(10.0, 10.0), (30.0, 10.0), (30.0, 30.0)], (8.0, 3.0));
    let n = dir(&b).expect("edge bound");
    assert!(n == [256, -256] || n == [-256, 256], "n = {n:?}");
    // Not moving: static class, no edge bound.
    let c = px_tri(vp, [(10.0, 10.0), (30.0, 10.0), (10.0, 30.0)], (0.0, 0.0));
    assert_eq!(dir(&c), None);
}

/// Samples admitted (inside the tile's box and predicate) over the whole viewport, and covered.
fn admitted<B: BoundsStrategy>(
    s: &B,
    t: &Triangle,
    vp: Viewport,
    pat: &SamplePattern<'_>,
) -> (u64, u64) {
    let mut ops = Default::default();
    let Outcome::Visible(set) = setup::<Exact, Full>(t, vp, &mut ops) else {
        panic!("visible")
    };
    let full = uvt_core::Setup::unculled::<Exact>(t, vp);
    let co = s.prepare::<Full>(&set, &mut ops);
    let fp = set.footprint();
    let (mut adm, mut cov) = (0, 0);
    for py in fp.y0..fp.y1 {
        for px in fp.x0..fp.x1 {
            let cell = PixelRect {
                x0: px,
                y0: py,
                x1: px + 1,
                y1: py + 1,
            };
            let b = s.tile::<Full>(&set, &co, cell, &mut ops);
            for smp in pat.pixel(px, py) {
                let hit = uvt_core::sample::test::<Exact, uvt_core::Full>(
                    &full,
                    uvt_core::ScreenPos::of(px, py, smp),
                    smp,
                    &mut ops,
                )
                .is_some();
                let ok = b.as_ref().is_some_and(|b| {
                    b.admits(
                        smp.u().to_bits(),
                        smp.v().to_bits(),
                        smp.t().to_bits(),
                        &mut ops,
                    )
                });
                assert!(
                    !hit || ok,
                    "covered sample culled at ({px}, {py})\n{}",
                    dump(t)
                );
                adm += u64::from(ok);
                cov += u64::from(hit);
            }
        }
    }
    (adm, cov)
}

/// The known case: a right triangle with a 45° hypotenuse translating along it. Laine's box
/// keeps every tile near the hypotenuse for the whole time the triangle's box overlaps it; the
/// edge bound drops the times the tile is on the far side of the hypotenuse. Without the edge
/// bound (`EdgeTime` passing Laine's box through) the admitted counts are equal and this fails.
#[test]
fn edge_bound_tightens_a_translating_right_triangle() {
    let vp = Viewport::new(48, 48).unwrap();
    let mut rng = Rng(seed() ^ 0x7a11);
    let samples = random_samples(&mut rng, 2, 16);
    let pat = SamplePattern::new(2, 16, &samples).unwrap();
    let t = px_tri(vp, [(6.0, 6.0), (26.0, 6.0), (6.0, 26.0)], (12.0, -12.0));
    let (laine, cov_l) = admitted(&Laine2011, &t, vp, &pat);
    let (edge, cov_e) = admitted(&edge_t(), &t, vp, &pat);
    assert_eq!(cov_l, cov_e);
    assert!(cov_e > 1000, "only {cov_e} covered");
    // Measured at the time of writing: Laine admits 1.4× what the edge bound does here; require
    // at least a 10% reduction so a weakened bound fails too.
    assert!(
        edge * 10 < laine * 9,
        "edge-t admits {edge}, Laine {laine} (covered {cov_e}): no tightening"
    );
}
