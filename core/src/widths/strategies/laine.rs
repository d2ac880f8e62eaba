//! [`Laine2011`](crate::bounds::laine::Laine2011)'s operators: the lens bounds (defocused
//! classes) and the dual-space bounding lines (moving classes), per triangle and per tile. Its
//! widths are the width table's `bounds/tri` and `bounds/tile` rows ([`crate::widths::stages`]).

use crate::config::registry::Config;
use crate::widths::ops::{Classes, Inventory, OpKind, Stage};
use crate::widths::row::{ext, lim, Table};
use crate::widths::stages::table;

/// Bits of the row of `stage` whose signal starts with `prefix` (0 if absent: a test checks
/// that every row read here exists).
pub(crate) fn row_bits(t: &Table, stage: &str, prefix: &str) -> u32 {
    t.find(stage, prefix).map_or(0, |r| r.bits())
}

/// Laine 2011's operators at configuration `cfg`.
// Counts are products of small constants (axes 2, sides 2, vertex ends 6, footprint ends 2).
#[allow(clippy::arithmetic_side_effects)]
pub fn push(inv: &mut Inventory, cfg: &Config) {
    let t = table(cfg);
    let e = ext().bits();
    let slope = row_bits(&t, "bounds/tri", "lens slope");
    let recip = row_bits(&t, "bounds/tri", "reciprocal");
    let delta = row_bits(&t, "bounds/tri", "dual δ");
    let line = row_bits(&t, "bounds/tile", "bounding line");
    let (ex, ew) = crate::widths::row::eps_max(cfg);
    let cs = lim()
        .add(crate::widths::mag::Mag::int(u128::from(ex)))
        .add(crate::widths::mag::Mag::int(u128::from(ew)))
        .bits();
    let aw = lim().add(lim()).bits();
    let (tri, tile) = (Stage::Triangle, Stage::Tile);
    let (d, m) = (Classes::DEFOCUS, Classes::MOTION);

    // ---- per triangle: lens sides (2 axes × 2 sides), `lens_axis` + `RecipConstraint::new` ----
    inv.op(
        tri,
        "lens slope `m1 − m0`, `h0 − h1`",
        OpKind::Add { bits: slope },
        4,
        d,
    );
    inv.op(
        tri,
        "reciprocal `q0 = (2^64 − 1) / |d|`",
        OpKind::Div {
            den: slope,
            quot: 64,
        },
        4,
        d,
    );
    inv.op(
        tri,
        "reciprocal remainder `q0·|d|`",
        OpKind::Mul { a: 64, b: slope },
        4,
        d,
    );
    inv.op(
        tri,
        "remainder `2^64 − q0·|d|`",
        OpKind::Add { bits: 65 },
        4,
        d,
    );
    inv.op(
        tri,
        "reciprocal fraction `r0·2^16 / |d|`",
        OpKind::Div {
            den: slope,
            quot: 16,
        },
        4,
        d,
    );
    inv.op(
        tri,
        "reciprocal `2^16·q0 + f (+ 1)`",
        OpKind::Add { bits: recip },
        4,
        d,
    );

    // ---- per triangle: dual-space values (2 axes × 6 vertex ends [× 2 footprint ends]) ----
    inv.op(tri, "`a + w`", OpKind::Add { bits: aw }, 12, m);
    inv.op(tri, "`(a + w)·E`", OpKind::Mul { a: aw, b: e }, 12, m);
    inv.op(tri, "bias `|c| + ε`", OpKind::Add { bits: cs }, 12, m);
    inv.op(
        tri,
        "bias `(|c| + ε)·E`",
        OpKind::Mul { a: cs, b: e },
        12,
        m,
    );
    inv.op(
        tri,
        "`w·ξ` (2·: a shift)",
        OpKind::Mul { a: aw, b: e },
        24,
        m,
    );
    inv.op(
        tri,
        "δ = `(a + w)·E − 2wξ`, `δ ∓ bias`",
        OpKind::Add { bits: delta },
        72,
        m,
    );
    inv.op(tri, "δmin / δmax", OpKind::Cmp { bits: delta }, 48, m);

    // ---- per tile: lens solves (2 axes × 2 sides), `lens_s` ----
    inv.op(
        tile,
        "lens numerator `x·2^BND − base`",
        OpKind::Add { bits: slope },
        4,
        d,
    );
    inv.op(
        tile,
        "lens cases `n < 0`, `n ≥ d`",
        OpKind::Cmp { bits: slope },
        8,
        d,
    );
    if let Some(r) = t.find("bounds/tile", "lens solve") {
        for mu in r.mul.iter().flatten() {
            inv.op(
                tile,
                "lens solve `n·r`",
                OpKind::Mul { a: mu.a, b: mu.b },
                mu.count,
                d,
            );
        }
    }

    // ---- per tile: bounding lines (2 axes × 4 lines) and t solves (2 axes × 2), `dual_t` ----
    let delta2 = delta.saturating_add(1);
    inv.op(
        tile,
        "line slope `v1 − v0`",
        OpKind::Add { bits: delta2 },
        8,
        m,
    );
    inv.op(
        tile,
        "slope sign (tile end pick)",
        OpKind::Cmp { bits: delta2 },
        8,
        m,
    );
    inv.op(tile, "`x − ξa`", OpKind::Add { bits: e }, 8, m);
    if let Some(r) = t.find("bounds/tile", "bounding line") {
        for mu in r.mul.iter().flatten() {
            inv.op(
                tile,
                "line `v0·D`, `(v1 − v0)·(x − ξa)`",
                OpKind::Mul { a: mu.a, b: mu.b },
                mu.count,
                m,
            );
        }
    }
    inv.op(tile, "line value sum", OpKind::Add { bits: line }, 8, m);
    let num = line.saturating_add(1);
    inv.op(
        tile,
        "t solve `lo1 − lo0`, `hi0 − hi1`",
        OpKind::Add { bits: num },
        4,
        m,
    );
    inv.op(
        tile,
        "t solve cases `n < 0`, `n ≥ d`",
        OpKind::Cmp { bits: num },
        8,
        m,
    );
    inv.op(
        tile,
        "t solve `n·2^16 / d`",
        OpKind::Div { den: num, quot: 16 },
        4,
        m,
    );
}
