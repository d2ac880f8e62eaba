//! The documented error distance d_q of a primitive at a configuration: how far (px) a decision
//! may differ from the exact one because of the input rounding and the datapath's perturbation.
//! `uvt fit` picks configurations by it; `uvt precision` reports it.
//!
//! **Documented error distance d_q of a primitive** (px). The same terms as the rigorous
//! per-sample check of `compare.rs` (module docs there: "Rounding", "Vertex perturbation"),
//! written per vertex instead of per sample: vertex k moves in clip space by at most
//! `Δx_k = 2δp + δt|x1 − x0| + δt|c1 − c0| + δt·max(|c0|, |c1|) + ε_x` (position rounding of x
//! and of the CoC, t rounding times the screen travel and the CoC change, u rounding times the
//! CoC, and the bounded datapath's perturbation `ε` of `Eps::of` for the primitive's class),
//! `Δy_k` likewise, `Δw_k = δp + δt|w1 − w0| + ε_w`, with `δp = 2^-(POS+1)` and
//! `δt = 2^-17 (+ 2^-(TUV+1) when TUV < 16)` ([`Rounding::at`]). Its projection moves by
//! `|x'/w' − x/w| = |Δx·w − x·Δw|/(w·w') ≤ (Δx_k + ρ_k·Δw_k)/(w_min − Δw_k)` where
//! `w_min = min(w0, w1)` is the vertex's nearest w over the shutter and
//! `ρ_k = max over both ends of (|x| + |c|)/w` its largest |x/w| over shutter and lens (the
//! guard band: a vertex far outside the view multiplies the w error) — both ends suffice because
//! `|x(t)| + |c(t)|` is at most the lerp of the ends' values and w(t) is the lerp of positive
//! ends. In pixels that is `·W/2` (x) and `·H/2` (y); the vertex moves by at most the Euclidean
//! length of the two. d_q of the primitive is the largest of these over its vertices, plus the
//! sample position's sub-pixel floor (less than 1/256 px in x and in y: `√2/256` px). (Before
//! issue 24 the axes were maximised separately and the floor counted once; on `uvt precision
//! --quick` 20 of exact-16-16-16's 7462 differing decisions and 1172 of bounded-12-12-12-26's
//! 179321 lay beyond that smaller figure.)
//! A point of an edge between two vertices in front of the camera is a convex combination of
//! their projections, so it moves by at most the larger vertex displacement. **No screen-space
//! bound** exists when some vertex has `w_min ≤ Δw_k` (it can reach the camera plane): such
//! primitives are counted separately and the confirmation reports their measured distances.
//! The scene's d_q of a configuration is the maximum over the other primitives.
//!
//! **The error statement of every primitive** ([`Statement`], [`statement`]). Two forms, and
//! every primitive has the first:
//! - *Clip space (backward error), always.* Every decision of the configuration equals the exact
//!   decision, at a sample position within 1/256 px of the pattern's (the sub-pixel floor), of
//!   the primitive with every vertex — at the sample's (t, u, v), lens offset included — moved
//!   by at most `δ = max_k ‖(Δx_k, Δy_k, Δw_k)‖₂` clip units (the terms above, with the CoC at
//!   its largest over the shutter). This is how the datapath is built: the core decides exactly
//!   on its rounded inputs, which lie within the rounding terms of the exact ones, and the
//!   bounded datapath's perturbation is a vertex perturbation of at most ε
//!   (`uvt_core::Eps`, `core/src/sample/bounded/mod.rs`). δ is finite for every finite input, camera-plane
//!   crossers and w ≤ 0 vertices included. It is *measured* by `compare.rs`'s per-sample check
//!   (`check_sample_eps`): a differing decision that no edge value or det within its Hadamard
//!   bound for a δ-perturbation explains is counted "beyond bound" (must be 0).
//! - *Screen space (d_q px), wherever it is defined.* When every vertex stays in front of the
//!   camera by more than its Δw (above), every differing decision lies within d_q px of an edge,
//!   and the primitive is held to that figure **however large it is**: a configuration whose
//!   d_q leaves the screen does not thereby escape to the clip statement. (Before issue 50 a d_q
//!   beyond the viewport's diagonal moved the primitive to the clip statement, and a
//!   configuration bad enough to lose a triangle could "meet" a pixel tolerance that way:
//!   one static triangle at w = 0.00166, 0.003 clip units across, lost all its 8454 samples at
//!   `bounded-12-12-12-24` and its confirmation passed.) A d_q beyond the tolerance fails it:
//!   `host/stress/domain_edge.json`'s second triangle has a vertex at w = 2^-16 (one LSB) and
//!   x = 8191.99, so its projection x/w ≈ 5·10^8 moves by ≈ 2.5·10^8 under a half-LSB w
//!   rounding — d_q 1.17·10^12 px on the 2048-px viewport (the x and y moves together) — and no configuration meets a pixel
//!   tolerance for it, although the per-sample distances stay below 3·10^-3 px (the figure
//!   bounds every point of the edge, the on-screen ones and the one at "infinity" alike).
//! - *Clip space only*, where the pixel form is undefined: a vertex within its Δw of the camera
//!   plane (or behind it). Such a primitive is held to its backward error δ, and δ must be
//!   **small against the primitive itself** ([`Statement::informative`]): at most
//!   [`CLIP_SHARE`] = 1/16 of its clip extent ([`extent`]: a lower bound, over the shutter and
//!   the lens, of its longest edge in (x, y, w)). A triangle whose every vertex may move by more
//!   than its own size is not described by "the exact decision of a nearby triangle": at
//!   δ ≥ half its longest edge the nearby triangle may be a point, which draws nothing. 1/16 keeps
//!   the nearby triangle's longest edge within 1/8 of its length and its direction within 7.2°.
//!   A configuration whose δ is not that small does not meet any tolerance for the primitive,
//!   and every differing decision of it fails a confirmation with a tolerance.
//!
//! **Meeting a tolerance** is one rule ([`Statement::meets`]) that `uvt fit`'s selection and its
//! confirmation both read: a primitive stated in pixels meets τ when d_q ≤ τ; one stated in clip
//! space only when δ ≤ τ_c and its statement is informative.
//!
//! A tolerance given in pixels (`uvt fit --tolerance τ`) has the clip form
//! `τ_c = 2τ/max(W, H)` ([`clip_tolerance`]): the clip displacement that moves a vertex at w = 1
//! by at most τ px.

use rayon::prelude::*;
use serde::Serialize;
use uvt_core::config::registry::Config;
use uvt_core::{Class, Precision, Setup, Triangle, Viewport};

use crate::config::rounding::{eps_of, Rounding};
use crate::scene::tri::SceneTri;

/// d_q of one primitive (px; module docs) with rounding `r` and datapath perturbation `eps`
/// (raw clip units x, y, w); `None` when some vertex can reach the camera plane.
pub fn prim_dq(tri: &SceneTri, vp: (u16, u16), r: &Rounding, eps: [f64; 3]) -> Option<f64> {
    let half = [f64::from(vp.0) / 2.0, f64::from(vp.1) / 2.0];
    let mut d: f64 = 0.0;
    for k in 0..3 {
        let (a, b) = (tri.t0[k], tri.t1[k]);
        let cmax = a[4].abs().max(b[4].abs());
        let lens = r.pos + r.tuv * (b[4] - a[4]).abs() + r.tuv * cmax;
        let dw = r.pos + r.tuv * (b[3] - a[3]).abs() + eps[2];
        let wmin = a[3].min(b[3]);
        // NaN-safe: anything but "in front by more than Δw" has no bound.
        if wmin.partial_cmp(&dw) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        let mut sq = 0.0;
        for (axis, e) in [(0usize, eps[0]), (1, eps[1])] {
            let dx = r.pos + r.tuv * (b[axis] - a[axis]).abs() + lens + e;
            let rho =
                ((a[axis].abs() + a[4].abs()) / a[3]).max((b[axis].abs() + b[4].abs()) / b[3]);
            let px = (dx + rho * dw) / (wmin - dw) * half[axis];
            sq += px * px;
        }
        // The vertex moves by at most its x and y bounds together (Euclidean).
        d = d.max(sq.sqrt());
    }
    // The sample moves by less than `sub` in x and in y: √2·sub.
    Some(d + std::f64::consts::SQRT_2 * r.sub)
}

/// The datapath perturbation of `cfg` for a primitive of `class` in `vp`, clip units.
pub fn eps_clip(cfg: &Config, class: Class, vp: Viewport) -> [f64; 3] {
    let e = uvt_core::Eps::of(cfg.off(), class, vp);
    let raw = |v: i32| f64::from(v) / 65536.0;
    [raw(e.x()[0]), raw(e.x()[1]), raw(e.w())]
}

/// The error statement of one primitive at one configuration (module docs, "The error statement
/// of every primitive").
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Statement {
    /// backward error δ, clip units: every decision equals the exact decision of the primitive
    /// with every vertex moved by at most this (always finite)
    pub clip: f64,
    /// d_q, px: every differing decision lies within this distance of an edge; `None` where
    /// only the clip statement applies (a vertex can reach the camera plane)
    pub px: Option<f64>,
    /// the primitive's own clip extent ([`extent`]), against which δ must be small
    pub extent: f64,
}

/// The largest share of a primitive's clip extent its backward error δ may be for the clip
/// statement to say something (module docs).
pub const CLIP_SHARE: f64 = 1.0 / 16.0;

impl Statement {
    /// The clip statement says something about this primitive: δ ≤ [`CLIP_SHARE`] × its extent
    /// (module docs). Always checked; it decides only for primitives stated in clip space only.
    pub fn informative(&self) -> bool {
        self.clip <= CLIP_SHARE * self.extent
    }

    /// δ as a share of the primitive's extent (infinite for a zero extent).
    pub fn share(&self) -> f64 {
        if self.extent > 0.0 {
            self.clip / self.extent
        } else {
            f64::INFINITY
        }
    }

    /// The one rule of meeting tolerance `tol` (module docs, "Meeting a tolerance").
    pub fn meets(&self, tol: &Tolerance) -> bool {
        match self.px {
            Some(d) => d <= tol.px,
            None => self.clip <= tol.clip && self.informative(),
        }
    }
}

/// The statement of one primitive with rounding `r` and datapath perturbation `eps` (raw clip
/// units x, y, w; module docs).
pub fn statement(tri: &SceneTri, vp: (u16, u16), r: &Rounding, eps: [f64; 3]) -> Statement {
    Statement {
        clip: backward(tri, r, eps),
        px: prim_dq(tri, vp, r, eps),
        extent: extent(tri),
    }
}

/// The primitive's clip extent (clip units; module docs): a lower bound, at every (t, u, v), on
/// its longest edge in (x, y, w). Per edge: the edge vector at the lens centre is linear in t,
/// so its smallest length is the distance of the origin from a segment; the lens offset adds
/// `(u·Δc, v·Δc, 0)` with |u|, |v| ≤ 1, at most `√2·|Δc|`, and |Δc| (linear in t) is largest at
/// an end. The largest of the three edges' bounds, 0 when none is positive.
pub fn extent(tri: &SceneTri) -> f64 {
    let mut e: f64 = 0.0;
    for k in 0..3 {
        let l = (k + 1) % 3;
        let at = |v: &[[f64; 5]; 3], f: usize| v[l][f] - v[k][f];
        let d0 = [0, 1, 3].map(|f| at(&tri.t0, f));
        let d1 = [0, 1, 3].map(|f| at(&tri.t1, f));
        let dd = [0, 1, 2].map(|i| d1[i] - d0[i]);
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let dd2 = dot(dd, dd);
        // The t in [0, 1] nearest the origin (0 when the edge does not change).
        let t = if dd2 > 0.0 {
            (-dot(d0, dd) / dd2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let p = [0, 1, 2].map(|i| d0[i] + t * dd[i]);
        let shortest = dot(p, p).sqrt();
        let dc = at(&tri.t0, 4).abs().max(at(&tri.t1, 4).abs());
        e = e.max(shortest - std::f64::consts::SQRT_2 * dc);
    }
    e.max(0.0)
}

/// The backward error δ (clip units) of one primitive: the largest vertex perturbation
/// `‖(Δx_k, Δy_k, Δw_k)‖₂` over its vertices (module docs; the terms of [`prim_dq`]).
pub fn backward(tri: &SceneTri, r: &Rounding, eps: [f64; 3]) -> f64 {
    let mut d: f64 = 0.0;
    for k in 0..3 {
        let (a, b) = (tri.t0[k], tri.t1[k]);
        let cmax = a[4].abs().max(b[4].abs());
        let lens = r.pos + r.tuv * (b[4] - a[4]).abs() + r.tuv * cmax;
        let dx = |axis: usize| r.pos + r.tuv * (b[axis] - a[axis]).abs() + lens + eps[axis];
        let dw = r.pos + r.tuv * (b[3] - a[3]).abs() + eps[2];
        d = d.max((dx(0) * dx(0) + dx(1) * dx(1) + dw * dw).sqrt());
    }
    d
}

/// A distance in pixels as reports print it: 6 decimals, or 4 significant digits from 10^4 px
/// on (a d_q is held however large; module docs).
pub fn px_text(d: f64) -> String {
    if d < 1e4 {
        format!("{d:.6}")
    } else {
        format!("{d:.3e}")
    }
}

/// The clip form of a tolerance of `px` pixels on viewport `vp` (module docs).
pub fn clip_tolerance(px: f64, vp: (u16, u16)) -> f64 {
    2.0 * px / f64::from(vp.0.max(vp.1))
}

/// The tolerance in both forms of the error statement (`crate::config::dq`): pixels for the
/// primitives stated in screen space, clip units (backward error) for the others.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Tolerance {
    /// pixels
    pub px: f64,
    /// clip units
    pub clip: f64,
}

impl Tolerance {
    /// `px` pixels and its clip form `2·px/max(W, H)` on viewport `vp` ([`clip_tolerance`]),
    /// unless `clip` is given.
    pub fn new(px: f64, clip: Option<f64>, vp: (u16, u16)) -> Tolerance {
        Tolerance {
            px,
            clip: clip.unwrap_or_else(|| clip_tolerance(px, vp)),
        }
    }
}

/// The statements of `tris` at rounding `r` for a core sample test whose perturbation at each
/// triangle is `eps_of` its unculled setup at `P` ([`statement`]), d_q scaled
/// by `dq_scale` (1 in every report; tests shrink it to show a difference beyond it is caught).
pub fn statements<P: Precision + Sync>(
    tris: &[SceneTri],
    core: &[Triangle],
    vp: Viewport,
    r: &Rounding,
    dq_scale: f64,
) -> Vec<Option<Statement>> {
    let v = (vp.width(), vp.height());
    tris.par_iter()
        .zip(core.par_iter())
        .map(|(st, ct)| {
            let eps = eps_of(&Setup::unculled::<P>(ct, vp));
            let mut s = statement(st, v, r, eps);
            s.px = s.px.map(|d| d * dq_scale);
            Some(s)
        })
        .collect()
}
