//! Planar records directed at single decisions of the sample test.
//!
//! **Single-bit edges**: an edge whose normal's `a` (or `b`, with `a = 0`) is
//! `±2^j`, for every `j` the rounded vertices allow (0..=29), with samples exactly on it
//! (`E_k = 0`: the fill rule decides, its compares meet one set bit) and `2^q` sample steps off
//! it (`E_k = ±2^(j+1+q)·H` or `·W`: one set bit when the viewport side is a power of two).
//! These are the cases a unit's zero tests and sign tests on `E`, `a` and `b` need to be told
//! apart from a compare that looks at one bit less, or at one bit more (the mutation flow's
//! survivors of `uvt_psample.v`'s lines "σ·E > 0; on E = 0 the fill rule").
//!
//! The vertices are exact (every component below 2^15 in magnitude: the planar setup's shift
//! is 0, `P' = P`), all three at `w = 2^p`, so the edge through two of them at `x = X` has
//! `a = 2^p·(y_1 − y_2)`, `b = 0`, and passes through the sample column `xs = 128·W·(2^p + X)/2^p`
//! exactly (`X` a multiple of `2^(p−7)`; the same with x and y swapped for `b`).
//!
//! **Depth exponent below −33** (the scaled depth saturates whatever `acc ≠ 0` is: the unit's
//! `s5_big`, bin `psample.depth.scale_saturated`): `f < −33` needs `bitlen(Zv) ≥ bitlen(D) + 40`
//! (`planar.rs` "Depth"), a determinant of a few units with normals near 2^30. The rows
//! `P_0 = (1, −K, 0)`, `P_1 = (0, 1, K)`, `P_2 = (0, 0, 1)` (x, y, w) have `det = 1` and
//! `n_2 = (−K², −K, 1)`: with `K = 2^14` and `|z_2|` near 2^29, `|Zv| ≈ 2^57` against `D = 256·W·H`.
//! The sample at the viewport's centre (`d = (0, 0, 256·W·H)`) is vertex 2: `E_0 = E_1 = 0`, and
//! the fill rule accepts both (`a_0 = 1`, `a_1 = K`, σ = +1), so it is covered, its depth
//! `z_2/w_2` far beyond the range (vertex 0 is at w = 0).
//!
//! **Depth at the range's ends at every shift**: the exact triangle `(−1, −1), (1, −1), (0, 1)`
//! at `w = 1` (`det = 4`) with `z_k = c·w_k + s·x_k` (or `·y_k`) is the plane `z/w = c + s·x/w`,
//! `Zv = det·(s, 0, c)`. With `c`, `s = ±2^σ` (`σ ≥ 7 > log|c|`) and the viewport's sides powers
//! of two, every step of the depth plane is exact: `G_w = c·2^(30−σ)`, `f = 14 + log(W·H) − σ`,
//! and at the viewport's centre (`d = (0, 0, 256·W·H)`) `acc = c·2^(38 − σ + log(W·H))`, a single
//! bit at `2^(amt − 2 + log|c| − 7)` for the depth shift `amt = f + 33`: the depth is `c·2^24`
//! exactly (`c = 2^7`: 2^31, one past the far end's first clamped value; `−2^8`: −2^32), the
//! accumulator's bits at the range test's mask boundary for `amt` from 20 to 62.

use rand::Rng;
use rand_pcg::Pcg64;
use uvt_core::{ScreenPos, Triangle, Vertex, Viewport};

use super::psample::PSet;

/// The largest vertex component that the planar setup keeps exact (shift 0).
const EXACT: i32 = (1 << 15) - 1;

/// The exponents `j` of `±2^j` an exact edge's `a` or `b` reaches: `2^p·2^r` with `p ≤ 14`,
/// `r ≤ 15`.
pub const BITS: core::ops::RangeInclusive<u32> = 0..=29;

/// A viewport side: a power of two half the time (the edge values off the edge one set bit),
/// any side otherwise.
fn side(rng: &mut Pcg64) -> u16 {
    if rng.gen() {
        1 << rng.gen_range(0..=11)
    } else {
        rng.gen_range(1..=2048)
    }
}

/// An edge to draw: its coefficient `sgn·2^j` (`a` when `!horizontal`, else `b` with `a = 0`),
/// its index `k` (opposite vertex k), the third vertex's side `apex`, and the bit `t` of
/// `E = ±2^t` that the records off the edge take (`None`: a drawn one).
struct Edge {
    j: u32,
    k: usize,
    sgn: bool,
    apex: bool,
    horizontal: bool,
    /// lean the `a` edge (not the `b` one): `b = −g·a` for a drawn `g ≠ 0`, through one exact
    /// sample point
    shear: bool,
    t: Option<u32>,
}

/// One triangle with edge `e`; records on the edge and off it (none when the drawn edge's span
/// holds too few samples along it inside the viewport).
fn one(set: &mut PSet, rng: &mut Pcg64, e: &Edge) {
    let Edge {
        j,
        k,
        sgn,
        apex,
        horizontal,
        shear,
        t: bit,
    } = *e;
    let p = rng.gen_range(j.saturating_sub(15)..=j.min(14));
    let r = j - p;
    // With a target bit t = j + 1 + h + q: the side along the edge 2^h, q below.
    let h_t = bit.map(|t| {
        let top = (t - j - 1).min(11);
        rng.gen_range((t - j - 1).saturating_sub(17).min(top)..=top)
    });
    // across, room for the ±2^q steps off the edge on one side or the other: 2^(q−7) pixels
    let room = match bit.zip(h_t) {
        Some((t, h)) => 1u16 << (t - j - 1 - h).saturating_sub(7),
        None => 1,
    };
    let (along_side, across_side) = (
        h_t.map_or_else(|| side(rng), |h| 1 << h),
        side(rng).max(room + 1).min(2048),
    );
    let vp = match if horizontal {
        Viewport::new(along_side, across_side)
    } else {
        Viewport::new(across_side, along_side)
    } {
        Ok(vp) => vp,
        Err(_) => return,
    };
    // Along the edge: screen axis `u` (its side `su`); across it: `v` (`sv`). For a vertical
    // edge u is y (ys grows downwards: ys = 128·H·(1 − y/w)), v is x (xs = 128·W·(1 + x/w)).
    let (su, sv) = if horizontal {
        (i64::from(vp.width()), i64::from(vp.height()))
    } else {
        (i64::from(vp.height()), i64::from(vp.width()))
    };
    // the line's coordinate X: |X| < 2^p, a multiple of 2^(p − 7) (its sample column exact)
    let step = 1i64 << p.saturating_sub(7);
    let lim = (1i64 << p) / step;
    let x_line = rng.gen_range(-lim + 1..lim) * step;
    // The sample coordinate across, in 1/256 px: 128·S·(2^p ± X)/2^p, exact (the sign: x grows
    // with xs, y against ys).
    let across = |c: i64| {
        let c = if horizontal { -c } else { c };
        (128 * sv * ((1i64 << p) + c)) >> p
    };
    let v_line = across(x_line);
    // the two ends along the edge, 2^r apart, the span around the screen centre (a leaning
    // edge: around the exact sample point's coordinate along it, y_s)
    let span = 1i64 << r;
    let exact = i64::from(EXACT);
    let lean = shear && !horizontal && span >= 2;
    let y_s = rng.gen_range(-lim + 1..lim) * step;
    let lo = if lean {
        rng.gen_range((y_s - span + 1).max(-exact)..=(y_s - 1).min(exact - span))
    } else {
        -rng.gen_range(1..=span.min(exact))
    };
    let lo = lo.max(-exact).min(exact - span);
    let hi = lo + span;
    // the lean g: x = X + g·(y − y_s) on the edge, every |x| ≤ 2^15 − 1
    let g_max = ((exact - x_line.abs()) / span).min(4);
    let g = if lean && g_max >= 1 {
        rng.gen_range(1..=g_max) * if rng.gen() { 1 } else { -1 }
    } else {
        0
    };
    let x_at = |y: i64| x_line + g * (y - y_s);
    // samples strictly inside the edge's span along it, in the middle half
    let along = |c: i64| {
        let c = if horizontal { c } else { -c };
        (128 * su * ((1i64 << p) + c)) >> p
    };
    let (a0, a1) = {
        let (x, y) = (along(lo), along(hi));
        (x.min(y).max(0), x.max(y).min(256 * su - 1))
    };
    if a1 - a0 < 4 {
        return;
    }
    let quarter = (a1 - a0) / 4;
    let w = 1i32 << p;
    let mut z = || rng.gen_range(-(1i32 << 15)..=1 << 15);
    let put = |u: i64, v: i64, z: i32| {
        let (u, v) = (u as i32, v as i32);
        Vertex::from_bits(if horizontal {
            [u, v, z, w, 0]
        } else {
            [v, u, z, w, 0]
        })
    };
    let (e1, e2) = if sgn { (lo, hi) } else { (hi, lo) };
    let off = if apex { 1i64 << 14 } else { -(1i64 << 14) };
    let ends = [put(e1, x_at(e1), z()), put(e2, x_at(e2), z())];
    let mid = (lo + hi) / 2;
    let third = put(mid, (x_at(mid) + off).clamp(-exact, exact), z());
    // the edge opposite vertex k: vertices k + 1 and k + 2 (cyclic)
    let mut v = [third; 3];
    v[(k + 1) % 3] = ends[0];
    v[(k + 2) % 3] = ends[1];
    let Ok(t) = Triangle::new_static(v) else {
        return;
    };
    let (vlim, ulim) = (256 * sv, 256 * su);
    // Off the edge by 2^q steps across: E = ±2^(j+1+q)·S (S the side along the edge), so with
    // S = 2^h a drawn bit t of E, t = j + 1 + h + q, when q lands in 0..=17.
    let mut offsets = vec![];
    match bit.zip(h_t) {
        Some((t, h)) => {
            let q = t - j - 1 - h;
            offsets.extend([1i64 << q, -(1i64 << q)]);
        }
        None => {
            offsets.extend([0, 0]);
            for _ in 0..2 {
                let q = rng.gen_range(0..=17);
                offsets.push(if rng.gen() { 1i64 << q } else { -(1i64 << q) });
            }
        }
    }
    for d in offsets {
        // a leaning edge passes the sample grid exactly at y_s alone
        let u = if g != 0 {
            along(y_s)
        } else {
            rng.gen_range(a0 + quarter..=a1 - quarter)
        };
        let v = v_line + d;
        if !(0..vlim).contains(&v) || !(0..ulim).contains(&u) {
            continue;
        }
        // both below 256·2048: u32
        let pos = if horizontal {
            ScreenPos {
                xs: u as u32,
                ys: v as u32,
            }
        } else {
            ScreenPos {
                xs: v as u32,
                ys: u as u32,
            }
        };
        set.push(&t, vp, pos);
    }
}

/// Records on single-bit edges (the module's header): for every `j` of [`BITS`], both signs
/// of the coefficient, both sides for the third vertex, `a` and `b`, each edge index, upright
/// and leaning: one triangle each ([`EDGE_CASES`]), up to four records (two on the edge, two
/// off it); then for every bit `t` of [`E_BITS`] [`E_CASES`] triangles whose two records off
/// the edge have `E = ±2^t` exactly.
pub fn single_bit_edges(set: &mut PSet, rng: &mut Pcg64) {
    let edge = |j: u32, case: u32, t: Option<u32>| Edge {
        j,
        k: (case / 8 % 3) as usize,
        sgn: case & 1 != 0,
        apex: case & 2 != 0,
        horizontal: case & 4 != 0,
        shear: case >= 24,
        t,
    };
    for j in BITS {
        for case in 0..EDGE_CASES {
            set.cov.triangles += 1;
            one(set, rng, &edge(j, case, None));
        }
    }
    for t in E_BITS {
        for case in 0..E_CASES {
            set.cov.triangles += 1;
            // t = j + 1 + h + q with h ≤ 11, q ≤ 17
            let j = rng.gen_range(t.saturating_sub(29).min(29)..=(t - 1).min(29));
            one(set, rng, &edge(j, case, Some(t)));
        }
    }
}

/// The bits `t` of `E = ±2^t` that [`single_bit_edges`] aims at, each with [`E_CASES`]
/// triangles and two records off the edge (`±2^t`).
pub const E_BITS: core::ops::RangeInclusive<u32> = 1..=58;

/// Triangles per exponent of [`single_bit_edges`]: both signs, both sides, `a` and `b`, each
/// edge index; upright, then leaning.
pub const EDGE_CASES: u32 = 48;

/// Triangles per bit of `E` of [`single_bit_edges`]: both signs, both sides, `a` and `b`, each
/// edge index, upright.
pub const E_CASES: u32 = 24;

/// The depth shifts `amt = f + 33` of [`depth_boundaries`] (up to `69 − log|c|`: 62 for the
/// first depth of [`BOUNDARY_DEPTHS`], 61 for the others).
pub const SHIFTS: core::ops::RangeInclusive<i32> = 20..=62;

/// The centre depths `c` (z/w) of [`depth_boundaries`]: 2^31 (past the far clamp), −2^32 and
/// 2^32 (past the near and far ones, the accumulator's sign unlike the bit below).
pub const BOUNDARY_DEPTHS: [i32; 3] = [1 << 7, -(1 << 8), 1 << 8];

/// Records at the depth range's ends for every shift of [`SHIFTS`] (the module's header): per
/// shift and depth of [`BOUNDARY_DEPTHS`] one triangle, its viewport and slope drawn so that
/// `f + 33 = amt`, the sample at the centre.
pub fn depth_boundaries(set: &mut PSet, rng: &mut Pcg64) {
    for amt in SHIFTS {
        for c in BOUNDARY_DEPTHS {
            set.cov.triangles += 1;
            // f = amt − 33 = 14 + log(W·H) − σ with σ in log|c|..=27 (the slope the largest
            // coefficient of Zv) and log(W·H) in 0..=22
            let lc = 31 - c.unsigned_abs().leading_zeros() as i32;
            let lwh_lo = (amt - 47 + lc).max(0);
            let lwh_hi = (amt - 47 + 27).min(22);
            if lwh_lo > lwh_hi {
                continue;
            }
            let lwh = rng.gen_range(lwh_lo..=lwh_hi);
            let sigma = 47 + lwh - amt;
            let lw = rng.gen_range((lwh - 11).max(0)..=lwh.min(11));
            let Ok(vp) = Viewport::new(1 << lw, 1 << (lwh - lw)) else {
                continue;
            };
            let slope = if rng.gen() {
                1i32 << sigma
            } else {
                -(1i32 << sigma)
            };
            let on_y = rng.gen::<bool>();
            let v = [(-1i32, -1i32), (1, -1), (0, 1)].map(|(x, y)| {
                let z = c + slope * if on_y { y } else { x };
                Vertex::from_bits([x, y, z, 1, 0])
            });
            let Ok(t) = Triangle::new_static(v) else {
                continue;
            };
            set.push(&t, vp, centre(vp));
        }
    }
}

/// The sample at the viewport's centre: `d = (0, 0, 256·W·H)`, the ray through `x/w = y/w = 0`.
fn centre(vp: Viewport) -> ScreenPos {
    ScreenPos {
        xs: 128 * u32::from(vp.width()),
        ys: 128 * u32::from(vp.height()),
    }
}

/// Triangles of [`saturated_depth`].
pub const SATURATED: usize = 48;

/// Covered samples whose depth exponent is below −33 (the module's header): the three rows with
/// `K` in `2^10..=2^14`, `z_2` up to ±2^29 (0 once in eight: `acc = 0`), `z_0`, `z_1` anywhere,
/// viewports of 1 to 16 pixels a side, the vertices in any cyclic order; the centre sample,
/// and one anywhere in the viewport.
pub fn saturated_depth(set: &mut PSet, rng: &mut Pcg64) {
    let lim = 1i32 << 29;
    for _ in 0..SATURATED {
        set.cov.triangles += 1;
        let k = rng.gen_range(1 << 10..=1i32 << 14);
        let z2 = match rng.gen_range(0..8) {
            0 => 0,
            _ => rng.gen_range(lim / 2..=lim) * if rng.gen() { 1 } else { -1 },
        };
        let mut z = || rng.gen_range(-lim..=lim);
        let rows = [[1, -k, z(), 0, 0], [0, 1, z(), k, 0], [0, 0, z2, 1, 0]];
        let r = rng.gen_range(0..3usize);
        let v = core::array::from_fn(|i| Vertex::from_bits(rows[(i + r) % 3]));
        let Ok(t) = Triangle::new_static(v) else {
            continue;
        };
        let Ok(vp) = Viewport::new(rng.gen_range(1..=16), rng.gen_range(1..=16)) else {
            continue;
        };
        set.push(&t, vp, centre(vp));
        let (w, h) = (u32::from(vp.width()), u32::from(vp.height()));
        let (xs, ys) = (rng.gen_range(0..256 * w), rng.gen_range(0..256 * h));
        set.push(&t, vp, ScreenPos { xs, ys });
    }
}

/// The depth shifts `f + 33` below [`SHIFTS`] that [`zero_depth`] reaches.
pub const SMALL_SHIFTS: core::ops::RangeInclusive<i32> = 4..=19;

/// Triangles of [`zero_depth`] per shift of [`SMALL_SHIFTS`].
pub const ZERO_PER_SHIFT: usize = 4;

/// Covered samples whose depth is exactly 0 at every shift of [`SMALL_SHIFTS`], where the range
/// test's mask reaches the accumulator's low bits (`j ≥ amt − 2`): the rows of
/// [`saturated_depth`] with `z_2 = 0`, so `Zv = (z_0 + K·z_1, z_1, 0)`, `G_w = 0` and the
/// centre sample (vertex 2) has `acc = 0`. On a 1×1 viewport `D = 256` and `f = 15 − B` for
/// `B = bitlen(z_0 + K·z_1)`: `K·z_1` is drawn in `[2^(B−1), 2^(B−1) + 2^(B−2))` and `z_0` of
/// its sign below `min(2^(B−3), 2^29)`, so `B = 48 − amt` exactly (`K ≤ 2^15 − 1`, `|z_1| ≤
/// 2^29`: `B ≤ 44`, `amt ≥ 4`). Per triangle the centre sample and one anywhere in the pixel.
pub fn zero_depth(set: &mut PSet, rng: &mut Pcg64) {
    let lim = 1i64 << 29;
    for amt in SMALL_SHIFTS {
        let b = 48 - amt; // 29..=44
        let lo = 1i64 << (b - 1);
        for _ in 0..ZERO_PER_SHIFT {
            set.cov.triangles += 1;
            // K·|z_1| ≥ 2^(B−1) with |z_1| ≤ 2^29 needs K ≥ 2^(B−1−29).
            let k = rng.gen_range((lo >> 29).max(1)..=i64::from(EXACT));
            let z1_lo = (lo + k - 1) / k; // ceil: K·z_1 ≥ 2^(B−1)
            let z1_hi = ((lo + (lo >> 1) - 1) / k).min(lim); // K·z_1 < 2^(B−1) + 2^(B−2)
            if z1_lo > z1_hi {
                continue;
            }
            let s = if rng.gen() { 1 } else { -1 };
            let z1 = s * rng.gen_range(z1_lo..=z1_hi);
            let z0 = s * rng.gen_range(0..(lo >> 2).min(lim));
            // |z| ≤ 2^29 and K ≤ 2^15 − 1: every value fits in i32.
            let (k, z0, z1) = (k as i32, z0 as i32, z1 as i32);
            let rows = [[1, -k, z0, 0, 0], [0, 1, z1, k, 0], [0, 0, 0, 1, 0]];
            let r = rng.gen_range(0..3usize);
            let v = core::array::from_fn(|i| Vertex::from_bits(rows[(i + r) % 3]));
            let Ok(t) = Triangle::new_static(v) else {
                continue;
            };
            let Ok(vp) = Viewport::new(1, 1) else {
                continue;
            };
            set.push(&t, vp, centre(vp));
            let (xs, ys) = (rng.gen_range(0..256), rng.gen_range(0..256));
            set.push(&t, vp, ScreenPos { xs, ys });
        }
    }
}
