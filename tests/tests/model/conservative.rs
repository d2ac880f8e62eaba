//! Conservativeness: a sample the sample test covers is never culled by setup, never outside the
//! footprint and never outside its bounds tile's (u, v, t) intervals or rejected by its per-sample
//! predicate — for every strategy (Laine 2011, swept-hull culling, lens-slab time bounds with 1,
//! 2, 8 slabs, bilinear (u, t)/(v, t) surfaces, hull + slabs, the combined best = hull + surfaces), every triangle kind and every bounds-tile size. Property tests (proptest, shrinking) plus a seeded-random sweep
//! (`UVT_SEED`, printed on failure; `UVT_EXTENSIVE=1` for many more cases).

use proptest::prelude::*;
use uvt_core::bounds::hyper::Hyper;
use uvt_core::bounds::lens_time::LensTime;
use uvt_core::bounds::registry::{best, hull, hull_lens};
use uvt_core::{BboxScan, Laine2011, SamplePattern, Viewport};
use uvt_tests::kinds::{make, params, Kind, ALL_KINDS, NP};
use uvt_tests::*;

fn check_all(kind: Kind, p: &[f64; NP], pat_seed: u64) -> Result<u64, String> {
    let t = make(kind, p);
    let vp = Viewport::new(24, 20).unwrap();
    let samples = mixed_samples(pat_seed);
    let pat = SamplePattern::new(2, 8, &samples).unwrap();
    let mut covered = 0;
    for bt in [1u16, 2, 4, 8] {
        covered = check_conservative(&Laine2011, &t, vp, &pat, bt)?;
        check_conservative(&hull(), &t, vp, &pat, bt)?;
        check_conservative(&LensTime::<8>, &t, vp, &pat, bt)?;
        check_conservative(&best(), &t, vp, &pat, bt)?;
        check_conservative(&Hyper, &t, vp, &pat, bt)?;
        check_conservative(&hull_lens(), &t, vp, &pat, bt)?;
    }
    check_conservative(&BboxScan, &t, vp, &pat, 1)?;
    check_conservative(&LensTime::<1>, &t, vp, &pat, 2)?;
    check_conservative(&LensTime::<2>, &t, vp, &pat, 1)?;
    Ok(covered)
}

/// The same check at narrow precisions: triangles and samples snapped to the grids.
fn check_narrow(kind: Kind, p: &[f64; NP], pat_seed: u64) -> Result<(), String> {
    use uvt_core::Prec;
    let t = make(kind, p);
    let vp = Viewport::new(24, 20).unwrap();
    let mut rng = Rng(pat_seed);
    let samples = random_samples(&mut rng, 2, 8);
    macro_rules! at {
        ($p:ty) => {{
            let tt = snap_tri::<$p>(&t);
            let ss = snap_samples::<$p>(&samples);
            let pat = SamplePattern::new_with::<$p>(2, 8, &ss).unwrap();
            for bt in [1u16, 2, 4, 8] {
                check_conservative_with::<_, $p>(&Laine2011, &tt, vp, &pat, bt)?;
                check_conservative_with::<_, $p>(&best(), &tt, vp, &pat, bt)?;
                check_conservative_with::<_, $p>(&Hyper, &tt, vp, &pat, bt)?;
                check_conservative_with::<_, $p>(&hull_lens(), &tt, vp, &pat, bt)?;
            }
        }};
    }
    at!(Prec<6, 6, 2>);
    at!(Prec<8, 8, 4>);
    at!(Prec<12, 10, 0>);
    Ok(())
}

/// The same check at bounded sample-test precisions (`Bounded<…, OFF>`), the rounded test as the
/// truth: setup and every strategy, widened by the conservative epsilon, must still admit every
/// sample the rounded test covers — at the candidate default (OFF = 20, ε ≈ 10 raw) and at coarse
/// grids (OFF = 24, 28: ε up to 26216 raw, 0.4 clip units on this 24×20 viewport), where a
/// strategy that dropped its epsilon term fails.
fn check_bounded(kind: Kind, p: &[f64; NP], pat_seed: u64) -> Result<u64, String> {
    use uvt_core::Bounded;
    let t = make(kind, p);
    let vp = Viewport::new(24, 20).unwrap();
    let samples = mixed_samples(pat_seed);
    let pat = SamplePattern::new(2, 8, &samples).unwrap();
    let mut covered = 0;
    macro_rules! at {
        ($p:ty) => {{
            for bt in [1u16, 4] {
                covered += check_conservative_with::<_, $p>(&Laine2011, &t, vp, &pat, bt)?;
                // Every tighter strategy carries the epsilon itself (hull faces widened by the
                // projected perturbation, slab and surface values by (ε_x + ε_w)·E).
                check_conservative_with::<_, $p>(&hull(), &t, vp, &pat, bt)?;
                check_conservative_with::<_, $p>(&LensTime::<8>, &t, vp, &pat, bt)?;
                check_conservative_with::<_, $p>(&Hyper, &t, vp, &pat, bt)?;
                check_conservative_with::<_, $p>(&best(), &t, vp, &pat, bt)?;
                check_conservative_with::<_, $p>(&hull_lens(), &t, vp, &pat, bt)?;
            }
            check_conservative_with::<_, $p>(&LensTime::<1>, &t, vp, &pat, 2)?;
            check_conservative_with::<_, $p>(&best(), &t, vp, &pat, 8)?;
            check_conservative_with::<_, $p>(&BboxScan, &t, vp, &pat, 1)?;
        }};
    }
    at!(uvt_core::BoundedPrecision);
    at!(Bounded<16, 16, 16, 24>);
    at!(Bounded<16, 16, 16, 28>);
    Ok(covered)
}

fn config() -> ProptestConfig {
    ProptestConfig {
        cases: cases(200, 5000),
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

macro_rules! kind_test {
    ($name:ident, $kind:expr) => {
        proptest! {
            #![proptest_config(config())]
            #[test]
            fn $name(p in params(), pat_seed in any::<u64>()) {
                if let Err(msg) = check_all($kind, &p, pat_seed) {
                    prop_assert!(false, "{}", msg);
                }
            }
        }
    };
}

kind_test!(conservative_static, Kind::Static);
kind_test!(conservative_moving, Kind::Moving);
kind_test!(conservative_defocused, Kind::Defocus);
kind_test!(conservative_motion_and_defocus, Kind::Both);
kind_test!(conservative_camera_plane_crossing, Kind::Crossing);
kind_test!(conservative_domain_extremes, Kind::Extreme);
kind_test!(conservative_slivers_and_flips, Kind::Sliver);
kind_test!(conservative_w_zero_vertex, Kind::WZero);

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(64, 1500), failure_persistence: None, ..ProptestConfig::default() })]
    #[test]
    fn conservative_at_bounded_precisions(p in params(), pat_seed in any::<u64>(), k in 0usize..8) {
        if let Err(msg) = check_bounded(ALL_KINDS[k], &p, pat_seed) {
            prop_assert!(false, "{}", msg);
        }
    }
}

/// Seeded random sweep of `check` over `kinds` (cycled), `n` cases from `UVT_SEED ^ salt`;
/// prints the seed on failure and must exercise coverage, or it proves nothing.
fn seeded_sweep(
    what: &str,
    salt: u64,
    n: u32,
    kinds: &[Kind],
    check: impl Fn(Kind, &[f64; NP], u64) -> Result<u64, String>,
) {
    let seed = seed();
    let mut rng = Rng(seed ^ salt);
    let mut covered = 0;
    for (case, kind) in (0..n).zip(kinds.iter().cycle()) {
        let mut p = [0.0; NP];
        p.iter_mut().for_each(|x| *x = rng.range(-1.0, 1.0));
        match check(*kind, &p, rng.next_u64()) {
            Ok(c) => covered += c,
            Err(msg) => panic!("{msg}\n  kind {kind:?}, case {case}, rerun with UVT_SEED={seed}"),
        }
    }
    assert!(
        covered > 1000,
        "only {covered} covered samples in the {what} (seed {seed})"
    );
}

/// Seeded random sweep of the bounded configurations over every kind.
#[test]
fn conservative_bounded_seeded_random() {
    seeded_sweep(
        "bounded sweep",
        0xb0d,
        cases(48, 2000),
        &ALL_KINDS,
        check_bounded,
    );
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(48, 1000), failure_persistence: None, ..ProptestConfig::default() })]
    #[test]
    fn conservative_at_narrow_precisions(p in params(), pat_seed in any::<u64>(), k in 0usize..6) {
        let kind = [Kind::Static, Kind::Moving, Kind::Defocus, Kind::Both, Kind::Crossing, Kind::Extreme][k];
        if let Err(msg) = check_narrow(kind, &p, pat_seed) {
            prop_assert!(false, "{}", msg);
        }
    }
}

/// Seeded random sweep over the six original kinds; prints the seed on failure.
#[test]
fn conservative_seeded_random() {
    let kinds = &ALL_KINDS[..6];
    seeded_sweep("sweep", 0, cases(60, 3000), kinds, check_all);
}
