//! The host's frame driver: runs one pipeline (the fixed-point core or the f64 reference) over a
//! whole frame with the same tile walk as `uvt_core::Renderer<_, N>` with 8×8 screen tiles, in
//! parallel over bands of 8 rows (rayon), and measures it.
//!
//! Per triangle and band: bounds tiles aligned to the bounds-tile grid, clipped to footprint ∩
//! band (identical cells to the core renderer's, since 1, 2, 4, 8 divide 8); samples inside the
//! tile's intervals are tested; covered ones are depth-tested (strictly nearer wins, triangles in
//! submission order) and resolved with round-half-up like `TileBuffer::resolve`.
//! Also counted: the bounding-box scan's tests (every sample of the footprint) and the oracle's —
//! per bounds tile, the samples inside the tightest axis-aligned (u, v, t) box around the samples
//! the pipeline actually covered there and around [`ORACLE_POINTS`] dense points of the tile's
//! (x, y, u, v, t) box that the exact triangle covers (dense points are drawn only in tiles where
//! the pattern covered a sample, and only inside the pipeline's own box). This in-band box is
//! kept for `uvt render`'s report; it overstates the reachable STE (tiles with no covered pattern
//! sample count nothing). The axis-aligned limit that `bench-ste` reports is
//! [`crate::oracle::axis_aligned_limit`]: dense sampling in every tile Laine keeps.

use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use uvt_core::bounds::strategy::{BoundsStrategy, RowSpan, TileBounds};
use uvt_core::config::unit::Full;
use uvt_core::{Class, Cull, Ops, Outcome, PixelRect, Triangle, Viewport};

use crate::pattern::Pattern;
use crate::reference;
use crate::scene::SceneTri;

/// Setup result of a pipeline.
pub enum SetupOut<S> {
    /// visible, with its class
    Visible(S, Class),
    /// culled
    Culled(Cull),
}

/// One rasterization pipeline the driver can run.
pub trait Pipeline: Sync {
    /// per-triangle data
    type Setup: Send + Sync;
    /// per-tile bounds
    type Bounds: Copy;
    /// setup of triangle `i`
    fn setup(&self, i: usize, ops: &mut Ops) -> SetupOut<Self::Setup>;
    /// footprint of a setup
    fn footprint(&self, s: &Self::Setup) -> PixelRect;
    /// the run of one row of bounds tiles to visit (`BoundsStrategy::row_span`; default: the
    /// whole row, no ops)
    fn row(&self, _s: &Self::Setup, row: PixelRect, _bt: u16, _ops: &mut Ops) -> RowSpan {
        RowSpan::whole(row)
    }
    /// bounds of one tile inside its row's span
    fn bounds(
        &self,
        s: &Self::Setup,
        span: &RowSpan,
        cell: PixelRect,
        ops: &mut Ops,
    ) -> Option<Self::Bounds>;
    /// whether sample `idx` of the table lies inside the bounds (box, then the strategy's
    /// per-sample predicate, counted in `ops.predicate`)
    fn inside(&self, b: &Self::Bounds, idx: usize, ops: &mut Ops) -> bool;
    /// (u, v, t) of sample `idx` as this pipeline sees it
    fn uvt(&self, idx: usize) -> [f64; 3];
    /// sample test: depth on a hit
    fn test(&self, s: &Self::Setup, px: u16, py: u16, idx: usize, ops: &mut Ops) -> Option<f64>;
    /// the far depth the buffer is cleared to
    fn far(&self) -> f64;
    /// the bounds as real (u, v, t) ranges
    fn ranges(&self, b: &Self::Bounds) -> [(f64, f64); 3];
}

/// The fixed-point core with bounds strategy `B` at precision `P`.
pub struct Fixed<'a, B, P = uvt_core::DefaultPrecision> {
    /// precision
    pub prec: std::marker::PhantomData<P>,
    /// bounds strategy
    pub strat: B,
    /// viewport
    pub vp: Viewport,
    /// core triangles
    pub tris: &'a [Triangle],
    /// sample table
    pub pattern: &'a Pattern,
}

impl<'a, B> Fixed<'a, B> {
    /// The core at the default precision.
    pub fn new(strat: B, vp: Viewport, tris: &'a [Triangle], pattern: &'a Pattern) -> Self {
        Fixed {
            prec: std::marker::PhantomData,
            strat,
            vp,
            tris,
            pattern,
        }
    }
}

impl<'a, B, P> Fixed<'a, B, P> {
    /// The core at precision `P` (e.g. `uvt_core::Exact`, whatever the default).
    pub fn new_at(strat: B, vp: Viewport, tris: &'a [Triangle], pattern: &'a Pattern) -> Self {
        Fixed {
            prec: std::marker::PhantomData,
            strat,
            vp,
            tris,
            pattern,
        }
    }
}

impl<B: BoundsStrategy + Sync, P: uvt_core::Precision + Sync> Pipeline for Fixed<'_, B, P>
where
    B::Coeffs: Send + Sync,
{
    type Setup = (uvt_core::Setup, B::Coeffs);
    type Bounds = B::Tile;
    fn setup(&self, i: usize, ops: &mut Ops) -> SetupOut<Self::Setup> {
        match uvt_core::setup_with::<P>(&self.tris[i], self.vp, ops) {
            Outcome::Visible(s) => {
                let c = self.strat.prepare(&s, ops);
                SetupOut::Visible((s, c), s.class())
            }
            Outcome::Culled(c) => SetupOut::Culled(c),
        }
    }
    fn footprint(&self, s: &Self::Setup) -> PixelRect {
        s.0.footprint()
    }
    fn row(&self, s: &Self::Setup, row: PixelRect, bt: u16, ops: &mut Ops) -> RowSpan {
        self.strat.row_span(&s.0, &s.1, row, bt, ops)
    }
    fn bounds(
        &self,
        s: &Self::Setup,
        span: &RowSpan,
        cell: PixelRect,
        ops: &mut Ops,
    ) -> Option<Self::Bounds> {
        self.strat
            .span_tile_unit::<Full>(&s.0, &s.1, span, cell, ops)
    }
    fn inside(&self, b: &Self::Bounds, idx: usize, ops: &mut Ops) -> bool {
        let q = &self.pattern.quant[idx];
        b.admits(q.u().to_bits(), q.v().to_bits(), q.t().to_bits(), ops)
    }
    fn uvt(&self, idx: usize) -> [f64; 3] {
        let q = &self.pattern.quant[idx];
        [q.u().to_num(), q.v().to_num(), q.t().to_num()]
    }
    fn test(&self, s: &Self::Setup, px: u16, py: u16, idx: usize, ops: &mut Ops) -> Option<f64> {
        let q = &self.pattern.quant[idx];
        // The renderer's dispatch: P's test chosen at compile time (the same hit as
        // `uvt_core::sample_test` on a setup of precision P).
        uvt_core::sample::sample_test_unit::<P, uvt_core::Full>(
            &s.0,
            uvt_core::ScreenPos::of(px, py, q),
            q,
            ops,
        )
        .map(|h| h.depth as f64)
    }
    fn far(&self) -> f64 {
        i32::MAX as f64
    }
    fn ranges(&self, b: &Self::Bounds) -> [(f64, f64); 3] {
        let r = |i: uvt_core::Interval| (i.lo() as f64 / 65536.0, i.hi() as f64 / 65536.0);
        let b = b.uvt_box();
        [r(b.u), r(b.v), r(b.t)]
    }
}

/// The f64 reference (Laine bounds in f64, ray-cast sample test) on exact inputs.
pub struct Reference<'a> {
    /// viewport (W, H)
    pub vp: (u16, u16),
    /// f64 triangles
    pub tris: &'a [SceneTri],
    /// sample table (its exact values are used)
    pub pattern: &'a Pattern,
}

impl Pipeline for Reference<'_> {
    type Setup = reference::setup::Setup;
    type Bounds = reference::bounds::UvtBox;
    fn setup(&self, i: usize, _: &mut Ops) -> SetupOut<Self::Setup> {
        match reference::setup::setup(&self.tris[i], self.vp) {
            Ok(s) => SetupOut::Visible(s, s.class),
            Err(c) => SetupOut::Culled(c),
        }
    }
    fn footprint(&self, s: &Self::Setup) -> PixelRect {
        s.footprint
    }
    fn bounds(
        &self,
        s: &Self::Setup,
        _: &RowSpan,
        cell: PixelRect,
        _: &mut Ops,
    ) -> Option<Self::Bounds> {
        reference::bounds::tile(s, cell)
    }
    fn inside(&self, b: &Self::Bounds, idx: usize, _: &mut Ops) -> bool {
        let e = &self.pattern.exact[idx];
        b.contains(e[2], e[3], e[4])
    }
    fn uvt(&self, idx: usize) -> [f64; 3] {
        let e = &self.pattern.exact[idx];
        [e[2], e[3], e[4]]
    }
    fn test(&self, s: &Self::Setup, px: u16, py: u16, idx: usize, _: &mut Ops) -> Option<f64> {
        let e = &self.pattern.exact[idx];
        reference::sample::sample_test(
            &s.tri,
            self.vp,
            px as f64 + e[0],
            py as f64 + e[1],
            e[2],
            e[3],
            e[4],
        )
    }
    fn far(&self) -> f64 {
        f64::INFINITY
    }
    fn ranges(&self, b: &Self::Bounds) -> [(f64, f64); 3] {
        [b.u, b.v, b.t]
    }
}

/// Counters of one frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct FrameStats {
    /// triangles submitted
    pub triangles: u64,
    /// culled outside
    pub culled_outside: u64,
    /// culled degenerate
    pub culled_degenerate: u64,
    /// visible by class: static, motion, defocus, motion+defocus
    pub by_class: [u64; 4],
    /// bounds tiles computed
    pub tiles_visited: u64,
    /// of which empty
    pub tiles_skipped: u64,
    /// samples tested (inside the tile intervals)
    pub samples_tested: u64,
    /// samples covered
    pub samples_covered: u64,
    /// samples the bounding-box scan tests: all samples of every footprint pixel
    pub footprint_samples: u64,
    /// samples inside the per-tile oracle boxes (counted only when the run has the oracle,
    /// [`RunOpts::oracle`]; 0 otherwise, so that runs without it do not pay its bookkeeping)
    pub oracle_tested: u64,
    /// operation counts (fixed pipeline only)
    pub ops_setup: u64,
    /// per-tile bounds ops
    pub ops_bounds: u64,
    /// sample-test ops
    pub ops_sample: u64,
    /// per-sample predicate ops of the bounds strategy
    pub ops_predicate: u64,
    /// per-row span ops of the bounds strategy
    pub ops_rows: u64,
}

impl FrameStats {
    fn add(&mut self, o: &FrameStats) {
        let a = [
            &mut self.triangles,
            &mut self.culled_outside,
            &mut self.culled_degenerate,
            &mut self.tiles_visited,
            &mut self.tiles_skipped,
            &mut self.samples_tested,
            &mut self.samples_covered,
            &mut self.footprint_samples,
            &mut self.oracle_tested,
            &mut self.ops_setup,
            &mut self.ops_bounds,
            &mut self.ops_sample,
            &mut self.ops_predicate,
            &mut self.ops_rows,
        ];
        let b = [
            o.triangles,
            o.culled_outside,
            o.culled_degenerate,
            o.tiles_visited,
            o.tiles_skipped,
            o.samples_tested,
            o.samples_covered,
            o.footprint_samples,
            o.oracle_tested,
            o.ops_setup,
            o.ops_bounds,
            o.ops_sample,
            o.ops_predicate,
            o.ops_rows,
        ];
        for (x, y) in a.into_iter().zip(b) {
            *x += y;
        }
        for (x, y) in self.by_class.iter_mut().zip(o.by_class) {
            *x += y;
        }
    }
    fn add_ops(&mut self, o: &Ops) {
        self.ops_setup += o.setup;
        self.ops_bounds += o.bounds;
        self.ops_sample += o.sample;
        self.ops_predicate += o.predicate;
        self.ops_rows += o.rows;
    }
    /// STE of the pipeline's bounds (covered / tested), in [0, 1].
    pub fn ste(&self) -> f64 {
        ratio(self.samples_covered, self.samples_tested)
    }
    /// STE of the bounding-box scan.
    pub fn ste_bbox(&self) -> f64 {
        ratio(self.samples_covered, self.footprint_samples)
    }
    /// STE of the oracle boxes.
    pub fn ste_oracle(&self) -> f64 {
        ratio(self.samples_covered, self.oracle_tested)
    }
}

fn ratio(a: u64, b: u64) -> f64 {
    if b == 0 {
        0.0
    } else {
        a as f64 / b as f64
    }
}

/// A rendered frame.
pub struct Frame {
    /// counters
    pub stats: FrameStats,
    /// resolved RGB per pixel, row-major (empty if not requested)
    pub image: Vec<[u8; 3]>,
    /// sample tests per pixel, row-major
    pub heat: Vec<u32>,
    /// wall time
    pub time: Duration,
}

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
}

impl<'a> RunOpts<'a> {
    /// Options for `scene` with its own viewport, spp and tile size, label = its name, black
    /// background, no image, no oracle; `colors` is `scene.colors()`.
    pub fn for_scene(scene: &'a crate::scene::Scene, colors: &'a [[u8; 3]]) -> RunOpts<'a> {
        RunOpts {
            vp: scene.viewport,
            spp: scene.spp,
            tile: scene.tile,
            colors,
            clear: [0; 3],
            image: false,
            label: &scene.name,
            oracle: None,
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
pub fn run<P: Pipeline>(p: &P, pattern: &Pattern, o: &RunOpts<'_>) -> Frame {
    let start = Instant::now();
    let n = o.colors.len();
    // First pass: every triangle's setup, keeping only its outcome and footprint (for the band
    // lists) and its ops. The setups themselves are not kept: each band recomputes the setups of
    // its triangles (deterministic, the same values; their ops are counted here, once). Keeping
    // them cost ~1 KB per triangle for the core (> 800 MiB on the dense scenes at full size),
    // written once and read back once per frame, most of it fresh pages the kernel had to zero.
    let setups: Vec<(SetupOut<PixelRect>, Ops)> = (0..n)
        .into_par_iter()
        .map(|i| {
            let mut ops = Ops::default();
            let s = match p.setup(i, &mut ops) {
                SetupOut::Visible(s, class) => SetupOut::Visible(p.footprint(&s), class),
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

fn band<P: Pipeline>(
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
    let mut depth = vec![p.far(); w * rows * s];
    let mut color = vec![o.clear; if o.image { w * rows * s } else { 0 }];
    let mut heat = vec![0u32; w * rows];
    let mut st = FrameStats::default();
    let mut ops = Ops::default();
    let screen = PixelRect {
        x0: 0,
        y0,
        x1: o.vp.0,
        y1,
    };
    let bt = o.tile as u16;
    // Only with the oracle: the tested samples of the current cell (for its in-band box count).
    let oracle = o.oracle.is_some();
    let mut tested_samples: Vec<usize> = Vec::new();
    let dense = if o.oracle.is_some() {
        oracle_points()
    } else {
        Vec::new()
    };
    for &i in list {
        let SetupOut::Visible(fp, _) = &setups[i as usize].0 else {
            continue;
        };
        let region = fp.intersect(&screen);
        if region.is_empty() {
            continue;
        }
        // The setup again (the first pass counted its ops); the same outcome, so visible.
        let SetupOut::Visible(setup, _) = p.setup(i as usize, &mut Ops::default()) else {
            continue;
        };
        let setup = &setup;
        let col = o.colors[i as usize];
        // Row → span → tiles (`uvt_core::walk_tiles`): the same cells in the same order as
        // `region.cells(bt)`; a cell outside its row's span counts as visited and skipped.
        // A row starts where a cell's y0 changes; its span is computed once, at its first cell.
        let mut row_span: Option<RowSpan> = None;
        for cell in region.cells(bt) {
            let span = match row_span {
                Some(sp) if sp.cols().y0 == cell.y0 => sp,
                _ => {
                    let row = PixelRect {
                        x0: region.x0,
                        x1: region.x1,
                        ..cell
                    };
                    let sp = p.row(setup, row, bt, &mut ops);
                    row_span = Some(sp);
                    sp
                }
            };
            st.tiles_visited += 1;
            let bounds = if span.admits(&cell) {
                p.bounds(setup, &span, cell, &mut ops)
            } else {
                None
            };
            let Some(bounds) = bounds else {
                st.tiles_skipped += 1;
                continue;
            };
            tested_samples.clear();
            let mut lo = [f64::MAX; 3];
            let mut hi = [f64::MIN; 3];
            for py in cell.y0..cell.y1 {
                for px in cell.x0..cell.x1 {
                    let pix = (py - y0) as usize * w + px as usize;
                    // The pixel's samples are consecutive in the table (`Pattern::index`).
                    let base = pat.index(px, py, 0);
                    for si in 0..s {
                        let idx = base + si;
                        if !p.inside(&bounds, idx, &mut ops) {
                            continue;
                        }
                        st.samples_tested += 1;
                        heat[pix] += 1;
                        if oracle {
                            tested_samples.push(idx);
                        }
                        let hit = p.test(setup, px, py, idx, &mut ops);
                        if let Some(d) = hit {
                            st.samples_covered += 1;
                            if oracle {
                                let uvt = p.uvt(idx);
                                for k in 0..3 {
                                    lo[k] = lo[k].min(uvt[k]);
                                    hi[k] = hi[k].max(uvt[k]);
                                }
                            }
                            let slot = pix * s + si;
                            if d < depth[slot] {
                                depth[slot] = d;
                                if o.image {
                                    color[slot] = col;
                                }
                            }
                        }
                    }
                }
            }
            // Oracle: the box also grows around densely sampled covered points of the tile
            // (exact geometry, f64 ray test), so it approaches the covered region's true box.
            if let (Some(tris), true) = (o.oracle, lo[0] <= hi[0]) {
                let r = p.ranges(&bounds);
                let tri = &tris[i as usize];
                for d in &dense {
                    let x = cell.x0 as f64 + d[0] * (cell.x1 - cell.x0) as f64;
                    let y = cell.y0 as f64 + d[1] * (cell.y1 - cell.y0) as f64;
                    let uvt = [0, 1, 2].map(|k| r[k].0 + d[k + 2] * (r[k].1 - r[k].0));
                    if reference::sample::sample_test(tri, o.vp, x, y, uvt[0], uvt[1], uvt[2])
                        .is_some()
                    {
                        for k in 0..3 {
                            lo[k] = lo[k].min(uvt[k]);
                            hi[k] = hi[k].max(uvt[k]);
                        }
                    }
                }
            }
            st.oracle_tested += tested_samples
                .iter()
                .filter(|&&idx| {
                    let uvt = p.uvt(idx);
                    (0..3).all(|k| lo[k] <= uvt[k] && uvt[k] <= hi[k])
                })
                .count() as u64;
        }
    }
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
