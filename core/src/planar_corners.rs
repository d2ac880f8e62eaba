//! Domain-corner test of the planar static test (`planar.rs`): static triangles whose raw
//! coordinates are taken from the domain's corners (±2^29, ±(2^29 − 1), ±1, 0, CoC 0), slivers
//! (a vertex one raw unit off the midpoint of the other two), w = 0 vertices and camera-plane
//! crossers, on 1×1, 1×2048, 2048×1 and 2048×2048 viewports, every screen corner and seeded
//! positions — with overflow checks on (the test profile): no panic; the rounded vertices,
//! shifts and normals equal an independent i128 computation (the shift found by search, not by
//! bit length); every declared range asserted (|P'| ≤ 2^15 − 1, s ≤ 15, |n| < 2^31, ε ≤ 2^14
//! and equal to the exact per-vertex residual, depth in [DEPTH_NEAR, DEPTH_FAR]); culled iff
//! det P' = 0; coverage equal to the exact test on P' in 192-bit arithmetic.
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
use crate::planar::planar_eval;
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

/// Nearest, ties away from zero, of `v / 2^s` (i128; independent of `planar.rs`).
fn round_away(v: i128, s: u32) -> i128 {
    if s == 0 {
        return v;
    }
    let q = (2 * v.abs() + (1 << s)) / (1 << (s + 1));
    if v < 0 {
        -q
    } else {
        q
    }
}

/// The rounded vertex `(P', s)` of (x, y, w): the least s with every |rnd| ≤ 2^15 − 1 (search).
pub(crate) fn round_vertex(p: [i128; 3]) -> ([i128; 3], u32) {
    (0..=40)
        .map(|s| (p.map(|c| round_away(c, s)), s))
        .find(|(r, _)| r.iter().all(|c| c.abs() < 1 << 15))
        .expect("some shift fits")
}

/// The exact test of `sample.rs` on the triangle `q` (192-bit): covered?
pub(crate) fn exact_on(q: &[[i128; 3]; 3], d: [i64; 3]) -> bool {
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

fn viewports() -> [Viewport; 4] {
    [(1, 1), (1, 2048), (2048, 1), (2048, 2048)].map(|(w, h)| Viewport::new(w, h).unwrap())
}

/// One triangle on every viewport: rounding, ranges, epsilon and coverage at the screen
/// corners and at seeded positions. Returns (visible setups, covered samples, culled with
/// det P' ≠ 0).
fn check(t: &Triangle, r: &mut Rng, ctx: &str) -> (u64, u64, u64) {
    let (mut vis, mut cov, mut wrong_cull) = (0, 0, 0);
    let p = t.v[0].map(|v| [v[0], v[1], v[3]].map(i128::from));
    let rv = p.map(round_vertex);
    let q = rv.map(|(v, _)| v);
    let n = [cross(q[1], q[2]), cross(q[2], q[0]), cross(q[0], q[1])];
    let det: i128 = (0..3).map(|i| q[0][i] * n[0][i]).sum();
    let mut want_eps = [0i128; 3];
    for k in 0..3 {
        for c in 0..3 {
            want_eps[c] = want_eps[c].max((p[k][c] - (q[k][c] << rv[k].1)).abs());
        }
    }
    for vp in viewports() {
        let s = Setup::unculled_with::<PlanarPrecision>(t, vp);
        let Some(pl) = s.planar() else {
            wrong_cull += u64::from(det != 0);
            continue;
        };
        vis += 1;
        assert_ne!(det, 0, "{ctx}: det P' = 0 but not culled");
        assert_eq!(
            pl.vertices().map(|v| v.map(i128::from)),
            q,
            "{ctx}: rounded vertices P'"
        );
        assert_eq!(pl.shifts(), rv.map(|(_, s)| s), "{ctx}: vertex shifts");
        assert!(pl.shifts().iter().all(|&x| x <= 15), "{ctx}: shift > 15");
        assert_eq!(pl.n().map(|v| v.map(i128::from)), n, "{ctx}: normals");
        assert!(
            n.iter().flatten().all(|c| c.abs() < 1 << 31),
            "{ctx}: |n| ≥ 2^31"
        );
        assert_eq!(pl.sigma() as i128, det.signum(), "{ctx}: σ");
        let e = s.eps();
        let eps = [e.x()[0], e.x()[1], e.w()].map(i128::from);
        assert_eq!(
            eps, want_eps,
            "{ctx}: ε is the largest residual |P − 2^s·P'|"
        );
        assert!(eps.iter().all(|&x| x <= 1 << 14), "{ctx}: ε {eps:?} > 2^14");
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
            let want = exact_on(&q, direction(vp, pos));
            assert_eq!(
                ev.hit.is_some(),
                want,
                "{ctx}: vp {vp:?} xs {xs} ys {ys}: expected (exact on P') {want}, observed {:?}",
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
    (vis, cov, wrong_cull)
}

fn mk(v: [[i32; 4]; 3]) -> Option<Triangle> {
    Triangle::new_static(v.map(|[x, y, z, w]| Vertex::from_bits([x, y, z, w, 0]))).ok()
}

#[test]
fn planar_at_the_domain_corners() {
    let seed = seed();
    let mut r = Rng(seed ^ 0xc02e);
    let (mut vis, mut cov, mut culled, mut wrong) = (0u64, 0u64, 0u64, 0u64);
    let mut run = |t: Option<Triangle>, r: &mut Rng, what: &str| {
        let Some(t) = t else { return };
        let ctx = format!("{what} (UVT_SEED={seed}) {t:?}");
        let (v, c, w) = check(&t, r, &ctx);
        culled += u64::from(v == 0);
        wrong += w;
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
        // rounding corners: m = 2^29 − 1 (rounds to 2^15: one more shift), ties at 2^14 and
        // 2^13 (away from zero), m = 2^15 − 1 and 2^15 (shift 0 and 1)
        [
            [LIM - 1, (1 << 14) + (1 << 15), 0, LIM - 1],
            [-(1 << 13) - (3 << 14), LIM - 1, 0, (1 << 28) + (1 << 13)],
            [(1 << 15) - 1, -(1 << 15), 5, 1 << 15],
        ],
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
    println!("planar corners: {vis} visible setups, {cov} covered samples; {culled} triangles culled on every viewport (det P' = 0)");
    assert_eq!(wrong, 0, "setups culled with det P' ≠ 0");
    assert!(
        vis > 1000 && cov > 100,
        "too little exercised: {vis} setups, {cov} hits"
    );
}
