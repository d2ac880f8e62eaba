//! The planar depth plane's exponent `f` of a reachable triangle lies in [−62, 68]
//! (`core/src/setup/planar.rs`, `depth_plane`), tighter than the format's [−62, 98] at its
//! top: with `ζ_k = z_k·2^(S − s_k)` (integers) the plane satisfies `P'·Zv = det·ζ`, so a
//! nonzero `Zv` has `max|Zv_i| ≥ |det| / (3·(2^15 − 1))`, and
//! `D / max|Zv| ≤ 2^S·256·W·H·3·(2^15 − 1) < 2^61.6`: `f = bitlen(D) − bitlen(max|Zv|) + 6
//! ≤ 62 + 6`. The mutation flow proves the planar unit's mutants under this bound (a flag of
//! `uvt_psample.v` that only `f ≥ 95` sets, docs/mutation.md); this test is the bound's check:
//! seeded triangles of every kind, and triangles built to approach it (domain-size vertices at
//! shift 15 whose first row is aligned with its normal, one depth of 1 LSB, 2048-pixel sides).

use uvt_core::{PlanarPrecision, Setup, Triangle, Vertex, Viewport};
use uvt_tests::kinds::{make_static, STATIC_KINDS};
use uvt_tests::*;

/// The largest `f` a reachable triangle's depth plane can have (module docs).
const F_MAX: i32 = 68;

fn exponent(t: &Triangle, vp: Viewport) -> Option<i32> {
    let pl = Setup::unculled::<PlanarPrecision>(t, vp).planar()?;
    Some(pl.depth_plane().1)
}

/// Vertices near ±2^29 (every vertex at shift 15), the first one's signs those of the normal
/// of the other two (its row aligned with n_0: det near 3·2^15·|n_0|), depths (±1, 0, 0) or
/// small: `Zv` a few units of `n_0`, `D` as large as the domain allows.
fn extreme(rng: &mut Rng) -> Triangle {
    let big = |rng: &mut Rng| {
        let m = (1i64 << 29) - rng.int_range(0, 1 << 16);
        if rng.below(2) == 0 {
            m
        } else {
            -m
        }
    };
    let p1 = [big(rng), big(rng), big(rng).abs()];
    let p2 = [big(rng), big(rng), big(rng).abs()];
    let n0 = [
        p1[1] as i128 * p2[2] as i128 - p1[2] as i128 * p2[1] as i128,
        p1[2] as i128 * p2[0] as i128 - p1[0] as i128 * p2[2] as i128,
        p1[0] as i128 * p2[1] as i128 - p1[1] as i128 * p2[0] as i128,
    ];
    let p0 = n0.map(|c| {
        let m = (1i64 << 29) - rng.int_range(0, 1 << 16);
        if c < 0 {
            -m
        } else {
            m
        }
    });
    let z0 = rng.int_range(-3, 3);
    let v = |p: [i64; 3], z: i64| {
        Vertex::from_bits([p[0] as i32, p[1] as i32, z as i32, p[2] as i32, 0])
    };
    Triangle::new_static([v(p0, z0), v(p1, 0), v(p2, 0)]).expect("domain-size vertices")
}

#[test]
fn depth_exponent_of_reachable_triangles_is_at_most_68() {
    let seed = seed();
    let mut rng = Rng(seed ^ 0xf6a8);
    let (mut max_f, mut checked) = (i32::MIN, 0u64);
    for i in 0..cases(4000, 200_000) {
        let (t, vp) = if i % 2 == 0 {
            (extreme(&mut rng), Viewport::new(2048, 2048).unwrap())
        } else {
            let side =
                |rng: &mut Rng| [1, 2048, rng.int_range(1, 2048) as u16][rng.below(3) as usize];
            let t = make_static(
                STATIC_KINDS[(i as usize / 2) % STATIC_KINDS.len()],
                &mut rng,
            );
            (t, Viewport::new(side(&mut rng), side(&mut rng)).unwrap())
        };
        let Some(f) = exponent(&t, vp) else { continue };
        checked += 1;
        max_f = max_f.max(f);
        assert!(
            (-62..=F_MAX).contains(&f),
            "UVT_SEED={seed:#x} case {i}: f = {f} outside [−62, {F_MAX}]: {t:?} in {vp:?}"
        );
    }
    // the built triangles come within a few units of the bound (66 at the default seed)
    assert!(checked > 1000, "{checked} triangles with a depth plane");
    assert!(
        max_f >= F_MAX - 6,
        "the largest f reached: {max_f} (bound {F_MAX})"
    );
}
