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
//! ends. In pixels that is `·W/2` (x) and `·H/2` (y). d_q of the primitive is the largest of
//! these over its vertices and both axes, plus the sample position's sub-pixel floor (1/256 px).
//! A point of an edge between two vertices in front of the camera is a convex combination of
//! their projections, so it moves by at most the larger vertex displacement. **No screen-space
//! bound** exists when some vertex has `w_min ≤ Δw_k` (it can reach the camera plane): such
//! primitives are counted separately and the confirmation reports their measured distances.
//! The scene's d_q of a configuration is the maximum over the other primitives.

use uvt_core::config::registry::Config;
use uvt_core::{Class, Viewport};

use crate::frame::compare::Rounding;
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
        for (axis, e) in [(0usize, eps[0]), (1, eps[1])] {
            let dx = r.pos + r.tuv * (b[axis] - a[axis]).abs() + lens + e;
            let rho =
                ((a[axis].abs() + a[4].abs()) / a[3]).max((b[axis].abs() + b[4].abs()) / b[3]);
            let px = (dx + rho * dw) / (wmin - dw) * half[axis];
            d = d.max(px);
        }
    }
    Some(d + r.sub)
}

/// The datapath perturbation of `cfg` for a primitive of `class` in `vp`, clip units.
pub fn eps_clip(cfg: &Config, class: Class, vp: Viewport) -> [f64; 3] {
    let e = uvt_core::Eps::of(cfg.off(), class, vp);
    let raw = |v: i32| f64::from(v) / 65536.0;
    [raw(e.x()[0]), raw(e.x()[1]), raw(e.w())]
}
