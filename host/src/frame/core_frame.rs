//! The core's frame on the host: the core's own render loop ([`uvt_core::Engine`]) over the
//! whole viewport, in parallel (rayon), measured. The host adds the division of the work and the
//! threads only: every triangle is set up once per frame by the core ([`Engine::setup`]), and
//! every band of the screen — one row of bounds tiles, full width — is one region of
//! [`Engine::render_region`] into a [`RegionBuffer`]: the same tile walk, sample test, depth
//! test, Zmax decision and counters as the no-heap renderer's screen tiles (regions made of
//! whole bounds tiles visit the same tiles, `uvt_core::raster::engine`; full-width bands also
//! compute the same row spans as any full-width division). What the tools count beyond
//! [`uvt_core::Stats`] is watched through an [`Observer`] ([`Watch`]).
//!
//! **Order and memory.** Triangles are taken in submission order, a chunk at a time
//! ([`CHUNK_BYTES`] of set-up triangles): a chunk is set up in parallel, each triangle in its
//! slot (never moved again), and handed to every band it meets. A band renders its chunks one at
//! a time, in order, into its buffers, which live for the whole frame — so each sample's depth
//! test sees every earlier triangle, as in one pass — while other bands render theirs and the
//! next chunks are set up: no band waits for another. At most [`MAX_INFLIGHT`] chunks are alive,
//! so memory is the frame's samples (depth, and colour when the image is kept) plus a few MiB of
//! set-up triangles, whatever the scene's size.

use std::collections::VecDeque;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use embedded_graphics_core::pixelcolor::RgbColor;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use uvt_core::raster::zmax::ZmaxRegisters;
use uvt_core::{
    DepthCull, Drawn, Engine, Error, Fate, Observer, Pipeline, PixelRect, PixelStats, Prim,
    RegionBuffer, Rgb888, Sample, SamplePattern, Seen, Stats, Triangle, Unobserved,
};

use super::counters::{Frame, FrameStats};
use super::opts::RunOpts;
use super::oracle::Oracle;

/// The most triangles in one chunk.
const CHUNK: usize = 1 << 14;

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
    if !matches!(o.tile, 1 | 2 | 4 | 8) {
        return Err(Error::BoundsTile { size: o.tile });
    }
    // Chunks set up and not yet rendered (declared first: the chunks refer to it).
    let inflight = AtomicUsize::new(0);
    let vp = engine.viewport();
    let (w, h) = (usize::from(vp.width()), usize::from(vp.height()));
    let spp = usize::from(pattern.spp());
    let color = |c: [u8; 3]| Rgb888::new(c[0], c[1], c[2]);
    let clear = color(o.clear);
    // The frame's buffers, one slice of each per band.
    // One row of bounds tiles per band (module docs).
    let band = u16::from(o.tile);
    let band_px = w * usize::from(band);
    let mut depth = vec![0i32; w * h * spp];
    let mut colors = vec![clear; if o.image { w * h * spp } else { 0 }];
    let mut pixel = vec![PixelStats::default(); w * h];
    let mut zmax = vec![0i32; if Z::ENABLED { w * h } else { 0 }];
    let mut bands = Vec::with_capacity(h.div_ceil(usize::from(band)));
    let mut colors_left: &mut [Rgb888] = &mut colors;
    let mut zmax_left: &mut [i32] = &mut zmax;
    for (b, (d, p)) in depth
        .chunks_mut(band_px * spp)
        .zip(pixel.chunks_mut(band_px))
        .enumerate()
    {
        let y0 = b as u16 * band;
        let rect = PixelRect {
            x0: 0,
            y0,
            x1: vp.width(),
            y1: (y0 + band).min(vp.height()),
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
    let chunk_len = chunk_len::<L::Entry>();
    let bands: Vec<BandSlot<'_, L::Entry, _, X>> = bands
        .into_iter()
        .map(|b| BandSlot {
            queue: Mutex::new((VecDeque::new(), false)),
            band: Mutex::new(b),
        })
        .collect();
    let failed: Mutex<Option<Error>> = Mutex::new(None);
    let mut setup = Stats::default();
    let mut footprint_samples = 0u64;
    rayon::scope(|sc| {
        for (c, part) in tris.chunks(chunk_len).enumerate() {
            // Backpressure: at most MAX_INFLIGHT chunks set up and not yet rendered by every
            // band they meet (memory); meanwhile this thread renders bands too.
            while inflight.load(Ordering::Acquire) >= MAX_INFLIGHT {
                if rayon::yield_now() != Some(rayon::Yield::Executed) {
                    std::thread::yield_now();
                }
            }
            if failed.lock().map_or(true, |f| f.is_some()) {
                return;
            }
            let base = c * chunk_len;
            let mut drawn: Vec<SetUp<L::Entry>> = Vec::new();
            drawn.resize_with(part.len(), || Ok(None));
            let mut counted = vec![Stats::default(); part.len()];
            // Each triangle is set up in its slot (its entry is not moved again) and read there
            // by the bands; pieces of SETUP_PIECE triangles are the parallel tasks (spawned
            // tasks, not a parallel iterator: its machinery would be compiled again for every
            // pipeline).
            rayon::scope(|pieces| {
                let slots = drawn
                    .chunks_mut(SETUP_PIECE)
                    .zip(counted.chunks_mut(SETUP_PIECE));
                for (n, ((slots, counts), tris)) in slots.zip(part.chunks(SETUP_PIECE)).enumerate()
                {
                    let first = base + n * SETUP_PIECE;
                    pieces.spawn(move |_| {
                        let each = slots.iter_mut().zip(counts.iter_mut()).zip(tris);
                        for (k, ((slot, s), t)) in each.enumerate() {
                            let i = first + k;
                            let prim = Prim {
                                tri: *t,
                                color: o.colors.get(i).map_or(clear, |&c| color(c)),
                            };
                            *slot = engine.setup(i, &prim, s);
                        }
                    });
                }
            });
            for s in &counted {
                setup.add(s);
            }
            // The triangles of this chunk that meet each band, in submission order.
            let mut bins: Vec<Vec<u32>> = vec![Vec::new(); bands.len()];
            for (k, d) in drawn.iter().enumerate() {
                let d = match d {
                    Ok(Some(d)) => d,
                    Ok(None) => continue,
                    Err(e) => {
                        if let Ok(mut f) = failed.lock() {
                            f.get_or_insert(*e);
                        }
                        return;
                    }
                };
                let fp = L::footprint(d.entry());
                footprint_samples +=
                    u64::from(fp.x1 - fp.x0) * u64::from(fp.y1 - fp.y0) * spp as u64;
                let (b0, b1) = (fp.y0 / band, (fp.y1 - 1) / band);
                for bin in &mut bins[usize::from(b0)..=usize::from(b1)] {
                    bin.push(k as u32);
                }
            }
            let chunk = Arc::new(Chunk {
                drawn,
                bins,
                inflight: &inflight,
            });
            inflight.fetch_add(1, Ordering::AcqRel);
            for (b, slot) in bands.iter().enumerate() {
                if chunk.bins[b].is_empty() {
                    continue;
                }
                let Ok(mut q) = slot.queue.lock() else {
                    return;
                };
                q.0.push_back(Arc::clone(&chunk));
                if !q.1 {
                    q.1 = true;
                    let (bands, failed) = (&bands, &failed);
                    sc.spawn(move |_| {
                        render_band(engine, pattern, o.tile, &bands[b], b, failed);
                    });
                }
            }
            bar.done(start, base + part.len());
        }
    });
    if let Some(e) = failed.into_inner().ok().flatten() {
        return Err(e);
    }
    let bands: Vec<Band<'_, _, X>> = bands
        .into_iter()
        .filter_map(|s| s.band.into_inner().ok())
        .collect();
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

/// Triangles one setup task sets up.
const SETUP_PIECE: usize = 64;

/// Chunks set up and not yet rendered by every band they meet, at most.
pub const MAX_INFLIGHT: usize = 8;

/// Bytes of set-up triangles in one chunk (the chunk's length follows from the entry's size, 64
/// to [`CHUNK`] triangles): small enough to stay in cache while the bands read it (measured on
/// the quick bench rows: 256 KiB against 8 MiB, 0.75–0.9 of the dense rows' core wall time).
pub const CHUNK_BYTES: usize = 256 << 10;

/// Triangles per chunk for entries of type `E`: [`CHUNK_BYTES`] of them, at least 256.
fn chunk_len<E>() -> usize {
    (CHUNK_BYTES / std::mem::size_of::<SetUp<E>>().max(1)).clamp(64, CHUNK)
}

/// One chunk of set-up triangles and, per band, the indices of those that meet it. Counted in
/// `inflight` while it lives.
struct Chunk<'a, E> {
    drawn: Vec<SetUp<E>>,
    bins: Vec<Vec<u32>>,
    inflight: &'a AtomicUsize,
}

impl<E> Drop for Chunk<'_, E> {
    fn drop(&mut self) {
        self.inflight.fetch_sub(1, Ordering::AcqRel);
    }
}

/// A band and the chunks waiting for it, in submission order, with whether a task is rendering
/// them (one at a time per band, so each sample sees the triangles in order).
struct BandSlot<'a, E, R, X> {
    queue: Mutex<(VecDeque<Arc<Chunk<'a, E>>>, bool)>,
    band: Mutex<Band<'a, R, X>>,
}

/// Render band `b`'s waiting chunks in order until none is left (then the band is idle again);
/// the first error is kept in `failed`.
fn render_band<L, Z, R, X>(
    engine: &Engine<L, Z>,
    pattern: &SamplePattern<'_>,
    tile: u8,
    slot: &BandSlot<'_, L::Entry, R, X>,
    b: usize,
    failed: &Mutex<Option<Error>>,
) where
    L: Pipeline,
    Z: DepthCull,
    R: ZmaxRegisters,
    X: Observer,
{
    loop {
        let next = match slot.queue.lock() {
            Ok(mut q) => match q.0.pop_front() {
                Some(c) => c,
                None => {
                    q.1 = false;
                    return;
                }
            },
            Err(_) => return,
        };
        let Ok(mut band) = slot.band.lock() else {
            return;
        };
        let band = &mut *band;
        let visible = |k: &u32| {
            next.drawn[*k as usize]
                .as_ref()
                .ok()
                .and_then(Option::as_ref)
        };
        let bin = next.bins.get(b).map_or(&[][..], Vec::as_slice);
        let done = engine.render_region(
            bin.iter().filter_map(visible),
            band.rect,
            pattern,
            tile,
            &mut band.store,
            &mut band.zregs,
            &mut band.stats,
            &mut band.watch,
        );
        if let (Err(e), Ok(mut f)) = (done, failed.lock()) {
            f.get_or_insert(e);
        }
    }
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
