//! The in-band oracle of `uvt render`'s report: per kept bounds tile of the core's walk, the
//! samples inside the tightest axis-aligned (u, v, t) box around the samples the core actually
//! covered there and around [`ORACLE_POINTS`] dense points of the tile's (x, y, u, v, t) box
//! that the exact triangle covers (dense points are drawn only in tiles where the pattern
//! covered a sample, and only inside the tile's own box). It watches the core's loop
//! ([`uvt_core::Observer`]); it overstates the reachable STE (tiles with no covered pattern
//! sample count nothing). The axis-aligned limit that `bench-ste` reports is
//! [`crate::oracle::limit::axis_aligned_limit`]: dense sampling in every tile Laine keeps.

use uvt_core::{Fate, PixelRect, Sample, Seen, UvtBox};

use crate::reference;
use crate::scene::tri::SceneTri;

/// Dense points per bounds tile for the oracle box (5D Sobol, Owen-scrambled, fixed seed).
pub const ORACLE_POINTS: u32 = 16;

/// The oracle's dense points: `[x, y, u, v, t]` in [0, 1)⁵.
fn oracle_points() -> Vec<[f64; 5]> {
    (0..ORACLE_POINTS)
        .map(|i| [0, 1, 2, 3, 4].map(|d| sobol_burley::sample(i, d, 0x0ac1e) as f64))
        .collect()
}

/// The oracle of one band: its count and the state of the current kept tile.
pub struct Oracle<'a> {
    tris: &'a [SceneTri],
    vp: (u16, u16),
    dense: Vec<[f64; 5]>,
    /// the current tile's box as real (u, v, t) ranges
    ranges: [(f64, f64); 3],
    /// (u, v, t) of the current tile's tested samples
    tested: Vec<[f64; 3]>,
    lo: [f64; 3],
    hi: [f64; 3],
    /// samples inside the oracle boxes so far
    pub count: u64,
}

/// A sample's (u, v, t) as reals.
fn uvt(s: &Sample) -> [f64; 3] {
    [s.u().to_num(), s.v().to_num(), s.t().to_num()]
}

impl<'a> Oracle<'a> {
    /// The oracle over the exact triangles `tris` on viewport `vp`.
    pub fn new(tris: &'a [SceneTri], vp: (u16, u16)) -> Oracle<'a> {
        Oracle {
            tris,
            vp,
            dense: oracle_points(),
            ranges: [(0.0, 0.0); 3],
            tested: Vec::new(),
            lo: [f64::MAX; 3],
            hi: [f64::MIN; 3],
            count: 0,
        }
    }

    /// A tile of the walk: a kept one starts a new box.
    pub fn cell(&mut self, fate: Fate) {
        if let Fate::Kept { bounds } = fate {
            let r = |i: uvt_core::Interval| (i.lo() as f64 / 65536.0, i.hi() as f64 / 65536.0);
            let b: UvtBox = bounds;
            self.ranges = [r(b.u), r(b.v), r(b.t)];
            self.tested.clear();
            self.lo = [f64::MAX; 3];
            self.hi = [f64::MIN; 3];
        }
    }

    /// A sample of the kept tile.
    pub fn sample(&mut self, s: &Sample, seen: Seen) {
        if !seen.admitted {
            return;
        }
        let p = uvt(s);
        self.tested.push(p);
        if seen.hit.is_some() {
            self.grow(p);
        }
    }

    fn grow(&mut self, p: [f64; 3]) {
        for ((lo, hi), x) in self.lo.iter_mut().zip(&mut self.hi).zip(p) {
            *lo = lo.min(x);
            *hi = hi.max(x);
        }
    }

    /// The end of kept tile `cell` of triangle `tri`: the box grows around the dense points
    /// the exact triangle covers (exact geometry, f64 ray test), then the tested samples inside
    /// it are counted.
    pub fn cell_end(&mut self, tri: u32, cell: PixelRect) {
        if self.lo[0] > self.hi[0] {
            return;
        }
        let Some(t) = self.tris.get(tri as usize) else {
            return;
        };
        let r = self.ranges;
        for i in 0..self.dense.len() {
            let d = self.dense[i];
            let x = cell.x0 as f64 + d[0] * (cell.x1 - cell.x0) as f64;
            let y = cell.y0 as f64 + d[1] * (cell.y1 - cell.y0) as f64;
            let p = [0, 1, 2].map(|k| r[k].0 + d[k + 2] * (r[k].1 - r[k].0));
            if reference::sample::sample_test(t, self.vp, x, y, p[0], p[1], p[2]).is_some() {
                self.grow(p);
            }
        }
        let (lo, hi) = (self.lo, self.hi);
        self.count += self
            .tested
            .iter()
            .filter(|p| (0..3).all(|k| lo[k] <= p[k] && p[k] <= hi[k]))
            .count() as u64;
    }
}
