//! Domain-corner test of the planar static test (`planar.rs`): static triangles whose raw
//! coordinates are taken from the domain's corners (±2^29, ±(2^29 − 1), ±1, 0, CoC 0), slivers
//! (two vertices one raw unit apart, collinear up to one unit) and huge triangles, on 1×1,
//! 1×2048, 2048×1 and 2048×2048 viewports, every screen corner and seeded positions — with
//! overflow checks on (the test profile): no panic, every declared range asserted (|n'| ≤ 2^30,
//! sh ≤ 30, ε ≤ `PLANAR_EPS_LIMIT`, |E'| < 2^62, depth in [DEPTH_NEAR, DEPTH_FAR]), the
//! epsilon checked against an independent exact i128 inequality per vertex and component, and
//! coverage against the exact test on Q in 192-bit arithmetic.
// Test code: plain i128 operators on values < 2^125; an overflow or a bad index panics, which is
// the failure signal of a test.
#![allow(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_possible_wrap
)]

use crate::formats::{PlanarPrecision, DEPTH_FAR, DEPTH_NEAR};
use crate::input::{Triangle, Vertex, Viewport};
use crate::planar::{planar_eval, PlanarEdges, PLANAR_EPS_LIMIT};
use crate::sample::{direction, ScreenPos};
use crate::setup::Setup;
use crate::stats::Ops;
use crate::testrng::{cases, seed, Rng};
use crate::wide::Wide;

const LIM: i32 = 1 << 29;
const VALUES: [i32; 9] = [-LIM, -LIM + 1, -1, 0, 1, LIM - 1, LIM, LIM / 2, -LIM / 3];

fn cross(a: [i128; 3], b: [i128; 3]) -> [i128; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Q_k = τ·(n'_{k+1} × n'_{k+2}), τ = σ·sign(det n') (module docs of `planar.rs`).
fn q_of(pl: &PlanarEdges) -> [[i128; 3]; 3] {
    let n = pl.n().map(|v| v.map(i128::from));
    let pp = [cross(n[1], n[2]), cross(n[2], n[0]), cross(n[0], n[1])];
    let detn: i128 = (0..3).map(|i| n[0][i] * pp[0][i]).sum();
    assert_ne!(detn, 0, "a visible planar setup has det(n') ≠ 0");
    let tau = i128::from(pl.sigma()) * detn.signum();
    pp.map(|v| v.map(|c| c * tau))
}

/// The exact test of `sample.rs` on Q (192-bit): covered?
fn exact_on_q(q: &[[i128; 3]; 3], d: [i64; 3]) -> bool {
    let qn = [cross(q[1], q[2]), cross(q[2], q[0]), cross(q[0], q[1])];
    let mut det = Wide::ZERO;
    for i in 0..3 {
        det.mul_add(qn[0][i], q[0][i] as i64);
    }
    let s = det.signum();
    s != 0
        && qn.iter().all(|nk| {
            let mut e = Wide::ZERO;
            for i in 0..3 {
                e.mul_add(nk[i], d[i]);
            }
            match e.signum() {
                0 => {
                    let (a, b) = if s > 0 {
                        (nk[0], nk[1])
                    } else {
                        (-nk[0], -nk[1])
                    };
                    a > 0 || (a == 0 && b > 0)
                }
                x => x == s,
            }
        })
}

/// The stored epsilon bounds |μ_k·Q_k − P_k| for the μ_k of the module docs (independent
/// exact check: an integer inequality per component).
fn check_eps(t: &Triangle, pl: &PlanarEdges, eps: [i128; 3], ctx: &str) {
    let q = q_of(pl);
    let p = t.v[0].map(|v| [v[0], v[1], v[3]].map(i128::from));
    let det: i128 = {
        let [a, b, c] = p;
        let n0 = cross(b, c);
        (0..3).map(|i| a[i] * n0[i]).sum()
    };
    let sh = pl.shifts();
    for k in 0..3 {
        let (pk, qk) = (p[k], q[k]);
        let (w, qw) = (pk[2], qk[2]);
        if w != 0 && qw != 0 && (w > 0) == (qw > 0) {
            assert_eq!(eps[2].min(0), 0);
            for c in 0..2 {
                let lhs = (qk[c] * w - pk[c] * qw).abs();
                assert!(
                    lhs <= eps[c] * qw.abs(),
                    "{ctx}: vertex {k} component {c}: |Q·w − p·Q_w| = {lhs} > ε·|Q_w| = {} (ε {})",
                    eps[c] * qw.abs(),
                    eps[c]
                );
            }
        } else {
            let s = sh[(k + 1) % 3] + sh[(k + 2) % 3];
            for c in 0..3 {
                let lhs = ((qk[c] << s) - det.abs() * pk[c]).abs();
                assert!(
                    lhs <= eps[c] * det.abs(),
                    "{ctx}: vertex {k} component {c}: |Q·2^s − |det|·p| = {lhs} > ε·|det| (ε {})",
                    eps[c]
                );
            }
        }
    }
}

fn viewports() -> [Viewport; 4] {
    [(1, 1), (1, 2048), (2048, 1), (2048, 2048)].map(|(w, h)| Viewport::new(w, h).unwrap())
}

/// One triangle on every viewport: ranges, epsilon and coverage at the screen corners and at
/// seeded positions. Returns (visible setups, covered samples).
fn check(t: &Triangle, r: &mut Rng, ctx: &str) -> (u64, u64) {
    let (mut vis, mut cov) = (0, 0);
    for vp in viewports() {
        let s = Setup::unculled_with::<PlanarPrecision>(t, vp);
        let Some(pl) = s.planar() else { continue };
        vis += 1;
        assert!(
            pl.n().iter().flatten().all(|c| c.abs() <= 1 << 30),
            "{ctx}: |n'| > 2^30"
        );
        assert!(pl.shifts().iter().all(|&x| x <= 30), "{ctx}: shift > 30");
        let e = s.eps();
        let eps = [e.x()[0], e.x()[1], e.w()];
        assert!(
            eps.iter().all(|&x| (0..=PLANAR_EPS_LIMIT).contains(&x)),
            "{ctx}: ε {eps:?} outside [0, limit]"
        );
        check_eps(t, &pl, eps.map(i128::from), ctx);
        let q = q_of(&pl);
        let (sw, sh) = (u32::from(vp.w) * 256, u32::from(vp.h) * 256);
        for k in 0..12u64 {
            let xs = match k % 3 {
                0 => 0,
                1 => sw - 1,
                _ => (r.next_u64() % u64::from(sw)) as u32,
            };
            let ys = match k / 3 {
                0 => 0,
                1 => sh - 1,
                _ => (r.next_u64() % u64::from(sh)) as u32,
            };
            let pos = ScreenPos { xs, ys };
            let ev = planar_eval(&s, pos, &mut Ops::default()).expect("inside the viewport");
            assert!(
                ev.e.iter().all(|x| x.unsigned_abs() < 1 << 62),
                "{ctx}: |E'| ≥ 2^62"
            );
            let want = exact_on_q(&q, direction(vp, pos));
            assert_eq!(
                ev.hit.is_some(),
                want,
                "{ctx}: vp {vp:?} xs {xs} ys {ys}: expected (exact on Q) {want}, observed {:?}",
                ev.hit
            );
            if let Some(h) = ev.hit {
                cov += 1;
                assert!(
                    (DEPTH_NEAR..=DEPTH_FAR).contains(&h.depth),
                    "{ctx}: depth out of range"
                );
            }
        }
    }
    (vis, cov)
}

fn mk(v: [[i32; 4]; 3]) -> Option<Triangle> {
    Triangle::new_static(v.map(|[x, y, z, w]| Vertex::from_bits([x, y, z, w, 0]))).ok()
}

#[test]
fn planar_at_the_domain_corners() {
    let seed = seed();
    let mut r = Rng(seed ^ 0xc02e);
    let (mut vis, mut cov, mut culled, mut limit) = (0u64, 0u64, 0u64, 0u64);
    let mut run = |t: Option<Triangle>, r: &mut Rng, what: &str| {
        let Some(t) = t else { return };
        let ctx = format!("{what} (UVT_SEED={seed}) {t:?}");
        let (v, c) = check(&t, r, &ctx);
        culled += u64::from(v == 0);
        // Culled with det(P) ≠ 0: det(n') = 0 or ε above the limit (reported separately).
        let p = t.v[0].map(|v| [v[0], v[1], v[3]].map(i128::from));
        let n0 = cross(p[1], p[2]);
        let det: i128 = (0..3).map(|i| p[0][i] * n0[i]).sum();
        limit += u64::from(v == 0 && det != 0);
        vis += v;
        cov += c;
    };
    // Hand-picked: the largest triangle, huge with w at both ends, slivers one raw unit thick,
    // a vertex on the camera plane, one behind it.
    let hand = [
        [
            [-LIM, -LIM, 0, LIM],
            [LIM, -LIM, 0, LIM],
            [-LIM, LIM, LIM, LIM],
        ],
        [
            [-LIM, -LIM, -LIM, LIM],
            [LIM, -LIM, LIM, 1],
            [0, LIM, 0, LIM],
        ],
        [
            [-LIM, -LIM, 0, LIM],
            [LIM, LIM, 0, LIM],
            [-LIM + 1, -LIM, 0, LIM],
        ],
        [[-LIM, -LIM, 0, LIM], [LIM, LIM - 1, 0, LIM], [0, 0, 0, LIM]],
        [[1, 0, 0, 1], [0, 1, 0, 1], [0, 0, 0, 1]],
        [[LIM, 0, 0, 0], [-LIM, -LIM, 0, LIM], [-LIM, LIM, 0, LIM]],
        [
            [LIM, LIM, LIM, -LIM],
            [-LIM, -LIM, 0, LIM],
            [LIM, -LIM, 0, LIM],
        ],
    ];
    for (i, v) in hand.into_iter().enumerate() {
        run(mk(v), &mut r, &format!("hand-picked {i}"));
    }
    for i in 0..cases(3000, 100_000) {
        let mut v = [[0i32; 4]; 3];
        for c in v.iter_mut().flatten() {
            *c = VALUES[(r.next_u64() % VALUES.len() as u64) as usize];
        }
        if i % 3 == 0 {
            // a sliver: the third vertex one raw unit off the first two's midpoint
            let m = |a: i32, b: i32| (a / 2 + b / 2).clamp(-LIM, LIM);
            v[2] = [
                m(v[0][0], v[1][0]) + 1,
                m(v[0][1], v[1][1]),
                v[0][2],
                m(v[0][3], v[1][3]),
            ];
            v[2] = v[2].map(|x| x.clamp(-LIM, LIM));
        }
        run(mk(v), &mut r, &format!("corner case {i}"));
    }
    println!("planar corners: {vis} visible setups, {cov} covered samples; {culled} triangles culled on every viewport, {limit} of them with det(P) ≠ 0 (det(n') = 0 or ε above the limit)");
    assert!(
        vis > 1000 && cov > 100,
        "too little exercised: {vis} setups, {cov} hits"
    );
}
