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

pub mod boxes;
pub mod eps;
pub mod exact_edges;
pub mod planar;
pub mod span;

use crate::arith::interval::Interval;
use crate::config::class::Class;
use crate::config::precision::{Precision, PrecisionBits};
use crate::config::unit::{Full, Unit};
use crate::input::{PixelRect, Triangle, Viewport, C};
use crate::setup::boxes::{axis_boxes, axis_range, corner_boxes, exact_boxes, AxisBoxes};
use crate::setup::eps::Eps;
use crate::setup::exact_edges::{degenerate, static_edges, StaticEdges};
use crate::setup::planar::{planar_setup, PlanarEdges};
use crate::setup::span::frustum_span;
use crate::stats::Ops;

/// Why a triangle was culled in setup.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cull {
    /// outside the frustum (or the viewport) for the whole shutter and lens
    Outside,
    /// zero determinant at every (t, u, v): covers no sample
    Degenerate,
}

/// Everything later stages need about one triangle. Built only by [`setup`] (or
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
/// planar test's rounded vertices and exact normals (a [`crate::config::precision::Planar`] precision, `planar.rs`), or
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

/// Result of a setup on a unit: visible with the per-triangle data `S` — a [`Setup`] here, the
/// specialised units' own setups in `crate::units` — culled with the reason, or refused: the
/// triangle's class needs an effect the unit has no hardware for (never on the full unit).
/// (No heap in core, so the large variant stays inline.)
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome<S = Setup> {
    /// culled, with the reason
    Culled(Cull),
    /// visible: the setup
    Visible(S),
    /// not accepted by the unit (nothing computed beyond [`Triangle::class`]): the class
    Refused(Class),
}

impl<S> Outcome<S> {
    /// The visible triangle's setup; `None` if culled or refused.
    pub fn visible(self) -> Option<S> {
        match self {
            Outcome::Visible(s) => Some(s),
            Outcome::Culled(_) | Outcome::Refused(_) => None,
        }
    }
    /// The class of a refused triangle; `None` if the unit accepted it (visible or culled).
    pub fn refused(&self) -> Option<Class> {
        match self {
            Outcome::Refused(c) => Some(*c),
            Outcome::Visible(_) | Outcome::Culled(_) => None,
        }
    }
}

impl Setup {
    /// The sample-test data of a triangle at precision `P` without culling or bounds
    /// (footprint = whole viewport, span = [0, 1]). For verification only: it lets tests and
    /// the host ask whether a triangle that [`setup`] culled really covers no sample.
    pub fn unculled<P: Precision>(tri: &Triangle, vp: Viewport) -> Setup {
        let class = tri.class();
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
            planar_setup::<false>(tri, vp, &mut Ops::default())
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

/// **Measurement only**: [`setup`] on the full unit with the conservative epsilon scaled down to
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
    setup_gated::<P, Full>(tri, tri.class(), vp, num, den, ops)
}

/// Run setup on one triangle at precision `P` on unit `U` ([`crate::config::unit`]): box
/// coordinates on `P`'s bound grid, the time span rounded outward to `P`'s t grid; counts its
/// arithmetic in `ops.setup`. [`Outcome::Refused`] (nothing computed beyond
/// [`Triangle::class`]) when `U` does not accept the triangle's class; for every class `U`
/// accepts the outcome is the full unit's. The terms of the classes `U` lacks are compiled out: the stages read the
/// unit's view of the triangle ([`unit_view`]: t0 fields only without motion, no CoC without
/// defocus), which equals the triangle for every class `U` accepts.
#[inline(always)]
pub fn setup<P: Precision, U: Unit>(tri: &Triangle, vp: Viewport, ops: &mut Ops) -> Outcome {
    let class = tri.class();
    if !U::accepts(class) {
        return Outcome::Refused(class);
    }
    setup_gated::<P, U>(&unit_view::<U>(tri), class, vp, 1, 1, ops)
}

/// The fields of `tri` unit `U` reads: the shutter-close vertices replaced by the open ones
/// without `U::MOTION`, the CoC set to 0 without `U::DEFOCUS`. For a triangle whose class `U`
/// accepts this is the triangle itself: a class without motion has equal ends ([`Triangle::class`]), one
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
    let planar = planar_class.then(|| planar_setup::<false>(tri, vp, ops));
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

    /// A bounded setup does not store the static normals, an exact one does; `edges()` gives
    /// the same value for both, and none for a moving triangle.
    #[test]
    fn edges_stored_for_exact_computed_for_bounded() {
        use crate::config::precision::{Bounded, Exact};
        let vp = Viewport::new(32, 32).unwrap();
        // Static, moving and defocused triangles (the demo scene's first three), raw = 256·value.
        let v = |a: [i32; 5]| crate::input::Vertex::from_bits(a.map(|x| x * 256));
        let tri = |a: [[i32; 5]; 3], b: [[i32; 5]; 3]| Triangle::new(a.map(v), b.map(v)).unwrap();
        let still = [
            [-400, -300, 200, 400, 0],
            [400, -300, 200, 400, 0],
            [0, 100, 200, 400, 0],
        ];
        let blur = [
            [60, -150, 80, 300, 20],
            [200, -150, 80, 300, 20],
            [130, -20, 80, 300, 20],
        ];
        let tris = [
            tri(still, still),
            tri(
                [
                    [-200, 0, 100, 256, 0],
                    [-100, 0, 100, 256, 0],
                    [-150, 120, 100, 256, 0],
                ],
                [
                    [100, 20, 110, 256, 0],
                    [200, 20, 110, 256, 0],
                    [150, 140, 110, 256, 0],
                ],
            ),
            tri(blur, blur),
        ];
        let mut visible = 0;
        for (i, t) in tris.iter().enumerate() {
            let mut ops = Ops::default();
            let ex = setup::<Exact, Full>(t, vp, &mut ops);
            let bd = setup::<Bounded<16, 16, 16, 20>, Full>(t, vp, &mut ops);
            if let (Outcome::Visible(ex), Outcome::Visible(bd)) = (ex, bd) {
                visible += 1;
                let want = (ex.class == Class::Static).then(|| static_edges(t));
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
        assert_eq!(visible, 3, "every triangle is visible");
    }
}
