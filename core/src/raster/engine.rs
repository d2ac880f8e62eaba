//! Stage 4 — **the one render loop**: [`Engine`] sets a triangle up ([`Engine::setup`], once per
//! triangle) and renders any list of set-up triangles ([`Drawn`]) over any rectangle of the
//! screen into any [`SampleStore`] ([`Engine::render_region`]). Every renderer is this loop: the
//! no-heap [`crate::Raster`] runs it per screen tile into a
//! [`crate::raster::tile_buffer::TileBuffer`] (the Cortex-M programs), a host runs it per band
//! of the screen into a [`crate::raster::store::RegionBuffer`], in parallel.
//!
//! Per triangle, in submission order, whose footprint meets the region: the pipeline walks the
//! bounds tiles (aligned to the bounds-tile grid, clipped to footprint and region) with its tile
//! step — the general pipeline's (u, v, t) intervals, row by row with the strategy's row spans;
//! the specialised units' own culls — and the one per-cell loop ([`shade_cell`]) runs the
//! pipeline's sample test on the samples the tile admits, depth-tests the hits into the store
//! ([`crate::raster::store::depth_test`]) and counts in [`Stats`] (`samples_covered =
//! samples_written + samples_occluded`). With Zmax ([`crate::raster::zmax`]) a kept tile whose
//! registers say every stored sample is nearer than the triangle's depth floor is skipped. An
//! [`Observer`] sees every tile and sample ([`crate::raster::observe`]).
//!
//! **Regions are made of whole bounds tiles** (their left and top edges on the bounds-tile grid,
//! their right and bottom edges on it or at the viewport's edge), so every bounds tile of the
//! screen lies in exactly one region, and any division of the screen into regions — 8 × 8
//! screen tiles, full-width bands one bounds tile high — visits the same tiles and samples with
//! the same decisions, in the same order per sample: the image and every tile and sample count
//! are the same. (A strategy
//! with row spans computes one span per row of a region, so its row-span operations, and the
//! tile operations a span spares, depend on the regions' width.)

use core::marker::PhantomData;

use embedded_graphics_core::pixelcolor::Rgb888;

use crate::bounds::strategy::{Admit, CellVisitor};
use crate::config::formats::DEPTH_NEAR;
use crate::config::unit::Unit;
use crate::error::Error;
use crate::input::{PixelRect, Prim, SamplePattern, Viewport};
use crate::raster::observe::{Fate, Observer, Seen};
use crate::raster::store::DepthTest;
use crate::raster::store::SampleStore;
use crate::raster::zmax::{DepthCull, ZmaxRegisters};
use crate::sample::pos::ScreenPos;
use crate::setup::{Cull, Outcome};
use crate::stats::{Ops, Stats};
use crate::units::pipeline::Pipeline;

/// One set-up triangle ready for the loop: its pipeline entry, colour, depth floor
/// ([`Pipeline::depth_floor`] with Zmax, else [`DEPTH_NEAR`]) and its index in the submitted
/// list. Built only by [`Engine::setup`].
#[derive(Clone, Copy, Debug)]
pub struct Drawn<E> {
    entry: E,
    color: Rgb888,
    floor: i32,
    index: u32,
}

impl<E> Drawn<E> {
    /// The pipeline entry (setup and the strategy's coefficients on the general pipeline).
    pub fn entry(&self) -> &E {
        &self.entry
    }
    /// The flat colour.
    pub fn color(&self) -> Rgb888 {
        self.color
    }
    /// The depth floor (Zmax culling).
    pub fn floor(&self) -> i32 {
        self.floor
    }
    /// The index in the list submitted to [`Engine::setup`].
    pub fn index(&self) -> u32 {
        self.index
    }
}

/// The render loop of pipeline `L` with Zmax culling `Z` over viewport `vp` (module docs).
/// Holds no triangle: callers keep their [`Drawn`] lists (a fixed-capacity one in
/// [`crate::Raster`], any list on a host).
#[derive(Clone, Copy, Debug)]
pub struct Engine<L, Z> {
    pipe: L,
    vp: Viewport,
    cull: PhantomData<Z>,
}

impl<L: Pipeline, Z: DepthCull> Engine<L, Z> {
    /// The loop of `L` with bounds strategy `bounds` over viewport `vp`.
    pub fn new(bounds: L::Bounds, vp: Viewport) -> Self {
        Engine {
            pipe: L::new(bounds),
            vp,
            cull: PhantomData,
        }
    }

    /// The viewport.
    pub fn viewport(&self) -> Viewport {
        self.vp
    }

    /// The pipeline.
    pub fn pipeline(&self) -> &L {
        &self.pipe
    }

    /// Set up primitive `prim`, number `index` of the submitted list, counting in `stats`
    /// (`triangles`, the culls, `by_class`, setup and depth-floor operations): `Ok(None)` when
    /// it is culled; [`Error::ClassNotInUnit`] when the unit does not accept its class (nothing
    /// computed beyond the class).
    #[inline(always)]
    pub fn setup(
        &self,
        index: usize,
        prim: &Prim,
        stats: &mut Stats,
    ) -> Result<Option<Drawn<L::Entry>>, Error> {
        Stats::inc(&mut stats.triangles);
        match self.pipe.setup(&prim.tri, self.vp, &mut stats.ops) {
            Outcome::Refused(class) => Err(refused::<L>(index, class)),
            Outcome::Culled(Cull::Outside) => {
                Stats::inc(&mut stats.culled_outside);
                Ok(None)
            }
            Outcome::Culled(Cull::Degenerate) => {
                Stats::inc(&mut stats.culled_degenerate);
                Ok(None)
            }
            Outcome::Visible(entry) => {
                if let Some(c) = stats.by_class.get_mut(L::class(&entry).index()) {
                    Stats::inc(c);
                }
                let floor = if Z::ENABLED {
                    L::depth_floor(&entry, &mut stats.ops)
                } else {
                    DEPTH_NEAR
                };
                Ok(Some(Drawn {
                    entry,
                    color: prim.color,
                    floor,
                    index: u32::try_from(index).unwrap_or(u32::MAX),
                }))
            }
        }
    }

    /// Render `region` (screen pixels) for the triangles `drawn`, in their order, into `store`,
    /// whose pixel (0, 0) is the region's top-left pixel; `zregs` are the store's Zmax registers
    /// (`NoRegisters` without Zmax: a mismatch does not compile). Counts in `stats`, shows
    /// `obs` every tile and sample (module docs). The store is not cleared. Errors, with
    /// nothing rendered: [`Error::SppMismatch`] (the pattern's spp is not the store's),
    /// [`Error::PixelOutOfRange`] (the region is empty, leaves the viewport or is larger than
    /// the store or its Zmax registers), [`Error::BoundsTile`] (not 1, 2, 4 or 8, or the region is not made of whole
    /// bounds tiles).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub fn render_region<'d, B, R, O>(
        &self,
        drawn: impl IntoIterator<Item = &'d Drawn<L::Entry>>,
        region: PixelRect,
        pattern: &SamplePattern<'_>,
        bounds_tile: u8,
        store: &mut B,
        zregs: &mut R,
        stats: &mut Stats,
        obs: &mut O,
    ) -> Result<(), Error>
    where
        L::Entry: 'd,
        B: SampleStore,
        R: ZmaxRegisters,
        O: Observer,
    {
        self.check_region(region, pattern, bounds_tile, store, zregs)?;
        self.shade_region(
            drawn,
            region,
            pattern,
            bounds_tile,
            store,
            zregs,
            stats,
            obs,
        );
        Ok(())
    }

    /// [`Engine::render_region`] without its checks: the caller has made them (the no-heap
    /// renderer's screen tiles, `crate::raster::renderer`).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub(crate) fn shade_region<'d, B, R, O>(
        &self,
        drawn: impl IntoIterator<Item = &'d Drawn<L::Entry>>,
        region: PixelRect,
        pattern: &SamplePattern<'_>,
        bounds_tile: u8,
        store: &mut B,
        zregs: &mut R,
        stats: &mut Stats,
        obs: &mut O,
    ) where
        L::Entry: 'd,
        B: SampleStore,
        R: ZmaxRegisters,
        O: Observer,
    {
        const {
            assert!(
                R::KEEPS == Z::ENABLED,
                "Zmax registers must match the DepthCull"
            )
        };
        let bt = u16::from(bounds_tile);
        let mut ops = Ops::default();
        for d in drawn {
            let r = L::footprint(&d.entry).intersect(&region);
            if r.is_empty() {
                continue;
            }
            let mut shade = Shade::<L, Z, B, R, O> {
                drawn: d,
                origin: region,
                pattern,
                store: &mut *store,
                zregs: &mut *zregs,
                stats: &mut *stats,
                obs: &mut *obs,
                cull: PhantomData,
            };
            self.pipe.walk(&d.entry, r, bt, &mut ops, &mut shade);
        }
        stats.ops.add(&ops);
    }

    /// The argument checks of [`Engine::render_region`].
    #[inline(always)]
    fn check_region<B: SampleStore, R: ZmaxRegisters>(
        &self,
        region: PixelRect,
        pattern: &SamplePattern<'_>,
        bounds_tile: u8,
        store: &B,
        zregs: &R,
    ) -> Result<(), Error> {
        let (w, h, spp) = store.size();
        if usize::from(pattern.spp()) != spp {
            return Err(Error::SppMismatch {
                tile: u16::try_from(spp).unwrap_or(u16::MAX),
                pattern: pattern.spp(),
            });
        }
        let (rw, rh) = (
            region.x1.wrapping_sub(region.x0),
            region.y1.wrapping_sub(region.y0),
        );
        if region.is_empty()
            || region.x1 > self.vp.w
            || region.y1 > self.vp.h
            || usize::from(rw) > w
            || usize::from(rh) > h
            || !zregs.covers(usize::from(rw), usize::from(rh))
        {
            return Err(Error::PixelOutOfRange);
        }
        let bt = u16::from(bounds_tile);
        let on_grid = |v: u16| v.checked_rem(bt) == Some(0);
        let whole = matches!(bounds_tile, 1 | 2 | 4 | 8)
            && on_grid(region.x0)
            && on_grid(region.y0)
            && (on_grid(region.x1) || region.x1 == self.vp.w)
            && (on_grid(region.y1) || region.y1 == self.vp.h);
        if !whole {
            return Err(Error::BoundsTile { size: bounds_tile });
        }
        Ok(())
    }
}

/// The refusal of primitive `index` of `class` by pipeline `L`'s unit.
pub(crate) fn refused<L: Pipeline>(index: usize, class: crate::config::class::Class) -> Error {
    Error::ClassNotInUnit {
        index,
        class,
        unit: <L::Unit as Unit>::NAME,
    }
}

/// The per-cell work of one triangle in one region, handed every bounds tile of the walk
/// ([`Pipeline::walk`]): a cell the tile step culls (or, on the general pipeline, outside its
/// row's span) counts as visited and skipped; with Zmax a kept cell whose registers say every
/// stored sample is nearer than the floor is culled; else [`shade_cell`].
struct Shade<'a, 'p, L: Pipeline, Z, B, R, O> {
    drawn: &'a Drawn<L::Entry>,
    /// the region: its top-left pixel is the store's (0, 0)
    origin: PixelRect,
    pattern: &'a SamplePattern<'p>,
    store: &'a mut B,
    zregs: &'a mut R,
    stats: &'a mut Stats,
    obs: &'a mut O,
    cull: PhantomData<Z>,
}

impl<L, Z, B, R, O> CellVisitor for Shade<'_, '_, L, Z, B, R, O>
where
    L: Pipeline,
    Z: DepthCull,
    B: SampleStore,
    R: ZmaxRegisters,
    O: Observer,
{
    #[inline(always)]
    fn cell<T: Admit>(&mut self, cell: PixelRect, tile: Option<T>, ops: &mut Ops) {
        Stats::inc(&mut self.stats.tiles_visited);
        let tri = self.drawn.index;
        let Some(tile) = tile else {
            Stats::inc(&mut self.stats.tiles_skipped);
            self.obs.cell(tri, cell, Fate::Skipped);
            return;
        };
        let origin = self.origin;
        if Z::ENABLED {
            // The cell lies inside the region: the offsets are in [0, width], [0, height].
            let rel = |a: u16, b: u16| usize::from(a.saturating_sub(b));
            let cols = (rel(cell.x0, origin.x0), rel(cell.x1, origin.x0));
            let rows = (rel(cell.y0, origin.y0), rel(cell.y1, origin.y0));
            if self.zregs.hides(self.drawn.floor, cols, rows, ops) {
                Stats::inc(&mut self.stats.tiles_zculled);
                self.obs.cell(tri, cell, Fate::Zculled);
                return;
            }
        }
        self.obs.cell(
            tri,
            cell,
            Fate::Kept {
                bounds: tile.enclosing_box(),
            },
        );
        shade_cell(self, cell, &tile, ops);
        self.obs.cell_end(tri, cell);
    }
}

/// The one per-cell sample loop of every pipeline and every renderer: each sample of the bounds
/// tile `cell` that the tile admits ([`Admit`], the walk's own tile type) is tested
/// ([`Pipeline::test`], its operations counted by the test or [`Pipeline::count`]), counted per
/// pixel, and on a hit depth-tested into the store; a written sample refreshes its pixel's Zmax
/// register (nothing without Zmax). An observer that asks for culled samples gets their test
/// too, counted nowhere.
#[inline(always)]
fn shade_cell<L, Z, B, R, O, T>(
    sh: &mut Shade<'_, '_, L, Z, B, R, O>,
    cell: PixelRect,
    tile: &T,
    ops: &mut Ops,
) where
    L: Pipeline,
    Z: DepthCull,
    B: SampleStore,
    R: ZmaxRegisters,
    O: Observer,
    T: Admit,
{
    let origin = sh.origin;
    let (entry, color, tri) = (&sh.drawn.entry, sh.drawn.color, sh.drawn.index);
    for py in cell.y0..cell.y1 {
        for px in cell.x0..cell.x1 {
            // The cell lies inside the region, so both differences are in [0, width), [0, height).
            let (Some(tx), Some(ty)) = (px.checked_sub(origin.x0), py.checked_sub(origin.y0))
            else {
                continue;
            };
            let (tx, ty) = (usize::from(tx), usize::from(ty));
            for (si, s) in sh.pattern.pixel(px, py).iter().enumerate() {
                if !tile.admit(s, ops) {
                    if O::CULLED_SAMPLES {
                        let pos = ScreenPos::of(px, py, s);
                        let hit = L::test(entry, pos, s, &mut Ops::default());
                        let seen = Seen {
                            admitted: false,
                            hit,
                            depth_test: None,
                        };
                        sh.obs.sample(tri, px, py, si, s, seen);
                    }
                    continue;
                }
                Stats::inc(&mut sh.stats.samples_tested);
                let hit = L::test(entry, ScreenPos::of(px, py, s), s, ops);
                L::count(hit.is_some(), ops);
                sh.store.count(tx, ty, hit.is_some());
                let depth_test = match hit {
                    None => None,
                    Some(h) => {
                        Stats::inc(&mut sh.stats.samples_covered);
                        // In range (tx, ty inside the store, si < spp) and h.depth ≠ DEPTH_EMPTY.
                        let r = sh.store.write(tx, ty, si, color, h.depth);
                        match r {
                            Some(DepthTest::Written) => {
                                Stats::inc(&mut sh.stats.samples_written);
                                sh.store.count_written(tx, ty);
                                sh.zregs.refresh(&*sh.store, tx, ty, ops);
                            }
                            Some(DepthTest::Occluded) => Stats::inc(&mut sh.stats.samples_occluded),
                            None => {}
                        }
                        r
                    }
                };
                let seen = Seen {
                    admitted: true,
                    hit,
                    depth_test,
                };
                sh.obs.sample(tri, px, py, si, s, seen);
            }
        }
    }
}
