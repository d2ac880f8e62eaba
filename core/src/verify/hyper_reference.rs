//! The per-tile surfaces of [`Hyper`] (affine in the tile's start and width, precomputed in
//! `prepare`) against the formulation they replaced, kept here as the test-only reference
//! ([`tile_surfaces_ref`]: 16 bounding-line values at both tile ends, min/max, then the corner
//! map). Every tile's result — Laine's box and all 16 coefficients — must be **identical**, on
//! seeded random motion + defocus triangles (`UVT_SEED`, printed on failure; `UVT_EXTENSIVE=1`
//! for more) with the exact and a bounded test, every bounds tile 1, 2, 4, 8 of the footprint
//! (clipped like the renderer's), reversed, empty and out-of-footprint tiles, and the domain
//! corner triangles of `eps_corners` on every row and column range of their footprint.
// Test code: plain i128 operators on values < 2^100; an overflow panics (the failure signal).
#![allow(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_possible_wrap,
    clippy::cast_sign_loss
)]

use crate::bounds::hyper::{corners, surface, Corners, Hyper, HyperTile, Surface};
use crate::bounds::laine::Laine2011;
use crate::bounds::strategy::BoundsStrategy;
use crate::config::class::Class;
use crate::config::precision::{Bounded, Exact, Precision};
use crate::config::unit::Full;
use crate::input::{PixelRect, Triangle, Vertex, Viewport};
use crate::setup::{setup, Outcome, Setup};
use crate::stats::Ops;
use uvt_testkit::{cases, seed, Rng};

/// The replaced per-tile computation, verbatim: corner values for tile ends [x0, x1] ⊆ [ξa, ξb],
/// lower = min of the two ends of each bounding line, upper = max, scaled by ξb − ξa.
fn tile_surfaces_ref(d: &Corners, x0: i64, x1: i64) -> Option<[Surface; 2]> {
    let [xa, xb] = d.xi;
    let line = |v: &[i64; 2], x: i64| {
        i128::from(v[0]) * i128::from(xb - x) + i128::from(v[1]) * i128::from(x - xa)
    };
    let lo = d.lo.map(|l| l.map(|v| line(&v, x0).min(line(&v, x1))));
    let hi = d.hi.map(|l| l.map(|v| line(&v, x0).max(line(&v, x1))));
    Some([surface(lo)?, surface(hi)?])
}

/// The replaced `Hyper::tile`.
fn tile_ref(s: &Setup, tile: PixelRect) -> Option<HyperTile> {
    let laine = Laine2011.prepare::<Full>(s, &mut Ops::default());
    let b = Laine2011.tile::<Full>(s, &laine, tile, &mut Ops::default())?;
    let eps = |axis: usize| i64::from(s.eps.x[axis].saturating_add(s.eps.w));
    let fp = s.footprint;
    let x = corners(
        &s.tri,
        [fp.x0, fp.x1].map(i64::from),
        0,
        i64::from(s.viewport.width()),
        eps(0),
    );
    let y = corners(
        &s.tri,
        [fp.y0, fp.y1].map(i64::from),
        1,
        i64::from(s.viewport.height()),
        eps(1),
    );
    let sx = tile_surfaces_ref(&x, i64::from(tile.x0), i64::from(tile.x1));
    let sy = tile_surfaces_ref(&y, i64::from(tile.y0), i64::from(tile.y1));
    let surfaces = sx.zip(sy).map(|(a, b)| [a, b]);
    Some(HyperTile { b, s: surfaces })
}

/// Compares the new and the reference tile; returns the number of tiles with surfaces.
fn check(s: &Setup, tiles: impl Iterator<Item = PixelRect>, what: &str) -> u64 {
    let c = Hyper.prepare::<Full>(s, &mut Ops::default());
    let mut with = 0;
    for tile in tiles {
        let got = Hyper.tile::<Full>(s, &c, tile, &mut Ops::default());
        let want = tile_ref(s, tile);
        assert_eq!(
            got, want,
            "{what}: tile {tile:?} of footprint {:?}, triangle {:?}\ngot  {got:x?}\nwant {want:x?}",
            s.footprint, s.tri
        );
        with += u64::from(matches!(got, Some(HyperTile { s: Some(_), .. })));
    }
    with
}

/// Every bounds tile of the footprint for sizes 1, 2, 4, 8 (aligned, clipped), and odd tiles:
/// reversed, empty, wider than 8, reaching past the footprint.
fn all_tiles(fp: PixelRect) -> impl Iterator<Item = PixelRect> {
    let odd = [
        PixelRect {
            x0: fp.x1,
            y0: fp.y1,
            x1: fp.x0,
            y1: fp.y0,
        },
        PixelRect {
            x0: fp.x0,
            y0: fp.y0,
            x1: fp.x0,
            y1: fp.y0,
        },
        fp,
        PixelRect {
            x0: fp.x0.saturating_sub(3),
            y0: fp.y0,
            x1: fp.x1.saturating_add(5),
            y1: fp.y1.saturating_add(1),
        },
    ];
    [1u16, 2, 4, 8]
        .into_iter()
        .flat_map(move |b| fp.cells(b))
        .chain(odd)
}

fn raw(rng: &mut Rng, lo: i64, hi: i64) -> i32 {
    (lo + (rng.next_u64() % (hi - lo + 1) as u64) as i64) as i32
}

/// A random motion + defocus triangle: w mostly in [1/4, 4], sometimes near or behind the
/// camera plane; x, y within ±1.5 w; CoC up to ±w/4.
pub(crate) fn random_tri(rng: &mut Rng) -> Option<Triangle> {
    let one = 1i64 << 16;
    let end = |rng: &mut Rng| {
        [0; 3].map(|_| {
            let w = if rng.next_u64() % 8 == 0 {
                raw(rng, -one / 4, one / 4)
            } else {
                raw(rng, one / 4, 4 * one)
            };
            let m = (i64::from(w).abs() * 3 / 2).max(1);
            let c = (i64::from(w).abs() / 4).max(1);
            Vertex::from_bits([
                raw(rng, -m, m),
                raw(rng, -m, m),
                raw(rng, 0, one),
                w,
                raw(rng, -c, c),
            ])
        })
    };
    let a = end(rng);
    let b = end(rng);
    Triangle::new(a, b).ok()
}

fn md_setup<P: Precision>(tri: &Triangle, vp: Viewport) -> Option<Setup> {
    match setup::<P, Full>(tri, vp, &mut Ops::default()) {
        Outcome::Visible(s) if s.class == Class::MotionDefocus => Some(s),
        _ => None,
    }
}

#[test]
fn affine_surfaces_match_the_reference_on_random_triangles() {
    let seed = seed();
    let mut rng = Rng(seed ^ 0x4a7e);
    let vps = [(40u16, 30u16), (17, 64), (1, 9)].map(|(w, h)| Viewport::new(w, h).unwrap());
    let (mut setups, mut tiles) = (0u32, 0u64);
    for case in 0..cases(400, 20_000) {
        let Some(tri) = random_tri(&mut rng) else {
            continue;
        };
        let vp = vps[case as usize % vps.len()];
        let what = format!("case {case}, UVT_SEED={seed}");
        for s in [
            md_setup::<Exact>(&tri, vp),
            md_setup::<Bounded<16, 16, 16, 20>>(&tri, vp),
        ]
        .into_iter()
        .flatten()
        {
            setups += 1;
            tiles += check(&s, all_tiles(s.footprint), &what);
        }
    }
    assert!(
        setups >= 100 && tiles >= 10_000,
        "only {setups} setups, {tiles} tiles with surfaces"
    );
}

#[test]
fn affine_surfaces_match_the_reference_at_the_domain_corners() {
    let mut setups = 0;
    for (vw, vh) in [(2048u16, 2048u16), (1, 1), (1, 2048)] {
        let vp = Viewport::new(vw, vh).unwrap();
        for tri in crate::verify::eps_corners::tris() {
            for s in [
                md_setup::<Exact>(&tri, vp),
                md_setup::<Bounded<16, 16, 16, 32>>(&tri, vp),
            ]
            .into_iter()
            .flatten()
            {
                setups += 1;
                let fp = s.footprint;
                // The surfaces of each axis depend on that axis's range only: every column range
                // on the first row range, every row range on the first column range.
                let rows = move |b: u16| fp.cells(b).filter(move |c| c.x0 == fp.x0);
                let cols = move |b: u16| fp.cells(b).filter(move |c| c.y0 == fp.y0);
                let tiles = [1u16, 8]
                    .into_iter()
                    .flat_map(move |b| rows(b).chain(cols(b)))
                    .chain(
                        all_tiles(PixelRect {
                            x1: fp.x0.saturating_add(3),
                            ..fp
                        })
                        .take(64),
                    );
                check(&s, tiles, &format!("corner triangle, viewport {vw}x{vh}"));
            }
        }
    }
    assert!(
        setups >= 4,
        "only {setups} corner setups with motion + defocus"
    );
}
