//! Coverage of a bounds tile at one lens point and time: the 2D question behind the axis-aligned
//! limit's 3D search.
//!
//! At fixed (u, v, t) the triangle is a 2D triangle in homogeneous clip space (possibly crossing
//! the camera plane). Whether it covers a sample position of a tile is decided (nearly) exactly
//! here: the tile's sample positions span the rectangle `[256·x0, 256·x1 − 1] × [256·y0,
//! 256·y1 − 1]` in 1/256 px; it is clipped (Sutherland–Hodgman, f64) by the three edge
//! half-planes `s·E_k(X, Y) > 0` of the core's coverage definition (`uvt_core::sample`: `n_k =
//! P_{k+1} × P_{k+2}` on the (x, y, w) parts of the vertices at (t, u, v), `s = sign(P_0·n_0)`,
//! `E_k = n_k·(2X/W − 1, 1 − 2Y/H, 1)` — homogeneous, so vertices with w ≤ 0 need no
//! projection). If the clipped polygon is non-empty, grid points inside it are **confirmed with
//! the core's own sample test** (`uvt_core::sample_test` on the frame's setup), and the first one
//! it covers is the witness. So a witness is always a point the core covers (the f64 clip only
//! chooses where to look); the answer errs only by "not covered" where the core covers a grid
//! point that the f64 polygon misses or that lies in a sliver where no tried point is covered —
//! the limit built on it stays an inner estimate.
//!
//! Which grid points are tried: when the polygon's bounding box holds at most
//! [`ENUMERATE_MAX`] grid points, all of them whose f64 edge values are above `−MARGIN_PX`
//! (a quarter of a grid step, so points the f64 clip puts just outside the polygon, where the
//! core's rounded test may still cover, are tried too); otherwise the polygon's vertex centroid
//! and the points halfway from it to each vertex. At most [`CORE_TESTS_MAX`] core tests per call.

use uvt_core::config::precision::DefaultPrecision;
use uvt_core::config::unit::Full;
use uvt_core::{sample, Lens, Ops, PixelRect, Sample, ScreenPos, Setup, SubPixel, Time};

/// Bounding boxes with at most this many grid points are enumerated.
pub const ENUMERATE_MAX: i64 = 64;
/// At most this many core sample tests per call.
pub const CORE_TESTS_MAX: u32 = 8;
/// Grid points this far (px) outside an f64 edge are still tried (a quarter of 1/256 px).
const MARGIN_PX: f64 = 1.0 / 1024.0;

/// One bounds tile of one triangle, ready for coverage questions at single (u, v, t) points.
#[derive(Clone, Debug)]
pub struct TileCover<'a> {
    s: &'a Setup,
    /// per vertex: raw (x, y, w, c) at t = 0 and their change over the shutter
    q: [[f64; 4]; 3],
    d: [[f64; 4]; 3],
    /// viewport width, height
    vp: (f64, f64),
    /// sample-position range of the tile, 1/256 px, inclusive
    g: [[i64; 2]; 2],
}

/// A grid point (1/256 px) and the sample of it at (u, v, t) raw; `None` outside the domain.
pub fn sample_at(xs: u32, ys: u32, uvt: [i32; 3]) -> Option<(ScreenPos, Sample)> {
    let smp = Sample::new(
        SubPixel::from_bits((xs & 255) as u8),
        SubPixel::from_bits((ys & 255) as u8),
        Lens::from_bits(uvt[0]),
        Lens::from_bits(uvt[1]),
        Time::from_bits(uvt[2]),
    )
    .ok()?;
    let (px, py) = (u16::try_from(xs >> 8).ok()?, u16::try_from(ys >> 8).ok()?);
    Some((ScreenPos::of(px, py, &smp), smp))
}

/// Whether the core covers grid point (xs, ys) at (u, v, t).
pub fn core_covers(s: &Setup, xs: u32, ys: u32, uvt: [i32; 3], ops: &mut Ops) -> bool {
    sample_at(xs, ys, uvt).is_some_and(|(pos, smp)| {
        sample::test::<DefaultPrecision, Full>(s, pos, &smp, ops).is_some()
    })
}

impl<'a> TileCover<'a> {
    /// The tile `cell` (pixels, non-empty) of the triangle of setup `s`.
    pub fn new(s: &'a Setup, cell: PixelRect) -> TileCover<'a> {
        let tri = s.tri();
        let (v0, v1) = (tri.vertices(0), tri.vertices(1));
        let pick = |b: [i32; 5]| [b[0], b[1], b[3], b[4]].map(f64::from);
        let q: [[f64; 4]; 3] = core::array::from_fn(|i| pick(v0[i].bits()));
        let r: [[f64; 4]; 3] = core::array::from_fn(|i| pick(v1[i].bits()));
        let d = core::array::from_fn(|i| core::array::from_fn(|f| r[i][f] - q[i][f]));
        let vp = s.viewport();
        let g = [
            [i64::from(cell.x0) * 256, i64::from(cell.x1) * 256 - 1],
            [i64::from(cell.y0) * 256, i64::from(cell.y1) * 256 - 1],
        ];
        TileCover {
            s,
            q,
            d,
            vp: (f64::from(vp.width()), f64::from(vp.height())),
            g,
        }
    }

    /// The lens point (u, v raw, unclamped) at which the triangle's homogeneous vertex centroid
    /// projects to the tile's centre at time `t` (raw), if the summed circle of confusion is not
    /// zero there: the centre line of the tile's covered (u, v, t) set, a seed for the search.
    /// With the vertices (x_i, y_i, w_i, c_i) linear in t, the centroid's screen position at lens
    /// (u, v) is ((X + uC)/W, (Y + vC)/W) (sums over the vertices), so u = (n_x·W − X)/C and v =
    /// (n_y·W − Y)/C with (n_x, n_y) the tile centre in NDC. Only chooses where to look (f64):
    /// every point kept is confirmed by the core.
    pub fn centre_line(&self, t: i32) -> Option<[f64; 2]> {
        let t = f64::from(t) / 65536.0;
        let sum = |f: usize| (0..3).map(|i| self.q[i][f] + t * self.d[i][f]).sum::<f64>();
        let (x, y, w, c) = (sum(0), sum(1), sum(2), sum(3));
        if c.abs() < 1e-9 || !c.is_finite() {
            return None;
        }
        let (vw, vh) = self.vp;
        // Tile centre in px (the grid range is inclusive, 1/256 px) and in NDC.
        let cx = (self.g[0][0] + self.g[0][1] + 1) as f64 / 512.0;
        let cy = (self.g[1][0] + self.g[1][1] + 1) as f64 / 512.0;
        let (nx, ny) = (2.0 * cx / vw - 1.0, 1.0 - 2.0 * cy / vh);
        let uv = [(nx * w - x) / c * 65536.0, (ny * w - y) / c * 65536.0];
        uv.iter().all(|z| z.is_finite()).then_some(uv)
    }

    /// The three edge half-planes `a·X + b·Y + c > 0` (X, Y in 1/256 px), normalised so
    /// `max(|a|, |b|) = 1/256` (values in px); `None` if the triangle is degenerate at (u, v, t).
    fn edges(&self, uvt: [i32; 3]) -> Option<[[f64; 3]; 3]> {
        let [u, v, t] = uvt.map(|x| f64::from(x) / 65536.0);
        let p: [[f64; 3]; 3] = core::array::from_fn(|i| {
            let l = |f: usize| self.q[i][f] + t * self.d[i][f];
            let c = l(3);
            [l(0) + u * c, l(1) + v * c, l(2)]
        });
        let cross = |a: &[f64; 3], b: &[f64; 3]| {
            [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ]
        };
        let n: [[f64; 3]; 3] = core::array::from_fn(|k| cross(&p[(k + 1) % 3], &p[(k + 2) % 3]));
        let det = p[0][0] * n[0][0] + p[0][1] * n[0][1] + p[0][2] * n[0][2];
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let s = det.signum();
        let (w, h) = self.vp;
        let mut out = [[0.0; 3]; 3];
        for (o, nk) in out.iter_mut().zip(&n) {
            // E = n.x·(2X/(256W) − 1) + n.y·(1 − 2Y/(256H)) + n.z, X, Y in 1/256 px.
            let a = s * 2.0 * nk[0] / (256.0 * w);
            let b = -s * 2.0 * nk[1] / (256.0 * h);
            let c = s * (nk[2] - nk[0] + nk[1]);
            let m = a.abs().max(b.abs()) * 256.0;
            if m == 0.0 {
                // A constant edge: all or nothing.
                if c > 0.0 {
                    *o = [0.0, 0.0, 1.0];
                    continue;
                }
                return None;
            }
            *o = [a / m, b / m, c / m];
        }
        Some(out)
    }

    /// The f64 edge values at grid point (xs, ys) (1/256 px) and (u, v, t) raw, in px: the point
    /// is inside the triangle (in the f64 model) iff all three are > 0; `None` if degenerate.
    pub fn edge_values(&self, xs: u32, ys: u32, uvt: [i32; 3]) -> Option<[f64; 3]> {
        let e = self.edges(uvt)?;
        let (x, y) = (f64::from(xs), f64::from(ys));
        Some(e.map(|k| k[0] * x + k[1] * y + k[2]))
    }

    /// A grid point of the tile (1/256 px) that the core covers at (u, v, t) raw, if one is found
    /// (see the module docs for which points are tried).
    pub fn witness(&self, uvt: [i32; 3], ops: &mut Ops) -> Option<(u32, u32)> {
        let e = self.edges(uvt)?;
        let [[x0, x1], [y0, y1]] = self.g.map(|r| r.map(|x| x as f64));
        let mut poly: Vec<[f64; 2]> = vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]];
        for ek in &e {
            poly = clip(&poly, ek, MARGIN_PX);
            if poly.is_empty() {
                return None;
            }
        }
        let val = |p: [f64; 2]| {
            e.iter()
                .map(|k| k[0] * p[0] + k[1] * p[1] + k[2])
                .fold(f64::INFINITY, f64::min)
        };
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in &poly {
            for d in 0..2 {
                lo[d] = lo[d].min(p[d]);
                hi[d] = hi[d].max(p[d]);
            }
        }
        let gl: [i64; 2] = core::array::from_fn(|d| (lo[d].ceil() as i64).max(self.g[d][0]));
        let gh: [i64; 2] = core::array::from_fn(|d| (hi[d].floor() as i64).min(self.g[d][1]));
        if gl[0] > gh[0] || gl[1] > gh[1] {
            return None;
        }
        let mut budget = CORE_TESTS_MAX;
        let mut try_point = |x: i64, y: i64, ops: &mut Ops| -> Option<(u32, u32)> {
            if budget == 0 || val([x as f64, y as f64]) < -MARGIN_PX {
                return None;
            }
            budget -= 1;
            let (xs, ys) = (u32::try_from(x).ok()?, u32::try_from(y).ok()?);
            core_covers(self.s, xs, ys, uvt, ops).then_some((xs, ys))
        };
        if (gh[0] - gl[0] + 1) * (gh[1] - gl[1] + 1) <= ENUMERATE_MAX {
            for y in gl[1]..=gh[1] {
                for x in gl[0]..=gh[0] {
                    if let Some(w) = try_point(x, y, ops) {
                        return Some(w);
                    }
                }
            }
            return None;
        }
        let n = poly.len() as f64;
        let c = [0, 1].map(|d| poly.iter().map(|p| p[d]).sum::<f64>() / n);
        let snap = |p: [f64; 2]| -> [i64; 2] {
            core::array::from_fn(|d| (p[d].round() as i64).clamp(gl[d], gh[d]))
        };
        let mut tried = Vec::with_capacity(poly.len() + 1);
        for p in core::iter::once(c).chain(
            poly.iter()
                .map(|v| [0.5 * (c[0] + v[0]), 0.5 * (c[1] + v[1])]),
        ) {
            let g = snap(p);
            if tried.contains(&g) {
                continue;
            }
            tried.push(g);
            if let Some(w) = try_point(g[0], g[1], ops) {
                return Some(w);
            }
        }
        None
    }
}

/// `poly` clipped by the half-plane `a·X + b·Y + c ≥ −margin` (Sutherland–Hodgman).
fn clip(poly: &[[f64; 2]], e: &[f64; 3], margin: f64) -> Vec<[f64; 2]> {
    let f = |p: &[f64; 2]| e[0] * p[0] + e[1] * p[1] + e[2] + margin;
    let mut out = Vec::with_capacity(poly.len() + 1);
    for (i, p) in poly.iter().enumerate() {
        let q = &poly[(i + 1) % poly.len()];
        let (fp, fq) = (f(p), f(q));
        if fp >= 0.0 {
            out.push(*p);
        }
        if (fp >= 0.0) != (fq >= 0.0) {
            let s = fp / (fp - fq);
            out.push([p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])]);
        }
    }
    out
}
