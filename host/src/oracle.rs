//! The axis-aligned limit: per bounds tile, an estimate of the tightest axis-aligned (u, v, t) box
//! of the triangle's coverage set, and how many pattern samples such a box would test.
//!
//! For every triangle and every bounds tile that Laine 2011 keeps (a conservative bound: the tiles
//! it culls hold no covered sample — tested in `tests/tests/conservative.rs`), the covered set is
//! the set of points on the core's grids (x, y in 1/256 px within the tile, u, v, t raw inside
//! Laine's box) that the core's exact sample test covers; its box is what the tightest
//! conservative axis-aligned bound must test. [`search::BoxSearch`] estimates that box from
//! inside: dense points per pixel (5D Owen-scrambled Sobol) and then a search that pushes each of
//! the six u, v, t faces outward along covered points (evolution strategy + bisection). Every
//! face of the estimate is attained by a covered point, so the estimated box lies inside the
//! true box, and the count `|{pattern samples of the tile inside the estimated box or covered}|`
//! is at most what any conservative axis-aligned bound tests: **the estimated limit STE errs on
//! the optimistic side** (it is ≥ the true limit STE; it can only fall as effort grows).
//!
//! Two efforts are evaluated, nested (the second continues the first's dense sequence and starts
//! its faces from the first's box), so their gap shows convergence; the covered pattern samples
//! outside each estimated box are counted too — each one proves that box too small, so a count
//! of 0 at the second effort and a small gap are the evidence of convergence. A strategy that is
//! not axis-aligned (per-sample predicates) may test fewer samples than this limit.

pub mod search;

use rayon::prelude::*;
use uvt_core::bounds::BoundsStrategy;
use uvt_core::{
    sample_test, Laine2011, Lens, Ops, Outcome, Sample, ScreenPos, SubPixel, Time, Triangle,
    Viewport,
};

use crate::pattern::Pattern;

use search::{BoxSearch, Effort, P5};

/// Counters of the axis-aligned limit at two efforts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Limit {
    /// the two efforts `[low, high]` (dense points per pixel, face-search proposals per face)
    pub effort: [Effort; 2],
    /// bounds tiles Laine keeps (where the search ran)
    pub tiles: u64,
    /// covered pattern samples
    pub covered: u64,
    /// samples the limit box tests (inside the estimated box, or covered), per effort
    pub tested: [u64; 2],
    /// covered pattern samples outside the estimated box, per effort
    pub missed: [u64; 2],
    /// sample tests of the search, per effort (the second effort's count includes the first's)
    pub points: [u64; 2],
}

impl Limit {
    fn add(&mut self, o: &Limit) {
        self.tiles += o.tiles;
        self.covered += o.covered;
        for k in 0..2 {
            self.tested[k] += o.tested[k];
            self.missed[k] += o.missed[k];
            self.points[k] += o.points[k];
        }
    }
    /// STE of the limit at effort index `k` (0: low, 1: high).
    pub fn ste(&self, k: usize) -> f64 {
        if self.tested[k] == 0 {
            0.0
        } else {
            self.covered as f64 / self.tested[k] as f64
        }
    }
}

/// `p` (x, y in 1/256 px, then u, v, t raw) as a pixel and a sample; `None` outside the sample
/// domain (never for points of a tile's search domain, which lie in Laine's box).
fn to_sample(p: &P5) -> Option<(u16, u16, Sample)> {
    let (px, sx) = (u16::try_from(p[0] >> 8).ok()?, (p[0] & 255) as u8);
    let (py, sy) = (u16::try_from(p[1] >> 8).ok()?, (p[1] & 255) as u8);
    let s = Sample::new(
        SubPixel::from_bits(sx),
        SubPixel::from_bits(sy),
        Lens::from_bits(p[2]),
        Lens::from_bits(p[3]),
        Time::from_bits(p[4]),
    )
    .ok()?;
    Some((px, py, s))
}

/// The axis-aligned limit of a frame for bounds tiles of `tile` pixels at two efforts (the
/// second continues the first; `effort[1].density` ≥ `effort[0].density`, and at most 2^16 per
/// pixel so a tile's points stay within one Sobol sequence).
pub fn axis_aligned_limit(
    tris: &[Triangle],
    vp: Viewport,
    pattern: &Pattern,
    tile: u8,
    effort: [Effort; 2],
) -> Limit {
    let mut total = tris
        .par_iter()
        .enumerate()
        .map(|(ti, tri)| {
            let mut ops = Ops::default();
            let mut out = Limit::default();
            let Outcome::Visible(s) = uvt_core::setup(tri, vp, &mut ops) else {
                return out;
            };
            let co = Laine2011.prepare(&s, &mut ops);
            for cell in s.footprint().cells(tile as u16) {
                let Some(b) = Laine2011.tile(&s, &co, cell, &mut ops) else {
                    continue;
                };
                out.tiles += 1;
                let area = u32::from(cell.x1 - cell.x0) * u32::from(cell.y1 - cell.y0);
                // 1/256 px: x1, y1 ≤ 2^16, so 256·x1 ≤ 2^24 fits i32.
                let lo = [
                    i32::from(cell.x0) * 256,
                    i32::from(cell.y0) * 256,
                    b.u.lo(),
                    b.v.lo(),
                    b.t.lo(),
                ];
                let hi = [
                    i32::from(cell.x1) * 256 - 1,
                    i32::from(cell.y1) * 256 - 1,
                    b.u.hi(),
                    b.v.hi(),
                    b.t.hi(),
                ];
                let seed = (ti as u64) << 32 ^ u64::from(cell.x0) << 16 ^ u64::from(cell.y0);
                let mut search = BoxSearch::new(lo, hi, 0x0ac1_e000_0000_0000 ^ seed);
                let tests = std::cell::Cell::new(0u64);
                let mut test = |p: &P5| {
                    tests.set(tests.get() + 1);
                    to_sample(p).is_some_and(|(px, py, smp)| {
                        sample_test(&s, ScreenPos::of(px, py, &smp), &smp, &mut ops).is_some()
                    })
                };
                let mut found = [search.clone(), search.clone()];
                for (k, e) in effort.iter().enumerate() {
                    search.dense(e.density.saturating_mul(area), &mut test);
                    search.push_faces(e.steps, &mut test);
                    found[k] = search.clone();
                    out.points[k] += tests.get();
                }
                for py in cell.y0..cell.y1 {
                    for px in cell.x0..cell.x1 {
                        for si in 0..pattern.spp as usize {
                            let smp = &pattern.quant[pattern.index(px, py, si)];
                            let uvt = [smp.u().to_bits(), smp.v().to_bits(), smp.t().to_bits()];
                            let hit = b.contains(uvt[0], uvt[1], uvt[2])
                                && sample_test(&s, ScreenPos::of(px, py, smp), smp, &mut ops)
                                    .is_some();
                            out.covered += hit as u64;
                            for (k, f) in found.iter().enumerate() {
                                let inside = f.contains_uvt(uvt);
                                out.tested[k] += (inside || hit) as u64;
                                out.missed[k] += (hit && !inside) as u64;
                            }
                        }
                    }
                }
            }
            out
        })
        .reduce(Limit::default, |mut a, b| {
            a.add(&b);
            a
        });
    total.effort = effort;
    total
}
