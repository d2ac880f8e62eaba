//! The time span a triangle may spend inside the frustum (Laine 2011 §3.2), widened by the
//! conservative epsilon.

use crate::arith::interval::{solve_le64, Interval};
use crate::input::{Triangle, W};
use crate::setup::boxes::axis_coord;
use crate::setup::eps::Eps;
use crate::stats::Ops;

/// Time span inside the frustum: for each plane w ∓ a ≥ 0 (both axes, widened by |c| for the
/// lens), the largest vertex distance is convex in t and lies below its chord; the chord's
/// non-negative part is a conservative span. The camera plane uses max w > 0 the same way.
/// Conservative epsilon (`bounded.rs`): the bounded test's perturbed vertex has
/// `w' ± a' ≤ w ± a + ε_w + ε_x`, and its hit needs `w' > 0`, i.e. `w + ε_w > 0`: both enter as
/// constant terms (zero for the exact test, which is then unchanged).
// Ranges: every raw field ≤ 2^29 in magnitude, ε ≤ 2^24: w + sign·x + |c| + ε < 2^31 and the
// differences a − b < 2^32, all in i64.
///
/// `MOTION = false` (a unit without motion, whose view of the triangle has equal ends,
/// [`unit_view`]): every chord is constant, `a = b`, and each `solve_le64(a − b, a)` is
/// `solve_le64(0, a)`, which [`constant_le`] gives without the division (`frac_div`), so such
/// a unit's program has none; the operations counted are the same.
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn frustum_span<const MOTION: bool>(
    tri: &Triangle,
    eps: &Eps,
    ops: &mut Ops,
) -> Option<Interval> {
    let solve = |a: i64, b: i64| {
        if MOTION {
            solve_le64(a - b, a)
        } else {
            constant_le(a)
        }
    };
    let [v0, v1] = &tri.v;
    let mut span = Interval::UNIT;
    let ew = i64::from(eps.w);
    // camera plane: a hit needs w > 0, so both ends' max w ≤ 0 means never visible.
    let wmax = |v: &[[i32; 5]; 3]| v.iter().map(|p| i64::from(p[W]) + ew).max().unwrap_or(0);
    let (a, b) = (wmax(v0), wmax(v1));
    ops.add_setup(6);
    if a <= 0 && b <= 0 {
        return None;
    }
    span = span.meet(solve(a, b)?)?;
    for axis in 0..2 {
        let e = ew + i64::from(eps.x.get(axis).copied().unwrap_or(0));
        for sign in [-1i64, 1] {
            let dist = |v: &[[i32; 5]; 3]| {
                v.iter()
                    .map(|p| {
                        let (x, cs) = axis_coord(p, axis);
                        i64::from(p[W]) + sign * x + cs.abs() + e
                    })
                    .max()
                    .unwrap_or(0)
            };
            let (a, b) = (dist(v0), dist(v1));
            ops.add_setup(14);
            span = span.meet(solve(a, b)?)?;
        }
    }
    Some(span)
}

/// `solve_le64(0, n)`: the t ∈ [0, 1] with `0·t ≤ n` — all of them for `n ≥ 0`, none else
/// (the constant chord of a triangle that does not move; `tests::constant_le_is_solve_le64_at_0`).
#[inline]
pub(crate) fn constant_le(n: i64) -> Option<Interval> {
    (n >= 0).then_some(Interval::UNIT)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::arith::interval::solve_le64;

    /// The constant-chord solve of the units without motion equals `solve_le64(0, n)` at the
    /// sign boundary and the ends of the range `frustum_span` feeds it (|n| < 2^32).
    #[test]
    fn constant_le_is_solve_le64_at_0() {
        let cases = [
            i64::MIN,
            -(1 << 32),
            -(1 << 31),
            -2,
            -1,
            0,
            1,
            2,
            1 << 31,
            1 << 32,
            i64::MAX,
        ];
        for n in cases {
            assert_eq!(
                constant_le(n),
                solve_le64(0, n),
                "n = {n} ({n:#x}): expected solve_le64(0, n), observed constant_le(n)"
            );
        }
    }
}
