//! The gift-wrapped cone faces ([`wrap_faces`]) against the pair search they replace where every
//! w > 0 ([`pair_faces`]): the same faces, in the same order, with the same coefficients
//! (`HullCoeffs` equal), on the swept points of seeded random triangles of every class, on
//! point sets drawn from a small grid (many collinear and coincident points: the march's ties)
//! scaled up to the domain's corners (|x|, |y| ≤ 2^30, w ≤ 2^29), on the named degenerate sets
//! (one point, coincident points, all on one line) and on the domain corner triangles of
//! `eps_corners`. `UVT_SEED` is printed on failure; `UVT_EXTENSIVE=1` for more cases. The counts
//! at the end show the comparison is not vacuous (faces found, both-orientation lines met,
//! fallback only for w ≤ 0) and that the march costs fewer setup ops than the pair search.
// Test code: plain operators on small counters; an overflow panics (the failure signal).
#![allow(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation
)]

use uvt_testkit::{cases, seed, Rng};

use crate::bounds::hull::faces::{pair_faces, swept_points};
use crate::bounds::hull::wrap::{all_in_front, wrap_faces};
use crate::bounds::hull::{hull_faces, WRAP_FROM};
use crate::config::class::Class;
use crate::input::Viewport;
use crate::stats::Ops;
use crate::verify::hyper_reference::random_tri;

/// Tallies: [sets compared, faces, sets with both orientations of one line, wrap ops, pair ops].
#[derive(Default)]
struct Tally([u64; 5]);

/// Compare both searches on `pts` (every w > 0); `what` names the input on failure.
fn same(pts: &[[i64; 3]], vp: Viewport, what: &str, t: &mut Tally) {
    assert!(all_in_front(pts), "{what}: a point with w <= 0: {pts:?}");
    let (mut ow, mut op) = (Ops::default(), Ops::default());
    let got = wrap_faces(pts, vp, &mut ow);
    let want = pair_faces(pts, vp, &mut op);
    assert_eq!(
        got,
        Some(want),
        "{what}: gift wrapping against the pair search\npoints {pts:?} (hex {:x?})\nviewport {vp:?}",
        pts
    );
    let f = want.faces();
    t.0[0] += 1;
    t.0[1] += f.len() as u64;
    t.0[2] += u64::from(f.len() == 2 && f[0].coeffs().0 == -f[1].coeffs().0 && f[0] != f[1]);
    t.0[3] += ow.setup;
    t.0[4] += op.setup;
}

/// Every class, so every swept point count (3, 6, 12, 24).
const CLASSES: [Class; 4] = [
    Class::Static,
    Class::Motion,
    Class::Defocus,
    Class::MotionDefocus,
];

fn vps() -> [Viewport; 3] {
    [(40u16, 30u16), (2048, 2048), (1, 9)].map(|(w, h)| Viewport::new(w, h).unwrap())
}

#[test]
fn wrap_matches_the_pair_search_on_random_triangles() {
    let seed = seed();
    let mut rng = Rng(seed ^ 0x9a7f);
    let mut t = Tally::default();
    let mut behind = 0u64;
    for case in 0..cases(400, 20_000) {
        let Some(tri) = random_tri(&mut rng) else {
            continue;
        };
        let vp = vps()[case as usize % 3];
        for class in CLASSES {
            let (pts, n) = swept_points(&tri, class);
            let pts = &pts[..n];
            if !all_in_front(pts) {
                // The pair search stays the definition there.
                behind += 1;
                assert_eq!(wrap_faces(pts, vp, &mut Ops::default()), None);
                continue;
            }
            same(
                pts,
                vp,
                &format!("case {case}, {class:?}, UVT_SEED={seed}"),
                &mut t,
            );
        }
    }
    let [sets, faces, _, wrap, pair] = t.0;
    assert!(
        sets >= 800 && faces >= 3 * sets && behind > 0,
        "sets {sets}, faces {faces}, behind {behind}"
    );
    assert!(
        2 * wrap < pair,
        "wrap {wrap} ops against pair {pair} ops over {sets} sets"
    );
}

/// Points from a 7 × 7 grid of projections (x, y ∈ [−3, 3], w ∈ {1, 2}: many collinear and
/// coincident points), each coordinate scaled by `k` and w by `kw`.
fn grid_set(rng: &mut Rng, n: usize, k: i64, kw: i64) -> Vec<[i64; 3]> {
    (0..n)
        .map(|_| {
            let w = rng.int_range(1, 2);
            [
                rng.int_range(-3, 3) * w * k,
                rng.int_range(-3, 3) * w * k,
                w * kw,
            ]
        })
        .collect()
}

#[test]
fn wrap_matches_the_pair_search_on_collinear_heavy_sets() {
    let seed = seed();
    let mut rng = Rng(seed ^ 0x57a2);
    let mut t = Tally::default();
    // Scales: small; x, y up to 3·2·2^27 < 2^30 with w up to 2^29 (the domain's corner).
    let scales = [(1i64, 1i64), (1 << 27, 1), (1, 1 << 28), (1 << 27, 1 << 28)];
    for case in 0..cases(2_000, 100_000) {
        let n = 1 + rng.below(24) as usize;
        let (k, kw) = scales[case as usize % scales.len()];
        let pts = grid_set(&mut rng, n, k, kw);
        let vp = vps()[case as usize % 3];
        same(&pts, vp, &format!("case {case}, UVT_SEED={seed}"), &mut t);
    }
    let [sets, faces, lines, _, _] = t.0;
    assert!(
        faces > sets && lines > 0,
        "sets {sets}, faces {faces}, lines {lines}"
    );
}

#[test]
fn wrap_matches_the_pair_search_on_named_degenerate_sets() {
    let vp = vps()[0];
    let mut t = Tally::default();
    let p = |x: i64, y: i64, w: i64| [x, y, w];
    let sets: [(&str, Vec<[i64; 3]>); 8] = [
        ("one point", vec![p(1, 2, 3)]),
        (
            "one projection, three scales",
            vec![p(1, 2, 3), p(2, 4, 6), p(3, 6, 9)],
        ),
        ("two points", vec![p(0, 0, 1), p(1, 0, 1)]),
        (
            "a line with repeats",
            vec![p(0, 0, 1), p(2, 2, 2), p(1, 1, 1), p(0, 0, 2), p(-1, -1, 1)],
        ),
        (
            "a vertical line",
            vec![p(1, -1, 1), p(1, 5, 1), p(2, 0, 2), p(1, 3, 1)],
        ),
        ("a triangle", vec![p(0, 0, 1), p(1, 0, 1), p(0, 1, 1)]),
        (
            "a square with edge midpoints and repeats",
            vec![
                p(0, 0, 1),
                p(1, 0, 2),
                p(1, 0, 1),
                p(2, 2, 2),
                p(0, 1, 1),
                p(0, 0, 5),
                p(1, 1, 2),
                p(0, 1, 2),
            ],
        ),
        (
            "the domain's corners",
            vec![
                p(1 << 30, 1 << 30, 1 << 29),
                p(-(1 << 30), 1 << 30, 1),
                p(1 << 30, -(1 << 30), 1),
                p(-(1 << 30), -(1 << 30), 1 << 29),
                p(0, 0, 1),
            ],
        ),
    ];
    for (name, pts) in &sets {
        same(pts, vp, name, &mut t);
    }
    let faces = |pts: &[[i64; 3]]| pair_faces(pts, vp, &mut Ops::default()).faces().len();
    assert_eq!(faces(&sets[0].1), 0);
    assert_eq!(faces(&sets[1].1), 0);
    assert_eq!(faces(&sets[3].1), 2);
    assert_eq!(faces(&sets[5].1), 3);
    assert_eq!(faces(&sets[6].1), 4);
}

#[test]
fn wrap_matches_the_pair_search_at_the_domain_corners() {
    let mut t = Tally::default();
    for vp in vps() {
        for tri in crate::verify::eps_corners::tris() {
            for class in CLASSES {
                let (pts, n) = swept_points(&tri, class);
                if all_in_front(&pts[..n]) {
                    same(
                        &pts[..n],
                        vp,
                        &format!("corner triangle, {class:?}"),
                        &mut t,
                    );
                }
            }
        }
    }
    assert!(t.0[0] >= 6, "only {} corner sets", t.0[0]);
}
/// The rule of [`hull_faces`]: gift wrapping from [`WRAP_FROM`] points on, because there it
/// costs fewer setup ops than the pair search on average over random triangles, and the pair
/// search below (per class: 3, 6, 12, 24 points). Fails when the counts move across the rule.
#[test]
fn wrap_is_used_where_it_costs_fewer_ops() {
    let seed = seed();
    let mut rng = Rng(seed ^ 0x31c5);
    let mut acc = [[0u64; 3]; 4];
    for _ in 0..cases(1_000, 20_000) {
        let Some(tri) = random_tri(&mut rng) else {
            continue;
        };
        for (a, class) in acc.iter_mut().zip(CLASSES) {
            let (pts, n) = swept_points(&tri, class);
            let pts = &pts[..n];
            if !all_in_front(pts) {
                continue;
            }
            let (mut ow, mut op, mut oh) = (Ops::default(), Ops::default(), Ops::default());
            wrap_faces(pts, vps()[0], &mut ow);
            pair_faces(pts, vps()[0], &mut op);
            hull_faces(pts, vps()[0], &mut oh);
            let chosen = if n >= WRAP_FROM { ow.setup } else { op.setup };
            assert_eq!(
                oh.setup, chosen,
                "{class:?}: hull_faces counts its choice's ops"
            );
            a[0] += 1;
            a[1] += ow.setup;
            a[2] += op.setup;
        }
    }
    for (a, class) in acc.iter().zip(CLASSES) {
        let n = swept_points(&crate::verify::eps_corners::tris()[0], class).1;
        let (wrap, pair) = (a[1] / a[0].max(1), a[2] / a[0].max(1));
        assert!(a[0] >= 100, "{class:?}: {} sets", a[0]);
        assert_eq!(
            n >= WRAP_FROM,
            wrap < pair,
            "{class:?} ({n} points): wrap {wrap} ops, pair search {pair} ops per setup \
             (UVT_SEED={seed})"
        );
    }
}
