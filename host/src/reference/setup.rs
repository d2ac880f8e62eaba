//! f64 reference — stage 1, setup (mirrors `uvt_core::setup`, written independently).
//!
//! Same definitions as the core's setup, in f64 with no rounding: class, frustum time
//! span from the plane chords, degeneracy, lens-corner boxes in pixels with the camera-plane test,
//! footprint. The camera-plane test here intersects every segment between two of the six
//! lens-extended points with the half-line (the core instead tests cone membership), so the two
//! implementations check each other.

use uvt_core::{Class, Cull, PixelRect};

use crate::scene::tri::SceneTri;

/// Lens-corner boxes of one axis in pixels; `None` = unbounded side.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RefAxisBoxes {
    /// box minimum at lens −1 and +1
    pub lo: Option<[f64; 2]>,
    /// box maximum at lens −1 and +1
    pub hi: Option<[f64; 2]>,
}

/// Reference setup result.
#[derive(Clone, Copy, Debug)]
pub struct RefSetup {
    /// class
    pub class: Class,
    /// pixels to visit
    pub footprint: PixelRect,
    /// t span in the frustum
    pub span: (f64, f64),
    /// boxes `[x, y]`
    pub axes: [RefAxisBoxes; 2],
    /// the triangle
    pub tri: SceneTri,
    /// viewport (W, H)
    pub vp: (u16, u16),
}

/// Axis coordinate (x or −y) and lens coefficient (c or −c) of a vertex `[x,y,z,w,c]`.
pub fn axis(v: &[f64; 5], ax: usize) -> (f64, f64) {
    if ax == 0 {
        (v[0], v[4])
    } else {
        (-v[1], -v[4])
    }
}

/// Class by the same rule as the core.
pub fn classify(t: &SceneTri) -> Class {
    let defocus = t.t0.iter().chain(t.t1.iter()).any(|v| v[4] != 0.0);
    let motion =
        t.t0.iter()
            .zip(t.t1.iter())
            .any(|(a, b)| (0..4).any(|f| a[f] != b[f]) || (defocus && a[4] != b[4]));
    match (motion, defocus) {
        (false, false) => Class::Static,
        (true, false) => Class::Motion,
        (false, true) => Class::Defocus,
        (true, true) => Class::MotionDefocus,
    }
}

/// {s ∈ [lo, hi] : s·d ≤ n}, or None.
pub fn solve_le(d: f64, n: f64, lo: f64, hi: f64) -> Option<(f64, f64)> {
    let (a, b) = if d > 0.0 {
        (lo, hi.min(n / d))
    } else if d < 0.0 {
        (lo.max(n / d), hi)
    } else if n >= 0.0 {
        (lo, hi)
    } else {
        return None;
    };
    (a <= b).then_some((a, b))
}

fn span(t: &SceneTri) -> Option<(f64, f64)> {
    let mut s = (0.0, 1.0);
    let wmax = |vs: &[[f64; 5]; 3]| vs.iter().map(|v| v[3]).fold(f64::MIN, f64::max);
    let (a, b) = (wmax(&t.t0), wmax(&t.t1));
    if a <= 0.0 && b <= 0.0 {
        return None;
    }
    s = solve_le(a - b, a, s.0, s.1)?;
    for ax in 0..2 {
        for sign in [-1.0, 1.0] {
            let dist = |vs: &[[f64; 5]; 3]| {
                vs.iter()
                    .map(|v| {
                        let (x, c) = axis(v, ax);
                        v[3] + sign * x + c.abs()
                    })
                    .fold(f64::MIN, f64::max)
            };
            let (a, b) = (dist(&t.t0), dist(&t.t1));
            s = solve_le(a - b, a, s.0, s.1)?;
        }
    }
    Some(s)
}

fn det(p: [[f64; 3]; 3]) -> f64 {
    let [a, b, c] = p;
    a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
        + a[2] * (b[0] * c[1] - b[1] * c[0])
}

fn degenerate(t: &SceneTri) -> bool {
    for tt in [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0] {
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)] {
            let p = [0, 1, 2].map(|k| {
                let l = |f: usize| t.t0[k][f] + tt * (t.t1[k][f] - t.t0[k][f]);
                [l(0) + u * l(4), l(1) + v * l(4), l(3)]
            });
            if det(p) != 0.0 {
                return false;
            }
        }
    }
    true
}

/// Does the hull of `pts` (a, w) meet {(s·dir, 0) : s ≥ 0}? Some segment between two points
/// (or a point) meets it iff the hull does.
pub fn crosses(pts: &[(f64, f64)], dir: f64) -> bool {
    for (i, &(a1, w1)) in pts.iter().enumerate() {
        for &(a2, w2) in &pts[i..] {
            if w1 == 0.0 && w2 == 0.0 {
                if a1 * dir >= 0.0 || a2 * dir >= 0.0 {
                    return true;
                }
            } else if (w1 <= 0.0 && w2 >= 0.0) || (w1 >= 0.0 && w2 <= 0.0) {
                let s = w1 / (w1 - w2);
                if (a1 + s * (a2 - a1)) * dir >= 0.0 {
                    return true;
                }
            }
        }
    }
    false
}

fn boxes(t: &SceneTri, ax: usize, e: f64) -> RefAxisBoxes {
    let all: Vec<[f64; 5]> = t.t0.iter().chain(t.t1.iter()).copied().collect();
    let ext = |sgn: f64| {
        all.iter()
            .map(|v| {
                let (a, c) = axis(v, ax);
                (a + sgn * c.abs(), v[3])
            })
            .collect::<Vec<_>>()
    };
    let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
    let mut front = false;
    for v in all.iter().filter(|v| v[3] > 0.0) {
        front = true;
        let (a, c) = axis(v, ax);
        for (k, lens) in [-1.0, 1.0].into_iter().enumerate() {
            let x = (a + lens * c + v[3]) * e / (2.0 * v[3]);
            lo[k] = lo[k].min(x);
            hi[k] = hi[k].max(x);
        }
    }
    RefAxisBoxes {
        lo: (front && !crosses(&ext(-1.0), -1.0)).then_some(lo),
        hi: (front && !crosses(&ext(1.0), 1.0)).then_some(hi),
    }
}

fn range(b: &RefAxisBoxes, e: f64) -> (u16, u16) {
    let p0 = b.lo.map_or(0.0, |l| l[0].min(l[1]).floor());
    let p1 = b.hi.map_or(e, |h| h[0].max(h[1]).floor() + 1.0);
    (p0.clamp(0.0, e) as u16, p1.clamp(0.0, e) as u16)
}

/// Setup one triangle.
pub fn setup(t: &SceneTri, vp: (u16, u16)) -> Result<RefSetup, Cull> {
    let class = classify(t);
    let span = span(t).ok_or(Cull::Outside)?;
    if degenerate(t) {
        return Err(Cull::Degenerate);
    }
    let (w, h) = (vp.0 as f64, vp.1 as f64);
    let axes = [boxes(t, 0, w), boxes(t, 1, h)];
    let (x0, x1) = range(&axes[0], w);
    let (y0, y1) = range(&axes[1], h);
    let footprint = PixelRect { x0, y0, x1, y1 };
    if footprint.is_empty() {
        return Err(Cull::Outside);
    }
    Ok(RefSetup {
        class,
        footprint,
        span,
        axes,
        tri: *t,
        vp,
    })
}
