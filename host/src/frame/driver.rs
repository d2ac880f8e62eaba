//! The host's frame driver: runs one pipeline (the fixed-point core or the f64 reference) over a
//! whole frame with the same tile walk as `uvt_core::Renderer<_, N>` with 8×8 screen tiles, in
//! parallel over bands of 8 rows (rayon), and measures it.
//!
//! Per triangle and band: bounds tiles aligned to the bounds-tile grid, clipped to footprint ∩
//! band (identical cells to the core renderer's, since 1, 2, 4, 8 divide 8), walked by the
//! pipeline's own walk (the core's: `BoundsStrategy::prepare`, then `BoundsStrategy::walk`, so
//! `auto`'s cells reach a per-sample loop compiled for the strategy it picked, as in the
//! renderer); samples inside the tile's intervals are tested; covered ones are depth-tested
//! (strictly nearer wins, triangles in submission order) and resolved with round-half-up like
//! `TileBuffer::resolve`. Unlike the renderer, which sets every triangle up once, the driver
//! rebuilds a triangle's setup and coefficients in every band its footprint meets (their ops
//! counted once): on the bench rows 1.1–2.5 bands per visible triangle.
//! Also counted: the bounding-box scan's tests (every sample of the footprint) and the oracle's —
//! per bounds tile, the samples inside the tightest axis-aligned (u, v, t) box around the samples
//! the pipeline actually covered there and around [`ORACLE_POINTS`] dense points of the tile's
//! (x, y, u, v, t) box that the exact triangle covers (dense points are drawn only in tiles where
//! the pattern covered a sample, and only inside the pipeline's own box). This in-band box is
//! kept for `uvt render`'s report; it overstates the reachable STE (tiles with no covered pattern
//! sample count nothing). The axis-aligned limit that `bench-ste` reports is
//! [`crate::oracle::limit::axis_aligned_limit`]: dense sampling in every tile Laine keeps.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use uvt_core::{Cull, Ops, PixelRect};

use crate::reference;
use crate::scene::file::Scene;
use crate::scene::pattern::Pattern;
use crate::scene::tri::SceneTri;

use super::counters::{Frame, FrameStats};
use super::pipeline::{FramePipeline, FrameTile, SetupOut, TileSink};

/// Options of a frame run.
#[derive(Clone)]
pub struct RunOpts<'a> {
    /// viewport (W, H)
    pub vp: (u16, u16),
    /// samples per pixel
    pub spp: u16,
    /// bounds tile size
    pub tile: u8,
    /// triangle colors
    pub colors: &'a [[u8; 3]],
    /// background
    pub clear: [u8; 3],
    /// keep the image
    pub image: bool,
    /// label for the progress bar (shown only when the frame takes more than a second)
    pub label: &'a str,
    /// exact triangles for the oracle's dense sampling (`None`: no oracle)
    pub oracle: Option<&'a [SceneTri]>,
    /// Zmax culling (`uvt_core::raster::zmax`): a kept bounds tile is skipped for a triangle
    /// whose depth floor is not below the largest depth stored in the tile
    pub zmax: bool,
}

impl<'a> RunOpts<'a> {
    /// Options for `scene` with its own viewport, spp and tile size, label = its name, black
    /// background, no image, no oracle; `colors` is `scene.colors()`.
    pub fn for_scene(scene: &'a Scene, colors: &'a [[u8; 3]]) -> RunOpts<'a> {
        RunOpts {
            vp: scene.viewport,
            spp: scene.spp,
            tile: scene.tile,
            colors,
            clear: [0; 3],
            image: false,
            label: &scene.name,
            oracle: None,
            zmax: false,
        }
    }
}

/// Dense points per bounds tile for the oracle box (5D Sobol, Owen-scrambled, fixed seed).
pub const ORACLE_POINTS: u32 = 16;

fn oracle_points() -> Vec<[f64; 5]> {
    (0..ORACLE_POINTS)
        .map(|i| [0, 1, 2, 3, 4].map(|d| sobol_burley::sample(i, d, 0x0ac1e) as f64))
        .collect()
}

const BAND: u16 = 8;

/// Run a pipeline over a frame.
pub fn run<P: FramePipeline>(p: &P, pattern: &Pattern, o: &RunOpts<'_>) -> Frame {
    let start = Instant::now();
    let n = o.colors.len();
    // First pass: every triangle's setup, keeping only its outcome and footprint (for the band
    // lists) and its ops. The setups themselves are not kept: each band recomputes the setups of
    // its triangles (deterministic, the same values; their ops are counted here, once). Keeping
    // them cost ~1 KB per triangle for the core (> 800 MiB on the dense scenes at full size),
    // written once and read back once per frame, most of it fresh pages the kernel had to zero.
    // The bounds strategy's coefficients are built in the bands only ([`FramePipeline::walk`]),
    // their ops counted in the first band of the footprint.
    let setups: Vec<(SetupOut<PixelRect>, Ops)> = (0..n)
        .into_par_iter()
        .map(|i| {
            let mut ops = Ops::default();
            let s = match p.setup(i, &mut ops) {
                SetupOut::Visible(s, class) => {
                    if o.zmax {
                        p.depth_floor(&s, &mut ops);
                    }
                    SetupOut::Visible(p.footprint(&s), class)
                }
                SetupOut::Culled(c) => SetupOut::Culled(c),
            };
            (s, ops)
        })
        .collect();
    let mut stats = FrameStats {
        triangles: n as u64,
        ..Default::default()
    };
    let (w, h) = (o.vp.0 as usize, o.vp.1 as usize);
    let bands = h.div_ceil(BAND as usize);
    let mut bins: Vec<Vec<u32>> = vec![Vec::new(); bands];
    for (i, (s, ops)) in setups.iter().enumerate() {
        stats.add_ops(ops);
        match s {
            SetupOut::Culled(Cull::Outside) => stats.culled_outside += 1,
            SetupOut::Culled(Cull::Degenerate) => stats.culled_degenerate += 1,
            SetupOut::Visible(fp, class) => {
                stats.by_class[class.index()] += 1;
                stats.footprint_samples +=
                    (fp.x1 - fp.x0) as u64 * (fp.y1 - fp.y0) as u64 * o.spp as u64;
                for bin in &mut bins[(fp.y0 / BAND) as usize..=((fp.y1 - 1) / BAND) as usize] {
                    bin.push(i as u32);
                }
            }
        }
    }
    let done = AtomicUsize::new(0);
    let bar = ProgressBar::with_draw_target(Some(bands as u64), ProgressDrawTarget::hidden());
    let shown = std::sync::Once::new();
    let results: Vec<(FrameStats, Vec<[u8; 3]>, Vec<u32>)> = bins
        .par_iter()
        .enumerate()
        .map(|(b, list)| {
            let r = band(p, pattern, o, &setups, b as u16, list);
            done.fetch_add(1, Ordering::Relaxed);
            if start.elapsed() > Duration::from_secs(1) {
                shown.call_once(|| {
                    bar.set_draw_target(ProgressDrawTarget::stderr());
                    bar.set_style(
                        ProgressStyle::with_template(
                            "{msg:>14} [{bar:40}] {pos}/{len} bands {elapsed}",
                        )
                        .unwrap_or_else(|_| ProgressStyle::default_bar()),
                    );
                    bar.set_message(o.label.to_string());
                });
            }
            bar.set_position(done.load(Ordering::Relaxed) as u64);
            r
        })
        .collect();
    bar.finish_and_clear();
    let mut image = if o.image {
        Vec::with_capacity(w * h)
    } else {
        Vec::new()
    };
    let mut heat = Vec::with_capacity(w * h);
    for (s, img, ht) in results {
        stats.add(&s);
        image.extend(img);
        heat.extend(ht);
    }
    Frame {
        stats,
        image,
        heat,
        time: start.elapsed(),
    }
}

/// The Zmax test of a kept bounds tile (`uvt_core::raster::zmax`, the renderer's decision and
/// counts): the largest per-pixel register over the cell's pixels (band rows from `y0`, `w`
/// pixels wide) against the triangle's floor.
fn zmax_hides(
    floor: f64,
    zmax: &[f64],
    cell: PixelRect,
    (y0, w): (u16, usize),
    ops: &mut Ops,
) -> bool {
    let mut max = f64::NEG_INFINITY;
    for py in cell.y0..cell.y1 {
        let row = (py - y0) as usize * w;
        let regs = &zmax[row + cell.x0 as usize..row + cell.x1 as usize];
        max = regs.iter().fold(max, |m, &d| m.max(d));
        ops.add_zmax(regs.len() as u64);
    }
    ops.add_zmax(1);
    floor >= max
}

fn band<P: FramePipeline>(
    p: &P,
    pat: &Pattern,
    o: &RunOpts<'_>,
    setups: &[(SetupOut<PixelRect>, Ops)],
    b: u16,
    list: &[u32],
) -> (FrameStats, Vec<[u8; 3]>, Vec<u32>) {
    let (w, s) = (o.vp.0 as usize, o.spp as usize);
    let y0 = b * BAND;
    let y1 = (y0 + BAND).min(o.vp.1);
    let rows = (y1 - y0) as usize;
    let mut buf = BandBuffers {
        y0,
        w,
        spp: s,
        depth: vec![p.far(); w * rows * s],
        // Zmax culling's per-pixel registers: the largest stored depth of each pixel's samples,
        // refreshed after each write (`uvt_core::raster::zmax::PixelMax`).
        zmax: vec![p.far(); if o.zmax { w * rows } else { 0 }],
        color: vec![o.clear; if o.image { w * rows * s } else { 0 }],
        heat: vec![0u32; w * rows],
        st: FrameStats::default(),
        tested_samples: Vec::new(),
        dense: if o.oracle.is_some() {
            oracle_points()
        } else {
            Vec::new()
        },
    };
    let mut ops = Ops::default();
    let screen = PixelRect {
        x0: 0,
        y0,
        x1: o.vp.0,
        y1,
    };
    for &i in list {
        let SetupOut::Visible(fp, _) = &setups[i as usize].0 else {
            continue;
        };
        let region = fp.intersect(&screen);
        // The footprint's first band: the strategy's coefficients are counted here, once.
        let first = fp.y0 >= y0;
        if region.is_empty() && !first {
            continue;
        }
        // The setup again (the first pass counted its ops); the same outcome, so visible.
        let SetupOut::Visible(setup, _) = p.setup(i as usize, &mut Ops::default()) else {
            continue;
        };
        // The floor again, its ops counted in the first pass.
        let floor = if o.zmax {
            p.depth_floor(&setup, &mut Ops::default())
        } else {
            f64::NEG_INFINITY
        };
        let mut shade = Shade {
            p,
            pat,
            o,
            setup: &setup,
            tri: i as usize,
            floor,
            buf: &mut buf,
        };
        // Row → span → tiles (`uvt_core::walk_tiles`, the pipeline's own walk): the same cells
        // in the same order as `region.cells(o.tile)`; a cell outside its row's span counts as
        // visited and skipped.
        let mut prep = Ops::default();
        p.walk(
            &setup,
            region,
            o.tile as u16,
            &mut prep,
            &mut ops,
            &mut shade,
        );
        if first {
            ops.add(&prep);
        }
    }
    let BandBuffers {
        color,
        heat,
        mut st,
        ..
    } = buf;
    st.add_ops(&ops);
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

/// One band's buffers and counters.
struct BandBuffers {
    /// the band's first row and the viewport's width
    y0: u16,
    w: usize,
    spp: usize,
    depth: Vec<f64>,
    zmax: Vec<f64>,
    color: Vec<[u8; 3]>,
    heat: Vec<u32>,
    st: FrameStats,
    /// Only with the oracle: the tested samples of the current cell (for its in-band box count).
    tested_samples: Vec<usize>,
    /// Only with the oracle: its dense points.
    dense: Vec<[f64; 5]>,
}

/// The sink of one triangle's walk in one band: each kept cell's samples are put through the
/// tile, tested, depth-tested and stored (and, with the oracle, boxed).
struct Shade<'a, 'o, P: FramePipeline> {
    p: &'a P,
    pat: &'a Pattern,
    o: &'a RunOpts<'o>,
    setup: &'a P::Setup,
    tri: usize,
    floor: f64,
    buf: &'a mut BandBuffers,
}

impl<P: FramePipeline> TileSink<P::Sample> for Shade<'_, '_, P> {
    #[inline(always)]
    fn cell<T: FrameTile<P::Sample>>(&mut self, cell: PixelRect, tile: Option<T>, ops: &mut Ops) {
        let (p, o, buf) = (self.p, self.o, &mut *self.buf);
        let (y0, w, s) = (buf.y0, buf.w, buf.spp);
        buf.st.tiles_visited += 1;
        let Some(bounds) = tile else {
            buf.st.tiles_skipped += 1;
            return;
        };
        if o.zmax && zmax_hides(self.floor, &buf.zmax, cell, (y0, w), ops) {
            buf.st.tiles_zculled += 1;
            return;
        }
        let st = &mut buf.st;
        st.samples_admitted += (cell.x1 - cell.x0) as u64 * (cell.y1 - cell.y0) as u64 * s as u64;
        let oracle = o.oracle.is_some();
        buf.tested_samples.clear();
        let mut lo = [f64::MAX; 3];
        let mut hi = [f64::MIN; 3];
        for py in cell.y0..cell.y1 {
            for px in cell.x0..cell.x1 {
                let pix = (py - y0) as usize * w + px as usize;
                // The pixel's samples are consecutive in the table (`Pattern::index`).
                let base = self.pat.index(px, py, 0);
                for si in 0..s {
                    let idx = base + si;
                    if !bounds.inside(p.sample(idx), ops) {
                        continue;
                    }
                    st.samples_tested += 1;
                    buf.heat[pix] += 1;
                    if oracle {
                        buf.tested_samples.push(idx);
                    }
                    let Some(d) = p.test(self.setup, px, py, idx, ops) else {
                        continue;
                    };
                    st.samples_covered += 1;
                    if oracle {
                        let uvt = p.uvt(idx);
                        for k in 0..3 {
                            lo[k] = lo[k].min(uvt[k]);
                            hi[k] = hi[k].max(uvt[k]);
                        }
                    }
                    let slot = pix * s + si;
                    if d < buf.depth[slot] {
                        buf.depth[slot] = d;
                        st.samples_written += 1;
                        if o.image {
                            buf.color[slot] = o.colors[self.tri];
                        }
                        if o.zmax {
                            let px = &buf.depth[pix * s..pix * s + s];
                            buf.zmax[pix] = px.iter().fold(f64::NEG_INFINITY, |m, &x| m.max(x));
                            ops.add_zmax(s as u64);
                        }
                    }
                }
            }
        }
        // Oracle: the box also grows around densely sampled covered points of the tile
        // (exact geometry, f64 ray test), so it approaches the covered region's true box.
        if let (Some(tris), true) = (o.oracle, lo[0] <= hi[0]) {
            let r = bounds.ranges();
            let tri = &tris[self.tri];
            for d in &buf.dense {
                let x = cell.x0 as f64 + d[0] * (cell.x1 - cell.x0) as f64;
                let y = cell.y0 as f64 + d[1] * (cell.y1 - cell.y0) as f64;
                let uvt = [0, 1, 2].map(|k| r[k].0 + d[k + 2] * (r[k].1 - r[k].0));
                if reference::sample::sample_test(tri, o.vp, x, y, uvt[0], uvt[1], uvt[2]).is_some()
                {
                    for k in 0..3 {
                        lo[k] = lo[k].min(uvt[k]);
                        hi[k] = hi[k].max(uvt[k]);
                    }
                }
            }
        }
        if oracle {
            st.oracle_tested += buf
                .tested_samples
                .iter()
                .filter(|&&idx| {
                    let uvt = p.uvt(idx);
                    (0..3).all(|k| lo[k] <= uvt[k] && uvt[k] <= hi[k])
                })
                .count() as u64;
        }
    }
}
