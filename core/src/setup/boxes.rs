//! Lens-corner boxes per screen axis (Laine 2011 §3.1), with the separating-line test that
//! leaves a side unbounded when the moving, lens-extended triangle may cross the camera plane
//! there, and the footprint range of an axis from its boxes.

use crate::config::formats::PixelCoord;
use crate::input::{Triangle, C, W, X, Y};
use crate::setup::eps::Eps;
use crate::stats::Ops;

/// One axis's lens-corner boxes, raw [`PixelCoord`]s at lens = −1 (`[0]`) and lens = +1 (`[1]`).
/// `None`: unbounded on that side for every lens point (camera-plane crossing on that side).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AxisBoxes {
    /// floor of the box minimum at each lens corner
    pub lo: Option<[PixelCoord; 2]>,
    /// ceil of the box maximum at each lens corner
    pub hi: Option<[PixelCoord; 2]>,
}

/// Axis coordinate `a` of raw vertex `p` (x, or −y) and its lens coefficient `cs`.
#[inline]
pub(crate) fn axis_coord(p: &[i32; 5], axis: usize) -> (i64, i64) {
    // |raw| ≤ 2^31 as i64: negation exact (saturating regardless).
    if axis == 0 {
        (i64::from(p[X]), i64::from(p[C]))
    } else {
        (
            i64::from(p[Y]).saturating_neg(),
            i64::from(p[C]).saturating_neg(),
        )
    }
}

/// Does the convex hull of `pts` (points (a, w)) meet the half-line {(s·dir, 0) : s ≥ 0}?
/// (Pairwise, for any i64 points: the reference of setup's one-pass `hull_meets_ray`.)
///
/// In 2D a direction lies in the cone of a point set iff it lies in the cone of one point or of
/// two points less than π apart (Carathéodory), and the hull meets the camera point iff a point is
/// the origin or two points are opposite. All products are exact for any `i64` inputs: they are
/// formed in `i128` (each product < 2^126, each sum of two < 2^127); setup's own points have
/// |a| ≤ 2^30, |w| ≤ 2^29.
#[allow(clippy::arithmetic_side_effects)] // ranges in the doc comment above
pub fn crosses_camera_plane(pts: &[(i64, i64)], dir: i64, ops: &mut Ops) -> bool {
    let dir = i128::from(dir);
    for &(a, w) in pts {
        ops.add_setup(2);
        if w == 0 && (a == 0 || i128::from(a) * dir > 0) {
            return true;
        }
    }
    for (i, &(ai, wi)) in pts.iter().enumerate() {
        let (ai, wi) = (i128::from(ai), i128::from(wi));
        for &(aj, wj) in pts.iter().skip(i.saturating_add(1)) {
            let (aj, wj) = (i128::from(aj), i128::from(wj));
            ops.add_setup(6);
            let cr = ai * wj - wi * aj;
            let dot = ai * aj + wi * wj;
            if cr == 0 && dot < 0 {
                return true;
            }
            // e = (dir, 0) in cone(p, q) for cross(p, q) > 0 iff cross(p, e) ≥ 0 ≤ cross(e, q),
            // with cross(p, e) = −w_p·dir and cross(e, q) = dir·w_q.
            let (p, q) = if cr > 0 { (wi, wj) } else { (wj, wi) };
            if cr != 0 && -p * dir >= 0 && dir * q >= 0 {
                return true;
            }
        }
    }
    false
}

/// The predicate of [`crosses_camera_plane`] with `dir = ±1` (`positive`: +1) on 32-bit
/// points, in one pass (setup's separating-line test; the pairwise function stays as the
/// reference the tests compare with).
///
/// Proof. Flip a to σ·a so the half-line is R = {(s, 0) : s ≥ 0}. The hull H of the points
/// meets the line w = 0 in the hull of (i) the points with w = 0 and (ii) for every pair p
/// (w_p < 0), q (w_q > 0) the point where segment pq crosses w = 0, at
/// `a_pq = (w_q·a_p − w_p·a_q)/(w_q − w_p)` (a convex combination with w = 0 of points on both
/// sides is a convex combination of such crossings and of points on the line). That hull is a
/// segment of the line, so H meets R iff one of (i), (ii) has a ≥ 0. For (ii), dividing
/// `w_q·a_p + |w_p|·a_q ≥ 0` by `|w_p|·w_q > 0`: `a_p/|w_p| + a_q/w_q ≥ 0`, which some pair
/// meets iff the pair of the largest `a_p/|w_p|` and the largest `a_q/w_q` does. So one pass
/// keeps those two (compared by cross-multiplication) and tests them once. Without points on
/// both sides only (i) remains.
///
/// Ranges: |a| < 2^31, |w| < 2^31 (setup's corners: |a| < 2^31, |w| ≤ 2^29 + 1): every
/// product < 2^62, the final sum < 2^63, exact in i64; the negations of i32 values in i64
/// are exact. `fast_corners::hull_meets_ray_matches_pairwise` compares it with the pairwise
/// function.
#[allow(clippy::arithmetic_side_effects)] // ranges in the doc comment above
pub(crate) fn hull_meets_ray(pts: &[(i32, i32)], positive: bool, ops: &mut Ops) -> bool {
    // (σ·a, |w|) of the best point below (w < 0) and above (w > 0) the line.
    let mut below: Option<(i64, i64)> = None;
    let mut above: Option<(i64, i64)> = None;
    for &(a, w) in pts {
        let a = if positive {
            i64::from(a)
        } else {
            -i64::from(a)
        };
        let w = i64::from(w);
        ops.add_setup(2);
        if w == 0 {
            if a >= 0 {
                return true;
            }
            continue;
        }
        let (slot, m) = if w < 0 {
            (&mut below, -w)
        } else {
            (&mut above, w)
        };
        ops.add_setup(3);
        if slot.map_or(true, |(ba, bm)| a * bm > ba * m) {
            *slot = Some((a, m));
        }
    }
    match (below, above) {
        (Some((ap, mp)), Some((aq, mq))) => {
            ops.add_setup(3);
            ap * mq + aq * mp >= 0
        }
        _ => false,
    }
}

/// Largest |box coordinate| setup produces (raw, 2^-bnd px): |num| < 2^58 in [`project`].
const BOX_LIMIT: PixelCoord = 1 << 58;

/// Pixel position `(a + w)·E·2^bnd / (2w)` of a front point (w > 0), floored or ceiled to the
/// bound grid of `bnd` fraction bits.
///
/// Ranges: |a + w| < 2^32 (|a| < 2^31 with the lens term and ε, |w| ≤ 2^29 + 1), E ≤ 2^11,
/// bnd ≤ 16 (`PrecisionBits`): the numerator is < 2^59, formed in i64 by checked
/// multiplications (the 2^bnd factor is `2^bnd` by `pow`, not a shift), and one 64-bit
/// division by 2w ≥ 2 (`checked_div_euclid`; the ceiling as the negated floor of −num, exact
/// since |num| < 2^59) gives |q| < 2^58. Should anything fail (w ≤ 0 is the caller's duty and
/// is checked), the result is the outward limit (−2^58 for a minimum, 2^58 for a maximum):
/// conservative. `corners::projection_at_the_domain_corners` and `fast_corners::
/// projection_and_pixel_floor_at_the_widest_corners` check the extremes against i128.
#[inline]
pub(crate) fn project(a: i64, w: i64, extent: i64, up: bool, bnd: u32) -> PixelCoord {
    let limit = if up { BOX_LIMIT } else { -BOX_LIMIT };
    if w <= 0 {
        return limit;
    }
    let num = a
        .checked_add(w)
        .and_then(|s| s.checked_mul(extent))
        .and_then(|s| s.checked_mul(2i64.checked_pow(bnd)?));
    let q = match (num, w.checked_mul(2)) {
        (Some(num), Some(den)) if up => num
            .checked_neg()
            .and_then(|m| m.checked_div_euclid(den))
            .and_then(i64::checked_neg),
        (Some(num), Some(den)) => num.checked_div_euclid(den),
        _ => None,
    };
    q.unwrap_or(limit)
}

/// Lens-corner boxes of one axis (Laine §3.1), with the separating-line test per side.
///
/// **Conservative epsilon** (bounded sample test, `bounded.rs`): the test decides exactly on a
/// triangle whose vertices lie within `ε_x` (this axis) of the exact `a(t, u)` and within `ε_w`
/// of the exact `w(t)`. At a fixed lens point u the exact vertex moves linearly in t, so the
/// perturbed vertex lies in the convex hull of the endpoints' corners `(a + u·cs ± ε_x, w ± ε_w)`
/// (a segment plus a box is the hull of its ends plus the box's corners). The projection
/// `(a + w)·E/(2w)` is increasing in a and linear-fractional, so over that hull (where w > 0)
/// its minimum is at a corner with `a + u·cs − ε_x`, its maximum at one with `+ ε_x`; each is
/// affine in u, so the chord argument of `bounds.rs` holds unchanged over the corner set. The
/// separating-line test runs on the corners too: the left set `(a − |cs| − ε_x, w ± ε_w)`, the
/// right set `(a + |cs| + ε_x, w ± ε_w)`, exactly as an extra `|c|` of `ε_x` plus a second w.
/// An exact precision (ε = 0) runs [`exact_boxes`] (chosen on the type's constant in
/// [`setup_scaled`]): the six-point instantiation of the same code, whose values with ε = 0 are
/// those of the exact boxes.
pub(crate) fn axis_boxes(
    tri: &Triangle,
    axis: usize,
    extent: i64,
    bnd: u32,
    eps: &Eps,
    ops: &mut Ops,
) -> AxisBoxes {
    let ex = eps.x.get(axis).copied().unwrap_or(0);
    // Monomorphized per corner count; the exact test (ε = 0) runs the six-point version.
    if eps.w == 0 {
        corner_boxes::<1, 6>(tri, axis, extent, bnd, ex, [0], ops)
    } else {
        corner_boxes::<2, 12>(
            tri,
            axis,
            extent,
            bnd,
            ex,
            [eps.w.saturating_neg(), eps.w],
            ops,
        )
    }
}

/// Axis coordinate `a` (x, or −y) and lens coefficient `cs` of raw vertex `p` as `i32`: a
/// checked triangle has |x|, |y|, |c| ≤ 2^29, so the negations are exact.
#[inline]
fn axis_coord32(p: &[i32; 5], axis: usize) -> (i32, i32) {
    if axis == 0 {
        (p[X], p[C])
    } else {
        (p[Y].saturating_neg(), p[C].saturating_neg())
    }
}

/// Whether the ratio `a/w` is below `b.0/b.1` (both w > 0): `a·w_b < a_b·w`, exact in i64
/// for |a| < 2^31, 0 < w < 2^31 (products < 2^62).
#[inline]
#[allow(clippy::arithmetic_side_effects)] // ranges in the doc comment above
fn ratio_below(a: i32, w: i32, b: (i32, i32)) -> bool {
    i64::from(a) * i64::from(b.1) < i64::from(b.0) * i64::from(w)
}

/// [`axis_boxes`] over `N` w offsets per vertex (`M = 6·N` corner points: both shutter ends),
/// or of the shutter-open vertices alone (`M = 3·N`: the box at the shutter's start,
/// [`start_boxes`]).
///
/// **One division per box side.** The projection `(a + w)·E·2^bnd/(2w) = (a/w + 1)·E·2^bnd/2`
/// is non-decreasing in the ratio `a/w` (w > 0), and so are its floor and ceiling. Hence the
/// minimum over the front corners of the floored projections is the floored projection of the
/// corner with the smallest `a/w`, and the maximum of the ceiled ones that of the largest:
/// the corners are compared by cross-multiplication (`a_i·w_j` against `a_j·w_i`, i64), and
/// each of the four box values of the axis (lens −1/+1, min/max) costs one [`project`] — the
/// same values as projecting every corner (equal ratios project to equal values), with 4
/// divisions instead of 4·M. `fast_corners::boxes_match_per_corner_projection` checks them
/// against the per-corner computation.
// Ranges: |a|, |cs|, |w| ≤ 2^29 (checked triangle), ε_x ≤ 2^24 and ε_w ≤ 1 (`Eps::of` with
// `OFFSET_SHIFT_MAX`): a ± |cs| ± ε_x and a + lens·cs ± ε_x are < 2^30 + 2^25 < 2^31 (i32),
// w ± ε_w ≤ 2^29 + 1 (i32), so [`ratio_below`]'s products are < 2^61 and `project`'s
// |a + w| < 2^32 keeps its numerator < 2^59 and |q| < 2^58 (w ≥ 1 there); the index i counts
// at most twelve corner points.
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn corner_boxes<const N: usize, const M: usize>(
    tri: &Triangle,
    axis: usize,
    extent: i64,
    bnd: u32,
    ex: i32,
    dws: [i32; N],
    ops: &mut Ops,
) -> AxisBoxes {
    let mut left = [(0i32, 0i32); M];
    let mut right = [(0i32, 0i32); M];
    let mut i = 0;
    // The shutter ends the corner set holds: both (M = 6·N) or the open one (M = 3·N).
    let n_ends = M / (3 * N);
    for ends in tri.v.iter().take(n_ends) {
        for p in ends.iter() {
            let (a, cs) = axis_coord32(p, axis);
            for &dw in dws.iter() {
                if let (Some(l), Some(r)) = (left.get_mut(i), right.get_mut(i)) {
                    *l = (a - cs.abs() - ex, p[W] + dw);
                    *r = (a + cs.abs() + ex, p[W] + dw);
                }
                i += 1;
                ops.add_setup(2);
            }
        }
    }
    // A corner set entirely in front (every w > 0; both sets share their w) has its hull in
    // w > 0, which cannot meet the camera plane: the test only runs when some w ≤ 0.
    let all_front = left.iter().all(|p| p.1 > 0);
    let unbounded_lo = !all_front && hull_meets_ray(&left, false, ops);
    let unbounded_hi = !all_front && hull_meets_ray(&right, true, ops);
    // Per lens corner: the front corner point with the smallest (a − ε_x)/w and the one with
    // the largest (a + ε_x)/w.
    let mut lo: [Option<(i32, i32)>; 2] = [None; 2];
    let mut hi: [Option<(i32, i32)>; 2] = [None; 2];
    for ends in tri.v.iter().take(n_ends) {
        for p in ends.iter() {
            let (a, cs) = axis_coord32(p, axis);
            for &dw in dws.iter() {
                let w = p[W] + dw;
                if w <= 0 {
                    continue;
                }
                for ((l, h), lens) in lo.iter_mut().zip(hi.iter_mut()).zip([-1i32, 1]) {
                    let au = a + lens * cs;
                    ops.add_setup(6);
                    let (al, ah) = (au - ex, au + ex);
                    if l.map_or(true, |b| ratio_below(al, w, b)) {
                        *l = Some((al, w));
                    }
                    if h.map_or(true, |b| ratio_below(b.0, b.1, (ah, w))) {
                        *h = Some((ah, w));
                    }
                }
            }
        }
    }
    let proj = |c: [Option<(i32, i32)>; 2], up: bool| match c {
        [Some(c0), Some(c1)] => {
            Some([c0, c1].map(|(a, w)| project(i64::from(a), i64::from(w), extent, up, bnd)))
        }
        _ => None,
    };
    AxisBoxes {
        lo: proj(lo, false).filter(|_| !unbounded_lo),
        hi: proj(hi, true).filter(|_| !unbounded_hi),
    }
}

/// [`axis_boxes`] of an exact precision (ε = 0): the six-point instantiation.
pub(crate) fn exact_boxes(
    tri: &Triangle,
    axis: usize,
    extent: i64,
    bnd: u32,
    ops: &mut Ops,
) -> AxisBoxes {
    corner_boxes::<1, 6>(tri, axis, extent, bnd, 0, [0], ops)
}

/// The lens-corner boxes of one axis of the triangle at the shutter's start (its open vertices
/// alone, without ε: the three-point instantiation of [`corner_boxes`]); `auto`'s travel check
/// ranks by them, nothing is bounded by them.
pub(crate) fn start_boxes(
    tri: &Triangle,
    axis: usize,
    extent: i64,
    bnd: u32,
    ops: &mut Ops,
) -> AxisBoxes {
    corner_boxes::<1, 3>(tri, axis, extent, bnd, 0, [0], ops)
}

/// Footprint columns (or rows) `[p0, p1)` of one axis from its boxes, clamped to `[0, E]`.
/// A sample at ξ is in column floor(ξ); ξ ≤ max means columns up to floor(max) are needed.
/// Pixel index floor(X / 2^bnd): an arithmetic right shift by bnd ≤ 16 (`PrecisionBits`), which
/// is the exact floor division by 2^bnd and loses no high bits (no divide instruction).
pub(crate) fn floor_px(x: PixelCoord, bnd: u32) -> PixelCoord {
    x.checked_shr(bnd).unwrap_or(if x < 0 { -1 } else { 0 })
}

pub(crate) fn axis_range(b: &AxisBoxes, extent: u16, bnd: u32) -> (u16, u16) {
    let e = i64::from(extent);
    let p0 = match b.lo {
        Some([l0, l1]) => floor_px(l0.min(l1), bnd),
        None => 0,
    };
    let p1 = match b.hi {
        Some([h0, h1]) => floor_px(h0.max(h1), bnd).saturating_add(1),
        None => e,
    };
    // Clamped to [0, E] with E ≤ 2048: the conversions are exact.
    let px = |p: i64| u16::try_from(p.clamp(0, e)).unwrap_or(extent);
    (px(p0), px(p1))
}
