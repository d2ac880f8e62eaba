//! f64 reference — stage 3, the sample test (mirrors `uvt_core::sample`, decided differently).
//!
//! Coverage by a ray–triangle intersection (McGuire et al. 2010 §3.4, Möller–Trumbore, with
//! ε = 0): the vertices are interpolated to the sample's t and moved by its lens point, and the ray
//! from the camera through the sample's NDC direction (gx, gy, 1) in clip (x, y, w) space must hit
//! the triangle at positive distance with all barycentrics ≥ 0. No edge functions, no fill rule:
//! exactly-on-edge samples may go to both or neither neighbour here (measured, not hidden).

use glam::DVec3;

use crate::scene::tri::SceneTri;

/// Vertices `(x, y, w)` and z at (t, u, v).
pub fn positions(tri: &SceneTri, t: f64, u: f64, v: f64) -> ([DVec3; 3], [f64; 3]) {
    let mut p = [DVec3::ZERO; 3];
    let mut z = [0.0; 3];
    for k in 0..3 {
        let l = |f: usize| tri.t0[k][f] + t * (tri.t1[k][f] - tri.t0[k][f]);
        let c = l(4);
        p[k] = DVec3::new(l(0) + u * c, l(1) + v * c, l(3));
        z[k] = l(2);
    }
    (p, z)
}

/// NDC direction of a screen position in pixels (x right, y down).
pub fn direction(vp: (u16, u16), x: f64, y: f64) -> DVec3 {
    DVec3::new(
        2.0 * x / vp.0 as f64 - 1.0,
        1.0 - 2.0 * y / vp.1 as f64,
        1.0,
    )
}

/// Ray test at screen position (x, y) px, lens (u, v), time t. Returns the depth z/w on a hit.
pub fn sample_test(
    tri: &SceneTri,
    vp: (u16, u16),
    x: f64,
    y: f64,
    u: f64,
    v: f64,
    t: f64,
) -> Option<f64> {
    let (p, z) = positions(tri, t, u, v);
    let d = direction(vp, x, y);
    let (e1, e2) = (p[1] - p[0], p[2] - p[0]);
    let pv = d.cross(e2);
    let det = e1.dot(pv);
    if det == 0.0 {
        return None;
    }
    let inv = 1.0 / det;
    let tv = -p[0];
    let b1 = tv.dot(pv) * inv;
    let qv = tv.cross(e1);
    let b2 = d.dot(qv) * inv;
    let dist = e2.dot(qv) * inv;
    if b1 < 0.0 || b2 < 0.0 || b1 + b2 > 1.0 || dist <= 0.0 {
        return None;
    }
    let b0 = 1.0 - b1 - b2;
    let zh = b0 * z[0] + b1 * z[1] + b2 * z[2];
    let wh = b0 * p[0].z + b1 * p[1].z + b2 * p[2].z;
    Some(zh / wh)
}

/// Distance in pixels from screen position (x, y) to the nearest edge of the triangle at
/// (t, u, v): point-to-segment distance between projected vertices when all three are in front
/// of the camera, otherwise the distance to the nearest edge *line* through the camera-plane-safe
/// homogeneous edge function (a lower bound on the segment distance).
pub fn edge_distance_px(
    tri: &SceneTri,
    vp: (u16, u16),
    x: f64,
    y: f64,
    u: f64,
    v: f64,
    t: f64,
) -> f64 {
    let (p, _) = positions(tri, t, u, v);
    let (w, h) = (vp.0 as f64, vp.1 as f64);
    if p.iter().all(|q| q.z > 0.0) {
        let s = p.map(|q| ((q.x / q.z + 1.0) * w / 2.0, (1.0 - q.y / q.z) * h / 2.0));
        (0..3)
            .map(|k| {
                let (a, b) = (s[k], s[(k + 1) % 3]);
                let (dx, dy) = (b.0 - a.0, b.1 - a.1);
                let l2 = dx * dx + dy * dy;
                let f = if l2 > 0.0 {
                    (((x - a.0) * dx + (y - a.1) * dy) / l2).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                ((x - a.0 - f * dx).powi(2) + (y - a.1 - f * dy).powi(2)).sqrt()
            })
            .fold(f64::MAX, f64::min)
    } else {
        let d = direction(vp, x, y);
        (0..3)
            .map(|k| {
                let n = p[(k + 1) % 3].cross(p[(k + 2) % 3]);
                // E(X, Y) = n·(2X/W − 1, 1 − 2Y/H, 1): gradient in pixels (2n.x/W, −2n.y/H).
                let g = ((2.0 * n.x / w).powi(2) + (2.0 * n.y / h).powi(2)).sqrt();
                if g > 0.0 {
                    n.dot(d).abs() / g
                } else {
                    f64::MAX
                }
            })
            .fold(f64::MAX, f64::min)
    }
}
