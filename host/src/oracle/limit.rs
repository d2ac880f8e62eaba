//! The axis-aligned limit: per bounds tile, an estimate of the tightest axis-aligned (u, v, t) box
//! of the triangle's coverage set, and how many pattern samples such a box would test.
//!
//! For every triangle and every bounds tile that Laine 2011 keeps (a conservative bound: the tiles
//! it culls hold no covered sample — tested in `tests/tests/model/conservative.rs`), the covered set is
//! the set of points on the core's grids (x, y in 1/256 px within the tile, u, v, t raw inside
//! Laine's box) that the core's sample test covers; its box is what the tightest conservative
//! axis-aligned bound must test. Its six faces are extremes of the projection of that set onto
//! (u, v, t): the set `S` of lens points and times at which the tile holds a covered grid point.
//!
//! [`Method::Clip3`] searches `S` directly: membership of one (u, v, t) is the 2D
//! question of [`super::clip::TileCover`] (the tile clipped by the triangle's edge half-planes at
//! (u, v, t), then a grid point inside confirmed by the core's own sample test), and
//! [`super::search::BoxSearch`] estimates the box of `S` from inside — dense (Owen-scrambled Sobol)
//! points, then a face search (evolution strategy + bisection) — in 3D for a triangle with motion
//! and defocus, in t alone for motion only, in (u, v) alone for defocus only (the other faces are
//! Laine's, i.e. the whole domain, attained because coverage does not depend on them), and not at
//! all for a static triangle. [`Method::Points5`] is the earlier search in 5D (x, y, u, v, t),
//! each point one core sample test; it converges slowly on tiny, strongly blurred triangles and
//! is kept for comparison.
//!
//! [`Method::Lines3`] (the default) is [`Method::Clip3`] plus two moves aimed at where `Clip3`
//! fell short on tiny, strongly blurred triangles (quick 'dense both ×2': 6% STE gap between its
//! efforts, covered pattern samples outside the high-effort box). Measured there, the faces that
//! grew between `Clip3`'s efforts were mostly t faces whose high-effort point has u (or v) at an
//! end of the domain — the covered set is a thin tube slanted in (u, t) and (v, t) (the
//! triangle's track through the tile as the lens point and time change), and a t extreme is the
//! tip where the tube leaves the domain through a u or v end — and the covered samples outside
//! were mostly in tiles where no point was found at all. So, at each effort:
//! - **centre-line seeds** ([`super::clip::TileCover::centre_line`]): for spread times, the lens
//!   point at which the triangle's vertex centroid projects to the tile's centre (a closed form:
//!   linear equations in u and v), and the times where that line leaves Laine's (u, v) box (the
//!   tube's tips), clamped into the box and asked like any point;
//! - **line pushes** ([`super::search::BoxSearch::push_lines`]) after the face search: from each
//!   face's point, bisect along each other active axis toward each end of the domain, then along
//!   the face's axis outward.
//!
//! Both only choose which points are asked; a point counts only if the clip finds a grid point
//! the core covers, so the estimate stays an inner one.
//!
//! Either way, every face of the estimate is attained by a point the core covers, so the
//! estimated box lies inside the true box, and the count `|{pattern samples of the tile inside
//! the estimated box or covered}|` is at most what any conservative axis-aligned bound tests:
//! **the estimated limit STE errs on the optimistic side** (it is ≥ the true limit STE; it can
//! only fall as effort grows).
//!
//! Two efforts are evaluated, nested (the second continues the first's dense sequence and starts
//! its faces from the first's box), so their gap shows convergence; the covered pattern samples
//! outside each estimated box are counted too — each one proves that box too small, so a count
//! of 0 at the second effort and a small gap are the evidence of convergence. A strategy that is
//! not axis-aligned (per-sample predicates) may test fewer samples than this limit.

use rayon::prelude::*;
use uvt_core::bounds::strategy::BoundsStrategy;
use uvt_core::config::precision::DefaultPrecision;
use uvt_core::config::unit::Full;
use uvt_core::{
    sample, Laine2011, Ops, Outcome, PixelRect, ScreenPos, Setup, Triangle, UvtBox, Viewport,
};

use crate::scene::pattern::Pattern;

use super::clip::{core_covers, TileCover};
use super::search::{BoxSearch, Effort, P5};

/// How a tile's limit box is searched.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub enum Method {
    /// as [`Method::Clip3`], plus seeds on the tile's centre line and line pushes of every face
    /// ([`super::search::BoxSearch::push_lines`]) after the face search, at each effort
    #[default]
    Lines3,
    /// in (u, v, t) (or its active part), each point answered by the 2D clip + a core test
    Clip3,
    /// in (x, y, u, v, t), each point one core sample test (the earlier limit)
    Points5,
}

impl Method {
    /// Label for tables.
    pub fn label(self) -> &'static str {
        match self {
            Method::Lines3 => "uvt search + 2D clip + centre-line seeds + line pushes",
            Method::Clip3 => "uvt search + 2D clip",
            Method::Points5 => "5D points",
        }
    }
}

/// Counters of the axis-aligned limit at two efforts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Limit {
    /// how the boxes were searched
    pub method: Method,
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
    /// membership questions of the search, per effort (the second effort's count includes the
    /// first's): points of `S` asked ([`Method::Clip3`], [`Method::Lines3`]) or sample tests
    /// ([`Method::Points5`])
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

/// A covered point: grid position (1/256 px) and (u, v, t) raw.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Witness {
    /// x, y in 1/256 px
    pub xy: [u32; 2],
    /// u, v, t raw
    pub uvt: [i32; 3],
}

/// One tile's estimated limit box at one effort: `[lo, hi]` per u, v, t, and the covered point
/// on each face (`faces[d][side]`, `d` = u, v, t, side 0 low, 1 high).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TileBox {
    /// per u, v, t: `[lo, hi]`
    pub uvt: [[i32; 2]; 3],
    /// the covered point attaining each face
    pub faces: [[Witness; 2]; 3],
}

impl TileBox {
    /// Whether (u, v, t) lies in the box.
    pub fn contains(&self, uvt: [i32; 3]) -> bool {
        self.uvt
            .iter()
            .zip(uvt)
            .all(|(iv, x)| iv[0] <= x && x <= iv[1])
    }
}

/// The estimated limit boxes of tile `cell` (inside Laine's box `b`) at the two nested efforts
/// (`None`: no covered point found), and the membership questions asked up to each.
pub fn tile_limit(
    s: &Setup,
    cell: PixelRect,
    b: &UvtBox,
    method: Method,
    effort: [Effort; 2],
    seed: u64,
    ops: &mut Ops,
) -> ([Option<TileBox>; 2], [u64; 2]) {
    let area = u32::from(cell.x1 - cell.x0) * u32::from(cell.y1 - cell.y0);
    let uvt_lo = [b.u.lo(), b.v.lo(), b.t.lo()];
    let uvt_hi = [b.u.hi(), b.v.hi(), b.t.hi()];
    // 1/256 px: x1, y1 ≤ 2^16, so 256·x1 ≤ 2^24 fits i32.
    let (xy_lo, xy_hi) = match method {
        Method::Clip3 | Method::Lines3 => ([0, 0], [0, 0]),
        Method::Points5 => (
            [i32::from(cell.x0) * 256, i32::from(cell.y0) * 256],
            [i32::from(cell.x1) * 256 - 1, i32::from(cell.y1) * 256 - 1],
        ),
    };
    let lo: P5 = [xy_lo[0], xy_lo[1], uvt_lo[0], uvt_lo[1], uvt_lo[2]];
    let hi: P5 = [xy_hi[0], xy_hi[1], uvt_hi[0], uvt_hi[1], uvt_hi[2]];
    let class = s.class();
    let (lens, time) = (class.defocus(), class.motion());
    let active = match method {
        Method::Clip3 | Method::Lines3 => [false, false, lens, lens, time],
        Method::Points5 => [true; 5],
    };
    let mut search = BoxSearch::new(lo, hi, 0x0ac1_e000_0000_0000 ^ seed).with_active(active);
    let cover = TileCover::new(s, cell);
    let tests = std::cell::Cell::new(0u64);
    let uvt_of = |p: &P5| [p[2], p[3], p[4]];
    let mut test = |p: &P5| {
        tests.set(tests.get() + 1);
        match method {
            Method::Clip3 | Method::Lines3 => cover.witness(uvt_of(p), ops).is_some(),
            Method::Points5 => match (u32::try_from(p[0]), u32::try_from(p[1])) {
                (Ok(x), Ok(y)) => core_covers(s, x, y, uvt_of(p), ops),
                _ => false,
            },
        }
    };
    let mut found = [None, None];
    let mut points = [0; 2];
    for (k, e) in effort.iter().enumerate() {
        // A static triangle's set is all of Laine's box or empty: one point decides.
        let n = if active.iter().any(|&a| a) {
            e.density.saturating_mul(area)
        } else {
            1
        };
        if method == Method::Lines3 && lens {
            search.seed(centre_seeds(&cover, b, time, n), &mut test);
        }
        search.dense(n, &mut test);
        search.push_faces(e.steps, &mut test);
        if method == Method::Lines3 {
            search.push_lines(&mut test);
        }
        found[k] = search.bounds().zip(search.faces());
        points[k] = tests.get();
    }
    let mut boxes = [None, None];
    for (k, f) in found.iter().enumerate() {
        let Some((bb, ext)) = f else {
            continue;
        };
        let mut faces = [[Witness {
            xy: [0, 0],
            uvt: [0; 3],
        }; 2]; 3];
        for d in 0..3 {
            for side in 0..2 {
                let p = ext[d + 2][side];
                let xy = match method {
                    // Deterministic: the same (u, v, t) finds the same witness again.
                    Method::Clip3 | Method::Lines3 => cover
                        .witness(uvt_of(&p), ops)
                        .map_or([u32::MAX; 2], |(x, y)| [x, y]),
                    Method::Points5 => [p[0], p[1]].map(|x| u32::try_from(x).unwrap_or(u32::MAX)),
                };
                faces[d][side] = Witness {
                    xy,
                    uvt: uvt_of(&p),
                };
            }
        }
        boxes[k] = Some(TileBox {
            uvt: [bb[2], bb[3], bb[4]],
            faces,
        });
    }
    (boxes, points)
}

/// Seeds for a tile's search with defocus: points of the centre line ([`TileCover::centre_line`])
/// at `n` times spread over Laine's t range (one time, its `lo`, without motion), and where the
/// centre line leaves Laine's (u, v) box (the tips of the covered set, found by bisection on t
/// between the spread times), each clamped into the box.
fn centre_seeds(cover: &TileCover, b: &UvtBox, time: bool, n: u32) -> Vec<P5> {
    let (tl, th) = (b.t.lo(), b.t.hi());
    let ts: Vec<i32> = if time {
        let span = f64::from(th) - f64::from(tl);
        (0..n)
            .map(|i| tl + ((f64::from(i) + 0.5) / f64::from(n) * span) as i32)
            .collect()
    } else {
        vec![tl]
    };
    let lo = [f64::from(b.u.lo()), f64::from(b.v.lo())];
    let hi = [f64::from(b.u.hi()), f64::from(b.v.hi())];
    let inside = |t: i32| {
        cover
            .centre_line(t)
            .is_some_and(|uv| (0..2).all(|d| lo[d] <= uv[d] && uv[d] <= hi[d]))
    };
    let at = |t: i32| -> Option<P5> {
        let uv = cover.centre_line(t)?;
        // Clamped into Laine's box, so the casts are in range.
        let c = |d: usize| uv[d].clamp(lo[d], hi[d]).round() as i32;
        Some([0, 0, c(0), c(1), t])
    };
    let mut out: Vec<P5> = ts.iter().filter_map(|&t| at(t)).collect();
    // The ends of the centre line's stretch inside the box: between consecutive times where
    // it is inside and outside, bisect on t (the line is a rational function of t).
    let mut ends: Vec<i32> = [tl, th].into_iter().filter(|&t| inside(t)).collect();
    let mut stops = vec![tl];
    stops.extend(ts.iter().copied());
    stops.push(th);
    for w in stops.windows(2) {
        let (mut a, mut z) = (w[0], w[1]);
        let ia = inside(a);
        if ia == inside(z) {
            continue;
        }
        while z - a > 1 {
            let m = a + (z - a) / 2;
            if inside(m) == ia {
                a = m;
            } else {
                z = m;
            }
        }
        ends.push(if ia { a } else { z });
    }
    out.extend(ends.into_iter().filter_map(at));
    out
}

/// The axis-aligned limit of a frame for bounds tiles of `tile` pixels at two efforts (the
/// second continues the first; `effort[1].density` ≥ `effort[0].density`, and at most 2^16 per
/// pixel so a tile's points stay within one Sobol sequence), searched by `method`.
pub fn axis_aligned_limit(
    tris: &[Triangle],
    vp: Viewport,
    pattern: &Pattern,
    tile: u8,
    effort: [Effort; 2],
    method: Method,
) -> Limit {
    let mut total = tris
        .par_iter()
        .enumerate()
        .map(|(ti, tri)| {
            let mut ops = Ops::default();
            let mut out = Limit::default();
            let Outcome::Visible(s) =
                uvt_core::setup::<uvt_core::DefaultPrecision, uvt_core::Full>(tri, vp, &mut ops)
            else {
                return out;
            };
            let co = Laine2011.prepare::<Full>(&s, &mut ops);
            for cell in s.footprint().cells(tile as u16) {
                let Some(b) = Laine2011.tile::<Full>(&s, &co, cell, &mut ops) else {
                    continue;
                };
                out.tiles += 1;
                let seed = (ti as u64) << 32 ^ u64::from(cell.x0) << 16 ^ u64::from(cell.y0);
                let (found, points) = tile_limit(&s, cell, &b, method, effort, seed, &mut ops);
                for (o, p) in out.points.iter_mut().zip(points) {
                    *o += p;
                }
                for py in cell.y0..cell.y1 {
                    for px in cell.x0..cell.x1 {
                        for si in 0..pattern.spp as usize {
                            let smp = &pattern.quant[pattern.index(px, py, si)];
                            let uvt = [smp.u().to_bits(), smp.v().to_bits(), smp.t().to_bits()];
                            let hit = b.contains(uvt[0], uvt[1], uvt[2])
                                && sample::test::<DefaultPrecision, Full>(
                                    &s,
                                    ScreenPos::of(px, py, smp),
                                    smp,
                                    &mut ops,
                                )
                                .is_some();
                            out.covered += hit as u64;
                            for (k, f) in found.iter().enumerate() {
                                let inside = f.is_some_and(|f| f.contains(uvt));
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
    total.method = method;
    total
}
