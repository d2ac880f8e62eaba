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
//!
//! **Conservative epsilon** (a [`crate::config::precision::Bounded`] precision, `bounded.rs`): that test
//! covers d exactly when the exact test covers it on a perturbed triangle `P'_k = P_k + δ_k`,
//! with `P_k` the exact vertex at the sample's (t, u, v) and `|δx| ≤ ε_x`, `|δy| ≤ ε_y`,
//! `|δw| ≤ ε_w` ([`crate::setup::eps::Eps`]). Coverage there still means `det' ≠ 0` and every
//! `E'_k·det' ≥ 0` (`bounded_eval`: the common sign of the E' when every w > 0, else the sign of
//! det'), so `d = Σ b_k·P'_k` with `b_k ≥ 0`. The faces stay those of the exact cone K; each face
//! is widened by a constant (no new face, no extra per-tile work):
//! - Let `w_min` be the least w of the hull points. If `w_min − ε_w > 0`, every `P_k` (in H) has
//!   `w ≥ w_min` and every `P'_k` has `w' ≥ w_min − ε_w > 0`. Project: a point with w > 0 sits at
//!   sample position `s(p) = (128W·(1 + x/w), 128H·(1 − y/w))` (1/256 px), where
//!   `d(s(p)) = p·256WH/w`, so for the face's affine `F(xs, ys) = n·d(xs, ys)`:
//!   `F(s(p)) = (256WH/w)·n·p`, ≥ 0 for every p ∈ H.
//! - From `d = Σ b_k·P'_k` and `d_w = 256WH = Σ b_k·w'_k` with every `w'_k > 0`, the weights
//!   `λ_k = b_k·w'_k/d_w` are ≥ 0 and sum to 1, and `s(d) = Σ λ_k·s(P'_k)`: the sample position
//!   is a convex combination of the projected perturbed vertices. F is affine, so
//!   `F(s(d)) ≥ min_k F(s(P'_k))`.
//! - `x'/w' − x/w = (δx·w − x·δw)/(w·w')`, so `|x'/w' − x/w| ≤ (ε_x + |x/w|·ε_w)/(w_min − ε_w)`;
//!   `|x/w|` over H (w > 0) is largest at a hull point (x/w is linear-fractional), bounded by
//!   `R_x = max ceil(|x_p|/w_p)` over the points. So the projection moves by at most
//!   `ρ_x = ceil(128W·(ε_x + R_x·ε_w)/(w_min − ε_w))` in xs and `ρ_y` (H, ε_y, R_y) in ys, and
//!   `F(s(P'_k)) ≥ F(s(P_k)) − |a|·ρ_x − |b|·ρ_y ≥ −(|a|·ρ_x + |b|·ρ_y)`.
//!
//!   Hence every covered sample has `F + |a|·ρ_x + |b|·ρ_y ≥ 0`: setup adds that constant to each
//!   face's c (the support of the box [−ρ_x, ρ_x] × [−ρ_y, ρ_y] in the face's direction: the
//!   face of the hull's projection grown by the box), and the tile test is unchanged.
//! - If `w_min − ε_w ≤ 0` (a hull point on or behind the camera plane, or within ε_w of it) the
//!   perturbed cone is not derived: no faces, nothing culled (conservative; the inner strategy
//!   keeps its own ε-carrying bounds). With ε = 0 (the exact test) the faces are untouched.
//!
//! **Per-tile cost** ([`HullTiles`]). The corner a face picks depends only on the signs of a and
//! b, so setup stores `a' = 256·a`, `b' = 256·b` and folds the corner's sub-pixel offset into c
//! (`a·(256·X1 − 1) = a'·X1 − a`): a tile evaluates `a'·xe + b'·ye + c' < 0` with xe, ye its
//! stored ends, 5 ops (2 mul, 2 add, 1 compare), the same integer as the direct maximum. A face
//! is dropped in setup when it does not cull the footprint pixel where its tile maximum is least
//! (the maximum over a pixel is monotone in the pixel's column and row, with the signs of a and
//! b, and a tile's maximum is ≥ that of each of its pixels): it then culls no tile inside the
//! footprint, so the decisions are unchanged. The kept faces are tested in a greedy order (the
//! face culling most of an up to 8 × 8 pixel grid over the footprint not culled by an earlier
//! one first), stopping at the first that culls; the order changes only the op count.
//!
//! **Row spans** ([`HullTiles::span`], [`HullCull`]'s `row_span`). In one row of tiles ye is
//! fixed, so each face keeps the cells with `a'·xe + r ≥ 0` (r = b'·ye + c'): a run of
//! consecutive cells, decided by the row's two end cells or, when the face crosses the row, by
//! one exact floor division whose quotient is below the row's width. Their intersection is
//! the row's span; inside it the face test is skipped and outside no tile is visited — exactly
//! the tiles the per-tile test keeps (clipped first and last cells included; proof at
//! [`TileFace`]'s `span`). Counted in `ops.rows`.
#![warn(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_possible_wrap
)]

use crate::bounds::strategy::{BoundsStrategy, RowSpan};
use crate::config::class::Class;
use crate::config::formats::SUBPIXEL_BITS;
use crate::config::unit::Unit;
use crate::input::{PixelRect, Triangle, Viewport, C, W, X, Y};
use crate::setup::Setup;
use crate::stats::Ops;
/// One pixel in sub-pixel units, 2^SUBPIXEL_BITS = 2^8 (a constant shift, checked by the compiler).
const SUBPIXEL_ONE: i128 = 1i128 << SUBPIXEL_BITS;

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
    let one = SUBPIXEL_ONE;
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
/// `false` on overflow. Counts 7 operations per face in `ops.bounds`. The direct form, kept as
/// the reference of [`HullTiles::culls`] (`hull/reference.rs`).
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

/// Largest grid of footprint pixels per axis on which setup measures each face's culling to
/// order the faces (8 × 8 = 64 points, one bit each).
const ORDER_GRID: u32 = 8;

/// One face in per-tile form: the tile is culled when `a·xe + b·ye + c < 0`, with `xe` the
/// tile's `x1` (`hi_x`) or `x0` and `ye` likewise: the corner the face's signs picked in setup,
/// with its sub-pixel offset folded into `c` (module docs, "Per-tile cost").
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TileFace {
    a: i128,
    b: i128,
    c: i128,
    hi_x: bool,
    hi_y: bool,
}

impl TileFace {
    /// The per-tile form of `f`: `a' = 256·a`, `b' = 256·b`, and for a > 0 the tile's largest
    /// sample column `256·x1 − 1` (so `a·(256·x1 − 1) = a'·x1 − a`, `−a` folded into c), else
    /// its first `256·x0`; the same for y. `None` on overflow (the face is then dropped).
    /// Ranges (module docs): |a|, |b| < 2^73, |c| < 2^124 after widening: |a'|, |b'| < 2^81,
    /// |c'| < 2^125.
    pub(crate) fn of(f: &HullFace) -> Option<TileFace> {
        let (hi_x, hi_y) = (f.a > 0, f.b > 0);
        let mut c = f.c;
        if hi_x {
            c = c.checked_sub(f.a)?;
        }
        if hi_y {
            c = c.checked_sub(f.b)?;
        }
        Some(TileFace {
            a: f.a.checked_mul(SUBPIXEL_ONE)?,
            b: f.b.checked_mul(SUBPIXEL_ONE)?,
            c,
            hi_x,
            hi_y,
        })
    }

    /// Whether the face is negative at every sample position of `tile` (then the tile is
    /// culled): 2 mul, 2 add, 1 compare, counted by the caller. The same integer as
    /// [`face_culls`]'s maximum: `a'·xe + b'·ye + c'` with xe, ye < 2^16 is < 2^98 + 2^125,
    /// exact; checked anyway (`false`, keep the tile, on overflow).
    #[inline]
    pub(crate) fn culls(&self, tile: PixelRect) -> bool {
        let xe = i128::from(if self.hi_x { tile.x1 } else { tile.x0 });
        let ye = i128::from(if self.hi_y { tile.y1 } else { tile.y0 });
        let v = self
            .a
            .checked_mul(xe)
            .and_then(|x| x.checked_add(self.b.checked_mul(ye)?))
            .and_then(|x| x.checked_add(self.c));
        matches!(v, Some(m) if m < 0)
    }

    /// Whether the coefficients lie in the documented ranges (|a'|, |b'| < 2^81,
    /// |c'| < 2^125): then `a'·xe + b'·ye + c'` with xe, ye < 2^16 is < 2^126 and nothing
    /// overflows in [`Self::culls`] or [`Self::span`].
    fn in_range(&self) -> bool {
        let lim = |v: i128, bits: u32| v.unsigned_abs() < 1u128.checked_shl(bits).unwrap_or(0);
        lim(self.a, 81) && lim(self.b, 81) && lim(self.c, 125)
    }

    /// The pixel columns `[lo, hi)` (unclamped; the caller clamps to the row; `lo ≥ hi`: none)
    /// of the cells of `row` that this face keeps, i.e. whose stored end `xe` has
    /// `a'·xe + r ≥ 0` with `r = b'·ye + c'` (ye: the row's shared y end). Cells of the row are
    /// aligned to the `b`-grid and clipped to `[x0, x1)`: cell k has `x0_k = max(first + k·b,
    /// row.x0)`, `x1_k = min(first + (k+1)·b, row.x1)` (`first = b·⌊row.x0/b⌋`); `xe_k` is
    /// `x1_k` if `a' > 0`, else `x0_k`, as in [`Self::culls`]. `v(k) = a'·xe_k + r` is monotone
    /// in k (`xe_k` increases), so the kept cells are a suffix (`a' > 0`), a prefix (`a' < 0`),
    /// all or none (`a' = 0`: the sign of r).
    /// - The two end cells decide all-or-none without a division: `a' > 0`: none if
    ///   `v(last) < 0`, all if `v(first) ≥ 0`; `a' < 0`: none if `v(first) < 0`, all if
    ///   `v(last) ≥ 0`.
    /// - Otherwise the sign changes inside the row and one exact floor division finds where,
    ///   relative to the first cell's end `xf = xe_first` (with `vf = v(first)`):
    ///   `a' > 0` (vf < 0): kept iff `xe ≥ X = xf − ⌊vf/a'⌋` (= `⌈−r/a'⌉`, since
    ///   `⌊(a'·xf + r)/a'⌋ = xf + ⌊r/a'⌋`), the cells from `k` with `first + (k+1)·b ≥ X`:
    ///   columns from `b·⌊(X − 1)/b⌋`. The quotient `−⌊vf/a'⌋` is in `(0, row.x1 − xf]`
    ///   (`v(last) = a'·row.x1 + r ≥ 0`).
    ///   `a' < 0` (vf ≥ 0): kept iff `x0_k ≤ Y = xf + ⌊vf/(−a')⌋` (= `⌊r/(−a')⌋`), the cells
    ///   with `first + k·b ≤ Y`: columns up to `b·⌊Y/b⌋ + b`. The quotient is in
    ///   `[0, xe_last − xf)` (`v(last) < 0`).
    ///
    ///   Either way the quotient is below the row's width `n_px = row.x1 − row.x0 < 2^16`: the
    ///   division needs only `q = bitlen(n_px)` quotient bits (a q-step restoring divider on the
    ///   ~83-bit operands; ≤ 12 steps in a 2048-pixel viewport), and it is counted as q ops.
    ///
    /// Ops (in `ops.rows`, one per multiply, add, compare, negation, min/max, alignment and
    /// quotient bit): `a' = 0`: 3 (r: mul, add; the compare); else r (2) and 3 per end cell
    /// evaluated (mul, add, compare; the second end only if the first does not decide); a
    /// crossing adds the division's q and 3 (the subtraction from xf, the `−1`/`+b` and the
    /// alignment to the `b` grid, a mask since b is a power of two).
    /// Ranges: `r`, `v` < 2^126 (b'·ye < 2^97, c' < 2^125, a'·xe < 2^97); `None` on overflow
    /// (outside the documented ranges; [`HullTiles::span`] then falls back).
    fn span(&self, row: PixelRect, b: i128, ops: &mut Ops) -> Option<(i128, i128)> {
        let ye = i128::from(if self.hi_y { row.y1 } else { row.y0 });
        let r = self.b.checked_mul(ye)?.checked_add(self.c)?;
        let (x0, x1) = (i128::from(row.x0), i128::from(row.x1));
        let none = Some((x1, x0));
        let all = Some((x0, x1));
        if self.a == 0 {
            ops.add_rows(3);
            return if r >= 0 { all } else { none };
        }
        let v = |xe: i128| self.a.checked_mul(xe)?.checked_add(r);
        // Cell ends: the first cell starts at row.x0 and ends at min(first + b, x1); the last
        // starts at max(first + (n−1)·b, x0) and ends at x1.
        let first = x0.checked_sub(x0.checked_rem_euclid(b)?)?;
        let first_end = first.checked_add(b)?.min(x1);
        let last_start = x1
            .checked_sub(1)?
            .checked_div_euclid(b)?
            .checked_mul(b)?
            .max(x0);
        let q_bits =
            u64::from(u16::BITS.saturating_sub(row.x1.saturating_sub(row.x0).leading_zeros()));
        ops.add_rows(2 + 3);
        if self.a > 0 {
            if v(x1)? < 0 {
                return none;
            }
            ops.add_rows(3);
            let vf = v(first_end)?;
            if vf >= 0 {
                return all;
            }
            ops.add_rows(q_bits + 3);
            let x = first_end.checked_sub(vf.checked_div_euclid(self.a)?)?;
            let lo = x.checked_sub(1)?.checked_div_euclid(b)?.checked_mul(b)?;
            Some((lo, x1))
        } else {
            let vf = v(x0)?;
            if vf < 0 {
                return none;
            }
            ops.add_rows(3);
            if v(last_start)? >= 0 {
                return all;
            }
            ops.add_rows(q_bits + 3);
            let y = x0.checked_add(vf.checked_div_euclid(self.a.checked_neg()?)?)?;
            let hi = y.checked_div_euclid(b)?.checked_mul(b)?.checked_add(b)?;
            Some((x0, hi))
        }
    }
}

/// Per-triangle faces in per-tile form, kept only if they can cull a tile of the footprint, and
/// ordered so that the faces culling the most footprint pixels come first.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HullTiles {
    faces: [TileFace; MAX_FACES],
    len: usize,
    /// every kept face lies in the documented ranges (|a'|, |b'| < 2^81, |c'| < 2^125), so no
    /// per-tile or per-row evaluation overflows and row spans are exact ([`HullTiles::span`])
    spans: bool,
}

impl HullTiles {
    /// No faces: nothing is culled.
    pub const EMPTY: HullTiles = HullTiles {
        faces: [TileFace {
            a: 0,
            b: 0,
            c: 0,
            hi_x: false,
            hi_y: false,
        }; MAX_FACES],
        len: 0,
        spans: true,
    };

    /// The kept faces, in test order.
    pub fn faces(&self) -> &[TileFace] {
        self.faces.get(..self.len).unwrap_or(&[])
    }

    /// The per-tile form of `hull` for tiles inside footprint `fp` (module docs, "Per-tile
    /// cost"): each face folded ([`TileFace::of`]; 4 ops), dropped if it does not cull the
    /// footprint pixel where it is least (5 ops; then it culls no tile inside `fp`), and the
    /// kept ones ordered greedily by the pixels of an up to 8 × 8 grid over `fp` they cull that
    /// no earlier face culls (5 ops per face and grid pixel, 2 per face and pick).
    pub fn of(hull: &HullCoeffs, fp: PixelRect, ops: &mut Ops) -> HullTiles {
        let mut out = HullTiles::EMPTY;
        if fp.is_empty() {
            return out;
        }
        let w = u32::from(fp.x1.saturating_sub(fp.x0));
        let h = u32::from(fp.y1.saturating_sub(fp.y0));
        let (gx, gy) = (w.min(ORDER_GRID), h.min(ORDER_GRID));
        // Grid pixel k of gx along x: fp.x0 + k·w/gx (< fp.x1; k·w ≤ 7·2^16, no overflow).
        let at = |o: u16, k: u32, n: u32, g: u32| {
            let d = k.saturating_mul(n).checked_div(g).unwrap_or(0);
            o.saturating_add(u16::try_from(d).unwrap_or(u16::MAX))
        };
        let pixel = |x: u16, y: u16| PixelRect {
            x0: x,
            y0: y,
            x1: x.saturating_add(1),
            y1: y.saturating_add(1),
        };
        let mut masks = [0u64; MAX_FACES];
        let mut n = 0usize;
        for f in hull.faces() {
            ops.add_setup(4 + 5);
            let Some(t) = TileFace::of(f) else {
                continue;
            };
            // The footprint pixel where the face's tile maximum is least: its value is monotone
            // in the pixel column (row) with the direction of sign(a) (sign(b)).
            let px = if f.a > 0 {
                fp.x0
            } else {
                fp.x1.saturating_sub(1)
            };
            let py = if f.b > 0 {
                fp.y0
            } else {
                fp.y1.saturating_sub(1)
            };
            if !t.culls(pixel(px, py)) {
                continue;
            }
            let mut mask = 0u64;
            for j in 0..gy {
                for i in 0..gx {
                    ops.add_setup(5);
                    if t.culls(pixel(at(fp.x0, i, w, gx), at(fp.y0, j, h, gy))) {
                        mask |= 1u64
                            .checked_shl(j.saturating_mul(ORDER_GRID).saturating_add(i))
                            .unwrap_or(0);
                    }
                }
            }
            if let (Some(slot), Some(m)) = (out.faces.get_mut(n), masks.get_mut(n)) {
                out.spans &= t.in_range();
                *slot = t;
                *m = mask;
                n = n.saturating_add(1);
            }
        }
        out.len = n;
        // Greedy order: next, the face culling the most grid pixels not yet culled (the first
        // such on ties, so the order is deterministic).
        let mut covered = 0u64;
        for k in 0..n {
            let mut pick = k;
            let mut gain = 0u32;
            for (i, m) in masks.iter().enumerate().take(n).skip(k) {
                ops.add_setup(2);
                let g = (m & !covered).count_ones();
                if g > gain {
                    (pick, gain) = (i, g);
                }
            }
            out.faces.swap(k, pick);
            masks.swap(k, pick);
            covered |= masks.get(k).copied().unwrap_or(0);
        }
        out
    }

    /// Whether some face culls `tile` (a tile inside the footprint), testing the faces in order
    /// and stopping at the first that culls: 5 ops per face tested.
    pub fn culls(&self, tile: PixelRect, ops: &mut Ops) -> bool {
        self.faces().iter().any(|f| {
            ops.add_bounds(5);
            f.culls(tile)
        })
    }

    /// The columns `[x0, x1)` of `row` (one row of `bt`-grid cells clipped to the footprint)
    /// whose cells no face culls, or `None` when the span is not used on this row (then every
    /// tile is tested by [`Self::culls`]). Exactly the cells [`Self::culls`] keeps: see
    /// [`TileFace::span`] per face; the kept set of each face is a run of consecutive cells (a
    /// prefix, a suffix, all or none), so their intersection is the run between the largest
    /// start and the least end, clamped to the row.
    ///
    /// Used when there is a face, the kept faces lie in the documented ranges, and the row has
    /// at least [`SPAN_MIN_CELLS`] cells (1 op, the width compare). Ops, in `ops.rows`: per
    /// face [`TileFace::span`]'s (3 to 11 + q, q = bitlen of the row's width) and 2 (the
    /// max/min with the running span, and the empty test: the faces stop at the first that
    /// leaves the span empty), and 2 per row (the clamp to the row).
    pub fn span(&self, row: PixelRect, bt: u16, ops: &mut Ops) -> Option<(u16, u16)> {
        if self.len == 0 || !self.spans {
            return None;
        }
        ops.add_rows(1);
        let b = bt.max(1);
        // Cells of the row: from align_down(x0) in steps of b up to x1 (x1 > x0 ≥ 0).
        let first = row.x0.checked_sub(row.x0.checked_rem(b)?)?;
        let n = row.x1.saturating_sub(first).div_ceil(b);
        if n < SPAN_MIN_CELLS {
            return None;
        }
        let (mut lo, mut hi) = (i128::from(row.x0), i128::from(row.x1));
        for f in self.faces() {
            let (l, h) = f.span(row, i128::from(b), ops)?;
            lo = lo.max(l);
            hi = hi.min(h);
            ops.add_rows(2);
            if lo >= hi {
                break;
            }
        }
        ops.add_rows(2);
        let lo = lo.clamp(i128::from(row.x0), i128::from(row.x1));
        let hi = hi.clamp(lo, i128::from(row.x1));
        Some((u16::try_from(lo).ok()?, u16::try_from(hi).ok()?))
    }
}

/// Least number of bounds tiles in a row for [`HullTiles::span`] to be used: on a one-tile row
/// the span costs each face at least 7 ops (r, an end cell, the running span) where the per-tile
/// test costs 5 per face and stops at the first that culls, so such rows keep the per-tile test.
pub const SPAN_MIN_CELLS: u16 = 2;

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
    type Coeffs = (HullTiles, S::Coeffs);
    type Tile = S::Tile;
    fn name(&self) -> &'static str {
        self.name
    }
    fn prepare<U: Unit>(&self, setup: &Setup, ops: &mut Ops) -> Self::Coeffs {
        let (pts, n) = swept_points(&setup.tri, setup.class);
        let pts = pts.get(..n).unwrap_or(&[]);
        let hull = if setup.eps.is_zero() {
            hull_faces(pts, setup.viewport, ops)
        } else {
            // The bounded test covers a perturbed triangle (module docs): the exact cone's faces
            // grown by the projected perturbation, or none where that is not derived.
            match eps_margin(pts, &setup.eps, setup.viewport, ops) {
                Some(rho) => hull_faces(pts, setup.viewport, ops).widened(rho, ops),
                None => HullCoeffs::EMPTY,
            }
        };
        let tiles = HullTiles::of(&hull, setup.footprint, ops);
        (tiles, self.inner.prepare::<U>(setup, ops))
    }
    fn tile<U: Unit>(
        &self,
        setup: &Setup,
        c: &Self::Coeffs,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<S::Tile> {
        if c.0.culls(tile, ops) {
            return None;
        }
        self.inner.tile::<U>(setup, &c.1, tile, ops)
    }
    /// The run of the row's cells no face culls ([`HullTiles::span`]), pruned; the whole row,
    /// not pruned, where spans are not used. The inner strategy's own span is not consulted
    /// (its tiles run through `tile`, as in [`Self::tile`]).
    fn row_span(
        &self,
        _setup: &Setup,
        c: &Self::Coeffs,
        row: PixelRect,
        bt: u16,
        ops: &mut Ops,
    ) -> RowSpan {
        match c.0.span(row, bt, ops) {
            Some((x0, x1)) => RowSpan::pruned(row, x0, x1),
            None => RowSpan::whole(row),
        }
    }
    /// Inside a pruned span no face culls the tile: only the inner bounds (what [`Self::tile`]
    /// returns for a tile no face culls); else [`Self::tile`] itself.
    fn span_tile<U: Unit>(
        &self,
        setup: &Setup,
        c: &Self::Coeffs,
        span: &RowSpan,
        tile: PixelRect,
        ops: &mut Ops,
    ) -> Option<S::Tile> {
        if span.is_pruned() {
            self.inner.tile::<U>(setup, &c.1, tile, ops)
        } else {
            self.tile::<U>(setup, c, tile, ops)
        }
    }
}
