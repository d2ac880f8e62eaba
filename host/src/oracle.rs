//! The axis-aligned limit: per bounds tile, an estimate of the tightest axis-aligned (u, v, t) box
//! of the triangle's continuous coverage set, and how many pattern samples such a box would test.
//!
//! For every triangle and every bounds tile that Laine 2011 keeps (a conservative bound: the tiles
//! it culls hold no covered sample — tested in `tests/tests/conservative.rs`), `density` dense
//! points per pixel are drawn over the tile's (x, y) and Laine's (u, v, t) box (5D Owen-scrambled
//! Sobol, on the core's grids: 1/256 px, 2^-16 in t/u/v) and tested with the core's exact sample
//! test; the box of the covered dense points estimates the coverage set's box from inside. A
//! conservative axis-aligned bound must contain that box and every covered pattern sample, so it
//! tests at least `|{pattern samples of the tile inside the box or covered}|` — the *limit*
//! counted here. The estimate approaches the true limit from the optimistic side as the density
//! grows; two densities are evaluated on nested point sets (the first `d0·area` points of the
//! same sequence) so their gap shows convergence, and the covered pattern samples outside the
//! dense box are counted (they measure what the dense box still misses). A strategy that is not
//! axis-aligned (per-sample predicates) may test fewer samples than this limit.

use rayon::prelude::*;
use uvt_core::bounds::{BoundsStrategy, UvtBox};
use uvt_core::{
    sample_test, Interval, Laine2011, Lens, Ops, Outcome, PixelRect, Sample, ScreenPos, SubPixel,
    Time, Triangle, Viewport,
};

/// A growing raw `[lo, hi]` range (the box accumulator; core `Interval`s are immutable).
#[derive(Clone, Copy, Debug)]
struct Span {
    lo: i32,
    hi: i32,
}

impl Span {
    fn of(iv: Interval) -> Span {
        Span {
            lo: iv.lo(),
            hi: iv.hi(),
        }
    }
    fn contains(&self, x: i32) -> bool {
        self.lo <= x && x <= self.hi
    }
}

/// A sample with new coordinates; every caller passes values inside the sample domain (points
/// of a core tile box).
fn sample(sx: SubPixel, sy: SubPixel, u: i32, v: i32, t: i32) -> Sample {
    Sample::new(
        sx,
        sy,
        Lens::from_bits(u),
        Lens::from_bits(v),
        Time::from_bits(t),
    )
    .expect("oracle points lie inside the tile's (u, v, t) box, inside the sample domain")
}

use crate::pattern::Pattern;

/// Counters of the axis-aligned limit at two densities.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Limit {
    /// dense points per pixel `[low, high]`
    pub density: [u32; 2],
    /// bounds tiles Laine keeps (where dense points were drawn)
    pub tiles: u64,
    /// covered pattern samples
    pub covered: u64,
    /// samples the limit box tests (inside the dense box, or covered), per density
    pub tested: [u64; 2],
    /// covered pattern samples outside the dense box, per density
    pub missed: [u64; 2],
    /// sample tests of the dense points and the face refinement (both densities)
    pub points: u64,
}

impl Limit {
    fn add(&mut self, o: &Limit) {
        self.tiles += o.tiles;
        self.covered += o.covered;
        self.points += o.points;
        for k in 0..2 {
            self.tested[k] += o.tested[k];
            self.missed[k] += o.missed[k];
        }
    }
    /// STE of the limit at density index `k` (0: low, 1: high).
    pub fn ste(&self, k: usize) -> f64 {
        if self.tested[k] == 0 {
            0.0
        } else {
            self.covered as f64 / self.tested[k] as f64
        }
    }
}

/// A covered point: pixel and sample.
type Pt = (u16, u16, Sample);

/// Growing (u, v, t) box of covered points, with the covered point at each of its 6 faces.
#[derive(Clone, Copy)]
struct BoxAcc(Option<[Span; 3]>, [[Option<Pt>; 2]; 3]);

fn uvt_of(s: &Sample) -> [i32; 3] {
    [s.u().to_bits(), s.v().to_bits(), s.t().to_bits()]
}

fn with_uvt(s: &Sample, k: usize, x: i32) -> Sample {
    let mut c = uvt_of(s);
    if let Some(slot) = c.get_mut(k) {
        *slot = x;
    }
    sample(s.sx(), s.sy(), c[0], c[1], c[2])
}

/// `p` with coordinate `j` (0: x, 1: y within the tile; 2..5: u, v, t) at end `e` (0 low, 1 high).
fn corner(p: &Pt, j: usize, e: usize, cell: &PixelRect, ends: &[Span; 3]) -> Pt {
    let mut q = *p;
    match (j, e) {
        (0, e) => {
            let (x, sx) = if e == 0 {
                (cell.x0, 0)
            } else {
                (cell.x1 - 1, 255)
            };
            let c = uvt_of(&q.2);
            (q.0, q.2) = (
                x,
                sample(SubPixel::from_bits(sx), q.2.sy(), c[0], c[1], c[2]),
            );
        }
        (1, e) => {
            let (y, sy) = if e == 0 {
                (cell.y0, 0)
            } else {
                (cell.y1 - 1, 255)
            };
            let c = uvt_of(&q.2);
            (q.1, q.2) = (
                y,
                sample(q.2.sx(), SubPixel::from_bits(sy), c[0], c[1], c[2]),
            );
        }
        (j, e) => {
            let iv = ends[j - 2];
            q.2 = with_uvt(&q.2, j - 2, if e == 0 { iv.lo } else { iv.hi });
        }
    }
    q
}

impl BoxAcc {
    fn grow(&mut self, pt: Pt) {
        let p = uvt_of(&pt.2);
        let b = self.0.get_or_insert(p.map(|x| Span { lo: x, hi: x }));
        for ((iv, x), ext) in b.iter_mut().zip(p).zip(self.1.iter_mut()) {
            if x <= iv.lo || ext[0].is_none() {
                iv.lo = x;
                ext[0] = Some(pt);
            }
            if x >= iv.hi || ext[1].is_none() {
                iv.hi = x;
                ext[1] = Some(pt);
            }
        }
    }
    /// Push each face outward by a greedy local search that only ever adds covered points (so
    /// the box stays an inner estimate): bisect along the face's axis from the covered point on
    /// it toward the bounding box's end; then move each other coordinate (x, y within the tile,
    /// the other two of u, v, t) to either end where the point stays covered, and bisect again
    /// (three rounds: coverage extremes of nearly planar edges sit at such corners).
    fn refine(&mut self, b: &UvtBox, cell: &PixelRect, covered: &mut impl FnMut(&Pt) -> bool) {
        let ends = [b.u, b.v, b.t].map(Span::of);
        for k in 0..3 {
            for side in 0..2 {
                let Some(mut p) = self.1[k][side] else {
                    continue;
                };
                for _round in 0..3 {
                    p = self.bisect(
                        p,
                        k,
                        if side == 0 { ends[k].lo } else { ends[k].hi },
                        covered,
                    );
                    for j in 0..5 {
                        if j == k + 2 {
                            continue;
                        }
                        for e in 0..2 {
                            let q = corner(&p, j, e, cell, &ends);
                            if q != p && covered(&q) {
                                self.grow(q);
                                p = q;
                                break;
                            }
                        }
                    }
                }
                self.bisect(
                    p,
                    k,
                    if side == 0 { ends[k].lo } else { ends[k].hi },
                    covered,
                );
            }
        }
    }

    /// Bisect along uvt axis `k` from covered `p` toward `target`; returns the farthest covered
    /// point found (added to the box).
    fn bisect(
        &mut self,
        p: Pt,
        k: usize,
        target: i32,
        covered: &mut impl FnMut(&Pt) -> bool,
    ) -> Pt {
        let far = (p.0, p.1, with_uvt(&p.2, k, target));
        if covered(&far) {
            self.grow(far);
            return far;
        }
        let (mut best, mut out) = (p, target);
        while (out - uvt_of(&best.2)[k]).abs() > 1 {
            let inside = uvt_of(&best.2)[k];
            let mid = inside + (out - inside) / 2;
            let q = (p.0, p.1, with_uvt(&p.2, k, mid));
            if covered(&q) {
                self.grow(q);
                best = q;
            } else {
                out = mid;
            }
        }
        best
    }

    fn contains(&self, s: &Sample) -> bool {
        self.0.is_some_and(|b| {
            b[0].contains(s.u().to_bits())
                && b[1].contains(s.v().to_bits())
                && b[2].contains(s.t().to_bits())
        })
    }
}

/// Dense point `i` of a tile on the core's grids, inside `b`.
fn dense_point(i: u32, cell: &PixelRect, b: &UvtBox, seed: u32) -> (u16, u16, Sample) {
    let d = |dim: u32| sobol_burley::sample(i, dim, seed) as f64;
    let axis = |lo: u16, hi: u16, x: f64| {
        let p = lo as f64 + x * (hi - lo) as f64;
        let px = (p.floor() as u16).min(hi - 1);
        let sub = ((p - px as f64) * 256.0).floor().clamp(0.0, 255.0) as u8;
        (px, SubPixel::from_bits(sub))
    };
    let (px, sx) = axis(cell.x0, cell.x1, d(0));
    let (py, sy) = axis(cell.y0, cell.y1, d(1));
    let raw = |iv: Interval, x: f64| {
        (iv.lo() as f64 + x * (iv.hi() - iv.lo()) as f64)
            .round()
            .clamp(iv.lo() as f64, iv.hi() as f64) as i32
    };
    let s = sample(sx, sy, raw(b.u, d(2)), raw(b.v, d(3)), raw(b.t, d(4)));
    (px, py, s)
}

/// The axis-aligned limit of a frame for bounds tiles of `tile` pixels, at `density` dense
/// points per pixel (low, high; high ≤ 1024 so every tile's points fit one Sobol sequence).
pub fn axis_aligned_limit(
    tris: &[Triangle],
    vp: Viewport,
    pattern: &Pattern,
    tile: u8,
    density: [u32; 2],
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
            let seed = 0x0ac1_e000 ^ ti as u32;
            for cell in s.footprint().cells(tile as u16) {
                let Some(b) = Laine2011.tile(&s, &co, cell, &mut ops) else {
                    continue;
                };
                out.tiles += 1;
                let area = (cell.x1 - cell.x0) as u32 * (cell.y1 - cell.y0) as u32;
                let n = density.map(|d| d * area);
                let mut boxes = [BoxAcc(None, [[None; 2]; 3]); 2];
                let mut tests = 0u64;
                let mut test = |p: &Pt| {
                    tests += 1;
                    sample_test(&s, ScreenPos::of(p.0, p.1, &p.2), &p.2, &mut ops).is_some()
                };
                for k in 0..2 {
                    let first = if k == 0 { 0 } else { n[0] };
                    if k == 1 {
                        boxes[1] = boxes[0];
                    }
                    for i in first..n[k] {
                        let p = dense_point(i, &cell, &b, seed);
                        if test(&p) {
                            boxes[k].grow(p);
                        }
                    }
                }
                for bx in boxes.iter_mut() {
                    bx.refine(&b, &cell, &mut test);
                }
                out.points += tests;
                for py in cell.y0..cell.y1 {
                    for px in cell.x0..cell.x1 {
                        for si in 0..pattern.spp as usize {
                            let smp = &pattern.quant[pattern.index(px, py, si)];
                            let hit =
                                b.contains(smp.u().to_bits(), smp.v().to_bits(), smp.t().to_bits())
                                    && sample_test(&s, ScreenPos::of(px, py, smp), smp, &mut ops)
                                        .is_some();
                            out.covered += hit as u64;
                            for (k, bx) in boxes.iter().enumerate() {
                                let inside = bx.contains(smp);
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
    total.density = density;
    total
}
