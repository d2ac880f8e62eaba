//! The swept cone's faces: the points of the swept, lens-extended triangle, the faces of their
//! cone, their conservative widening for the bounded test (module docs of [`crate::bounds::hull`]).
#![warn(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_possible_wrap
)]

use crate::config::class::Class;
use crate::config::formats::SUBPIXEL_BITS;
use crate::input::{PixelRect, Triangle, Viewport, C, W, X, Y};
use crate::stats::Ops;

/// One pixel in sub-pixel units, 2^SUBPIXEL_BITS = 2^8 (a constant shift, checked by the compiler).
pub(crate) const SUBPIXEL_ONE: i128 = 1i128 << SUBPIXEL_BITS;

/// Most faces kept per triangle (a cone over 24 points has at most 24 faces; the degenerate
/// planar case keeps both orientations of one plane). Dropping a face is conservative.
pub const MAX_FACES: usize = 24;

/// One face of the swept cone as an affine function of the sample position: `a·xs + b·ys + c`
/// (xs, ys in 1/256 px) is ≥ 0 for every direction the triangle may cover.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct HullFace {
    pub(crate) a: i128,
    pub(crate) b: i128,
    pub(crate) c: i128,
}

impl HullFace {
    /// Coefficients `(a, b, c)`.
    pub fn coeffs(&self) -> (i128, i128, i128) {
        (self.a, self.b, self.c)
    }
}

/// Per-triangle faces of the swept cone.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HullCoeffs {
    pub(crate) faces: [HullFace; MAX_FACES],
    pub(crate) len: usize,
}

impl HullCoeffs {
    /// No faces: nothing is culled.
    pub const EMPTY: HullCoeffs = HullCoeffs {
        faces: [HullFace { a: 0, b: 0, c: 0 }; MAX_FACES],
        len: 0,
    };

    /// The faces found in setup.
    pub fn faces(&self) -> &[HullFace] {
        self.faces.get(..self.len).unwrap_or(&[])
    }

    /// Every face's c raised by `|a|·ρx + |b|·ρy` (module docs, conservative epsilon); a face
    /// whose widened c overflows is dropped (dropping a face only culls less). 4 ops per face.
    pub fn widened(&self, rho: [i128; 2], ops: &mut Ops) -> HullCoeffs {
        let mut out = HullCoeffs::EMPTY;
        for f in self.faces() {
            ops.setup = ops.setup.saturating_add(4);
            let c =
                f.a.checked_abs()
                    .and_then(|a| a.checked_mul(rho[0]))
                    .and_then(|m| {
                        let n = f.b.checked_abs()?.checked_mul(rho[1])?;
                        f.c.checked_add(m)?.checked_add(n)
                    });
            let (Some(c), Some(slot)) = (c, out.faces.get_mut(out.len)) else {
                continue;
            };
            *slot = HullFace { c, ..*f };
            out.len = out.len.saturating_add(1);
        }
        out
    }
}

/// The projected perturbation `[ρx, ρy]` (1/256 px) of the bounded test's vertices (module docs,
/// conservative epsilon): `ceil(128·E·(ε + R·ε_w)/(w_min − ε_w))` per axis, with `R` the largest
/// `ceil(|coordinate|/w)` over the hull points. `None` when some hull point has `w ≤ ε_w` (the
/// bound is not derived there) or on overflow (outside the domain); then no face may be kept.
/// Ranges: |x ± c| ≤ 2^30, 1 ≤ w ≤ 2^29, ε < 2^24, ε_w ≤ 2^14 (1 for the bounded test, the
/// rounding residual for the planar one), E ≤ 2^11: R ≤ 2^30, 128·E·(ε + R·ε_w) < 2^63; all in
/// checked i128.
pub fn eps_margin(
    pts: &[[i64; 3]],
    eps: &crate::setup::eps::Eps,
    vp: Viewport,
    ops: &mut Ops,
) -> Option<[i128; 2]> {
    let ew = i128::from(eps.w());
    let mut wmin: Option<i128> = None;
    let mut r = [0i128; 2];
    for p in pts {
        ops.setup = ops.setup.saturating_add(6);
        let w = i128::from(*p.get(2)?);
        if w <= ew {
            return None;
        }
        wmin = Some(wmin.map_or(w, |m| m.min(w)));
        for (ri, &x) in r.iter_mut().zip(p.iter()) {
            let q = crate::arith::div::ceil_div(i128::from(x).checked_abs()?, w)?;
            *ri = (*ri).max(q);
        }
    }
    let den = wmin?.checked_sub(ew)?;
    let ext = [vp.width(), vp.height()];
    let mut rho = [0i128; 2];
    for ((out, (&e, &ri)), &ex) in rho
        .iter_mut()
        .zip(ext.iter().zip(r.iter()))
        .zip(eps.x().iter())
    {
        ops.setup = ops.setup.saturating_add(5);
        let num = ri
            .checked_mul(ew)?
            .checked_add(i128::from(ex))?
            .checked_mul(128i128.checked_mul(i128::from(e))?)?;
        *out = crate::arith::div::ceil_div(num, den)?;
    }
    Some(rho)
}

/// The (at most 24) homogeneous points (x, y, w) whose cone contains every vertex at every
/// (t, u, v) the triangle's class can vary over. Raw I16F16: |x ± c| ≤ 2^30, |w| ≤ 2^29.
pub fn swept_points(tri: &Triangle, class: Class) -> ([[i64; 3]; 24], usize) {
    let mut pts = [[0i64; 3]; 24];
    let mut n = 0usize;
    let ends: &[[[i32; 5]; 3]] = if class.motion() {
        &tri.v
    } else {
        tri.v.get(..1).unwrap_or(&[])
    };
    let lens: &[(i64, i64)] = if class.defocus() {
        &[(-1, -1), (-1, 1), (1, -1), (1, 1)]
    } else {
        &[(0, 0)]
    };
    for end in ends {
        for p in end {
            for &(su, sv) in lens {
                if let Some(slot) = pts.get_mut(n) {
                    *slot = lens_point(p, su, sv);
                }
                n = n.saturating_add(1);
            }
        }
    }
    (pts, n.min(24))
}

/// `(x + su·c, y + sv·c, w)` of raw vertex `p` for su, sv ∈ {−1, 0, 1}.
#[allow(clippy::arithmetic_side_effects, clippy::indexing_slicing)]
fn lens_point(p: &[i32; 5], su: i64, sv: i64) -> [i64; 3] {
    // Constant indices X, Y, W, C < 5; |x|, |c| ≤ 2^29 and |su| ≤ 1: |x + su·c| ≤ 2^30.
    let (x, y, w, c) = (p[X] as i64, p[Y] as i64, p[W] as i64, p[C] as i64);
    [x + su * c, y + sv * c, w]
}

/// `p × q`, exact: |p|, |q| ≤ 2^30 so each product ≤ 2^60 and each component < 2^61.
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn cross(p: &[i64; 3], q: &[i64; 3]) -> [i128; 3] {
    let [px, py, pw] = p.map(i128::from);
    let [qx, qy, qw] = q.map(i128::from);
    [py * qw - pw * qy, pw * qx - px * qw, px * qy - py * qx]
}

/// `n·p`, exact: |n| < 2^61 and |p| ≤ 2^30, so each product < 2^91 and the sum < 2^93.
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn dot(n: &[i128; 3], p: &[i64; 3]) -> i128 {
    n[0] * i128::from(p[0]) + n[1] * i128::from(p[1]) + n[2] * i128::from(p[2])
}

/// Whether `m` and `n` are positive multiples of each other (same face); None on overflow.
fn same_face(m: &[i128; 3], n: &[i128; 3]) -> Option<bool> {
    // |m|, |n| < 2^61: products < 2^122, differences < 2^123, exact; checked anyway.
    let c0 = m[1]
        .checked_mul(n[2])?
        .checked_sub(m[2].checked_mul(n[1])?)?;
    let c1 = m[2]
        .checked_mul(n[0])?
        .checked_sub(m[0].checked_mul(n[2])?)?;
    let c2 = m[0]
        .checked_mul(n[1])?
        .checked_sub(m[1].checked_mul(n[0])?)?;
    let d = m[0]
        .checked_mul(n[0])?
        .checked_add(m[1].checked_mul(n[1])?)?
        .checked_add(m[2].checked_mul(n[2])?)?;
    Some(c0 == 0 && c1 == 0 && c2 == 0 && d > 0)
}

/// `n·d(xs, ys)` as `a·xs + b·ys + c` with d from `sample::direction`:
/// d = ((2xs − 256W)·H, (256H − 2ys)·W, 256·W·H), so a = 2H·n0, b = −2W·n1,
/// c = 256·W·H·(n2 + n1 − n0). |n| < 2^61, W, H ≤ 2^11: |a|, |b| < 2^73, |c| < 2^93.
pub(crate) fn face_of(n: &[i128; 3], vp: Viewport) -> Option<HullFace> {
    let (w, h) = (i128::from(vp.width()), i128::from(vp.height()));
    let one = SUBPIXEL_ONE;
    let a = n[0].checked_mul(h.checked_mul(2)?)?;
    let b = n[1].checked_mul(w.checked_mul(-2)?)?;
    let s = n[2].checked_add(n[1])?.checked_sub(n[0])?;
    let c = s.checked_mul(one.checked_mul(w)?.checked_mul(h)?)?;
    Some(HullFace { a, b, c })
}

/// The faces of the cone of `pts` by trying every pair of points (O(n³)): the definition, used
/// where some point has w ≤ 0 and as the reference of the gift wrapping
/// ([`crate::bounds::hull::wrap`]).
pub fn pair_faces(pts: &[[i64; 3]], vp: Viewport, ops: &mut Ops) -> HullCoeffs {
    let mut normals = [[0i128; 3]; MAX_FACES];
    let mut out = HullCoeffs {
        faces: [HullFace::default(); MAX_FACES],
        len: 0,
    };
    for (i, p) in pts.iter().enumerate() {
        for q in pts.iter().skip(i.saturating_add(1)) {
            let n = cross(p, q);
            ops.setup = ops.setup.saturating_add(9);
            if n == [0; 3] {
                continue;
            }
            let (mut pos, mut neg) = (false, false);
            for r in pts {
                let s = dot(&n, r);
                ops.setup = ops.setup.saturating_add(6);
                pos |= s > 0;
                neg |= s < 0;
                if pos && neg {
                    break;
                }
            }
            let candidates: &[i128] = match (pos, neg) {
                (true, true) => &[],
                (false, true) => &[-1],
                (true, false) => &[1],
                (false, false) => &[1, -1],
            };
            for &sign in candidates {
                let m = n.map(|v| v.saturating_mul(sign));
                let known = normals.get(..out.len).unwrap_or(&[]);
                ops.setup = ops
                    .setup
                    .saturating_add(15u64.saturating_mul(known.len() as u64));
                if known.iter().any(|k| same_face(k, &m) != Some(false)) {
                    continue;
                }
                let (Some(face), Some(slot), Some(nslot)) = (
                    face_of(&m, vp),
                    out.faces.get_mut(out.len),
                    normals.get_mut(out.len),
                ) else {
                    continue;
                };
                *slot = face;
                *nslot = m;
                out.len = out.len.saturating_add(1);
                ops.setup = ops.setup.saturating_add(8);
            }
        }
    }
    out
}

/// Whether `face` is negative at every sample position of `tile` (then the tile is culled);
/// `false` on overflow. Counts 7 operations per face in `ops.bounds`. The direct form, kept as
/// the reference of [`HullTiles::culls`] (`core/src/verify/hull_reference.rs`).
pub fn face_culls(face: &HullFace, tile: PixelRect, ops: &mut Ops) -> bool {
    ops.bounds = ops.bounds.saturating_add(7);
    let one = SUBPIXEL_ONE;
    let lo = |p: u16| i128::from(p).checked_mul(one);
    let hi = |p: u16| {
        i128::from(p)
            .checked_mul(one)
            .and_then(|v| v.checked_sub(1))
    };
    let xs = if face.a > 0 { hi(tile.x1) } else { lo(tile.x0) };
    let ys = if face.b > 0 { hi(tile.y1) } else { lo(tile.y0) };
    let max = xs.zip(ys).and_then(|(xs, ys)| {
        face.a
            .checked_mul(xs)?
            .checked_add(face.b.checked_mul(ys)?)?
            .checked_add(face.c)
    });
    matches!(max, Some(m) if m < 0)
}
