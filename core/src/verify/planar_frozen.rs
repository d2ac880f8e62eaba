//! A frozen copy of the planar static test (`planar.rs`) as of the vertex-rounding redesign
//! (branch wip-st, ST2) with the full-precision depth plane (branch wip-pa: z is no longer
//! rounded with its vertex's shift; the depth plane is the rounded triangle's with the
//! unrounded z, `planar.rs` "Depth"), kept verbatim (test-only; `frozen_eval` takes the planar data instead
//! of a `Setup`, the inline and lint attributes dropped) as the contract of the
//! `planar-16-16-16-20` configuration: `planar_frozen_tests` checks that setup (rounded
//! vertices, shifts, normals, σ, depth plane, epsilon) and the per-sample test (E, coverage,
//! depth) equal the frozen copy's on seeded random and domain-corner inputs, and a committed
//! hash over a fixed input sequence pins the frozen outputs: a later change of the planar bits
//! fails here. Do not edit the functions below.
// Test code, verbatim: its range proofs are those of `planar.rs` at that commit.
#![allow(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_possible_wrap,
    clippy::cast_sign_loss
)]

use crate::config::formats::{DEPTH_FAR, DEPTH_FRAC, DEPTH_NEAR, SUBPIXEL_BITS};
use crate::input::{Triangle, Viewport, W, X, Y, Z};
use crate::sample::planar;
use crate::sample::planar::PlanarEval;
use crate::sample::pos::{Hit, ScreenPos};
use crate::setup::eps::Eps;
use crate::setup::planar::PlanarEdges;
use crate::stats::Ops;

/// Bits of a rounded vertex component: |P'| ≤ 2^15 − 1 (i16).
const VERTEX_BITS: u32 = 15;

/// Bit length of a `u128` (0 for 0).
fn bitlen(x: u128) -> u32 {
    u128::BITS.saturating_sub(x.leading_zeros())
}

/// `rnd(v, s) = sign(v)·⌊(|v| + 2^(s−1)) / 2^s⌋` (module table; exact for s = 0): nearest, ties
/// away from zero. For |v| ≤ 2^29 and s ≤ 15 the sum is < 2^30 (u32) and the result ≤ 2^29.
// s ≤ 15 (callers): the shifts are in range; |v| + half < 2^30 in u32; the result ≤ 2^29 fits
// i32 and its negation is exact.
fn rnd(v: i32, s: u32) -> i32 {
    let half = if s == 0 { 0 } else { 1u32 << (s - 1) };
    let q = ((v.unsigned_abs() + half) >> s) as i32;
    if v < 0 {
        -q
    } else {
        q
    }
}

/// The shift `s` (0..=15) of one vertex from `m = max(|x|, |y|, |w|)` ≤ 2^29 (module table):
/// the least of `bitlen(m) − 15` and one more, such that `rnd(m, s) ≤ 2^15 − 1`.
// bitlen(m) ≤ 30: s ≤ 15; the increment happens only for bitlen ≤ 29 (s ≤ 14), module docs.
fn vertex_shift(m: u32) -> u32 {
    let s = u32::BITS
        .saturating_sub(m.leading_zeros())
        .saturating_sub(VERTEX_BITS);
    if rnd(m as i32, s) > (1 << VERTEX_BITS) - 1 {
        s + 1
    } else {
        s
    }
}

/// Cross product of rounded vertices (|.| ≤ 2^15 − 1): each product ≤ (2^15 − 1)² < 2^30, each
/// difference ≤ 2·(2^15 − 1)² < 2^31: exact in i32.
fn cross(a: [i32; 3], b: [i32; 3]) -> [i32; 3] {
    let [a0, a1, a2] = a;
    let [b0, b1, b2] = b;
    [a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0]
}

/// `a · b` in i64 for |a_i| < 2^31, |b_i| ≤ 2^29: each product < 2^60, the sum < 2^62.
fn dot64(a: &[i32; 3], b: &[i32; 3]) -> i64 {
    a.iter()
        .zip(b.iter())
        .map(|(&x, &y)| i64::from(x) * i64::from(y))
        .sum()
}

/// `⌊v / 2^r⌋` for `r ≥ 0`, `v·2^(−r)` (exact) for `r < 0`, as i64: the caller picks `r` so
/// that the result has at most 62 bits (`depth_plane`); anything else saturates (not reached).
// |r| < 128: both shifts are in range for i128 and exact (left: the result has ≤ 62 bits).
fn shift_to_i64(v: i128, r: i32) -> i64 {
    let x = if r >= 0 {
        v >> r.min(127)
    } else {
        v << (-r).min(127)
    };
    i64::try_from(x).unwrap_or(if v < 0 { i64::MIN } else { i64::MAX })
}

/// The depth plane `(G, f)` from the exact `Zv` (< 2^77) and `D ≠ 0` (|D| < 2^93), module
/// docs.
// bitlen(D) ≤ 93: rd = bitlen(D) − 32 ∈ [−23, 61] (D ≥ 256), rz = bitlen(max|Zv|) − 62 ∈
// [−61, 15]; every shifted value has ≤ 32 bits (D) or ≤ 62 bits (Zv); f ∈ [−62, 98].
fn depth_plane(zv: [i128; 3], d: i128) -> Option<([i32; 3], i32)> {
    // Orient D > 0: |D|, |Zv| < 2^120, the negations are exact.
    let (zv, d) = if d < 0 { (zv.map(|c| -c), -d) } else { (zv, d) };
    if d < 256 {
        return None;
    }
    let bz = bitlen(zv.iter().map(|c| c.unsigned_abs()).max().unwrap_or(0)) as i32;
    if bz == 0 {
        return Some(([0; 3], 0));
    }
    let (rd, rz) = (bitlen(d.unsigned_abs()) as i32 - 32, bz - 62);
    let d32 = shift_to_i64(d, rd); // [2^31, 2^32)
    let mut g = [0i32; 3];
    for (gi, &z) in g.iter_mut().zip(zv.iter()) {
        // |Z62| < 2^62, D32 ≥ 2^31: the floor quotient is in [−2^31, 2^31): i32.
        *gi = i32::try_from(shift_to_i64(z, rz).div_euclid(d32)).ok()?;
    }
    // Zv_i / D ≈ G_i·2^(rz − rd); depth·2^-24 = Σ Zv_i·d_i / D: f = rd − rz − 24.
    Some((g, rd - rz - DEPTH_FRAC as i32))
}

/// Planar setup of a static triangle (its t0 vertices) in `vp`: the rounded vertices, their
/// exact normals, the epsilon and the depth plane, or `None` (culled as degenerate: det P' = 0).
pub(crate) fn frozen_setup(
    tri: &Triangle,
    vp: Viewport,
    ops: &mut Ops,
) -> Option<(PlanarEdges, Eps)> {
    let [v0, _] = &tri.v;
    let mut pv = [[0i32; 3]; 3];
    let mut s = [0u32; 3];
    let mut z = [0i32; 3];
    let mut eps = [0i32; 3];
    for (k, q) in v0.iter().enumerate() {
        // Checked triangle: |x|, |y|, |z|, |w| ≤ 2^29.
        let p = [q[X], q[Y], q[W]];
        let m = p.iter().map(|c| c.unsigned_abs()).max().unwrap_or(0);
        let sk = vertex_shift(m);
        let r = p.map(|c| rnd(c, sk));
        for ((e, &c), &cr) in eps.iter_mut().zip(p.iter()).zip(r.iter()) {
            // |c'| ≤ 2^15 − 1, s ≤ 15: c'·2^s < 2^30; the residual ≤ 2^(s−1) ≤ 2^14.
            *e = (*e).max((c - (cr << sk)).abs());
        }
        if let (Some(pk), Some(sl), Some(zk)) = (pv.get_mut(k), s.get_mut(k), z.get_mut(k)) {
            (*pk, *sl, *zk) = (r, sk, q[Z]);
        }
        ops.add_setup(12);
    }
    let [p0, p1, p2] = pv;
    let n = [cross(p1, p2), cross(p2, p0), cross(p0, p1)];
    let [n0, n1, n2] = n;
    // |P'| < 2^15, |n| < 2^31: |det P'| < 3·2^46.
    let det = dot64(&p0, &n0);
    ops.add_setup(21);
    if det == 0 {
        return None;
    }
    // Depth plane of the rounded triangle with the unrounded depths (module docs): with S =
    // max s_k, Zv_i = Σ_k z_k·2^(S − s_k)·n_k,i (|z| ≤ 2^29, 2^(S − s_k) ≤ 2^15, |n| < 2^31:
    // each term < 2^75, |Zv| < 2^77, i128) and D = det·2^S·256·W·H (< 3·2^46·2^15·2^30 <
    // 2^93, i128); S − s_k ∈ [0, 15]: the shifts are in range and exact.
    let smax = s.iter().copied().max().unwrap_or(0);
    let zs = [0, 1, 2].map(|k| {
        let (zk, sk) = (
            z.get(k).copied().unwrap_or(0),
            s.get(k).copied().unwrap_or(0),
        );
        i128::from(zk) << (smax - sk)
    });
    let zv = [0, 1, 2].map(|i| {
        [n0, n1, n2]
            .iter()
            .zip(zs.iter())
            .map(|(nk, &zk)| zk * i128::from(nk.get(i).copied().unwrap_or(0)))
            .sum::<i128>()
    });
    let dw = i64::from(vp.w) * i64::from(vp.h) * (1i64 << SUBPIXEL_BITS);
    let (g, f) = depth_plane(zv, (i128::from(det) << smax) * i128::from(dw))?;
    ops.add_setup(20);
    // |P'| ≤ 2^15 − 1 and s ≤ 15 (module table): the conversions are exact.
    let pv = pv.map(|p| p.map(|c| i16::try_from(c).unwrap_or(0)));
    let s = s.map(|c| u8::try_from(c).unwrap_or(0));
    Some((
        PlanarEdges {
            pv,
            s,
            n,
            sigma: if det > 0 { 1 } else { -1 },
            g,
            f,
        },
        Eps {
            x: [eps[0], eps[1]],
            w: eps[2],
        },
    ))
}

/// The sample direction as i32: inside the viewport (checked by the caller) every component is
/// ≤ 2^30 in magnitude (`sample::direction`).
fn direction32(vp: Viewport, xs: i32, ys: i32) -> [i32; 3] {
    let (w, h) = (i32::from(vp.w), i32::from(vp.h));
    let one = 1i32 << SUBPIXEL_BITS;
    // |2xs − 256W| ≤ 256W ≤ 2^19, ×H ≤ 2^11: ≤ 2^30; 256·W·H ≤ 2^30.
    [(2 * xs - one * w) * h, (one * h - 2 * ys) * w, one * w * h]
}

/// Fill rule on `E_k = 0` (module docs): `σ·a > 0`, or `a = 0` and `σ·b > 0`.
fn fill(n: &[i32; 3], sigma: i32) -> bool {
    let [a, b, _] = *n;
    if sigma > 0 {
        a > 0 || (a == 0 && b > 0)
    } else {
        a < 0 || (a == 0 && b < 0)
    }
}

/// Depth of a hit from the plane `(G, f)` (module docs).
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
    } else if acc == 0 {
        0
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
pub(crate) fn frozen_eval(pl: &PlanarEdges, vp: Viewport, pos: ScreenPos) -> Option<PlanarEval> {
    let ops = &mut Ops::default();
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
    let pos_side = pl.sigma > 0;
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

#[cfg(test)]
mod planar_frozen_tests {
    use super::*;
    use crate::config::precision::PlanarPrecision;
    use crate::input::Vertex;
    use crate::setup::Setup;
    use uvt_testkit::{cases, seed, Rng};

    const LIM: i64 = 1 << 29;

    /// A static triangle: coordinates at the domain's ends, small, or a regular triangle in
    /// front of the camera (w > 0) whose NDC corners are random.
    fn triangle(r: &mut Rng) -> Option<Triangle> {
        let kind = r.next_u64() % 3;
        let mut v = [[0i32; 5]; 3];
        let w0 = (r.next_u64() % (LIM as u64)) as i64 + 1;
        for p in v.iter_mut() {
            *p = if kind == 0 {
                [
                    r.signed(LIM),
                    r.signed(LIM),
                    r.signed(LIM),
                    r.signed(LIM),
                    0,
                ]
                .map(|x| x as i32)
            } else {
                let w = if kind == 1 { w0 } else { r.signed(LIM) };
                let nx = r.signed(1 << 16);
                let ny = r.signed(1 << 16);
                let z = r.signed(LIM);
                [(nx * w) >> 16, (ny * w) >> 16, z, w, 0].map(|x| x as i32)
            };
        }
        Triangle::new_static(v.map(Vertex::from_bits)).ok()
    }

    fn viewport(r: &mut Rng) -> Viewport {
        let side = |r: &mut Rng| match r.next_u64() % 4 {
            0 => 2048,
            1 => 1,
            _ => (r.next_u64() % 2048) as u16 + 1,
        };
        Viewport::new(side(r), side(r)).unwrap()
    }

    fn fnv(h: &mut u64, words: &[i64]) {
        for w in words {
            for b in w.to_le_bytes() {
                *h = (*h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
            }
        }
    }

    /// Live setup and test against the frozen copy on `cases` triangles × 16 positions from
    /// `seed`; returns the hash of the frozen outputs and (visible, covered) counts.
    fn compare(seed: u64, cases: u32) -> (u64, u64, u64) {
        let mut r = Rng(seed);
        let mut h = 0xcbf2_9ce4_8422_2325u64;
        let (mut vis, mut cov) = (0, 0);
        for i in 0..cases {
            let Some(t) = triangle(&mut r) else { continue };
            let vp = viewport(&mut r);
            let live = Setup::unculled::<PlanarPrecision>(&t, vp);
            let frozen = frozen_setup(&t, vp, &mut Ops::default());
            let lf = live.planar().map(|p| (p, live.eps()));
            assert_eq!(
                lf, frozen,
                "case {i} (seed {seed}): setup differs from the frozen copy\n  {t:?} vp {vp:?}"
            );
            let Some((pl, e)) = frozen else {
                fnv(&mut h, &[-1]);
                continue;
            };
            vis += 1;
            let mut words = vec![
                i64::from(pl.sigma),
                i64::from(pl.f),
                i64::from(e.x[0]),
                i64::from(e.x[1]),
                i64::from(e.w),
            ];
            words.extend(pl.n.iter().flatten().map(|&x| i64::from(x)));
            words.extend(pl.pv.iter().flatten().map(|&x| i64::from(x)));
            words.extend(pl.s.iter().map(|&x| i64::from(x)));
            words.extend(pl.g.iter().map(|&x| i64::from(x)));
            fnv(&mut h, &words);
            for k in 0..16u64 {
                let (sw, sh) = (u32::from(vp.w) * 256, u32::from(vp.h) * 256);
                let xs = match k % 4 {
                    0 => 0,
                    1 => sw - 1,
                    _ => (r.next_u64() % u64::from(sw)) as u32,
                };
                let ys = match k / 4 {
                    0 => 0,
                    1 => sh - 1,
                    _ => (r.next_u64() % u64::from(sh)) as u32,
                };
                let pos = ScreenPos { xs, ys };
                let want = frozen_eval(&pl, vp, pos);
                let got = planar::eval(&live, pos, &mut Ops::default());
                assert_eq!(got, want, "case {i} (seed {seed}) xs {xs} ys {ys}: expected (frozen) {want:?}, observed {got:?}\n  {t:?} vp {vp:?}");
                let Some(ev) = want else { continue };
                cov += u64::from(ev.hit.is_some());
                fnv(
                    &mut h,
                    &[
                        ev.e[0],
                        ev.e[1],
                        ev.e[2],
                        ev.hit.map_or(-1, |x| i64::from(x.depth)),
                    ],
                );
            }
        }
        (h, vis, cov)
    }

    /// The fixed-seed hash of the frozen copy's outputs, committed: it pins the contract of
    /// `planar-16-16-16-20`; then a seeded random comparison (`UVT_SEED`).
    #[test]
    fn planar_equals_the_frozen_contract() {
        let (h, vis, cov) = compare(0x9a7a_0001, 4000);
        println!("pinned: hash {h:#018x}, {vis} visible setups, {cov} covered samples");
        assert!(
            vis > 1000 && cov > 1000,
            "the pinned sequence exercises too little: {vis} setups, {cov} hits"
        );
        assert_eq!(
            h, PINNED,
            "the frozen planar contract's hash changed: {h:#018x}"
        );
        let s = seed();
        compare(s ^ 0x51a7, cases(2000, 100_000));
    }

    const PINNED: u64 = 0xc841_45eb_b6a9_4e44;
}
