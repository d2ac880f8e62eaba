//! Domain corners: moving triangles (two with ±2^29 CoC) with ±2^29 coordinates, w from 1 raw to 2^29, at
//! the widest epsilon (offset grid 2^32) and at ε = 0, on 2048×2048, 1×1 and 1×2048
//! viewports, every corner tile of the footprint (1×1 and 8×8) with overflow checks on (the
//! test profile): each unchecked product named in the range comments is driven to its
//! extreme, and the lines are compared with an independent i128 computation.
// Test code: plain operators on values far inside i128; an overflow panics (the failure).
#![allow(clippy::arithmetic_side_effects, clippy::indexing_slicing)]
use crate::bounds::edge_time::*;
use crate::bounds::strategy::BoundsStrategy;
use crate::config::precision::{Bounded, Exact};
use crate::config::unit::Full;
use crate::input::Vertex;
use crate::input::{PixelRect, Triangle, Viewport, C, W, X, Y};
use crate::setup::Setup;
use crate::setup::{setup, Outcome};
use crate::stats::Ops;

const LIM: i32 = 1 << 29;

fn tris() -> [Triangle; 6] {
    let t = |p: [[i32; 5]; 3], q: [[i32; 5]; 3]| {
        Triangle::new(p.map(Vertex::from_bits), q.map(Vertex::from_bits)).expect("in domain")
    };
    let a = [LIM, -LIM, LIM, LIM, 0];
    let b = [-LIM, LIM, -LIM, 1, 0];
    let c = [LIM, LIM, -LIM, LIM / 2, 0];
    let f = [-LIM, -LIM, LIM, 2, 0];
    let g = [-LIM, LIM, -LIM, LIM, 0];
    let h = [LIM, 3 * (LIM / 4), 0, LIM, 0];
    // With defocus: CoC at the domain's ±2^29 (and 0) on moving vertices.
    let lens = |mut p: [i32; 5], c: i32| {
        p[4] = c;
        p
    };
    [
        t([a, b, c], [f, c, a]),
        t([a, g, c], [f, c, a]),
        t([a, g, h], [g, h, a]),
        t([f, g, h], [a, b, c]),
        t(
            [lens(a, LIM), lens(g, -LIM), c],
            [lens(f, -LIM), c, lens(a, LIM)],
        ),
        t([lens(a, LIM), g, lens(h, LIM)], [g, lens(h, -LIM), a]),
    ]
}

/// The lines from the definition, in i128: values `φ = A − 2wζ` widened by ρ.
fn lines_i128(s: &Setup, n: [i64; 2]) -> ([i128; 4], [i128; 4]) {
    let [nx, ny] = n.map(i128::from);
    let (ew, eh) = (i128::from(s.viewport.w), i128::from(s.viewport.h));
    let fp = s.footprint;
    let zs = [
        (fp.x0, fp.y0),
        (fp.x1, fp.y0),
        (fp.x0, fp.y1),
        (fp.x1, fp.y1),
    ]
    .map(|(x, y)| nx * i128::from(x) + ny * i128::from(y));
    let (za, zb) = (*zs.iter().min().unwrap(), *zs.iter().max().unwrap());
    let e = s.eps;
    let rho = nx.abs() * ew * i128::from(e.x[0] + e.w) + ny.abs() * eh * i128::from(e.x[1] + e.w);
    let mut lo = [[i128::MAX; 2]; 2];
    let mut hi = [[i128::MIN; 2]; 2];
    for (time, ends) in s.tri.v.iter().enumerate() {
        for p in ends {
            let (x, y, w) = (i128::from(p[X]), i128::from(p[Y]), i128::from(p[W]));
            let bias = (nx.abs() * ew + ny.abs() * eh) * i128::from(p[C]).abs() + rho;
            for (end, z) in [za, zb].into_iter().enumerate() {
                let phi = nx * ew * (x + w) + ny * eh * (w - y) - 2 * w * z;
                lo[time][end] = lo[time][end].min(phi - bias);
                hi[time][end] = hi[time][end].max(phi + bias);
            }
        }
    }
    let d = zb - za;
    let ls = [lo[0], lo[1], hi[0], hi[1]];
    (ls.map(|v| v[0] * d), ls.map(|v| v[1] - v[0]))
}

fn corners<P: crate::config::precision::Precision>() -> usize {
    let mut active = 0;
    for (vw, vh) in [(2048u16, 2048u16), (1, 1), (1, 2048)] {
        let vp = Viewport::new(vw, vh).unwrap();
        for tri in tris() {
            let mut ops = Ops::default();
            let Outcome::Visible(s) = setup::<P, Full>(&tri, vp, &mut ops) else {
                continue;
            };
            let Some(e) = edge_axis(&s, &mut ops) else {
                continue;
            };
            active += 1;
            let (base, slope) = lines_i128(&s, e.n);
            assert_eq!(e.base, base, "{tri:?} {vw}x{vh}");
            assert_eq!(e.slope.map(i128::from), slope, "{tri:?} {vw}x{vh}");
            assert!(e.n.iter().all(|v| v.abs() <= N_MAX));
            assert!(e.base.iter().all(|b| b.abs() < 1 << 73));
            assert!(e.slope.iter().all(|b| b.abs() < 1 << 53));
            let strat = EdgeTime::new(crate::bounds::laine::Laine2011, "edge-t");
            let c = strat.prepare::<Full>(&s, &mut ops);
            let fp = s.footprint();
            for (x, y) in [(fp.x0, fp.y0), (fp.x1 - 1, fp.y1 - 1), (fp.x0, fp.y1 - 1)] {
                for bt in [1u16, 8] {
                    let tile = PixelRect {
                        x0: x,
                        y0: y,
                        x1: (x + bt).min(fp.x1),
                        y1: (y + bt).min(fp.y1),
                    };
                    let _ = e.t(tile, &mut ops);
                    let _ = strat.tile::<Full>(&s, &c, tile, &mut ops);
                }
            }
        }
    }
    active
}

#[test]
fn edge_lines_at_the_domain_corners() {
    assert!(corners::<Bounded<16, 16, 16, 32>>() >= 5);
    assert!(corners::<Exact>() >= 5);
}
