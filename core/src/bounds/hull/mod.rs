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
//! points surround the camera, then nothing is culled): by trying every pair, or, when every
//! point has w > 0, by gift wrapping the projected points, which finds the same faces with the
//! same coefficients in the same order at a fraction of the ops ([`wrap`], [`hull_faces`]). The direction of a sample at sub-pixel
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
//! one first), stopping at the first that culls; the order changes only the op count. The first
//! [`KEPT_FACES`](tiles::KEPT_FACES) (8) of that order are stored: keeping fewer faces culls a
//! subset of the tiles (conservative), and no triangle of the quick bench scenes keeps more
//! than 6, so there the decisions are those of every face.
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

pub mod faces;
pub mod tiles;
pub mod wrap;

use crate::bounds::hull::faces::{eps_margin, pair_faces, swept_points, HullCoeffs};
use crate::bounds::hull::tiles::HullTiles;
use crate::bounds::hull::wrap::wrap_faces;
use crate::bounds::strategy::{BoundsStrategy, RowSpan};
use crate::config::unit::Unit;
use crate::input::PixelRect;
use crate::input::Viewport;
use crate::setup::Setup;
use crate::stats::Ops;

/// Gift wrapping from this many hull points on; below, the pair search costs fewer setup ops.
/// Means over 2000 random triangles (`verify/wrap_reference.rs`'s generator, seed 7): pair
/// search against wrapping 150 : 290 ops at 3 points (a static triangle), 702 : 677 at 6
/// (motion only), 3385 : 1642 at 12 (defocus only), 15932 : 3534 at 24 (both);
/// `wrap_is_used_where_it_costs_fewer_ops` fails when a class's means cross the rule. The faces
/// are the same either way.
pub const WRAP_FROM: usize = 4;

/// The faces of the cone of `pts`: every plane through the origin and two points that has all
/// points on one side (both orientations when all points lie on it), in the order of
/// [`pair_faces`]: by gift wrapping ([`wrap_faces`], O(n·h)) when every w > 0 and there are at
/// least [`WRAP_FROM`] points, else by [`pair_faces`] (O(n³)).
pub fn hull_faces(pts: &[[i64; 3]], vp: Viewport, ops: &mut Ops) -> HullCoeffs {
    let wrapped = if pts.len() >= WRAP_FROM {
        wrap_faces(pts, vp, ops)
    } else {
        None
    };
    match wrapped {
        Some(h) => h,
        None => pair_faces(pts, vp, ops),
    }
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
    type Coeffs = (HullTiles, S::Coeffs);
    type Tile = S::Tile;
    fn name(&self) -> &'static str {
        self.name
    }
    #[inline(always)]
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
