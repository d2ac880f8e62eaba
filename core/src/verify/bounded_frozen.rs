//! A frozen copy of the bounded sample test as of main commit b1c6e2e (the contract the RTL
//! unit is built against), kept verbatim (test-only) as the oracle for the faster `bounded.rs`:
//! `bounded_frozen_tests` checks that both produce identical `BoundedEval`s (a', b', E',
//! orientation, coverage, depth) on random and domain-corner inputs, and a committed hash over a
//! fixed input sequence pins both. Do not edit the functions below; they are the reference.
// Test code, verbatim from b1c6e2e: its range proofs are those of `bounded.rs` at that commit.
#![allow(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_possible_wrap,
    clippy::cast_sign_loss
)]

use crate::config::formats::{DEPTH_FAR, DEPTH_FRAC, DEPTH_NEAR, SUBPIXEL_BITS, TUV_FRAC};
use crate::config::precision::{OFFSET_SHIFT_MAX, OFFSET_SHIFT_MIN};
use crate::input::{Sample, C, W, X, Y, Z};
use crate::sample::bounded::BoundedEval;
use crate::sample::pos::{Hit, ScreenPos};
use crate::setup::Setup;
use crate::stats::Ops;

const TUV_SCALE: i64 = 1 << TUV_FRAC;
const SUBPIXEL_SCALE: i64 = 1 << SUBPIXEL_BITS;
const DEPTH_SCALE: i128 = 1 << DEPTH_FRAC;

/// `round(v / 2^16)`, to nearest with ties toward +∞: `floor((v + 2^15) / 2^16)`.
/// Callers pass |v| ≤ 2^45 (module table), so the sum cannot overflow and the result is ≤ 2^29.
#[inline]
#[allow(clippy::arithmetic_side_effects)]
fn rnd16(v: i64) -> i64 {
    // floor((v + 2^15) / 2^16) as an arithmetic right shift by the constant 16 (exact floor).
    (v + TUV_SCALE / 2).checked_shr(TUV_FRAC).unwrap_or(0)
}

/// Vertex positions `(x, y, w, z)` at the sample's (t, u, v), each on the raw 2^-16 grid
/// (steps 1–2 of the module table). Ranges: |x|, |y| ≤ 2^30, |w|, |z| ≤ 2^29.
// Checked triangle: every field |f| ≤ 2^29, |f1 − f0| ≤ 2^30; |T| ≤ 2^16, |U|, |V| ≤ 2^16:
// f0·2^16 + T·(f1 − f0) = (2^16 − T)·f0 + T·f1, ≤ 2^45; U·c_t ≤ 2^45. All in i64.
#[allow(clippy::arithmetic_side_effects)]
fn positions(setup: &Setup, s: &Sample, ops: &mut Ops) -> [[i64; 4]; 3] {
    let [v0, v1] = &setup.tri.v;
    let t = i64::from(s.t().to_bits());
    let (u, v) = (i64::from(s.u().to_bits()), i64::from(s.v().to_bits()));
    let motion = setup.class.motion();
    let defocus = setup.class.defocus();
    let mut out = [[0i64; 4]; 3];
    for ((q, r), o) in v0.iter().zip(v1.iter()).zip(out.iter_mut()) {
        let mut f = q.map(i64::from);
        if motion {
            for (fi, &ri) in f.iter_mut().zip(r.iter()) {
                *fi = rnd16(*fi * TUV_SCALE + t * (i64::from(ri) - *fi));
            }
            ops.add_sample(15);
        }
        if defocus {
            f[X] += rnd16(u * f[C]);
            f[Y] += rnd16(v * f[C]);
            ops.add_sample(6);
        }
        *o = [f[X], f[Y], f[W], f[Z]];
    }
    out
}

/// `round(v / 2^s)`, to nearest with ties toward +∞, for the offset grid (step 4): `half` is
/// 2^(s−1); the arithmetic right shift by `s` is the floor division by 2^s (a right shift
/// cannot overflow; `s` ≤ 32 < 64, so `checked_shr` never returns `None`, and if it did the
/// result would be 0, not a panic). |v| < 1.5·2^49, half ≤ 2^31: the sum cannot overflow;
/// |result| < 2^30 for s ≥ 20. (A shift rather than a division: no 64-bit divide on the M4.)
#[inline]
#[allow(clippy::arithmetic_side_effects)]
fn rnd_grid(v: i64, half: i64, s: u32) -> i64 {
    (v + half).checked_shr(s).unwrap_or(0)
}

/// Fill-rule decision on `E'_k = 0` (step 7), for edge k with vertices `i = k+1`, `j = k+2`:
/// inside iff `s·κ > 0` with the antisymmetric tie key `κ = cmp((b'_i, a'_i, w_i), (b'_j, a'_j,
/// w_j))` (lexicographic). Comparators only; see the module docs for why it is watertight.
#[inline]
fn fill_rule(ab: &[(i64, i64); 3], w: &[i64; 3], i: usize, j: usize, s: i64) -> bool {
    let (Some(&(ai, bi)), Some(&(aj, bj)), Some(&wi), Some(&wj)) =
        (ab.get(i), ab.get(j), w.get(i), w.get(j))
    else {
        return false;
    };
    match (bi, ai, wi).cmp(&(bj, aj, wj)) {
        core::cmp::Ordering::Greater => s > 0,
        core::cmp::Ordering::Less => s < 0,
        core::cmp::Ordering::Equal => false,
    }
}

/// Depth z/w from the rounded edge values (step 8; rounding as in `sample.rs`: floor).
// After the shift |e''| < 2^24, |w|, |z| ≤ 2^29: products < 2^53, sums of three < 2^55 (i64);
// num·2^24 < 2^79 and den > 0 at the division (i128).
#[allow(clippy::arithmetic_side_effects)]
fn depth(e: &[i64; 3], wz: &[(i64, i64); 3], sign: i64) -> i32 {
    let big = e.iter().map(|x| x.unsigned_abs()).max().unwrap_or(0);
    let len = u64::BITS - big.leading_zeros();
    // Floor shift by sh ≤ 37 (|E'| < 2^61): an arithmetic right shift, exact floor, cannot fail.
    let sh = len.saturating_sub(24);
    let (mut num, mut den) = (0i64, 0i64);
    for (ek, &(w, z)) in e.iter().zip(wz.iter()) {
        let ek = ek.checked_shr(sh).unwrap_or(0);
        num += ek * z;
        den += ek * w;
    }
    let (num, den) = (i128::from(num * sign), i128::from(den * sign));
    // den > 0 (checked by floor_div) and the quotient's floor; through a 64-bit divide when the
    // scaled numerator fits (`floor_div`), else the 128-bit one.
    let Some(q) = crate::arith::div::floor_div(num * DEPTH_SCALE, den) else {
        return DEPTH_FAR;
    };
    let clamped = q.clamp(i128::from(DEPTH_NEAR), i128::from(DEPTH_FAR));
    i32::try_from(clamped).unwrap_or(DEPTH_FAR)
}

/// The bounded sample test with its intermediates, offsets on the grid `2^shift`. Counts its
/// arithmetic in `ops.sample`. `None` for a position outside the viewport (module docs) or a
/// `shift` outside [`OFFSET_SHIFT_MIN`]..=[`OFFSET_SHIFT_MAX`] (the range the proofs cover).
// Ranges in the module table: |x| ≤ 2^30, |w| ≤ 2^29, 256W ≤ 2^19 and |2xs − 256W| ≤ 256W
// (checked below), so |A| < 1.5·2^49; |a'| < 2^30 (grid ≥ 2^20); |E'| < 2^61; the rare-path
// Σ E'·w < 2^92.
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn frozen_eval(
    setup: &Setup,
    shift: u32,
    pos: ScreenPos,
    s: &Sample,
    ops: &mut Ops,
) -> Option<BoundedEval> {
    if !(OFFSET_SHIFT_MIN..=OFFSET_SHIFT_MAX).contains(&shift) {
        return None;
    }
    let half = 2i64.checked_pow(shift.checked_sub(1)?)?;
    let vp = setup.viewport;
    let (sw, sh) = (
        SUBPIXEL_SCALE * i64::from(vp.w),
        SUBPIXEL_SCALE * i64::from(vp.h),
    );
    let (xs, ys) = (i64::from(pos.xs), i64::from(pos.ys));
    if xs >= sw || ys >= sh {
        return None;
    }
    let (gx, gy) = (2 * xs - sw, sh - 2 * ys);
    let p = positions(setup, s, ops);
    let ab = p.map(|[x, y, w, _]| {
        (
            rnd_grid(sw * x - gx * w, half, shift),
            rnd_grid(sh * y - gy * w, half, shift),
        )
    });
    let w = p.map(|q| q[2]);
    let [(a0, b0), (a1, b1), (a2, b2)] = ab;
    let e = [a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0];
    ops.add_sample(2 + 3 * 8 + 9);
    let sign = if w.iter().all(|&wk| wk > 0) {
        let pos_ = e.iter().any(|&x| x > 0);
        let neg = e.iter().any(|&x| x < 0);
        ops.add_sample(3);
        match (pos_, neg) {
            (true, false) => 1,
            (false, true) => -1,
            _ => 0,
        }
    } else {
        let det: i128 = e
            .iter()
            .zip(w.iter())
            .map(|(&ek, &wk)| i128::from(ek) * i128::from(wk))
            .sum();
        ops.add_sample(6);
        i64::from(det > 0) - i64::from(det < 0)
    };
    let covered = sign != 0
        && e.iter()
            .enumerate()
            .all(|(k, &ek)| match (ek * sign).signum() {
                1 => true,
                0 => fill_rule(&ab, &w, (k + 1) % 3, (k + 2) % 3, sign),
                _ => false,
            });
    let hit = covered.then(|| {
        ops.add_sample(12);
        Hit {
            depth: depth(&e, &p.map(|q| (q[2], q[3])), sign),
        }
    });
    Some(BoundedEval {
        ab,
        e,
        det_sign: sign,
        hit,
    })
}

#[cfg(test)]
mod tests {
    use super::frozen_eval;
    use crate::config::formats::{Lens, SubPixel, Time, DEPTH_FAR, DEPTH_NEAR};
    use crate::config::precision::DefaultPrecision;
    use crate::input::{Sample, Triangle, Vertex, Viewport};
    use crate::sample::bounded;
    use crate::sample::bounded::BoundedEval;
    use crate::sample::pos::ScreenPos;
    use crate::setup::Setup;
    use crate::stats::Ops;

    use uvt_testkit::Rng;

    const LIM: i64 = 1 << 29;
    const ONE: i64 = 1 << 16;

    fn viewport(r: &mut Rng) -> Viewport {
        let mut side = || match r.next_u64() % 4 {
            0 => 1,
            1 => 2048,
            _ => r.int_range(1, 2048) as u16,
        };
        Viewport::new(side(), side()).unwrap()
    }

    fn sample(r: &mut Rng) -> Sample {
        Sample::new(
            SubPixel::from_bits(r.biased(0, 255) as u8),
            SubPixel::from_bits(r.biased(0, 255) as u8),
            Lens::from_bits(r.biased(-ONE, ONE) as i32),
            Lens::from_bits(r.biased(-ONE, ONE) as i32),
            Time::from_bits(r.biased(0, ONE) as i32),
        )
        .unwrap()
    }

    /// A random triangle of a random class: half of them anywhere in the domain (extremes
    /// biased), half small ones around the NDC point `(gx, gy)` at w ∈ [−1, 8] (hits, ties, the
    /// rare orientation path, depth saturation).
    #[allow(clippy::needless_range_loop)]
    fn triangle(r: &mut Rng, g: (f64, f64)) -> Triangle {
        let (motion, defocus) = (r.next_u64() % 2 == 0, r.next_u64() % 2 == 0);
        let wide = r.next_u64() % 2 == 0;
        let mut ends = [[[0i32; 5]; 3]; 2];
        let size = [ONE / 64, ONE / 4, 4 * ONE][r.next_u64() as usize % 3];
        for k in 0..3 {
            let v0 = if wide {
                [0; 5].map(|_| r.biased(-LIM, LIM))
            } else {
                let w = r.int_range(-ONE, 8 * ONE);
                let x = (g.0 * w as f64) as i64 + r.int_range(-size, size);
                let y = (g.1 * w as f64) as i64 + r.int_range(-size, size);
                let z = [r.int_range(-2 * w.abs(), 2 * w.abs()), r.biased(-LIM, LIM)]
                    [r.next_u64() as usize % 2];
                [x, y, z, w, r.int_range(-ONE / 8, ONE / 8)]
            };
            let mut v1 = v0;
            if motion {
                for f in v1.iter_mut() {
                    *f = if wide {
                        r.biased(-LIM, LIM)
                    } else {
                        (*f + r.int_range(-ONE / 2, ONE / 2)).clamp(-LIM, LIM)
                    };
                }
            }
            let (mut a, mut b) = (v0.map(|x| x as i32), v1.map(|x| x as i32));
            if !defocus {
                a[4] = 0;
                b[4] = 0;
            }
            ends[0][k] = a;
            ends[1][k] = b;
        }
        Triangle::new(
            ends[0].map(Vertex::from_bits),
            ends[1].map(Vertex::from_bits),
        )
        .unwrap()
    }

    /// FNV-1a 64 over the outputs.
    fn fnv(h: &mut u64, words: &[i64]) {
        for w in words {
            for b in w.to_le_bytes() {
                *h = (*h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3);
            }
        }
    }

    fn words(e: &BoundedEval) -> [i64; 12] {
        let [(a0, b0), (a1, b1), (a2, b2)] = e.ab;
        let d = e.hit.map_or(i64::MIN, |h| i64::from(h.depth));
        [
            a0, b0, a1, b1, a2, b2, e.e[0], e.e[1], e.e[2], e.det_sign, d, 0,
        ]
    }

    #[derive(Default, Debug)]
    struct Mix {
        n: u64,
        hits: u64,
        misses: u64,
        rare: u64,
        ties: u64,
        near: u64,
        far: u64,
        unsat: u64,
    }

    /// Runs `cases` random (triangle, sample) pairs from `seed` through both implementations;
    /// returns the hash of the frozen copy's outputs and the category counts. Panics with the
    /// inputs on the first difference.
    fn compare(seed: u64, cases: u32) -> (u64, Mix) {
        let mut r = Rng(seed);
        let mut h = 0xcbf2_9ce4_8422_2325u64;
        let mut mix = Mix::default();
        for _ in 0..cases {
            let vp = viewport(&mut r);
            let (px, py) = (
                r.biased(0, i64::from(vp.width()) - 1) as u16,
                r.biased(0, i64::from(vp.height()) - 1) as u16,
            );
            let s = sample(&mut r);
            let pos = ScreenPos::of(px, py, &s);
            let g = (
                (2.0 * f64::from(pos.xs) / (256.0 * f64::from(vp.width()))) - 1.0,
                1.0 - 2.0 * f64::from(pos.ys) / (256.0 * f64::from(vp.height())),
            );
            let tri = triangle(&mut r, g);
            let setup = Setup::unculled::<DefaultPrecision>(&tri, vp);
            let shift = if r.next_u64() % 2 == 0 {
                20
            } else {
                r.int_range(19, 33) as u32
            };
            let old = frozen_eval(&setup, shift, pos, &s, &mut Ops::default());
            let new = bounded::eval(&setup, shift, pos, &s, &mut Ops::default());
            assert_eq!(
                old, new,
                "seed {seed}: frozen vs new differ\n  shift {shift} pos {pos:?} {s:?}\n  {tri:?}\n  vp {vp:?}\n  frozen {old:x?}\n  new {new:x?}"
            );
            let Some(e) = old else {
                fnv(&mut h, &[-1]);
                continue;
            };
            fnv(&mut h, &words(&e));
            mix.n += 1;
            match e.hit {
                Some(hit) if hit.depth == DEPTH_NEAR => mix.near += 1,
                Some(hit) if hit.depth == DEPTH_FAR => mix.far += 1,
                Some(_) => mix.unsat += 1,
                None => mix.misses += 1,
            }
            mix.hits += u64::from(e.hit.is_some());
            mix.ties += u64::from(e.e.contains(&0) && e.det_sign != 0);
            let w_pos = tri.v[0].iter().all(|q| q[3] > 0) && tri.v[1].iter().all(|q| q[3] > 0);
            mix.rare += u64::from(!w_pos);
        }
        (h, mix)
    }

    fn seed() -> u64 {
        uvt_testkit::seed()
    }

    /// The fixed-seed hash of the frozen copy's outputs, committed: it pins the contract (a', b',
    /// E', orientation, coverage, depth) independently of both implementations.
    const PINNED_SEED: u64 = 0x0b0d_ed20;
    const PINNED_CASES: u32 = 60_000;
    const PINNED_HASH: u64 = 0x20cc_d9a7_b46f_5318;

    #[test]
    fn bounded_eval_equals_the_frozen_contract() {
        // A fixed sequence whose hash is committed, then a seeded random one.
        let (h, mix) = compare(PINNED_SEED, PINNED_CASES);
        println!("pinned: hash {h:#018x} {mix:?}");
        assert_eq!(
            h, PINNED_HASH,
            "the frozen contract's hash changed: {h:#018x}"
        );
        // Every path was exercised (else the comparison proves little).
        assert!(
            mix.unsat > 1000
                && mix.misses > 1000
                && mix.near > 10
                && mix.far > 10
                && mix.ties > 10
                && mix.rare > 1000,
            "{mix:?}"
        );
        let seed = seed();
        let cases = uvt_testkit::cases(100_000, 5_000_000);
        let (_, mix) = compare(seed, cases);
        println!("seed {seed}: {mix:?}");
    }

    /// The depth quotient against the 128-bit floor division on its whole operand range:
    /// den ∈ (0, 2^55), |num| < 2^7·den, extremes and random.
    #[test]
    fn depth_quotient_equals_the_128_bit_division() {
        let seed = seed();
        let mut r = Rng(seed);
        let check = |num: i64, den: i64| {
            let want = (i128::from(num) * (1 << 24)).div_euclid(i128::from(den));
            for (name, got) in [
                (
                    "depth_quotient_32",
                    crate::sample::bounded::depth::depth_quotient_32(num, den),
                ),
                (
                    "depth_quotient_wide",
                    crate::sample::bounded::depth::depth_quotient_wide(num, den),
                ),
            ] {
                assert_eq!(
                    i128::from(got),
                    want,
                    "{name}: num {num} ({num:#x}) den {den} ({den:#x}), seed {seed}"
                );
            }
        };
        let dmax = (1i64 << 55) - 1;
        for den in [
            1,
            2,
            3,
            (1 << 31) - 1,
            1 << 31,
            (1 << 32) - 1,
            1 << 32,
            dmax,
        ] {
            for num in [
                0,
                1,
                -1,
                128 * den - 1,
                1 - 128 * den,
                den,
                -den,
                den - 1,
                1 - den,
            ] {
                check(num, den);
            }
        }
        for _ in 0..200_000 {
            let den = (r.next_u64() >> (9 + r.next_u64() % 54)).max(1) as i64;
            let lim = 128 * den - 1;
            let num = match r.next_u64() % 4 {
                0 => r.biased(-lim, lim),
                1 => r.int_range(-den, den),
                _ => r.int_range(-lim, lim) >> (r.next_u64() % 40),
            };
            check(num, den);
        }
    }
}
