//! The exact triangle's determinant: whether it vanishes at every (t, u, v) (degenerate), and
//! the static edge normals and determinant sign of the exact test.

use crate::input::{Triangle, C, W, X, Y};
use crate::stats::Ops;

/// Static in-focus edge data: normals `n_k = P_{k+1} × P_{k+2}` and `det`, raw 2·16 fraction bits.
/// Built only by setup from a checked [`Triangle`], so |n| < 2^59 and `det_sign` is ±1.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StaticEdges {
    pub(crate) n: [[i128; 3]; 3],
    pub(crate) det_sign: i32,
}

impl StaticEdges {
    /// Edge normals (a, b, c) per edge.
    pub fn n(&self) -> [[i128; 3]; 3] {
        self.n
    }
    /// Sign of P0·(P1×P2): −1 or 1 (0 is culled).
    pub fn det_sign(&self) -> i32 {
        self.det_sign
    }
}

/// det(P0, P1, P2) of raw (x, y, w) triples, exact in i128 (|P| < 2^33 here, so |det| < 2^102).
#[inline]
// Callers pass |P| < 2^33: products of three < 2^99, the sum of six < 2^102.
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn det3(p: &[[i128; 3]; 3]) -> i128 {
    let [a, b, c] = p;
    a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
        + a[2] * (b[0] * c[1] - b[1] * c[0])
}

/// Whether det(t, u, v) is zero for every t, u, v. det is cubic in t and bilinear in (u, v), so it
/// vanishes identically iff it vanishes at t ∈ {0, 1/3, 2/3, 1} × (u, v) ∈ {0, 1}² (evaluated
/// exactly, scaled by 3 so every point is an integer).
// Ranges: j, u, v ∈ {0..3}; (3 − j)·q + j·r ≤ 3·2^29, plus u·c ≤ 3·2^29: |P| < 2^32 < 2^33 as
// `det3` needs.
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn degenerate(tri: &Triangle, (motion, defocus): (bool, bool), ops: &mut Ops) -> bool {
    let [v0, v1] = &tri.v;
    let tj: &[i128] = if motion { &[0, 1, 2, 3] } else { &[0] };
    let lens: &[i128] = if defocus { &[0, 1] } else { &[0] };
    for &j in tj {
        for &u in lens {
            for &v in lens {
                let mut p = [[0i128; 3]; 3];
                for ((q, r), out) in v0.iter().zip(v1.iter()).zip(p.iter_mut()) {
                    let mut l = [0i128; 5];
                    for ((o, &a), &b) in l.iter_mut().zip(q).zip(r) {
                        *o = (3 - j) * i128::from(a) + j * i128::from(b);
                    }
                    let c = l[C];
                    *out = [l[X] + u * c, l[Y] + v * c, l[W]];
                }
                ops.add_setup(30);
                if det3(&p) != 0 {
                    return false;
                }
            }
        }
    }
    true
}

// |P| ≤ 2^29 raw: each product < 2^58, each normal component < 2^59.
#[allow(clippy::arithmetic_side_effects)]
pub(crate) fn static_edges(tri: &Triangle) -> StaticEdges {
    let p = tri.v[0].map(|q| [q[X], q[Y], q[W]].map(i128::from));
    let det = det3(&p);
    let [p0, p1, p2] = p;
    let n = [(p1, p2), (p2, p0), (p0, p1)].map(|(a, b)| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    });
    StaticEdges {
        n,
        det_sign: if det < 0 { -1 } else { i32::from(det > 0) },
    }
}
