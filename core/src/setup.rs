//! Stage 1 — triangle setup, exactly once per triangle (Laine 2011 §3).
//!
//! Classifies the triangle (static / motion / defocus / both), culls it when it is outside the
//! frustum for the whole shutter or degenerate at every (t, u, v), and otherwise computes:
//! - per screen axis, the two lens-corner bounding boxes (§3.1) of the six vertices, each side
//!   either a finite pixel coordinate or unbounded when the moving, lens-extended triangle may
//!   cross the camera plane on that side (separating-line test, §3.1 "Vertices behind camera");
//! - the screen footprint: the union of both boxes, clamped to the viewport;
//! - the time span the triangle may spend inside the frustum (§3.2 last paragraphs);
//! - what the sample test needs: per-vertex base and delta terms, and for a static in-focus
//!   triangle its three edge normals and determinant (a plain 2D test).
//!
//! Axis convention: both axes are handled by one code path on a coordinate `a` that grows with
//! the pixel index: `a = x` (columns, extent W) and `a = −y` (rows, extent H). A lens coordinate
//! moves `a` by `lens·cs` with `cs = c` for x and `cs = −c` for y. Pixel position of a point in
//! front of the camera: `ξ = (a + w)·E / (2w)`.

use crate::bounded::Eps;
use crate::formats::{DefaultPrecision, PixelCoord, Precision, PrecisionBits};
use crate::input::{PixelRect, Triangle, Viewport, C, W, X, Y, Z};
use crate::interval::{solve_le64, Interval};
use crate::planar::{planar_setup, PlanarEdges};
use crate::stats::Ops;
use crate::unit::{Full, Unit};

/// Which effects a triangle has; the class decides which work is skipped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Class {
    /// no motion, in focus: plain 2D test, no bounds
    Static,
    /// motion only: t bounds, no lens terms
    Motion,
    /// defocus only: u/v bounds, no t terms
    Defocus,
    /// both: everything
    MotionDefocus,
}

impl Class {
    /// Index 0..4 for counters.
    pub fn index(self) -> usize {
        match self {
            Class::Static => 0,
            Class::Motion => 1,
            Class::Defocus => 2,
            Class::MotionDefocus => 3,
        }
    }
    /// Name for reports and errors: "static", "motion", "defocus", "motion+defocus".
    pub fn name(self) -> &'static str {
        match self {
            Class::Static => "static",
            Class::Motion => "motion",
            Class::Defocus => "defocus",
            Class::MotionDefocus => "motion+defocus",
        }
    }
    /// Whether the triangle moves (any of x, y, z, w, or the CoC of a defocused triangle).
    pub fn motion(self) -> bool {
        matches!(self, Class::Motion | Class::MotionDefocus)
    }
    /// Whether any CoC is non-zero.
    pub fn defocus(self) -> bool {
        matches!(self, Class::Defocus | Class::MotionDefocus)
    }
}

/// Why a triangle was culled in setup.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cull {
    /// outside the frustum (or the viewport) for the whole shutter and lens
    Outside,
    /// zero determinant at every (t, u, v): covers no sample
    Degenerate,
}

/// One axis's lens-corner boxes, raw [`PixelCoord`]s at lens = −1 (`[0]`) and lens = +1 (`[1]`).
/// `None`: unbounded on that side for every lens point (camera-plane crossing on that side).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AxisBoxes {
    /// floor of the box minimum at each lens corner
    pub lo: Option<[PixelCoord; 2]>,
    /// ceil of the box maximum at each lens corner
    pub hi: Option<[PixelCoord; 2]>,
}

/// Static in-focus edge data: normals `n_k = P_{k+1} × P_{k+2}` and `det`, raw 2·16 fraction bits.
/// Built only by setup from a checked [`Triangle`], so |n| < 2^59 and `det_sign` is ±1.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StaticEdges {
    pub(crate) n: [[i128; 3]; 3],
    pub(crate) det_sign: i32,
}

impl StaticEdges {
    /// Edge normals (a, b, c) per edge.
    pub fn n(&self) -> [[i128; 3]; 3] {
        self.n
    }
    /// Sign of P0·(P1×P2): −1 or 1 (0 is culled).
    pub fn det_sign(&self) -> i32 {
        self.det_sign
    }
}

/// Everything later stages need about one triangle. Built only by [`setup_with`] (or
/// [`Setup::unculled`]) from a checked [`Triangle`] and [`Viewport`]; read through its methods,
/// so no out-of-domain value (say a bound precision of 70 bits) can reach the bounds' shifts:
///
/// ```compile_fail,E0616
/// fn widen(s: &mut uvt_core::Setup) {
///     s.prec.bnd = 70;
/// }
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Setup {
    pub(crate) class: Class,
    pub(crate) footprint: PixelRect,
    pub(crate) span: Interval,
    pub(crate) axes: [AxisBoxes; 2],
    pub(crate) tri: Triangle,
    /// `dv[i][k] = r_i[k] − q_i[k]`: each vertex field's change over the shutter (|.| ≤ 2^30,
    /// both ends |.| ≤ 2^29), the bounded sample test's lerp operand ([`Setup::dv`]).
    pub(crate) dv: [[i32; 5]; 3],
    pub(crate) viewport: Viewport,
    pub(crate) edges: Stored,
    pub(crate) prec: PrecisionBits,
    pub(crate) eps: Eps,
}

/// The static-triangle data a setup stores for its sample test, in one slot (so a setup is no
/// larger than with the exact normals alone): the exact normals (an exact precision), the
/// planar test's rounded vertices and exact normals (a [`crate::formats::Planar`] precision, `planar.rs`), or
/// nothing (every other class or precision).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Stored {
    /// nothing stored
    None,
    /// the exact normals (`sample.rs`)
    Exact(StaticEdges),
    /// the planar test's data (`planar.rs`)
    Planar(PlanarEdges),
}

impl Stored {
    /// The stored exact normals, if any.
    pub(crate) fn exact(&self) -> Option<StaticEdges> {
        match self {
            Stored::Exact(e) => Some(*e),
            _ => None,
        }
    }
}

impl Setup {
    /// Effects present.
    pub fn class(&self) -> Class {
        self.class
    }
    /// Pixels to visit (inside the viewport).
    pub fn footprint(&self) -> PixelRect {
        self.footprint
    }
    /// t span inside the frustum.
    pub fn span(&self) -> Interval {
        self.span
    }
    /// Lens-corner boxes, `[x axis, y axis]`.
    pub fn axes(&self) -> [AxisBoxes; 2] {
        self.axes
    }
    /// The input triangle.
    pub fn tri(&self) -> &Triangle {
        &self.tri
    }
    /// Each vertex field's change over the shutter, `r − q` (t = 1 minus t = 0), per vertex
    /// and field (x, y, z, w, CoC); all zero for the classes without motion. |.| ≤ 2^30.
    pub fn dv(&self) -> [[i32; 5]; 3] {
        self.dv
    }
    /// Viewport.
    pub fn viewport(&self) -> Viewport {
        self.viewport
    }
    /// Static in-focus edge data (class `Static` only). Stored by an exact precision's setup
    /// (its sample test reads them); computed here from the triangle for a bounded one (same
    /// value), so a bounded program does not contain the i128 normals unless it asks.
    pub fn edges(&self) -> Option<StaticEdges> {
        match self.edges {
            Stored::Exact(e) => Some(e),
            _ => (self.class == Class::Static).then(|| static_edges(&self.tri)),
        }
    }
    /// The precision this setup (and its bounds) use.
    pub fn prec(&self) -> PrecisionBits {
        self.prec
    }
    /// The conservative epsilon setup and the bounds widened by (zero for the exact test).
    pub fn eps(&self) -> Eps {
        self.eps
    }
    /// The planar test's per-triangle data (a static triangle of a `Planar` precision).
    pub fn planar(&self) -> Option<PlanarEdges> {
        match self.edges {
            Stored::Planar(p) => Some(p),
            _ => None,
        }
    }
}

/// Result of setup. (No heap in core, so the large variant stays inline.)
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// culled, with the reason
    Culled(Cull),
    /// visible: the setup
    Visible(Setup),
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

/// Classify: motion if any field differs between the ends (the CoC only counts when non-zero
/// somewhere), defocus if any CoC is non-zero.
pub fn classify(tri: &Triangle) -> Class {
    let [v0, v1] = &tri.v;
    let defocus = v0.iter().chain(v1.iter()).any(|p| p[C] != 0);
    let motion = v0.iter().zip(v1.iter()).any(|(a, b)| {
        a[X] != b[X] || a[Y] != b[Y] || a[Z] != b[Z] || a[W] != b[W] || (defocus && a[C] != b[C])
    });
    match (motion, defocus) {
        (false, false) => Class::Static,
        (true, false) => Class::Motion,
        (false, true) => Class::Defocus,
        (true, true) => Class::MotionDefocus,
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
fn axis_boxes(
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

/// [`axis_boxes`] over `N` w offsets per vertex (`M = 6·N` corner points).
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
    for ends in tri.v.iter() {
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
    for ends in tri.v.iter() {
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

/// Footprint columns (or rows) `[p0, p1)` of one axis from its boxes, clamped to `[0, E]`.
/// A sample at ξ is in column floor(ξ); ξ ≤ max means columns up to floor(max) are needed.
/// Pixel index floor(X / 2^bnd): an arithmetic right shift by bnd ≤ 16 (`PrecisionBits`), which
/// is the exact floor division by 2^bnd and loses no high bits (no divide instruction).
pub(crate) fn floor_px(x: PixelCoord, bnd: u32) -> PixelCoord {
    x.checked_shr(bnd).unwrap_or(if x < 0 { -1 } else { 0 })
}

fn axis_range(b: &AxisBoxes, extent: u16, bnd: u32) -> (u16, u16) {
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

/// Time span inside the frustum: for each plane w ∓ a ≥ 0 (both axes, widened by |c| for the
/// lens), the largest vertex distance is convex in t and lies below its chord; the chord's
/// non-negative part is a conservative span. The camera plane uses max w > 0 the same way.
/// Conservative epsilon (`bounded.rs`): the bounded test's perturbed vertex has
/// `w' ± a' ≤ w ± a + ε_w + ε_x`, and its hit needs `w' > 0`, i.e. `w + ε_w > 0`: both enter as
/// constant terms (zero for the exact test, which is then unchanged).
// Ranges: every raw field ≤ 2^29 in magnitude, ε ≤ 2^24: w + sign·x + |c| + ε < 2^31 and the
// differences a − b < 2^32, all in i64.
///
/// `MOTION = false` (a unit without motion, whose view of the triangle has equal ends,
/// [`unit_view`]): every chord is constant, `a = b`, and each `solve_le64(a − b, a)` is
/// `solve_le64(0, a)`, which [`constant_le`] gives without the division (`frac_div`), so such
/// a unit's program has none; the operations counted are the same.
#[allow(clippy::arithmetic_side_effects)]
fn frustum_span<const MOTION: bool>(tri: &Triangle, eps: &Eps, ops: &mut Ops) -> Option<Interval> {
    let solve = |a: i64, b: i64| {
        if MOTION {
            solve_le64(a - b, a)
        } else {
            constant_le(a)
        }
    };
    let [v0, v1] = &tri.v;
    let mut span = Interval::UNIT;
    let ew = i64::from(eps.w);
    // camera plane: a hit needs w > 0, so both ends' max w ≤ 0 means never visible.
    let wmax = |v: &[[i32; 5]; 3]| v.iter().map(|p| i64::from(p[W]) + ew).max().unwrap_or(0);
    let (a, b) = (wmax(v0), wmax(v1));
    ops.add_setup(6);
    if a <= 0 && b <= 0 {
        return None;
    }
    span = span.meet(solve(a, b)?)?;
    for axis in 0..2 {
        let e = ew + i64::from(eps.x.get(axis).copied().unwrap_or(0));
        for sign in [-1i64, 1] {
            let dist = |v: &[[i32; 5]; 3]| {
                v.iter()
                    .map(|p| {
                        let (x, cs) = axis_coord(p, axis);
                        i64::from(p[W]) + sign * x + cs.abs() + e
                    })
                    .max()
                    .unwrap_or(0)
            };
            let (a, b) = (dist(v0), dist(v1));
            ops.add_setup(14);
            span = span.meet(solve(a, b)?)?;
        }
    }
    Some(span)
}

/// `solve_le64(0, n)`: the t ∈ [0, 1] with `0·t ≤ n` — all of them for `n ≥ 0`, none else
/// (the constant chord of a triangle that does not move; `tests::constant_le_is_solve_le64_at_0`).
#[inline]
fn constant_le(n: i64) -> Option<Interval> {
    (n >= 0).then_some(Interval::UNIT)
}

/// det(P0, P1, P2) of raw (x, y, w) triples, exact in i128 (|P| < 2^33 here, so |det| < 2^102).
#[inline]
// Callers pass |P| < 2^33: products of three < 2^99, the sum of six < 2^102.
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn det3(p: &[[i128; 3]; 3]) -> i128 {
    let [a, b, c] = p;
    a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
        + a[2] * (b[0] * c[1] - b[1] * c[0])
}

/// Whether det(t, u, v) is zero for every t, u, v. det is cubic in t and bilinear in (u, v), so it
/// vanishes identically iff it vanishes at t ∈ {0, 1/3, 2/3, 1} × (u, v) ∈ {0, 1}² (evaluated
/// exactly, scaled by 3 so every point is an integer).
// Ranges: j, u, v ∈ {0..3}; (3 − j)·q + j·r ≤ 3·2^29, plus u·c ≤ 3·2^29: |P| < 2^32 < 2^33 as
// `det3` needs.
#[allow(clippy::arithmetic_side_effects)]
fn degenerate(tri: &Triangle, (motion, defocus): (bool, bool), ops: &mut Ops) -> bool {
    let [v0, v1] = &tri.v;
    let tj: &[i128] = if motion { &[0, 1, 2, 3] } else { &[0] };
    let lens: &[i128] = if defocus { &[0, 1] } else { &[0] };
    for &j in tj {
        for &u in lens {
            for &v in lens {
                let mut p = [[0i128; 3]; 3];
                for ((q, r), out) in v0.iter().zip(v1.iter()).zip(p.iter_mut()) {
                    let mut l = [0i128; 5];
                    for ((o, &a), &b) in l.iter_mut().zip(q).zip(r) {
                        *o = (3 - j) * i128::from(a) + j * i128::from(b);
                    }
                    let c = l[C];
                    *out = [l[X] + u * c, l[Y] + v * c, l[W]];
                }
                ops.add_setup(30);
                if det3(&p) != 0 {
                    return false;
                }
            }
        }
    }
    true
}

impl Setup {
    /// The sample-test data of a triangle without culling or bounds (footprint = whole
    /// viewport, span = [0, 1]). For verification only: it lets tests and the host ask whether a
    /// triangle that [`setup`] culled really covers no sample.
    pub fn unculled(tri: &Triangle, vp: Viewport) -> Setup {
        Setup::unculled_with::<DefaultPrecision>(tri, vp)
    }

    /// [`Setup::unculled`] at precision `P` (its sample test: exact or bounded).
    pub fn unculled_with<P: Precision>(tri: &Triangle, vp: Viewport) -> Setup {
        let class = classify(tri);
        let prec = PrecisionBits::of::<P>();
        let full = AxisBoxes { lo: None, hi: None };
        let footprint = PixelRect {
            x0: 0,
            y0: 0,
            x1: vp.w,
            y1: vp.h,
        };
        let exact = P::OFFSET_SHIFT.is_none();
        let planar = if P::PLANAR && class == Class::Static {
            planar_setup(tri, vp, &mut Ops::default())
        } else {
            None
        };
        let edges = match planar {
            Some((p, _)) => Stored::Planar(p),
            None if exact && class == Class::Static => Stored::Exact(static_edges(tri)),
            None => Stored::None,
        };
        Setup {
            class,
            footprint,
            span: Interval::UNIT,
            axes: [full, full],
            tri: *tri,
            dv: shutter_deltas(tri),
            viewport: vp,
            edges,
            prec,
            eps: match planar {
                Some((_, e)) => e,
                None => Eps::of(prec.offset_shift(), class, vp),
            },
        }
    }
}

// |P| ≤ 2^29 raw: each product < 2^58, each normal component < 2^59.
#[allow(clippy::arithmetic_side_effects)]
fn static_edges(tri: &Triangle) -> StaticEdges {
    let p = tri.v[0].map(|q| [q[X], q[Y], q[W]].map(i128::from));
    let det = det3(&p);
    let [p0, p1, p2] = p;
    let n = [(p1, p2), (p2, p0), (p0, p1)].map(|(a, b)| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    });
    StaticEdges {
        n,
        det_sign: if det < 0 { -1 } else { i32::from(det > 0) },
    }
}

/// Run setup on one triangle at the default precision. Counts its arithmetic in `ops.setup`.
pub fn setup(tri: &Triangle, vp: Viewport, ops: &mut Ops) -> Outcome {
    setup_with::<DefaultPrecision>(tri, vp, ops)
}

/// Run setup at precision `P`: box coordinates on `P`'s bound grid, the time span rounded
/// outward to `P`'s t grid.
pub fn setup_with<P: Precision>(tri: &Triangle, vp: Viewport, ops: &mut Ops) -> Outcome {
    setup_scaled::<P>(tri, vp, 1, 1, ops)
}

/// **Measurement only**: [`setup_with`] with the conservative epsilon scaled down to
/// `floor(ε·num/den)` (`num ≤ den`, else `num = den`; `den = 0` gives ε = 0), so a report can
/// find the smallest margin with zero violations. Below the analytic ε the bounds are **not**
/// guaranteed conservative for the bounded test; every value stays inside the range proofs.
pub fn setup_scaled<P: Precision>(
    tri: &Triangle,
    vp: Viewport,
    num: u32,
    den: u32,
    ops: &mut Ops,
) -> Outcome {
    setup_gated::<P, Full>(tri, classify(tri), vp, num, den, ops)
}

/// Setup on unit `U` ([`crate::unit`]) at precision `P`: `Err(class)` (nothing computed
/// beyond [`classify`]) when `U` does not accept the triangle's class, else exactly
/// [`setup_with::<P>`]'s outcome. The terms of the classes `U` lacks are compiled out: the
/// stages read the unit's view of the triangle ([`unit_view`]: t0 fields only without
/// motion, no CoC without defocus), which equals the triangle for every class `U` accepts.
pub fn setup_unit<P: Precision, U: Unit>(
    tri: &Triangle,
    vp: Viewport,
    ops: &mut Ops,
) -> Result<Outcome, Class> {
    let class = classify(tri);
    if !U::accepts(class) {
        return Err(class);
    }
    Ok(setup_gated::<P, U>(
        &unit_view::<U>(tri),
        class,
        vp,
        1,
        1,
        ops,
    ))
}

/// The fields of `tri` unit `U` reads: the shutter-close vertices replaced by the open ones
/// without `U::MOTION`, the CoC set to 0 without `U::DEFOCUS`. For a triangle whose class `U`
/// accepts this is the triangle itself: a class without motion has equal ends (`classify`), one
/// without defocus every CoC 0. Compiled per unit, so the full unit copies the triangle as is.
pub fn unit_view<U: Unit>(tri: &Triangle) -> Triangle {
    let mut t = *tri;
    if !U::MOTION {
        let [v0, _] = t.v;
        t.v = [v0, v0];
    }
    if !U::DEFOCUS {
        for p in t.v.iter_mut().flatten() {
            p[C] = 0;
        }
    }
    t
}

/// [`setup_scaled`] of a triangle of `class` that `U` accepts (the caller checks): every class
/// branch is `U::MOTION && class.motion()` (`U::DEFOCUS && …`), the same value for an accepted
/// class and a constant `false` where the unit lacks the effect.
fn setup_gated<P: Precision, U: Unit>(
    tri: &Triangle,
    class: Class,
    vp: Viewport,
    num: u32,
    den: u32,
    ops: &mut Ops,
) -> Outcome {
    let prec = PrecisionBits::of::<P>();
    // Exact precisions decide on the type's constant: their instantiation carries no epsilon
    // code, so the exact setup compiles (and costs on the Cortex-M4F) as before the epsilon.
    let exact = P::OFFSET_SHIFT.is_none();
    // A `Planar` precision's static triangles (the class gated as in every unit: a constant for
    // the static-only unit) take the planar test, whose epsilon is per triangle (`planar.rs`);
    // `None` inside: culled as degenerate after the frustum test.
    let planar_class =
        P::PLANAR && !(U::MOTION && class.motion()) && !(U::DEFOCUS && class.defocus());
    let planar = planar_class.then(|| planar_setup(tri, vp, ops));
    let full = if exact {
        Eps::default()
    } else if let Some(pl) = planar {
        pl.map_or(Eps::default(), |(_, e)| e)
    } else {
        Eps::of(prec.offset_shift(), class, vp)
    };
    let scale = |e: i32| {
        let (n, d) = (i64::from(num.min(den)), i64::from(den));
        i64::from(e)
            .checked_mul(n)
            .and_then(|x| x.checked_div(d))
            .and_then(|x| i32::try_from(x).ok())
            .unwrap_or(0)
    };
    // Without motion ε_w is 0 for every accepted class (`Eps::of`); stating it lets the unit
    // drop the twelve-corner box code. The planar test's ε_w (the w rounding residual) is kept.
    let eps = Eps {
        x: full.x.map(scale),
        w: if U::MOTION || P::PLANAR {
            scale(full.w)
        } else {
            0
        },
    };
    ops.add_setup(30);
    let span_eps = if exact { Eps::default() } else { eps };
    let span = match if U::MOTION {
        frustum_span::<true>(tri, &span_eps, ops)
    } else {
        frustum_span::<false>(tri, &span_eps, ops)
    } {
        Some(s) => s.round_out(prec.tuv()),
        None => return Outcome::Culled(Cull::Outside),
    };
    let planar = match planar {
        Some(None) => return Outcome::Culled(Cull::Degenerate),
        Some(Some((p, _))) => Some(p),
        None => None,
    };
    // A bounded test decides on a perturbed triangle, which need not be degenerate.
    let gated = (U::MOTION && class.motion(), U::DEFOCUS && class.defocus());
    if exact && degenerate(tri, gated, ops) {
        return Outcome::Culled(Cull::Degenerate);
    }
    let (ew, eh) = (vp.w as i64, vp.h as i64);
    let axes = if exact {
        [
            exact_boxes(tri, 0, ew, prec.bnd(), ops),
            exact_boxes(tri, 1, eh, prec.bnd(), ops),
        ]
    } else if U::MOTION || P::PLANAR {
        [
            axis_boxes(tri, 0, ew, prec.bnd(), &eps, ops),
            axis_boxes(tri, 1, eh, prec.bnd(), &eps, ops),
        ]
    } else {
        // ε_w = 0 without motion: `axis_boxes`' six-point branch, without its twelve-point one.
        let ex = |axis: usize| eps.x.get(axis).copied().unwrap_or(0);
        [
            corner_boxes::<1, 6>(tri, 0, ew, prec.bnd(), ex(0), [0], ops),
            corner_boxes::<1, 6>(tri, 1, eh, prec.bnd(), ex(1), [0], ops),
        ]
    };
    let (x0, x1) = axis_range(&axes[0], vp.w, prec.bnd());
    let (y0, y1) = axis_range(&axes[1], vp.h, prec.bnd());
    let footprint = PixelRect { x0, y0, x1, y1 };
    if footprint.is_empty() {
        return Outcome::Culled(Cull::Outside);
    }
    // The edge normals are counted for every static triangle (the setup's cost model), but
    // stored only by an exact precision, whose sample test reads them (`sample.rs`); the
    // bounded test never does, so its programs (the unit programs) carry no i128 normals.
    // [`Setup::edges`] gives the same value for both.
    if class == Class::Static {
        ops.add_setup(30);
    }
    let edges = match planar {
        Some(p) => Stored::Planar(p),
        None if exact && class == Class::Static => Stored::Exact(static_edges(tri)),
        None => Stored::None,
    };
    Outcome::Visible(Setup {
        class,
        footprint,
        span,
        axes,
        tri: *tri,
        dv: shutter_deltas(tri),
        viewport: vp,
        edges,
        prec,
        eps,
    })
}

/// `r − q` per vertex and field ([`Setup::dv`]). A checked triangle's fields are |.| ≤ 2^29, so
/// each difference is |.| ≤ 2^30 and fits i32 (`bounded_corners.rs` drives ±2^29 ends).
#[allow(clippy::arithmetic_side_effects)]
fn shutter_deltas(tri: &Triangle) -> [[i32; 5]; 3] {
    let [q, r] = &tri.v;
    let mut d = [[0; 5]; 3];
    for ((dv, qv), rv) in d.iter_mut().zip(q).zip(r) {
        for ((dk, qk), rk) in dv.iter_mut().zip(qv).zip(rv) {
            *dk = rk - qk;
        }
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The constant-chord solve of the units without motion equals `solve_le64(0, n)` at the
    /// sign boundary and the ends of the range `frustum_span` feeds it (|n| < 2^32).
    #[test]
    fn constant_le_is_solve_le64_at_0() {
        let cases = [
            i64::MIN,
            -(1 << 32),
            -(1 << 31),
            -2,
            -1,
            0,
            1,
            2,
            1 << 31,
            1 << 32,
            i64::MAX,
        ];
        for n in cases {
            assert_eq!(
                constant_le(n),
                solve_le64(0, n),
                "n = {n} ({n:#x}): expected solve_le64(0, n), observed constant_le(n)"
            );
        }
    }

    /// A bounded setup does not store the static normals, an exact one does; `edges()` gives
    /// the same value for both, and none for a moving triangle.
    #[test]
    fn edges_stored_for_exact_computed_for_bounded() {
        use crate::formats::{Bounded, Exact};
        let vp = Viewport::new(32, 32).unwrap();
        let prims = crate::demo::prims().unwrap();
        for (i, p) in prims.iter().enumerate() {
            let mut ops = Ops::default();
            let ex = setup_with::<Exact>(&p.tri, vp, &mut ops);
            let bd = setup_with::<Bounded<16, 16, 16, 20>>(&p.tri, vp, &mut ops);
            if let (Outcome::Visible(ex), Outcome::Visible(bd)) = (ex, bd) {
                let want = (ex.class == Class::Static).then(|| static_edges(&p.tri));
                assert_eq!(
                    ex.edges.exact(),
                    want,
                    "prim {i}: exact setup stores the normals"
                );
                assert_eq!(
                    bd.edges,
                    Stored::None,
                    "prim {i}: bounded setup stores none"
                );
                assert_eq!(bd.edges(), want, "prim {i}: bounded edges()");
                assert_eq!(ex.edges(), want, "prim {i}: exact edges()");
            }
        }
    }
}
