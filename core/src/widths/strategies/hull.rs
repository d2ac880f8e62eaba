//! [`HullCull`](crate::bounds::hull::HullCull)'s own operators (the inner strategy's are in its
//! own file): per triangle the cone's faces and their per-tile form (`prepare`: `eps_margin`,
//! `pair_faces`, `widened`, `HullTiles::of`), per tile the face test (`HullTiles::culls`), per
//! row the span (`HullTiles::span`). Every class runs them, over 3 hull points (static), 6
//! (motion), 12 (defocus) or 24 (both); a cone over n points has at most n faces, of which the
//! first [`KEPT_FACES`] are kept, so the counts differ by class and each operator is listed
//! once per class set (`per`).
//!
//! **The setup path listed.** Below [`WRAP_FROM`] points (static) only the pair search runs,
//! after `eps_margin` and before `widened` on the bounded test. From [`WRAP_FROM`] points on,
//! the pair search runs only when some w ≤ 0 (then `eps_margin` keeps no face: exact test only)
//! and gift wrapping when every w > 0; the pair search's bound exceeds the wrapping's with
//! `eps_margin` and `widened` (`pair_tally` ≥ `wrap_tally` + `eps_tally`, asserted below),
//! so the pair search's operators are the ones listed, for every class. These are bounds, not
//! measured maxima (the pair search's candidates are bounded by geometry, `known`); the test
//! below checks that the listed counts cover them stage by stage. The code's tally counts a
//! few constant shifts as ops (face_of's ·2, ·256; the fold's ·256) and leaves out compares it
//! runs (the cross's `n = 0`, 3 of same_face's 4 tests): the latter are listed, and cover them.
//!
//! Widths: the cone's values from the domain constants with [`Mag`] (`faces.rs`: |x ± c| ≤ 2^30,
//! w ≤ 2^29, normals ≤ 2^61, `n·p` < 2^93, `same_face`'s terms < 2^124); the per-tile form's
//! from the ranges `TileFace::in_range` keeps (|a'|, |b'| < 2^81, |c'| < 2^125, so
//! `a'·xe + b'·ye + c'` < 2^126). Where a narrower block runs on a wider block's operator of the
//! same kind the two share one entry (said at the op).

use crate::bounds::hull::tiles::KEPT_FACES;
use crate::bounds::hull::WRAP_FROM;
use crate::config::formats::MAX_VIEWPORT;
use crate::config::registry::Config;
use crate::widths::mag::Mag;
use crate::widths::ops::{Classes, Inventory, OpKind, Stage};
use crate::widths::row::{eps_max, ext, lim};

/// Hull points per class, in `Class::index` order (`swept_points`).
const POINTS: [u32; 4] = [3, 6, 12, 24];
/// [`KEPT_FACES`] (8) as a count.
#[allow(clippy::cast_possible_truncation)] // 8
const KEPT: u32 = KEPT_FACES as u32;
/// [`WRAP_FROM`] (4) as a count.
#[allow(clippy::cast_possible_truncation)] // 4
const WRAP: u32 = WRAP_FROM as u32;
/// Pixels `HullTiles::of` tests each face on: the footprint's least one and an 8 × 8 grid.
const PIXELS: u32 = 1 + 64;
/// Quotient bits of a span's division: the row's width is ≤ [`MAX_VIEWPORT`] (2048), so `q`
/// = bitlen(2048) = 12 (`TileFace::span`).
const Q: u32 = u16::BITS - MAX_VIEWPORT.leading_zeros();

// Counts below are sums and products of small constants (n ≤ 24 points, ≤ 276 pairs): every
// value is < 2^20, far from u32's range.

/// Pairs of `n ≥ 1` points.
#[allow(clippy::arithmetic_side_effects)]
const fn pairs(n: u32) -> u32 {
    n * (n - 1) / 2
}

/// Bound on the known faces `pair_faces` compares its candidates with (one `same_face` each),
/// summed over the candidates. All points on one plane: 2 candidates per pair, against ≤ 2 faces
/// (4 per pair). Otherwise ≤ 1 candidate per pair, against ≤ F faces (F ≤ n facets); in a cone
/// with F ≥ 3 facets a point lies on ≤ 2 of them and a facet holds ≤ n − F + 2 points, so the
/// candidate pairs Σ C(k_f, 2) are ≤ n·(n − F + 1) (and ≤ the pairs). F ≤ 2 is inside 4 per pair.
#[allow(clippy::arithmetic_side_effects)]
const fn known(n: u32) -> u32 {
    let p = pairs(n);
    let mut best = 4 * p;
    let mut f = 3;
    while f <= n {
        let s = n * (n - f + 1);
        let s = if s < p { s } else { p };
        if f * s > best {
            best = f * s;
        }
        f += 1;
    }
    best
}

/// Faces scanned by `HullTiles::of`'s greedy order over `f` candidates: Σ_{k < min(f, 8)} (f − k).
#[allow(clippy::arithmetic_side_effects)]
const fn picks(f: u32) -> u32 {
    let (mut s, mut k) = (0, 0);
    while k < f && k < KEPT {
        s += f - k;
        k += 1;
    }
    s
}

/// `pair_faces`' tally at n points, worst case: 9 per pair (cross), 6 per point per pair (no
/// early exit), 15 per known face compared ([`known`]), 8 per face (≤ n).
#[allow(clippy::arithmetic_side_effects)]
const fn pair_tally(n: u32) -> u32 {
    9 * pairs(n) + 6 * n * pairs(n) + 15 * known(n) + 8 * n
}

/// `wrap_faces`' tally at n points, worst case: 6 per point (start); 4 per point at c's
/// projection and 4 more per step (≤ 8n in all: the steps' c are distinct); per step (≤ n, one
/// per face) 9 (cross), 7 + 8 + 9 per point (dot, `farther`, re-cross), and `first_pair`'s 6 per
/// point and 9 per pair tried (≤ n − 1: the first point on the line pairs with a non-parallel
/// one); 8 per face.
#[allow(clippy::arithmetic_side_effects)]
const fn wrap_tally(n: u32) -> u32 {
    6 * n + 8 * n + n * (9 + 24 * n + 6 * n + 9 * (n - 1)) + 8 * n
}

/// `eps_margin` (6 per point, 10) and `widened` (4 per face, ≤ n): the bounded test's extra.
#[allow(clippy::arithmetic_side_effects)]
const fn eps_tally(n: u32) -> u32 {
    6 * n + 10 + 4 * n
}

// The pair search bounds the setup tally from `WRAP_FROM` points on; below, static only.
const _: () = assert!(
    wrap_tally(6) + eps_tally(6) <= pair_tally(6)
        && wrap_tally(12) + eps_tally(12) <= pair_tally(12)
        && wrap_tally(24) + eps_tally(24) <= pair_tally(24)
        && POINTS[0] < WRAP
        && POINTS[1] >= WRAP
);

/// 1 on the bounded static path (below [`WRAP_FROM`] points: `eps_margin`, the pair search,
/// `widened`), else 0.
const fn bnd(n: u32) -> u32 {
    (n < WRAP) as u32
}

/// Push `kind` with per-class counts `c` (static, motion, defocus, both): once for every class
/// if all are equal, else once per class set (both as defocus's count plus its own excess;
/// every count here grows with the class's points, so `c[3] ≥ c[2]`); zero counts are skipped.
fn per(inv: &mut Inventory, st: Stage, what: &'static str, kind: OpKind, c: [u32; 4]) {
    let [s, m, d, b] = c;
    if s == m && m == d && d == b {
        inv.op(st, what, kind, s, Classes::ALL);
        return;
    }
    let sets = [
        (s, Classes::STATIC),
        (m, Classes::MOTION_ONLY),
        (d, Classes::DEFOCUS),
        (b.saturating_sub(d), Classes::BOTH),
    ];
    for (n, cl) in sets.into_iter().filter(|(n, _)| *n > 0) {
        inv.op(st, what, kind, n, cl);
    }
}

/// A count as a function of the class's hull points (or kept faces).
type Count = fn(u32) -> u32;

/// The hull's operators at configuration `cfg` (`eps_margin`'s widths from its ε).
// Counts as above (< 2^20).
#[allow(clippy::arithmetic_side_effects)]
pub fn push(inv: &mut Inventory, cfg: &Config) {
    let add = |m: Mag| OpKind::Add { bits: m.bits() };
    let cmp = |m: Mag| OpKind::Cmp { bits: m.bits() };
    let mul = |a: Mag, b: Mag| OpKind::Mul {
        a: a.bits(),
        b: b.bits(),
    };
    // The cone (`faces.rs`): points |x ± c| ≤ 2^30 (w ≤ 2^29 shares the width), normals
    // `p × q`, `n·r`, face_of's `s = n2 + n1 − n0` and |a| = |2H·n0|.
    let xy = lim().times(2);
    let nrm = xy.mul(xy).times(2);
    let dot = nrm.mul(xy).times(3);
    let s = nrm.times(3);
    let a = nrm.mul(ext().times(2));
    // The per-tile form (`TileFace::in_range`): |a'|, |b'| < 2^81, the sums
    // `a'·xe + b'·ye + c'` < 2^126 (< 2^k: k + 1 signed bits, `Mag::pow2(k − 1)`'s); pixel
    // ends xe, ye ≤ MAX_VIEWPORT.
    let (ap, v) = (Mag::pow2(80), Mag::pow2(125));
    let (sum, sign, prod) = (add(v), cmp(v), mul(ap, ext()));
    // `eps_margin` (bounded static path): R = ⌈|x|/w⌉ ≤ 2^30, 1 ≤ w ≤ 2^29,
    // num = 128·E·(ε + R·ε_w) (< 2^63), ρ = ⌈num/(w_min − ε_w)⌉ ≤ num.
    let (ex, ew) = eps_max(cfg);
    let (ex, ew) = (Mag::int(u128::from(ex)), Mag::int(u128::from(ew)));
    let (w, r) = (lim(), xy);
    let eps = r.mul(ew).add(ex);
    let num = eps.mul(ext()).times(128);

    // ---- per triangle: `pair_faces`, `eps_margin`, `widened`, `HullTiles::of` ----
    // Narrower operations share a wider operator of their kind: the cross's differences
    // (≤ 2^61), `eps_margin`'s `+ ε`, `w_min − ε_w` and the greedy order's popcount (≤ 64) run
    // on face_of's adder (`s`); face_of's `n0·2H`, `n1·2W`, `W·H`, `s·256WH` (≤ 64 × 24) and
    // `eps_margin`'s `R·ε_w`, `(ε + R·ε_w)·E` (·128: a shift) on the dot's multiplier; the
    // cross's zero test (63 bits), `eps_margin`'s `w ≤ ε_w`, min w, max R and the greedy
    // `g > gain` on the dot's comparator; same_face's sums and tests (< 2^124), `widened`'s
    // `c + |a|·ρ + |b|·ρ` (< 2^124) and the fold `c − a`, `c − b` (< 2^125) on the pixel test's
    // adder and comparator. One compare per value tested: the dot's sign, each component of
    // `n = 0`, same_face's `c = 0` (3) and `d > 0`.
    let tri: [(&str, OpKind, Count); 9] = [
        ("cross `p × q`", mul(xy, xy), |n| 6 * pairs(n)),
        (
            "cross `−`, face_of `s`, eps, popcount",
            add(s.max(eps)),
            |n| 3 * pairs(n) + 2 * n + 3 * bnd(n) + picks(n),
        ),
        ("dot, face_of and eps products", mul(s.max(eps), xy), |n| {
            3 * n * pairs(n) + 4 * n + 4 * bnd(n)
        }),
        ("dot sum", add(dot), |n| 2 * n * pairs(n)),
        ("dot sign, `n = 0`, eps, `g > gain`", cmp(dot), |n| {
            (n + 3) * pairs(n) + 4 * n * bnd(n) + picks(n)
        }),
        ("same_face products", mul(nrm, nrm), |n| 9 * known(n)),
        ("same_face, widened, fold, pixel sums", sum, |n| {
            5 * known(n) + (2 + 2 * PIXELS + 2 * bnd(n)) * n
        }),
        ("same_face tests, pixel `< 0`", sign, |n| {
            4 * known(n) + PIXELS * n
        }),
        ("pixel test `a'·xe`, `b'·ye`", prod, |n| 2 * PIXELS * n),
    ];
    for (what, kind, f) in tri {
        per(inv, Stage::Triangle, what, kind, POINTS.map(f));
    }
    let div = |q: Mag| OpKind::Div {
        den: w.bits(),
        quot: q.mag_bits(),
    };
    let n = POINTS[0];
    let eps_ops: [(&str, OpKind, u32); 3] = [
        ("R = ⌈|x|/w⌉", div(r), 2 * n),
        ("ρ = ⌈num/(w_min − ε_w)⌉", div(num), 2),
        ("widened `|a|·ρ`, `|b|·ρ`", mul(a, num), 2 * n),
    ];
    for (what, kind, c) in eps_ops {
        per(inv, Stage::Triangle, what, kind, [c, 0, 0, 0]);
    }

    // ---- per tile (`HullTiles::culls`): every kept face (no early exit) ----
    let tile: [(&str, OpKind, Count); 3] = [
        ("face `a'·xe`, `b'·ye`", prod, |k| 2 * k),
        ("face `a'·xe + b'·ye + c'`", sum, |k| 2 * k),
        ("face `< 0`", sign, |k| k),
    ];
    // ---- per row (`HullTiles::span`): every kept face crossing the row ----
    // Per face: r (mul, add), two end cells (mul, add, sign), the quotient's q restoring steps
    // (a subtractor of `a'`'s width + 1 each; the code counts q ops, so they are listed as
    // steps, not as one `Div`), 2 column adds, the running span (max, min, empty). Per row:
    // the cells' ends and count (the code forms them per face), the width compare, the clamps
    // (2 each). Columns ≤ x1 + b ≤ 2·MAX_VIEWPORT.
    let (col, step) = (ext().times(2), add(ap.times(2)));
    let row: [(&str, OpKind, Count); 6] = [
        ("`b'·ye`, end cells `a'·xe`", prod, |k| 3 * k),
        ("`r = b'·ye + c'`, `a'·xe + r`", sum, |k| 3 * k),
        ("end cells `v < 0`, `v ≥ 0`", sign, |k| 2 * k),
        ("`⌊vf/a'⌋` restoring steps", step, |k| Q * k),
        ("span columns, cell ends, count", add(col), |k| 2 * k + 4),
        ("span max / min, `n < 2`, clamps", cmp(col), |k| 3 * k + 7),
    ];
    for (st, ops) in [(Stage::Tile, &tile[..]), (Stage::Row, &row[..])] {
        for &(what, kind, f) in ops {
            per(inv, st, what, kind, POINTS.map(|n| f(n.min(KEPT))));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::class::Class;

    /// The code's tally bounds (module docs) per class and stage are within the inventory.
    #[test]
    // Small counts, as in `push`.
    #[allow(clippy::arithmetic_side_effects)]
    fn inventory_covers_the_tally_bounds() {
        let mut inv = Inventory::default();
        push(&mut inv, &Config::of::<crate::DefaultPrecision>());
        assert!(inv.is_complete());
        for (c, n) in Class::ALL.into_iter().zip(POINTS) {
            let bounded = bnd(n) * eps_tally(n);
            let of = (9 + 5 * 64) * n + 2 * picks(n);
            let k = n.min(KEPT);
            let tally = [
                (Stage::Triangle, pair_tally(n) + bounded + of),
                (Stage::Tile, 5 * k),
                (Stage::Row, 3 + k * (13 + Q)),
            ];
            for (st, t) in tally {
                assert!(inv.count(st, c) >= u64::from(t), "{st:?} {c:?}: {t}");
            }
        }
    }
}
