//! The static-only unit's setup at a planar precision (module docs of
//! [`crate::units::static_only`]): classification, the planar setup in 32-bit divides, the
//! oriented and fill-adjusted edge functions, the depth plane's split shift and the exact 2D
//! footprint.

use crate::config::formats::{DEPTH_FAR, DEPTH_NEAR, SUBPIXEL_BITS};
use crate::config::unit::{StaticOnly, Unit};
use crate::input::{PixelRect, Triangle, Viewport};
use crate::setup::planar::planar_setup;
use crate::setup::{Cull, Outcome};
use crate::stats::Ops;

/// One static triangle's data for the tile cull and the sample test. Built only by
/// [`static_setup`] from a checked [`Triangle`], so every field is in the range the module
/// table states.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StaticSetup {
    /// oriented normals `σa_k`, `σb_k` (|.| < 2^31)
    pub(crate) ab: [[i32; 2]; 3],
    /// `σ·c_k·d_w`, minus 1 where the fill rule refuses `E_k = 0` (|.| < 2^61 + 1): a sample
    /// passes edge k iff `c_k + σa_k·d_x + σb_k·d_y ≥ 0`
    pub(crate) c: [i64; 3],
    /// the planar depth plane `G` and exponent `f`
    pub(crate) g: [i32; 3],
    pub(crate) f: i32,
    /// no position of the viewport saturates the depth: it takes the split shift `sh` ∈
    /// [0, 31], `m` ∈ [1, 2^31] (`static_depth`), else the planar test's own function
    pub(crate) fast: bool,
    pub(crate) sh: u32,
    pub(crate) m: u32,
    /// `G_2·d_w` (|.| < 2^61): the depth's constant term
    pub(crate) gw: i64,
    /// `2H`, `2W`, `256·W·H`: `d_x = 2H·xs − 256WH`, `d_y = 256WH − 2W·ys`
    pub(crate) h2: i32,
    pub(crate) w2: i32,
    pub(crate) wh: i32,
    /// `256·W`, `256·H`: positions inside the viewport are below these
    pub(crate) end: [u32; 2],
    pub(crate) footprint: PixelRect,
    pub(crate) vp: Viewport,
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

/// Static setup of `tri` in `vp` (module docs): [`Outcome::Refused`] for a triangle that is not static
/// and in focus (nothing computed beyond [`Triangle::class`]); culled as degenerate when the rounded
/// triangle has `det P' = 0`, as outside when no sample can be covered.
#[allow(clippy::arithmetic_side_effects)] // ranges at each line
pub fn static_setup(tri: &Triangle, vp: Viewport, ops: &mut Ops) -> Outcome<StaticSetup> {
    let class = tri.class();
    if !StaticOnly::accepts(class) {
        return Outcome::Refused(class);
    }
    let Some((pl, _)) = planar_setup::<true>(tri, vp, ops) else {
        return Outcome::Culled(Cull::Degenerate);
    };
    let pv = pl.vertices();
    if pv.iter().all(|p| p[2] <= 0) {
        return Outcome::Culled(Cull::Outside);
    }
    let footprint = if pv.iter().all(|p| p[2] > 0) {
        // |x'|, |y'|, w' < 2^15 and W, H ≤ 2^11: |numerator| < 2^27, 0 < 2w' < 2^16.
        let col = |p: &[i32; 3]| floor_div(i32::from(vp.w) * (p[0] + p[2]), 2 * p[2]);
        let row = |p: &[i32; 3]| floor_div(i32::from(vp.h) * (p[2] - p[1]), 2 * p[2]);
        let (cs, rs) = (pv.map(|p| col(&p)), pv.map(|p| row(&p)));
        let span = |v: [i32; 3]| (v.iter().copied().min(), v.iter().copied().max());
        let ((Some(c0), Some(c1)), (Some(r0), Some(r1))) = (span(cs), span(rs)) else {
            return Outcome::Culled(Cull::Outside);
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
        return Outcome::Culled(Cull::Outside);
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
    Outcome::Visible(StaticSetup {
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
    })
}

/// `σE_k` (fill-adjusted, module docs) at direction components `(dx, dy)`: |σa|, |σb| < 2^31,
/// |d| ≤ 2^30, |c| ≤ 2^61: each product < 2^61, the sum < 3·2^61 + 1 < 2^63 (exact i64).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn edge(ab: &[i32; 2], c: i64, dx: i32, dy: i32) -> i64 {
    c + i64::from(ab[0]) * i64::from(dx) + i64::from(ab[1]) * i64::from(dy)
}

/// `(d_x, d_y)` of the sample position `(xs, ys)`, both below `256·(W, H)` (checked by the
/// callers): |2H·xs − 256WH| ≤ 256WH ≤ 2^30, the same for y (`sample::direction`).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn dxy(s: &StaticSetup, xs: i32, ys: i32) -> (i32, i32) {
    (s.h2 * xs - s.wh, s.wh - s.w2 * ys)
}

/// `sh` of a plane whose depth takes the planar test's own function ([`static_depth`]).
pub(crate) const GENERAL: u32 = 32;

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
