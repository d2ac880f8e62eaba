//! The core's frame on the host: the core's own render loop ([`uvt_core::Engine`]) over the
//! whole viewport, in parallel over bands of [`BAND`] rows (rayon), measured. The host adds the
//! banding and the threads only: every triangle is set up once per frame by the core
//! ([`Engine::setup`]), every band is one region of [`Engine::render_region`] into a
//! [`RegionBuffer`] — the same tile walk, sample test, depth test, Zmax decision and counters as
//! the no-heap renderer's screen tiles (regions made of whole bounds tiles visit the same tiles,
//! `uvt_core::raster::engine`) — and what the tools count beyond [`uvt_core::Stats`] is watched
//! through an [`Observer`] ([`Watch`]).
//!
//! Triangles are taken in submission order, [`CHUNK`] at a time: a chunk is set up in parallel,
//! then every band renders the chunk's triangles that meet it into its buffers, which live for
//! the whole frame (so each sample's depth test sees every earlier triangle, as in one pass).
//! Memory is the frame's samples (depth, and colour when the image is kept) plus one chunk of
//! set-up triangles, whatever the scene's size.

use std::time::{Duration, Instant};

use embedded_graphics_core::pixelcolor::RgbColor;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use uvt_core::{
    DepthCull, Drawn, Engine, Error, Fate, Observer, Pipeline, PixelRect, PixelStats, Prim,
    RegionBuffer, Rgb888, Sample, SamplePattern, Seen, Stats, Triangle, Unobserved,
};

use super::counters::{Frame, FrameStats};
use super::opts::RunOpts;
use super::oracle::Oracle;

/// Rows of one band (the unit of parallel work; a multiple of every bounds-tile size).
pub const BAND: u16 = 8;

/// Triangles set up at a time (memory: this many set-up triangles at once).
pub const CHUNK: usize = 1 << 14;

/// What the host counts beyond the core's [`Stats`], watching one band's loop: the samples of
/// the kept tiles (each put through the tile's admission; the Cortex-M cost model's "admits"),
/// with the oracle its boxes ([`super::oracle`]), and a caller's own observer `X`
/// ([`run_core_with`]).
pub struct Watch<'a, X> {
    spp: u64,
    /// samples of the kept bounds tiles
    pub admitted: u64,
    /// the in-band oracle
    pub oracle: Option<Oracle<'a>>,
    /// the caller's observer
    pub extra: X,
}

impl<X: Observer> Observer for Watch<'_, X> {
    const CULLED_SAMPLES: bool = X::CULLED_SAMPLES;
    #[inline(always)]
    fn cell(&mut self, tri: u32, cell: PixelRect, fate: Fate) {
        if let Fate::Kept { .. } = fate {
            let area = u64::from(cell.x1 - cell.x0) * u64::from(cell.y1 - cell.y0);
            self.admitted += area * self.spp;
        }
        if let Some(o) = &mut self.oracle {
            o.cell(fate);
        }
        self.extra.cell(tri, cell, fate);
    }
    #[inline(always)]
    fn sample(&mut self, tri: u32, px: u16, py: u16, si: usize, s: &Sample, seen: Seen) {
        if let Some(o) = &mut self.oracle {
            o.sample(s, seen);
        }
        self.extra.sample(tri, px, py, si, s, seen);
    }
    #[inline(always)]
    fn cell_end(&mut self, tri: u32, cell: PixelRect) {
        if let Some(o) = &mut self.oracle {
            o.cell_end(tri, cell);
        }
        self.extra.cell_end(tri, cell);
    }
}

/// One triangle's setup: visible, culled or refused.
type SetUp<E> = Result<Option<Drawn<E>>, Error>;

/// One band's buffers (slices of the frame's) and counters.
struct Band<'a, R, X> {
    rect: PixelRect,
    store: RegionBuffer<'a>,
    zregs: R,
    stats: Stats,
    watch: Watch<'a, X>,
}

/// The frame of `engine` (any pipeline, configuration, unit, Zmax) over `tris` with the
/// colours, image and oracle of `o` and the sample table `pattern` (on the configuration's
/// grids): counters, image, heat map (sample tests per pixel) and wall time. `o.vp` must be the
/// engine's viewport. Errors are the core's (a class the unit does not accept, a pattern or
/// bounds tile it refuses).
pub fn run_core<L, Z>(
    engine: &Engine<L, Z>,
    tris: &[Triangle],
    pattern: &SamplePattern<'_>,
    o: &RunOpts<'_>,
) -> Result<Frame, Error>
where
    L: Pipeline + Sync,
    L::Entry: Send + Sync,
    Z: DepthCull,
{
    run_core_with(engine, tris, pattern, o, |_| Unobserved).map(|(f, _)| f)
}

/// [`run_core`] with a caller's observer per band, `extra(band)` (its rectangle): the frame and
/// the bands' observers, top to bottom.
pub fn run_core_with<L, Z, X>(
    engine: &Engine<L, Z>,
    tris: &[Triangle],
    pattern: &SamplePattern<'_>,
    o: &RunOpts<'_>,
    extra: impl Fn(PixelRect) -> X,
) -> Result<(Frame, Vec<X>), Error>
where
    L: Pipeline + Sync,
    L::Entry: Send + Sync,
    Z: DepthCull,
    X: Observer + Send,
{
    let start = Instant::now();
    let vp = engine.viewport();
    let (w, h) = (usize::from(vp.width()), usize::from(vp.height()));
    let spp = usize::from(pattern.spp());
    let color = |c: [u8; 3]| Rgb888::new(c[0], c[1], c[2]);
    let clear = color(o.clear);
    // The frame's buffers, one slice of each per band.
    let band_px = w * usize::from(BAND);
    let mut depth = vec![0i32; w * h * spp];
    let mut colors = vec![clear; if o.image { w * h * spp } else { 0 }];
    let mut pixel = vec![PixelStats::default(); w * h];
    let mut zmax = vec![0i32; if Z::ENABLED { w * h } else { 0 }];
    let mut bands = Vec::with_capacity(h.div_ceil(usize::from(BAND)));
    let mut colors_left: &mut [Rgb888] = &mut colors;
    let mut zmax_left: &mut [i32] = &mut zmax;
    for (b, (d, p)) in depth
        .chunks_mut(band_px * spp)
        .zip(pixel.chunks_mut(band_px))
        .enumerate()
    {
        let y0 = b as u16 * BAND;
        let rect = PixelRect {
            x0: 0,
            y0,
            x1: vp.width(),
            y1: (y0 + BAND).min(vp.height()),
        };
        let c = take(&mut colors_left, if o.image { d.len() } else { 0 });
        let z = take(&mut zmax_left, if Z::ENABLED { p.len() } else { 0 });
        bands.push(Band {
            rect,
            store: RegionBuffer::new(rect, pattern.spp(), clear, d, c, p)?,
            zregs: Z::region_registers(vp.width(), z)?,
            stats: Stats::default(),
            watch: Watch {
                spp: spp as u64,
                admitted: 0,
                oracle: o.oracle.map(|t| Oracle::new(t, o.vp)),
                extra: extra(rect),
            },
        });
    }
    let bar = Bar::new(tris.len(), o.label);
    let mut setup = Stats::default();
    let mut footprint_samples = 0u64;
    for (c, chunk) in tris.chunks(CHUNK).enumerate() {
        let base = c * CHUNK;
        let set: Vec<(SetUp<L::Entry>, Stats)> = chunk
            .par_iter()
            .enumerate()
            .map(|(k, t)| {
                let mut s = Stats::default();
                let i = base + k;
                let prim = Prim {
                    tri: *t,
                    color: o.colors.get(i).map_or(clear, |&c| color(c)),
                };
                (engine.setup(i, &prim, &mut s), s)
            })
            .collect();
        let mut drawn = Vec::with_capacity(set.len());
        for (d, s) in set {
            setup.add(&s);
            if let Some(d) = d? {
                drawn.push(d);
            }
        }
        // The triangles of this chunk that meet each band, in submission order.
        let mut bins: Vec<Vec<u32>> = vec![Vec::new(); bands.len()];
        for (k, d) in drawn.iter().enumerate() {
            let fp = L::footprint(d.entry());
            footprint_samples += u64::from(fp.x1 - fp.x0) * u64::from(fp.y1 - fp.y0) * spp as u64;
            let (b0, b1) = (fp.y0 / BAND, (fp.y1 - 1) / BAND);
            for bin in &mut bins[usize::from(b0)..=usize::from(b1)] {
                bin.push(k as u32);
            }
        }
        bands
            .par_iter_mut()
            .zip(bins.par_iter())
            .filter(|(_, bin)| !bin.is_empty())
            .try_for_each(|(band, bin)| {
                engine.render_region(
                    bin.iter().map(|&k| &drawn[k as usize]),
                    band.rect,
                    pattern,
                    o.tile,
                    &mut band.store,
                    &mut band.zregs,
                    &mut band.stats,
                    &mut band.watch,
                )
            })?;
        bar.done(start, base + chunk.len());
    }
    bar.finish();
    let mut stats = FrameStats::from_core(&setup);
    stats.footprint_samples = footprint_samples;
    let mut image = Vec::with_capacity(if o.image { w * h } else { 0 });
    let mut heat = Vec::with_capacity(w * h);
    for band in &bands {
        let mut s = FrameStats::from_core(&band.stats);
        s.samples_admitted = band.watch.admitted;
        s.oracle_tested = band.watch.oracle.as_ref().map_or(0, |x| x.count);
        stats.add(&s);
        let (bw, bh) = (band.rect.x1 - band.rect.x0, band.rect.y1 - band.rect.y0);
        for y in 0..usize::from(bh) {
            for x in 0..usize::from(bw) {
                heat.push(band.store.pixel_stats(x, y).tested);
                if o.image {
                    let c = band.store.resolve(x, y).unwrap_or(clear);
                    image.push([c.r(), c.g(), c.b()]);
                }
            }
        }
    }
    let extras = bands.into_iter().map(|b| b.watch.extra).collect();
    let frame = Frame {
        stats,
        image,
        samples: colors,
        heat,
        time: start.elapsed(),
    };
    Ok((frame, extras))
}

/// The first `n` values of `rest`, which keeps the others.
fn take<'a, T>(rest: &mut &'a mut [T], n: usize) -> &'a mut [T] {
    let (head, tail) = std::mem::take(rest).split_at_mut(n);
    *rest = tail;
    head
}

/// The progress bar of a frame: hidden unless the frame takes more than a second.
struct Bar {
    bar: ProgressBar,
    shown: std::sync::Once,
    label: String,
}

impl Bar {
    fn new(triangles: usize, label: &str) -> Bar {
        Bar {
            bar: ProgressBar::with_draw_target(
                Some(triangles as u64),
                ProgressDrawTarget::hidden(),
            ),
            shown: std::sync::Once::new(),
            label: label.to_string(),
        }
    }

    fn done(&self, start: Instant, triangles: usize) {
        if start.elapsed() > Duration::from_secs(1) {
            self.shown.call_once(|| {
                self.bar.set_draw_target(ProgressDrawTarget::stderr());
                self.bar.set_style(
                    ProgressStyle::with_template(
                        "{msg:>14} [{bar:40}] {pos}/{len} triangles {elapsed}",
                    )
                    .unwrap_or_else(|_| ProgressStyle::default_bar()),
                );
                self.bar.set_message(self.label.clone());
            });
        }
        self.bar.set_position(triangles as u64);
    }

    fn finish(&self) {
        self.bar.finish_and_clear();
    }
}
