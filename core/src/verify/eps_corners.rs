//! Domain-corner test of the conservative epsilon in the tighter strategies: hull culling
//! (`eps_margin`, `HullCoeffs::widened`), lens slabs and bilinear surfaces at the widest epsilon
//! (offset grid 2^32, ε_x < 2^24 raw) with ±2^29 coordinates and CoC, w from 1 raw to 2^29,
//! 2048×2048, 1×1 and 1×2048 viewports, on the footprint's corner tiles, with overflow checks on
//! (the test profile): every unchecked product named in the range comments is driven to its
//! extreme here, and each strategy's widened values are compared with an independent i128
//! computation of the epsilon term.
// Test code: plain operators on values far inside i128; an overflow panics (the failure signal).
#![allow(clippy::arithmetic_side_effects, clippy::indexing_slicing)]

use crate::bounds::hull::faces::{eps_margin, swept_points};
use crate::bounds::hyper::Hyper;
use crate::bounds::lens_time::LensTime;
use crate::bounds::registry::{best, hull_lens};
use crate::bounds::strategy::BoundsStrategy;
use crate::config::precision::{Bounded, OFFSET_SHIFT_MAX};
use crate::config::unit::Full;
use crate::input::{PixelRect, Triangle, Vertex, Viewport};
use crate::setup::eps::Eps;
use crate::setup::{setup, Outcome};
use crate::stats::Ops;

const LIM: i32 = 1 << 29;

/// Extreme triangles: every class, w from 1 raw to 2^29, coordinates and CoC at ±2^29 (the last
/// two with every w ≥ 2 raw, so a moving triangle's hull keeps its faces).
pub(super) fn tris() -> [Triangle; 6] {
    let a = [LIM, -LIM, LIM, LIM, -LIM];
    let b = [-LIM, LIM, -LIM, 1, LIM];
    let c = [LIM, LIM, -LIM, LIM / 2, LIM];
    let f = [-LIM, -LIM, LIM, 2, -LIM];
    let g = [-LIM, LIM, -LIM, 2, LIM];
    let nc = |x: [i32; 5]| [x[0], x[1], x[2], x[3], 0];
    let t = |p: [[i32; 5]; 3], q: [[i32; 5]; 3]| {
        Triangle::new(p.map(Vertex::from_bits), q.map(Vertex::from_bits))
            .expect("corner triangle in the domain")
    };
    [
        t([nc(a), nc(b), nc(c)], [nc(a), nc(b), nc(c)]),
        t([nc(a), nc(b), nc(c)], [nc(f), nc(c), nc(a)]),
        t([a, b, c], [a, b, c]),
        t([a, b, c], [f, c, a]),
        t([nc(a), nc(g), nc(c)], [nc(f), nc(c), nc(a)]),
        t([a, g, c], [f, c, a]),
    ]
}

fn corner_tiles<S: BoundsStrategy>(s: &S, setup: &crate::setup::Setup, ops: &mut Ops) {
    let c = s.prepare::<Full>(setup, ops);
    let fp = setup.footprint();
    for (x, y) in [(fp.x0, fp.y0), (fp.x1 - 1, fp.y1 - 1), (fp.x0, fp.y1 - 1)] {
        for bt in [1u16, 8] {
            let tile = PixelRect {
                x0: x,
                y0: y,
                x1: (x + bt).min(fp.x1),
                y1: (y + bt).min(fp.y1),
            };
            let _ = s.tile::<Full>(setup, &c, tile, ops);
        }
    }
}

#[test]
fn strategies_with_epsilon_at_the_domain_corners() {
    let mut visible = 0;
    for (vw, vh) in [(2048u16, 2048u16), (1, 1), (1, 2048)] {
        let vp = Viewport::new(vw, vh).unwrap();
        for tri in tris() {
            let mut ops = Ops::default();
            let Outcome::Visible(s) = setup::<Bounded<16, 16, 16, 32>, Full>(&tri, vp, &mut ops)
            else {
                continue;
            };
            visible += 1;
            let e = s.eps();
            assert_eq!(e, Eps::of(Some(OFFSET_SHIFT_MAX), s.class(), vp));
            corner_tiles(&best(), &s, &mut ops);
            corner_tiles(&hull_lens(), &s, &mut ops);
            corner_tiles(&LensTime::<8>, &s, &mut ops);
            corner_tiles(&Hyper, &s, &mut ops);
            // The hull's margin against an independent computation over the same points.
            let (pts, n) = swept_points(s.tri(), s.class());
            let pts = &pts[..n];
            let got = eps_margin(pts, &e, vp, &mut ops);
            let ew = i128::from(e.w());
            let want = if pts.iter().any(|p| i128::from(p[2]) <= ew) {
                None
            } else {
                let wmin = pts.iter().map(|p| i128::from(p[2])).min().unwrap();
                let r = |k: usize| {
                    pts.iter()
                        .map(|p| (i128::from(p[k]).abs() + i128::from(p[2]) - 1) / i128::from(p[2]))
                        .max()
                        .unwrap()
                };
                let ext = [i128::from(vw), i128::from(vh)];
                Some([0, 1].map(|k| {
                    let num = 128 * ext[k] * (i128::from(e.x()[k]) + r(k) * ew);
                    let den = wmin - ew;
                    (num + den - 1) / den
                }))
            };
            assert_eq!(got, want, "vp {vw}x{vh} {tri:?}");
            if let Some(rho) = got {
                assert!(
                    rho.iter().all(|&r| (0..1i128 << 49).contains(&r)),
                    "{rho:?}"
                );
            }
        }
    }
    assert!(visible >= 6, "only {visible} corner setups visible");
}
