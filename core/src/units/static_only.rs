//! The static-specialised static-only unit at a [`crate::config::precision::Planar`] precision: setup,
//! 2D tile cull and sample test of a static, in-focus triangle and nothing else (issue 13).
//!
//! [`crate::Renderer`] on [`crate::StaticOnly`] runs the general machinery with the motion and
//! defocus terms gated off: Laine's lens-corner boxes, the t span, per-tile (u, v, t) intervals
//! and a sample interface carrying (u, v, t). A static in-focus triangle needs none of it: its
//! coverage at a [`crate::config::precision::Planar`] precision is the planar test (`planar.rs`), which
//! reads the sample's (x, y) only. [`StaticRenderer`] is that unit's renderer; it is selected at
//! compile time ([`specialised`]: a constant of the precision and unit types) by the demo scene
//! and its Cortex-M programs, and its program links none of the general stages.
//!
//! **What each stage computes** (and only this):
//!
//! | stage | computes | reads |
//! |---|---|---|
//! | [`static_setup`] | [`Triangle::class`] (acceptance); the planar setup (`planar.rs`: rounded vertices `P'`, exact normals `n_k = (a, b, c)`, σ, depth plane `(G, f)`, its three divisions in 32-bit divides: `planar_setup_with::<true>`, the same bits, no 64-bit division routine); oriented normals `a' = σa`, `b' = σb`; `C_k = σ·c_k·d_w − [edge k's fill rule refuses E_k = 0]` (i64, \|.\| < 2^61 + 1); `G_2·d_w`; the depth's split shift `(sh, m)` ([`static_depth`]); the 2D footprint | x, y, z, w of the t0 vertices (the class: all fields) |
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
//! triangle and position (`tests/tests/static_unit.rs`).
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
//! and the operation counts (`tests/tests/static_unit.rs` checks the equalities).

use embedded_graphics_core::pixelcolor::Rgb888;

use crate::config::class::Class;
use crate::config::formats::{DEPTH_FAR, DEPTH_NEAR, SUBPIXEL_BITS};
use crate::config::precision::Precision;
use crate::config::unit::{StaticOnly, Unit};
use crate::error::Error;
use crate::input::{PixelRect, Prim, SamplePattern, Triangle, Viewport};
use crate::raster::renderer::{tile_screen, walk_screen};
use crate::raster::tile_buffer::{DepthTest, PixelStats, TileBuffer};
use crate::sample::planar::depth;
use crate::sample::pos::{Hit, ScreenPos};
use crate::setup::planar::planar_setup_with;
use crate::setup::Cull;
use crate::stats::{Ops, Stats};

/// Whether precision `P` on unit `U` renders on this module's path: a planar precision on the
/// static-only unit. A constant of the types (monomorphisation selects the path; no run-time
/// flag).
pub const fn specialised<P: Precision, U: Unit>() -> bool {
    P::PLANAR && !U::MOTION && !U::DEFOCUS
}

/// One static triangle's data for the tile cull and the sample test. Built only by
/// [`static_setup`] from a checked [`Triangle`], so every field is in the range the module
/// table states.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StaticSetup {
    /// oriented normals `σa_k`, `σb_k` (|.| < 2^31)
    ab: [[i32; 2]; 3],
    /// `σ·c_k·d_w`, minus 1 where the fill rule refuses `E_k = 0` (|.| < 2^61 + 1): a sample
    /// passes edge k iff `c_k + σa_k·d_x + σb_k·d_y ≥ 0`
    c: [i64; 3],
    /// the planar depth plane `G` and exponent `f`
    g: [i32; 3],
    f: i32,
    /// no position of the viewport saturates the depth: it takes the split shift `sh` ∈
    /// [0, 31], `m` ∈ [1, 2^31] (`static_depth`), else the planar test's own function
    fast: bool,
    sh: u32,
    m: u32,
    /// `G_2·d_w` (|.| < 2^61): the depth's constant term
    gw: i64,
    /// `2H`, `2W`, `256·W·H`: `d_x = 2H·xs − 256WH`, `d_y = 256WH − 2W·ys`
    h2: i32,
    w2: i32,
    wh: i32,
    /// `256·W`, `256·H`: positions inside the viewport are below these
    end: [u32; 2],
    footprint: PixelRect,
    vp: Viewport,
}

impl StaticSetup {
    /// Pixels that may hold covered samples (inside the viewport; module docs).
    pub fn footprint(&self) -> PixelRect {
        self.footprint
    }
    /// The viewport.
    pub fn viewport(&self) -> Viewport {
        self.vp
    }
    /// Whether the depth takes the path without saturation (no position of the viewport
    /// saturates; `static_depth`), else the planar test's own function: for tests that must
    /// see both.
    pub fn depth_unsaturated(&self) -> bool {
        self.fast
    }
}

/// Result of [`static_setup`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StaticOutcome {
    /// culled, with the reason
    Culled(Cull),
    /// visible
    Visible(StaticSetup),
}

/// Floor of `num / den` for `den > 0` (the caller's ranges: |num| < 2^27, den < 2^17).
fn floor_div(num: i32, den: i32) -> i32 {
    // den > 0: the Euclidean quotient is the floor; None (den = 0) is not reached.
    num.checked_div_euclid(den).unwrap_or(0)
}

/// `[lo, hi]` (pixel indices, inclusive, any sign) clipped to `[0, extent)` as a half-open
/// `u16` range.
fn clip(lo: i32, hi: i32, extent: u16) -> (u16, u16) {
    let e = i32::from(extent);
    // Both clamped to [0, E] with E ≤ 2048: exact in u16.
    let px = |p: i32| u16::try_from(p.clamp(0, e)).unwrap_or(extent);
    (px(lo), px(hi.saturating_add(1)))
}

/// Static setup of `tri` in `vp` (module docs): `Err(class)` for a triangle that is not static
/// and in focus (nothing computed beyond [`Triangle::class`]); culled as degenerate when the rounded
/// triangle has `det P' = 0`, as outside when no sample can be covered.
#[allow(clippy::arithmetic_side_effects)] // ranges at each line
pub fn static_setup(tri: &Triangle, vp: Viewport, ops: &mut Ops) -> Result<StaticOutcome, Class> {
    let class = tri.class();
    if !StaticOnly::accepts(class) {
        return Err(class);
    }
    let Some((pl, _)) = planar_setup_with::<true>(tri, vp, ops) else {
        return Ok(StaticOutcome::Culled(Cull::Degenerate));
    };
    let pv = pl.vertices();
    if pv.iter().all(|p| p[2] <= 0) {
        return Ok(StaticOutcome::Culled(Cull::Outside));
    }
    let footprint = if pv.iter().all(|p| p[2] > 0) {
        // |x'|, |y'|, w' < 2^15 and W, H ≤ 2^11: |numerator| < 2^27, 0 < 2w' < 2^16.
        let col = |p: &[i32; 3]| floor_div(i32::from(vp.w) * (p[0] + p[2]), 2 * p[2]);
        let row = |p: &[i32; 3]| floor_div(i32::from(vp.h) * (p[2] - p[1]), 2 * p[2]);
        let (cs, rs) = (pv.map(|p| col(&p)), pv.map(|p| row(&p)));
        let span = |v: [i32; 3]| (v.iter().copied().min(), v.iter().copied().max());
        let ((Some(c0), Some(c1)), (Some(r0), Some(r1))) = (span(cs), span(rs)) else {
            return Ok(StaticOutcome::Culled(Cull::Outside));
        };
        let ((x0, x1), (y0, y1)) = (clip(c0, c1, vp.w), clip(r0, r1, vp.h));
        PixelRect { x0, y0, x1, y1 }
    } else {
        PixelRect {
            x0: 0,
            y0: 0,
            x1: vp.w,
            y1: vp.h,
        }
    };
    ops.add_setup(6 * 4);
    if footprint.is_empty() {
        return Ok(StaticOutcome::Culled(Cull::Outside));
    }
    let sigma = pl.sigma();
    // 256·W·H ≤ 2^30, 2W, 2H ≤ 2^12, 256·W, 256·H ≤ 2^19.
    let (w, h) = (i32::from(vp.w), i32::from(vp.h));
    let one = 1i32 << SUBPIXEL_BITS;
    let wh = one * w * h;
    let n = pl.n();
    // |a|, |b|, |c| ≤ 2·(2^15 − 1)² < 2^31 (`planar.rs`), σ = ±1: the negations are exact;
    // |c·d_w| < 2^61, and minus 1 stays far inside i64.
    let ab = n.map(|[a, b, _]| [sigma * a, sigma * b]);
    let mut c = [0i64; 3];
    for ((ck, nk), [a, b]) in c.iter_mut().zip(n.iter()).zip(ab.iter()) {
        // The fill rule on E_k = 0 (`planar.rs`, on the oriented normal): σa > 0, or a = 0
        // and σb > 0. Refused: the edge needs σE_k > 0, i.e. σE_k − 1 ≥ 0 (integers).
        let tie = *a > 0 || (*a == 0 && *b > 0);
        *ck = i64::from(sigma * nk[2]) * i64::from(wh) - i64::from(!tie);
    }
    let (g, f) = pl.depth_plane();
    // |G| ≤ 2^31, d_w ≤ 2^30.
    let gw = i64::from(g[2]) * i64::from(wh);
    // The viewport's corner positions: 256·W − 1, 256·H − 1 < 2^19; the directions as in
    // `dxy` (|.| ≤ 2^30).
    let (xh, yh) = (one * w - 1, one * h - 1);
    let (dx0, dx1, dy0, dy1) = (-wh, 2 * h * xh - wh, wh, wh - 2 * w * yh);
    let (sh, m) = depth_split(g, f, gw, [dx0, dx1], [dy1, dy0]);
    let fast = sh < GENERAL;
    ops.add_setup(12 + 4 * 3);
    Ok(StaticOutcome::Visible(StaticSetup {
        ab,
        c,
        g,
        f,
        fast,
        sh,
        m,
        gw,
        h2: 2 * h,
        w2: 2 * w,
        wh,
        end: [
            u32::from(vp.w) << SUBPIXEL_BITS,
            u32::from(vp.h) << SUBPIXEL_BITS,
        ],
        footprint,
        vp,
    }))
}

/// `σE_k` (fill-adjusted, module docs) at direction components `(dx, dy)`: |σa|, |σb| < 2^31,
/// |d| ≤ 2^30, |c| ≤ 2^61: each product < 2^61, the sum < 3·2^61 + 1 < 2^63 (exact i64).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects)]
fn edge(ab: &[i32; 2], c: i64, dx: i32, dy: i32) -> i64 {
    c + i64::from(ab[0]) * i64::from(dx) + i64::from(ab[1]) * i64::from(dy)
}

/// `(d_x, d_y)` of the sample position `(xs, ys)`, both below `256·(W, H)` (checked by the
/// callers): |2H·xs − 256WH| ≤ 256WH ≤ 2^30, the same for y (`sample::direction`).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects)]
fn dxy(s: &StaticSetup, xs: i32, ys: i32) -> (i32, i32) {
    (s.h2 * xs - s.wh, s.wh - s.w2 * ys)
}

/// Whether bounds tile `cell` may hold a covered sample: `false` only if some edge's largest
/// fill-adjusted `σE_k` over the tile's sample rectangle is negative (module docs; exact and
/// conservative). Counts its operations in `ops.bounds`.
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_wrap)]
pub fn static_tile(s: &StaticSetup, cell: PixelRect, ops: &mut Ops) -> bool {
    if cell.is_empty() {
        return false;
    }
    if cell.x1 > s.vp.w || cell.y1 > s.vp.h {
        // Not a tile the renderer walks (it clips to the viewport): kept, and the sample test
        // refuses every position outside the viewport.
        return true;
    }
    ops.add_bounds(4 + 3 * 4);
    // cell.x1 ≤ W ≤ 2048 and x1 > x0 ≥ 0: 256·x1 − 1 < 2^19, exact in i32 (the same for y).
    let one = 1i32 << SUBPIXEL_BITS;
    let (dxl, dyl) = dxy(s, i32::from(cell.x0) * one, i32::from(cell.y0) * one);
    let (dxh, dyh) = dxy(
        s,
        i32::from(cell.x1) * one - 1,
        i32::from(cell.y1) * one - 1,
    );
    s.ab.iter().zip(s.c.iter()).all(|(ab, &c)| {
        // d_x grows with xs, d_y falls with ys: the corner of the largest σE_k.
        let dx = if ab[0] > 0 { dxh } else { dxl };
        let dy = if ab[1] > 0 { dyl } else { dyh };
        edge(ab, c, dx, dy) >= 0
    })
}

/// The static sample test at screen position `pos`: bit for bit the planar test's result
/// (module docs); `None` outside the viewport.
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_wrap)]
pub fn static_test(s: &StaticSetup, pos: ScreenPos) -> Option<Hit> {
    let [ew, eh] = s.end;
    if pos.xs >= ew || pos.ys >= eh {
        return None;
    }
    // xs, ys < 2^19: exact in i32.
    let (dx, dy) = dxy(s, pos.xs as i32, pos.ys as i32);
    for (ab, &c) in s.ab.iter().zip(s.c.iter()) {
        if edge(ab, c, dx, dy) < 0 {
            return None;
        }
    }
    Some(Hit {
        depth: static_depth(s, dx, dy),
    })
}

/// `sh` of a plane whose depth takes the planar test's own function ([`static_depth`]).
const GENERAL: u32 = 32;

/// The planar test's depth ([`crate::sample::planar`]: `⌊Σ G_i·d_i / 2^min(f, 63)⌋` saturated to
/// [`DEPTH_NEAR`, `DEPTH_FAR`]) with the constant term `G_2·d_w` from setup: the same sum, the
/// same bits. When setup found that no position of the viewport saturates ([`depth_split`]:
/// `1 ≤ f ≤ 63` and the quotient inside the depth range at the viewport's four corner
/// positions — the sum is affine in the position and the floor monotone, so its extremes are
/// at the corners) the quotient `q = ⌊acc / 2^f⌋` is the depth as it stands and is formed from
/// the sum's two 32-bit words `acc = hi·2^32 + lo` (`hi = ⌊acc / 2^32⌋`, `lo` ∈ [0, 2^32))
/// without a 64-bit variable shift: `q = (hi >> sh)·m + ⌊lo·m / 2^32⌋` modulo 2^32, with
/// - `f ≤ 31`: `sh = 0`, `m = 2^(32−f)` ∈ [2, 2^31]: `acc / 2^f = hi·m + lo·m / 2^32` and `hi·m`
///   is an integer, so `q = hi·m + ⌊lo·m / 2^32⌋` (the high word of the 32 × 32 → 64 unsigned
///   product `lo·m` < 2^63);
/// - `f ≥ 32`: `sh = f − 32` ∈ [0, 31], `m = 1`: `q = ⌊⌊acc / 2^32⌋ / 2^(f−32)⌋ = hi >> sh`,
///   and `⌊lo / 2^32⌋ = 0`.
///
/// `q` ∈ [DEPTH_NEAR, DEPTH_FAR] ⊂ i32 and the wrapping u32 sum is congruent to it modulo
/// 2^32, so its i32 reading is `q` exactly. Otherwise (`fast` false) the planar test's own
/// function decides.
#[inline(always)]
#[allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_truncation,
    clippy::cast_possible_wrap,
    clippy::cast_sign_loss
)]
fn static_depth(s: &StaticSetup, dx: i32, dy: i32) -> i32 {
    if !s.fast {
        return depth(&s.g, s.f, &[dx, dy, s.wh]);
    }
    let [g0, g1, _] = s.g;
    // |G·d| ≤ 2^61 each, three terms < 2^63 (`planar.rs`).
    let acc = s.gw + i64::from(g0) * i64::from(dx) + i64::from(g1) * i64::from(dy);
    split_floor(acc, s.sh, s.m)
}

/// `(hi >> sh)·m + ⌊lo·m / 2^32⌋` modulo 2^32 read as i32, `acc = hi·2^32 + lo` ([`static_depth`];
/// `sh` < 32: the shift is in range; `lo·m` < 2^64 in u64).
#[inline(always)]
#[allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_truncation,
    clippy::cast_possible_wrap,
    clippy::cast_sign_loss
)]
pub(crate) fn split_floor(acc: i64, sh: u32, m: u32) -> i32 {
    let (hi, lo) = ((acc >> 32) as i32, acc as u32);
    let low = ((u64::from(lo) * u64::from(m)) >> 32) as u32;
    ((hi >> sh) as u32).wrapping_mul(m).wrapping_add(low) as i32
}

/// The depth's split shift `(sh, m)` of plane `(g, f)` (`gw = G_2·d_w`, [`static_depth`]):
/// `(f − 32, 1)` or `(0, 2^(32−f))` when `1 ≤ f ≤ 63` and no position of the viewport
/// saturates, else `(GENERAL, 1)`. `dx`, `dy`: the ranges of `d_x`, `d_y` over the viewport's
/// positions. The sum `gw + G_0·d_x + G_1·d_y` is affine with separate terms, so its extremes
/// over the positions are `gw` plus each term's extreme over its own range (at an end); the
/// floor is monotone, so no position saturates iff both extremes' quotients lie in
/// [`DEPTH_NEAR`, `DEPTH_FAR`].
#[allow(clippy::arithmetic_side_effects, clippy::cast_sign_loss)]
#[inline(never)]
pub(crate) fn depth_split(g: [i32; 3], f: i32, gw: i64, dx: [i32; 2], dy: [i32; 2]) -> (u32, u32) {
    // |G·d| ≤ 2^61 per term: each extreme's sum < 2^63 (`static_depth`).
    let term = |gi: i32, [lo, hi]: [i32; 2]| {
        let (a, b) = (i64::from(gi) * i64::from(lo), i64::from(gi) * i64::from(hi));
        (a.min(b), a.max(b))
    };
    let ((x0, x1), (y0, y1)) = (term(g[0], dx), term(g[1], dy));
    let fast = (1..=63).contains(&f) && {
        // f ∈ [1, 63]: the shifts are in range.
        let (lo, hi) = ((gw + x0 + y0) >> f, (gw + x1 + y1) >> f);
        lo >= i64::from(DEPTH_NEAR) && hi <= i64::from(DEPTH_FAR)
    };
    match f {
        // 32 − f ∈ [1, 31]: 2^(32−f) ∈ [2, 2^31] (u32; a right shift of a constant).
        1..=31 if fast => (0, (1u32 << 31) >> (f - 1) as u32),
        // f − 32 ∈ [0, 31].
        32..=63 if fast => ((f - 32) as u32, 1),
        _ => (GENERAL, 1),
    }
}

/// Operations counted per sample test (direction 2, three edges × (2 multiply-adds, 1 add,
/// 1 compare)) and per hit (the depth), as the planar test counts them.
const SAMPLE_OPS: u64 = 14;
const HIT_OPS: u64 = 4;

/// The static-only unit's renderer at a planar precision: at most `N` visible triangles, one
/// [`StaticSetup`] each (no (u, v, t) bounds, no general setup). The same interface and
/// counters as [`crate::Renderer`] ([`crate::Renderer::render_tile`] for the tile walk), the
/// same image as the full unit (module docs).
pub struct StaticRenderer<const N: usize> {
    vp: Viewport,
    setups: heapless::Vec<(StaticSetup, Rgb888), N>,
    /// counters accumulated over setup and every rendered tile
    pub stats: Stats,
}

impl<const N: usize> StaticRenderer<N> {
    /// Set every triangle up once, in order. Fails with [`Error::ClassNotInUnit`] naming the
    /// first primitive that is not static and in focus ([`static_setup`] classifies each before
    /// computing anything for it), or with [`Error::TooManyTriangles`] if more than `N`
    /// triangles before it are visible. No renderer is returned on an error.
    pub fn new(vp: Viewport, prims: &[Prim]) -> Result<Self, Error> {
        let mut r = StaticRenderer {
            vp,
            setups: heapless::Vec::new(),
            stats: Stats::default(),
        };
        for (index, p) in prims.iter().enumerate() {
            Stats::inc(&mut r.stats.triangles);
            let out = static_setup(&p.tri, vp, &mut r.stats.ops).map_err(|class| {
                Error::ClassNotInUnit {
                    index,
                    class,
                    unit: StaticOnly::NAME,
                }
            })?;
            match out {
                StaticOutcome::Culled(Cull::Outside) => Stats::inc(&mut r.stats.culled_outside),
                StaticOutcome::Culled(Cull::Degenerate) => {
                    Stats::inc(&mut r.stats.culled_degenerate)
                }
                StaticOutcome::Visible(s) => {
                    if let Some(c) = r.stats.by_class.get_mut(Class::Static.index()) {
                        Stats::inc(c);
                    }
                    r.setups
                        .push((s, p.color))
                        .map_err(|_| Error::TooManyTriangles { capacity: N })?;
                }
            }
        }
        Ok(r)
    }

    /// The visible setups.
    pub fn setups(&self) -> impl Iterator<Item = &StaticSetup> {
        self.setups.iter().map(|(s, _)| s)
    }

    /// Render the screen tile whose top-left pixel is (`x0`, `y0`) into `fb` (cleared first);
    /// the same checks and errors as [`crate::Renderer::render_tile`].
    pub fn render_tile<const TW: usize, const TH: usize, const S: usize>(
        &mut self,
        x0: u16,
        y0: u16,
        pattern: &SamplePattern<'_>,
        bounds_tile: u8,
        clear: Rgb888,
        fb: &mut TileBuffer<TW, TH, S>,
    ) -> Result<(), Error> {
        let screen = tile_screen::<TW, TH, S>(pattern, bounds_tile, x0, y0, &self.vp)?;
        fb.clear_fill(clear);
        let StaticRenderer { setups, stats, .. } = self;
        let mut ops = Ops::default();
        for (setup, color) in setups.iter() {
            let region = setup.footprint.intersect(&screen);
            for cell in region.cells(u16::from(bounds_tile)) {
                Stats::inc(&mut stats.tiles_visited);
                if !static_tile(setup, cell, &mut ops) {
                    Stats::inc(&mut stats.tiles_skipped);
                    continue;
                }
                shade_cell(setup, cell, screen, pattern, *color, fb, stats, &mut ops);
            }
        }
        stats.ops.add(&ops);
        Ok(())
    }

    /// Render the whole viewport tile by tile, handing every resolved pixel with its counters
    /// to `out(x, y, color, stats)` (as [`crate::Renderer::render_with`]).
    pub fn render_with<const TW: usize, const TH: usize, const S: usize>(
        &mut self,
        pattern: &SamplePattern<'_>,
        bounds_tile: u8,
        clear: Rgb888,
        out: impl FnMut(u16, u16, Rgb888, PixelStats),
    ) -> Result<(), Error> {
        let mut fb = TileBuffer::<TW, TH, S>::new_fill(clear);
        let vp = self.vp;
        walk_screen(
            vp,
            &mut fb,
            |x0, y0, fb| self.render_tile(x0, y0, pattern, bounds_tile, clear, fb),
            out,
        )
    }
}

/// Test every sample of one bounds tile (the counters as the general renderer keeps them).
#[allow(clippy::too_many_arguments)]
fn shade_cell<const TW: usize, const TH: usize, const S: usize>(
    setup: &StaticSetup,
    cell: PixelRect,
    screen: PixelRect,
    pattern: &SamplePattern<'_>,
    color: Rgb888,
    fb: &mut TileBuffer<TW, TH, S>,
    stats: &mut Stats,
    ops: &mut Ops,
) {
    for py in cell.y0..cell.y1 {
        for px in cell.x0..cell.x1 {
            // The cell lies inside the screen tile, so both differences are in [0, TW), [0, TH).
            let (Some(tx), Some(ty)) = (px.checked_sub(screen.x0), py.checked_sub(screen.y0))
            else {
                continue;
            };
            let (tx, ty) = (usize::from(tx), usize::from(ty));
            for (si, s) in pattern.pixel(px, py).iter().enumerate() {
                Stats::inc(&mut stats.samples_tested);
                ops.add_sample(SAMPLE_OPS);
                let hit = static_test(setup, ScreenPos::of(px, py, s));
                fb.count(tx, ty, hit.is_some());
                let Some(h) = hit else {
                    continue;
                };
                ops.add_sample(HIT_OPS);
                Stats::inc(&mut stats.samples_covered);
                // In range (tx < TW, ty < TH, si < S = spp) and h.depth ≠ DEPTH_EMPTY.
                match fb.write(tx, ty, si, color, h.depth) {
                    Some(DepthTest::Written) => {
                        Stats::inc(&mut stats.samples_written);
                        fb.count_written(tx, ty);
                    }
                    Some(DepthTest::Occluded) => Stats::inc(&mut stats.samples_occluded),
                    None => {}
                }
            }
        }
    }
}
