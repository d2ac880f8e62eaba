//! Stage 4 — the no-heap renderer: [`Raster`], the render loop ([`crate::raster::engine`]) with
//! a fixed-capacity list of triangles and a screen walk in tiles, and the [`Renderer`] a user
//! instantiates — the raster of the pipeline [`crate::units::select`] picks for a (precision,
//! unit).
//!
//! [`Raster`] sets every triangle up exactly once ([`Engine::setup`]) into a fixed-capacity
//! `heapless::Vec` (no heap; memory is `N` entries plus one tile buffer, and with Zmax one
//! register per pixel of the screen tile), then walks the screen tile by tile, each screen tile
//! one region of [`Engine::render_region`] into a [`TileBuffer`]. Resolve averages the S
//! samples per channel with round-half-up.

use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::pixelcolor::Rgb888;
use embedded_graphics_core::prelude::{Pixel, Point};

use crate::bounds::laine::Laine2011;
use crate::config::precision::{DefaultPrecision, PlanarPrecision};
use crate::config::unit::{Full, MotionOnly, StaticOnly, Unit};
use crate::error::Error;
use crate::input::{PixelRect, Prim, SamplePattern, Viewport};
use crate::raster::engine::{refused, Drawn, Engine};
use crate::raster::observe::Unobserved;
use crate::raster::store::PixelStats;
use crate::raster::tile_buffer::{tile_size, TileBuffer};
use crate::raster::zmax::{Cleared, DepthCull, NoZmax};
use crate::stats::Stats;
use crate::units::pipeline::Pipeline;
use crate::units::select::PipelineOf;

/// The renderer of precision `P` (default: [`DefaultPrecision`]) on unit `U` (default: [`Full`];
/// a narrower unit refuses the classes it lacks, [`Error::ClassNotInUnit`]) with bounds strategy
/// `B`, holding at most `N` visible triangles: the [`Raster`] of the pipeline
/// [`crate::units::select`] picks — the static-only unit's own pipeline at a planar precision,
/// the motion-only unit's at a bounded one (where `B` is not used: those units cull with their
/// own tests), else the general pipeline. Generic code names it with the bound
/// `(P, U): Select<B>` ([`crate::units::select::Select`]), which every precision and unit
/// satisfy.
///
/// `Z` turns Zmax culling on ([`crate::raster::zmax::Zmax`]) or leaves it out ([`NoZmax`], the default):
/// `Renderer<Laine2011, 64, DefaultPrecision, Full, Zmax>`.
pub type Renderer<B, const N: usize, P = DefaultPrecision, U = Full, Z = NoZmax> =
    Raster<PipelineOf<B, P, U>, N, Z>;

/// The static-only unit's renderer at the planar configuration (`planar-16-16-16-20`).
pub type StaticRenderer<const N: usize> = Renderer<Laine2011, N, PlanarPrecision, StaticOnly>;

/// The motion-only unit's renderer at bounded precision `P`.
pub type MotionRenderer<const N: usize, P = DefaultPrecision> =
    Renderer<Laine2011, N, P, MotionOnly>;

/// The render loop of pipeline `L` holding at most `N` visible triangles (module docs), with
/// Zmax culling `Z` ([`crate::raster::zmax`]; [`NoZmax`] compiles it out). [`Renderer`] names it
/// by precision and unit; a pipeline can also be named directly (e.g. the general pipeline on a
/// unit that has its own, to compare the two).
pub struct Raster<L: Pipeline, const N: usize, Z: DepthCull = NoZmax> {
    engine: Engine<L, Z>,
    /// the visible triangles, in order
    entries: heapless::Vec<Drawn<L::Entry>, N>,
    /// counters accumulated over setup and every rendered tile
    pub stats: Stats,
}

impl<L: Pipeline, const N: usize, Z: DepthCull> Raster<L, N, Z> {
    /// Set every triangle up exactly once, in order, with bounds strategy `bounds`. Fails with
    /// [`Error::ClassNotInUnit`] (naming the first such primitive, culled or not) if a
    /// primitive's class is not accepted by the unit — every class is checked before any setup
    /// — or with [`Error::TooManyTriangles`] if more than `N` triangles are visible. No renderer
    /// is returned on an error. [`Raster::empty`] and [`Raster::load`] do the same in place.
    #[inline(always)]
    pub fn new(bounds: L::Bounds, vp: Viewport, prims: &[Prim]) -> Result<Self, Error> {
        let mut r = Self::empty(bounds, vp);
        r.load(prims)?;
        Ok(r)
    }

    /// A renderer with no triangle (it renders the clear color), to be [`Raster::load`]ed in
    /// place: the caller's frame then holds the only copy of the entries.
    pub fn empty(bounds: L::Bounds, vp: Viewport) -> Self {
        Raster {
            engine: Engine::new(bounds, vp),
            entries: heapless::Vec::new(),
            stats: Stats::default(),
        }
    }

    /// Replace the triangles by `prims`, set up as in [`Raster::new`], and reset the counters.
    /// On an error the renderer is left with no triangle and the counters of the setups done
    /// before it (nothing half-loaded is rendered).
    #[inline(never)]
    pub fn load(&mut self, prims: &[Prim]) -> Result<(), Error> {
        self.entries.clear();
        self.stats = Stats::default();
        for (index, p) in prims.iter().enumerate() {
            let class = p.tri.class();
            if !<L::Unit as Unit>::accepts(class) {
                return Err(refused::<L>(index, class));
            }
        }
        let Raster {
            engine,
            entries,
            stats,
        } = self;
        for (index, p) in prims.iter().enumerate() {
            // Every class is accepted (checked above): a refusal cannot occur; were it to, the
            // primitive is refused, never rendered.
            let pushed = match engine.setup(index, p, stats) {
                Ok(None) => Ok(()),
                Ok(Some(d)) => entries
                    .push(d)
                    .map_err(|_| Error::TooManyTriangles { capacity: N }),
                Err(e) => Err(e),
            };
            if let Err(e) = pushed {
                entries.clear();
                return Err(e);
            }
        }
        Ok(())
    }

    /// The visible triangles' pipeline entries (the general pipeline's: setup and the
    /// strategy's coefficients), in order.
    pub fn entries(&self) -> impl Iterator<Item = &L::Entry> {
        self.entries.iter().map(Drawn::entry)
    }

    /// Render the screen tile whose top-left pixel is (`x0`, `y0`) into `fb` (cleared first).
    pub fn render_tile<const TW: usize, const TH: usize, const S: usize>(
        &mut self,
        x0: u16,
        y0: u16,
        pattern: &SamplePattern<'_>,
        bounds_tile: u8,
        clear: Rgb888,
        fb: &mut TileBuffer<TW, TH, S>,
    ) -> Result<(), Error> {
        let screen =
            tile_screen::<TW, TH, S>(pattern, bounds_tile, x0, y0, &self.engine.viewport())?;
        fb.clear_fill(clear);
        // The Zmax registers of this screen tile (zero-sized without Zmax).
        let mut zregs = <Z::Registers<TW, TH> as Cleared>::cleared();
        let Raster {
            engine,
            entries,
            stats,
        } = self;
        // The checks of `Engine::render_region` are `tile_screen`'s: the pattern's spp is the
        // buffer's, the tile lies in the viewport and fits the buffer and its registers
        // (TW × TH), and it is made of whole bounds tiles (x0, y0 on the bounds-tile grid, the
        // bounds tile divides TW and TH, the right and bottom edges at x0 + TW, y0 + TH or the
        // viewport's).
        engine.shade_region(
            entries.iter(),
            screen,
            pattern,
            bounds_tile,
            fb,
            &mut zregs,
            stats,
            &mut Unobserved,
        );
        Ok(())
    }

    /// Render the whole viewport tile by tile, handing every resolved pixel with its counters to
    /// `out(x, y, color, stats)`. One `TileBuffer` lives on the stack.
    pub fn render_with<const TW: usize, const TH: usize, const S: usize>(
        &mut self,
        pattern: &SamplePattern<'_>,
        bounds_tile: u8,
        clear: Rgb888,
        out: impl FnMut(u16, u16, Rgb888, PixelStats),
    ) -> Result<(), Error> {
        let mut fb = TileBuffer::<TW, TH, S>::new_fill(clear);
        let vp = self.engine.viewport();
        walk_screen(
            vp,
            &mut fb,
            |x0, y0, fb| self.render_tile(x0, y0, pattern, bounds_tile, clear, fb),
            out,
        )
    }

    /// Render the whole viewport into an embedded-graphics `DrawTarget`, one tile at a time.
    pub fn render<D, const TW: usize, const TH: usize, const S: usize>(
        &mut self,
        pattern: &SamplePattern<'_>,
        bounds_tile: u8,
        clear: Rgb888,
        target: &mut D,
    ) -> Result<(), RenderError<D::Error>>
    where
        D: DrawTarget<Color = Rgb888>,
    {
        let mut draw_err = None;
        self.render_with::<TW, TH, S>(pattern, bounds_tile, clear, |x, y, c, _| {
            if draw_err.is_none() {
                let px = Pixel(Point::new(x as i32, y as i32), c);
                if let Err(e) = target.draw_iter(core::iter::once(px)) {
                    draw_err = Some(e);
                }
            }
        })
        .map_err(RenderError::Core)?;
        match draw_err {
            Some(e) => Err(RenderError::Draw(e)),
            None => Ok(()),
        }
    }
}

/// The screen walk of every renderer's `render_with`: for each screen tile of `vp` (raster
/// order) `render(x0, y0, fb)` renders it into `fb`, then each of its pixels inside `vp` goes to
/// `out(x, y, color, stats)` in raster order.
pub(crate) fn walk_screen<const TW: usize, const TH: usize, const S: usize>(
    vp: Viewport,
    fb: &mut TileBuffer<TW, TH, S>,
    mut render: impl FnMut(u16, u16, &mut TileBuffer<TW, TH, S>) -> Result<(), Error>,
    mut out: impl FnMut(u16, u16, Rgb888, PixelStats),
) -> Result<(), Error> {
    let (tw, th) = tile_size::<TW, TH>();
    let mut y0 = 0u16;
    while y0 < vp.h {
        let mut x0 = 0u16;
        while x0 < vp.w {
            render(x0, y0, fb)?;
            // The tile's pixels in raster order, one loop (not unrolled per column).
            for (ty, tx) in (0..th).flat_map(|ty| (0..tw).map(move |tx| (ty, tx))) {
                // x0 + tx < 2048 + 2048: no saturation happens.
                let (x, y) = (x0.saturating_add(tx), y0.saturating_add(ty));
                if x < vp.w && y < vp.h {
                    let (tx, ty) = (usize::from(tx), usize::from(ty));
                    out(x, y, fb.resolve(tx, ty), fb.pixel_stats(tx, ty));
                }
            }
            // tw ≥ 1 (TileBuffer's const assertion), so the walk advances.
            x0 = x0.saturating_add(tw);
        }
        y0 = y0.saturating_add(th);
    }
    Ok(())
}

/// The argument checks of every renderer's `render_tile`: the pattern has `S` samples per
/// pixel ([`Error::SppMismatch`]), the bounds tile is 1, 2, 4 or 8 and divides `TW` and `TH`
/// ([`Error::BoundsTile`]), and (`x0`, `y0`) lies in `vp` ([`Error::PixelOutOfRange`]); then
/// the tile's pixels clipped to the viewport.
#[inline(always)]
pub(crate) fn tile_screen<const TW: usize, const TH: usize, const S: usize>(
    pattern: &SamplePattern<'_>,
    bounds_tile: u8,
    x0: u16,
    y0: u16,
    vp: &Viewport,
) -> Result<PixelRect, Error> {
    check_tile_args::<TW, TH, S>(pattern, bounds_tile, x0, y0, vp)?;
    let (tw, th) = tile_size::<TW, TH>();
    Ok(PixelRect {
        x0,
        y0,
        x1: x0.saturating_add(tw).min(vp.w),
        y1: y0.saturating_add(th).min(vp.h),
    })
}

/// The checks of [`tile_screen`].
fn check_tile_args<const TW: usize, const TH: usize, const S: usize>(
    pattern: &SamplePattern<'_>,
    bounds_tile: u8,
    x0: u16,
    y0: u16,
    vp: &Viewport,
) -> Result<(), Error> {
    if usize::from(pattern.spp()) != S {
        return Err(Error::SppMismatch {
            tile: u16::try_from(S).unwrap_or(u16::MAX),
            pattern: pattern.spp(),
        });
    }
    let bt = usize::from(bounds_tile);
    let divides = |n: usize| n.checked_rem(bt) == Some(0);
    if !matches!(bounds_tile, 1 | 2 | 4 | 8) || !divides(TW) || !divides(TH) {
        return Err(Error::BoundsTile { size: bounds_tile });
    }
    if x0 >= vp.w || y0 >= vp.h {
        return Err(Error::PixelOutOfRange);
    }
    // bt ∈ {1, 2, 4, 8}: the remainders exist.
    if x0.checked_rem(u16::from(bounds_tile)) != Some(0)
        || y0.checked_rem(u16::from(bounds_tile)) != Some(0)
    {
        return Err(Error::BoundsTile { size: bounds_tile });
    }
    Ok(())
}

/// Error of [`Raster::render`]: the core's, or the draw target's.
#[derive(Debug, PartialEq, Eq)]
pub enum RenderError<E> {
    /// refused by the core
    Core(Error),
    /// the draw target failed
    Draw(E),
}
