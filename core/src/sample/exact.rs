//! Stage 3 — the 5D sample test: does the triangle at the sample's (t, u, v) cover the sample's
//! screen position, and at what depth? (Olano & Greer 1997 homogeneous edge functions;
//! Akenine-Möller 2007 §3.3.2 time-continuous triangles.)
//!
//! **Exact.** Vertex positions at the sample's (t, u, v) are formed without any rounding at the
//! class's scale (`F` fraction bits: 16 static, 32 motion-only or defocus-only, 48 both):
//! `P = q·2^16 + T·(r − q)` (T = raw t) and `x += U·c(t)`, `y += V·c(t)`. The sample direction is
//! `d = ((2Xs − 256W)·H, (256H − 2Ys)·W, 256·W·H)` (NDC scaled by 256·W·H > 0; Xs, Ys in 1/256 px).
//! Edge normals `n_k = P_{k+1} × P_{k+2}` are exact `i128`; edge values `E_k = n_k·d` and
//! `det = P_0·n_0` are exact 192-bit ([`Wide`]). Coverage is decided on signs only, so it is
//! the exact rational answer for the quantized inputs: nothing in it rounds.
//!
//! **Coverage.** With `s = sign(det)`: covered iff `det ≠ 0` and for every edge `s·E_k > 0`, or
//! `E_k = 0` and the fill rule accepts. **Fill rule:** on `E_k = 0` accept iff `s·a_k > 0`, or
//! `s·a_k = 0` and `s·b_k > 0`, where `(a_k, b_k)` are the first two components of `n_k`. This is
//! the sign of `s·E_k` at the sample displaced by an infinitesimal `(ε, ε²)` in `d`, the same
//! displacement for every triangle, so every sample behaves like one in general position: two
//! triangles sharing an edge (whose `n` are exact negatives because the cross product of the same
//! two exact vertices is antisymmetric) never both take nor both leave a sample on it, at any
//! (t, u, v). Vertices behind the camera need no special case: the ray `λ·d, λ > 0` only reaches
//! points with `w > 0`, and a hit behind the camera has all `E_k/det ≤ 0` with one `< 0`.
//!
//! **Depth** `z/w` at the hit equals `Σ E_k z_k / Σ E_k w_k`. The `E_k` are first shifted right
//! by a common amount (floor) so the largest keeps [`DEPTH_EDGE_BITS`] significant bits, then
//! `floor(num·2^24 / den)` after orienting `den > 0`. Depth never influences coverage.
//!
//! **Depth format (saturating, with a reserved empty value).** Outputs lie in raw
//! `[DEPTH_NEAR, DEPTH_FAR] = [i32::MIN, i32::MAX − 1]`: a quotient below `i32::MIN` (z/w < −128)
//! saturates to `DEPTH_NEAR`, one above `i32::MAX − 1` (z/w ≥ 128 − 2^-23) to `DEPTH_FAR`. Raw
//! `i32::MAX` is `DEPTH_EMPTY`, the value a tile buffer clears to, and is never produced, so with
//! the buffer's strict "less wins" test a covered sample always replaces an empty slot.
//! **Shifted denominator ≤ 0.** The exact `Σ E_k w_k` (oriented) is the hit's w times a positive
//! factor, and a covered sample's hit lies on the ray `λ·d, λ > 0`, so it has w > 0: the exact
//! denominator is positive. Only the floor shift of the `E_k` can make it ≤ 0, when the hit is at
//! w → 0+ (a triangle crossing the camera plane) and z/w → ±∞. The shifted numerator has lost its
//! significance too, so the sign of the divergence is not known reliably; the output is the far
//! end `DEPTH_FAR`: deterministic, written into an empty slot, and never occluding a sample of smaller
//! depth (D3D would clip such a hit by the near plane; here it stays visible only where
//! nothing else is).

use crate::arith::wide::Wide;
use crate::config::class::Class;
use crate::config::formats::{DEPTH_EDGE_BITS, DEPTH_FAR, DEPTH_FRAC, DEPTH_NEAR, TUV_FRAC};
use crate::config::unit::Unit;
use crate::input::{Sample, C, W, X, Y, Z};
use crate::sample::pos::{direction, Hit, ScreenPos};
use crate::setup::Setup;
use crate::stats::Ops;

/// 2^16: scales a 16-fraction-bit value by one t/u/v step (a constant, not a run-time shift).
const TUV_SCALE: i64 = 1 << TUV_FRAC;

/// 2^24: the depth quotient's scale.
const DEPTH_SCALE: i128 = 1 << DEPTH_FRAC;

/// Exact vertex positions `(x, y, w, z)` at (t, u, v) for the triangle's class, and their
/// fraction bits. Ranges: |q| ≤ 2^29, |r − q| ≤ 2^30, |T| ≤ 2^16, |U| ≤ 2^16, so every value is
/// ≤ 2^14 in real terms and |raw| ≤ 2^62 at 48 fraction bits.
///
/// Overflow, line by line (checked `Triangle` and `Sample`): `lerp(f) = q·2^16 + T·(r − q)` is
/// `(2^16 − T)·q + T·r`, so |lerp| ≤ 2^16·2^29 = 2^45 (the products: |q·2^16| ≤ 2^45,
/// |T·(r − q)| ≤ 2^46); static or defocus-only `q·2^16 + U·c`: ≤ 2^45 + 2^45 = 2^46;
/// motion+defocus `lerp·2^16 + U·l[C]`: ≤ 2^61 + 2^61 = 2^62. All < 2^63: no i64 overflow.
/// The scalings are multiplications by the constant 2^16 (no shift), so debug builds' overflow
/// checks see them; `tests::positions_at_the_domain_corners` drives the extremes.
/// On unit `U` the class arms `U` lacks are compiled out (an accepted class takes the same arm).
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn positions<U: Unit>(setup: &Setup, s: &Sample, ops: &mut Ops) -> ([[i64; 4]; 3], u32) {
    let [v0, v1] = &setup.tri.v;
    let t = i64::from(s.t().to_bits());
    let (u, v) = (i64::from(s.u().to_bits()), i64::from(s.v().to_bits()));
    let mut out = [[0i64; 4]; 3];
    let gated = (
        U::MOTION && setup.class.motion(),
        U::DEFOCUS && setup.class.defocus(),
    );
    let frac = match gated {
        (false, false) => {
            for (q, o) in v0.iter().zip(out.iter_mut()) {
                *o = [q[X], q[Y], q[W], q[Z]].map(i64::from);
            }
            16
        }
        (true, false) => {
            for ((q, r), o) in v0.iter().zip(v1.iter()).zip(out.iter_mut()) {
                let l = lerp5(q, r, t);
                *o = [l[X], l[Y], l[W], l[Z]];
                ops.add_sample(8);
            }
            32
        }
        (false, true) => {
            for (q, o) in v0.iter().zip(out.iter_mut()) {
                let c = i64::from(q[C]);
                *o = [
                    i64::from(q[X]) * TUV_SCALE + u * c,
                    i64::from(q[Y]) * TUV_SCALE + v * c,
                    i64::from(q[W]) * TUV_SCALE,
                    i64::from(q[Z]) * TUV_SCALE,
                ];
                ops.add_sample(4);
            }
            32
        }
        (true, true) => {
            for ((q, r), o) in v0.iter().zip(v1.iter()).zip(out.iter_mut()) {
                let l = lerp5(q, r, t);
                let c = l[C];
                *o = [
                    l[X] * TUV_SCALE + u * c,
                    l[Y] * TUV_SCALE + v * c,
                    l[W] * TUV_SCALE,
                    l[Z] * TUV_SCALE,
                ];
                ops.add_sample(14);
            }
            48
        }
    };
    (out, frac)
}

/// `q·2^16 + T·(r − q)` per field: |.| ≤ 2^45 (see [`positions`]).
#[inline]
#[allow(clippy::arithmetic_side_effects)] // |q·2^16| ≤ 2^45, |T·(r − q)| ≤ 2^46, sum ≤ 2^45
fn lerp5(q: &[i32; 5], r: &[i32; 5], t: i64) -> [i64; 5] {
    let mut out = [0i64; 5];
    for ((o, &a), &b) in out.iter_mut().zip(q).zip(r) {
        *o = i64::from(a) * TUV_SCALE + t * (i64::from(b) - i64::from(a));
    }
    out
}

/// Cross product of the (x, y, w) parts, exact: |P| ≤ 2^62 so each term < 2^124, sum < 2^125.
#[inline]
#[allow(clippy::arithmetic_side_effects)] // |each product| ≤ 2^124, |difference| ≤ 2^125 < 2^127
fn cross(a: &[i64; 4], b: &[i64; 4]) -> [i128; 3] {
    let [ax, ay, aw, _] = a.map(i128::from);
    let [bx, by, bw, _] = b.map(i128::from);
    [ay * bw - aw * by, aw * bx - ax * bw, ax * by - ay * bx]
}

#[inline]
fn dot_wide(n: &[i128; 3], d: &[i64; 3]) -> Wide {
    let mut acc = Wide::ZERO;
    for (a, b) in n.iter().zip(d.iter()) {
        acc.mul_add(*a, *b);
    }
    acc
}

/// Fill-rule decision for an edge whose value is exactly zero.
#[inline]
fn fill_rule(n: &[i128; 3], det_sign: i32) -> bool {
    let [n0, n1, _] = *n;
    // |n| < 2^126 (sample-test normals, < 2^61 static): negation exact; saturating regardless.
    let (a, b) = if det_sign > 0 {
        (n0, n1)
    } else {
        (n0.saturating_neg(), n1.saturating_neg())
    };
    a > 0 || (a == 0 && b > 0)
}

/// Coverage from the edge values and normals; `None` if not covered.
#[inline]
fn decide(e: &[Wide; 3], n: &[[i128; 3]; 3], det_sign: i32) -> bool {
    if det_sign == 0 {
        return false;
    }
    e.iter()
        .zip(n.iter())
        .all(|(ek, nk)| match (ek.signum(), det_sign > 0) {
            (1, true) | (-1, false) => true,
            (0, _) => fill_rule(nk, det_sign),
            _ => false,
        })
}

/// Depth z/w from the edge values and the vertices' (w, z), see module docs.
///
/// Ranges: after the shift every |e'| ≤ 2^32 (bit length ≤ 32), |w|, |z| ≤ 2^62, so each product
/// is < 2^94 and the sums < 2^96; `num·2^24` (a multiplication by a constant, no shift) is
/// < 2^120; `den > 0` at the division. `tests::depth_at_the_range_corners` drives the extremes.
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn depth(e: &[Wide; 3], wz: &[(i64, i64); 3], det_sign: i32) -> i32 {
    let len = e.iter().map(Wide::bit_len).max().unwrap_or(0);
    let sh = len.saturating_sub(DEPTH_EDGE_BITS);
    let (mut num, mut den) = (0i128, 0i128);
    for (ek, &(w, z)) in e.iter().zip(wz.iter()) {
        // The quotient has ≤ 32 significant bits, so `shr_floor` cannot return None; if it did,
        // the far end is the documented "no reliable depth" value.
        let Some(ek) = ek.shr_floor(sh) else {
            return DEPTH_FAR;
        };
        num += ek * i128::from(z);
        den += ek * i128::from(w);
    }
    if det_sign < 0 {
        num = -num;
        den = -den;
    }
    if den <= 0 {
        return DEPTH_FAR;
    }
    let q = (num * DEPTH_SCALE).div_euclid(den);
    let clamped = q.clamp(i128::from(DEPTH_NEAR), i128::from(DEPTH_FAR));
    i32::try_from(clamped).unwrap_or(DEPTH_FAR)
}

/// Everything the exact test computed for one sample: the exact edge values, the determinant
/// and the decision. Golden vectors export it so RTL can be checked stage-internally.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ExactEval {
    /// edge values E_0, E_1, E_2 (exact)
    pub e: [Wide; 3],
    /// det = P_0 · (P_1 × P_2) (exact; for static triangles only its sign is kept: ±1 or 0)
    pub det: Wide,
    /// coverage and depth
    pub hit: Option<Hit>,
}

/// The exact test with its intermediates, on unit `U` for a setup whose class `U` accepts (the
/// renderer checks; the full unit accepts every class): the class terms `U` lacks are compiled
/// out. Counts its arithmetic in `ops.sample`. Always the exact test, whatever the setup's
/// precision; a `Bounded` setup's rounded intermediates come from [`crate::sample::bounded::eval`].
pub fn eval<U: Unit>(setup: &Setup, pos: ScreenPos, s: &Sample, ops: &mut Ops) -> ExactEval {
    let d = direction(setup.viewport, pos);
    ops.add_sample(5);
    // A bounded setup does not store the normals (`Setup::edges`): computed here, same value.
    let stored = setup.edges.exact();
    let computed = if stored.is_none() {
        setup.edges()
    } else {
        None
    };
    if let (Class::Static, Some(st)) = (setup.class, stored.as_ref().or(computed.as_ref())) {
        // Plain 2D test: normals precomputed in setup (|n| < 2^61), |d| < 2^45: each product
        // < 2^106, the sum < 2^108.
        #[allow(clippy::arithmetic_side_effects)]
        let e = st.n.map(|[a, b, c]| {
            let [dx, dy, dw] = d.map(i128::from);
            Wide::from_i128(a * dx + b * dy + c * dw)
        });
        ops.add_sample(18);
        let det = Wide::from_i128(i128::from(st.det_sign));
        if !decide(&e, &st.n, st.det_sign) {
            return ExactEval { e, det, hit: None };
        }
        let wz = setup.tri.v[0].map(|q| (i64::from(q[W]), i64::from(q[Z])));
        ops.add_sample(12);
        return ExactEval {
            e,
            det,
            hit: Some(Hit {
                depth: depth(&e, &wz, st.det_sign),
            }),
        };
    }
    let (p, _frac) = positions::<U>(setup, s, ops);
    let n = [
        cross(&p[1], &p[2]),
        cross(&p[2], &p[0]),
        cross(&p[0], &p[1]),
    ];
    let e = n.map(|nk| dot_wide(&nk, &d));
    let mut det = Wide::ZERO;
    for (nc, pc) in n[0].iter().zip(p[0].iter()) {
        det.mul_add(*nc, *pc);
    }
    ops.add_sample(18 + 15 + 5 + 6);
    let det_sign = det.signum();
    if !decide(&e, &n, det_sign) {
        return ExactEval { e, det, hit: None };
    }
    let wz = p.map(|q| (q[2], q[3]));
    ops.add_sample(12);
    ExactEval {
        e,
        det,
        hit: Some(Hit {
            depth: depth(&e, &wz, det_sign),
        }),
    }
}
