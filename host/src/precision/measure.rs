//! The brute-force measurement behind `uvt precision` (and `uvt render --precision`): the core's
//! decisions at a precision against the f64 reference on every footprint sample of every
//! triangle — coverage, distances, the quantization check, depth, bound slack, violations and
//! the measured epsilon (module docs of [`super::row`] and [`super::sweep`]) — and the
//! framebuffer check of covered samples that are not written ([`lost_samples`]).

use rayon::prelude::*;
use uvt_core::bounds::strategy::BoundsStrategy;
use uvt_core::config::precision::DefaultPrecision;
use uvt_core::config::unit::Full;
use uvt_core::{Laine2011, Ops, Outcome, PixelRect, Precision, ScreenPos, Setup, Triangle};

use crate::config::{dq, planar_static};
use crate::fit::search::inputs;
use crate::frame::compare::{check_sample_eps, eps_of, footprint_union, Rounding};
use crate::reference;
use crate::scene::file::Scene;
use crate::scene::pattern::Pattern;

use super::row::{finish, PrecRow};

/// Per-triangle brute force over the union of both footprints: coverage, distance and depth
/// once; bounds slack, violations and epsilon for every tile size of `accs`.
///
/// `dq_scale` scales every primitive's d_q (1 in every report; tests halve it to show that a
/// measured difference beyond it is caught).
pub(super) fn errors<P: Precision + Sync>(
    s: &Scene,
    core: &[Triangle],
    pat: &Pattern,
    accs: &mut [PrecRow],
    dq_scale: f64,
) {
    let vp = s.core_viewport();
    let v = s.viewport;
    let tiles: Vec<u16> = accs.iter().map(|a| a.tile as u16).collect();
    let parts: Vec<Vec<PrecRow>> = s
        .tris
        .par_iter()
        .zip(core.par_iter())
        .map(|(st, ct)| {
            let mut a: Vec<PrecRow> = tiles.iter().map(|_| PrecRow::default()).collect();
            let mut ops = Ops::default();
            let fx = match uvt_core::setup::<P, Full>(ct, vp, &mut ops) {
                Outcome::Visible(x) => Some((x, Laine2011.prepare::<Full>(&x, &mut ops))),
                Outcome::Culled(_) | Outcome::Refused(_) => None,
            };
            let rf = reference::setup::setup(st, v).ok();
            let Some(region) = footprint_union(
                fx.as_ref().map(|x| x.0.footprint()),
                rf.as_ref().map(|x| x.footprint),
            ) else {
                return a;
            };
            // P's own sample test (exact or bounded) and its perturbation in the bound.
            let full = Setup::unculled::<P>(ct, vp);
            let eps = eps_of(&full);
            let rounding = Rounding::at(P::POS_FRAC, P::TUV_FRAC);
            // The primitive's error statement at P (`crate::config::dq`): d_q px where stated in
            // pixels (scaled by `dq_scale`), else its backward error δ in clip units.
            let statement = dq::statement(st, v, &rounding, eps);
            let cell_of = |px: u16, py: u16, fp: PixelRect, bt: u16| {
                PixelRect {
                    x0: px - px % bt,
                    y0: py - py % bt,
                    x1: px - px % bt + bt,
                    y1: py - py % bt + bt,
                }
                .intersect(&fp)
            };
            let mut boxes = Vec::with_capacity(tiles.len());
            for py in region.y0..region.y1 {
                for px in region.x0..region.x1 {
                    boxes.clear();
                    for (ti, &bt) in tiles.iter().enumerate() {
                        let fbox = fx.as_ref().and_then(|(x, c)| {
                            x.footprint().contains(px, py).then(|| {
                                Laine2011.tile::<Full>(
                                    x,
                                    c,
                                    cell_of(px, py, x.footprint(), bt),
                                    &mut ops,
                                )
                            })
                        });
                        let rbox = rf.as_ref().and_then(|x| {
                            x.footprint.contains(px, py).then(|| {
                                reference::bounds::tile(x, cell_of(px, py, x.footprint, bt))
                            })
                        });
                        // Slack, once per cell (at its top-left pixel inside the region).
                        let first_x = px % bt == 0 || px == region.x0;
                        let first_y = py % bt == 0 || py == region.y0;
                        if let (true, true, Some(Some(fb)), Some(Some(rb))) =
                            (first_x, first_y, fbox, rbox)
                        {
                            let w = [(fb.t, rb.t), (fb.u, rb.u), (fb.v, rb.v)];
                            for (k, (fi, ri)) in w.iter().enumerate() {
                                let d = (fi.hi() - fi.lo()) as f64 / 65536.0 - (ri.1 - ri.0);
                                a[ti].slack_mean[k] += d;
                                a[ti].slack_max[k] = a[ti].slack_max[k].max(d);
                            }
                            a[ti].slack_n += 1;
                        }
                        boxes.push((fbox, rbox));
                    }
                    for si in 0..pat.spp as usize {
                        let idx = pat.index(px, py, si);
                        let (q, e) = (&pat.quant[idx], &pat.exact[idx]);
                        let hf = uvt_core::sample::test::<P, Full>(
                            &full,
                            ScreenPos::of(px, py, q),
                            q,
                            &mut ops,
                        );
                        let (x, y) = (px as f64 + e[0], py as f64 + e[1]);
                        let hr = reference::sample::sample_test(st, v, x, y, e[2], e[3], e[4]);
                        // Tile-independent measures go into row 0 and are copied when merging.
                        a[0].compared += 1;
                        if hf.is_some() != hr.is_some() {
                            a[0].differ += 1;
                            let d =
                                reference::sample::edge_distance_px(st, v, x, y, e[2], e[3], e[4]);
                            a[0].max_differ_px = a[0].max_differ_px.max(d);
                            match statement.px {
                                Some(d_q) => a[0].beyond_dq += u64::from(d > d_q * dq_scale),
                                None => {
                                    a[0].differ_clip += 1;
                                    a[0].max_clip = a[0].max_clip.max(statement.clip);
                                }
                            }
                            let c = check_sample_eps(st, v, x, y, e[2], e[3], e[4], &rounding, eps);
                            a[0].max_ratio = a[0].max_ratio.max(c.ratio);
                            a[0].beyond_bound += u64::from(c.ratio > 1.0);
                            a[0].behind += u64::from(c.behind);
                        }
                        if let (Some(h), Some(z)) = (hf, hr) {
                            if h.depth != uvt_core::config::formats::DEPTH_FAR && z.abs() < 128.0 {
                                let err = (h.depth as f64 - z * 16777216.0).abs();
                                a[0].depth_lsb[0] = a[0].depth_lsb[0].max(err);
                                a[0].depth_lsb[1] += err;
                                a[0].depth_n += 1;
                            }
                        }
                        if hf.is_none() {
                            continue;
                        }
                        let (u, vv, t) = (q.u().to_bits(), q.v().to_bits(), q.t().to_bits());
                        for (ti, (fbox, rbox)) in boxes.iter().enumerate() {
                            match fbox {
                                Some(Some(b)) if b.contains(u, vv, t) => {}
                                _ => a[ti].violations += 1,
                            }
                            match rbox {
                                Some(Some(rb)) => {
                                    let s3 = [
                                        t as f64 / 65536.0,
                                        u as f64 / 65536.0,
                                        vv as f64 / 65536.0,
                                    ];
                                    let r3 = [rb.t, rb.u, rb.v];
                                    for k in 0..3 {
                                        let out = (r3[k].0 - s3[k]).max(s3[k] - r3[k].1).max(0.0);
                                        a[ti].eps_measured[k] = a[ti].eps_measured[k].max(out);
                                    }
                                }
                                _ => a[ti].eps_outside += 1,
                            }
                        }
                    }
                }
            }
            a
        })
        .collect();
    for part in parts {
        let cov = part[0].clone();
        for (acc, p) in accs.iter_mut().zip(part) {
            acc.compared += cov.compared;
            acc.differ += cov.differ;
            acc.max_differ_px = acc.max_differ_px.max(cov.max_differ_px);
            acc.beyond_bound += cov.beyond_bound;
            acc.max_ratio = acc.max_ratio.max(cov.max_ratio);
            acc.behind += cov.behind;
            acc.beyond_dq += cov.beyond_dq;
            acc.differ_clip += cov.differ_clip;
            acc.max_clip = acc.max_clip.max(cov.max_clip);
            acc.depth_lsb[0] = acc.depth_lsb[0].max(cov.depth_lsb[0]);
            acc.depth_lsb[1] += cov.depth_lsb[1];
            acc.depth_n += cov.depth_n;
            for k in 0..3 {
                acc.slack_mean[k] += p.slack_mean[k];
                acc.slack_max[k] = acc.slack_max[k].max(p.slack_max[k]);
                acc.eps_measured[k] = acc.eps_measured[k].max(p.eps_measured[k]);
            }
            acc.slack_n += p.slack_n;
            acc.violations += p.violations;
            acc.eps_outside += p.eps_outside;
        }
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

/// Covered samples that reach an empty framebuffer slot, and of those the ones not written:
/// `(reached_empty, lost)`. Counted independently of the core's counters: every pixel gets its
/// own cleared core `TileBuffer`; the triangles run in submission order over every sample of
/// their footprint (no bounds: coverage is the sample test's alone); a covered sample whose slot
/// still holds the clear value (depth and color) must afterwards hold its depth and color.
pub fn lost_samples(scene: &Scene) -> (u64, u64) {
    let pat = Pattern::new(scene.pattern, scene.spp, scene.seed);
    let vp = scene.core_viewport();
    let mut ops = Ops::default();
    let setups: Vec<Setup> = scene
        .tris
        .iter()
        .map(|t| t.to_core().expect("loaded scene is in the domain"))
        .filter_map(|t| {
            match uvt_core::setup::<uvt_core::DefaultPrecision, uvt_core::Full>(&t, vp, &mut ops) {
                Outcome::Visible(s) => Some(s),
                Outcome::Culled(_) | Outcome::Refused(_) => None,
            }
        })
        .collect();
    let black = uvt_core::Rgb888::new(0, 0, 0);
    let white = uvt_core::Rgb888::new(255, 255, 255);
    let spp = usize::from(pat.spp);
    (0..vp.height())
        .into_par_iter()
        .map(|py| {
            let (mut reached, mut lost) = (0u64, 0u64);
            let mut fb = uvt_core::TileBuffer::<1, 1, 64>::new(black);
            let mut ops = Ops::default();
            for px in 0..vp.width() {
                fb.clear(black);
                for s in setups.iter().filter(|s| s.footprint().contains(px, py)) {
                    for si in 0..spp {
                        let q = &pat.quant[pat.index(px, py, si)];
                        let pos = ScreenPos::of(px, py, q);
                        let Some(h) =
                            uvt_core::sample::test::<DefaultPrecision, Full>(s, pos, q, &mut ops)
                        else {
                            continue;
                        };
                        let empty = fb.depth(0, 0, si)
                            == Some(uvt_core::config::formats::DEPTH_EMPTY)
                            && fb.sample_color(0, 0, si) == Some(black);
                        let _ = fb.write(0, 0, si, white, h.depth);
                        if empty {
                            reached += 1;
                            let written = fb.depth(0, 0, si) == Some(h.depth)
                                && fb.sample_color(0, 0, si) == Some(white);
                            lost += u64::from(!written);
                        }
                    }
                }
            }
            (reached, lost)
        })
        .reduce(|| (0, 0), |a, b| (a.0 + b.0, a.1 + b.1))
}

/// The core's decisions at precision `P` (triangles `core`, table `pat` quantized to `P`) against
/// the f64 reference on every footprint sample, with the quantization distance at `P` and the
/// conservativeness check at the scene's tile size (used by `uvt render --precision`).
pub fn decisions<P: Precision + Sync>(scene: &Scene, core: &[Triangle], pat: &Pattern) -> PrecRow {
    let mut acc = [PrecRow {
        tile: scene.tile,
        ..Default::default()
    }];
    errors::<P>(scene, core, pat, &mut acc, 1.0);
    let [mut row] = acc;
    finish(&mut row);
    row
}

/// [`decisions`] at the planar static configuration with its per-primitive d_q scaled by
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
