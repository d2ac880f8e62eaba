//! The brute-force measurement behind `uvt precision` and `uvt stress`: the one comparison
//! ([`crate::compare::pass`]) of the core's decisions at a precision with the f64 reference on
//! every footprint sample of every triangle — coverage, distances, the quantization check,
//! depth, bound slack, violations and the measured epsilon (module docs of [`super::row`] and
//! [`super::sweep`]) — and the framebuffer check of covered samples that are not written
//! ([`lost_samples`]).

use embedded_graphics_core::pixelcolor::RgbColor;
use uvt_core::config::precision::DefaultPrecision;
use uvt_core::config::unit::Full;
use uvt_core::{
    BboxScan, DepthTest, Engine, General, Laine2011, NoZmax, Observer, PixelRect, Precision,
    Sample, Seen, Triangle,
};

use crate::compare::pass::{compare, Spec};
use crate::config::dq::statements;
use crate::config::planar_static;
use crate::config::rounding::Rounding;
use crate::fit::search::inputs;
use crate::frame::core_frame::run_core_with;
use crate::frame::opts::RunOpts;
use crate::scene::file::Scene;
use crate::scene::pattern::Pattern;

use super::row::{finish, PrecRow};

/// The one comparison ([`crate::compare::pass`]) of the core at `P` with the reference on every
/// footprint sample of every triangle of `s`, Laine 2011's conservativeness at every tile size
/// of `accs`, into `accs` (coverage, distances, statements and depth are the same for every
/// tile size). `dq_scale` scales every primitive's d_q (1 in every report; tests halve it to
/// show that a measured difference beyond it is caught).
pub(super) fn errors<P: Precision + Sync>(
    s: &Scene,
    core: &[Triangle],
    pat: &Pattern,
    accs: &mut [PrecRow],
    dq_scale: f64,
) {
    let vp = s.core_viewport();
    let rounding = Rounding::at(P::POS_FRAC, P::TUV_FRAC);
    let spec = Spec {
        strategy: Laine2011,
        tiles: accs.iter().map(|a| a.tile).collect(),
        statements: statements::<P>(&s.tris, core, vp, &rounding, dq_scale),
        tolerance: None,
        rounding,
    };
    let c = compare::<P, _>(&s.tris, core, vp, pat, &spec);
    for (acc, t) in accs.iter_mut().zip(&c.tiles) {
        acc.compared += c.compared;
        acc.differ += c.differ;
        acc.max_differ_px = acc.max_differ_px.max(c.max_distance_px);
        acc.beyond_bound += c.beyond_bound;
        acc.max_ratio = acc.max_ratio.max(c.max_ratio);
        acc.behind += c.behind;
        acc.beyond_dq += c.beyond_statement;
        acc.differ_clip += c.differ_clip;
        acc.max_clip = acc.max_clip.max(c.max_clip);
        acc.differ_clip_uninformative += c.differ_clip_uninformative;
        acc.prims_lost_gained[0] += c.lost;
        acc.prims_lost_gained[1] += c.gained;
        acc.depth_lsb[0] = acc.depth_lsb[0].max(c.depth_lsb_max);
        acc.depth_lsb[1] += c.depth_lsb_sum;
        acc.depth_n += c.depth_n;
        for k in 0..3 {
            acc.slack_mean[k] += t.slack_sum[k];
            acc.slack_max[k] = acc.slack_max[k].max(t.slack_max[k]);
            acc.eps_measured[k] = acc.eps_measured[k].max(t.eps_measured[k]);
        }
        acc.slack_n += t.slack_n;
        acc.violations += t.violations;
        acc.eps_outside += t.eps_outside;
    }
}

/// The planar configuration's d_q per primitive of `s` (`crate::config::planar_static::prim_dq`;
/// `None`: no screen-space bound) and the largest of them.
pub fn planar_dq(s: &Scene) -> (f64, Vec<Option<f64>>) {
    let v: Vec<Option<f64>> = s
        .tris
        .iter()
        .map(|t| {
            let c = t.to_core().ok()?;
            let class = c.class();
            planar_static::prim_dq(t, &c, class, s.viewport, 1.0)
        })
        .collect();
    let m = v.iter().flatten().fold(0.0f64, |a, &b| a.max(b));
    (m, v)
}

/// Covered samples that reach an empty framebuffer slot, and of those the ones not written, plus
/// the slots whose final colour is not the nearest covered sample's: `(reached_empty, lost)`.
/// Counted independently of the core's counters and depth test, by an observer of the core's
/// frame ([`Lost`]) at the default precision with the bounding-box scan (every sample of every
/// footprint is tested: coverage is the sample test's alone), the triangles in submission order.
pub fn lost_samples(scene: &Scene) -> anyhow::Result<(u64, u64)> {
    let (core, pat) = scene.inputs_at::<DefaultPrecision>()?;
    let colors = scene.colors();
    let o = RunOpts {
        image: true,
        ..RunOpts::for_scene(scene, &colors)
    };
    let table = pat.core();
    let vp = scene.core_viewport();
    let engine = Engine::<General<BboxScan, DefaultPrecision, Full>, NoZmax>::new(BboxScan, vp);
    let spp = usize::from(pat.spp);
    let (frame, bands) = run_core_with(&engine, &core, &table, &o, |rect| {
        Lost::new(rect, spp, &colors)
    })
    .map_err(|e| anyhow::anyhow!("{e}"))?;
    let (mut reached, mut lost) = (0, 0);
    let mut slot = 0;
    for b in &bands {
        reached += b.reached;
        lost += b.lost;
        // The frame's samples are the bands' slots in order (row-major, then by sample).
        for want in &b.nearest {
            let got = frame.samples.get(slot).copied();
            let want = want.map_or(o.clear, |(_, c)| c);
            lost += u64::from(got.map(|c| [c.r(), c.g(), c.b()]) != Some(want));
            slot += 1;
        }
    }
    Ok((reached, lost))
}

/// The observer of [`lost_samples`] over one band: per slot whether it was ever written, and
/// the nearest covered sample so far (depth, colour; the first on equal depths).
struct Lost<'a> {
    rect: PixelRect,
    spp: usize,
    colors: &'a [[u8; 3]],
    written: Vec<bool>,
    nearest: Vec<Option<(i32, [u8; 3])>>,
    reached: u64,
    lost: u64,
}

impl<'a> Lost<'a> {
    fn new(rect: PixelRect, spp: usize, colors: &'a [[u8; 3]]) -> Lost<'a> {
        let n = usize::from(rect.x1 - rect.x0) * usize::from(rect.y1 - rect.y0) * spp;
        Lost {
            rect,
            spp,
            colors,
            written: vec![false; n],
            nearest: vec![None; n],
            reached: 0,
            lost: 0,
        }
    }
}

impl Observer for Lost<'_> {
    fn sample(&mut self, tri: u32, px: u16, py: u16, si: usize, _: &Sample, seen: Seen) {
        let (Some(h), true) = (seen.hit, seen.admitted) else {
            return;
        };
        let w = usize::from(self.rect.x1 - self.rect.x0);
        let pixel = usize::from(py - self.rect.y0) * w + usize::from(px - self.rect.x0);
        let slot = pixel * self.spp + si;
        let written = seen.depth_test == Some(DepthTest::Written);
        if !self.written[slot] {
            self.reached += 1;
            self.lost += u64::from(!written);
        }
        self.written[slot] |= written;
        let color = self.colors.get(tri as usize).copied().unwrap_or_default();
        if self.nearest[slot].map_or(true, |(d, _)| h.depth < d) {
            self.nearest[slot] = Some((h.depth, color));
        }
    }
}

/// The comparison of the planar static configuration with its per-primitive d_q scaled by
/// `dq_scale` (1: the documented d_q; `beyond_dq` counts the differing decisions of primitives
/// with a d_q farther than the scaled d_q from the nearest edge), and the degenerate count.
pub fn planar_decisions(scene: &Scene, dq_scale: f64) -> anyhow::Result<PrecRow> {
    type P = uvt_core::PlanarPrecision;
    let (core, pat) = inputs::<P>(scene)?;
    let mut acc = [PrecRow {
        config: uvt_core::config::registry::PLANAR.to_string(),
        tile: scene.tile,
        d_q: [planar_dq(scene).0, 0.0],
        degenerate: planar_static::degenerate(scene).0,
        ..Default::default()
    }];
    errors::<P>(scene, &core, &pat, &mut acc, dq_scale);
    let [mut row] = acc;
    finish(&mut row);
    Ok(row)
}
