//! Stage 3, planar — the static sample test of a [`crate::config::precision::Planar`] precision. Setup
//! rounds each **vertex** of a static triangle once to 15 bits; from then on everything is
//! exact: the edge normals of the rounded triangle fit i32 and the test per sample is three
//! 32 × 32 → 64 dot products — **exactly the exact test (`sample.rs`) on the rounded
//! triangle**, so it inherits its watertightness at shared edges and shared vertices.
//!
//! **Setup, per triangle** (raw clip units, `P_k = (x_k, y_k, w_k)` at t0, each |.| ≤ 2^29; no
//! projection, so camera-plane crossers and w = 0 vertices need no special case):
//!
//! | signal | value | rounding | format |
//! |---|---|---|---|
//! | `m_k` | `max(\|x_k\|, \|y_k\|, \|w_k\|)` | exact | u32, ≤ 2^29 |
//! | `s_k` | `max(0, bitlen(m_k) − 15)`, plus 1 if `rnd(m_k, s) > 2^15 − 1` | — | 0..=15 |
//! | `P'_k` | `rnd(P_k, s_k)` per component, `rnd(v, s) = sign(v)·⌊(\|v\| + 2^(s−1))/2^s⌋` (0 for s = 0: exact) | nearest, ties away from 0 | i16, \|.\| ≤ 2^15 − 1 |
//! | `z_k` | kept unrounded (the depth plane scales it by `2^(S − s_k)`, `S = max s_k`) | exact | i32, \|.\| ≤ 2^29 |
//! | `n_k` | `P'_{k+1} × P'_{k+2}` | exact | i32, \|.\| ≤ 2·(2^15 − 1)² < 2^31 |
//! | `σ` | `sign(det P')`, `det P' = P'_0 · n_0` | exact | i64 (\|det\| < 3·2^46); ±1, 0 culled |
//! | `ε_x, ε_y, ε_w` | `max_k \|c_k − 2^s_k·c'_k\|` per component c | exact | ≤ 2^14 |
//! | `G`, `f` | depth plane, below | floor | i32 ×3, exponent i32 |
//!
//! `s_k` and `P'_k` are functions of vertex k's own (x, y, w): a vertex shared by several
//! triangles has the same `P'` in each. `rnd(m_k) ≤ 2^15 − 1` bounds every component (rnd is
//! monotone in |v|). `s_k ≤ 15`: `m_k = 2^29` gives s = 15 and `rnd = 2^14`; below, bitlen ≤ 29,
//! s ≤ 14 before the increment, and after it `m_k < 2^(15+s)` gives `rnd(m_k, s + 1) ≤ 2^14`.
//! Coverage and ε need no division and no i128 (the depth plane needs `det·256·W·H` < 2^78 in
//! i128 and three divisions of a 62-bit by a 32-bit value, `floor_div_d32`: a 64-bit division
//! routine, or 32-bit divides in the static-specialised unit — the same quotients).
//!
//! **Per sample** (`d` = [`crate::sample::pos::direction`], each \|d_i\| ≤ 2^30 inside a viewport
//! ≤ 2048, i32): `E_k = n_k · d` (three SMULL/SMLAL, \|E\| < 3·2^61 < 2^63, i64, exact).
//! Covered iff for every k: `σ·E_k > 0`, or `E_k = 0` and the fill rule accepts:
//! `σ·a_k > 0`, or `a_k = 0` and `σ·b_k > 0` (`(a, b, c) = n_k`; comparators only).
//!
//! **What it decides: exactly the exact test on `P'`.** These are the exact test's edge values,
//! orientation and fill rule (`sample.rs`) for the triangle with vertices `P'_k`, bit for bit
//! (`tests/tests/model/planar.rs` compares with an independent 192-bit evaluation). The open cone of
//! a triangle is invariant under positive per-vertex factors: the triangle `2^s_k·P'_k` has
//! normals `2^(s_{k+1}+s_{k+2})·n_k` and determinant `2^(s_0+s_1+s_2)·det P'` — the same signs,
//! the same decision. A triangle with `det P' = 0` (a sliver that rounding makes degenerate)
//! covers nothing in the exact test on `P'` and is culled (`Cull::Degenerate`).
//!
//! **Watertight, vertices included.** A consistently wound mesh of static triangles becomes,
//! vertex by vertex, the mesh of the `P'` (shared vertices stay shared, since `P'` depends on
//! the vertex alone); the planar test on each triangle is the exact test on that mesh, which is
//! watertight at edges and vertices: an edge seen as `(i, j)` and `(j, i)` has exactly negated
//! normals, so off the plane exactly one side has `σ·E > 0` and on it the fill rule's key
//! `(a, b)` is negated too; at a shared vertex all the triangles' planes pass through the one
//! point `P'`. No exemption.
//!
//! **Agreement with the exact test.** `2^s_k·P'_k = P_k + δ_k` with `|δ_k,c| ≤ h_k =
//! 2^(s_k − 1)` (0 for s_k = 0; `h_k ≤ 2^-16·m_k·(1 + 2^-14)`): each vertex moves by at most
//! 2^-16 of its largest component. The rounded triangle's edge value (up to its positive factor)
//! is `(P_{k+1} + δ_{k+1}) × (P_{k+2} + δ_{k+2}) · d`, which differs from the exact `E_k =
//! n_k·d` by at most `B_k(d) = h_{k+1}·‖P_{k+2} × d‖₁ + h_{k+2}·‖P_{k+1} × d‖₁ +
//! 2·h_{k+1}·h_{k+2}·‖d‖₁`. If every `|E_k| > B_k` the signs agree edge by edge, so a sample
//! decided differently has `|E_k| ≤ B_k` for some k — it lies within `B_k / |∇E_k|` px of edge k
//! (`∇E_k = (2a_k·H, −2b_k·W)` per 1/256 px) — unless the rounding flips the triangle's
//! orientation (a crosser within the rounding of degenerate). Per primitive (the `fit` style):
//! a vertex with `w_k > h_k` projects within `ρ_k = h_k·(1 + max(|x_k|, |y_k|)/w_k)/(w_k − h_k)`
//! NDC of its exact projection — 2^-16·(1 + guard-band ratio) relative to the nearest w; far
//! off-screen vertices at small w (guard band ≈ 2^13) move up to ¼ NDC. The agreement test
//! checks `|E_k| ≤ B_k` exactly (integers) on every differing sample, guard-band cases included.
//!
//! **Conservative epsilon.** The bounds (`setup.rs` boxes and time span, `HullCull` faces, …)
//! are conservative for every triangle whose vertices lie within `ε_x` (x), `ε_y` (y), `ε_w`
//! (w) of `P_k` — up to a positive factor per vertex, since coverage is the cone (their proofs
//! only use that vertex box). Coverage here is the exact test on `2^s_k·P'_k`, whose distance
//! from `P_k` per component is `|c_k − 2^s_k·c'_k|` ≤ 2^(s_k−1) ≤ 2^14: setup stores the
//! maximum over the vertices, per component, as the setup's [`Eps`] — exact, no rounding, well
//! inside the bounds' range proofs (ε < 2^24). No triangle is culled for its epsilon. With
//! `ε_w > 0` the hull (`strategies/hull.rs`) keeps its faces only when every hull point has
//! `w > ε_w` (its projected-perturbation proof needs `w_min − ε_w > 0`): a static triangle with
//! a vertex within ε_w (≤ 0.25 clip units) of the camera plane, or crossing it, keeps no hull
//! faces (the inner strategy's bounds, which carry ε, still apply — conservative, less tight).
//!
//! **Depth** (hits only), same format, saturation and direction as the bounded test (I8F24,
//! floor, saturated to [`DEPTH_NEAR`, `DEPTH_FAR`]): the depth of the exact test on the
//! rounded triangle `Q_k = 2^s_k·P'_k` with the **unrounded** depths `z_k`. The hit of ray `d`
//! is `Σ_k α_k·Q_k = d` with `α_k = E_k(Q)/det Q = 2^(−s_k)·E_k/det P'` (`E_k(Q) =
//! 2^(s_{k+1}+s_{k+2})·E_k`, `det Q = 2^(s_0+s_1+s_2)·det P'`), so `z/w = Σ_k z_k·α_k / d_w =
//! Zv·d / D` with `S = max s_k`, `Zv = Σ_k z_k·2^(S − s_k)·n_k` (i128, \|.\| < 2^77) and `D =
//! det P'·2^S·256·W·H` (i128, < 2^93): affine in the sample, no division per sample. (Until
//! this version z was rounded with its vertex's shift, `z'_k = rnd(z_k, s_k)`, an extra error
//! of up to `Σ_k |α_k|·2^(s_k−1)/d_w` — up to ~0.06 in z/w on the tests' triangles.) Setup (D
//! oriented > 0 with Zv): `D32 = ⌊D / 2^rd⌋` with `rd = bitlen(D) − 32` (a left shift, exact,
//! when negative: D ≥ 256), so D32 ∈ [2^31, 2^32); `Z62_i = ⌊Zv_i / 2^rz⌋` with `rz =
//! bitlen(max|Zv_i|) − 62`, |Z62| < 2^62; `G_i = ⌊Z62_i / D32⌋` ∈ [−2^31, 2^31) (i32; three
//! 64-bit divisions per triangle), `f = rd − rz − 24` ∈ [−62, 98]. Per hit: `acc = Σ G_i·d_i`
//! (\|.\| < 3·2^61, i64 exact), depth = `⌊acc / 2^f⌋` (arithmetic shift; `f ≥ 63` gives 0 or
//! −1) or `acc·2^(−f)` saturated for `f < 0`, then saturated to the depth range (`Zv = 0`:
//! depth 0).
//!
//! *Error against the exact z/w of the rounded triangle* (raw LSBs of 2^-24): at most
//! `(3·2^30 + Σ|G_i·d_i|·2^-30)/2^f + 1` (the floors of G and of the depth, D32's truncation;
//! checked on every hit by `tests/tests/model/planar.rs`).
//!
//! *Error against the exact depth of the unrounded triangle* (what `Exact` computes, before its
//! own floor): on the triangle's plane z is linear in `X = (x, y, w)`, `z = ζ·X` with `P·ζ = z`
//! (rows `P_k`) exactly and `(P + Δ)·ζ' = z` rounded (`Δ` rows `δ_k`, `|δ_k,c| ≤ h_k`), so
//! `P·(ζ' − ζ) = −Δ·ζ'` and, with `P^(−1) = [n_0 n_1 n_2]/det P`, `(ζ' − ζ)·d = −Σ_k
//! λ_k·(δ_k·ζ')` where `λ_k = E_k/det P` are the exact triangle's ray barycentrics (`Σ λ_k·P_k =
//! d`). Hence `|Δ(z/w)| ≤ Σ_k |λ_k|·h_k·‖ζ'‖₁ / d_w` — the vertex move times the rounded
//! plane's depth slope; for a hit with every `w_k > 0` (`λ_k ≥ 0`, `Σ λ_k·w_k = d_w`) at most
//! `max_k h_k·‖ζ'‖₁ / min_k w_k`. In LSBs: that × 2^24, plus the error above and Exact's own
//! floor (1). Checked per hit, exactly as stated, by `tests/tests/model/planar.rs`
//! (`depth_within_the_derived_bound_of_exact`), which fails on the old z rounding. Depth never
//! influences coverage.

use crate::config::formats::{DEPTH_FAR, DEPTH_NEAR, SUBPIXEL_BITS};
use crate::coverage::{on, Bin, NoProbe, Probe};
use crate::input::Viewport;
use crate::sample::pos::{Hit, ScreenPos};
use crate::setup::Setup;
use crate::stats::Ops;

/// The planar test's intermediates of one sample (for tests).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlanarEval {
    /// edge values `E_k = n_k · d` (exact)
    pub e: [i64; 3],
    /// coverage and depth
    pub hit: Option<Hit>,
}

/// The sample direction as i32: inside the viewport (checked by the caller) every component is
/// ≤ 2^30 in magnitude (`sample::direction`).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_wrap)]
fn direction32(vp: Viewport, xs: i32, ys: i32) -> [i32; 3] {
    let (w, h) = (i32::from(vp.w), i32::from(vp.h));
    let one = 1i32 << SUBPIXEL_BITS;
    // |2xs − 256W| ≤ 256W ≤ 2^19, ×H ≤ 2^11: ≤ 2^30; 256·W·H ≤ 2^30.
    [(2 * xs - one * w) * h, (one * h - 2 * ys) * w, one * w * h]
}

/// Fill rule on `E_k = 0` (module docs): `σ·a > 0`, or `a = 0` and `σ·b > 0`.
#[inline]
fn fill(n: &[i32; 3], sigma: i32) -> bool {
    let [a, b, _] = *n;
    if sigma > 0 {
        a > 0 || (a == 0 && b > 0)
    } else {
        a < 0 || (a == 0 && b < 0)
    }
}

/// The coverage bin of a [`fill`] decision `inside` with the normal `n`.
#[inline]
fn tie_bin(n: &[i32; 3], inside: bool) -> Bin {
    let [a, b, _] = *n;
    match (a != 0, b != 0, inside) {
        (true, _, true) => Bin::PsTieAInside,
        (true, _, false) => Bin::PsTieAOutside,
        (false, true, true) => Bin::PsTieBInside,
        (false, true, false) => Bin::PsTieBOutside,
        (false, false, _) => Bin::PsTieNone,
    }
}

/// Depth of a hit from the plane `(G, f)` (module docs).
#[inline(never)]
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn depth(g: &[i32; 3], f: i32, d: &[i32; 3]) -> i32 {
    depth_in(g, f, d, &mut NoProbe)
}

/// [`depth`], its paths reported to `pr` (out of line: [`eval_probed`] calls [`depth`] itself,
/// non-generic, where nobody reads the probe).
#[inline(never)]
fn depth_p(g: &[i32; 3], f: i32, d: &[i32; 3], pr: &mut impl Probe) -> i32 {
    depth_in(g, f, d, pr)
}

/// The body of [`depth`] and [`depth_p`].
#[inline(always)]
#[allow(clippy::arithmetic_side_effects)]
fn depth_in(g: &[i32; 3], f: i32, d: &[i32; 3], pr: &mut impl Probe) -> i32 {
    // |G| ≤ 2^31, |d| ≤ 2^30: each product ≤ 2^61, the sum < 2^63.
    let acc: i64 = g
        .iter()
        .zip(d.iter())
        .map(|(&a, &b)| i64::from(a) * i64::from(b))
        .sum();
    let q = if f >= 0 {
        pr.pick(f >= 63, Bin::PsDepthShiftCap, Bin::PsDepthShift);
        // An arithmetic shift by ≤ 63: the floor (0 or −1 past the magnitude).
        acc >> f.min(63)
    } else if acc == 0 {
        pr.hit(Bin::PsDepthZero);
        0
    } else {
        let k = f.unsigned_abs();
        match 2i64.checked_pow(k).and_then(|p| acc.checked_mul(p)) {
            Some(v) => {
                pr.hit(Bin::PsDepthScale);
                v
            }
            None => {
                pr.hit(Bin::PsDepthScaleSat);
                if acc < 0 {
                    i64::MIN
                } else {
                    i64::MAX
                }
            }
        }
    };
    pr.hit(if q < i64::from(DEPTH_NEAR) {
        Bin::PsDepthNear
    } else if q > i64::from(DEPTH_FAR) {
        Bin::PsDepthFar
    } else {
        Bin::PsDepthIn
    });
    // Clamped to [DEPTH_NEAR, DEPTH_FAR]: the conversion is exact.
    i32::try_from(q.clamp(i64::from(DEPTH_NEAR), i64::from(DEPTH_FAR))).unwrap_or(DEPTH_FAR)
}

/// The planar test with its intermediates: `None` for a position outside the viewport or a
/// setup without planar data (not a static triangle of a `Planar` precision).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_wrap)]
pub fn eval(setup: &Setup, pos: ScreenPos, ops: &mut Ops) -> Option<PlanarEval> {
    eval_probed(setup, pos, ops, &mut NoProbe)
}

/// [`eval`], every decision path it takes reported to `pr` (`crate::coverage`).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_wrap)]
pub fn eval_probed(
    setup: &Setup,
    pos: ScreenPos,
    ops: &mut Ops,
    pr: &mut impl Probe,
) -> Option<PlanarEval> {
    let crate::setup::Stored::Planar(pl) = &setup.edges else {
        return None;
    };
    let vp = setup.viewport;
    let (sw, sh) = (
        (u32::from(vp.w)) << SUBPIXEL_BITS,
        (u32::from(vp.h)) << SUBPIXEL_BITS,
    );
    if pos.xs >= sw || pos.ys >= sh {
        return None;
    }
    // xs < 2^19, ys < 2^19: exact in i32.
    let d = direction32(vp, pos.xs as i32, pos.ys as i32);
    // |n| < 2^31, |d| ≤ 2^30: three products < 2^61, |E| < 3·2^61 < 2^63 (i64).
    let e = pl.n.map(|nk| {
        nk.iter()
            .zip(d.iter())
            .map(|(&a, &b)| i64::from(a) * i64::from(b))
            .sum::<i64>()
    });
    let [e0, e1, e2] = e;
    for ek in e {
        pr.sign(ek, [Bin::PsEdgeNeg, Bin::PsEdgeZero, Bin::PsEdgePos]);
    }
    let pos_side = pl.sigma > 0;
    pr.pick(pos_side, Bin::PsOrientPos, Bin::PsOrientNeg);
    let covered = if e0 != 0 && e1 != 0 && e2 != 0 {
        // Every E has the orientation's strict sign.
        if pos_side {
            e0 > 0 && e1 > 0 && e2 > 0
        } else {
            e0 < 0 && e1 < 0 && e2 < 0
        }
    } else {
        e.iter().zip(pl.n.iter()).all(|(&ek, nk)| {
            if ek == 0 {
                let inside = fill(nk, pl.sigma);
                if on(pr) {
                    pr.hit(tie_bin(nk, inside));
                }
                inside
            } else {
                (ek > 0) == pos_side
            }
        })
    };
    ops.add_sample(9 + 2 + 3);
    pr.pick(covered, Bin::PsCovered, Bin::PsMissed);
    let hit = covered.then(|| {
        ops.add_sample(4);
        Hit {
            depth: if on(pr) {
                depth_p(&pl.g, pl.f, &d, pr)
            } else {
                depth(&pl.g, pl.f, &d)
            },
        }
    });
    Some(PlanarEval { e, hit })
}

/// The planar test: the depth on a hit ([`eval`]).
#[inline]
pub fn test(setup: &Setup, pos: ScreenPos, ops: &mut Ops) -> Option<Hit> {
    eval(setup, pos, ops)?.hit
}
