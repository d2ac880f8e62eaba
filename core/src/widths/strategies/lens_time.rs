//! [`LensTime`](crate::bounds::lens_time::LensTime)'s own operators at R = [`BEST_SLABS`]
//! slabs, motion + defocus triangles only (the Laine 2011 box underneath is
//! [`super::laine`]'s): per triangle the dual values of every axis and slab (`slab_axis`), per
//! tile every slab's t interval (`slab_t`) and the box narrowed to the non-empty slabs, per
//! sample the slab index and t compares of both axes (`predicate`).
//!
//! Counts are the operations the code runs on its worst-case path, each where it runs it (as in
//! [`super::hyper`]): a value the code recomputes inside a loop (`a + w` and `(a + w)·E` per
//! footprint end, `ξb − x` per line end) is counted at every iteration. With R ≤ 4 every lens
//! factor (R, `2j − R`, `2j − R + 2` ∈ {0, ±1, ±2, ±4}) is a shift or zero, so the bias products
//! are `cs × E` multipliers. Widths come from the domain constants with [`Mag`], as the range
//! comments of `bounds/lens_time.rs` state them (there for R ≤ 8: dual values < 2^47, line
//! values < 2^59): |a|, |cs|, |w| ≤ 2^29, E, ξ, x ≤ 2^11, t, u ∈ [−2^16, 2^16].

use crate::bounds::composed::BEST_SLABS;
use crate::config::formats::TUV_FRAC;
use crate::config::registry::Config;
use crate::widths::mag::Mag;
use crate::widths::ops::{Classes, Inventory, OpKind, Stage};
use crate::widths::row::{eps_max, ext, lim, one};

// The lens factors are powers of two (or 0) only for R ≤ 4: R = 8 has 2j − R = ±6, a constant
// multiplier this inventory does not list.
const _: () = assert!(
    BEST_SLABS == 1 || BEST_SLABS == 2 || BEST_SLABS == 4,
    "lens_time inventory: R must be 1, 2 or 4"
);

/// Slabs per axis, R.
#[allow(clippy::cast_possible_truncation)] // R ≤ 4 (asserted above)
const R: u32 = BEST_SLABS as u32;

/// `LensTime<BEST_SLABS>`'s own operators at configuration `cfg`, one per operator kind and
/// stage (a group of nearby widths takes the widest).
// Counts are products of small constants (axes 2, slabs R ≤ 4, vertex ends 6, footprint ends 2,
// line ends 2, lines 4, solves 2); the epsilon sum is of two u32 values in u128.
#[allow(clippy::arithmetic_side_effects)]
pub fn push(inv: &mut Inventory, cfg: &Config) {
    let b = Classes::BOTH;
    let (tri, tile, smp) = (Stage::Triangle, Stage::Tile, Stage::Predicate);
    let add = |m: Mag| OpKind::Add { bits: m.bits() };
    let cmp = |m: Mag| OpKind::Cmp { bits: m.bits() };
    let mul = |m: Mag, o: Mag| OpKind::Mul {
        a: m.bits(),
        b: o.bits(),
    };
    let e = ext();
    let r = Mag::int(u128::from(R));
    let (ex, ew) = eps_max(cfg);
    let eps = Mag::int(u128::from(ex) + u128::from(ew));
    let aw = lim().times(2); // a + w
    let base = aw.mul(e).add(lim().times(2).mul(e)); // (a + w)·E − 2wξ
                                                     // k·cs·E, (k + 2)·cs·E with |k|, |k + 2| ≤ R; then R·base + b ∓ pert (≥ |base|, |b|).
    let bias = r.mul(lim()).mul(e);
    let v = r.mul(base).add(bias).add(r.mul(eps).mul(e));
    // v0·(ξb − x) + v1·(x − ξa): weights ≥ 0 summing to D ≤ E.
    let line = v.mul(e);
    let num = line.times(2); // lo1 − lo0, hi0 − hi1
    let t = one(); // raw t / u / v and interval ends
    let slabs = 2 * R; // `slab_axis` calls / `slab_t` calls: 2 axes × R
    let it = slabs * 12; // × 6 vertex ends × 2 footprint ends

    // `round_out` of each slab's interval (a no-op at 16 t fraction bits).
    let round = u32::from(cfg.tuv() < TUV_FRAC);

    // ---- per triangle: `prepare`, 2 axes × R slabs (`slab_axis`) ----
    inv.op(tri, "`ε_x + ε_w` (per axis)", add(eps), 2, b);
    inv.op(tri, "`pert = R·(ε_x + ε_w)·E`", mul(eps, e), slabs, b);
    let what = "bias `k·cs·E`, `(k + 2)·cs·E` (per vertex end); `w·ξ` (2·: a shift)";
    inv.op(tri, what, mul(lim(), e), slabs * 12 + it, b);
    inv.op(tri, "`a + w`", add(aw), it, b);
    inv.op(tri, "`(a + w)·E`", mul(aw, e), it, b);
    let what = "`(a + w)·E − 2wξ` (R·: a shift); `base + b ∓ pert` (lo, hi)";
    inv.op(tri, what, add(v), it + 4 * it, b);
    let what = "`min(b1, b2)`, `max(b1, b2)`; lo min / hi max";
    inv.op(tri, what, cmp(v), 2 * it + 2 * it, b);

    // ---- per tile: `tile`, 2 axes × R slabs (`slab_t` on a non-empty slab) ----
    inv.op(
        tile,
        "`ξb − x`, `x − ξa` (per line end)",
        add(e),
        16 * slabs,
        b,
    );
    let what = "line `v0·(ξb − x)`, `v1·(x − ξa)`";
    inv.op(tile, what, mul(v, e), 16 * slabs, b);
    let what = "line value sum (8); solve `lo1 − lo0`, `hi0 − hi1` (2)";
    inv.op(tile, what, add(num), 10 * slabs, b);
    let what = "line min / max over the tile ends (4); solve cases `d > 0`, `n < 0`, `n ≥ d` (6)";
    inv.op(tile, what, cmp(num), 10 * slabs, b);
    let div = OpKind::Div {
        den: num.bits(),
        quot: 16,
    };
    inv.op(tile, "solve `n·2^16 / d` (`solve_le`)", div, 2 * slabs, b);
    let what = "solve ceiling `q + (r ≠ 0)` (2); `round_out` upper end up";
    inv.op(tile, what, add(t), (2 + round) * slabs, b);
    // Per slab: range ∩ lens box, solve ∩ solve, ∩ b.t (3 each: max, min, empty), the two hull
    // joins (min, max), `round_out`'s `min(hi, 1)`; per axis b.t ∩ t hull (3).
    let what = "interval meets and hull joins, `round_out` `min(hi, 1)`";
    inv.op(tile, what, cmp(t), (13 + round) * slabs + 6, b);

    // ---- per sample: `predicate`, 2 axes (`slab_of`, `contains`) ----
    let what = "`u.clamp(−1, 1)` (a no-op on the sample domain); `lo ≤ t`, `t ≤ hi`";
    inv.op(smp, what, cmp(t), 4 + 4, b);
    inv.op(smp, "`u + 2^16`", add(t.times(2)), 2, b);
    inv.op(smp, "slab index `min(i, R − 1)`", cmp(r), 2, b);
}
