//! Stage 3, planar — the static sample test of a [`crate::formats::Planar`] precision: a static
//! triangle's three edges are fixed planes through the eye, `E_k(d) = n_k·d` with
//! `n_k = P_{k+1} × P_{k+2}` (`StaticEdges`, exact i128), and the sample direction `d` is affine
//! in the sample position; so setup rounds each normal once to i32 and the test per sample is
//! three 32 × 32 → 64 dot products.
//!
//! **Setup, per triangle** (raw clip units, `P_k = (x_k, y_k, w_k)` at t0; no projection, so
//! camera-plane crossers need no special case):
//!
//! | signal | value | rounding | format |
//! |---|---|---|---|
//! | `n_k` | `P_{k+1} × P_{k+2}` | exact | i128, \|.\| < 2^59 (2·16 fraction bits) |
//! | `sh_k` | `max(0, bitlen(max_i \|n_k,i\|) − 30)` | — | 0..=29 |
//! | `n'_k` | `rnd(n_k / 2^sh_k)` per component, `rnd(x) = sign(x)·⌊(\|x\| + 2^(sh−1))/2^sh⌋` | nearest, ties away from 0, symmetric | i32, \|.\| ≤ 2^30 |
//! | `σ` | `sign(det(P_0, P_1, P_2))` | exact (i128) | ±1 (0 culled) |
//! | `P''_k` | `n'_{k+1} × n'_{k+2}` | exact | i64, \|.\| ≤ 2^61 |
//! | `det(n')` | `n'_0 · P''_0` | exact | i128, \|.\| < 2^93 (0 culled) |
//! | `G`, `f` | depth plane, below | floor | i32 ×3, exponent i32 |
//!
//! **Per sample** (`d` = [`crate::sample::direction`], each \|d_i\| ≤ 2^30 inside a viewport
//! ≤ 2048, i32): `E'_k = n'_k · d` (three SMULL/SMLAL, \|E'\| ≤ 3·2^60 < 2^62, i64, exact).
//! Covered iff for every k: `σ·E'_k > 0`, or `E'_k = 0` and the fill rule accepts:
//! `σ·a'_k > 0`, or `a'_k = 0` and `σ·b'_k > 0` (`(a', b', c') = n'_k`; comparators only).
//!
//! **What it decides: exactly the exact test on a triangle `Q`.** With `Q_k = τ·P''_k`,
//! `τ = σ·sign(det n')`: the identity `(a×b)×(a×c) = (a·(b×c))·a` gives
//! `Q_{k+1} × Q_{k+2} = det(n')·n'_k` and `det(Q) = τ·det(n')²`, so the exact test of
//! `sample.rs` on `Q` (edge values `det(n')·E'_k`, orientation `sign(det Q) = τ`, fill rule on
//! `det(n')·(a'_k, b'_k)`) is covered iff `σ·E'_k > 0` for all k or on ties `σ·a'_k > 0`, … —
//! the test above, bit for bit (`tests/tests/planar.rs` compares with a 192-bit exact test on
//! `Q`). A triangle with `det(P) = 0` or `det(n') = 0` is culled (`Cull::Degenerate`).
//!
//! **Watertight.** `n'_k` is a function of `n_k` alone (its own shift, a rounding symmetric
//! under negation), and an edge seen as `(i, j)` by one triangle and `(j, i)` by its neighbour
//! has exactly negated `n`, hence exactly negated `n'`: the two rounded planes are one plane.
//! With the same orientation σ (a consistently wound mesh), off the plane exactly one of the
//! two has `σ·E' > 0`; on it (`E' = 0`) the fill rule's key `(a', b')` is negated too, so
//! exactly one accepts (`(a', b') = (0, 0)` means the plane is `d_w = 0`, which no sample is
//! on). **At a shared vertex** the rounded planes of the triangles around it need not meet in
//! one point (each triangle's corner is `P''`, the meet of its own two rounded planes): a sample
//! within the edge distance below of two of those planes can be covered twice or not at all.
//! This is the one place the planar test is not watertight; `tests/tests/planar.rs` measures it.
//!
//! **Agreement with the exact test.** Per component `|n'_k − n_k/2^sh_k| ≤ 1/2`, so
//! `|E'_k − E_k/2^sh_k| ≤ (|d_x| + |d_y| + |d_w|)/2`: a sample decided differently from the
//! exact test has `|E_k| ≤ 2^(sh_k − 1)·‖d‖₁` for some k — within
//! `2^(sh_k−1)·‖d‖₁ / (512·‖(a_k·H, b_k·W)‖)` px of edge k (the gradient of `E_k` is
//! `(2a_k·H, −2b_k·W)` per 1/256 px). Checked exactly (integers) by the agreement test.
//!
//! **Conservative epsilon.** The bounds (`setup.rs` boxes and time span, `HullCull` faces, …)
//! are conservative for every triangle whose vertices lie, up to a positive factor each, within
//! `ε_x` (x), `ε_y` (y), `ε_w` (w) of `P_k` (their proofs only use that vertex box; the exact
//! test's coverage is the open cone of the vertices, invariant under positive per-vertex
//! factors). Coverage here is the exact test on `Q`, so setup stores, rounded up, a bound on
//! `min_μ |μ·Q_k − P_k|` for a chosen `μ > 0` per vertex: if `w_k > 0` and `Q_w > 0`,
//! `μ = w_k/Q_w` (then `ε_w` = 0 and `ε_x ≥ ⌈|Q_x·w_k − x_k·Q_w| / Q_w⌉`, likewise y); else
//! `μ = 2^(sh_{k+1}+sh_{k+2})/|det P|` (`n_{k+1} × n_{k+2} = det(P)·P_k`, so this is `P_k` up to
//! the roundings), every component `⌈|Q_c·2^s − |det P|·P_c| / |det P|⌉`. The maximum over the
//! vertices is the setup's [`Eps`]. Any `μ > 0` gives a valid bound, so each vertex's `μ_k·Q_k`
//! lies in the box and every covered sample (a ray in the open cone of `Q`) is inside every
//! bound. A bound above [`PLANAR_EPS_LIMIT`] (the bounds' range proofs take ε < 2^24), or an
//! overflow of the checked i128 arithmetic, culls the triangle (`Cull::Degenerate`): only a
//! sliver whose rounded planes meet more than 256 clip units from its vertices, counted
//! separately by the tests.
//!
//! **Depth** (hits only), same format, saturation and direction as the bounded test (I8F24,
//! floor, saturated to [`DEPTH_NEAR`, `DEPTH_FAR`]): the hit of ray `d` on the triangle has
//! `w = d_w` and `z = Σ_k z_k·E_k/det(P)`, so `z/w = Zv·d / (det(P)·d_w)` with the exact plane
//! `Zv = Σ_k z_k·n_k` (i128, < 2^90) and `D = det(P)·d_w` (< 2^120): affine in the sample, no
//! division per sample. Setup: `Zv` and `D` are floored to ≤ 62 bits (`Zv = Zv''·2^rz`,
//! `D = D''·2^rd`, D'' oriented > 0), `G_i = ⌊Zv''_i·2^e / D''⌋` with `e = 30 + bitlen(D'') −
//! bitlen(max|Zv''|)` (so |G_i| < 2^31, i32), `f = e − 24 − rz + rd`. Per hit:
//! `acc = Σ G_i·d_i` (\|.\| < 3·2^61, i64 exact), depth = `⌊acc / 2^f⌋` (arithmetic shift,
//! `f ≥ 63` gives 0 or −1) or `acc·2^(−f)` saturated for `f < 0`, then saturated to the depth
//! range. Depth never influences coverage.

use crate::bounded::Eps;
use crate::formats::{DEPTH_FAR, DEPTH_FRAC, DEPTH_NEAR, SUBPIXEL_BITS};
use crate::input::{Triangle, Viewport, W, X, Y, Z};
use crate::sample::{Hit, ScreenPos};
use crate::setup::{det3, Setup};
use crate::stats::Ops;

/// Largest conservative epsilon component the planar setup stores (raw clip units): the
/// bounds' range proofs take ε_x + ε_w < 2^25. A triangle needing more is culled (module docs).
pub const PLANAR_EPS_LIMIT: i32 = (1 << 24) - 1;

/// Magnitude limit of the rounded normals: |n'| ≤ 2^30 (bit length of |n| above 30 is shifted).
const NORMAL_BITS: u32 = 30;

/// The planar test's per-triangle data. Built only by the planar setup from a checked
/// [`Triangle`], so every field is in the range the module table states.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlanarEdges {
    pub(crate) n: [[i32; 3]; 3],
    pub(crate) sh: [u32; 3],
    pub(crate) sigma: i32,
    pub(crate) g: [i32; 3],
    pub(crate) f: i32,
}

impl PlanarEdges {
    /// The rounded edge normals `n'_k = (a', b', c')`, |.| ≤ 2^30.
    pub fn n(&self) -> [[i32; 3]; 3] {
        self.n
    }
    /// The per-edge shifts `sh_k` (0..=29): `n'_k ≈ n_k / 2^sh_k`.
    pub fn shifts(&self) -> [u32; 3] {
        self.sh
    }
    /// The orientation σ = sign(det P): −1 or 1.
    pub fn sigma(&self) -> i32 {
        self.sigma
    }
    /// The depth plane `G` and its exponent `f` (module docs).
    pub fn depth_plane(&self) -> ([i32; 3], i32) {
        (self.g, self.f)
    }
}

/// Bit length of a `u128` (0 for 0).
fn bitlen(x: u128) -> u32 {
    u128::BITS.saturating_sub(x.leading_zeros())
}

/// `rnd(x / 2^sh)`: nearest, ties away from zero, `rnd(−x) = −rnd(x)`. For |x| < 2^(30 + sh)
/// the result is ≤ 2^30 (i32); anything else (not produced by a checked triangle) saturates.
fn rnd_sym(x: i128, sh: u32) -> i32 {
    let m = x.unsigned_abs();
    let half = if sh == 0 {
        0
    } else {
        1u128.checked_shl(sh.saturating_sub(1)).unwrap_or(0)
    };
    let q = m.saturating_add(half).checked_shr(sh).unwrap_or(0);
    let q = i32::try_from(q).unwrap_or(i32::MAX);
    if x < 0 {
        q.saturating_neg()
    } else {
        q
    }
}

/// Round one exact normal: `(n', sh)` (module table).
fn round_normal(n: &[i128; 3]) -> ([i32; 3], u32) {
    let m = n.iter().map(|c| c.unsigned_abs()).max().unwrap_or(0);
    let sh = bitlen(m).saturating_sub(NORMAL_BITS);
    (n.map(|c| rnd_sym(c, sh)), sh)
}

/// Cross product of two rounded normals, exact: |n'| ≤ 2^30, products ≤ 2^60, |.| ≤ 2^61.
#[allow(clippy::arithmetic_side_effects)] // ranges in the doc comment
fn cross32(a: &[i32; 3], b: &[i32; 3]) -> [i64; 3] {
    let [a0, a1, a2] = a.map(i64::from);
    let [b0, b1, b2] = b.map(i64::from);
    [a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0]
}

/// `⌈|num| / den⌉` for `den > 0`, as an epsilon component; `None` above [`PLANAR_EPS_LIMIT`].
fn eps_of(num: i128, den: i128) -> Option<i32> {
    let q = crate::formats::ceil_div(num.checked_abs()?, den)?;
    i32::try_from(q).ok().filter(|&e| e <= PLANAR_EPS_LIMIT)
}

/// The epsilon of one vertex `p` = (x, y, w) for the corner `q` of `Q` (module docs), or
/// `None` when it exceeds the limit or the checked arithmetic overflows.
fn vertex_eps(p: [i128; 3], q: [i128; 3], s: u32, adet: i128) -> Option<[i32; 3]> {
    let [x, y, w] = p;
    let [qx, qy, qw] = q;
    if w > 0 && qw > 0 {
        // μ = w/Q_w: |Q·w| < 2^61·2^29, |x·Q_w| < 2^29·2^61, difference < 2^91.
        let ex = eps_of(qx.checked_mul(w)?.checked_sub(x.checked_mul(qw)?)?, qw)?;
        let ey = eps_of(qy.checked_mul(w)?.checked_sub(y.checked_mul(qw)?)?, qw)?;
        return Some([ex, ey, 0]);
    }
    // μ = 2^s/|det P|: |Q·2^s| < 2^61·2^58, |det|·|P| < 2^90·2^29; checked regardless.
    let scale = 2i128.checked_pow(s)?;
    let c = |qc: i128, pc: i128| {
        eps_of(
            qc.checked_mul(scale)?.checked_sub(adet.checked_mul(pc)?)?,
            adet,
        )
    };
    Some([c(qx, x)?, c(qy, y)?, c(qw, w)?])
}

/// The depth plane `(G, f)` from the exact `Zv` and `D ≠ 0` (module docs).
#[allow(clippy::arithmetic_side_effects)] // ranges at each line
fn depth_plane(zv: [i128; 3], d: i128) -> Option<([i32; 3], i32)> {
    let bz = bitlen(zv.iter().map(|c| c.unsigned_abs()).max().unwrap_or(0));
    let bd = bitlen(d.unsigned_abs());
    // rz, rd ≤ 127 − 62: arithmetic right shifts, floor; results < 2^62 in magnitude.
    let (rz, rd) = (bz.saturating_sub(62), bd.saturating_sub(62));
    let zv = zv.map(|c| c >> rz);
    let d = d >> rd;
    let (zv, d) = if d < 0 {
        (zv.map(|c| -c), -d) // |.| < 2^62: exact negations
    } else {
        (zv, d)
    };
    if d <= 0 {
        return None;
    }
    let (bz, bd) = (
        bitlen(zv.iter().map(|c| c.unsigned_abs()).max().unwrap_or(0)),
        bitlen(d.unsigned_abs()),
    );
    // e ∈ [30 + 1 − 62, 30 + 62]: bz, bd ≤ 62, bd ≥ 1.
    let e = 30 + i64::from(bd) - i64::from(bz);
    let mut g = [0i32; 3];
    for (gi, &z) in g.iter_mut().zip(zv.iter()) {
        // |Zv''| < 2^bz, D'' ≥ 2^(bd−1): |Zv''·2^e / D''| < 2^(bz + e − bd + 1) = 2^31, and the
        // floor stays ≥ −2^31: i32. Numerator < 2^(bz+e) ≤ 2^93 (e ≥ 0) or divisor
        // D''·2^(−e) < 2^(bd−e) ≤ 2^93 (e < 0): exact in i128.
        let q = if e >= 0 {
            crate::formats::floor_div(
                z.checked_mul(2i128.checked_pow(u32::try_from(e).ok()?)?)?,
                d,
            )?
        } else {
            let k = u32::try_from(-e).ok()?;
            crate::formats::floor_div(z, d.checked_mul(2i128.checked_pow(k)?)?)?
        };
        *gi = i32::try_from(q).ok()?;
    }
    // |e − 24 − rz + rd| < 2^8: fits i32.
    let f = e - i64::from(DEPTH_FRAC) - i64::from(rz) + i64::from(rd);
    Some((g, i32::try_from(f).ok()?))
}

/// Planar setup of a static triangle (its t0 vertices) in `vp`: the rounded planes and the
/// conservative epsilon, or `None` (culled as degenerate: det(P) = 0, det(n') = 0, or an
/// epsilon above [`PLANAR_EPS_LIMIT`]).
#[allow(clippy::arithmetic_side_effects)] // ranges at each line
pub(crate) fn planar_setup(
    tri: &Triangle,
    vp: Viewport,
    ops: &mut Ops,
) -> Option<(PlanarEdges, Eps)> {
    let [v0, _] = &tri.v;
    // |P| ≤ 2^29 (checked triangle): det3 < 2^90, each normal component < 2^59.
    let p = v0.map(|q| [q[X], q[Y], q[W]].map(i128::from));
    let det = det3(&p);
    ops.add_setup(30);
    if det == 0 {
        return None;
    }
    let [p0, p1, p2] = p;
    let exact = [(p1, p2), (p2, p0), (p0, p1)].map(|(a, b)| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    });
    let r = exact.map(|n| round_normal(&n));
    let n = r.map(|(n, _)| n);
    let sh = r.map(|(_, s)| s);
    let [n0, n1, n2] = n;
    let pp = [cross32(&n1, &n2), cross32(&n2, &n0), cross32(&n0, &n1)];
    // |n'_0| ≤ 2^30, |P''_0| ≤ 2^61: each product ≤ 2^91, the sum < 2^93.
    let detn: i128 = n0
        .iter()
        .zip(pp[0].iter())
        .map(|(&a, &b)| i128::from(a) * i128::from(b))
        .sum();
    ops.add_setup(45);
    if detn == 0 {
        return None;
    }
    let sigma: i32 = if det > 0 { 1 } else { -1 };
    let tau = if detn > 0 { sigma } else { -sigma };
    let adet = det.abs(); // < 2^90
    let mut eps = [0i32; 3];
    let [s0, s1, s2] = sh;
    // sh ≤ 29 each: s ≤ 58.
    let shifts = [s1 + s2, s2 + s0, s0 + s1];
    for ((pk, qk), &s) in p.iter().zip(pp.iter()).zip(shifts.iter()) {
        let q = qk.map(|c| i128::from(c) * i128::from(tau)); // |.| ≤ 2^61
        let e = vertex_eps(*pk, q, s, adet)?;
        for (m, v) in eps.iter_mut().zip(e) {
            *m = (*m).max(v);
        }
        ops.add_setup(12);
    }
    // Depth plane: Zv = Σ z_k·n_k (|z| ≤ 2^29, |n| < 2^59: < 3·2^88), D = det·256·W·H
    // (< 2^90·2^30).
    let mut zv = [0i128; 3];
    for (nk, q) in exact.iter().zip(v0.iter()) {
        for (o, c) in zv.iter_mut().zip(nk.iter()) {
            *o += c * i128::from(q[Z]);
        }
    }
    let dw = (1i128 << SUBPIXEL_BITS) * i128::from(vp.w) * i128::from(vp.h);
    let (g, f) = depth_plane(zv, det * dw)?;
    ops.add_setup(20);
    Some((
        PlanarEdges { n, sh, sigma, g, f },
        Eps {
            x: [eps[0], eps[1]],
            w: eps[2],
        },
    ))
}

/// The planar test's intermediates of one sample (for tests).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlanarEval {
    /// edge values `E'_k = n'_k · d` (exact)
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

/// Fill rule on `E'_k = 0` (module docs): `σ·a' > 0`, or `a' = 0` and `σ·b' > 0`.
#[inline]
fn fill(n: &[i32; 3], sigma: i32) -> bool {
    let [a, b, _] = *n;
    if sigma > 0 {
        a > 0 || (a == 0 && b > 0)
    } else {
        a < 0 || (a == 0 && b < 0)
    }
}

/// Depth of a hit from the plane `(G, f)` (module docs).
#[inline(never)]
#[allow(clippy::arithmetic_side_effects)]
fn depth(g: &[i32; 3], f: i32, d: &[i32; 3]) -> i32 {
    // |G| ≤ 2^31, |d| ≤ 2^30: each product ≤ 2^61, the sum < 2^63.
    let acc: i64 = g
        .iter()
        .zip(d.iter())
        .map(|(&a, &b)| i64::from(a) * i64::from(b))
        .sum();
    let q = if f >= 0 {
        // An arithmetic shift by ≤ 63: the floor (0 or −1 past the magnitude).
        acc >> f.min(63)
    } else {
        let k = f.unsigned_abs();
        match 2i64.checked_pow(k).and_then(|p| acc.checked_mul(p)) {
            Some(v) => v,
            None if acc < 0 => i64::MIN,
            None => i64::MAX,
        }
    };
    // Clamped to [DEPTH_NEAR, DEPTH_FAR]: the conversion is exact.
    i32::try_from(q.clamp(i64::from(DEPTH_NEAR), i64::from(DEPTH_FAR))).unwrap_or(DEPTH_FAR)
}

/// The planar test with its intermediates: `None` for a position outside the viewport or a
/// setup without planar data (not a static triangle of a `Planar` precision).
#[inline(always)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_wrap)]
pub fn planar_eval(setup: &Setup, pos: ScreenPos, ops: &mut Ops) -> Option<PlanarEval> {
    let pl = setup.planar.as_ref()?;
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
    // |n'| ≤ 2^30, |d| ≤ 2^30: three products ≤ 2^60, |E'| < 2^62 (i64).
    let e = pl.n.map(|nk| {
        nk.iter()
            .zip(d.iter())
            .map(|(&a, &b)| i64::from(a) * i64::from(b))
            .sum::<i64>()
    });
    let [e0, e1, e2] = e;
    let pos_side = pl.sigma > 0;
    let covered = if e0 != 0 && e1 != 0 && e2 != 0 {
        // Every E' has the orientation's strict sign.
        if pos_side {
            e0 > 0 && e1 > 0 && e2 > 0
        } else {
            e0 < 0 && e1 < 0 && e2 < 0
        }
    } else {
        e.iter().zip(pl.n.iter()).all(|(&ek, nk)| {
            if ek == 0 {
                fill(nk, pl.sigma)
            } else {
                (ek > 0) == pos_side
            }
        })
    };
    ops.add_sample(9 + 2 + 3);
    let hit = covered.then(|| {
        ops.add_sample(4);
        Hit {
            depth: depth(&pl.g, pl.f, &d),
        }
    });
    Some(PlanarEval { e, hit })
}

/// The planar test: the depth on a hit ([`planar_eval`]).
#[inline]
pub fn planar_test(setup: &Setup, pos: ScreenPos, ops: &mut Ops) -> Option<Hit> {
    planar_eval(setup, pos, ops)?.hit
}
