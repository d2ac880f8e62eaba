//! The f64 reference's frame: its own loop, deliberately independent of the core's — f64 setup
//! ([`reference::setup`]), Laine 2011's bounds in f64 on every bounds tile of the footprint
//! ([`reference::bounds`]), the ray-cast sample test ([`reference::sample`]) on the exact sample
//! table, an f64 depth test (strictly nearer wins, triangles in submission order) and resolve
//! with round-half-up — in parallel over bands of 8 rows (rayon). Nothing here calls the core:
//! the core's frame is [`super::core_frame`], and [`super::compare`] holds the two against each
//! other sample by sample.
//!
//! A triangle's setup is recomputed in every band its footprint meets (cheap in f64; keeping
//! every setup would cost ~300 bytes per triangle).

use std::time::Instant;

use rayon::prelude::*;
use uvt_core::{Cull, PixelRect};

use crate::reference;
use crate::scene::pattern::Pattern;
use crate::scene::tri::SceneTri;

use super::counters::{Frame, FrameStats};
use super::opts::RunOpts;

/// Rows of one band.
const BAND: u16 = 8;

/// The reference's frame of `tris` on the exact values of `pattern` with the options `o` (its
/// viewport, spp, bounds-tile size, colours, background and image; no oracle, no Zmax):
/// counters (no operation counts), image, heat map and wall time.
pub fn run_reference(tris: &[SceneTri], pattern: &Pattern, o: &RunOpts<'_>) -> Frame {
    let start = Instant::now();
    let vp = o.vp;
    // Footprints and classes (the setups themselves are recomputed per band).
    let setups: Vec<Result<(PixelRect, uvt_core::Class), Cull>> = tris
        .par_iter()
        .map(|t| reference::setup::setup(t, vp).map(|s| (s.footprint, s.class)))
        .collect();
    let mut stats = FrameStats {
        triangles: tris.len() as u64,
        ..Default::default()
    };
    let (w, h) = (vp.0 as usize, vp.1 as usize);
    let mut bins: Vec<Vec<u32>> = vec![Vec::new(); h.div_ceil(BAND as usize)];
    for (i, s) in setups.iter().enumerate() {
        match s {
            Err(Cull::Outside) => stats.culled_outside += 1,
            Err(Cull::Degenerate) => stats.culled_degenerate += 1,
            Ok((fp, class)) => {
                stats.by_class[class.index()] += 1;
                stats.footprint_samples +=
                    (fp.x1 - fp.x0) as u64 * (fp.y1 - fp.y0) as u64 * o.spp as u64;
                for bin in &mut bins[(fp.y0 / BAND) as usize..=((fp.y1 - 1) / BAND) as usize] {
                    bin.push(i as u32);
                }
            }
        }
    }
    let results: Vec<(FrameStats, Vec<[u8; 3]>, Vec<u32>)> = bins
        .par_iter()
        .enumerate()
        .map(|(b, list)| band(tris, pattern, o, &setups, b as u16, list))
        .collect();
    let mut image = Vec::with_capacity(if o.image { w * h } else { 0 });
    let mut heat = Vec::with_capacity(w * h);
    for (s, img, ht) in results {
        stats.add(&s);
        image.extend(img);
        heat.extend(ht);
    }
    Frame {
        stats,
        image,
        samples: Vec::new(),
        heat,
        time: start.elapsed(),
    }
}

/// One band `b` of the reference's frame: the triangles of `list` in order.
fn band(
    tris: &[SceneTri],
    pat: &Pattern,
    o: &RunOpts<'_>,
    setups: &[Result<(PixelRect, uvt_core::Class), Cull>],
    b: u16,
    list: &[u32],
) -> (FrameStats, Vec<[u8; 3]>, Vec<u32>) {
    let (w, s) = (o.vp.0 as usize, o.spp as usize);
    let y0 = b * BAND;
    let y1 = (y0 + BAND).min(o.vp.1);
    let rows = (y1 - y0) as usize;
    let mut depth = vec![f64::INFINITY; w * rows * s];
    let mut color = vec![o.clear; if o.image { w * rows * s } else { 0 }];
    let mut heat = vec![0u32; w * rows];
    let mut st = FrameStats::default();
    let screen = PixelRect {
        x0: 0,
        y0,
        x1: o.vp.0,
        y1,
    };
    for &i in list {
        let i = i as usize;
        let Ok((fp, _)) = setups[i] else {
            continue;
        };
        let region = fp.intersect(&screen);
        if region.is_empty() {
            continue;
        }
        // The setup again (the same outcome: visible).
        let Ok(setup) = reference::setup::setup(&tris[i], o.vp) else {
            continue;
        };
        for cell in region.cells(o.tile as u16) {
            st.tiles_visited += 1;
            let Some(bounds) = reference::bounds::tile(&setup, cell) else {
                st.tiles_skipped += 1;
                continue;
            };
            st.samples_admitted +=
                (cell.x1 - cell.x0) as u64 * (cell.y1 - cell.y0) as u64 * s as u64;
            for py in cell.y0..cell.y1 {
                for px in cell.x0..cell.x1 {
                    let pix = (py - y0) as usize * w + px as usize;
                    // The pixel's samples are consecutive in the table (`Pattern::index`).
                    let base = pat.index(px, py, 0);
                    for si in 0..s {
                        let e = &pat.exact[base + si];
                        if !bounds.contains(e[2], e[3], e[4]) {
                            continue;
                        }
                        st.samples_tested += 1;
                        heat[pix] += 1;
                        let (x, y) = (px as f64 + e[0], py as f64 + e[1]);
                        let hit = reference::sample::sample_test(
                            &setup.tri, o.vp, x, y, e[2], e[3], e[4],
                        );
                        let Some(d) = hit else {
                            continue;
                        };
                        st.samples_covered += 1;
                        let slot = pix * s + si;
                        if d < depth[slot] {
                            depth[slot] = d;
                            st.samples_written += 1;
                            if o.image {
                                color[slot] = o.colors[i];
                            }
                        }
                    }
                }
            }
        }
    }
    let image = if o.image {
        (0..w * rows)
            .map(|pix| {
                let mut sum = [0u32; 3];
                for c in &color[pix * s..pix * s + s] {
                    for k in 0..3 {
                        sum[k] += c[k] as u32;
                    }
                }
                sum.map(|v| ((v + s as u32 / 2) / s as u32).min(255) as u8)
            })
            .collect()
    } else {
        Vec::new()
    };
    (st, image, heat)
}
