//! Triangle kinds of the conservativeness tests (`tests/tests/model/conservative.rs`), shared
//! with the auto, edge-time, motion-unit, planar, row-span, static-unit, strategy-ops and Zmax
//! tests.

use uvt_core::Triangle;

use crate::{c, tri, Rng};

/// Triangle kinds of the conservativeness tests.
#[derive(Clone, Copy, Debug)]
pub enum Kind {
    /// in focus, not moving
    Static,
    /// moving, in focus
    Moving,
    /// defocused, not moving
    Defocus,
    /// moving and defocused
    Both,
    /// crossing the camera plane (w of either sign)
    Crossing,
    /// values at the domain's extremes (±2^13) and zeros
    Extreme,
    /// a near-degenerate sliver whose third vertex crosses the long edge during the shutter when
    /// p[7] > 0 (orientation flip through degeneracy)
    Sliver,
    /// one vertex exactly on the camera plane (w = 0) at both ends
    WZero,
}

/// Every kind, in declaration order (the conservativeness tests pick from it by index).
pub const ALL_KINDS: [Kind; 8] = [
    Kind::Static,
    Kind::Moving,
    Kind::Defocus,
    Kind::Both,
    Kind::Crossing,
    Kind::Extreme,
    Kind::Sliver,
    Kind::WZero,
];

/// Parameters per triangle.
pub const NP: usize = 48;

/// Proptest's strategy for a kind's parameters: [`NP`] values in [−1, 1] (proptest's arrays
/// stop at 32, hence two).
pub fn params() -> impl proptest::strategy::Strategy<Value = [f64; NP]> {
    use proptest::strategy::Strategy;
    proptest::array::uniform32(-1.0f64..=1.0).prop_flat_map(|a| {
        proptest::array::uniform16(-1.0f64..=1.0).prop_map(move |b| {
            let mut p = [0.0; NP];
            p[..32].copy_from_slice(&a);
            p[32..].copy_from_slice(&b);
            p
        })
    })
}

/// Map parameters in [-1, 1] to a triangle of the given kind (shrinks toward simple shapes).
pub fn make(kind: Kind, p: &[f64; NP]) -> Triangle {
    if let Kind::Extreme = kind {
        let lim = (1i64 << 29) as f64 / 65536.0;
        let e = |x: f64| {
            if x.abs() > 0.9 {
                lim * x.signum()
            } else if x.abs() < 0.05 {
                0.0
            } else {
                x * lim * if x.abs() > 0.5 { 1.0 } else { 0.001 }
            }
        };
        let v = |o: usize| [e(p[o]), e(p[o + 1]), e(p[o + 2]), e(p[o + 3]), e(p[o + 4])];
        return tri([v(0), v(5), v(10)], [v(15), v(20), v(25)]);
    }
    if let Kind::Sliver = kind {
        let (ax, ay, bx, by) = (1.2 * p[0], 1.2 * p[1], 1.2 * p[2], 1.2 * p[3]);
        let s = 0.5 + 0.5 * p[4];
        let (dx, dy) = (bx - ax, by - ay);
        let len = (dx * dx + dy * dy).sqrt().max(1e-3);
        let off = 2e-3 * p[5];
        let flip = if p[7] > 0.0 { -1.0 } else { 1.0 };
        let coc = if p[9] > 0.0 { 0.2 * p[8] } else { 0.0 };
        let v = |k: usize, o: f64| {
            let (nx, ny) = match k {
                0 => (ax, ay),
                1 => (bx, by),
                _ => (ax + s * dx - o * dy / len, ay + s * dy + o * dx / len),
            };
            let w = 1.5 + p[10 + k];
            [nx * w, ny * w, 0.5 * w, w, coc]
        };
        return tri(
            [v(0, off), v(1, off), v(2, off)],
            [v(0, off), v(1, off), v(2, flip * off)],
        );
    }
    if let Kind::WZero = kind {
        let v = |k: usize, o: usize| {
            if k == 0 {
                return [3.0 * p[o], 3.0 * p[o + 1], 0.0, 0.0, 0.0];
            }
            let w = 1.5 + p[o + 2 + k];
            let (nx, ny) = (1.2 * p[o + 4 + k], 1.2 * p[o + 6 + k]);
            [
                nx * w,
                ny * w,
                0.5 * w,
                w,
                if p[40] > 0.0 { 0.2 * p[41] } else { 0.0 },
            ]
        };
        let o1 = if p[42] > 0.0 { 10 } else { 0 };
        return tri([v(0, 0), v(1, 0), v(2, 0)], [v(0, o1), v(1, o1), v(2, o1)]);
    }
    if let Kind::Crossing = kind {
        let v = |k: usize, o: usize| {
            let w = 3.0 * p[o + k];
            [
                3.0 * p[o + 3 + k],
                3.0 * p[o + 6 + k],
                0.5 * w,
                w,
                if p[40] > 0.0 { 0.3 * p[41] } else { 0.0 },
            ]
        };
        return tri([v(0, 0), v(1, 0), v(2, 0)], [v(0, 9), v(1, 9), v(2, 9)]);
    }
    let (cx, cy) = (1.2 * p[0], 1.2 * p[1]);
    let w = 1.0 + 2.5 * (p[2] + 1.0);
    let s = 0.05 + 0.6 * p[3].abs();
    let motion = matches!(kind, Kind::Moving | Kind::Both);
    let defocus = matches!(kind, Kind::Defocus | Kind::Both);
    let (a, b) = (0.15 * p[22], 0.3 * p[23]);
    let coc = |w: f64, k: usize| {
        if defocus {
            a * w + b + 0.05 * p[24 + k]
        } else {
            0.0
        }
    };
    let mut t0 = [[0.0; 5]; 3];
    let mut t1 = [[0.0; 5]; 3];
    for k in 0..3 {
        let (nx, ny) = (cx + s * p[4 + 2 * k], cy + s * p[5 + 2 * k]);
        let wk = w * (1.0 + 0.3 * p[10 + k]);
        t0[k] = [nx * wk, ny * wk, 0.5 * wk, wk, coc(wk, k)];
        t1[k] = if motion {
            let (mx, my) = (
                nx + 1.5 * p[13] + 0.2 * p[16 + k],
                ny + 1.5 * p[14] + 0.2 * p[19 + k],
            );
            let w1 = wk * (1.0 + 0.5 * p[15]);
            [mx * w1, my * w1, 0.5 * w1 + 0.1 * p[27 + k], w1, coc(w1, k)]
        } else {
            t0[k]
        };
    }
    tri(t0, t1)
}

/// The kinds the planar and static-unit tests make static with [`make_static`]: regular,
/// crossing the camera plane, one vertex at w = 0, slivers, domain extremes, and the moving
/// kind's shapes (large, guard band).
pub const STATIC_KINDS: [Kind; 6] = [
    Kind::Static,
    Kind::Crossing,
    Kind::WZero,
    Kind::Sliver,
    Kind::Extreme,
    Kind::Moving,
];

/// A triangle of `kind` from fresh random parameters in [-1, 1], made static and in focus (its
/// t1 vertices replaced by t0, every CoC 0): the static triangles of the planar and static-unit
/// tests, every kind's shapes (guard band, crossers, w = 0, slivers, extremes).
pub fn make_static(kind: Kind, rng: &mut Rng) -> Triangle {
    let mut p = [0.0; NP];
    for x in p.iter_mut() {
        *x = rng.range(-1.0, 1.0);
    }
    let mut v = make(kind, &p).vertices(0);
    for x in v.iter_mut() {
        x.coc = c(0.0);
    }
    Triangle::new_static(v).expect("static triangle in the domain")
}
