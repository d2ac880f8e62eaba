//! Tests of the interval solvers' narrow fast paths against the i128 computations they
//! replaced: the reciprocals `floor/ceil(2^80/|d|)` without a 128-bit divide, the reciprocal
//! products without a 128 × 128 multiply, [`frac_div`] (one 32-bit divide and a correction) and
//! [`solve_le`]/[`solve_le64`] — every result **identical**, at the ends of each branch and on
//! seeded random operands (`UVT_SEED`, printed on failure; `UVT_EXTENSIVE=1` for more).
// Test code: reference computations in plain i128 on values ≤ 2^100; an overflow panics, which
// is the failure signal of a test.
#![allow(
    clippy::arithmetic_side_effects,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_possible_wrap
)]

use crate::arith::interval::{frac_div, solve_le, solve_le64, Interval, RecipConstraint};
use crate::config::formats::TUV_ONE;

/// An interval the solvers may return (test-only constructor).
fn iv(lo: i32, hi: i32) -> Interval {
    Interval::new(lo, hi).unwrap()
}

/// `x` clamped to [0, 1] raw.
fn clamp(x: i128) -> i32 {
    x.clamp(0, i128::from(TUV_ONE)) as i32
}

/// The old reciprocal: one i128 division each way.
fn recip_i128(d: i64) -> (i128, i128) {
    let k = 1i128 << crate::config::formats::RECIP_SHIFT;
    let a = i128::from(d).abs();
    if a == 0 {
        return (0, 0);
    }
    (-(-k).div_euclid(a), k.div_euclid(a))
}

#[test]
fn recip_matches_i128() {
    let seed = uvt_testkit::seed();
    let mut rng = uvt_testkit::Rng(seed ^ 0x7ec1);
    let mut ds: Vec<i64> = vec![0, 1, -1, 2, 3, 7, 1 << 32, (1 << 32) + 1, (1 << 59) - 1];
    for e in 0..64 {
        let p = 1i64.checked_shl(e).unwrap_or(i64::MAX);
        ds.extend([
            p,
            p.saturating_sub(1),
            p.saturating_add(1),
            p.saturating_neg(),
        ]);
    }
    ds.extend([i64::MAX, i64::MIN, i64::MIN + 1]);
    for _ in 0..uvt_testkit::cases(20_000, 2_000_000) {
        ds.push(rng.signed(1 << 59));
    }
    for d in ds {
        let c = RecipConstraint::new(d);
        let (up, dn) = recip_i128(d);
        assert!(
            c.r_up() == up && c.r_dn() == dn,
            "d={d} ({d:#x}): r_up {} ({:#x}) want {up} ({up:#x}), \
             r_dn {} ({:#x}) want {dn} ({dn:#x}); UVT_SEED={seed}",
            c.r_up(),
            c.r_up(),
            c.r_dn(),
            c.r_dn()
        );
    }
}

#[test]
fn recip_solve_matches_i128_product() {
    // The split product against the i128 product and divide by 2^64 it replaced.
    let seed = uvt_testkit::seed();
    let mut rng = uvt_testkit::Rng(seed ^ 0x5017);
    let mut pairs: Vec<(i64, i64)> = Vec::new();
    for d in [
        1i64,
        -1,
        2,
        3,
        (1 << 40) + 7,
        (1 << 59) - 1,
        -(1 << 59),
        i64::MAX,
        i64::MIN,
    ] {
        for n in [
            0i64,
            1,
            -1,
            d / 3,
            d / 2,
            d.saturating_sub(1),
            d,
            d.saturating_neg(),
        ] {
            pairs.push((d, n));
        }
    }
    for _ in 0..uvt_testkit::cases(50_000, 2_000_000) {
        let d = rng.signed(1 << 62);
        let n = match rng.next_u64() % 3 {
            0 => rng.signed(1 << 62),
            1 => d / 2 + rng.signed(4),
            _ => rng.signed(d.unsigned_abs().min(1 << 62) as i64),
        };
        pairs.push((d, n));
    }
    let sh = 1i128 << 64;
    for (d, n) in pairs {
        let c = RecipConstraint::new(d);
        let (d128, n128) = (i128::from(d), i128::from(n));
        let want = if d > 0 {
            if n < 0 {
                None
            } else if n >= d {
                Some(Interval::UNIT)
            } else {
                let hi = -(-(n128 * c.r_up())).div_euclid(sh);
                Some(iv(0, clamp(hi)))
            }
        } else if d < 0 {
            let (a, b) = (-d128, -n128);
            if b <= 0 {
                Some(Interval::UNIT)
            } else if b > a {
                None
            } else {
                Some(iv(clamp((b * c.r_dn()).div_euclid(sh)), TUV_ONE))
            }
        } else {
            (n >= 0).then_some(Interval::UNIT)
        };
        assert_eq!(
            c.solve(n),
            want,
            "d={d} ({d:#x}) n={n} ({n:#x}); UVT_SEED={seed}"
        );
    }
}

#[test]
fn frac_div_matches_i128() {
    let seed = uvt_testkit::seed();
    let mut rng = uvt_testkit::Rng(seed ^ 0xf7ac);
    let mut cases = vec![
        (0u64, 1u64),
        (1, 2),
        (1 << 62, 1 << 63),
        ((1 << 63) - 1, 1 << 63),
        (2, 3),
    ];
    for _ in 0..uvt_testkit::cases(20_000, 2_000_000) {
        let d = rng.signed(1 << 62).unsigned_abs().max(1) * 2;
        let n = rng.next_u64() % d;
        cases.push((n, d));
    }
    for (n, d) in cases {
        for k in [0u32, 1, 15, 16] {
            let m = u128::from(n) << k;
            let want = (m / u128::from(d), m % u128::from(d) != 0);
            let got = frac_div(n, d, k);
            assert_eq!(
                got.map(|(q, r)| (u128::from(q), r)),
                Some(want),
                "n={n} ({n:#x}) d={d} ({d:#x}) k={k}; UVT_SEED={seed}"
            );
        }
    }
    // Outside its contract it refuses instead of answering.
    assert_eq!(frac_div(5, 5, 16), None);
    assert_eq!(frac_div(1, (1 << 63) + 1, 16), None);
    assert_eq!(frac_div(1, 2, 17), None);
}

#[test]
fn solve_le_matches_i128_division() {
    // The three quotient paths (64-bit divide, shift-subtract, i128 divide) against the
    // i128 division, at the ends of each path's range and on seeded random operands.
    let seed = uvt_testkit::seed();
    let mut rng = uvt_testkit::Rng(seed ^ 0x501e);
    let want = |d: i128, n: i128| -> Option<Interval> {
        let one = i128::from(TUV_ONE);
        if d > 0 {
            (n >= 0).then(|| iv(0, clamp(-(-(n * one)).div_euclid(d))))
        } else if d < 0 {
            (-n <= -d).then(|| iv(clamp((-n * one).div_euclid(-d)), TUV_ONE))
        } else {
            (n >= 0).then_some(Interval::UNIT)
        }
    };
    let mut cases: Vec<(i128, i128)> = Vec::new();
    for d in [
        1i128,
        3,
        (1 << 47) - 1,
        1 << 47,
        (1 << 47) + 1,
        (1 << 63) - 1,
        1 << 63,
        (1 << 63) + 1,
        1 << 90,
    ] {
        for n in [0, 1, d / 3, d / 2, d - 1, d] {
            cases.extend([(d, n), (-d, -n)]);
        }
    }
    for _ in 0..uvt_testkit::cases(20_000, 2_000_000) {
        let d = i128::from(rng.signed(1 << 62)) * 2 + 1;
        let n = i128::from(rng.next_u64() >> 1) % d.abs();
        cases.extend([(d, n.copysign_like(d)), (d, -n), (d, n)]);
    }
    for (d, n) in cases {
        assert_eq!(
            solve_le(d, n),
            want(d, n),
            "d={d} ({d:#x}) n={n} ({n:#x}); UVT_SEED={seed}"
        );
        if let (Ok(d64), Ok(n64)) = (i64::try_from(d), i64::try_from(n)) {
            assert_eq!(
                solve_le64(d64, n64),
                want(d, n),
                "solve_le64 d={d} ({d:#x}) n={n} ({n:#x}); UVT_SEED={seed}"
            );
        }
    }
}

trait CopySign {
    fn copysign_like(self, o: Self) -> Self;
}
impl CopySign for i128 {
    fn copysign_like(self, o: i128) -> i128 {
        if o < 0 {
            -self
        } else {
            self
        }
    }
}
