//! The motion-only unit's setup (module docs of [`crate::units::motion_only`]): per vertex and
//! shutter end the base and `r − q` of (x, y, w, z), the fast datapath's constants, and one
//! screen box per time slab of the shutter with their union, the footprint.

use crate::config::class::Class;
use crate::config::formats::SUBPIXEL_BITS;
use crate::config::precision::{Precision, OFFSET_SHIFT_MAX, OFFSET_SHIFT_MIN};
use crate::config::unit::{MotionOnly, Unit};
use crate::input::{PixelRect, Triangle, Viewport, W, X, Y, Z};
use crate::setup::eps::Eps;
use crate::setup::{Cull, Outcome};
use crate::stats::Ops;

/// Number of equal time slabs of the shutter with their own screen box.
pub const SLABS: usize = 4;
// A tile's slab mask is a `u8` (`MotionTile::Slabs`): one bit per slab, shifts by < 8.
const _: () = assert!(SLABS <= u8::BITS as usize);

/// One static or moving in-focus triangle's data for the slab cull and the sample test. Built
/// only by [`motion_setup`] from a checked [`Triangle`] and [`Viewport`], so every field is in
/// the range stated beside it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MotionSetup {
    /// per shutter end (0: t0, 1: t1), per vertex, `(x, y, w, z)` (|.| ≤ 2^29)
    pub(crate) base: [[[i32; 4]; 3]; 2],
    /// per vertex `r − q` of `(x, y, w, z)` (|.| ≤ 2^30)
    pub(crate) d: [[i32; 4]; 3],
    /// `256W·k`, `256H·k` with `k = 2^(32−S)` (< 2^31 when `fast`)
    pub(crate) swq: i32,
    pub(crate) shq: i32,
    /// `k = 2^(32−S)` ∈ [1, 2^12]
    pub(crate) k: i32,
    /// `256W`, `256H` (≤ 2^19)
    pub(crate) sw: i32,
    pub(crate) sh: i32,
    /// `256W`, `256H` as the position limits
    pub(crate) end: [u32; 2],
    /// both viewport sides below 2^(S−9): the fast datapath applies (T ≠ 2^15)
    pub(crate) fast: bool,
    /// the offset grid S ∈ [`OFFSET_SHIFT_MIN`]..=[`OFFSET_SHIFT_MAX`]
    pub(crate) shift: u32,
    /// a static triangle (`r = q`) with every w > 0 on a `fast` viewport: the sample test
    /// takes [`crate::units::motion_only::sample`]'s static path with the constants below
    pub(crate) still: bool,
    /// static path: per vertex `(w, z)` (|.| ≤ 2^29)
    pub(crate) wz: [(i32, i32); 3],
    /// per shutter end, per vertex: the fast datapath's data (`swq·x + 2^31`, `shq·y + 2^31`
    /// of the base vertex, meaningful when `fast`; `d`'s and `base`'s x, y, w regrouped so that
    /// one vertex is read with a few LDRD / LDM)
    pub(crate) hot: [[Vfast; 3]; 2],
    pub(crate) slabs: [PixelRect; SLABS],
    footprint: PixelRect,
    class: Class,
    vp: Viewport,
}

impl MotionSetup {
    /// Pixels that may hold covered samples: the union of the slab boxes (module docs).
    pub fn footprint(&self) -> PixelRect {
        self.footprint
    }
    /// The box of time slab `j` (module docs); `None` for `j ≥ SLABS`.
    pub fn slab(&self, j: usize) -> Option<PixelRect> {
        self.slabs.get(j).copied()
    }
    /// The triangle's class (static or motion).
    pub fn class(&self) -> Class {
        self.class
    }
    /// The viewport.
    pub fn viewport(&self) -> Viewport {
        self.vp
    }
}

/// One vertex at one shutter end for the fast datapath (`MotionSetup::hot`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Vfast {
    /// `swq·x + 2^31`, `shq·y + 2^31` of the base vertex (|.| < 2^60 + 2^31)
    pub(crate) cx: i64,
    pub(crate) cy: i64,
    /// `r − q` of x, y, w (|.| ≤ 2^30)
    pub(crate) dx: i32,
    pub(crate) dy: i32,
    pub(crate) dw: i32,
    /// the base vertex's w (|.| ≤ 2^29)
    pub(crate) bw: i32,
}

/// The corners' projections at one slab end: `None` (the viewport) when some corner has
/// `w ≤ 0` but not all, `Some(None)` when all have `w ≤ 0`, else the floors of the smallest and
/// largest projection per axis.
type EndBox = Option<Option<[(i64, i64); 2]>>;

/// Slab end `j` ∈ 0..=K of `tri` (module docs): corners of `(K − j)·q + j·r ± K·ε`.
#[allow(clippy::arithmetic_side_effects)]
fn end_box(tri: &Triangle, j: i64, eps: &Eps, vp: Viewport, ops: &mut Ops) -> EndBox {
    // SLABS = 4: the conversion is exact.
    #[allow(clippy::cast_possible_wrap)]
    const K: i64 = SLABS as i64;
    let [q, r] = &tri.v;
    // K ≤ 8, j ∈ 0..=K, fields |.| ≤ 2^29: |(K − j)·q + j·r| ≤ K·2^29 ≤ 2^32.
    let at = |k: usize, f: usize| {
        let (a, b) = (
            q.get(k).and_then(|v| v.get(f)),
            r.get(k).and_then(|v| v.get(f)),
        );
        (K - j) * i64::from(a.copied().unwrap_or(0)) + j * i64::from(b.copied().unwrap_or(0))
    };
    // ε ≤ 2^24 (`Eps::of`): K·ε ≤ 2^27.
    let ew = K * i64::from(eps.w());
    let [ex, ey] = eps.x().map(|e| K * i64::from(e));
    let ws = [0, 1, 2].map(|k| at(k, W));
    let (wmin, wmax) = ws
        .iter()
        .fold((i64::MAX, i64::MIN), |(lo, hi), &w| (lo.min(w), hi.max(w)));
    if wmax + ew <= 0 {
        return Some(None);
    }
    if wmin - ew <= 0 {
        return None;
    }
    let mut out = [(i64::MAX, i64::MIN); 2];
    for (axis, (o, (e, ext))) in out.iter_mut().zip([(ex, vp.w), (ey, vp.h)]).enumerate() {
        for k in 0..3 {
            let a = if axis == 0 { at(k, X) } else { -at(k, Y) };
            let w = ws.get(k).copied().unwrap_or(1);
            let (lo, hi) = corner_range(a, w, e, ew, ext)?;
            *o = (o.0.min(lo), o.1.max(hi));
        }
    }
    ops.add_setup(3 * 2 * 2 * 3);
    Some(Some(out))
}

/// The floors of the smallest and largest projection `(a + w)·E/(2w)` over the four corners
/// `(a ± e, w ± ew)` (every w > 0, the caller's check): `E/2 + a·E/(2w)` is smallest at
/// `a − e` and, there, at the largest w if `a − e ≥ 0`, else at the smallest; the largest at
/// `a + e` and the smallest w if `a + e ≥ 0`, else the largest (the floor is monotone).
/// |a|, e, |w|, ew < 2^33 (`end_box`): the sums are exact in i64.
#[inline(never)]
#[allow(clippy::arithmetic_side_effects)]
fn corner_range(a: i64, w: i64, e: i64, ew: i64, ext: u16) -> Option<(i64, i64)> {
    let (lo, hi) = (a - e, a + e);
    let wl = if lo >= 0 { w + ew } else { w - ew };
    let wh = if hi >= 0 { w - ew } else { w + ew };
    Some((project(lo, wl, ext)?, project(hi, wh, ext)?))
}

/// `floor((a + w)·E / (2w))` for `w > 0` (the caller's check): |a + w| < 2^34, E ≤ 2^11, so
/// the product is < 2^45; checked anyway (`None`, the viewport, on a failure). Out of line:
/// one copy of the 64-bit division for every corner.
#[inline(never)]
#[allow(clippy::arithmetic_side_effects)]
fn project(a: i64, w: i64, ext: u16) -> Option<i64> {
    a.checked_add(w)?
        .checked_mul(i64::from(ext))?
        .checked_div_euclid(w.checked_mul(2)?)
}

/// `[lo, hi]` (pixel indices, any sign) clipped to `[0, extent)` as a half-open range.
fn clip(lo: i64, hi: i64, extent: u16) -> (u16, u16) {
    let e = i64::from(extent);
    let px = |p: i64| u16::try_from(p.clamp(0, e)).unwrap_or(extent);
    (px(lo), px(hi.saturating_add(1)))
}

/// The box of the slab between two ends (module docs).
fn slab_box(a: EndBox, b: EndBox, vp: Viewport) -> PixelRect {
    let all = PixelRect {
        x0: 0,
        y0: 0,
        x1: vp.w,
        y1: vp.h,
    };
    match (a, b) {
        (Some(None), Some(None)) => PixelRect {
            x0: 0,
            y0: 0,
            x1: 0,
            y1: 0,
        },
        (Some(Some(p)), Some(Some(q))) => {
            let [(x0, x1), (y0, y1)] = [0, 1].map(|i| {
                let (Some(u), Some(v)) = (p.get(i), q.get(i)) else {
                    return (0, 0);
                };
                (u.0.min(v.0), u.1.max(v.1))
            });
            let ((x0, x1), (y0, y1)) = (clip(x0, x1, vp.w), clip(y0, y1, vp.h));
            PixelRect { x0, y0, x1, y1 }
        }
        _ => all,
    }
}

/// Motion setup of `tri` in `vp` at precision `P` (module docs): [`Outcome::Refused`] for a triangle
/// the motion-only unit does not accept (nothing computed beyond [`Triangle::class`]).
#[allow(clippy::arithmetic_side_effects)]
pub fn motion_setup<P: Precision>(
    tri: &Triangle,
    vp: Viewport,
    ops: &mut Ops,
) -> Outcome<MotionSetup> {
    let class = tri.class();
    if !MotionOnly::accepts(class) {
        return Outcome::Refused(class);
    }
    let shift = P::OFFSET_SHIFT.unwrap_or(OFFSET_SHIFT_MIN);
    let eps = Eps::of(Some(shift), Class::Motion, vp);
    let mut ends = [None; SLABS + 1];
    for (j, e) in (0i64..).zip(ends.iter_mut()) {
        *e = end_box(tri, j, &eps, vp, ops);
    }
    let mut slabs = [PixelRect::default(); SLABS];
    let mut fp: Option<PixelRect> = None;
    for (s, w) in slabs.iter_mut().zip(ends.windows(2)) {
        if let [a, b] = w {
            *s = slab_box(*a, *b, vp);
        }
        if !s.is_empty() {
            fp = Some(fp.map_or(*s, |f| PixelRect {
                x0: f.x0.min(s.x0),
                y0: f.y0.min(s.y0),
                x1: f.x1.max(s.x1),
                y1: f.y1.max(s.y1),
            }));
        }
    }
    let Some(footprint) = fp else {
        return Outcome::Culled(Cull::Outside);
    };
    let [q, r] = &tri.v;
    let pick = |v: &[i32; 5]| [v[X], v[Y], v[W], v[Z]];
    let base = [q.map(|v| pick(&v)), r.map(|v| pick(&v))];
    let mut d = [[0i32; 4]; 3];
    for ((dk, qk), rk) in d.iter_mut().zip(base[0]).zip(base[1]) {
        for ((o, a), b) in dk.iter_mut().zip(qk).zip(rk) {
            // |a|, |b| ≤ 2^29: |b − a| ≤ 2^30.
            *o = b - a;
        }
    }
    // 256·W, 256·H ≤ 2^19; k = 2^(32−S) ∈ [1, 2^12] (a right shift of a constant by S − 20
    // ∈ 0..=12); side = 2^(S−9) ≥ 2048 (`bounded::Fast::new`).
    let one = 1i32 << SUBPIXEL_BITS;
    let (sw, sh) = (one * i32::from(vp.w), one * i32::from(vp.h));
    let k = (1i32 << 12) >> (shift - OFFSET_SHIFT_MIN);
    let side = (1u32 << 23) >> (OFFSET_SHIFT_MAX - shift);
    let fast = u32::from(vp.w | vp.h) < side;
    // `fast`: 256·max(W, H) < 2^(S−1), so 256W·k < 2^31; else the products are not used and
    // saturate harmlessly.
    let (swq, shq) = (sw.saturating_mul(k), sh.saturating_mul(k));
    let [b0, _] = base;
    let still = fast && class == Class::Static && b0.iter().all(|v| v[2] > 0);
    // |swq|, |shq| < 2^31 (`fast`; else the values are not read), |x|, |y| ≤ 2^29: each
    // product < 2^60, plus 2^31 (i64).
    let c = base.map(|end| {
        end.map(|v| {
            [
                i64::from(swq) * i64::from(v[0]) + (1 << 31),
                i64::from(shq) * i64::from(v[1]) + (1 << 31),
            ]
        })
    });
    let wz = b0.map(|v| (v[2], v[3]));
    let mut hot = [[Vfast::default(); 3]; 2];
    for ((h, ce), be) in hot.iter_mut().zip(c).zip(base) {
        for (((hv, [cx, cy]), bv), dv) in h.iter_mut().zip(ce).zip(be).zip(d) {
            *hv = Vfast {
                cx,
                cy,
                dx: dv[0],
                dy: dv[1],
                dw: dv[2],
                bw: bv[2],
            };
        }
    }
    ops.add_setup(12);
    Outcome::Visible(MotionSetup {
        base,
        d,
        swq,
        shq,
        k,
        sw,
        sh,
        end: [sw.unsigned_abs(), sh.unsigned_abs()],
        fast,
        shift,
        still,
        wz,
        hot,
        slabs,
        footprint,
        class,
        vp,
    })
}

#[cfg(test)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]
mod tests {
    use super::*;
    use uvt_testkit::{cases, seed, Rng};

    /// [`corner_range`] (two chosen corners) against the floors of all four corners'
    /// projections, on extreme and seeded random operands: the ranges `end_box` feeds it
    /// (|a| ≤ 2^31 + 2^27, 0 < w − ew, ew ≤ 2^27, e ≤ 2^27, E ≤ 2048).
    #[test]
    fn corner_range_is_the_four_corner_range() {
        let s = seed();
        let mut rng = Rng(s);
        let brute = |a: i64, w: i64, e: i64, ew: i64, ext: u16| {
            let c = [
                (a - e, w - ew),
                (a - e, w + ew),
                (a + e, w - ew),
                (a + e, w + ew),
            ];
            let p = c.map(|(ac, wc)| ((ac + wc) * i64::from(ext)).div_euclid(2 * wc));
            (p.iter().copied().min(), p.iter().copied().max())
        };
        let check = |a: i64, w: i64, e: i64, ew: i64, ext: u16| {
            if w - ew <= 0 {
                return;
            }
            let (lo, hi) = brute(a, w, e, ew, ext);
            let got = corner_range(a, w, e, ew, ext);
            assert_eq!(
                got.map(Some),
                lo.zip(hi).map(Some),
                "UVT_SEED={s}: a {a} ({a:#x}) w {w} e {e} ew {ew} E {ext}"
            );
        };
        let big = (1i64 << 31) + (1 << 27);
        for a in [-big, -1, 0, 1, big, 12345] {
            for w in [1, 2, 5, 1 << 20, big] {
                for (e, ew) in [(0, 0), (1, 1), (2050 * 4, 4), (1 << 27, 1 << 27)] {
                    for ext in [1, 7, 2048] {
                        check(a, w, e, ew, ext);
                    }
                }
            }
        }
        for _ in 0..cases(100_000, 2_000_000) {
            let a = rng.signed(big);
            let ew = rng.signed(1 << 27).abs() >> (rng.next_u64() % 28);
            let w = ew + 1 + rng.signed(big).abs();
            let e = rng.signed(1 << 27).abs() >> (rng.next_u64() % 28);
            let ext = 1 + (rng.next_u64() % 2048) as u16;
            check(a, w, e, ew, ext);
        }
    }
}
