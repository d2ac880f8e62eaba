//! Tests of setup's and the bounds' narrow fast paths against the computations they replaced:
//! the one-pass separating-line test against the pairwise one ([`crosses_camera_plane`]), the
//! one-division-per-side lens-corner boxes against projecting every corner, and the i64
//! dual-space lines at the domain's corners against i128. Domain corners (±2^29 coordinates and
//! CoC, ε_x = 2^24, ε_w = 1, w = 0 and ±1, a 2048×2048 viewport, 16 bound bits) plus seeded
//! random cases (`UVT_SEED`, printed on failure; `UVT_EXTENSIVE=1` for more), with overflow
//! checks on. Every output must be **identical** to the old computation's.
// Test code: the reference computations use plain i128 operators on values ≤ 2^100; an overflow
// or a bad index panics, which is the failure signal of a test.
#![allow(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_possible_wrap
)]

use crate::arith::interval::solve_le;
use crate::bounds::laine::{dual_t, DualAxis};
use crate::config::formats::PixelCoord;
use crate::input::{Triangle, Vertex, C, W, X, Y};
use crate::setup::boxes::{corner_boxes, crosses_camera_plane, hull_meets_ray, project, AxisBoxes};
use crate::stats::Ops;
use uvt_testkit::{cases, seed, Rng};

const LIM: i32 = 1 << 29;

#[test]
fn hull_meets_ray_matches_pairwise() {
    let seed = seed();
    let mut rng = Rng(seed ^ 0x4011);
    let big = [
        -(1i64 << 31) + 1,
        -(1 << 30),
        -LIM as i64,
        -1,
        0,
        1,
        LIM as i64 + 1,
        (1 << 31) - 1,
    ];
    let mut checked = [0u32; 2];
    for case in 0..cases(200_000, 5_000_000) {
        let n = 1 + (rng.next_u64() % 12) as usize;
        // Small coordinates make the degenerate configurations (collinear, opposite, on the
        // line, the origin) common; the large ones drive the products to their extremes.
        let small = case % 2 == 0;
        let pts: Vec<(i32, i32)> = (0..n)
            .map(|_| {
                let r = rng.next_u64();
                if small {
                    ((r % 7) as i32 - 3, ((r >> 8) % 5) as i32 - 2)
                } else {
                    (
                        big[(r % 8) as usize] as i32 - ((r >> 8) % 3) as i32 * (r % 8 > 4) as i32,
                        [
                            -LIM - 1,
                            -LIM,
                            -1,
                            0,
                            1,
                            LIM,
                            LIM + 1,
                            ((r >> 20) % 1000) as i32 - 500,
                        ][((r >> 16) % 8) as usize],
                    )
                }
            })
            .collect();
        let wide: Vec<(i64, i64)> = pts.iter().map(|&(a, w)| (a.into(), w.into())).collect();
        for positive in [false, true] {
            let want =
                crosses_camera_plane(&wide, if positive { 1 } else { -1 }, &mut Ops::default());
            let got = hull_meets_ray(&pts, positive, &mut Ops::default());
            assert_eq!(
                got, want,
                "points {pts:?} dir {positive}: one-pass {got}, pairwise {want}; UVT_SEED={seed}"
            );
            checked[usize::from(want)] += 1;
        }
    }
    // Both answers must be exercised, or the comparison proves little.
    assert!(
        checked[0] > 1000 && checked[1] > 1000,
        "answers {checked:?}"
    );
}

/// The old box code: every front corner projected, min of the floors / max of the ceilings,
/// with the pairwise separating-line test.
fn boxes_per_corner(
    tri: &Triangle,
    axis: usize,
    extent: i64,
    bnd: u32,
    ex: i64,
    dws: &[i64],
) -> AxisBoxes {
    let coord = |p: &[i32; 5]| {
        if axis == 0 {
            (i64::from(p[X]), i64::from(p[C]))
        } else {
            (-i64::from(p[Y]), -i64::from(p[C]))
        }
    };
    let (mut left, mut right) = (Vec::new(), Vec::new());
    for p in tri.v.iter().flatten() {
        let (a, cs) = coord(p);
        for &dw in dws {
            left.push((a - cs.abs() - ex, i64::from(p[W]) + dw));
            right.push((a + cs.abs() + ex, i64::from(p[W]) + dw));
        }
    }
    let ulo = crosses_camera_plane(&left, -1, &mut Ops::default());
    let uhi = crosses_camera_plane(&right, 1, &mut Ops::default());
    let mut lo = [PixelCoord::MAX; 2];
    let mut hi = [PixelCoord::MIN; 2];
    let mut any = false;
    for p in tri.v.iter().flatten() {
        let (a, cs) = coord(p);
        for &dw in dws {
            let w = i64::from(p[W]) + dw;
            if w <= 0 {
                continue;
            }
            any = true;
            for (k, lens) in [-1i64, 1].into_iter().enumerate() {
                let au = a + lens * cs;
                lo[k] = lo[k].min(project(au - ex, w, extent, false, bnd));
                hi[k] = hi[k].max(project(au + ex, w, extent, true, bnd));
            }
        }
    }
    AxisBoxes {
        lo: (!ulo && any).then_some(lo),
        hi: (!uhi && any).then_some(hi),
    }
}

#[test]
fn boxes_match_per_corner_projection() {
    let seed = seed();
    let mut rng = Rng(seed ^ 0xb0c5);
    let pick = [-LIM, -LIM + 1, -(1 << 16), -1, 0, 1, 1 << 16, LIM - 1, LIM];
    let mut bounded_sides = 0u32;
    for case in 0..cases(3_000, 100_000) {
        let field = |rng: &mut Rng, w: bool| -> i32 {
            let r = rng.next_u64();
            match r % 4 {
                0 => pick[((r >> 8) % 9) as usize],
                1 if w => ((r >> 8) % 5) as i32 - 2,
                _ => rng.signed(if case % 3 == 0 { 1 << 18 } else { LIM as i64 }) as i32,
            }
        };
        let mut end = || {
            [0; 3].map(|_| {
                let mut v = [0i32; 5];
                for (f, x) in v.iter_mut().enumerate() {
                    *x = field(&mut rng, f == W);
                }
                Vertex::from_bits(v)
            })
        };
        let (t0, t1) = (end(), end());
        let Ok(tri) = Triangle::new(t0, t1) else {
            continue;
        };
        for axis in 0..2 {
            for (extent, bnd) in [(2048i64, 16u32), (960, 16), (1, 0), (540, 8)] {
                for ex in [0i32, 1, 11, 1 << 24] {
                    let one =
                        corner_boxes::<1, 6>(&tri, axis, extent, bnd, ex, [0], &mut Ops::default());
                    let want1 = boxes_per_corner(&tri, axis, extent, bnd, ex.into(), &[0]);
                    assert_eq!(
                        one, want1,
                        "axis {axis} E {extent} bnd {bnd} ε {ex} (N=1) {tri:?}; UVT_SEED={seed}"
                    );
                    let two = corner_boxes::<2, 12>(
                        &tri,
                        axis,
                        extent,
                        bnd,
                        ex,
                        [-1, 1],
                        &mut Ops::default(),
                    );
                    let want2 = boxes_per_corner(&tri, axis, extent, bnd, ex.into(), &[-1, 1]);
                    assert_eq!(
                        two, want2,
                        "axis {axis} E {extent} bnd {bnd} ε {ex} (N=2) {tri:?}; UVT_SEED={seed}"
                    );
                    bounded_sides += u32::from(want2.lo.is_some()) + u32::from(want2.hi.is_some());
                }
            }
        }
    }
    assert!(
        bounded_sides > 1000,
        "only {bounded_sides} finite box sides compared"
    );
}

#[test]
fn dual_t_at_the_domain_corners() {
    // |δ| up to 2^44 − 1 at every footprint end and tile edge in 0..=65535, against the same
    // lines in i128.
    let m = (1i64 << 44) - 1;
    let vals = [-m, -m + 1, -1, 0, 1, m - 1, m];
    let mut rng = Rng(seed() ^ 0xd0a1);
    for _ in 0..cases(20_000, 1_000_000) {
        let mut pick = || vals[(rng.next_u64() % 7) as usize];
        let lo = [[pick(), pick()], [pick(), pick()]];
        let hi = [[pick(), pick()], [pick(), pick()]];
        for (xa, xb) in [(0i64, 65535i64), (0, 2048), (7, 9), (0, 1)] {
            let d = DualAxis {
                xi: [xa, xb],
                lo,
                hi,
            };
            for (x0, x1) in [(xa, xb), (xa, xa), (xb, xb), (xa + 1, xb)] {
                let line = |v: &[i64; 2], x: i64| {
                    i128::from(v[0]) * i128::from(xb - x) + i128::from(v[1]) * i128::from(x - xa)
                };
                let [l0, l1] = lo.map(|v| line(&v, x0).min(line(&v, x1)));
                let [h0, h1] = hi.map(|v| line(&v, x0).max(line(&v, x1)));
                let want = solve_le(l1 - l0, -l0).and_then(|a| a.meet(solve_le(h0 - h1, h0)?));
                let got = dual_t(&d, x0, x1, &mut Ops::default());
                assert_eq!(got, want, "{d:?} x0={x0} x1={x1}");
            }
        }
    }
}

#[test]
fn projection_and_pixel_floor_at_the_widest_corners() {
    // The bounded corners reach |a| < 2^30 + 2^25 and w = 2^29 + 1; E = 2048, bnd 0..=16: the
    // i64 projection against the i128 quotient, and the pixel floor (a right shift) against
    // the floor division.
    let amax = (1i64 << 31) - 1;
    for a in [
        -amax,
        -(1 << 30) - (1 << 25),
        -1,
        0,
        1,
        (1 << 30) + (1 << 25),
        amax,
    ] {
        for w in [1i64, 2, 3, (1 << 29) + 1] {
            for bnd in [0u32, 1, 8, 15, 16] {
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
    // w ≤ 0 is refused with the outward limit, not a panic.
    assert_eq!(project(5, 0, 2048, false, 16), -(1 << 58));
    assert_eq!(project(5, -3, 2048, true, 16), 1 << 58);
    for x in [
        -(1i64 << 58),
        -(1 << 58) + 1,
        -65537,
        -65536,
        -1,
        0,
        1,
        65535,
        65536,
        (1 << 58) - 1,
        1 << 58,
    ] {
        for bnd in 0..=16u32 {
            let want = x.div_euclid(1 << bnd);
            assert_eq!(
                crate::setup::boxes::floor_px(x, bnd),
                want,
                "x={x} ({x:#x}) bnd={bnd}"
            );
        }
    }
}
