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
//! - *Screen space (d_q px), where it says something.* When every vertex stays in front of the
//!   camera by more than its Δw (above) and the resulting d_q is at most the viewport's diagonal
//!   ([`pixel_limit`]), every differing decision lies within d_q px of an edge. A larger d_q is
//!   finite but meaningless (a displacement bound larger than the screen): `host/stress/domain_edge.json`'s
//!   second triangle has a vertex at w = 2^-16 (one LSB) and x = 8191.99, so its projection
//!   x/w ≈ 5·10^8 moves by ≈ 2.5·10^8 under a half-LSB w rounding — 8·10^11 px on the 2048-px
//!   viewport, although that vertex is "at infinity" in one direction either way and the
//!   per-sample distances stay below 3·10^-3 px. Such a primitive, and one whose vertex can
//!   reach the camera plane, is stated in clip space only; no report says "no bound".
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
    /// only the clip statement applies (a vertex can reach the camera plane, or d_q exceeds
    /// [`pixel_limit`])
    pub px: Option<f64>,
}

/// The statement of one primitive with rounding `r` and datapath perturbation `eps` (raw clip
/// units x, y, w; module docs).
pub fn statement(tri: &SceneTri, vp: (u16, u16), r: &Rounding, eps: [f64; 3]) -> Statement {
    Statement {
        clip: backward(tri, r, eps),
        px: prim_dq(tri, vp, r, eps).filter(|d| *d <= pixel_limit(vp)),
    }
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

/// The largest d_q (px) stated in screen space: the viewport's diagonal (module docs).
pub fn pixel_limit(vp: (u16, u16)) -> f64 {
    f64::from(vp.0).hypot(f64::from(vp.1))
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
