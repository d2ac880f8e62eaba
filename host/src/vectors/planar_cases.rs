//! The planar sample-test records' own triangles: named cases of the planar static configuration
//! (slivers, camera-plane crossers, guard band, fill-rule ties, domain corners, depth-plane
//! extremes) and domain-end random static triangles (`psample` turns both into records).

use rand::Rng;
use uvt_core::{Triangle, Vertex, Viewport};

use crate::scene::tri::quantize;

fn tri(v: [[f64; 4]; 3]) -> Triangle {
    let q = |a: f64| quantize(a).to_bits();
    Triangle::new_static(v.map(|p| Vertex::from_bits([q(p[0]), q(p[1]), q(p[2]), q(p[3]), 0])))
        .expect("named planar case inside the domain")
}

/// The planar configuration's own named cases: (name, static triangles, viewport side).
pub fn named_cases() -> Vec<(&'static str, Vec<Triangle>, u16)> {
    let m = 8191.9;
    vec![
        (
            "slivers: degenerate after the vertex rounding (culled, no record) and thin but kept",
            vec![
                // y = 0.1 clip units at w = 8000 rounds to 0 with shift 15: all on y' = 0.
                tri([
                    [-4000.0, 0.0, 0.5, 8000.0],
                    [0.0, 0.1, 0.5, 8000.0],
                    [4000.0, 0.0, 0.5, 8000.0],
                ]),
                tri([
                    [-4000.0, 0.0, 0.5, 8000.0],
                    [0.0, 0.3, 0.5, 8000.0],
                    [4000.0, 0.0, 0.5, 8000.0],
                ]),
                tri([
                    [-0.9, -0.9, 0.5, 1.0],
                    [0.9, 0.9, 0.5, 1.0],
                    [0.9, 0.9001, 0.5, 1.0],
                ]),
            ],
            64,
        ),
        (
            "camera-plane crossers and w = 0 vertices (static)",
            vec![
                tri([
                    [-0.5, -0.5, 0.2, -1.0],
                    [0.5, -0.5, 0.2, 1.5],
                    [0.0, 0.5, 0.2, 0.5],
                ]),
                tri([
                    [0.3, 0.2, 0.0, 0.0],
                    [0.5, -0.5, 0.25, 1.0],
                    [-0.5, -0.5, 0.25, 1.0],
                ]),
                tri([
                    [0.0, 0.0, 0.0, 0.0],
                    [-0.5, -0.5, 0.25, 1.0],
                    [0.5, -0.5, 0.25, 1.0],
                ]),
                tri([
                    [-1.0, -1.0, 0.5, -2.0],
                    [1.0, -1.0, 0.5, -2.0],
                    [0.0, 1.0, 0.5, 1.0],
                ]),
                tri([
                    [-1.0, -1.0, 0.5, -1.0],
                    [1.0, -1.0, 0.5, -1.0],
                    [0.0, 1.0, 0.5, -1.0],
                ]),
            ],
            32,
        ),
        (
            "guard band (vertices far off-screen, |x/w| up to 8000)",
            vec![
                tri([
                    [-8000.0, -0.5, 0.5, 1.0],
                    [8000.0, -0.5, 0.5, 1.0],
                    [0.0, 4000.0, 0.5, 1.0],
                ]),
                tri([[-m, -m, 0.5, 0.01], [m, -m, 0.5, 0.01], [0.0, m, 0.5, 0.01]]),
            ],
            61,
        ),
        (
            "fill-rule ties: shared vertical and horizontal edges through the viewport centre",
            vec![
                tri([
                    [0.0, 0.5, 0.2, 1.0],
                    [0.0, -0.5, 0.2, 1.0],
                    [-0.5, 0.0, 0.2, 1.0],
                ]),
                tri([
                    [0.0, -0.5, 0.2, 1.0],
                    [0.0, 0.5, 0.2, 1.0],
                    [0.5, 0.0, 0.2, 1.0],
                ]),
                tri([
                    [-0.5, 0.0, 0.2, 1.0],
                    [0.5, 0.0, 0.2, 1.0],
                    [0.0, 0.5, 0.2, 1.0],
                ]),
                tri([
                    [0.5, 0.0, 0.2, 1.0],
                    [-0.5, 0.0, 0.2, 1.0],
                    [0.0, -0.5, 0.2, 1.0],
                ]),
            ],
            32,
        ),
        (
            "2048-pixel domain corners (coordinates near ±8192, shift 15)",
            vec![
                tri([[-m, -m, m, m], [m, -m, -m, m], [0.0, m, m, m]]),
                tri([[m, m, m, 1.0 / 65536.0], [-m, m, m, m], [m, -m, m, m]]),
                tri([[-m, -m, -m, m], [m, m, -m, m], [m, -m, m, m]]),
            ],
            2048,
        ),
        (
            "saturating depths (z/w beyond ±128) and extreme depth-plane exponents",
            vec![
                tri([
                    [-0.5, -0.5, 8000.0, 1.0],
                    [0.5, -0.5, 8000.0, 1.0],
                    [0.0, 0.5, 8000.0, 1.0],
                ]),
                tri([
                    [-0.5, -0.5, -8000.0, 1.0],
                    [0.5, -0.5, -8000.0, 1.0],
                    [0.0, 0.5, -8000.0, 1.0],
                ]),
                tri([
                    [-0.5, -0.5, 200.0, 1.0],
                    [0.5, -0.5, -129.0, 1.0],
                    [0.0, 0.5, 0.25, 1.0],
                ]),
                tri([
                    [-0.001, -0.001, m, 0.001],
                    [0.001, -0.001, -m, 0.001],
                    [0.0, 0.001, m, 0.001],
                ]),
            ],
            1,
        ),
        (
            "depth-plane exponent f >= 63 (z of one LSB on a large triangle)",
            vec![
                tri([
                    [-m, -m, 1.0 / 65536.0, m],
                    [m, -m, 1.0 / 65536.0, m],
                    [0.0, m, 1.0 / 65536.0, m],
                ]),
                tri([
                    [-m, -m, -1.0 / 65536.0, m],
                    [m, m, 1.0 / 65536.0, m],
                    [m, -m, 0.0, m],
                ]),
            ],
            2048,
        ),
    ]
}

/// Domain-end random static triangles (as the frozen planar contract's test draws them):
/// coordinates anywhere in ±2^29 raw, or a regular triangle whose NDC corners are random at one
/// w or at random w of either sign; viewports of side 1, 2048 or random.
pub fn domain_random(rng: &mut rand_pcg::Pcg64, n: usize) -> Vec<(Triangle, Viewport)> {
    const LIM: i64 = 1 << 29;
    let mut out = Vec::new();
    while out.len() < n {
        let kind = rng.gen_range(0..3);
        let w0 = rng.gen_range(1..=LIM);
        let mut v = [[0i32; 5]; 3];
        for p in v.iter_mut() {
            let mut s = |l: i64| rng.gen_range(-l..=l);
            *p = if kind == 0 {
                [s(LIM), s(LIM), s(LIM), s(LIM), 0].map(|x| x as i32)
            } else {
                let w = if kind == 1 { w0 } else { s(LIM) };
                let (nx, ny, z) = (s(1 << 16), s(1 << 16), s(LIM));
                [(nx * w) >> 16, (ny * w) >> 16, z, w, 0].map(|x| x as i32)
            };
        }
        let side = |rng: &mut rand_pcg::Pcg64| match rng.gen_range(0..4) {
            0 => 2048,
            1 => 1,
            _ => rng.gen_range(1..=2048u16),
        };
        let vp = Viewport::new(side(rng), side(rng)).expect("sides in 1..=2048");
        if let Ok(t) = Triangle::new_static(v.map(Vertex::from_bits)) {
            out.push((t, vp));
        }
    }
    out
}
