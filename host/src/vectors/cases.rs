//! The named edge cases of the unit-level vector set: triangles for each stage's corner cases
//! (camera-plane crossings, w = 0 vertices, zero area, shared-edge ties, huge motion and CoC,
//! domain limits), by name. The unit set runs every stage on them (`export`); the bounded
//! sample-test records use them too (`bsample`).

use uvt_core::Triangle;

use crate::scene::tri::quantize;

fn v(a: [f64; 5]) -> uvt_core::Vertex {
    let q = quantize;
    uvt_core::Vertex {
        x: q(a[0]),
        y: q(a[1]),
        z: q(a[2]),
        w: q(a[3]),
        coc: q(a[4]),
    }
}

/// A generator triangle from f64 vertices at both ends (rounded to nearest I16F16).
pub(super) fn tri(a: [[f64; 5]; 3], b: [[f64; 5]; 3]) -> Triangle {
    Triangle::new(a.map(v), b.map(v)).expect("generator triangle inside the domain")
}

/// A triangle around the centre at w = 1 (the named cases' base).
pub(super) fn base_tri() -> [[f64; 5]; 3] {
    [
        [-0.5, -0.5, 0.25, 1.0, 0.0],
        [0.5, -0.5, 0.25, 1.0, 0.0],
        [0.0, 0.5, 0.25, 1.0, 0.0],
    ]
}

/// Named edge cases: (name, triangles, viewport side).
pub(super) fn named_cases() -> Vec<(&'static str, Vec<Triangle>, u16)> {
    let base = [
        [-0.5, -0.5, 0.25, 1.0, 0.0],
        [0.5, -0.5, 0.25, 1.0, 0.0],
        [0.0, 0.5, 0.25, 1.0, 0.0],
    ];
    let with = |f: &dyn Fn([f64; 5]) -> [f64; 5]| base.map(f);
    let m = 8191.9;
    vec![
        (
            "camera-plane crossing during the shutter",
            vec![
                tri(
                    with(&|v| [v[0], v[1], v[2], 1.0, 0.0]),
                    with(&|v| [v[0] + 0.3, v[1], v[2], -0.5, 0.0]),
                ),
                tri(
                    with(&|v| [v[0], v[1], v[2], 2.0, 0.1]),
                    [
                        [-0.5, -0.5, 0.2, -1.0, -0.1],
                        [0.5, -0.5, 0.2, 1.5, 0.05],
                        [0.0, 0.5, 0.2, 0.5, 0.0],
                    ],
                ),
            ],
            32,
        ),
        (
            "a vertex at w = 0",
            vec![
                tri(
                    [
                        [0.3, 0.2, 0.0, 0.0, 0.0],
                        [0.5, -0.5, 0.25, 1.0, 0.0],
                        [-0.5, -0.5, 0.25, 1.0, 0.0],
                    ],
                    [
                        [0.3, 0.2, 0.0, 0.0, 0.0],
                        [0.5, -0.5, 0.25, 1.0, 0.0],
                        [-0.5, -0.5, 0.25, 1.0, 0.0],
                    ],
                ),
                tri(
                    [
                        [0.0, 0.0, 0.0, 0.0, 0.0],
                        [0.5, -0.5, 0.25, 1.0, 0.0],
                        [-0.5, -0.5, 0.25, 1.0, 0.0],
                    ],
                    [
                        [0.2, 0.0, 0.1, 0.5, 0.0],
                        [0.5, -0.5, 0.25, 1.0, 0.0],
                        [-0.5, -0.5, 0.25, 1.0, 0.0],
                    ],
                ),
            ],
            32,
        ),
        (
            "zero area (always, and at one end only)",
            vec![
                tri(
                    [
                        [-0.5, 0.0, 0.2, 1.0, 0.0],
                        [0.0, 0.0, 0.2, 1.0, 0.0],
                        [0.5, 0.0, 0.2, 1.0, 0.0],
                    ],
                    [
                        [-0.5, 0.0, 0.2, 1.0, 0.0],
                        [0.0, 0.0, 0.2, 1.0, 0.0],
                        [0.5, 0.0, 0.2, 1.0, 0.0],
                    ],
                ),
                tri(
                    [
                        [-0.5, 0.0, 0.2, 1.0, 0.0],
                        [0.0, 0.0, 0.2, 1.0, 0.0],
                        [0.5, 0.0, 0.2, 1.0, 0.0],
                    ],
                    base,
                ),
            ],
            32,
        ),
        (
            "shared-edge ties (samples exactly on the shared edge x = 0)",
            vec![
                tri(
                    [
                        [0.0, 0.5, 0.2, 1.0, 0.0],
                        [0.0, -0.5, 0.2, 1.0, 0.0],
                        [-0.5, 0.0, 0.2, 1.0, 0.0],
                    ],
                    [
                        [0.0, 0.5, 0.2, 1.0, 0.0],
                        [0.0, -0.5, 0.2, 1.0, 0.0],
                        [-0.5, 0.0, 0.2, 1.0, 0.0],
                    ],
                ),
                tri(
                    [
                        [0.0, -0.5, 0.2, 1.0, 0.0],
                        [0.0, 0.5, 0.2, 1.0, 0.0],
                        [0.5, 0.0, 0.2, 1.0, 0.0],
                    ],
                    [
                        [0.0, -0.5, 0.2, 1.0, 0.0],
                        [0.0, 0.5, 0.2, 1.0, 0.0],
                        [0.5, 0.0, 0.2, 1.0, 0.0],
                    ],
                ),
            ],
            32,
        ),
        (
            "huge motion (across the whole domain)",
            vec![tri(
                with(&|v| [v[0] * 10.0 - 8000.0, v[1] * 10.0, v[2], 10.0, 0.0]),
                with(&|v| [v[0] * 10.0 + 8000.0, v[1] * 10.0, v[2], 10.0, 0.0]),
            )],
            64,
        ),
        (
            "huge CoC (|c| at the domain limit)",
            vec![
                tri(
                    with(&|v| [v[0], v[1], v[2], 1.0, m]),
                    with(&|v| [v[0], v[1], v[2], 1.0, m]),
                ),
                tri(
                    with(&|v| [v[0], v[1], v[2], 1.0, -m]),
                    with(&|v| [v[0] + 0.5, v[1], v[2], 1.0, m]),
                ),
            ],
            64,
        ),
        (
            "domain limits (every coordinate near ±8192, viewport 2048)",
            vec![
                tri(
                    [[-m, -m, m, m, m], [m, -m, -m, m, -m], [0.0, m, m, m, m]],
                    [[m, m, -m, m, -m], [-m, m, m, m, m], [0.0, -m, -m, m, -m]],
                ),
                tri(
                    [
                        [m, m, m, 1.0 / 65536.0, 0.0],
                        [-m, m, m, m, 0.0],
                        [m, -m, m, m, 0.0],
                    ],
                    [
                        [m, m, m, 1.0 / 65536.0, 0.0],
                        [-m, m, m, m, 0.0],
                        [m, -m, m, m, 0.0],
                    ],
                ),
            ],
            2048,
        ),
    ]
}
