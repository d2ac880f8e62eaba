//! The faces in their per-tile form: one corner per face, useless faces dropped, a greedy order,
//! and the row spans (module docs of [`crate::bounds::hull`]).
#![warn(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_possible_wrap
)]

use crate::bounds::hull::faces::{HullCoeffs, HullFace, MAX_FACES, SUBPIXEL_ONE};
use crate::input::PixelRect;
use crate::stats::Ops;

/// Most faces a triangle keeps in per-tile form: the first [`KEPT_FACES`] of the greedy order
/// ([`HullTiles::of`]). Keeping fewer faces only culls fewer tiles (conservative); on the quick
/// bench scenes no triangle keeps more than 6 (`tests/tests/model/hull.rs` measures the most on each,
/// so the cap changes no decision there). It sets the per-triangle record: 8 faces of 3 × 128
/// bits and 2 corner bits, against 24 before — the record every strategy with hull culling
/// stores and copies per triangle.
pub const KEPT_FACES: usize = 8;

/// Largest grid of footprint pixels per axis on which setup measures each face's culling to
/// order the faces (8 × 8 = 64 points, one bit each).
const ORDER_GRID: u32 = 8;

/// One face in per-tile form: the tile is culled when `a·xe + b·ye + c < 0`, with `xe` the
/// tile's `x1` (`hi_x`) or `x0` and `ye` likewise: the corner the face's signs picked in setup,
/// with its sub-pixel offset folded into `c` (module docs, "Per-tile cost").
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TileFace {
    a: i128,
    b: i128,
    c: i128,
    hi_x: bool,
    hi_y: bool,
}

impl TileFace {
    /// The per-tile form of `f`: `a' = 256·a`, `b' = 256·b`, and for a > 0 the tile's largest
    /// sample column `256·x1 − 1` (so `a·(256·x1 − 1) = a'·x1 − a`, `−a` folded into c), else
    /// its first `256·x0`; the same for y. `None` on overflow (the face is then dropped).
    /// Ranges (module docs): |a|, |b| < 2^73, |c| < 2^124 after widening: |a'|, |b'| < 2^81,
    /// |c'| < 2^125.
    pub(crate) fn of(f: &HullFace) -> Option<TileFace> {
        let (hi_x, hi_y) = (f.a > 0, f.b > 0);
        let mut c = f.c;
        if hi_x {
            c = c.checked_sub(f.a)?;
        }
        if hi_y {
            c = c.checked_sub(f.b)?;
        }
        Some(TileFace {
            a: f.a.checked_mul(SUBPIXEL_ONE)?,
            b: f.b.checked_mul(SUBPIXEL_ONE)?,
            c,
            hi_x,
            hi_y,
        })
    }

    /// Whether the face is negative at every sample position of `tile` (then the tile is
    /// culled): 2 mul, 2 add, 1 compare, counted by the caller. The same integer as
    /// [`face_culls`]'s maximum: `a'·xe + b'·ye + c'` with xe, ye < 2^16 is < 2^98 + 2^125,
    /// exact; checked anyway (`false`, keep the tile, on overflow).
    #[inline]
    pub(crate) fn culls(&self, tile: PixelRect) -> bool {
        let xe = i128::from(if self.hi_x { tile.x1 } else { tile.x0 });
        let ye = i128::from(if self.hi_y { tile.y1 } else { tile.y0 });
        let v = self
            .a
            .checked_mul(xe)
            .and_then(|x| x.checked_add(self.b.checked_mul(ye)?))
            .and_then(|x| x.checked_add(self.c));
        matches!(v, Some(m) if m < 0)
    }

    /// Whether the coefficients lie in the documented ranges (|a'|, |b'| < 2^81,
    /// |c'| < 2^125): then `a'·xe + b'·ye + c'` with xe, ye < 2^16 is < 2^126 and nothing
    /// overflows in [`Self::culls`] or [`Self::span`].
    fn in_range(&self) -> bool {
        let lim = |v: i128, bits: u32| v.unsigned_abs() < 1u128.checked_shl(bits).unwrap_or(0);
        lim(self.a, 81) && lim(self.b, 81) && lim(self.c, 125)
    }

    /// The pixel columns `[lo, hi)` (unclamped; the caller clamps to the row; `lo ≥ hi`: none)
    /// of the cells of `row` that this face keeps, i.e. whose stored end `xe` has
    /// `a'·xe + r ≥ 0` with `r = b'·ye + c'` (ye: the row's shared y end). Cells of the row are
    /// aligned to the `b`-grid and clipped to `[x0, x1)`: cell k has `x0_k = max(first + k·b,
    /// row.x0)`, `x1_k = min(first + (k+1)·b, row.x1)` (`first = b·⌊row.x0/b⌋`); `xe_k` is
    /// `x1_k` if `a' > 0`, else `x0_k`, as in [`Self::culls`]. `v(k) = a'·xe_k + r` is monotone
    /// in k (`xe_k` increases), so the kept cells are a suffix (`a' > 0`), a prefix (`a' < 0`),
    /// all or none (`a' = 0`: the sign of r).
    /// - The two end cells decide all-or-none without a division: `a' > 0`: none if
    ///   `v(last) < 0`, all if `v(first) ≥ 0`; `a' < 0`: none if `v(first) < 0`, all if
    ///   `v(last) ≥ 0`.
    /// - Otherwise the sign changes inside the row and one exact floor division finds where,
    ///   relative to the first cell's end `xf = xe_first` (with `vf = v(first)`):
    ///   `a' > 0` (vf < 0): kept iff `xe ≥ X = xf − ⌊vf/a'⌋` (= `⌈−r/a'⌉`, since
    ///   `⌊(a'·xf + r)/a'⌋ = xf + ⌊r/a'⌋`), the cells from `k` with `first + (k+1)·b ≥ X`:
    ///   columns from `b·⌊(X − 1)/b⌋`. The quotient `−⌊vf/a'⌋` is in `(0, row.x1 − xf]`
    ///   (`v(last) = a'·row.x1 + r ≥ 0`).
    ///   `a' < 0` (vf ≥ 0): kept iff `x0_k ≤ Y = xf + ⌊vf/(−a')⌋` (= `⌊r/(−a')⌋`), the cells
    ///   with `first + k·b ≤ Y`: columns up to `b·⌊Y/b⌋ + b`. The quotient is in
    ///   `[0, xe_last − xf)` (`v(last) < 0`).
    ///
    ///   Either way the quotient is below the row's width `n_px = row.x1 − row.x0 < 2^16`: the
    ///   division needs only `q = bitlen(n_px)` quotient bits (a q-step restoring divider on the
    ///   ~83-bit operands; ≤ 12 steps in a 2048-pixel viewport), and it is counted as q ops.
    ///
    /// Ops (in `ops.rows`, one per multiply, add, compare, negation, min/max, alignment and
    /// quotient bit): `a' = 0`: 3 (r: mul, add; the compare); else r (2) and 3 per end cell
    /// evaluated (mul, add, compare; the second end only if the first does not decide); a
    /// crossing adds the division's q and 3 (the subtraction from xf, the `−1`/`+b` and the
    /// alignment to the `b` grid, a mask since b is a power of two).
    /// Ranges: `r`, `v` < 2^126 (b'·ye < 2^97, c' < 2^125, a'·xe < 2^97); `None` on overflow
    /// (outside the documented ranges; [`HullTiles::span`] then falls back).
    fn span(&self, row: PixelRect, b: i128, ops: &mut Ops) -> Option<(i128, i128)> {
        let ye = i128::from(if self.hi_y { row.y1 } else { row.y0 });
        let r = self.b.checked_mul(ye)?.checked_add(self.c)?;
        let (x0, x1) = (i128::from(row.x0), i128::from(row.x1));
        let none = Some((x1, x0));
        let all = Some((x0, x1));
        if self.a == 0 {
            ops.add_rows(3);
            return if r >= 0 { all } else { none };
        }
        let v = |xe: i128| self.a.checked_mul(xe)?.checked_add(r);
        // Cell ends: the first cell starts at row.x0 and ends at min(first + b, x1); the last
        // starts at max(first + (n−1)·b, x0) and ends at x1.
        let first = x0.checked_sub(x0.checked_rem_euclid(b)?)?;
        let first_end = first.checked_add(b)?.min(x1);
        let last_start = x1
            .checked_sub(1)?
            .checked_div_euclid(b)?
            .checked_mul(b)?
            .max(x0);
        let q_bits =
            u64::from(u16::BITS.saturating_sub(row.x1.saturating_sub(row.x0).leading_zeros()));
        ops.add_rows(2 + 3);
        if self.a > 0 {
            if v(x1)? < 0 {
                return none;
            }
            ops.add_rows(3);
            let vf = v(first_end)?;
            if vf >= 0 {
                return all;
            }
            ops.add_rows(q_bits + 3);
            let x = first_end.checked_sub(vf.checked_div_euclid(self.a)?)?;
            let lo = x.checked_sub(1)?.checked_div_euclid(b)?.checked_mul(b)?;
            Some((lo, x1))
        } else {
            let vf = v(x0)?;
            if vf < 0 {
                return none;
            }
            ops.add_rows(3);
            if v(last_start)? >= 0 {
                return all;
            }
            ops.add_rows(q_bits + 3);
            let y = x0.checked_add(vf.checked_div_euclid(self.a.checked_neg()?)?)?;
            let hi = y.checked_div_euclid(b)?.checked_mul(b)?.checked_add(b)?;
            Some((x0, hi))
        }
    }
}

/// Per-triangle faces in per-tile form, kept only if they can cull a tile of the footprint, and
/// ordered so that the faces culling the most footprint pixels come first; at most
/// [`KEPT_FACES`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HullTiles {
    faces: [TileFace; KEPT_FACES],
    len: usize,
    /// every kept face lies in the documented ranges (|a'|, |b'| < 2^81, |c'| < 2^125), so no
    /// per-tile or per-row evaluation overflows and row spans are exact ([`HullTiles::span`])
    spans: bool,
}

impl HullTiles {
    /// No faces: nothing is culled.
    pub const EMPTY: HullTiles = HullTiles {
        faces: [TileFace {
            a: 0,
            b: 0,
            c: 0,
            hi_x: false,
            hi_y: false,
        }; KEPT_FACES],
        len: 0,
        spans: true,
    };

    /// The kept faces, in test order.
    pub fn faces(&self) -> &[TileFace] {
        self.faces.get(..self.len).unwrap_or(&[])
    }

    /// The per-tile form of `hull` for tiles inside footprint `fp` (module docs, "Per-tile
    /// cost"): each face folded ([`TileFace::of`]; 4 ops), dropped if it does not cull the
    /// footprint pixel where it is least (5 ops; then it culls no tile inside `fp`), and the
    /// kept ones ordered greedily by the pixels of an up to 8 × 8 grid over `fp` they cull that
    /// no earlier face culls (5 ops per face and grid pixel, 2 per face and pick); the first
    /// [`KEPT_FACES`] of that order are stored.
    pub fn of(hull: &HullCoeffs, fp: PixelRect, ops: &mut Ops) -> HullTiles {
        let mut out = HullTiles::EMPTY;
        if fp.is_empty() {
            return out;
        }
        // Every face that culls some tile of the footprint, before the greedy order picks the
        // stored ones.
        let mut cand = [TileFace::default(); MAX_FACES];
        let w = u32::from(fp.x1.saturating_sub(fp.x0));
        let h = u32::from(fp.y1.saturating_sub(fp.y0));
        let (gx, gy) = (w.min(ORDER_GRID), h.min(ORDER_GRID));
        // Grid pixel k of gx along x: fp.x0 + k·w/gx (< fp.x1; k·w ≤ 7·2^16, no overflow).
        let at = |o: u16, k: u32, n: u32, g: u32| {
            let d = k.saturating_mul(n).checked_div(g).unwrap_or(0);
            o.saturating_add(u16::try_from(d).unwrap_or(u16::MAX))
        };
        let pixel = |x: u16, y: u16| PixelRect {
            x0: x,
            y0: y,
            x1: x.saturating_add(1),
            y1: y.saturating_add(1),
        };
        let mut masks = [0u64; MAX_FACES];
        let mut n = 0usize;
        for f in hull.faces() {
            ops.add_setup(4 + 5);
            let Some(t) = TileFace::of(f) else {
                continue;
            };
            // The footprint pixel where the face's tile maximum is least: its value is monotone
            // in the pixel column (row) with the direction of sign(a) (sign(b)).
            let px = if f.a > 0 {
                fp.x0
            } else {
                fp.x1.saturating_sub(1)
            };
            let py = if f.b > 0 {
                fp.y0
            } else {
                fp.y1.saturating_sub(1)
            };
            if !t.culls(pixel(px, py)) {
                continue;
            }
            let mut mask = 0u64;
            for j in 0..gy {
                for i in 0..gx {
                    ops.add_setup(5);
                    if t.culls(pixel(at(fp.x0, i, w, gx), at(fp.y0, j, h, gy))) {
                        mask |= 1u64
                            .checked_shl(j.saturating_mul(ORDER_GRID).saturating_add(i))
                            .unwrap_or(0);
                    }
                }
            }
            if let (Some(slot), Some(m)) = (cand.get_mut(n), masks.get_mut(n)) {
                *slot = t;
                *m = mask;
                n = n.saturating_add(1);
            }
        }
        // Greedy order: next, the face culling the most grid pixels not yet culled (the first
        // such on ties, so the order is deterministic); stored up to KEPT_FACES.
        let mut covered = 0u64;
        for k in 0..n.min(KEPT_FACES) {
            let mut pick = k;
            let mut gain = 0u32;
            for (i, m) in masks.iter().enumerate().take(n).skip(k) {
                ops.add_setup(2);
                let g = (m & !covered).count_ones();
                if g > gain {
                    (pick, gain) = (i, g);
                }
            }
            cand.swap(k, pick);
            masks.swap(k, pick);
            covered |= masks.get(k).copied().unwrap_or(0);
            if let (Some(slot), Some(t)) = (out.faces.get_mut(k), cand.get(k)) {
                out.spans &= t.in_range();
                *slot = *t;
                out.len = k.saturating_add(1);
            }
        }
        out
    }

    /// Whether some face culls `tile` (a tile inside the footprint), testing the faces in order
    /// and stopping at the first that culls: 5 ops per face tested.
    pub fn culls(&self, tile: PixelRect, ops: &mut Ops) -> bool {
        self.faces().iter().any(|f| {
            ops.add_bounds(5);
            f.culls(tile)
        })
    }

    /// The columns `[x0, x1)` of `row` (one row of `bt`-grid cells clipped to the footprint)
    /// whose cells no face culls, or `None` when the span is not used on this row (then every
    /// tile is tested by [`Self::culls`]). Exactly the cells [`Self::culls`] keeps: see
    /// [`TileFace::span`] per face; the kept set of each face is a run of consecutive cells (a
    /// prefix, a suffix, all or none), so their intersection is the run between the largest
    /// start and the least end, clamped to the row.
    ///
    /// Used when there is a face, the kept faces lie in the documented ranges, and the row has
    /// at least [`SPAN_MIN_CELLS`] cells (1 op, the width compare). Ops, in `ops.rows`: per
    /// face [`TileFace::span`]'s (3 to 11 + q, q = bitlen of the row's width) and 2 (the
    /// max/min with the running span, and the empty test: the faces stop at the first that
    /// leaves the span empty), and 2 per row (the clamp to the row).
    pub fn span(&self, row: PixelRect, bt: u16, ops: &mut Ops) -> Option<(u16, u16)> {
        if self.len == 0 || !self.spans {
            return None;
        }
        ops.add_rows(1);
        let b = bt.max(1);
        // Cells of the row: from align_down(x0) in steps of b up to x1 (x1 > x0 ≥ 0).
        let first = row.x0.checked_sub(row.x0.checked_rem(b)?)?;
        let n = row.x1.saturating_sub(first).div_ceil(b);
        if n < SPAN_MIN_CELLS {
            return None;
        }
        let (mut lo, mut hi) = (i128::from(row.x0), i128::from(row.x1));
        for f in self.faces() {
            let (l, h) = f.span(row, i128::from(b), ops)?;
            lo = lo.max(l);
            hi = hi.min(h);
            ops.add_rows(2);
            if lo >= hi {
                break;
            }
        }
        ops.add_rows(2);
        let lo = lo.clamp(i128::from(row.x0), i128::from(row.x1));
        let hi = hi.clamp(lo, i128::from(row.x1));
        Some((u16::try_from(lo).ok()?, u16::try_from(hi).ok()?))
    }
}

/// Least number of bounds tiles in a row for [`HullTiles::span`] to be used: on a one-tile row
/// the span costs each face at least 7 ops (r, an end cell, the running span) where the per-tile
/// test costs 5 per face and stops at the first that culls, so such rows keep the per-tile test.
pub const SPAN_MIN_CELLS: u16 = 2;
