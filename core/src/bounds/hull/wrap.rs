//! The swept cone's faces by gift wrapping (Jarvis's march), for point sets with every w > 0:
//! the same faces, in the same order and with the same coefficients, as the search over all
//! pairs ([`pair_faces`](crate::bounds::hull::faces::pair_faces)), at O(n·h) instead of O(n³)
//! work (n points, h faces).
//!
//! **Why the faces are the same.** For points with w > 0, `(p × q)·r = w_p·w_q·w_r·o(P, Q, R)`
//! with `o` the orientation of the projected points `P = (x/w, y/w)`, so a plane through the
//! origin and two points with every point on one side is a line through two projected points
//! with every projected point on one side: a supporting line of the projected hull through two
//! distinct points, i.e. the line of one of its edges (all points on one line: that line, both
//! orientations). The pair search finds each such line first at the pair (i, j), i < j, that
//! comes first in its loop order among the pairs of points on the line with `p_i × p_j ≠ 0`,
//! and keeps `±(p_i × p_j)` (the sign that puts the points on the non-negative side; both, the
//! plus sign first, when all points lie on the line). The march visits every edge of the
//! projected hull once (below), and for each it finds that pair again from the set S of points
//! on the edge's line and keeps the same normal; the faces are then sorted by (i, j), the pair
//! search's order of discovery.
//!
//! **The march.** Start at the point with the least projection in (x, y) lexicographic order, an
//! extreme point. From an extreme point c, the next point is the candidate nx with no point on
//! the negative side of `c × nx` (a point r with `(c × nx)·r < 0` replaces nx), and among points
//! on the line the farthest from c (a point with `(c × nx)·r = 0` farther along the ray
//! replaces nx): nx is then an extreme point too and c → nx an edge with every point on its
//! left or on it. All points on one ray from c occur only when all points are collinear (c is
//! extreme); that case is the first edge's S holding every point. The march ends when it
//! returns to the start's projection; it stops (falling back) after more steps than faces can
//! exist. Points with the start's projection are never "farther", so the march skips them.
//!
//! **Ranges.** |x|, |y| ≤ 2^30, 0 < w ≤ 2^29 (`swept_points`): projections compare by
//! `x_a·w_b < x_b·w_a` (< 2^59 each side), distances along an axis by
//! `|x_b·w_c − x_c·w_b|·w_a` (< 2^60 · 2^29 = 2^89); `cross` and `dot` as in `faces.rs`
//! (< 2^61, < 2^93). All in i128, exact.
#![warn(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_possible_wrap
)]

use crate::bounds::hull::faces::{cross, dot, face_of, HullCoeffs, MAX_FACES};
use crate::input::Viewport;
use crate::stats::Ops;

/// Whether every point has w > 0 (the march applies).
pub fn all_in_front(pts: &[[i64; 3]]) -> bool {
    pts.iter().all(|p| p[2] > 0)
}

/// `(x·w', y·w')` of `p` against `q`'s w, for comparing projections: exact (module docs).
#[allow(clippy::arithmetic_side_effects)]
fn scaled(p: &[i64; 3], q: &[i64; 3]) -> (i128, i128) {
    let wq = i128::from(q[2]);
    (i128::from(p[0]) * wq, i128::from(p[1]) * wq)
}

/// Whether p's projection is before q's in (x, y) lexicographic order (w > 0 both).
fn before(p: &[i64; 3], q: &[i64; 3]) -> bool {
    let (px, py) = scaled(p, q);
    let (qx, qy) = scaled(q, p);
    px < qx || (px == qx && py < qy)
}

/// Whether p and q have the same projection.
fn same_point(p: &[i64; 3], q: &[i64; 3]) -> bool {
    scaled(p, q) == scaled(q, p)
}

/// Whether b is strictly farther from c than a, for a and b on one ray from c with a's
/// projection distinct from c's: along x, or along y when the ray is vertical (module docs).
#[allow(clippy::arithmetic_side_effects, clippy::indexing_slicing)]
fn farther(c: &[i64; 3], a: &[i64; 3], b: &[i64; 3]) -> bool {
    let (cw, aw, bw) = (i128::from(c[2]), i128::from(a[2]), i128::from(b[2]));
    let along = |k: usize, p: &[i64; 3]| {
        let (pk, ck) = (i128::from(p[k]), i128::from(c[k]));
        (pk * cw - ck * i128::from(p[2])).abs()
    };
    // k ∈ {0, 1}: an index of the 3-element points.
    let k = if along(0, a) != 0 { 0 } else { 1 };
    // |P_k − C_k| = along/(w_p·w_c): compare along_b·w_a with along_a·w_b.
    along(k, b) * aw > along(k, a) * bw
}

/// One face found by the march: its normal and the pair (i, j) that names it.
#[derive(Clone, Copy, Default)]
struct Found {
    key: (usize, usize),
    normal: [i128; 3],
}

/// The points on the plane of `n`: the first pair (i < j) of them whose cross product is not
/// zero, that cross product, and whether every point is on the plane; 6 ops per point and 9
/// per pair tried.
fn first_pair(
    pts: &[[i64; 3]],
    n: &[i128; 3],
    ops: &mut Ops,
) -> Option<(usize, usize, [i128; 3], bool)> {
    let mut on = [false; 24];
    let mut all = true;
    for (flag, r) in on.iter_mut().zip(pts) {
        ops.add_setup(6);
        *flag = dot(n, r) == 0;
        all &= *flag;
    }
    for (i, p) in pts.iter().enumerate() {
        if !on.get(i).copied().unwrap_or(false) {
            continue;
        }
        for (j, q) in pts.iter().enumerate().skip(i.saturating_add(1)) {
            if !on.get(j).copied().unwrap_or(false) {
                continue;
            }
            ops.add_setup(9);
            let m = cross(p, q);
            if m != [0; 3] {
                return Some((i, j, m, all));
            }
        }
    }
    None
}

/// `m` with the orientation of `n` (both normals of one plane, so parallel and non-zero).
fn oriented(m: [i128; 3], n: &[i128; 3]) -> [i128; 3] {
    let flip = m
        .iter()
        .zip(n)
        .find(|(a, _)| **a != 0)
        .is_some_and(|(a, b)| (*a > 0) != (*b > 0));
    if flip {
        m.map(|v| v.saturating_neg())
    } else {
        m
    }
}

/// The faces of the cone of `pts` (every w > 0), identical to
/// [`pair_faces`](crate::bounds::hull::faces::pair_faces)'s; `None` when the march does not
/// apply (some w ≤ 0, or a check fails, which the module docs rule out): then the caller uses
/// the pair search.
pub fn wrap_faces(pts: &[[i64; 3]], vp: Viewport, ops: &mut Ops) -> Option<HullCoeffs> {
    if !all_in_front(pts) || pts.len() > 24 {
        return None;
    }
    let mut start = pts.first()?;
    for p in pts {
        ops.add_setup(6);
        if before(p, start) {
            start = p;
        }
    }
    let mut found = [Found::default(); MAX_FACES];
    let mut nf = 0usize;
    let mut c = start;
    loop {
        // The first candidate with a projection other than c's.
        let mut nx = None;
        for r in pts {
            ops.add_setup(4);
            if !same_point(r, c) {
                nx = Some(r);
                break;
            }
        }
        let Some(mut nx) = nx else {
            break; // every point at one projection: no face (the pair search finds none)
        };
        let mut n = cross(c, nx);
        ops.add_setup(9);
        for r in pts {
            ops.add_setup(7);
            let d = dot(&n, r);
            let replace = d < 0
                || (d == 0 && {
                    ops.add_setup(8);
                    farther(c, nx, r)
                });
            if replace {
                nx = r;
                n = cross(c, nx);
                ops.add_setup(9);
            }
        }
        let (i, j, m, all_on_line) = first_pair(pts, &n, ops)?;
        if all_on_line {
            // Every point on one line: that line, both orientations, + first (pair search).
            let mut out = HullCoeffs::EMPTY;
            for s in [m, m.map(|v| v.saturating_neg())] {
                let (Some(f), Some(slot)) = (face_of(&s, vp), out.faces.get_mut(out.len)) else {
                    continue;
                };
                ops.add_setup(8);
                *slot = f;
                out.len = out.len.saturating_add(1);
            }
            return Some(out);
        }
        let m = oriented(m, &n);
        let slot = found.get_mut(nf)?;
        *slot = Found {
            key: (i, j),
            normal: m,
        };
        nf = nf.saturating_add(1);
        if same_point(nx, start) {
            break;
        }
        c = nx;
    }
    // The pair search's order of discovery (insertion sort; at most 24 faces).
    let found = found.get_mut(..nf)?;
    for k in 1..found.len() {
        let mut l = k;
        while l > 0 {
            let (Some(a), Some(b)) = (found.get(l.saturating_sub(1)), found.get(l)) else {
                break;
            };
            if a.key <= b.key {
                break;
            }
            found.swap(l.saturating_sub(1), l);
            l = l.saturating_sub(1);
        }
    }
    let mut out = HullCoeffs::EMPTY;
    for f in found.iter() {
        let (Some(face), Some(slot)) = (face_of(&f.normal, vp), out.faces.get_mut(out.len)) else {
            continue;
        };
        ops.add_setup(8);
        *slot = face;
        out.len = out.len.saturating_add(1);
    }
    Some(out)
}
