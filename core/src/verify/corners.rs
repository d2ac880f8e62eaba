//! Domain-corner tests of every place that scales a value by a power of two (the former left
//! shifts, issue 9 item 3): each drives the extreme raw inputs of the declared domain (±2^29
//! coordinates and CoC, t = 1, u, v = ±1, a 2048×2048 viewport, pixel indices up to 65535,
//! 16 bound fraction bits) and compares the result with an independent wider computation
//! (`i128` from the start, or a different formula), so a lost bit would show as a mismatch; the
//! tests run with overflow checks on, which see the multiplications that replaced the shifts.
// Test code: the independent reference computations use plain i128 operators on values far
// inside i128 (≤ 2^120), and an out-of-range index or overflow panics, which is the failure
// signal of a test.
#![allow(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation
)]

use crate::arith::interval::{solve_le, Interval, RecipConstraint};
use crate::arith::wide::Wide;
use crate::bounds::laine::{lens_s, LensAxis, LensSide};
use crate::config::class::Class;
use crate::config::formats::{Lens, SubPixel, Time, DEPTH_FAR, DEPTH_NEAR};
use crate::config::unit::Full;
use crate::input::{Sample, Triangle, Vertex, Viewport, C, W, X, Y, Z};
use crate::sample::exact;
use crate::sample::exact::{depth, positions};
use crate::sample::pos::{direction, ScreenPos};
use crate::setup::boxes::project;
use crate::setup::Setup;
use crate::stats::Ops;

const LIM: i32 = 1 << 29;
const ONE: i32 = 1 << 16;

fn vtx(b: [i32; 5]) -> Vertex {
    Vertex::from_bits(b)
}

fn smp(sx: u8, sy: u8, u: i32, v: i32, t: i32) -> Sample {
    let s = Sample::new(
        SubPixel::from_bits(sx),
        SubPixel::from_bits(sy),
        Lens::from_bits(u),
        Lens::from_bits(v),
        Time::from_bits(t),
    );
    match s {
        Ok(s) => s,
        Err(e) => panic!("corner sample out of domain: {e}"),
    }
}

/// Independent position: `((q·2^16 + T·(r − q))·2^16 + U·(c_q·2^16 + T·(c_r − c_q))` in i128,
/// reduced to the class's fraction bits (`frac` = 16, 32 or 48).
fn position_i128(q: &[i32; 5], r: &[i32; 5], s: &Sample, frac: u32) -> [i128; 4] {
    let t = i128::from(s.t().to_bits());
    let (u, v) = (i128::from(s.u().to_bits()), i128::from(s.v().to_bits()));
    let l = |f: usize| i128::from(q[f]) * 65536 + t * (i128::from(r[f]) - i128::from(q[f]));
    // 48-fraction-bit full formula, then divided down exactly for the narrower classes.
    let full = [
        l(X) * 65536 + u * l(C),
        l(Y) * 65536 + v * l(C),
        l(W) * 65536,
        l(Z) * 65536,
    ];
    let div = 2i128.pow(48 - frac);
    full.map(|x| {
        assert_eq!(x % div, 0, "class {frac} position not exact at its scale");
        x / div
    })
}

/// Extreme triangles of every class, vertices at ±2^29 moving to ∓2^29, CoC ±2^29.
fn corner_triangles() -> [(Triangle, Class); 4] {
    let a = [LIM, -LIM, LIM, LIM, -LIM];
    let b = [-LIM, LIM, -LIM, 1, LIM];
    let c = [LIM, LIM, -LIM, LIM / 2, LIM];
    let nc = |x: [i32; 5]| [x[0], x[1], x[2], x[3], 0];
    let sw = |x: [i32; 5]| [x[1], x[0], x[3], x[2], x[4]];
    let mk = |t0: [[i32; 5]; 3], t1: [[i32; 5]; 3]| match Triangle::new(t0.map(vtx), t1.map(vtx)) {
        Ok(t) => t,
        Err(e) => panic!("{e}"),
    };
    [
        (
            mk([nc(a), nc(b), nc(c)], [nc(a), nc(b), nc(c)]),
            Class::Static,
        ),
        (
            mk([nc(a), nc(b), nc(c)], [nc(sw(a)), nc(sw(b)), nc(sw(c))]),
            Class::Motion,
        ),
        (mk([a, b, c], [a, b, c]), Class::Defocus),
        (mk([a, b, c], [sw(a), sw(b), sw(c)]), Class::MotionDefocus),
    ]
}

#[test]
fn positions_at_the_domain_corners() {
    let vp = Viewport::new(2048, 2048).unwrap();
    let samples = [
        smp(0, 0, ONE, ONE, ONE),
        smp(255, 255, -ONE, -ONE, ONE),
        smp(0, 255, -ONE, ONE, 0),
        smp(255, 0, ONE, -ONE, ONE / 2),
        smp(17, 99, ONE - 1, 1 - ONE, ONE - 1),
    ];
    for (tri, class) in corner_triangles() {
        let setup = Setup::unculled::<crate::config::precision::Exact>(&tri, vp);
        assert_eq!(setup.class(), class);
        let [v0, v1] = &tri.v;
        for s in &samples {
            let (p, frac) = positions::<Full>(&setup, s, &mut Ops::default());
            for ((q, r), got) in v0.iter().zip(v1.iter()).zip(p.iter()) {
                let want = position_i128(q, r, s, frac);
                let got128 = got.map(i128::from);
                assert_eq!(
                    got128, want,
                    "class {class:?} sample {s:?}: positions {got:?} ({got:#x?}), i128 {want:?} ({want:#x?})"
                );
            }
            // The whole sample test at the corner runs without overflow, at every screen corner.
            for (px, py) in [(0, 0), (2047, 0), (0, 2047), (2047, 2047), (1024, 1023)] {
                let _ =
                    exact::eval::<Full>(&setup, ScreenPos::of(px, py, s), s, &mut Ops::default());
            }
        }
    }
}

#[test]
fn screen_position_and_direction_at_the_corners() {
    let s = smp(255, 255, 0, 0, 0);
    let p = ScreenPos::of(u16::MAX, u16::MAX, &s);
    assert_eq!((p.xs, p.ys), ((1 << 24) - 1, (1 << 24) - 1));
    let vp = Viewport::new(2048, 2048).unwrap();
    for (xs, ys) in [
        (0u32, 0u32),
        (2048 * 256 - 1, 2048 * 256 - 1),
        (u32::MAX, u32::MAX),
    ] {
        let d = direction(vp, ScreenPos { xs, ys });
        let (w, h) = (2048i128, 2048i128);
        let want = [
            (2 * i128::from(xs) - 256 * w) * h,
            (256 * h - 2 * i128::from(ys)) * w,
            256 * w * h,
        ];
        assert_eq!(d.map(i128::from), want, "xs={xs:#x} ys={ys:#x}");
    }
}

/// `Wide` holding `m · 2^k` exactly (|m| < 2^62, k ≥ 62), built from products that fit.
fn wide_pow(m: i64, k: u32) -> Wide {
    let mut w = Wide::ZERO;
    // m·2^k = (m·2^(k−62)) · 2^62 with the first factor < 2^127 for k ≤ 126.
    w.mul_add(i128::from(m) * 2i128.pow(k - 62), 1 << 62);
    w
}

#[test]
fn depth_at_the_range_corners() {
    // Edge values m_k·2^126 (bit length up to 158) keep m_k exactly after the shift to 32
    // significant bits; w, z at the 48-fraction-bit extremes ±2^62.
    let big = (1i64 << 32) - 1;
    type Case = ([i64; 3], [(i64, i64); 3], i32);
    let cases: [Case; 6] = [
        (
            [big, big, big],
            [(1 << 62, 1 << 62), (1 << 62, -(1 << 62)), (1, 1 << 62)],
            1,
        ),
        (
            [big, -big, 1],
            [
                (1 << 62, (1 << 62) - 1),
                (1 << 61, 1 << 62),
                (3, -(1 << 62)),
            ],
            1,
        ),
        (
            [-big, -big, -big],
            [(1 << 62, 1 << 60), (1 << 62, 1 << 61), (1 << 62, 1)],
            -1,
        ),
        ([1, 0, 0], [(1, 1 << 62), (0, 0), (0, 0)], 1),
        ([1, 0, 0], [(1, -(1 << 62)), (0, 0), (0, 0)], 1),
        ([big, big, 0], [(-(1 << 62), 5), (1 << 62, 7), (0, 0)], 1),
    ];
    for (m, wz, sign) in cases {
        let e = m.map(|mk| wide_pow(mk, 126));
        let got = depth(&e, &wz, sign);
        // Independent: num/den in i128 from m directly, quotient split as
        // floor(num/den)·2^24 + floor((num mod den)·2^24/den), then saturated.
        let (mut num, mut den) = (0i128, 0i128);
        for (mk, (w, z)) in m.iter().zip(wz.iter()) {
            num += i128::from(*mk) * i128::from(*z);
            den += i128::from(*mk) * i128::from(*w);
        }
        if sign < 0 {
            (num, den) = (-num, -den);
        }
        let want = if den <= 0 {
            DEPTH_FAR
        } else {
            let q = num.div_euclid(den) * (1 << 24) + num.rem_euclid(den) * (1 << 24) / den;
            q.clamp(i128::from(DEPTH_NEAR), i128::from(DEPTH_FAR)) as i32
        };
        assert_eq!(
            got, want,
            "m={m:?} wz={wz:?} sign={sign}: depth {got} ({got:#x}), independent {want} ({want:#x})"
        );
        assert_ne!(got, crate::config::formats::DEPTH_EMPTY);
    }
}

#[test]
fn projection_at_the_domain_corners() {
    // a ± |c| reaches ±2^30, w from 1 to 2^29, E = 2048, bound fraction bits 0..=16.
    for a in [
        -(2 * LIM as i64),
        -(LIM as i64),
        0,
        LIM as i64,
        2 * LIM as i64,
    ] {
        for w in [1i64, 3, LIM as i64] {
            for bnd in [0u32, 8, 16] {
                for up in [false, true] {
                    let got = project(a, w, 2048, up, bnd);
                    let num = (i128::from(a) + i128::from(w)) * 2048 * 2i128.pow(bnd);
                    let den = 2 * i128::from(w);
                    let want = if up {
                        -(-num).div_euclid(den)
                    } else {
                        num.div_euclid(den)
                    };
                    assert_eq!(
                        i128::from(got),
                        want,
                        "a={a} w={w} bnd={bnd} up={up}: {got} ({got:#x}), i128 {want} ({want:#x})"
                    );
                }
            }
        }
    }
}

#[test]
fn lens_edges_at_the_domain_corners() {
    // Tile edges up to pixel 65535 at 16 bound fraction bits (x·2^16 < 2^32), against the exact
    // solver on the same n computed in i128.
    for x in [0i64, 1, 2047, 2048, 65535] {
        for bnd in [0u32, 4, 16] {
            let xs = i128::from(x) * 2i128.pow(bnd);
            for (base, d) in [
                (0i64, 1i64 << 40),
                (-(1 << 57), 1 << 58),
                (1 << 40, -(1 << 41)),
            ] {
                let side = LensSide {
                    base,
                    c: RecipConstraint::new(d),
                };
                let lo_only = LensAxis {
                    lo: Some(side),
                    hi: None,
                };
                let hi_only = LensAxis {
                    lo: None,
                    hi: Some(side),
                };
                let got_lo = lens_s(&lo_only, 0, x, bnd, &mut Ops::default());
                let got_hi = lens_s(&hi_only, x, 0, bnd, &mut Ops::default());
                let want_lo = solve_le(i128::from(d), xs - i128::from(base));
                let want_hi = solve_le(i128::from(d), i128::from(base) - xs);
                for (got, want) in [(got_lo, want_lo), (got_hi, want_hi)] {
                    let ok = match (got, want) {
                        (None, None) => true,
                        (Some(g), Some(w)) => wider_by_at_most_one(g, w),
                        _ => false,
                    };
                    assert!(
                        ok,
                        "x={x} bnd={bnd} base={base} d={d}: {got:?} vs exact {want:?}"
                    );
                }
            }
        }
    }
}

/// `g` contains `w` and each end differs by at most one LSB (the reciprocal's outward rounding).
fn wider_by_at_most_one(g: Interval, w: Interval) -> bool {
    g.lo() <= w.lo() && g.hi() >= w.hi() && w.lo() - g.lo() <= 1 && g.hi() - w.hi() <= 1
}

#[test]
fn wide_shift_at_the_corners() {
    // Values that fit i128: shr_floor(s) equals the arithmetic shift of the i128, for every s.
    for v in [
        i128::MAX >> 1,
        -(i128::MAX >> 1),
        (1i128 << 119) + 12345,
        -(1i128 << 119) - 1,
        -1,
        1,
    ] {
        let w = Wide::from_i128(v);
        for s in 0..=191u32 {
            let want = v >> s.min(127);
            assert_eq!(w.shr_floor(s), Some(want), "v={v:#x} s={s}");
        }
    }
    // m·2^126 (beyond i128): exact quotient where it fits, None (not wrapped bits) where not.
    for m in [(1i64 << 32) - 1, -(1i64 << 32), 1, -1] {
        let w = wide_pow(m, 126);
        for s in 0..=191u32 {
            let exact = if s >= 126 {
                Some(i128::from(m) >> (s - 126).min(127))
            } else {
                2i128
                    .checked_pow(126 - s)
                    .and_then(|p| i128::from(m).checked_mul(p))
            };
            assert_eq!(w.shr_floor(s), exact, "m={m} s={s}");
        }
    }
}
