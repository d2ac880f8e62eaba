//! The quantization check of `uvt_host::compare` (issue 9 item 5): its per-sample edge-function
//! bound contains every admissible input rounding, for every geometry including w ≤ 0 vertices
//! and camera-plane crossings; it catches a wrong core where the old pixel bound was infinite;
//! and at a narrow precision the differences behind the camera are explained, but not by a bound
//! scaled down 16×.

use uvt_core::{DefaultPrecision, Prec, Precision, Triangle, Viewport};
use uvt_host::compare::bound::check_sample;
use uvt_host::compare::pass::{compare, Comparison, Spec};
use uvt_host::config::rounding::Rounding;
use uvt_host::reference::sample::{direction, positions};
use uvt_host::scene::file::Scene;
use uvt_host::scene::pattern::Pattern;
use uvt_host::scene::tri::SceneTri;
use uvt_tests::*;

/// The comparison's decisions at precision `P` and rounding `r`.
fn decisions<P: Precision + Sync>(
    tris: &[SceneTri],
    core: &[Triangle],
    vp: Viewport,
    pat: &Pattern,
    r: Rounding,
) -> Comparison {
    compare::<P, _>(tris, core, vp, pat, &Spec::decisions(r))
}

fn stress(name: &str) -> Scene {
    let dir = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../host/stress");
    Scene::load(&dir.join(format!("{name}.json"))).expect("stress scene loads")
}

/// The stress scenes with a vertex at w ≤ 0 during the shutter.
const BEHIND: [&str; 3] = [
    "crossing_camera_plane",
    "vertex_w0_at_t0",
    "all_behind_camera",
];

/// Every rounding the core's inputs may carry (each clip value and CoC end by ≤ pos, t/u/v by
/// ≤ tuv with |u'|, |v'| ≤ 1 and t' in [0, 1], the sample floored by < sub) moves E_0, E_1, E_2
/// and det by no more than the check's bounds. Corners of the rounding box and random points.
#[test]
fn bound_contains_every_admissible_rounding() {
    let seed = seed();
    let mut rng = Rng(seed ^ 0x9c);
    let mut r = Rng(seed);
    let vp = (61u16, 37u16);
    let mut worst: f64 = 0.0;
    for case in 0..cases(4000, 80_000) {
        let kind = case % 6;
        let tri = uvt_host::scene::builtin::random_tri(&mut rng, kind);
        let rd = match case % 3 {
            0 => Rounding::at(16, 16),
            1 => Rounding::at(8, 8),
            _ => Rounding::at(6, 12),
        };
        let (x, y) = (r.unit() * vp.0 as f64, r.unit() * vp.1 as f64);
        let (u, v, t) = (2.0 * r.unit() - 1.0, 2.0 * r.unit() - 1.0, r.unit());
        let c = check_sample(&tri, vp, x, y, u, v, t, &rd);
        for trial in 0..8 {
            // Trials 0..4: corners (every error at ±its limit); 4..8: uniform inside the box.
            let mut e = |lim: f64| {
                if trial < 4 {
                    if r.unit() < 0.5 {
                        -lim
                    } else {
                        lim
                    }
                } else {
                    (2.0 * r.unit() - 1.0) * lim
                }
            };
            let mut q = tri;
            for vtx in q.t0.iter_mut().chain(q.t1.iter_mut()) {
                for f in [0, 1, 3, 4] {
                    vtx[f] += e(rd.pos);
                }
            }
            let tq = (t + e(rd.tuv)).clamp(0.0, 1.0);
            let uq = (u + e(rd.tuv)).clamp(-1.0, 1.0);
            let vq = (v + e(rd.tuv)).clamp(-1.0, 1.0);
            let xq = x - (e(rd.sub).abs()).min(x);
            let yq = y - (e(rd.sub).abs()).min(y);
            let (p, _) = positions(&q, tq, uq, vq);
            let d = direction(vp, xq, yq);
            let mut got = [0.0; 4];
            for k in 0..3 {
                got[k] = p[(k + 1) % 3].cross(p[(k + 2) % 3]).dot(d);
            }
            got[3] = p[0].dot(p[1].cross(p[2]));
            for (k, g) in got.iter().enumerate() {
                let moved = (g - c.values[k]).abs();
                worst = worst.max(moved / c.bounds[k]);
                assert!(
                    moved <= c.bounds[k],
                    "value {k} moved {moved:e} > bound {:e} (exact {:e}, rounded {:e}; hex {:#x} {:#x})\n\
                     triangle {tri:?}\nrounded {q:?}\nsample x {x} y {y} u {u} v {v} t {t} -> \
                     {xq} {yq} {uq} {vq} {tq}, rounding {rd:?}, seed {seed}",
                    c.bounds[k],
                    c.values[k],
                    g,
                    moved.to_bits(),
                    c.bounds[k].to_bits()
                );
            }
        }
    }
    println!("largest |rounded − exact| / bound: {worst:.3}");
}

/// Hand-picked: a unit right triangle at w = 1 on a 2×2 viewport, sample at the screen centre
/// (NDC origin, d = (0, 0, 1)), no motion, no lens: edge values and det are exact small numbers.
#[test]
fn hand_picked_values() {
    let v = |x: f64, y: f64| [x, y, 0.0, 1.0, 0.0];
    let tri = SceneTri {
        t0: [v(-0.5, -0.5), v(0.5, -0.5), v(-0.5, 0.5)],
        t1: [v(-0.5, -0.5), v(0.5, -0.5), v(-0.5, 0.5)],
        color: [255, 255, 255],
    };
    let c = check_sample(&tri, (2, 2), 1.0, 1.0, 0.0, 0.0, 0.0, &Rounding::at(16, 16));
    // E_0 = [d p1 p2] = det[(0,0,1),(0.5,−0.5,1),(−0.5,0.5,1)] = 0.25 − 0.25 = 0; E_1 =
    // det[(0,0,1),(−0.5,0.5,1),(−0.5,−0.5,1)] = 0.5; E_2 = det[(0,0,1),(−0.5,−0.5,1),(0.5,−0.5,1)]
    // = 0.5; det = [p0 p1 p2] = E_0 + E_1 + E_2 at w = 1 = 1.
    assert_eq!(c.values, [0.0, 0.5, 0.5, 1.0], "{c:?}");
    assert_eq!(c.which, 0);
    assert_eq!(c.ratio, 0.0);
    // Static, in focus: only the 2^-17 vertex rounding and the sub-pixel floor contribute.
    // δ_k = √(2·(2·2^-17)² + (2^-17)²) = 3·2^-17; ‖Δd‖ = (2/256)·√(1/4 + 1/4); the bound of E_0
    // is ‖Δd‖‖p1'‖‖p2'‖ + ‖d‖δ(‖p2‖ + δ) + ‖d‖‖p1‖δ (+ round-off term).
    let dl = 3.0 * 2f64.powi(-17);
    let n = 1.5f64.sqrt();
    let dd = (2.0 / 256.0) * 0.5f64.sqrt();
    let b0 = dd * (n + dl) * (n + dl) + dl * (n + dl) + n * dl;
    let f = 2f64.powi(-40) * 3.0 * 144.0; // Σm = 3 vertices × 2 ends × (|x| + |y| + |w| = 2)
    assert!(
        (c.bounds[0] - (b0 + f)).abs() <= 1e-15,
        "{:e} vs {:e}",
        c.bounds[0],
        b0 + f
    );
    // In pixels: ∇E_0 = (2n_x/W, −2n_y/H) with n_0 = p1 × p2 = (−1, −1, 0): |∇| = √2.
    assert!((c.bound_px.unwrap() - c.bounds[0] / 2f64.sqrt()).abs() <= 1e-15);
    assert!(!c.behind);
}

/// A deliberately wrong core (vertex 0 shifted by 1/64 clip unit) is caught on the scenes with a
/// vertex at w ≤ 0. The old pixel bound was infinite there: on this very input the old check
/// reported 0 beyond bound (crossing_camera_plane: 95 differences up to 26.5 px; vertex_w0_at_t0:
/// 94 differences). The right core passes on the same scenes.
#[test]
fn wrong_core_is_caught_behind_the_camera() {
    for name in BEHIND {
        let s = stress(name);
        let pat = Pattern::new(s.pattern, s.spp, s.seed);
        let right = decisions::<DefaultPrecision>(
            &s.tris,
            &s.core_tris().unwrap(),
            s.core_viewport(),
            &pat,
            Rounding::default_precision(),
        );
        assert_eq!(right.beyond_bound, 0, "{name}: {right:?}");
        let mut wrong = s.clone();
        for t in wrong.tris.iter_mut() {
            t.t0[0][0] += 1.0 / 64.0;
            t.t1[0][0] += 1.0 / 64.0;
        }
        let d = decisions::<DefaultPrecision>(
            &s.tris,
            &wrong.core_tris().unwrap(),
            s.core_viewport(),
            &pat,
            Rounding::default_precision(),
        );
        println!("{name}: right {right:?}\n  wrong {d:?}");
        if name == "all_behind_camera" {
            assert_eq!(d.fixed_only + d.f64_only, 0, "nothing visible: {d:?}");
            continue;
        }
        assert!(
            d.behind > 0,
            "{name}: no difference on a w ≤ 0 triangle: {d:?}"
        );
        assert!(d.beyond_bound > 0, "{name}: wrong core not caught: {d:?}");
    }
}

fn narrow(name: &str, scale: f64) -> Comparison {
    type P = Prec<8, 8, 4>;
    let s = stress(name);
    let pat = Pattern::new(s.pattern, s.spp, s.seed).with_tuv(8);
    let core: Vec<_> = s
        .tris
        .iter()
        .map(|t| t.to_core_with::<P>().unwrap())
        .collect();
    let r = Rounding::at(8, 8);
    let r = Rounding {
        pos: r.pos * scale,
        tuv: r.tuv * scale,
        sub: r.sub * scale,
    };
    decisions::<P>(&s.tris, &core, s.core_viewport(), &pat, r)
}

/// At 8 position and 8 t/u/v bits the w ≤ 0 scenes differ from f64, behind the camera too; every
/// difference is explained by the derived bound, and a bound scaled down 16× would not explain
/// them (the check has teeth on exactly the cases the old one exempted).
#[test]
fn narrow_precision_behind_the_camera_is_explained() {
    let (mut all, mut small) = (Comparison::default(), 0);
    for name in BEHIND {
        let d = narrow(name, 1.0);
        println!("{name} at 8/8: {d:?}");
        assert_eq!(d.beyond_bound, 0, "{name}: {d:?}");
        assert!(d.max_ratio <= 1.0, "{name}: {d:?}");
        all.behind += d.behind;
        all.max_ratio = all.max_ratio.max(d.max_ratio);
        small += narrow(name, 1.0 / 16.0).beyond_bound;
    }
    assert!(all.behind > 0, "no difference behind the camera: {all:?}");
    assert!(
        small > 0,
        "a 16× smaller bound still explains every difference (max ratio {})",
        all.max_ratio
    );
}
