//! Tile-row spans of the swept hull's faces (`HullTiles::span`, `HullCull::row_span`): the span
//! path visits exactly the tiles the per-tile face test keeps.
//!
//! - Reference: for seeded-random triangles of every kind (static, moving, defocus, both,
//!   crossing, domain extremes, slivers, w = 0; `UVT_SEED`, printed on failure; many more with
//!   `UVT_EXTENSIVE=1`), at the exact and the default bounded precision, bounds tiles 1, 2, 4, 8,
//!   and regions = the footprint, the footprint clipped by 8×8 and 16×16 screen tiles and by a
//!   random rectangle (clipped first and last cells): per row, a cell lies in the span if and
//!   only if no face culls it. The sweep must see partial spans on clipped rows, or it proves
//!   nothing.
//! - Renderer: `best()` and the same strategy without a row step (every tile face-tested)
//!   render identical images and identical counters except the bounds and row op counts.

use uvt_core::bounds::hull::tiles::HullTiles;
use uvt_core::bounds::registry::{best, hull};
use uvt_core::config::unit::Full;
use uvt_core::{
    setup, BoundsStrategy, DefaultPrecision, Exact, Ops, Outcome, PixelRect, Precision, Prim,
    Renderer, Rgb888, SamplePattern, Setup, Stats, Triangle, Unit, Viewport,
};
use uvt_tests::kinds::{make, ALL_KINDS, NP};
use uvt_tests::*;

/// What a sweep saw (so that a sweep that exercises nothing fails).
#[derive(Default, Debug)]
struct Seen {
    /// rows where the span was used
    rows: u64,
    /// cells outside their row's span
    pruned: u64,
    /// rows whose span is neither empty nor the whole row, on a row clipped at an unaligned end
    partial_clipped: u64,
}

/// Hull faces of `t` at precision `P` on `vp`, with its setup.
fn faces<P: Precision>(t: &Triangle, vp: Viewport) -> Option<(Setup, HullTiles)> {
    let mut ops = Ops::default();
    match setup::<P, Full>(t, vp, &mut ops) {
        Outcome::Visible(s) => Some((s, hull().prepare::<Full>(&s, &mut ops).0)),
        Outcome::Culled(_) | Outcome::Refused(_) => None,
    }
}

/// Every row of `region` at tile size `bt`: span membership against the per-tile face test.
fn check_region(
    tiles: &HullTiles,
    region: PixelRect,
    bt: u16,
    seen: &mut Seen,
) -> Result<(), String> {
    let mut ops = Ops::default();
    for row in region.rows(bt) {
        let Some((x0, x1)) = tiles.span(row, bt, &mut ops) else {
            continue;
        };
        seen.rows += 1;
        let mut kept = 0;
        let mut all = 0;
        for cell in row.cells(bt) {
            all += 1;
            let in_span = x0 <= cell.x0 && cell.x1 <= x1;
            let by_tile = !tiles.culls(cell, &mut ops);
            kept += u64::from(by_tile);
            if in_span != by_tile {
                return Err(format!(
                    "row {row:?} (bt {bt}): span [{x0}, {x1}) ({x0:#x}, {x1:#x}) but cell {cell:?}: \
                     in span {in_span}, per-tile face test keeps it {by_tile}"
                ));
            }
        }
        seen.pruned += all - kept;
        let unaligned = row.x0 % bt != 0 || row.x1 % bt != 0;
        if unaligned && kept > 0 && kept < all {
            seen.partial_clipped += 1;
        }
    }
    Ok(())
}

/// One triangle at precision `P`: every tile size and region.
fn check_at<P: Precision>(t: &Triangle, clip: PixelRect, seen: &mut Seen) -> Result<(), String> {
    let vp = Viewport::new(64, 48).unwrap();
    let Some((s, tiles)) = faces::<P>(t, vp) else {
        return Ok(());
    };
    let fp = s.footprint();
    for bt in [1u16, 2, 4, 8] {
        let mut regions = vec![fp, fp.intersect(&clip)];
        for screen in [8u16, 16] {
            regions.extend(
                PixelRect {
                    x0: 0,
                    y0: 0,
                    x1: 64,
                    y1: 48,
                }
                .cells(screen)
                .map(|c| c.intersect(&fp)),
            );
        }
        for r in regions.into_iter().filter(|r| !r.is_empty()) {
            check_region(&tiles, r, bt, seen).map_err(|e| {
                format!(
                    "{e}\n  region {r:?}, footprint {fp:?}, faces {}",
                    tiles.faces().len()
                )
            })?;
        }
    }
    Ok(())
}

#[test]
fn spans_equal_the_per_tile_face_test_seeded_random() {
    let seed = seed();
    let mut rng = Rng(seed ^ 0x5a7);
    let mut seen = Seen::default();
    for case in 0..cases(400, 20_000) {
        let k = (case % 8) as usize;
        let mut p = [0.0; NP];
        p.iter_mut().for_each(|x| *x = rng.range(-1.0, 1.0));
        let t = make(ALL_KINDS[k], &p);
        let x0 = rng.below(40) as u16;
        let y0 = rng.below(30) as u16;
        let clip = PixelRect {
            x0,
            y0,
            x1: x0 + 1 + rng.below(24) as u16,
            y1: y0 + 1 + rng.below(18) as u16,
        };
        let r = check_at::<Exact>(&t, clip, &mut seen)
            .and_then(|_| check_at::<DefaultPrecision>(&t, clip, &mut seen));
        if let Err(msg) = r {
            panic!(
                "{msg}\n  kind {:?}, case {case}, clip {clip:?}, rerun with UVT_SEED={seed}\n{}",
                ALL_KINDS[k],
                dump(&t)
            );
        }
    }
    println!("{seen:?}");
    assert!(
        seen.rows > 1000 && seen.pruned > 1000 && seen.partial_clipped > 100,
        "the sweep exercised too little: {seen:?} (UVT_SEED={seed})"
    );
}

/// `S` without a row step: every tile goes through `S::tile` (the per-tile face test).
struct NoSpan<S>(S);

impl<S: BoundsStrategy> BoundsStrategy for NoSpan<S> {
    type Coeffs = S::Coeffs;
    type Tile = S::Tile;
    fn name(&self) -> &'static str {
        "no-span"
    }
    fn prepare<U: Unit>(&self, setup: &Setup, ops: &mut Ops) -> S::Coeffs {
        self.0.prepare::<U>(setup, ops)
    }
    fn tile<U: Unit>(
        &self,
        setup: &Setup,
        c: &S::Coeffs,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<S::Tile> {
        self.0.tile::<U>(setup, c, tile, ops)
    }
}

/// Render `prims` on 64×48 at bounds tile `bt`: the image and the counters.
fn render<B: BoundsStrategy>(
    b: B,
    prims: &[Prim],
    pat: &SamplePattern<'_>,
    bt: u8,
) -> (Vec<Rgb888>, Stats) {
    let vp = Viewport::new(64, 48).unwrap();
    let mut r = Box::new(Renderer::<B, 16, Exact>::new(b, vp, prims).expect("setup"));
    let mut img = vec![Rgb888::new(0, 0, 0); 64 * 48];
    r.render_with::<8, 8, 4>(pat, bt, Rgb888::new(0, 0, 0), |x, y, c, _| {
        img[usize::from(y) * 64 + usize::from(x)] = c;
    })
    .expect("render");
    (img, r.stats)
}

#[test]
fn renderer_with_spans_equals_per_tile_test() {
    let seed = seed();
    let mut rng = Rng(seed ^ 0x5b7);
    let samples = random_samples(&mut rng, 2, 4);
    let pat = SamplePattern::new(2, 4, &samples).unwrap();
    let (mut rows, mut saved) = (0u64, 0i64);
    for case in 0..cases(12, 300) {
        let prims: Vec<Prim> = (0..8)
            .map(|i| {
                let mut p = [0.0; NP];
                p.iter_mut().for_each(|x| *x = rng.range(-1.0, 1.0));
                let color = Rgb888::new(30 * i as u8, 255 - 20 * i as u8, rng.below(256) as u8);
                Prim {
                    tri: make(ALL_KINDS[(case as usize + i) % 8], &p),
                    color,
                }
            })
            .collect();
        for bt in [1u8, 2, 4, 8] {
            let (ia, sa) = render(best(), &prims, &pat, bt);
            let (ib, sb) = render(NoSpan(best()), &prims, &pat, bt);
            let strip = |s: &Stats| {
                let mut s = *s;
                s.ops.bounds = 0;
                s.ops.rows = 0;
                s
            };
            let fail = |what: &str| {
                format!(
                    "{what} differ (bt {bt}, case {case}, UVT_SEED={seed})\n  spans   {sa:?}\n  per tile {sb:?}\n{}",
                    prims.iter().map(|p| dump(&p.tri)).collect::<Vec<_>>().join("\n")
                )
            };
            assert!(ia == ib, "{}", fail("images"));
            assert!(strip(&sa) == strip(&sb), "{}", fail("counters"));
            assert_eq!(sb.ops.rows, 0, "{}", fail("row ops without a row step"));
            rows += sa.ops.rows;
            saved += sb.ops.bounds as i64 - sa.ops.bounds as i64;
        }
    }
    println!("row ops {rows}, bounds ops saved {saved}");
    assert!(
        rows > 0 && saved > 0,
        "no row step ran or nothing saved: rows {rows}, saved {saved}"
    );
}
