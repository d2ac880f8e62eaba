//! The static-specialised static-only unit at a [`crate::config::precision::Planar`] precision: setup,
//! 2D tile cull and sample test of a static, in-focus triangle and nothing else (issue 13).
//!
//! The general pipeline ([`crate::units::general`]) on [`crate::StaticOnly`] runs the general
//! machinery with the motion and defocus terms gated off: Laine's lens-corner boxes, the t span,
//! per-tile (u, v, t) intervals and a sample interface carrying (u, v, t). A static in-focus
//! triangle needs none of it: its coverage at a [`crate::config::precision::Planar`] precision
//! is the planar test (`sample::planar`), which reads the sample's (x, y) only.
//! [`StaticPipeline`] is that unit's pipeline; [`crate::units::select`] picks it for every
//! planar precision on the static-only unit, so `Renderer<_, _, PlanarPrecision, StaticOnly>`
//! (alias `StaticRenderer`) runs it, and its program links none of the general stages.
//!
//! **What each stage computes** (and only this):
//!
//! | stage | computes | reads |
//! |---|---|---|
//! | [`static_setup`] | [`Triangle::class`] (acceptance); the planar setup (`planar.rs`: rounded vertices `P'`, exact normals `n_k = (a, b, c)`, σ, depth plane `(G, f)`, its three divisions in 32-bit divides: `planar_setup::<true>`, the same bits, no 64-bit division routine); oriented normals `a' = σa`, `b' = σb`; `C_k = σ·c_k·d_w − [edge k's fill rule refuses E_k = 0]` (i64, \|.\| < 2^61 + 1); `G_2·d_w`; the depth's split shift `(sh, m)` ([`static_depth`]); the 2D footprint | x, y, z, w of the t0 vertices (the class: all fields) |
//! | [`static_tile`] | per bounds tile: the largest `C_k + a'_k·d_x + b'_k·d_y` of each edge over the tile's sample rectangle (one corner per edge, 2 multiply-adds) | the tile's pixel rectangle |
//! | [`static_test`] | `C_k + a'_k·d_x + b'_k·d_y ≥ 0` for k = 0, 1, 2 (six 32 × 32 → 64 multiply-adds), depth on a hit (two multiply-adds, then `(hi >> sh)·m + ⌊lo·m / 2^32⌋` on the sum's words: no 64-bit variable shift) | the sample's (x, y) |
//!
//! **Exactly the planar test.** `d = (d_x, d_y, d_w)` is [`crate::sample::pos::direction`] (d_w =
//! 256·W·H is a constant of the viewport), so `σE_k = σ(a_k d_x + b_k d_y + c_k d_w)` is the
//! planar test's edge value times σ, in exact i64 (each product < 2^61, the sum < 3·2^61). The
//! planar test covers iff, per edge, `σE_k > 0`, or `E_k = 0` and the fill rule (σa > 0, or
//! a = 0 and σb > 0) accepts, i.e. `σE_k ≥ 0` where the rule accepts and `σE_k ≥ 1` where it
//! refuses (integers): `C_k` carries the 1, so one sign test per edge decides. The depth is the
//! planar test's sum `Σ G_i·d_i` with its constant term `G_2·d_w` from setup, floored and
//! saturated the same way (`f < 1`, or a viewport where some position saturates, calls the
//! planar test's own function; otherwise the floor from the sum's two words, [`static_depth`]). So
//! [`static_test`] returns bit for bit what [`crate::sample::planar::planar_test`] returns on the same
//! triangle and position (`tests/tests/model/static_unit.rs`).
//!
//! **Footprint** (exact, no ε: coverage is decided on `P'` itself, so bounds of `P'` are
//! conservative as they stand). A covered `d` lies in the closed cone `Σ λ_k P'_k`, λ ≥ 0
//! (`E_k = λ_k·det P'`, and covered needs `σE_k ≥ 0`). If every `w'_k ≤ 0` no `d` with `d_w > 0`
//! is in it: culled as outside. If every `w'_k > 0` the sample's NDC point is a convex
//! combination of the projected `P'_k`, so its pixel column lies in `[min_k, max_k]` of
//! `⌊W·(x'_k + w'_k) / (2w'_k)⌋` and its row in the same of `⌊H·(w'_k − y'_k) / (2w'_k)⌋` (the
//! sample at `xs` has NDC `x = (2·xs − 256W) / 256W`; the floor is monotone), clipped to the
//! viewport. Otherwise (a camera-plane crosser or a vertex at w' = 0) the footprint is the
//! viewport and the tile cull alone prunes.
//!
//! **Tile cull** (exact, conservative). A bounds tile `[x0, x1) × [y0, y1)` holds sample
//! positions `xs ∈ [256·x0, 256·x1 − 1]`, `ys ∈ [256·y0, 256·y1 − 1]`. The fill-adjusted edge
//! value `C_k + a'_k·d_x + b'_k·d_y` is affine in (xs, ys) with slopes of the signs of `a'_k`
//! (in xs) and `−b'_k` (in ys), so its maximum over the rectangle is at the corner
//! `(a' > 0 ? xs_hi : xs_lo, b' > 0 ? ys_lo : ys_hi)`. A covered sample has it ≥ 0 for every
//! k, so a tile where some edge's maximum is < 0 holds no covered sample and is skipped. This
//! is the planar ε made unnecessary: the decision the bound protects is taken on the very
//! integers the bound evaluates.
//!
//! **Left out, and why that is exact**: the t span and lens-corner boxes (a static in-focus
//! triangle's samples do not depend on (u, v, t)); the per-tile (u, v, t) intervals (the same
//! reason: every sample of a tile passes them); the bounded datapath and the planar ε (only
//! for bounds built from the unrounded vertices); the frustum span (a culling aid: a triangle it
//! culls covers no sample, and here the footprint and the tile cull find the same). A triangle
//! of any other class is refused ([`crate::Error::ClassNotInUnit`]), never rendered.
//!
//! **Same image as the full unit.** Both units' culls are conservative and both decide with the
//! planar test, so every sample is covered by the same triangles with the same depths, written
//! in the same triangle order: image, depth, covered, written and occluded counts are equal.
//! What differs is the work: tiles visited and skipped, samples tested, culled-triangle reasons
//! and the operation counts (`tests/tests/model/static_unit.rs` checks the equalities).

pub mod cull;
pub mod sample;
pub mod setup;

use core::marker::PhantomData;

use crate::bounds::strategy::{Admit, BoundsStrategy};
use crate::config::class::Class;
use crate::config::unit::StaticOnly;
use crate::input::{PixelRect, Sample, Triangle, Viewport};
use crate::sample::pos::{Hit, ScreenPos};
use crate::setup::Outcome;
use crate::stats::Ops;
use crate::units::pipeline::Pipeline;
use crate::units::static_only::cull::static_tile;
use crate::units::static_only::sample::static_test;
use crate::units::static_only::setup::{static_setup, StaticSetup};

/// Operations counted per sample test (direction 2, three edges × (2 multiply-adds, 1 add,
/// 1 compare)) and per hit (the depth), as the planar test counts them.
const SAMPLE_OPS: u64 = 14;

const HIT_OPS: u64 = 4;

/// The static-only unit's pipeline at a planar precision (module docs). `B` is the strategy the
/// renderer is given; this unit's own tile cull replaces it.
#[derive(Clone, Copy, Debug)]
pub struct StaticPipeline<B> {
    bounds: PhantomData<B>,
}

impl<B: BoundsStrategy> Pipeline for StaticPipeline<B> {
    type Bounds = B;
    type Unit = StaticOnly;
    type Entry = StaticSetup;
    type Tile = ();
    const NAME: &'static str = "StaticRenderer";

    fn new(_: B) -> Self {
        StaticPipeline {
            bounds: PhantomData,
        }
    }

    #[inline(always)]
    fn setup(&self, tri: &Triangle, vp: Viewport, ops: &mut Ops) -> Outcome<StaticSetup> {
        static_setup(tri, vp, ops)
    }

    fn class(_: &StaticSetup) -> Class {
        Class::Static
    }

    fn footprint(entry: &StaticSetup) -> PixelRect {
        entry.footprint()
    }

    #[inline(always)]
    fn tile(&self, entry: &StaticSetup, cell: PixelRect, ops: &mut Ops) -> Option<()> {
        static_tile(entry, cell, ops).then_some(())
    }

    #[inline(always)]
    fn test(entry: &StaticSetup, pos: ScreenPos, _: &Sample, _: &mut Ops) -> Option<Hit> {
        static_test(entry, pos)
    }

    #[inline(always)]
    fn count(covered: bool, ops: &mut Ops) {
        ops.add_sample(SAMPLE_OPS);
        if covered {
            ops.add_sample(HIT_OPS);
        }
    }
}

/// A kept tile of the static-only unit: every sample of it is tested — a static in-focus
/// triangle's coverage does not depend on (u, v, t).
impl Admit for () {
    #[inline(always)]
    fn admit(&self, _: &Sample, _: &mut Ops) -> bool {
        true
    }
}
