//! Swept-hull tile culling (after McGuire et al. 2010's 6-vertex hull, expanded by the CoC; for a
//! static triangle the standard hierarchical tile-vs-triangle edge test), composable with any
//! strategy: [`HullCull`] culls the tile when no sample position of it can be covered at any
//! (t, u, v), and otherwise returns the inner strategy's bounds.
//!
//! **Why it is conservative (also when vertices cross the camera plane).** No projection is
//! done; everything is in homogeneous clip space (x, y, w). At (t, u, v) vertex k is
//! `P_k = lerp(q_k, r_k, t) + (u·c_k(t), v·c_k(t), 0)` with `c_k(t) = lerp(c_k0, c_k1, t)`. For
//! fixed signs σu, σv ∈ {±1} the point `A(t) = lerp(q, r, t) + (σu·c(t), σv·c(t), 0)` is affine in
//! t, so it is a convex combination of A(0) and A(1); and for fixed t, u ∈ [−1, 1] makes
//! u·c(t) a convex combination of ±c(t) (same for v). So P_k(t, u, v) lies in the convex hull
//! of the 8 points {q_k, r_k} + (±c, ±c, 0) (with the CoC of the same end), i.e. every vertex
//! lies in the convex hull H of at most 24 points (3 for a static in-focus triangle, 6 for motion
//! only, 12 for defocus only). The sample test (`sample.rs`) covers the direction d of a sample
//! only if d = Σ b_k·P_k with all b_k ≥ 0 (Cramer's rule: b_k = E_k/det, and coverage needs every
//! E_k·sign(det) ≥ 0), so d lies in the convex cone K spanned by H. A plane through the origin
//! with normal n and n·p ≥ 0 for all 24 points has n·d ≥ 0 for every d ∈ K. Setup finds all such
//! planes spanned by two of the points (the faces of K; none when K is not pointed, e.g. when the
//! points surround the camera, then nothing is culled). The direction of a sample at sub-pixel
//! position (xs, ys) (1/256 px) is affine in (xs, ys) (`sample::direction`), so n·d is
//! `a·xs + b·ys + c`; over the tile's closed range of sample positions
//! (xs ∈ [256·X0, 256·X1 − 1], same for ys) its maximum is at the corner picked by the signs of
//! a and b. If that maximum is < 0 for one face, no sample of the tile can be covered at any
//! (t, u, v): the tile is culled. Every product is exact (ranges below) or checked; an overflow
//! (outside the documented domain) keeps the tile.
#![warn(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_possible_wrap
)]

use crate::bounds::BoundsStrategy;
use crate::formats::SUBPIXEL_BITS;
use crate::input::{PixelRect, Triangle, Viewport, C, W, X, Y};
use crate::setup::{Class, Setup};
use crate::stats::Ops;

/// Most faces kept per triangle (a cone over 24 points has at most 24 faces; the degenerate
/// planar case keeps both orientations of one plane). Dropping a face is conservative.
pub const MAX_FACES: usize = 24;

/// One face of the swept cone as an affine function of the sample position: `a·xs + b·ys + c`
/// (xs, ys in 1/256 px) is ≥ 0 for every direction the triangle may cover.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct HullFace {
    a: i128,
    b: i128,
    c: i128,
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
    faces: [HullFace; MAX_FACES],
    len: usize,
}

impl HullCoeffs {
    /// The faces found in setup.
    pub fn faces(&self) -> &[HullFace] {
        self.faces.get(..self.len).unwrap_or(&[])
    }
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
fn cross(p: &[i64; 3], q: &[i64; 3]) -> [i128; 3] {
    let [px, py, pw] = p.map(i128::from);
    let [qx, qy, qw] = q.map(i128::from);
    [py * qw - pw * qy, pw * qx - px * qw, px * qy - py * qx]
}

/// `n·p`, exact: |n| < 2^61 and |p| ≤ 2^30, so each product < 2^91 and the sum < 2^93.
#[allow(clippy::arithmetic_side_effects)]
fn dot(n: &[i128; 3], p: &[i64; 3]) -> i128 {
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
fn face_of(n: &[i128; 3], vp: Viewport) -> Option<HullFace> {
    let (w, h) = (i128::from(vp.width()), i128::from(vp.height()));
    let one = 1i128 << SUBPIXEL_BITS;
    let a = n[0].checked_mul(h.checked_mul(2)?)?;
    let b = n[1].checked_mul(w.checked_mul(-2)?)?;
    let s = n[2].checked_add(n[1])?.checked_sub(n[0])?;
    let c = s.checked_mul(one.checked_mul(w)?.checked_mul(h)?)?;
    Some(HullFace { a, b, c })
}

/// The faces of the cone of `pts`: every plane through the origin and two points that has all
/// points on one side (both orientations when all points lie on it).
pub fn hull_faces(pts: &[[i64; 3]], vp: Viewport, ops: &mut Ops) -> HullCoeffs {
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
/// `false` on overflow. Counts 7 operations per face in `ops.bounds`.
pub fn face_culls(face: &HullFace, tile: PixelRect, ops: &mut Ops) -> bool {
    ops.bounds = ops.bounds.saturating_add(7);
    let one = 1i128 << SUBPIXEL_BITS;
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

/// Tile culling by the swept cone's faces, in front of strategy `S`.
#[derive(Clone, Copy, Debug, Default)]
pub struct HullCull<S> {
    inner: S,
    name: &'static str,
}

impl<S> HullCull<S> {
    /// Hull culling in front of `inner`, reported as `name`.
    pub const fn new(inner: S, name: &'static str) -> Self {
        HullCull { inner, name }
    }
}

impl<S: BoundsStrategy> BoundsStrategy for HullCull<S> {
    type Coeffs = (HullCoeffs, S::Coeffs);
    type Tile = S::Tile;
    fn name(&self) -> &'static str {
        self.name
    }
    fn prepare(&self, setup: &Setup, ops: &mut Ops) -> Self::Coeffs {
        let (pts, n) = swept_points(&setup.tri, setup.class);
        // The cone is that of the exact vertices; a bounded precision's sample test covers the
        // perturbed triangle (`Setup::eps`), which this cone does not yet include: no faces then,
        // so nothing is culled and the tile is the inner strategy's (conservative, no gain).
        let pts = if setup.eps.is_zero() {
            pts.get(..n).unwrap_or(&[])
        } else {
            &[]
        };
        let hull = hull_faces(pts, setup.viewport, ops);
        (hull, self.inner.prepare(setup, ops))
    }
    fn tile(
        &self,
        setup: &Setup,
        c: &Self::Coeffs,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<S::Tile> {
        if c.0.faces().iter().any(|f| face_culls(f, tile, ops)) {
            return None;
        }
        self.inner.tile(setup, &c.1, tile, ops)
    }
}
