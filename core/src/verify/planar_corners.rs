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

use crate::arith::wide::Wide;
use crate::config::formats::{DEPTH_FAR, DEPTH_NEAR};
use crate::config::precision::PlanarPrecision;
use crate::input::{Triangle, Vertex, Viewport};
use crate::sample::planar;
use crate::sample::pos::{direction, ScreenPos};
use crate::setup::Setup;
use crate::stats::Ops;
use uvt_testkit::{cases, seed, Rng};

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
        let s = Setup::unculled::<PlanarPrecision>(t, vp);
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
            let ev = planar::eval(&s, pos, &mut Ops::default()).expect("inside the viewport");
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

/// `floor_div_d32`'s two forms (`DIV32`: 32-bit divides; else `i64::div_euclid`) against the
/// i128 floor division at the operand corners (|z| up to 2^62 − 1, multiples of d32 and one
/// off, d32 at both ends of [2^31, 2^32)) and on seeded operands: bit for bit.
#[test]
fn div32_floor_equals_the_division_at_the_corners() {
    use crate::setup::planar::floor_div_d32;
    let seed = seed();
    let mut r = Rng(seed ^ 0xd132);
    let mut ds = vec![
        1i64 << 31,
        (1 << 31) + 1,
        (1 << 32) - 1,
        (1 << 32) - 2,
        3 << 30,
    ];
    let mut zs = vec![
        0i64,
        1,
        -1,
        (1 << 62) - 1,
        -(1 << 62) + 1,
        1 << 61,
        -(1 << 61),
    ];
    for _ in 0..cases(2000, 200_000) {
        ds.push((1 << 31) + (r.next_u64() % (1 << 31)) as i64);
        zs.push(r.signed((1 << 62) - 1));
    }
    let mut n = 0u64;
    for (i, &d) in ds.iter().enumerate() {
        // z at the quotient's ends and around multiples of d: q·d + {−1, 0, 1}.
        let q_end = ((1i128 << 62) - 1) / i128::from(d);
        let mut zi: Vec<i64> = [q_end, -q_end, 1, -1, q_end / 2, -q_end / 3]
            .iter()
            .flat_map(|&q| [-1i128, 0, 1].map(|o| q * i128::from(d) + o))
            .filter(|z| z.abs() < 1 << 62)
            .map(|z| z as i64)
            .collect();
        zi.extend(zs.iter().skip(i % 7).step_by(97).copied());
        for &z in &zi {
            let want = i128::from(z).div_euclid(i128::from(d));
            let (fast, general) = (floor_div_d32::<true>(z, d), floor_div_d32::<false>(z, d));
            assert!(
                fast.map(i128::from) == Some(want) && general == fast,
                "floor(z / d), z {z} ({z:#x}) d {d} ({d:#x}) (UVT_SEED={seed}): expected {want} \
                 ({want:#x}), observed DIV32 {fast:?}, div_euclid {general:?}"
            );
            n += 1;
        }
    }
    assert!(n > 10_000, "too few operands: {n}");
}

/// The static unit's setup form of the planar setup (`planar_setup::<true>`, the depth
/// plane's divisions in 32-bit divides) against the general one and against the frozen copy
/// (the form before it), at the domain corners (the triangles of `planar_at_the_domain_corners`)
/// and on seeded random triangles on every corner viewport and seeded ones: bit for bit.
#[test]
fn div32_setup_equals_the_general_and_frozen_setup() {
    use crate::setup::planar::planar_setup;
    use crate::verify::planar_frozen::frozen_setup;
    let seed = seed();
    let mut r = Rng(seed ^ 0x5e7d);
    let mut vis = 0u64;
    let mut check = |t: &Triangle, vp: Viewport, what: &str| {
        let a = planar_setup::<true>(t, vp, &mut Ops::default());
        let b = planar_setup::<false>(t, vp, &mut Ops::default());
        let c = frozen_setup(t, vp, &mut Ops::default());
        assert!(
            a == b && a == c,
            "{what} (UVT_SEED={seed}) {t:?} vp {vp:?}: expected (general) {b:?}\n  frozen {c:?}\n  observed (DIV32) {a:?}"
        );
        vis += u64::from(a.is_some());
    };
    for i in 0..cases(3000, 100_000) {
        let mut v = [[0i32; 4]; 3];
        for (k, p) in v.iter_mut().enumerate() {
            *p = match i % 3 {
                0 => [0; 4].map(|_| VALUES[(r.next_u64() % VALUES.len() as u64) as usize]),
                1 => [0; 4].map(|_| r.signed(i64::from(LIM)) as i32),
                _ => {
                    // In front of the camera: random NDC, w and z.
                    let w = (r.next_u64() % (LIM as u64)) as i64 + 1 + k as i64;
                    let w = w.min(i64::from(LIM));
                    let (nx, ny) = (r.signed(1 << 16), r.signed(1 << 16));
                    [(nx * w) >> 16, (ny * w) >> 16, r.signed(i64::from(LIM)), w].map(|x| x as i32)
                }
            };
        }
        let Some(t) = mk(v) else { continue };
        for vp in viewports() {
            check(&t, vp, &format!("case {i}"));
        }
        let side = |r: &mut Rng| (r.next_u64() % 2048) as u16 + 1;
        let vp = Viewport::new(side(&mut r), side(&mut r)).unwrap();
        check(&t, vp, &format!("case {i}, seeded viewport"));
    }
    assert!(vis > 1000, "too few visible setups: {vis}");
}

/// The static unit's depth without a 64-bit variable shift (`static_unit::split_floor` with the
/// `(sh, m)` that `depth_split` chooses) against `⌊acc / 2^f⌋` for every f ∈ [1, 63] at the
/// corners of the depth range (quotients DEPTH_NEAR, DEPTH_FAR, 0, −1, 1 and seeded, remainders
/// 0, 1, 2^f − 1 and seeded; |acc| < 2^63): bit for bit. And `depth_split`'s decision (two
/// extremes of the affine sum) against the four corner positions' quotients (the form before
/// it) on seeded planes and viewports.
#[test]
fn static_depth_split_equals_the_shift() {
    use crate::units::static_only::sample::split_floor;
    use crate::units::static_only::setup::depth_split;
    let seed = seed();
    let mut r = Rng(seed ^ 0xde97);
    let mut n = 0u64;
    for f in 1..=63i32 {
        let mut qs = vec![
            DEPTH_NEAR,
            DEPTH_NEAR + 1,
            -1,
            0,
            1,
            DEPTH_FAR - 1,
            DEPTH_FAR,
        ];
        let mut rems = vec![0i128, 1, (1i128 << f) - 1, (1i128 << f) - 2];
        for _ in 0..cases(20, 2000) {
            qs.push(r.next_u64() as i32);
            rems.push(i128::from(r.next_u64()) % (1i128 << f));
        }
        for &q in &qs {
            for &rem in &rems {
                let acc = (i128::from(q) << f) + rem.max(0);
                let Ok(acc) = i64::try_from(acc) else {
                    continue;
                };
                // A plane whose sum is acc at every position: G_0 = G_1 = 0, gw = acc.
                let (sh, m) = depth_split([0, 0, 1], f, acc, [-1, 1], [-1, 1]);
                let want = (acc >> f) as i32;
                let fast = (DEPTH_NEAR..=DEPTH_FAR).contains(&want);
                assert_eq!(sh < 32, fast, "f {f} acc {acc} ({acc:#x}): split {sh} {m}");
                if !fast {
                    continue;
                }
                let got = split_floor(acc, sh, m);
                assert_eq!(
                    got, want,
                    "f {f} acc {acc} ({acc:#x}) (UVT_SEED={seed}) sh {sh} m {m}: expected \
                     {want} ({want:#x}), observed {got} ({got:#x})"
                );
                n += 1;
            }
        }
    }
    // The decision against the four corners (the form before it).
    let mut fast_n = 0u64;
    for i in 0..cases(20_000, 1_000_000) {
        let g = [0; 3].map(|_| r.signed(1 << 31).clamp(-(1 << 31), (1 << 31) - 1) as i32);
        let f = (r.next_u64() % 70) as i32 - 3;
        let side = |r: &mut Rng| match r.next_u64() % 3 {
            0 => 2048i64,
            1 => 1,
            _ => (r.next_u64() % 2048) as i64 + 1,
        };
        let (w, h) = (side(&mut r), side(&mut r));
        let wh = 256 * w * h;
        // gw near a value that makes the plane's depth land in range for some f.
        let gw = match i % 2 {
            0 => i64::from(g[2]) * wh,
            _ => r.signed(1 << 61),
        };
        let (dx, dy) = (
            [-wh, wh - 2 * h].map(|x| x as i32),
            [-wh + 2 * w, wh].map(|x| x as i32),
        );
        let old = (0..=63).contains(&f) && f >= 1 && {
            let corners = [
                (dx[0], dy[0]),
                (dx[1], dy[0]),
                (dx[0], dy[1]),
                (dx[1], dy[1]),
            ];
            corners.iter().all(|&(x, y)| {
                let q = (i128::from(gw)
                    + i128::from(g[0]) * i128::from(x)
                    + i128::from(g[1]) * i128::from(y))
                    >> f;
                (i128::from(DEPTH_NEAR)..=i128::from(DEPTH_FAR)).contains(&q)
            })
        };
        let (sh, _) = depth_split(g, f, gw, dx, dy);
        assert_eq!(
            sh < 32,
            old,
            "case {i} (UVT_SEED={seed}): g {g:?} f {f} gw {gw} vp {w}x{h}: expected fast {old}"
        );
        fast_n += u64::from(old);
    }
    assert!(
        n > 2000 && fast_n > 100,
        "too little exercised: {n} splits, {fast_n} fast planes"
    );
}
