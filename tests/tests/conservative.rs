//! Conservativeness: a sample the sample test covers is never culled by setup, never outside the
//! footprint and never outside its bounds tile's (u, v, t) intervals or rejected by its per-sample
//! predicate — for every strategy (Laine 2011, swept-hull culling, lens-slab time bounds with 1,
//! 2, 8 slabs, bilinear (u, t)/(v, t) surfaces, hull + slabs, the combined best = hull + surfaces), every triangle kind and every bounds-tile size. Property tests (proptest, shrinking) plus a seeded-random sweep
//! (`UVT_SEED`, printed on failure; `UVT_EXTENSIVE=1` for many more cases).

use proptest::prelude::*;
use uvt_core::strategies::{best, hull, hull_lens, Hyper, LensTime};
use uvt_core::{BboxScan, Laine2011, SamplePattern, Triangle, Viewport};
use uvt_tests::*;

#[derive(Clone, Copy, Debug)]
enum Kind {
    Static,
    Moving,
    Defocus,
    Both,
    Crossing,
    Extreme,
}

const NP: usize = 48;

/// Map parameters in [-1, 1] to a triangle of the given kind (shrinks toward simple shapes).
fn make(kind: Kind, p: &[f64; NP]) -> Triangle {
    if let Kind::Extreme = kind {
        let lim = (1i64 << 29) as f64 / 65536.0;
        let e = |x: f64| {
            if x.abs() > 0.9 {
                lim * x.signum()
            } else if x.abs() < 0.05 {
                0.0
            } else {
                x * lim * if x.abs() > 0.5 { 1.0 } else { 0.001 }
            }
        };
        let v = |o: usize| [e(p[o]), e(p[o + 1]), e(p[o + 2]), e(p[o + 3]), e(p[o + 4])];
        return tri([v(0), v(5), v(10)], [v(15), v(20), v(25)]);
    }
    if let Kind::Crossing = kind {
        let v = |k: usize, o: usize| {
            let w = 3.0 * p[o + k];
            [
                3.0 * p[o + 3 + k],
                3.0 * p[o + 6 + k],
                0.5 * w,
                w,
                if p[40] > 0.0 { 0.3 * p[41] } else { 0.0 },
            ]
        };
        return tri([v(0, 0), v(1, 0), v(2, 0)], [v(0, 9), v(1, 9), v(2, 9)]);
    }
    let (cx, cy) = (1.2 * p[0], 1.2 * p[1]);
    let w = 1.0 + 2.5 * (p[2] + 1.0);
    let s = 0.05 + 0.6 * p[3].abs();
    let motion = matches!(kind, Kind::Moving | Kind::Both);
    let defocus = matches!(kind, Kind::Defocus | Kind::Both);
    let (a, b) = (0.15 * p[22], 0.3 * p[23]);
    let coc = |w: f64, k: usize| {
        if defocus {
            a * w + b + 0.05 * p[24 + k]
        } else {
            0.0
        }
    };
    let mut t0 = [[0.0; 5]; 3];
    let mut t1 = [[0.0; 5]; 3];
    for k in 0..3 {
        let (nx, ny) = (cx + s * p[4 + 2 * k], cy + s * p[5 + 2 * k]);
        let wk = w * (1.0 + 0.3 * p[10 + k]);
        t0[k] = [nx * wk, ny * wk, 0.5 * wk, wk, coc(wk, k)];
        t1[k] = if motion {
            let (mx, my) = (
                nx + 1.5 * p[13] + 0.2 * p[16 + k],
                ny + 1.5 * p[14] + 0.2 * p[19 + k],
            );
            let w1 = wk * (1.0 + 0.5 * p[15]);
            [mx * w1, my * w1, 0.5 * w1 + 0.1 * p[27 + k], w1, coc(w1, k)]
        } else {
            t0[k]
        };
    }
    tri(t0, t1)
}

fn check_all(kind: Kind, p: &[f64; NP], pat_seed: u64) -> Result<u64, String> {
    let t = make(kind, p);
    let vp = Viewport::new(24, 20).unwrap();
    let mut rng = Rng(pat_seed);
    let samples = if pat_seed % 3 == 0 {
        grid_samples(&mut rng, 2, 8)
    } else {
        random_samples(&mut rng, 2, 8)
    };
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

fn params() -> impl Strategy<Value = [f64; NP]> {
    proptest::array::uniform32(-1.0f64..=1.0).prop_flat_map(|a| {
        proptest::array::uniform16(-1.0f64..=1.0).prop_map(move |b| {
            let mut p = [0.0; NP];
            p[..32].copy_from_slice(&a);
            p[32..].copy_from_slice(&b);
            p
        })
    })
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

/// Seeded random sweep over all kinds; prints the seed on failure.
#[test]
fn conservative_seeded_random() {
    let seed = seed();
    let mut rng = Rng(seed);
    let kinds = [
        Kind::Static,
        Kind::Moving,
        Kind::Defocus,
        Kind::Both,
        Kind::Crossing,
        Kind::Extreme,
    ];
    let mut covered = 0;
    for case in 0..cases(60, 3000) {
        let kind = kinds[case as usize % kinds.len()];
        let mut p = [0.0; NP];
        p.iter_mut().for_each(|x| *x = rng.range(-1.0, 1.0));
        match check_all(kind, &p, rng.next_u64()) {
            Ok(n) => covered += n,
            Err(msg) => panic!("{msg}\n  kind {kind:?}, case {case}, rerun with UVT_SEED={seed}"),
        }
    }
    // The sweep must exercise coverage, or it proves nothing.
    assert!(
        covered > 1000,
        "only {covered} covered samples in the sweep (seed {seed})"
    );
}
