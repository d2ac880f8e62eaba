//! Conservativeness: a sample the sample test covers is never culled by setup, never outside the
//! footprint and never outside its bounds tile's (u, v, t) intervals — for every triangle kind and
//! every bounds-tile size. Property tests (proptest, shrinking) plus a seeded-random sweep
//! (`UVT_SEED`, printed on failure; `UVT_EXTENSIVE=1` for many more cases).

use proptest::prelude::*;
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
    /// a near-degenerate sliver whose third vertex crosses the long edge during the shutter when
    /// p[7] > 0 (orientation flip through degeneracy)
    Sliver,
    /// one vertex exactly on the camera plane (w = 0) at both ends
    WZero,
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
    if let Kind::Sliver = kind {
        let (ax, ay, bx, by) = (1.2 * p[0], 1.2 * p[1], 1.2 * p[2], 1.2 * p[3]);
        let s = 0.5 + 0.5 * p[4];
        let (dx, dy) = (bx - ax, by - ay);
        let len = (dx * dx + dy * dy).sqrt().max(1e-3);
        let off = 2e-3 * p[5];
        let flip = if p[7] > 0.0 { -1.0 } else { 1.0 };
        let coc = if p[9] > 0.0 { 0.2 * p[8] } else { 0.0 };
        let v = |k: usize, o: f64| {
            let (nx, ny) = match k {
                0 => (ax, ay),
                1 => (bx, by),
                _ => (ax + s * dx - o * dy / len, ay + s * dy + o * dx / len),
            };
            let w = 1.5 + p[10 + k];
            [nx * w, ny * w, 0.5 * w, w, coc]
        };
        return tri(
            [v(0, off), v(1, off), v(2, off)],
            [v(0, off), v(1, off), v(2, flip * off)],
        );
    }
    if let Kind::WZero = kind {
        let v = |k: usize, o: usize| {
            if k == 0 {
                return [3.0 * p[o], 3.0 * p[o + 1], 0.0, 0.0, 0.0];
            }
            let w = 1.5 + p[o + 2 + k];
            let (nx, ny) = (1.2 * p[o + 4 + k], 1.2 * p[o + 6 + k]);
            [
                nx * w,
                ny * w,
                0.5 * w,
                w,
                if p[40] > 0.0 { 0.2 * p[41] } else { 0.0 },
            ]
        };
        let o1 = if p[42] > 0.0 { 10 } else { 0 };
        return tri([v(0, 0), v(1, 0), v(2, 0)], [v(0, o1), v(1, o1), v(2, o1)]);
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
    }
    check_conservative(&BboxScan, &t, vp, &pat, 1)?;
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
            }
        }};
    }
    at!(Prec<6, 6, 2>);
    at!(Prec<8, 8, 4>);
    at!(Prec<12, 10, 0>);
    Ok(())
}

/// The same check at bounded sample-test precisions (`Bounded<…, OFF>`): setup and the bounds
/// widened by the conservative epsilon must still contain every sample the rounded test covers.
fn check_bounded(kind: Kind, p: &[f64; NP], pat_seed: u64) -> Result<u64, String> {
    use uvt_core::Bounded;
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
    macro_rules! at {
        ($p:ty) => {{
            for bt in [1u16, 4] {
                covered += check_conservative_with::<_, $p>(&Laine2011, &t, vp, &pat, bt)?;
            }
            check_conservative_with::<_, $p>(&BboxScan, &t, vp, &pat, 1)?;
        }};
    }
    at!(uvt_core::BoundedPrecision);
    at!(Bounded<16, 16, 16, 24>);
    at!(Bounded<16, 16, 16, 28>);
    Ok(covered)
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
kind_test!(conservative_slivers_and_flips, Kind::Sliver);
kind_test!(conservative_w_zero_vertex, Kind::WZero);

const ALL_KINDS: [Kind; 8] = [
    Kind::Static,
    Kind::Moving,
    Kind::Defocus,
    Kind::Both,
    Kind::Crossing,
    Kind::Extreme,
    Kind::Sliver,
    Kind::WZero,
];

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(64, 1500), failure_persistence: None, ..ProptestConfig::default() })]
    #[test]
    fn conservative_at_bounded_precisions(p in params(), pat_seed in any::<u64>(), k in 0usize..8) {
        if let Err(msg) = check_bounded(ALL_KINDS[k], &p, pat_seed) {
            prop_assert!(false, "{}", msg);
        }
    }
}

/// Seeded random sweep of the bounded configurations over every kind; prints the seed on
/// failure and must exercise coverage.
#[test]
fn conservative_bounded_seeded_random() {
    let seed = seed();
    let mut rng = Rng(seed ^ 0xb0d);
    let mut covered = 0;
    for case in 0..cases(48, 2000) {
        let kind = ALL_KINDS[case as usize % ALL_KINDS.len()];
        let mut p = [0.0; NP];
        p.iter_mut().for_each(|x| *x = rng.range(-1.0, 1.0));
        match check_bounded(kind, &p, rng.next_u64()) {
            Ok(n) => covered += n,
            Err(msg) => panic!("{msg}\n  kind {kind:?}, case {case}, rerun with UVT_SEED={seed}"),
        }
    }
    assert!(
        covered > 1000,
        "only {covered} covered samples in the bounded sweep (seed {seed})"
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
