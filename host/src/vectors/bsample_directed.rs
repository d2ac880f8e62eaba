//! Bounded records directed at the fill rule's tie key, which the mutation flow's survivors of
//! `uvt_bsample.v` asked for (docs/mutation.md): `κ = cmp((b', a', w)_{k+1}, (b', a',
//! w)_{k+2})`, decided only when a rounded edge value `E'_k` is 0 and the sample is inside the
//! other two edges. The unit set's own search finds a few such ties per triangle at coarse
//! positions (48 in all); these triangles are built so that every record is one:
//!
//! - **column**: two vertices on the sample's column (`x/w` that of the sample, exactly): their
//!   `a' = 0`, `E'_k = 0`, and `b'` (one above, one below) decides;
//! - **row**: two vertices on the sample's row: `b' = 0` for both, `b'_i = b'_j`, and `a'`
//!   decides;
//! - **vertex**: one vertex on the sample (`a' = b' = 0`): two ties at once, each key comparing
//!   `(0, 0, w)` with the other vertex's;
//! - **rounded**: a column edge with one end a raw step off the column: `A` below 2^(OFF−1), so
//!   `a'` still rounds to 0 and the bounded test ties where the exact one does not;
//! - **bits**: a vertex on the sample and the other two ±2^p (1/128 clip) away along both axes,
//!   the viewport's sides and the weights powers of two: the other vertices' `a'` and `b'` are
//!   single bits (`b' = 2^(17 + log H + log m + q − OFF)` for `v − v_s = 2^q`, rounded where
//!   the exponent is negative), so a key compare that drops or adds one bit changes the key.
//!
//! Vertices are static, `w` a whole number of clip units (`2^16` raw) per vertex (1 to 4, so
//! the keys' `w` differ), the sample's column `x/w = k/128` (`xs = 128·W + k·W`, exact) and row
//! `y/w = k'/128`; the third vertex far on either side, the edge index and the order of its
//! ends drawn.

use rand::Rng;
use rand_pcg::Pcg64;
use uvt_core::{Lens, Sample, ScreenPos, SubPixel, Time, Triangle, Vertex, Viewport};

use super::bsample::{BSet, Grid};

/// Triangles of [`tie_keys`] per kind (column, row, vertex, rounded, bits).
pub const PER_KIND: usize = 150;

/// Raw clip units per clip unit.
const ONE: i64 = 1 << 16;

/// Records whose every sample ties (the module's header): [`PER_KIND`] triangles of each kind,
/// one record each (a triangle whose sample falls outside its viewport is skipped).
pub fn tie_keys(set: &mut BSet, rng: &mut Pcg64, g: Grid) {
    for kind in 0..5 {
        for _ in 0..PER_KIND {
            one(set, rng, g, kind);
        }
    }
}

fn one(set: &mut BSet, rng: &mut Pcg64, g: Grid, kind: u32) {
    let side = |rng: &mut Pcg64| -> u16 {
        match rng.gen_range(0..3) {
            0 => 1 << rng.gen_range(0..=11),
            _ => rng.gen_range(1..=2048),
        }
    };
    let pow2 = |rng: &mut Pcg64| -> u16 { 1 << rng.gen_range(0..=11) };
    let vp = if kind == 4 {
        Viewport::new(pow2(rng), pow2(rng))
    } else {
        Viewport::new(side(rng), side(rng))
    };
    let Ok(vp) = vp else {
        return;
    };
    let (w, h) = (i64::from(vp.width()), i64::from(vp.height()));
    // The sample at x/w = kx/128, y/w = ky/128 (kx, ky in −127..=127): xs = 128·W + kx·W,
    // ys = 128·H − ky·H, exact in 1/256 px.
    let (kx, ky) = (rng.gen_range(-127..=127i64), rng.gen_range(-127..=127i64));
    let (xs, ys) = (128 * w + kx * w, 128 * h - ky * h);
    // The vertex of weight m (w = m clip units) at clip position (x/w, y/w) = (u, v)/128.
    let z = |rng: &mut Pcg64| rng.gen_range(0..ONE);
    let at = |u: i64, v: i64, m: i64, z: i64| {
        let c = |p: i64| (p * m * ONE / 128) as i32;
        Vertex::from_bits([c(u), c(v), z as i32, (m * ONE) as i32, 0])
    };
    let mut m = || {
        if kind == 4 {
            1 << rng.gen_range(0..=2)
        } else {
            rng.gen_range(1..=4i64)
        }
    };
    let (m1, m2, m3) = (m(), m(), m());
    // along the edge: the two ends d1 > 0 and −d2 < 0 away from the sample (in 1/128 clip)
    let d1 = rng.gen_range(1..=200i64);
    let d2 = rng.gen_range(1..=200i64);
    let far = if rng.gen() { 250 } else { -250 };
    let (e1, e2, third) = match kind {
        // column: x = kx, y above and below; the third vertex left or right
        0 | 3 => {
            let e1 = at(kx, ky + d1, m1, z(rng));
            let nudge = if kind == 3 {
                if rng.gen() {
                    1
                } else {
                    -1
                }
            } else {
                0
            };
            let e2 = {
                let v = at(kx, ky - d2, m2, z(rng)).bits();
                Vertex::from_bits([v[0] + nudge, v[1], v[2], v[3], v[4]])
            };
            (e1, e2, at(kx + far, ky, m3, z(rng)))
        }
        // row: y = ky, x right and left; the third vertex above or below
        1 => (
            at(kx + d1, ky, m1, z(rng)),
            at(kx - d2, ky, m2, z(rng)),
            at(kx, ky + far, m3, z(rng)),
        ),
        // vertex on the sample; the other two a power of two away along the column and the
        // row (with power-of-two sides and weights, their a' and b' single bits)
        4 => {
            let mut p2 = || {
                let e = 1i64 << rng.gen_range(0..=7);
                if rng.gen() {
                    e
                } else {
                    -e
                }
            };
            let (u1, v1, u2, v2) = (p2(), p2(), p2(), p2());
            (
                at(kx, ky, m1, z(rng)),
                at(kx + u1, ky + v1, m2, z(rng)),
                at(kx + u2, ky + v2, m3, z(rng)),
            )
        }
        // vertex on the sample; the other two around it
        _ => (
            at(kx, ky, m1, z(rng)),
            at(kx + far, ky + rng.gen_range(-200..=200), m2, z(rng)),
            at(kx + rng.gen_range(-200..=200), ky + far, m3, z(rng)),
        ),
    };
    let (e1, e2) = if rng.gen() { (e1, e2) } else { (e2, e1) };
    let k = rng.gen_range(0..3usize);
    let mut v = [third; 3];
    v[(k + 1) % 3] = e1;
    v[(k + 2) % 3] = e2;
    let Ok(t) = Triangle::new_static(v) else {
        return;
    };
    if !(0..256 * w).contains(&xs) || !(0..256 * h).contains(&ys) {
        return;
    }
    let s = Sample::new(
        SubPixel::ZERO,
        SubPixel::ZERO,
        Lens::ZERO,
        Lens::ZERO,
        Time::from_bits(rng.gen_range(0..=65536)),
    )
    .expect("t in [0, 1], the lens centre");
    // In 0..256·2048: both fit u32.
    let pos = ScreenPos {
        xs: xs as u32,
        ys: ys as u32,
    };
    set.push(&t, vp, g, pos, &s);
}
