//! f64 reference — stage 2, per-tile bounds (mirrors `uvt_core::bounds::laine::Laine2011`).
//!
//! The same Laine 2011 construction in f64 with exact divisions and no outward rounding: u/v from
//! the interpolated lens-corner boxes, t from the dual-space bounding lines over the footprint.

use uvt_core::PixelRect;

use super::setup::{axis, solve_le, RefSetup};

/// A (u, v, t) box in reals.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RefBox {
    /// lens u
    pub u: (f64, f64),
    /// lens v
    pub v: (f64, f64),
    /// time
    pub t: (f64, f64),
}

impl RefBox {
    /// Whether (u, v, t) is inside (closed).
    pub fn contains(&self, u: f64, v: f64, t: f64) -> bool {
        let i = |r: (f64, f64), x: f64| r.0 <= x && x <= r.1;
        i(self.u, u) && i(self.v, v) && i(self.t, t)
    }
}

fn meet(a: (f64, f64), b: (f64, f64)) -> Option<(f64, f64)> {
    let r = (a.0.max(b.0), a.1.min(b.1));
    (r.0 <= r.1).then_some(r)
}

/// s ∈ [0,1] (lens parameter) for which the interpolated box of one axis overlaps [x0, x1].
fn lens_s(s: &RefSetup, ax: usize, x0: f64, x1: f64) -> Option<(f64, f64)> {
    let b = s.axes[ax];
    let mut r = (0.0, 1.0);
    if let Some([m0, m1]) = b.lo {
        r = solve_le(m1 - m0, x1 - m0, r.0, r.1)?;
    }
    if let Some([h0, h1]) = b.hi {
        r = solve_le(h0 - h1, h0 - x0, r.0, r.1)?;
    }
    Some(r)
}

/// t interval of one axis for pixel range [x0, x1] inside the footprint.
fn dual_t(s: &RefSetup, ax: usize, x0: f64, x1: f64) -> Option<(f64, f64)> {
    let (fa, fb) = if ax == 0 {
        (s.footprint.x0 as f64, s.footprint.x1 as f64)
    } else {
        (s.footprint.y0 as f64, s.footprint.y1 as f64)
    };
    let e = if ax == 0 { s.vp.0 } else { s.vp.1 } as f64;
    // δmin/δmax at the footprint ends, t = 0 and 1.
    let ends = |vs: &[[f64; 5]; 3], xi: f64| {
        let (mut lo, mut hi) = (f64::MAX, f64::MIN);
        for v in vs {
            let (a, c) = axis(v, ax);
            let d = (a + v[3]) * e - 2.0 * v[3] * xi;
            lo = lo.min(d - c.abs() * e);
            hi = hi.max(d + c.abs() * e);
        }
        (lo, hi)
    };
    let line = |va: f64, vb: f64, x: f64| va + (vb - va) * (x - fa) / (fb - fa);
    let per_t = |vs: &[[f64; 5]; 3]| {
        let (la, ha) = ends(vs, fa);
        let (lb, hb) = ends(vs, fb);
        (
            line(la, lb, x0).min(line(la, lb, x1)),
            line(ha, hb, x0).max(line(ha, hb, x1)),
        )
    };
    let (lo0, hi0) = per_t(&s.tri.t0);
    let (lo1, hi1) = per_t(&s.tri.t1);
    let r = solve_le(lo1 - lo0, -lo0, 0.0, 1.0)?;
    solve_le(hi0 - hi1, hi0, r.0, r.1)
}

/// Laine 2011 bounds of one tile (pixels `cell`, clipped to the footprint).
pub fn tile(s: &RefSetup, cell: PixelRect) -> Option<RefBox> {
    let mut b = RefBox {
        u: (-1.0, 1.0),
        v: (-1.0, 1.0),
        t: s.span,
    };
    let r = [
        (cell.x0 as f64, cell.x1 as f64),
        (cell.y0 as f64, cell.y1 as f64),
    ];
    for (ax, &(p0, p1)) in r.iter().enumerate() {
        if s.class.defocus() {
            let (s0, s1) = lens_s(s, ax, p0, p1)?;
            let lens = (2.0 * s0 - 1.0, 2.0 * s1 - 1.0);
            if ax == 0 {
                b.u = lens;
            } else {
                b.v = lens;
            }
        }
        if s.class.motion() {
            b.t = meet(b.t, dual_t(s, ax, p0, p1)?)?;
        }
    }
    Some(b)
}
