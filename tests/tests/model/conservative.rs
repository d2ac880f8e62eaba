//! Conservativeness: a sample the sample test covers is never culled by setup, never outside the
//! footprint and never outside its bounds tile's (u, v, t) intervals or rejected by its per-sample
//! predicate — for every strategy of the registry (`STRATEGIES`, each run as `AnyStrategy`: its
//! own code; lens-slab time bounds also with 1, 2 and 8 slabs) at every configuration of the
//! registry (`CONFIGS`, and two beside it), every triangle kind and every bounds-tile size: a new
//! strategy or configuration is covered without editing this file. Property tests (proptest, shrinking) plus a seeded-random sweep
//! (`UVT_SEED`, printed on failure; `UVT_EXTENSIVE=1` for many more cases).

use proptest::prelude::*;
use uvt_core::bounds::lens_time::LensTime;
use uvt_core::config::registry::{Config, CONFIGS};
use uvt_core::{
    with_config, Bounded, DefaultPrecision, Prec, Precision, Sample, SamplePattern, Triangle,
    Viewport,
};
use uvt_tests::kinds::{make, params, Kind, ALL_KINDS, NP};
use uvt_tests::*;

fn check_all(kind: Kind, p: &[f64; NP], pat_seed: u64) -> Result<u64, String> {
    let t = make(kind, p);
    let vp = Viewport::new(24, 20).unwrap();
    let samples = mixed_samples(pat_seed);
    let pat = SamplePattern::new(2, 8, &samples).unwrap();
    let mut covered = 0;
    for bt in [1u16, 2, 4, 8] {
        covered = check_every_strategy::<DefaultPrecision>(&t, vp, &pat, bt)?;
    }
    // Slab counts beside the registry's (lens-t has BEST_SLABS).
    check_conservative(&LensTime::<1>, &t, vp, &pat, 2)?;
    check_conservative(&LensTime::<2>, &t, vp, &pat, 1)?;
    check_conservative(&LensTime::<8>, &t, vp, &pat, 4)?;
    Ok(covered)
}

/// Every strategy at configuration `P`, triangle and samples snapped to its grids, at the
/// bounds-tile sizes `tiles`.
fn check_at<P: Precision>(
    t: &Triangle,
    vp: Viewport,
    samples: &[Sample],
    tiles: &[u16],
) -> Result<u64, String> {
    let tt = snap_tri::<P>(t);
    let ss = snap_samples::<P>(samples);
    let pat = SamplePattern::new_with::<P>(2, 8, &ss).map_err(|e| e.to_string())?;
    let mut covered = 0;
    for &bt in tiles {
        covered += check_every_strategy::<P>(&tt, vp, &pat, bt)
            .map_err(|e| format!("{}: {e}", Config::of::<P>()))?;
    }
    Ok(covered)
}

/// The same check at every exact configuration of the registry (narrower exact inputs:
/// triangles and samples snapped to the grids), and at `Prec<12, 10, 0>` beside them.
fn check_narrow(kind: Kind, p: &[f64; NP], pat_seed: u64) -> Result<(), String> {
    let t = make(kind, p);
    let vp = Viewport::new(24, 20).unwrap();
    let mut rng = Rng(pat_seed);
    let samples = random_samples(&mut rng, 2, 8);
    for e in CONFIGS.iter().filter(|e| e.config.off().is_none()) {
        with_config!(e.config, P => check_at::<P>(&t, vp, &samples, &[1, 2, 4, 8]))
            .unwrap_or_else(|| Err(format!("{}: no type", e.name)))?;
    }
    check_at::<Prec<12, 10, 0>>(&t, vp, &samples, &[1, 2, 4, 8])?;
    Ok(())
}

/// The same check at every bounded and planar configuration of the registry, the rounded test
/// as the truth: setup and every strategy, widened by the conservative epsilon, must still admit
/// every sample the rounded test covers — at the default (OFF = 20, ε ≈ 10 raw) and at coarse
/// grids (OFF up to 28: ε up to 26216 raw, 0.4 clip units on this 24×20 viewport, with
/// `Bounded<16, 16, 16, 28>` beside the registry), where a strategy that dropped its epsilon
/// term fails.
fn check_bounded(kind: Kind, p: &[f64; NP], pat_seed: u64) -> Result<u64, String> {
    let t = make(kind, p);
    let vp = Viewport::new(24, 20).unwrap();
    let samples = mixed_samples(pat_seed);
    let mut covered = 0;
    for e in CONFIGS.iter().filter(|e| e.config.off().is_some()) {
        covered += with_config!(e.config, P => check_at::<P>(&t, vp, &samples, &[1, 4]))
            .unwrap_or_else(|| Err(format!("{}: no type", e.name)))?;
    }
    covered += check_at::<Bounded<16, 16, 16, 28>>(&t, vp, &samples, &[1, 8])?;
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
