//! [`HullTiles`] (faces folded to one corner each, useless faces dropped, greedy order) against
//! the direct per-face test it replaced ([`face_culls`] on every face): the culling decision
//! must be **identical** for every bounds tile 1, 2, 4, 8 of the footprint (clipped like the
//! renderer's), on seeded random triangles of every class (`UVT_SEED`, printed on failure;
//! `UVT_EXTENSIVE=1` for more) with the exact and a bounded test, and on the domain corner
//! triangles of `eps_corners` along the footprint's edge rows and columns. It also checks that
//! faces are dropped and tiles culled, so the comparison is not vacuous. Where a triangle keeps
//! [`KEPT_FACES`] faces (the cap may have dropped more) the per-tile form must cull a subset of
//! the direct test's tiles; a synthetic cone with more candidate faces than the cap shows the
//! cap dropping faces and staying conservative.
// Test code: plain operators on small counters; an overflow panics (the failure signal).
#![allow(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation
)]

use uvt_testkit::{cases, seed, Rng};

use crate::bounds::hull::faces::{eps_margin, face_culls, swept_points, HullCoeffs};
use crate::bounds::hull::hull_faces;
use crate::bounds::hull::tiles::{HullTiles, KEPT_FACES};
use crate::config::precision::{Bounded, Exact, Precision};
use crate::config::unit::Full;
use crate::input::{PixelRect, Triangle, Viewport};
use crate::setup::{setup, Outcome, Setup};
use crate::stats::Ops;
use crate::verify::hyper_reference::random_tri;

/// The faces exactly as `HullCull::prepare` builds them before the per-tile form.
fn faces(s: &Setup) -> HullCoeffs {
    let (pts, n) = swept_points(&s.tri, s.class);
    let pts = &pts[..n];
    let mut ops = Ops::default();
    if s.eps.is_zero() {
        hull_faces(pts, s.viewport, &mut ops)
    } else {
        match eps_margin(pts, &s.eps, s.viewport, &mut ops) {
            Some(rho) => hull_faces(pts, s.viewport, &mut ops).widened(rho, &mut ops),
            None => HullCoeffs::EMPTY,
        }
    }
}

/// Counts: [setups, faces before, faces kept, tiles, tiles culled].
fn check(s: &Setup, tiles: impl Iterator<Item = PixelRect>, what: &str, n: &mut [u64; 5]) {
    let hull = faces(s);
    let t = HullTiles::of(&hull, s.footprint, &mut Ops::default());
    n[0] += 1;
    n[1] += hull.faces().len() as u64;
    n[2] += t.faces().len() as u64;
    for tile in tiles {
        let want = hull
            .faces()
            .iter()
            .any(|f| face_culls(f, tile, &mut Ops::default()));
        let got = t.culls(tile, &mut Ops::default());
        // Fewer than the cap: nothing was dropped by it, the decisions are identical; at the
        // cap the per-tile form may cull less, never more.
        let ok = if t.faces().len() < KEPT_FACES {
            got == want
        } else {
            !got || want
        };
        assert!(
            ok,
            "{what}: tile {tile:?} of footprint {:?}: per-tile form culls {got}, direct {want}\n\
             faces {:?}\nkept {:?}\ntriangle {:?}",
            s.footprint,
            hull.faces(),
            t.faces(),
            s.tri
        );
        n[3] += 1;
        n[4] += u64::from(want);
    }
}

fn visible<P: Precision>(tri: &Triangle, vp: Viewport) -> Option<Setup> {
    match setup::<P, Full>(tri, vp, &mut Ops::default()) {
        Outcome::Visible(s) => Some(s),
        _ => None,
    }
}

/// The four classes of one random triangle: as drawn, without CoC, without motion, neither.
fn classes(tri: &Triangle) -> [Option<Triangle>; 4] {
    let [a, b] = tri.v;
    let flat = |e: [[i32; 5]; 3]| {
        e.map(|mut p| {
            p[4] = 0;
            p
        })
    };
    let mk = |p: [[i32; 5]; 3], q: [[i32; 5]; 3]| {
        Triangle::new(
            p.map(crate::input::Vertex::from_bits),
            q.map(crate::input::Vertex::from_bits),
        )
        .ok()
    };
    [
        mk(a, b),
        mk(flat(a), flat(b)),
        mk(a, a),
        mk(flat(a), flat(a)),
    ]
}

#[test]
fn per_tile_faces_match_the_direct_test_on_random_triangles() {
    let seed = seed();
    let mut rng = Rng(seed ^ 0x4d11);
    let vps = [(40u16, 30u16), (17, 64), (1, 9)].map(|(w, h)| Viewport::new(w, h).unwrap());
    let mut n = [0u64; 5];
    for case in 0..cases(300, 15_000) {
        let Some(tri) = random_tri(&mut rng) else {
            continue;
        };
        let vp = vps[case as usize % vps.len()];
        let what = format!("case {case}, UVT_SEED={seed}");
        for t in classes(&tri).into_iter().flatten() {
            for s in [
                visible::<Exact>(&t, vp),
                visible::<Bounded<16, 16, 16, 20>>(&t, vp),
            ]
            .into_iter()
            .flatten()
            {
                let fp = s.footprint;
                let tiles = [1u16, 2, 4, 8].into_iter().flat_map(move |b| fp.cells(b));
                check(&s, tiles, &what, &mut n);
            }
        }
    }
    let [setups, before, kept, tiles, culled] = n;
    assert!(
        setups >= 400 && kept < before && kept > 0 && culled >= tiles / 20 && culled < tiles,
        "setups {setups}, faces {before} → kept {kept}, tiles {tiles}, culled {culled}"
    );
}

#[test]
fn per_tile_faces_match_the_direct_test_at_the_domain_corners() {
    let mut n = [0u64; 5];
    for (vw, vh) in [(2048u16, 2048u16), (1, 1), (1, 2048)] {
        let vp = Viewport::new(vw, vh).unwrap();
        for tri in crate::verify::eps_corners::tris() {
            for s in [
                visible::<Exact>(&tri, vp),
                visible::<Bounded<16, 16, 16, 32>>(&tri, vp),
            ]
            .into_iter()
            .flatten()
            {
                let fp = s.footprint;
                let edge = move |c: &PixelRect| {
                    c.x0 == fp.x0 || c.y0 == fp.y0 || c.x1 == fp.x1 || c.y1 == fp.y1
                };
                let tiles = [1u16, 8]
                    .into_iter()
                    .flat_map(move |b| fp.cells(b).filter(edge));
                check(
                    &s,
                    tiles,
                    &format!("corner triangle, viewport {vw}x{vh}"),
                    &mut n,
                );
            }
        }
    }
    assert!(n[0] >= 6, "only {} corner setups", n[0]);
}

#[test]
fn folded_corner_is_exact_at_zero() {
    // Small faces through sample corners: the direct maximum is exactly 0 (kept) or −1
    // (culled) on many tiles, so an off-by-one in the folded constant changes some decision.
    let mut at = [0u32; 2];
    for a in -3i128..=3 {
        for b in -3i128..=3 {
            for x0 in 0u16..6 {
                for y0 in 0u16..6 {
                    for (wx, wy) in [(1u16, 1u16), (2, 1), (1, 8), (8, 8)] {
                        let tile = PixelRect {
                            x0,
                            y0,
                            x1: x0 + wx,
                            y1: y0 + wy,
                        };
                        // c so that the direct maximum at the tile is exactly 0, then −1.
                        let xs = if a > 0 {
                            256 * i128::from(tile.x1) - 1
                        } else {
                            256 * i128::from(x0)
                        };
                        let ys = if b > 0 {
                            256 * i128::from(tile.y1) - 1
                        } else {
                            256 * i128::from(y0)
                        };
                        for d in [0i128, -1] {
                            let f = crate::bounds::hull::faces::HullFace {
                                a,
                                b,
                                c: d - a * xs - b * ys,
                            };
                            let want = face_culls(&f, tile, &mut Ops::default());
                            let t = crate::bounds::hull::tiles::TileFace::of(&f).unwrap();
                            let got = t.culls(tile);
                            assert_eq!(got, want, "face {f:?} tile {tile:?}");
                            at[usize::from(want)] += 1;
                            let mut one = HullCoeffs::EMPTY;
                            one.faces[0] = f;
                            one.len = 1;
                            let fp = PixelRect {
                                x0: 0,
                                y0: 0,
                                x1: 16,
                                y1: 16,
                            };
                            let kept = HullTiles::of(&one, fp, &mut Ops::default());
                            let got = kept.culls(tile, &mut Ops::default());
                            assert_eq!(got, want, "face {f:?} tile {tile:?} kept {kept:?}");
                        }
                    }
                }
            }
        }
    }
    assert!(at[0] > 1000 && at[1] > 1000, "{at:?}");
}

#[test]
fn the_cap_keeps_the_first_faces_and_culls_a_subset() {
    // 16 faces tangent to a circle of radius 40 px around (64, 64) px (in 1/256 px): each culls
    // the tiles beyond its tangent, a distinct corner region of the 128 × 128 footprint. More
    // candidates than the cap, so it must drop some and still cull only tiles the direct test
    // culls.
    let fp = PixelRect {
        x0: 0,
        y0: 0,
        x1: 128,
        y1: 128,
    };
    let mut hull = HullCoeffs::EMPTY;
    for k in 0..16usize {
        let ang = k as f64 * core::f64::consts::PI / 8.0;
        let (a, b) = ((-ang.cos() * 1024.0) as i128, (-ang.sin() * 1024.0) as i128);
        // a·xs + b·ys + c ≥ 0 inside: c = −(a·cx + b·cy) + |n|·r, all in 1/256 px.
        let (cx, cy, r) = (64 * 256, 64 * 256, 40 * 256);
        hull.faces[k] = crate::bounds::hull::faces::HullFace {
            a,
            b,
            c: -(a * cx + b * cy) + 1024 * r,
        };
    }
    hull.len = 16;
    let t = HullTiles::of(&hull, fp, &mut Ops::default());
    assert_eq!(t.faces().len(), KEPT_FACES, "kept {:?}", t.faces());
    let (mut direct, mut kept) = (0u32, 0u32);
    for b in [1u16, 4, 8] {
        for tile in fp.cells(b) {
            let want = hull
                .faces()
                .iter()
                .any(|f| face_culls(f, tile, &mut Ops::default()));
            let got = t.culls(tile, &mut Ops::default());
            assert!(
                !got || want,
                "tile {tile:?}: kept faces cull it, the direct test does not"
            );
            direct += u32::from(want);
            kept += u32::from(got);
        }
    }
    assert!(
        kept > 0 && kept < direct,
        "culled: kept faces {kept}, all faces {direct}"
    );
}
