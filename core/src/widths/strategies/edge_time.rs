//! [`EdgeTime`](crate::bounds::edge_time::EdgeTime)'s own operators, moving triangles only (the
//! inner strategy's are its own file's): per triangle the mid-shutter triangle (`mid2`), each
//! edge's direction and score (`edge_dir`, three edges) and the pick, then the four bounding
//! lines along the chosen normal (`edge_axis`); per tile the t interval along it
//! (`EdgeAxis::t`) and its meet with the inner box. No row step, no predicate (the inner ones).
//!
//! Counts are the operations the code runs on its worst-case path (every edge scored, an oblique
//! one found), each where it runs it (as in [`super::hyper`]): `n_x·W` per vertex end and again
//! for ρ and the lens weight, `|l1|·W` again for the score. Widths come from the domain constants
//! with [`Mag`], as the range comments of `bounds/edge_time.rs` state them: mid-shutter
//! |P| ≤ 2^30, |l| ≤ 2^61, |g| ≤ 2^72, |n_i| ≤ N_MAX = 2^8, pixel coordinates ≤ E = 2^11,
//! |ζ| ≤ 2^20, dual values < 2^52, line values < 2^75.

use crate::bounds::edge_time::N_MAX;
use crate::config::formats::TUV_FRAC;
use crate::config::registry::Config;
use crate::widths::mag::Mag;
use crate::widths::ops::{Classes, Inventory, OpKind, Stage};
use crate::widths::row::{eps_max, ext, lim, one};

/// `EdgeTime`'s own operators at configuration `cfg`, one per operator kind and stage (a group
/// of nearby widths takes the widest).
// Counts are sums of products of small constants (edges 3, vertex ends 6, footprint ends 2,
// lines 4, solves 2); the epsilon sum is of two u32 values in u128.
#[allow(clippy::arithmetic_side_effects)]
pub fn push(inv: &mut Inventory, cfg: &Config) {
    let m = Classes::MOTION;
    let (tri, tile) = (Stage::Triangle, Stage::Tile);
    let add = |x: Mag| OpKind::Add { bits: x.bits() };
    let cmp = |x: Mag| OpKind::Cmp { bits: x.bits() };
    let mul = |x: Mag, o: Mag| OpKind::Mul {
        a: x.bits(),
        b: o.bits(),
    };
    let e = ext();
    let n = Mag::int(u128::from(N_MAX.unsigned_abs()));
    // `edge_dir`: P = q + r, l = P × P (two products), g = l·E; n_i = ⌊(2N·g_i + m) / 2m⌋.
    let p = lim().times(2);
    let l = p.mul(p).times(2);
    let g = l.mul(e);
    let nnum = g.mul(n).times(2).add(g);
    // Score: |l|·E·2^8 / (w_i·w_j), w_i·w_j ≥ 1; the product saturates in u128.
    let q = l.mul(e).times(256);
    // `edge_axis`: ζ = n_x·x + n_y·y; D, ζ − ζa ≤ 2|ζ|; ρ, lens weight, A, φ, the lines.
    let nw = n.mul(e);
    let z = nw.times(2);
    let zr = z.times(2);
    let (ex, ew) = eps_max(cfg);
    let eps = Mag::int(u128::from(ex) + u128::from(ew));
    let rho = nw.mul(eps).times(2);
    let lens = nw.times(2);
    let aw = lim().times(2); // x + w, w − y
    let a = nw.mul(aw).times(2);
    let bias = lens.mul(lim()).add(rho);
    let v = a.add(lim().mul(z).times(2)).add(bias); // φ ± bias (≥ |A|, |bias|, |φ|)
    let slope = v.times(2);
    let line = v.mul(zr).add(slope.mul(zr)); // base + slope·(ζ − ζa)
    let num = line.times(2);
    let t = one();
    // `round_out` of the t interval (a no-op at 16 t fraction bits).
    let round = u32::from(cfg.tuv() < TUV_FRAC);

    // ---- per triangle: `mid2`, 3 × `edge_dir` and the pick ----
    let what = "`mid2` `q + r` (9); `x + w`, `w − y` (12)";
    inv.op(tri, what, add(p), 9 + 12, m);
    inv.op(
        tri,
        "`l0`, `l1` products (12); score `w_i·w_j` (3)",
        mul(p, p),
        15,
        m,
    );
    inv.op(tri, "`l0 = p1·q2 − p2·q1`, `l1`", add(l), 6, m);
    let what = "`g = (l0·H, −l1·W)`; score `|l1|·W`, `|l0|·H` (·256: a shift)";
    inv.op(tri, what, mul(l, e), 12, m);
    inv.op(tri, "`max(|g0|, |g1|)`, `m = 0`", cmp(g), 6, m);
    inv.op(tri, "`2N·g_i + m` (2N: a shift)", add(nnum), 6, m);
    let div = OpKind::Div {
        den: g.times(2).bits(),
        quot: n.bits(),
    };
    inv.op(tri, "`n_i = ⌊(2N·g_i + m) / 2m⌋`", div, 6, m);
    inv.op(tri, "score `w_i > 0`, `w_j > 0`", cmp(p), 6, m);
    let div = OpKind::Div {
        den: p.mul(p).bits(),
        quot: q.mag_bits(),
    };
    inv.op(tri, "score `Δξ`, `Δη` `/ (w_i·w_j)`", div, 6, m);
    inv.op(tri, "score `Δξ·Δη` (saturated)", mul(q, q), 3, m);
    let what = "pick `s > 0` (3 edges), `s > best` (2; u128)";
    inv.op(tri, what, OpKind::Cmp { bits: 128 }, 5, m);

    // ---- per triangle: `edge_axis` ----
    let what = "`n_x·x`, `n_y·y` (8 corners); `|n_x|·W`, `|n_y|·H` (4); `n_x·W`, `n_y·H` (12)";
    inv.op(tri, what, mul(n, e), 8 + 4 + 12, m);
    let what = "corner `ζ = n_x·x + n_y·y` (4); `D = ζb − ζa` (1)";
    inv.op(tri, what, add(zr), 5, m);
    let what = "pick `n_x ≠ 0`, `n_y ≠ 0` (6); `ζa = min`, `ζb = max` (6)";
    inv.op(tri, what, cmp(z), 12, m);
    inv.op(tri, "ρ `|n_x|·W·(ε_x + ε_w)`, y", mul(nw, eps), 2, m);
    let what = "`ε_x + ε_w`, `ε_y + ε_w`; ρ sum, lens weight sum";
    inv.op(tri, what, add(rho.max(lens).max(eps)), 4, m);
    inv.op(tri, "`n_x·W·(x + w)`, `n_y·H·(w − y)`", mul(nw, aw), 12, m);
    let what = "`w·ζ` (2·: a shift; 12); lens term `lens·|c|` (6)";
    inv.op(tri, what, mul(lim(), z.max(lens)), 12 + 6, m);
    // Per vertex end: `A` sum, `bias = lens·|c| + ρ` (6 each); per footprint end: `φ = A − 2wζ`
    // (12), `φ ∓ bias` (24); per line: slope `v1 − v0` (4).
    let what = "`A`, `bias`, `φ = A − 2wζ`, `φ ∓ bias`, slope `v1 − v0`";
    inv.op(tri, what, add(slope), 6 + 6 + 12 + 24 + 4, m);
    let what = "lo min / hi max (24); line end pick `s < 0` / `s ≥ 0` (4)";
    inv.op(tri, what, cmp(slope), 24 + 4, m);
    inv.op(tri, "line base `v0·D`", mul(v, zr), 4, m);

    // ---- per tile: `EdgeAxis::t` and the meet with the inner box (`edge_tile`) ----
    inv.op(tile, "corner pick `n_x ≥ 0`, `n_y ≥ 0`", cmp(n), 2, m);
    inv.op(
        tile,
        "`n_x·x`, `n_y·y` (both picked corners)",
        mul(n, e),
        4,
        m,
    );
    inv.op(tile, "`n_x·x + n_y·y − ζa`", add(zr), 4, m);
    inv.op(tile, "line `s·(ζ − ζa)`", mul(slope, zr), 4, m);
    let what = "line `base + s·(ζ − ζa)` (4); solve `lo1 − lo0`, `hi0 − hi1` (2)";
    inv.op(tile, what, add(num), 4 + 2, m);
    inv.op(
        tile,
        "solve cases `d > 0`, `n < 0`, `n ≥ d`",
        cmp(num),
        6,
        m,
    );
    let div = OpKind::Div {
        den: num.bits(),
        quot: 16,
    };
    inv.op(tile, "solve `n·2^16 / d` (`solve_le`)", div, 2, m);
    let what = "solve ceiling `q + (r ≠ 0)` (2); `round_out` upper end up";
    inv.op(tile, what, add(t), 2 + round, m);
    let what = "meets: solve ∩ solve, ∩ inner t (6); `round_out` `min(hi, 1)`";
    inv.op(tile, what, cmp(t), 6 + round, m);
}
