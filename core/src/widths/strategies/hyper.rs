//! [`Hyper`](crate::bounds::hyper::Hyper)'s own operators (motion + defocus only; the inner
//! Laine 2011 box is [`super::laine`]'s): per triangle the corner values and each axis's per-tile
//! form (`corners`, `axis_form`), per tile the surface coefficients `α + β·xl + γ·(n − 1)`
//! (`HyperAxis::surfaces`), per sample `c0 + c1·σ + c2·t + c3·t·σ` for 2 axes × 2 surfaces.
//!
//! Widths come from the domain constants with [`Mag`], as the range comments of
//! `bounds/hyper.rs` state them (there with looser powers of two): raw |a|, |cs|, |w| ≤ 2^29,
//! E, ξ, x ≤ 2^11. Where a coefficient carries a constant power-of-two factor (c0 = 2^33·A0,
//! c1 = 2^16·(B0 − A0), c2 = 2^17·(A1 − A0)) its known-zero low bits are dropped at the
//! multiplier, as the width table's `opw` does.

use crate::config::registry::Config;
use crate::widths::mag::Mag;
use crate::widths::ops::{Classes, Inventory, OpKind, Stage};
use crate::widths::row::{eps_max, ext, lim, one};

/// Hyper's operators at configuration `cfg` (counts for both axes).
// Counts are products of small constants (axes 2, vertex ends 6, lens 2, footprint ends 2,
// lines 8, surfaces 2, coefficients 4).
#[allow(clippy::arithmetic_side_effects)]
pub fn push(inv: &mut Inventory, cfg: &Config) {
    let b = Classes::BOTH;
    let (tri, tile, smp) = (Stage::Triangle, Stage::Tile, Stage::Predicate);
    let e = ext();
    let (ex, ew) = eps_max(cfg);
    let eps = Mag::int(u128::from(ex) + u128::from(ew));
    // Corner value: |a ± cs + w| ≤ 3·2^29, |2wξ| ≤ 2^41: |f| ≤ 5·2^40; widened by (ε_x + ε_w)·E.
    let a3 = lim().times(3);
    let f = a3.mul(e).add(lim().times(2).mul(e));
    let v = f.add(eps.mul(e));
    // A line `K + S·x`: |S|, |T| ≤ 2v; |K| and its value at any x ∈ [0, E]: ≤ 2v·E.
    let s = v.times(2);
    let k = v.mul(e).times(2);
    let al = k.add(s); // α = K + T
    let add = |m: Mag| OpKind::Add { bits: m.bits() };
    let cmp = |m: Mag| OpKind::Cmp { bits: m.bits() };
    let mul = |m: Mag, o: Mag| OpKind::Mul {
        a: m.bits(),
        b: o.bits(),
    };

    // ---- per triangle: `corners`, 2 axes × 6 vertex ends × 2 lens × 2 footprint ends ----
    inv.op(tri, "`ε_x + ε_w`", add(eps), 2, b);
    inv.op(tri, "`pert = (ε_x + ε_w)·E`", mul(eps, e), 2, b);
    inv.op(tri, "`a + lens·cs`, `+ w`", add(a3), 96, b);
    inv.op(tri, "`(a ± cs + w)·E`", mul(a3, e), 48, b);
    inv.op(tri, "`w·ξ` (2·: a shift)", mul(lim(), e), 48, b);
    inv.op(tri, "`f = (a ± cs + w)·E − 2wξ`", add(f), 48, b);
    inv.op(tri, "`f − pert`, `f + pert`", add(v), 96, b);
    inv.op(tri, "corner min / max", cmp(v), 96, b);

    // ---- per triangle: `axis_form`, 2 axes × 8 lines (`line_affine`) ----
    inv.op(tri, "line `v0·ξb`, `v1·ξa`", mul(v, e), 32, b);
    inv.op(tri, "line `K = v0·ξb − v1·ξa`", add(k), 16, b);
    inv.op(tri, "line `S = v1 − v0`", add(s), 16, b);
    inv.op(tri, "line `T = min(S, 0)` / `max(S, 0)`", cmp(s), 16, b);
    inv.op(tri, "line `α = K + T`", add(al), 16, b);
    // 2 axes × 2 surfaces × (α, β, γ) × `surface`'s 5 adds (its 3 power-of-two products are
    // shifts); c3 = a0 − b0 − a1 + b1 is the widest.
    inv.op(
        tri,
        "`surface` `b0 − a0`, `a1 − a0`, c3",
        add(al.times(4)),
        60,
        b,
    );

    // ---- per tile: `surfaces`, 2 axes × 2 surfaces × 4 coefficients ----
    inv.op(tile, "`n = x1 − x0`, `n − 1`", add(e), 4, b);
    inv.op(tile, "`n = 1`", cmp(e), 2, b);
    // β and γ of c0 are 2^33·(S or T), of c1 / c2 2^16 / 2^17 × a difference of two, of c3 a
    // sum of four: multiplied by xl and n − 1 (≤ E) with the shifts dropped.
    for (what, m, n) in [
        ("c0 `β·xl`, `γ·(n − 1)`", s, 8),
        ("c1, c2 `β·xl`, `γ·(n − 1)`", s.times(2), 16),
        ("c3 `β·xl`, `γ·(n − 1)`", s.times(4), 8),
    ] {
        inv.op(tile, what, mul(m, e), n, b);
    }
    // |α + β·xl + γ·(n − 1)| ≤ (|α| + 2·|S|·E)·4 (c3's four terms).
    let coef = al.add(s.mul(e).times(2)).times(4);
    inv.op(tile, "`α + β·xl`, `+ γ·(n − 1)`", add(coef), 32, b);

    // ---- per sample: `predicate`, 2 axes (σ, t·σ) × 2 surfaces (`Surface::eval`) ----
    // t ∈ [0, 2^16], σ = u + 2^16 ∈ [0, 2^17], t·σ ≤ 2^33: 18, 19, 35 bits signed (as the width
    // table's T; one fewer as unsigned operands). A coefficient is the surface of the line values
    // at the tile's ends (≤ k): c1, c2 ≤ 2k and c3 ≤ 4k after the shifts.
    let t = one();
    let sigma = one().times(2);
    let ts = t.mul(sigma);
    let sum = k.times(9).mul(Mag::pow2(33)); // |c0| + |c1·σ| + |c2·t| + |c3·t·σ|
    inv.op(smp, "`σ = u + 2^16`", add(sigma), 2, b);
    inv.op(smp, "`t·σ`", mul(t, sigma), 2, b);
    inv.op(smp, "`c1·σ`", mul(k.times(2), sigma), 4, b);
    inv.op(smp, "`c2·t`", mul(k.times(2), t), 4, b);
    inv.op(smp, "`c3·(t·σ)`", mul(k.times(4), ts), 4, b);
    inv.op(smp, "`c0 + c1·σ + c2·t + c3·t·σ`", add(sum), 12, b);
    inv.op(smp, "`L ≤ 0`, `U ≥ 0`", cmp(sum), 4, b);
}
