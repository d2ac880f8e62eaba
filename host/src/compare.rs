//! Brute-force comparison of the core's coverage with the f64 reference's, sample by sample, and
//! the documented quantization distance that bounds where they may disagree.
//!
//! The core sees rounded inputs: vertex coordinates and CoC to 2^-16 (error ≤ 2^-17), t/u/v to
//! 2^-16 (≤ 2^-17), sub-pixel positions floored to 1/256 px. To first order a vertex's screen
//! position moves by at most
//!   `d_q = √2/256 + S·2^-17·[(2 + R) + max_k(|Δx_k| + |Δc_k| + R·|Δw_k|) + max_k|c_k|] / w_min`
//! pixels, with S = max(W, H)/2 px per NDC unit, R the largest |x/w|, |y/w| of the six vertices,
//! w_min their smallest w and Δ the t0→t1 change; edges move no more than their vertices. The
//! documented bound is **2·d_q + 10^-6 px** (factor 2 for second-order terms and f64 round-off).
//! A sample farther than that from every edge must get the same answer from both; the bound is
//! infinite (no claim) when a vertex has w ≤ 0 at either end.

use rayon::prelude::*;
use uvt_core::{sample_test, PixelRect, ScreenPos, Setup, Triangle, Viewport};

use crate::pattern::Pattern;
use crate::reference;
use crate::scene::SceneTri;

/// Result of a comparison.
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct CoverageDiff {
    /// (triangle, sample) pairs compared
    pub compared: u64,
    /// covered by the core only
    pub fixed_only: u64,
    /// covered by the reference only
    pub f64_only: u64,
    /// differences farther from an edge than the documented bound (must be 0)
    pub beyond_bound: u64,
    /// largest distance in pixels of a differing sample from the nearest edge
    pub max_distance_px: f64,
    /// largest documented bound among triangles with a difference
    pub max_bound_px: f64,
}

impl CoverageDiff {
    fn add(&mut self, o: &CoverageDiff) {
        self.compared += o.compared;
        self.fixed_only += o.fixed_only;
        self.f64_only += o.f64_only;
        self.beyond_bound += o.beyond_bound;
        self.max_distance_px = self.max_distance_px.max(o.max_distance_px);
        self.max_bound_px = self.max_bound_px.max(o.max_bound_px);
    }
    /// Differences per compared pair.
    pub fn rate(&self) -> f64 {
        if self.compared == 0 {
            0.0
        } else {
            (self.fixed_only + self.f64_only) as f64 / self.compared as f64
        }
    }
}

/// The documented quantization distance (pixels) of one triangle, see the module docs.
pub fn quant_distance_px(t: &SceneTri, vp: (u16, u16)) -> f64 {
    let all: Vec<&[f64; 5]> = t.t0.iter().chain(t.t1.iter()).collect();
    let wmin = all.iter().map(|v| v[3]).fold(f64::MAX, f64::min);
    if wmin <= 0.0 {
        return f64::INFINITY;
    }
    let r = all
        .iter()
        .map(|v| (v[0].abs().max(v[1].abs())) / v[3])
        .fold(0.0, f64::max);
    let motion = (0..3)
        .map(|k| {
            let (a, b) = (t.t0[k], t.t1[k]);
            (b[0] - a[0]).abs().max((b[1] - a[1]).abs())
                + (b[4] - a[4]).abs()
                + r * (b[3] - a[3]).abs()
        })
        .fold(0.0, f64::max);
    let coc = all.iter().map(|v| v[4].abs()).fold(0.0, f64::max);
    let s = vp.0.max(vp.1) as f64 / 2.0;
    let eps = 2f64.powi(-17);
    let dq = 2f64.sqrt() / 256.0 + s * eps * ((2.0 + r) + motion + coc) / wmin;
    2.0 * dq + 1e-6
}

/// The bounding rectangle of two optional footprints (`None` if both are absent).
pub fn footprint_union(a: Option<PixelRect>, b: Option<PixelRect>) -> Option<PixelRect> {
    match (a, b) {
        (Some(a), Some(b)) => Some(PixelRect {
            x0: a.x0.min(b.x0),
            y0: a.y0.min(b.y0),
            x1: a.x1.max(b.x1),
            y1: a.y1.max(b.y1),
        }),
        (Some(a), None) | (None, Some(a)) => Some(a),
        (None, None) => None,
    }
}

/// Compare every sample of every triangle's footprints (the union of the core's and the
/// reference's; both are conservative, so every covered sample is inside it).
pub fn compare(tris: &[SceneTri], core: &[Triangle], vp: Viewport, pat: &Pattern) -> CoverageDiff {
    let v = (vp.width(), vp.height());
    tris.par_iter()
        .zip(core.par_iter())
        .map(|(st, ct)| {
            let mut d = CoverageDiff::default();
            let mut ops = Default::default();
            let fp_fixed = match uvt_core::setup(ct, vp, &mut ops) {
                uvt_core::Outcome::Visible(s) => Some(s.footprint()),
                _ => None,
            };
            let fp_ref = reference::setup::setup(st, v).ok().map(|s| s.footprint);
            let Some(region) = footprint_union(fp_fixed, fp_ref) else {
                return d;
            };
            let full = Setup::unculled(ct, vp);
            let bound = quant_distance_px(st, v);
            for py in region.y0..region.y1 {
                for px in region.x0..region.x1 {
                    for si in 0..pat.spp as usize {
                        let idx = pat.index(px, py, si);
                        let (q, e) = (&pat.quant[idx], &pat.exact[idx]);
                        let f = sample_test(&full, ScreenPos::of(px, py, q), q, &mut ops).is_some();
                        let (x, y) = (px as f64 + e[0], py as f64 + e[1]);
                        let r =
                            reference::sample::sample_test(st, v, x, y, e[2], e[3], e[4]).is_some();
                        d.compared += 1;
                        if f != r {
                            if f {
                                d.fixed_only += 1
                            } else {
                                d.f64_only += 1
                            }
                            let dist =
                                reference::sample::edge_distance_px(st, v, x, y, e[2], e[3], e[4]);
                            d.max_distance_px = d.max_distance_px.max(dist);
                            d.max_bound_px = d.max_bound_px.max(bound);
                            if dist > bound {
                                d.beyond_bound += 1;
                            }
                        }
                    }
                }
            }
            d
        })
        .reduce(CoverageDiff::default, |mut a, b| {
            a.add(&b);
            a
        })
}
