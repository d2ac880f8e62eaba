//! The motion-specialised motion-only unit at a bounded precision: setup, per-tile time-slab
//! cull and sample test of a static or moving, in-focus triangle and nothing else (issue 13).
//!
//! The general pipeline ([`crate::units::general`]) on [`crate::MotionOnly`] runs the general
//! machinery with the lens terms gated off: Laine's lens-corner boxes and dual-space t bounds,
//! the frustum span, per-tile (u, v, t) intervals, class dispatch per sample and a sample
//! interface carrying (u, v, t). [`MotionPipeline`] is this unit's pipeline at every bounded
//! precision: [`crate::units::select`] picks it, so `Renderer<_, _, P, MotionOnly>` (alias
//! `MotionRenderer`) runs it, and its program links none of the general stages.
//!
//! | stage | computes | reads |
//! |---|---|---|
//! | [`setup::motion_setup`] | [`Triangle::class`] (acceptance); per vertex and shutter end the base `(x, y, w, z)` and `r − q`; the grid factors `256W·2^(32−S)`, `256H·2^(32−S)`, `2^(32−S)`; whether the fast datapath applies to the viewport; one screen box per time slab ([`setup::SLABS`] equal slabs of the shutter) and their union, the footprint | x, y, z, w of both shutter ends (the class: all fields) |
//! | [`cull::motion_tile`] | per bounds tile: the set of slabs whose box meets it (a bit mask; empty: the tile is skipped) | the tile's pixel rectangle |
//! | [`sample::motion_test`] | the bounded sample test of the motion class (steps 1–8 of `sample::bounded`), bit for bit | the sample's (x, y, t) |
//!
//! A [`crate::config::precision::Planar`] precision's static triangles take the planar test in the full
//! unit; here they take [`crate::units::static_only`]'s setup, tile cull and test, which are bit for
//! bit that test (its module docs), so that configuration renders the same image too.
//!
//! **Slab boxes** (conservative). The bounded test decides exactly on the triangle `P'_k =
//! (x'_k, y'_k, w_k)` whose vertices lie within `ε_x` (x), `ε_y` (y) and `ε_w` (w) of the exact
//! vertex `P_k(t) = q_k + t·(r_k − q_k)` ([`Eps`] of the motion class: `bounded.rs` module docs;
//! for a static triangle the same bound holds a fortiori). For t in slab `j` = `[j/K, (j+1)/K]`
//! `P_k(t)` lies on the segment from `P_k(j/K)` to `P_k((j+1)/K)`, so `P'_k` lies in the convex
//! hull `H_j` of the corners `(a ± ε_a, w ± ε_w)` of the six end points (per axis, `a` = x or
//! −y; scaled by K these are the integers `(K − j)·q + j·r`, exact). Then:
//! - if every corner of `H_j` has `w > 0`, every `w_k > 0`, and a covered sample's NDC point is
//!   a convex combination of the projected `P'_k` (the exact test on `P'`: `E'` are positive
//!   multiples of its edge functions); the projection `(a + w)·E/(2w)` is linear-fractional
//!   on the hull (w > 0), so its extremes are at corners, and the sample's pixel index (the
//!   floor of its continuous position, a monotone function) lies between the floors of the
//!   smallest and largest corner projection: the slab's box is that range, clipped to the
//!   viewport;
//! - if every corner has `w ≤ 0`, every `w_k ≤ 0`: a covered direction `d` (d_w > 0) would be a
//!   non-negative combination of the `P'_k` with `d_w = Σ λ_k w_k ≤ 0` — none is covered, and the
//!   box is empty;
//! - otherwise (a camera-plane crosser, a vertex at w = 0) the box is the viewport.
//!
//! Any arithmetic that fails its checked form gives the viewport (conservative). A sample with
//! t in slab `j` (`j = min(⌊T·K/2^16⌋, K − 1)`; a t on a slab boundary belongs to both slabs'
//! closed intervals) that is covered lies in box `j`: the tile cull keeps the slabs whose box
//! meets the tile and the renderer tests only samples of those slabs. The footprint is the
//! union of the boxes; a triangle with every box empty is culled as outside.
//!
//! **Same image as the full unit.** Both units' culls are conservative and both decide with the
//! same test on the same values, so every sample is covered by the same triangles with the same
//! depths, written in the same triangle order: image, depth, covered, written and occluded
//! counts are equal (`tests/tests/model/motion_unit.rs`). The work differs: tiles visited and skipped,
//! samples tested, culling reasons and the operation counts.

pub mod cull;
pub(crate) mod depth;
pub mod sample;
pub mod setup;

use core::marker::PhantomData;

use crate::bounds::strategy::{Admit, BoundsStrategy};
use crate::config::class::Class;
use crate::config::formats::DEPTH_NEAR;
use crate::config::precision::Precision;
use crate::config::unit::MotionOnly;
use crate::input::{PixelRect, Sample, Triangle, Viewport};
use crate::raster::zmax;
use crate::sample::pos::{Hit, ScreenPos};
use crate::setup::Outcome;
use crate::stats::Ops;
use crate::units::motion_only::cull::{motion_tile, slab_of};
use crate::units::motion_only::sample::motion_test;
use crate::units::motion_only::setup::{motion_setup, MotionSetup};
use crate::units::pipeline::Pipeline;
use crate::units::static_only::cull::static_tile;
use crate::units::static_only::sample::static_test;
use crate::units::static_only::setup::{static_setup, StaticSetup};

/// Operations counted per sample test and per hit: the bounded test's count for the motion
/// class on its fast path (`bounded::class_ops` + 3) and its depth (12).
const SAMPLE_OPS: u64 = 15 * 3 + 2 + 3 * 8 + 9 + 3;
const HIT_OPS: u64 = 12;

/// One visible triangle's setup. (No heap in core, so the large variant stays inline.)
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MotionEntry {
    /// a static or moving triangle on the motion path
    Motion(MotionSetup),
    /// a static triangle at a planar precision (the planar test)
    Static(StaticSetup),
}

/// What the slab cull hands the sample loop for a kept bounds tile.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MotionTile {
    /// a static triangle's kept tile: every sample is tested
    Static,
    /// the slabs whose box meets the tile (bit j: slab j; never 0): a sample is tested iff its
    /// t lies in one of them
    Slabs(u8),
}

/// The motion-only unit's pipeline at bounded (or planar) precision `P` (module docs). `B` is
/// the strategy the renderer is given; this unit's own slab cull replaces it.
#[derive(Clone, Copy, Debug)]
pub struct MotionPipeline<B, P> {
    bounds: PhantomData<(B, P)>,
}

impl<B: BoundsStrategy, P: Precision> Pipeline for MotionPipeline<B, P> {
    type Bounds = B;
    type Unit = MotionOnly;
    type Entry = MotionEntry;
    type Tile = MotionTile;
    const NAME: &'static str = "MotionRenderer";

    fn new(_: B) -> Self {
        MotionPipeline {
            bounds: PhantomData,
        }
    }

    /// A static triangle at a planar precision takes the static-only unit's setup (the planar
    /// test), every other accepted triangle the motion setup.
    #[inline(always)]
    fn setup(&self, tri: &Triangle, vp: Viewport, ops: &mut Ops) -> Outcome<MotionEntry> {
        if P::PLANAR && tri.class() == Class::Static {
            match static_setup(tri, vp, ops) {
                Outcome::Visible(s) => Outcome::Visible(MotionEntry::Static(s)),
                Outcome::Culled(c) => Outcome::Culled(c),
                Outcome::Refused(c) => Outcome::Refused(c),
            }
        } else {
            match motion_setup::<P>(tri, vp, ops) {
                Outcome::Visible(m) => Outcome::Visible(MotionEntry::Motion(m)),
                Outcome::Culled(c) => Outcome::Culled(c),
                Outcome::Refused(c) => Outcome::Refused(c),
            }
        }
    }

    fn class(entry: &MotionEntry) -> Class {
        match entry {
            MotionEntry::Motion(m) => m.class(),
            MotionEntry::Static(_) => Class::Static,
        }
    }

    fn footprint(entry: &MotionEntry) -> PixelRect {
        match entry {
            MotionEntry::Motion(m) => m.footprint(),
            MotionEntry::Static(s) => s.footprint(),
        }
    }

    #[inline(always)]
    fn tile(&self, entry: &MotionEntry, cell: PixelRect, ops: &mut Ops) -> Option<MotionTile> {
        match entry {
            MotionEntry::Static(s) if P::PLANAR => {
                static_tile(s, cell, ops).then_some(MotionTile::Static)
            }
            MotionEntry::Motion(m) => {
                let mask = motion_tile(m, cell, ops);
                (mask != 0).then_some(MotionTile::Slabs(mask))
            }
            MotionEntry::Static(_) => None,
        }
    }

    #[inline(always)]
    fn test(entry: &MotionEntry, pos: ScreenPos, s: &Sample, _: &mut Ops) -> Option<Hit> {
        match entry {
            MotionEntry::Motion(m) => motion_test::<P>(m, pos, s),
            MotionEntry::Static(st) if P::PLANAR => static_test(st, pos),
            MotionEntry::Static(_) => None,
        }
    }

    /// The motion path's [`zmax::floor_of`] its ends' `(w, z)` (the bounded test's lerp
    /// rounds to nearest, as the floor's proof takes it); a planar static triangle: none.
    fn depth_floor(entry: &MotionEntry, ops: &mut Ops) -> i32 {
        match entry {
            MotionEntry::Motion(m) => {
                zmax::floor_of(&m.base.map(|end| end.map(|v| (v[2], v[3]))), ops)
            }
            MotionEntry::Static(_) => DEPTH_NEAR,
        }
    }

    #[inline(always)]
    fn count(covered: bool, ops: &mut Ops) {
        ops.add_sample(SAMPLE_OPS);
        if covered {
            ops.add_sample(HIT_OPS);
        }
    }
}

/// A kept tile of the motion-only unit: a sample is tested when its time slab is in the tile's
/// mask (every sample of a planar static triangle's tile).
impl Admit for MotionTile {
    #[inline(always)]
    fn admit(&self, s: &Sample, _: &mut Ops) -> bool {
        match *self {
            MotionTile::Static => true,
            // slab_of < SLABS ≤ u8::BITS (asserted at SLABS): the shift is in range.
            MotionTile::Slabs(mask) => (mask >> slab_of(s.t().to_bits())) & 1 != 0,
        }
    }
}
