//! Domain-corner tests of the bounded sample test (`bounded.rs`) and of the conservative epsilon
//! in setup and bounds: the extreme raw inputs (±2^29 coordinates and CoC moving to ∓2^29,
//! t = 1, u, v = ±1, 2048×2048 and 1×1 viewports, every screen corner, offset grids 2^20 and
//! 2^32) against an independent `i128` computation of every rounded intermediate, with overflow
//! checks on; and the declared ranges (|a'| < 2^30 at 2^20, |E'| < 2^61, ε < 2^24) asserted.
// Test code: the independent computations use plain i128 operators on values ≤ 2^100; an
// overflow or a bad index panics, which is the failure signal of a test.
#![allow(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation
)]

use crate::bounds::laine::Laine2011;
use crate::bounds::strategy::BoundsStrategy;
use crate::config::class::Class;
use crate::config::formats::{Lens, SubPixel, Time};
use crate::config::precision::{Bounded, DefaultPrecision, OFFSET_SHIFT_MAX, OFFSET_SHIFT_MIN};
use crate::config::unit::Full;
use crate::input::{PixelRect, Sample, Triangle, Vertex, Viewport, C, W, X, Y};
use crate::sample::bounded;
use crate::sample::bounded::datapath::Fast;
use crate::sample::pos::ScreenPos;
use crate::setup::eps::Eps;
use crate::setup::{setup, Outcome, Setup};
use crate::stats::Ops;

const LIM: i32 = 1 << 29;
const ONE: i32 = 1 << 16;

fn smp(sx: u8, sy: u8, u: i32, v: i32, t: i32) -> Sample {
    Sample::new(
        SubPixel::from_bits(sx),
        SubPixel::from_bits(sy),
        Lens::from_bits(u),
        Lens::from_bits(v),
        Time::from_bits(t),
    )
    .unwrap()
}

fn tris() -> [Triangle; 4] {
    let a = [LIM, -LIM, LIM, LIM, -LIM];
    let b = [-LIM, LIM, -LIM, 1, LIM];
    let c = [LIM, LIM, -LIM, LIM / 2, LIM];
    let nc = |x: [i32; 5]| [x[0], x[1], x[2], x[3], 0];
    let sw = |x: [i32; 5]| [x[1], x[0], x[3], x[2], x[4]];
    let mk = |t0: [[i32; 5]; 3], t1: [[i32; 5]; 3]| {
        Triangle::new(t0.map(Vertex::from_bits), t1.map(Vertex::from_bits)).unwrap()
    };
    [
        mk([nc(a), nc(b), nc(c)], [nc(a), nc(b), nc(c)]),
        mk([nc(a), nc(b), nc(c)], [nc(sw(a)), nc(sw(b)), nc(sw(c))]),
        mk([a, b, c], [a, b, c]),
        mk([a, b, c], [sw(a), sw(b), sw(c)]),
    ]
}

/// round(v / 2^s), ties toward +∞, in i128.
fn rnd(v: i128, s: u32) -> i128 {
    (v + (1i128 << s) / 2).div_euclid(1i128 << s)
}

#[test]
fn bounded_test_at_the_domain_corners() {
    let samples = [
        smp(0, 0, ONE, ONE, ONE),
        smp(255, 255, -ONE, -ONE, ONE),
        smp(0, 255, -ONE, ONE, 0),
        smp(255, 0, ONE, -ONE, ONE / 2),
        smp(17, 99, ONE - 1, 1 - ONE, ONE - 1),
    ];
    for (vw, vh) in [(2048u16, 2048u16), (1, 1), (2048, 1)] {
        let vp = Viewport::new(vw, vh).unwrap();
        for tri in tris() {
            let setup = Setup::unculled::<DefaultPrecision>(&tri, vp);
            let (motion, defocus) = (setup.class().motion(), setup.class().defocus());
            for s in &samples {
                let (t, u, v) = (
                    i128::from(s.t().to_bits()),
                    i128::from(s.u().to_bits()),
                    i128::from(s.v().to_bits()),
                );
                // Independent positions.
                let p = [0usize, 1, 2].map(|k| {
                    let (q, r) = (tri.v[0][k], tri.v[1][k]);
                    let f = |i: usize| {
                        let (a, b) = (i128::from(q[i]), i128::from(r[i]));
                        if motion {
                            rnd(a * 65536 + t * (b - a), 16)
                        } else {
                            a
                        }
                    };
                    let c = f(C);
                    let (lx, ly) = if defocus {
                        (rnd(u * c, 16), rnd(v * c, 16))
                    } else {
                        (0, 0)
                    };
                    (f(X) + lx, f(Y) + ly, f(W))
                });
                for (px, py) in [(0, 0), (vw - 1, 0), (0, vh - 1), (vw - 1, vh - 1)] {
                    let pos = ScreenPos::of(px, py, s);
                    let (sw, sh) = (256 * i128::from(vw), 256 * i128::from(vh));
                    let gx = 2 * i128::from(pos.xs) - sw;
                    let gy = sh - 2 * i128::from(pos.ys);
                    for shift in [OFFSET_SHIFT_MIN, 26, OFFSET_SHIFT_MAX] {
                        let ab = p.map(|(x, y, w)| {
                            (rnd(sw * x - gx * w, shift), rnd(sh * y - gy * w, shift))
                        });
                        let e = [0usize, 1, 2].map(|k| {
                            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
                            ab[i].0 * ab[j].1 - ab[j].0 * ab[i].1
                        });
                        let got =
                            bounded::eval(&setup, shift, pos, s, &mut Ops::default()).unwrap();
                        let got_ab = got.ab.map(|(a, b)| (i128::from(a), i128::from(b)));
                        assert_eq!(
                            got_ab, ab,
                            "vp {vw}x{vh} shift {shift} {s:?} px ({px},{py})"
                        );
                        assert_eq!(got.e.map(i128::from), e, "vp {vw}x{vh} shift {shift} {s:?}");
                        for (a, b) in ab {
                            assert!(a.abs() < 1 << 30 && b.abs() < 1 << 30, "offset range");
                        }
                        assert!(e.iter().all(|x| x.abs() < 1 << 61), "edge range {e:?}");
                    }
                }
                // Outside the viewport: refused, not evaluated.
                let out = ScreenPos {
                    xs: 256 * u32::from(vw),
                    ys: 0,
                };
                assert!(bounded::eval(&setup, 20, out, s, &mut Ops::default()).is_none());
                assert!(
                    bounded::eval(&setup, 19, ScreenPos::of(0, 0, s), s, &mut Ops::default())
                        .is_none()
                );
            }
        }
    }
}

/// The boundary between the fast and the general datapath (`bounded.rs`, `Fast::new`): T = 2^15
/// (motion classes), U or V = 2^16 (defocus classes) and a side W or H ≥ 2^(S−9) go to the
/// general datapath, their neighbours to the fast one. On both sides of each boundary, at every
/// screen corner, on the domain-corner triangles (lerps over |f1 − f0| = 2^30, CoC ±2^29, where
/// every scaled factor is at its extreme) and on a screen-covering triangle (hits, depth), at
/// grids 2^20, 2^21 and 2^32, every output equals the frozen contract (`bounded_frozen.rs`),
/// and each path is taken where expected. Fails, e.g., if `Fast::new` accepts T = 2^15 (its
/// time factor 2^31 overflows i32) or W = 2048 at S = 20.
#[test]
fn fast_and_general_datapaths_agree_at_their_boundary() {
    use crate::verify::bounded_frozen::frozen_eval;
    let ts = [0, 1, ONE / 2 - 1, ONE / 2, ONE / 2 + 1, ONE - 1, ONE];
    let ls = [-ONE, 1 - ONE, -1, 0, 1, ONE - 1, ONE];
    let cover = {
        let v = |x: i32, y: i32, z: i32, w: i32, c: i32| Vertex::from_bits([x, y, z, w, c]);
        Triangle::new(
            [
                v(-4 * ONE, -4 * ONE, ONE / 2, ONE, ONE / 8),
                v(4 * ONE, -4 * ONE, ONE / 4, ONE, -ONE / 8),
                v(0, 4 * ONE, ONE / 3, 2 * ONE, ONE / 16),
            ],
            [
                v(-3 * ONE, -5 * ONE, ONE / 2, ONE + 7, ONE / 7),
                v(5 * ONE, -4 * ONE, ONE / 5, ONE, -ONE / 9),
                v(ONE, 5 * ONE, ONE / 3, 2 * ONE - 3, ONE / 17),
            ],
        )
        .unwrap()
    };
    let mut all = tris().to_vec();
    all.push(cover);
    let (mut fast, mut general, mut hits) = (0u32, 0u32, 0u32);
    for (vw, vh) in [
        (2047u16, 2047u16),
        (2048, 2047),
        (2047, 2048),
        (2048, 2048),
        (1, 1),
    ] {
        let vp = Viewport::new(vw, vh).unwrap();
        for tri in &all {
            let setup = Setup::unculled::<DefaultPrecision>(tri, vp);
            let (motion, defocus) = (setup.class().motion(), setup.class().defocus());
            for &t in &ts {
                for (&u, &v) in ls.iter().zip(ls.iter().rev()) {
                    let s = smp(0, 255, u, v, t);
                    for (px, py) in [(0, 0), (vw - 1, 0), (0, vh - 1), (vw - 1, vh - 1)] {
                        let pos = ScreenPos::of(px, py, &s);
                        for shift in [OFFSET_SHIFT_MIN, 21, OFFSET_SHIFT_MAX] {
                            let mut ops = Ops::default();
                            let want = frozen_eval(&setup, shift, pos, &s, &mut ops);
                            let got = bounded::eval(&setup, shift, pos, &s, &mut ops);
                            assert_eq!(
                                got, want,
                                "vp {vw}x{vh} shift {shift} {s:?} px ({px},{py}) {tri:?}"
                            );
                            let refused = (motion && t == ONE / 2)
                                || (defocus && (u == ONE || v == ONE))
                                || u32::from(vw.max(vh)) >= 1 << (shift - 9);
                            let f = takes_fast_path(&setup, shift, pos, &s);
                            assert_eq!(f, !refused, "vp {vw}x{vh} shift {shift} {s:?}");
                            fast += u32::from(f);
                            general += u32::from(!f);
                            hits += u32::from(got.is_some_and(|e| e.hit.is_some()));
                        }
                    }
                }
            }
        }
    }
    assert!(
        fast > 1000 && general > 1000 && hits > 100,
        "{fast} {general} {hits}"
    );
}

#[test]
fn epsilon_setup_and_bounds_at_the_domain_corners() {
    for (vw, vh) in [(2048u16, 2048u16), (1, 1), (1, 2048)] {
        let vp = Viewport::new(vw, vh).unwrap();
        for tri in tris() {
            let class = Setup::unculled::<DefaultPrecision>(&tri, vp).class();
            let e = Eps::of(Some(OFFSET_SHIFT_MAX), class, vp);
            assert!(e.x().iter().all(|&x| (1..1 << 24).contains(&x)), "{e:?}");
            // Setup and Laine2011 at the widest epsilon run without overflow on every tile.
            let mut ops = Ops::default();
            if let Outcome::Visible(s) = setup::<Bounded<16, 16, 16, 32>, Full>(&tri, vp, &mut ops)
            {
                assert_eq!(s.eps(), e);
                let c = Laine2011.prepare::<Full>(&s, &mut ops);
                let fp = s.footprint();
                for (x, y) in [(fp.x0, fp.y0), (fp.x1 - 1, fp.y1 - 1)] {
                    let tile = PixelRect {
                        x0: x,
                        y0: y,
                        x1: x + 1,
                        y1: y + 1,
                    };
                    let _ = Laine2011.tile::<Full>(&s, &c, tile, &mut ops);
                }
            }
        }
    }
    // The exact configuration: zero epsilon.
    let vp = Viewport::new(7, 5).unwrap();
    for tri in tris() {
        assert!(Setup::unculled::<crate::config::precision::Exact>(&tri, vp)
            .eps()
            .is_zero());
    }
}

/// The exact path's original box code and the epsilon corner code agree at ε = 0 (one or two
/// w corners), on the domain corners and on ordinary triangles, for every bound precision.
#[test]
fn corner_boxes_at_zero_epsilon_equal_the_exact_boxes() {
    use crate::setup::boxes::{corner_boxes, exact_boxes};
    let ordinary = Triangle::new(
        [
            [-3 * ONE, -ONE, ONE, 2 * ONE, ONE / 8],
            [ONE, -2 * ONE, ONE, 3 * ONE, -ONE / 4],
            [0, 2 * ONE, ONE, ONE, 0],
        ]
        .map(Vertex::from_bits),
        [
            [-ONE, -ONE, ONE, 2 * ONE, ONE / 8],
            [2 * ONE, -ONE, ONE, -ONE, ONE / 2],
            [0, 3 * ONE, ONE, ONE, 0],
        ]
        .map(Vertex::from_bits),
    )
    .unwrap();
    let mut all = tris().to_vec();
    all.push(ordinary);
    for tri in all {
        for axis in 0..2 {
            for bnd in [0u32, 8, 16] {
                let mut ops = Ops::default();
                let e = exact_boxes(&tri, axis, 960, bnd, &mut ops);
                let one = corner_boxes::<1, 6>(&tri, axis, 960, bnd, 0, [0], &mut ops);
                let two = corner_boxes::<2, 12>(&tri, axis, 960, bnd, 0, [0, 0], &mut ops);
                assert_eq!(e, one, "axis {axis} bnd {bnd} {tri:?}");
                assert_eq!(e, two, "axis {axis} bnd {bnd} {tri:?}");
            }
        }
    }
}

/// Whether [`bounded_eval`] takes the fast datapath for these inputs (for the boundary tests;
/// inputs as [`bounded_eval`] accepts them).
#[allow(clippy::cast_possible_wrap)]
#[cfg(test)]
fn takes_fast_path(setup: &Setup, shift: u32, pos: ScreenPos, s: &Sample) -> bool {
    let (vp, xs, ys) = (setup.viewport, pos.xs as i32, pos.ys as i32);
    match setup.class {
        Class::Static => Fast::new::<false, false, false>(vp, xs, ys, s, shift).is_some(),
        Class::Motion => Fast::new::<true, false, false>(vp, xs, ys, s, shift).is_some(),
        Class::Defocus => Fast::new::<false, true, false>(vp, xs, ys, s, shift).is_some(),
        Class::MotionDefocus => Fast::new::<true, true, false>(vp, xs, ys, s, shift).is_some(),
    }
}
