//! The bounded sample test (`core/src/sample/bounded/`): hand-picked cases bit for bit, and its
//! agreement with the exact test — decisions may differ only where the derived vertex
//! perturbation can move an edge across the sample (seeded random, `UVT_SEED`).

use uvt_core::config::unit::Full;
use uvt_core::sample::bounded;
use uvt_core::{
    Bounded, BoundedPrecision, Eps, Exact, Precision, Sample, SamplePattern, ScreenPos, Setup,
    Triangle, Viewport,
};
use uvt_tests::*;

fn eval(t: &Triangle, vp: Viewport, px: u16, py: u16, s: &Sample) -> uvt_core::BoundedEval {
    let setup = Setup::unculled::<BoundedPrecision>(t, vp);
    bounded::eval(
        &setup,
        20,
        ScreenPos::of(px, py, s),
        s,
        &mut Default::default(),
    )
    .expect("inside the viewport")
}

/// A static triangle (−1,−1), (1,−1), (0,1) at w = 1, z = ½ in a 4×4 viewport, sample at the
/// centre of pixel (1, 1) (NDC (−¼, ¼)): every value by hand (module table of `bounded.rs`).
/// A = 1024·x + 2^24, B = 1024·y − 2^24 (raw x, y = ±65536 or 0), grid 2^20.
#[test]
fn hand_picked_static() {
    let vp = Viewport::new(4, 4).unwrap();
    let t = tri(
        [
            [-1.0, -1.0, 0.5, 1.0, 0.0],
            [1.0, -1.0, 0.5, 1.0, 0.0],
            [0.0, 1.0, 0.5, 1.0, 0.0],
        ],
        [
            [-1.0, -1.0, 0.5, 1.0, 0.0],
            [1.0, -1.0, 0.5, 1.0, 0.0],
            [0.0, 1.0, 0.5, 1.0, 0.0],
        ],
    );
    let s = sample_raw(128, 128, 0, 0, 0);
    let ev = eval(&t, vp, 1, 1, &s);
    // a' = (−3·2^24, 5·2^24, 2^24)/2^20, b' = (−5·2^24, −5·2^24, 3·2^24)/2^20
    assert_eq!(ev.ab, [(-48, -80), (80, -80), (16, 48)], "{ev:?}");
    // E0 = 80·48 − 16·(−80), E1 = 16·(−80) − (−48)·48, E2 = (−48)(−80) − 80·(−80)
    assert_eq!(ev.e, [5120, 1024, 10240], "{ev:?}");
    assert_eq!(ev.det_sign, 1);
    // z/w = ½ exactly: raw 2^23.
    assert_eq!(ev.hit.map(|h| h.depth), Some(0x80_0000), "{ev:?}");
}

/// Rounding of the offsets to nearest with ties toward +∞, and of the motion lerp likewise.
#[test]
fn hand_picked_roundings() {
    let vp = Viewport::new(4, 4).unwrap();
    let s = sample_raw(128, 128, 0, 0, 0); // gx = −256, A = 1024·x + 2^24 at w = 1
    let raw = |r: i32| r as f64 / 65536.0;
    // x = −16896 raw: A = −2^19 (tie, −½ grid) → 0; x = −15872: A = +2^19 (tie, +½) → 1;
    // x = −15873: A = 2^19 − 1024 → 0.
    let t = tri(
        [
            [raw(-16896), -1.0, 0.5, 1.0, 0.0],
            [raw(-15872), -1.0, 0.5, 1.0, 0.0],
            [raw(-15873), 1.0, 0.5, 1.0, 0.0],
        ],
        [
            [raw(-16896), -1.0, 0.5, 1.0, 0.0],
            [raw(-15872), -1.0, 0.5, 1.0, 0.0],
            [raw(-15873), 1.0, 0.5, 1.0, 0.0],
        ],
    );
    let ev = eval(&t, vp, 1, 1, &s);
    assert_eq!(ev.ab.map(|p| p.0), [0, 1, 0], "{ev:?}");
    // Motion: x from 1535 to 1536 raw (w = 1 fixed), sample at gx = 0 (pixel 2, sx 0) and
    // t = ½: the lerp 1535.5 rounds (tie) up to 1536, A = 1024·1536 = 1.5·2^20 → a' = 2 (tie up);
    // had the lerp rounded down, a' would be round(1535/1024) = 1.
    let t = tri(
        [
            [raw(1535), -1.0, 0.5, 1.0, 0.0],
            [1.0, -1.0, 0.5, 1.0, 0.0],
            [0.0, 1.0, 0.5, 1.0, 0.0],
        ],
        [
            [raw(1536), -1.0, 0.5, 1.0, 0.0],
            [1.0, -1.0, 0.5, 1.0, 0.0],
            [0.0, 1.0, 0.5, 1.0, 0.0],
        ],
    );
    let ev = eval(&t, vp, 2, 1, &sample_raw(0, 128, 0, 0, 1 << 15));
    assert_eq!(ev.ab[0].0, 2, "{ev:?}");
}

/// A vertex behind the camera (w < 0) takes the rare orientation path: det' = Σ E'·w exactly.
#[test]
fn hand_picked_rare_orientation_path() {
    let vp = Viewport::new(4, 4).unwrap();
    let v = [
        [-1.0, -1.0, 0.5, 1.0, 0.0],
        [1.0, -1.0, 0.5, 1.0, 0.0],
        [0.0, 1.0, -0.5, -1.0, 0.0],
    ];
    let t = tri(v, v);
    let s = sample_raw(128, 128, 0, 0, 0);
    let ev = eval(&t, vp, 1, 1, &s);
    // Vertex 2 at w = −1: A = 0 + (−2^24)... by hand: A2 = 1024·0 + 256·(−65536) = −2^24 → −16,
    // B2 = 1024·65536 − 256·(−65536) = 5·2^24 → 80; vertices 0, 1 as in `hand_picked_static`.
    assert_eq!(ev.ab, [(-48, -80), (80, -80), (-16, 80)], "{ev:?}");
    let [(a0, b0), (a1, b1), (a2, b2)] = ev.ab;
    let e = [a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0];
    assert_eq!(ev.e, e);
    let det: i64 = e[0] + e[1] - e[2]; // w' = (1, 1, −1) in units of 65536
    assert_eq!(ev.det_sign, det.signum(), "{ev:?}");
    // Same decision as the exact test on this unrounded-representable case.
    let exact = uvt_core::sample::test::<Exact, Full>(
        &Setup::unculled::<Exact>(&t, vp),
        ScreenPos::of(1, 1, &s),
        &s,
        &mut Default::default(),
    );
    assert_eq!(
        ev.hit.is_some(),
        exact.is_some(),
        "{ev:?} vs exact {exact:?}"
    );
}

/// The exact bound on a vertex's perturbation (raw clip units, not rounded up): k/2 + 2^(S−1)/(256E)
/// for x/y, ½ for w of a moving triangle (`bounded.rs` module docs).
fn eps_real(shift: u32, motion: bool, defocus: bool, extent: u16) -> f64 {
    let k = match (motion, defocus) {
        (false, false) => 0.0,
        (true, true) => 3.0,
        _ => 1.0,
    };
    k / 2.0 + 2f64.powi(shift as i32 - 1) / (256.0 * extent as f64)
}

/// Distance from p to segment ab.
fn seg_dist(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let s = if l2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    ((p.0 - a.0 - s * dx).powi(2) + (p.1 - a.1 - s * dy).powi(2)).sqrt()
}

/// Result of comparing one configuration: (samples, disagreements, max distance/bound ratio of a
/// disagreement).
fn agreement<P: Precision>(seed: u64, cases: u32) -> Result<(u64, u64, f64), String> {
    let shift = P::OFFSET_SHIFT.expect("a bounded precision");
    let vp = Viewport::new(64, 48).unwrap();
    let (wf, hf) = (64.0, 48.0);
    let mut rng = Rng(seed);
    let samples = random_samples(&mut rng, 2, 4);
    let pat = SamplePattern::new(2, 4, &samples).unwrap();
    let (mut n, mut diff, mut worst) = (0u64, 0u64, 0.0f64);
    for case in 0..cases {
        let motion = case % 2 == 1;
        let defocus = case % 4 >= 2;
        let (cx, cy) = (rng.range(-1.0, 1.0), rng.range(-1.0, 1.0));
        let size = rng.range(0.02, 0.6);
        let mut ends = [[[0.0; 5]; 3]; 2];
        let (mx, my, mw) = (
            rng.range(-0.3, 0.3),
            rng.range(-0.3, 0.3),
            rng.range(0.8, 1.25),
        );
        let [e0, e1] = &mut ends;
        for (a, b) in e0.iter_mut().zip(e1.iter_mut()) {
            let (nx, ny) = (
                cx + size * rng.range(-1.0, 1.0),
                cy + size * rng.range(-1.0, 1.0),
            );
            let w = rng.range(1.0, 4.0);
            let c = if defocus { rng.range(-0.05, 0.05) } else { 0.0 };
            *a = [nx * w, ny * w, 0.5 * w, w, c];
            *b = if motion {
                let w1 = w * mw;
                [(nx + mx) * w1, (ny + my) * w1, 0.5 * w1, w1, c * 1.1]
            } else {
                *a
            };
        }
        let t = tri(ends[0], ends[1]);
        let exact = Setup::unculled::<Exact>(&t, vp);
        let bounded = Setup::unculled::<P>(&t, vp);
        let class = bounded.class();
        let (ex, ey) = (
            eps_real(shift, class.motion(), class.defocus(), 64) / 65536.0,
            eps_real(shift, class.motion(), class.defocus(), 48) / 65536.0,
        );
        let ew = if class.motion() { 0.5 / 65536.0 } else { 0.0 };
        // The analytic epsilon setup uses is the ceiling of these (checked here too).
        let e = Eps::of(Some(shift), class, vp);
        if (e.x()[0] as f64) < ex * 65536.0 || (e.x()[1] as f64) < ey * 65536.0 {
            return Err(format!("Eps::of {e:?} below the bound {ex} {ey}"));
        }
        let v0 = t.vertices(0);
        let v1 = t.vertices(1);
        for py in 0..vp.height() {
            for px in 0..vp.width() {
                for s in pat.pixel(px, py) {
                    let pos = ScreenPos::of(px, py, s);
                    let mut ops = Default::default();
                    let a =
                        uvt_core::sample::test::<Exact, Full>(&exact, pos, s, &mut ops).is_some();
                    let b = uvt_core::sample::test::<P, Full>(&bounded, pos, s, &mut ops).is_some();
                    n += 1;
                    if a == b {
                        continue;
                    }
                    diff += 1;
                    // Vertices at (t, u, v) in f64; pixel positions; per-vertex pixel radius.
                    let (tt, uu, vv) = (
                        s.t().to_num::<f64>(),
                        s.u().to_num::<f64>(),
                        s.v().to_num::<f64>(),
                    );
                    let mut pts = [(0.0, 0.0); 3];
                    let mut r = 0.0f64;
                    for k in 0..3 {
                        let f = |g: fn(&uvt_core::Vertex) -> f64| {
                            g(&v0[k]) + tt * (g(&v1[k]) - g(&v0[k]))
                        };
                        let c = f(|q| q.coc.to_num());
                        let x = f(|q| q.x.to_num()) + uu * c;
                        let y = f(|q| q.y.to_num()) + vv * c;
                        let w = f(|q| q.w.to_num());
                        pts[k] = ((x / w + 1.0) * wf / 2.0, (1.0 - y / w) * hf / 2.0);
                        let rx = (ex + (x / w).abs() * ew) / (w - ew) * wf / 2.0;
                        let ry = (ey + (y / w).abs() * ew) / (w - ew) * hf / 2.0;
                        r = r.max(rx.hypot(ry));
                    }
                    let p = (
                        px as f64 + s.sx().to_num::<f64>(),
                        py as f64 + s.sy().to_num::<f64>(),
                    );
                    let d = seg_dist(p, pts[0], pts[1])
                        .min(seg_dist(p, pts[1], pts[2]))
                        .min(seg_dist(p, pts[2], pts[0]));
                    worst = worst.max(d / r);
                    // f64 slack 1e-9 px on distances of order 1..100 px (relative error ~1e-15).
                    if d > r + 1e-9 {
                        return Err(format!(
                            "exact {a} vs bounded {b} at distance {d} px > bound {r} px\n  {}\n{}",
                            dump_sample(px, py, s),
                            dump(&t)
                        ));
                    }
                }
            }
        }
    }
    Ok((n, diff, worst))
}

/// Bounded and exact decisions differ only within the derived perturbation of an edge; the
/// coarse grid must produce disagreements (else the check proves nothing).
#[test]
fn bounded_agrees_with_exact_up_to_the_perturbation() {
    let seed = seed();
    let cases = cases(24, 400);
    let fine = agreement::<BoundedPrecision>(seed, cases);
    let coarse = agreement::<Bounded<16, 16, 16, 26>>(seed, cases);
    let (fine, coarse) = match (fine, coarse) {
        (Ok(f), Ok(c)) => (f, c),
        (Err(m), _) | (_, Err(m)) => panic!("{m}\n  rerun with UVT_SEED={seed}"),
    };
    println!("grid 2^20: {fine:?}\ngrid 2^26: {coarse:?} (samples, disagreements, max d/r)");
    assert!(
        coarse.1 > 0,
        "no disagreement at grid 2^26 (seed {seed}): the check is vacuous"
    );
}
