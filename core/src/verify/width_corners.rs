//! The domain-corner width test: every input at ±limit (and seeded random picks among the
//! extreme raw values), t ∈ {0, ½, 1 − LSB, 1}, u, v ∈ {−1, 0, 1}, sample positions at the
//! viewport's corners, W = H = `MAX_VIEWPORT` and 1 (and mixed), every offset shift 20..=32,
//! through the bounded and the exact sample test and the products of setup and the bounds. A
//! shadow computation in `i128` forms every intermediate (left shifts as the multiplications
//! they are), is checked bit for bit against the core's observable outputs (`bounded_eval`'s
//! a', b', E', orientation, coverage and depth; `sample_eval`'s E and det), and the largest
//! |value| of each intermediate must lie within the bound and width `widths.rs` declares.
//! `narrowing_a_width_fails` shows the check fails when a declared width is one bit too narrow.
//! Seed: `UVT_SEED` (printed on failure); `UVT_EXTENSIVE=1` drives 20× more random triangles.
// Test code: plain i128 operators on values < 2^100; an overflow or a bad index panics, which is
// the failure signal of a test.
#![allow(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_possible_wrap
)]

use std::collections::BTreeMap;
use std::format;
use std::string::String;
use std::vec::Vec;

use crate::config::formats::{Lens, SubPixel, Time};
use crate::config::precision::{Bounded, DefaultPrecision, OFFSET_SHIFT_MAX, OFFSET_SHIFT_MIN};
use crate::config::registry::Config;
use crate::config::unit::Full;
use crate::input::{Sample, Triangle, Vertex, Viewport, C, W, X, Y, Z};
use crate::sample::pos::ScreenPos;
use crate::sample::{bounded, exact};
use crate::setup::Setup;
use crate::stats::Ops;
use crate::widths::row::Table;
use crate::widths::stages::table;

const LIM: i32 = 1 << 29;
const ONE: i32 = 1 << 16;

/// Largest |value| observed per (stage, signal prefix).
#[derive(Default)]
struct Seen(BTreeMap<(&'static str, &'static str), u128>);

impl Seen {
    fn see(&mut self, stage: &'static str, prefix: &'static str, v: i128) {
        let e = self.0.entry((stage, prefix)).or_insert(0);
        *e = (*e).max(v.unsigned_abs());
    }
}

/// Every observed maximum against the declared row: `|v| ≤ bound` and `|v|` fits `bits`
/// (two's complement). `narrow` declares the named row one bit narrower (the self-test).
fn verify(t: &Table, seen: &Seen, narrow: Option<&str>) -> Vec<String> {
    let mut bad = Vec::new();
    for (&(stage, prefix), &v) in seen.0.iter() {
        let Some(row) = t.find(stage, prefix) else {
            bad.push(format!("{stage}: no declared row for {prefix:?}"));
            continue;
        };
        let bits = row.bits() - u32::from(narrow == Some(prefix));
        let bound = row.bound.to_u128().unwrap_or(u128::MAX);
        // A value v fits `bits` signed bits iff v ≤ 2^(bits−1) − 1 (and −v ≥ −2^(bits−1)).
        let fits = bits >= 129 || v < 1u128 << (bits - 1);
        if v > bound || !fits {
            bad.push(format!(
                "{stage} {prefix:?}: observed |v| = {v} ({v:#x}) > bound {} or does not fit {bits} bits",
                row.bound
            ));
        }
    }
    bad
}

fn seed() -> u64 {
    uvt_testkit::seed()
}

/// Hand-picked extreme triangles and seeded random ones whose every field is an extreme raw
/// value (±2^29, ±(2^29 − 1), ±1, 0).
fn triangles(seed: u64, n: usize) -> Vec<Triangle> {
    let a = [LIM, -LIM, LIM, -LIM, LIM];
    let b = [-LIM, LIM, -LIM, 1, LIM];
    let c = [LIM, LIM, LIM, LIM / 2, -LIM];
    let sw = |x: [i32; 5]| [-x[0], -x[1], -x[2], -x[3], -x[4]];
    let mk = |t0: [[i32; 5]; 3], t1: [[i32; 5]; 3]| {
        Triangle::new(t0.map(Vertex::from_bits), t1.map(Vertex::from_bits)).ok()
    };
    let mut out: Vec<Triangle> = [
        mk([a, b, c], [a, b, c]),
        mk([a, b, c], [sw(a), sw(b), sw(c)]),
        mk(
            [a, b, c].map(|v| [v[0], v[1], v[2], v[3], 0]),
            [a, b, c].map(|v| [v[0], v[1], v[2], v[3], 0]),
        ),
    ]
    .into_iter()
    .flatten()
    .collect();
    let vals = [LIM, -LIM, LIM - 1, 1 - LIM, 1, -1, 0];
    let mut rng = uvt_testkit::Rng(seed);
    while out.len() < n {
        let mut v = [[[0i32; 5]; 3]; 2];
        for f in v.iter_mut().flatten().flatten() {
            *f = vals[(rng.next_u64() % vals.len() as u64) as usize];
        }
        if let Some(t) = mk(v[0], v[1]) {
            out.push(t);
        }
    }
    out
}

fn smp(sx: u8, sy: u8, u: i32, v: i32, t: i32) -> Sample {
    Sample::new(
        SubPixel::from_bits(sx),
        SubPixel::from_bits(sy),
        Lens::from_bits(u),
        Lens::from_bits(v),
        Time::from_bits(t),
    )
    .unwrap()
}

fn samples() -> Vec<Sample> {
    let mut out = Vec::new();
    for (t, (u, v)) in [0, ONE / 2, ONE - 1, ONE].into_iter().zip([
        (ONE, ONE),
        (-ONE, ONE),
        (0, -ONE),
        (-ONE, -ONE),
    ]) {
        out.push(smp(0, 0, u, v, t));
        out.push(smp(255, 255, v, u, ONE - t));
    }
    out
}

/// round(v / 2^s), ties toward +∞.
fn rnd(v: i128, s: u32) -> i128 {
    (v + (1i128 << s) / 2).div_euclid(1i128 << s)
}

/// The bounded test in the shadow: returns (ab, e, det_sign, covered, depth) and records every
/// intermediate.
#[allow(clippy::type_complexity)]
fn shadow_bounded(
    tri: &Triangle,
    vp: (i128, i128),
    pos: ScreenPos,
    s: &Sample,
    shift: u32,
    seen: &mut Seen,
) -> ([(i128, i128); 3], [i128; 3], i128, bool, Option<i32>) {
    let setup =
        Setup::unculled::<DefaultPrecision>(tri, Viewport::new(vp.0 as u16, vp.1 as u16).unwrap());
    let (motion, defocus) = (setup.class().motion(), setup.class().defocus());
    let (t, u, v) = (
        i128::from(s.t().to_bits()),
        i128::from(s.u().to_bits()),
        i128::from(s.v().to_bits()),
    );
    let p = [0usize, 1, 2].map(|k| {
        let (q, r) = (tri.v[0][k], tri.v[1][k]);
        let mut f = [X, Y, W, Z, C].map(|i| i128::from(q[i]));
        if motion {
            for (fi, i) in f.iter_mut().zip([X, Y, W, Z, C]) {
                let l = *fi * 65536 + t * (i128::from(r[i]) - *fi);
                seen.see("sample", "1 lerp", l);
                *fi = rnd(l, 16);
                seen.see("sample", "1 lerped", *fi);
            }
        }
        let (mut x, mut y) = (f[0], f[1]);
        if defocus {
            seen.see("sample", "2 lens product", u * f[4]);
            seen.see("sample", "2 lens product", v * f[4]);
            x += rnd(u * f[4], 16);
            y += rnd(v * f[4], 16);
            seen.see("sample", "2 `x", x);
            seen.see("sample", "2 `x", y);
        }
        (x, y, f[2], f[3])
    });
    let (sw, sh) = (256 * vp.0, 256 * vp.1);
    let gx = 2 * i128::from(pos.xs) - sw;
    let gy = sh - 2 * i128::from(pos.ys);
    let half = 1i128 << (shift - 1);
    let ab = p.map(|(x, y, w, _)| {
        let (aa, bb) = (sw * x - gx * w, sh * y - gy * w);
        for z in [aa, bb] {
            seen.see("sample", "3 offset", z);
            seen.see("sample", "4 `A + 2^(S−1)`", z + half);
        }
        let r = (rnd(aa, shift), rnd(bb, shift));
        seen.see("sample", "4 rounded offset", r.0);
        seen.see("sample", "4 rounded offset", r.1);
        r
    });
    let w = p.map(|q| q.2);
    let e = [0usize, 1, 2].map(|k| {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let v = ab[i].0 * ab[j].1 - ab[j].0 * ab[i].1;
        seen.see("sample", "5 edge", v);
        v
    });
    let sign = if w.iter().all(|&x| x > 0) {
        let (p_, n_) = (e.iter().any(|&x| x > 0), e.iter().any(|&x| x < 0));
        match (p_, n_) {
            (true, false) => 1,
            (false, true) => -1,
            _ => 0,
        }
    } else {
        let det: i128 = (0..3).map(|k| e[k] * w[k]).sum();
        seen.see("sample", "6 orientation", det);
        det.signum()
    };
    let covered = sign != 0
        && (0..3).all(|k| match (e[k] * sign).signum() {
            1 => true,
            0 => {
                let (i, j) = ((k + 1) % 3, (k + 2) % 3);
                // The multiplication-free tie key (step 7): no intermediate of its own.
                match (ab[i].1, ab[i].0, w[i]).cmp(&(ab[j].1, ab[j].0, w[j])) {
                    std::cmp::Ordering::Greater => sign > 0,
                    std::cmp::Ordering::Less => sign < 0,
                    std::cmp::Ordering::Equal => false,
                }
            }
            _ => false,
        });
    let depth = covered.then(|| {
        let big = e.iter().map(|x| x.unsigned_abs()).max().unwrap();
        let len = 128 - big.leading_zeros();
        let sh = len.saturating_sub(crate::widths::row::BOUNDED_DEPTH_EDGE_BITS);
        let (mut num, mut den) = (0i128, 0i128);
        for k in 0..3 {
            let ek = e[k] >> sh;
            num += ek * p[k].3;
            den += ek * p[k].2;
        }
        seen.see("sample", "8 depth `Σ", num);
        seen.see("sample", "8 depth `Σ", den);
        let (num, den) = (num * sign, den * sign);
        seen.see("sample", "8 depth quotient", num * (1 << 24));
        if den <= 0 {
            return crate::config::formats::DEPTH_FAR;
        }
        (num * (1 << 24))
            .div_euclid(den)
            .clamp(i128::from(i32::MIN), i128::from(i32::MAX - 1)) as i32
    });
    (ab, e, sign, covered, depth)
}

fn viewports() -> [(i128, i128); 3] {
    let m = i128::from(crate::config::formats::MAX_VIEWPORT);
    [(m, m), (1, 1), (m, 1)]
}

/// Drive the bounded test at every shift; every observable checked bit for bit.
fn drive_bounded(n: usize) -> BTreeMap<u32, Seen> {
    let seed = seed();
    let mut by_shift: BTreeMap<u32, Seen> = BTreeMap::new();
    for tri in triangles(seed, n) {
        for vp in viewports() {
            let setup = Setup::unculled::<DefaultPrecision>(
                &tri,
                Viewport::new(vp.0 as u16, vp.1 as u16).unwrap(),
            );
            for s in samples() {
                let (mx, my) = (vp.0 as u16 - 1, vp.1 as u16 - 1);
                for (px, py) in [(0, 0), (mx, 0), (0, my), (mx, my)] {
                    let pos = ScreenPos::of(px, py, &s);
                    for shift in OFFSET_SHIFT_MIN..=OFFSET_SHIFT_MAX {
                        let seen = by_shift.entry(shift).or_default();
                        let (ab, e, sign, cov, depth) =
                            shadow_bounded(&tri, vp, pos, &s, shift, seen);
                        let got =
                            bounded::eval(&setup, shift, pos, &s, &mut Ops::default()).unwrap();
                        let ctx = format!(
                            "UVT_SEED={seed} {tri:?} vp {vp:?} {s:?} pos {pos:?} shift {shift}"
                        );
                        let got_ab = got.ab.map(|(a, b)| (i128::from(a), i128::from(b)));
                        assert_eq!(got_ab, ab, "a', b': {ctx}");
                        assert_eq!(got.e.map(i128::from), e, "E': {ctx}");
                        assert_eq!(i128::from(got.det_sign), sign, "orientation: {ctx}");
                        assert_eq!(got.hit.is_some(), cov, "coverage: {ctx}");
                        let gd = got.hit.map(|h| h.depth);
                        assert_eq!(
                            gd,
                            depth,
                            "depth: expected {depth:?} ({:#x?}), observed {gd:?} ({:#x?}): {ctx}",
                            depth.map(|d| d as u32),
                            gd.map(|d| d as u32)
                        );
                    }
                }
            }
        }
    }
    by_shift
}

fn n_random() -> usize {
    uvt_testkit::cases(60, 2000) as usize
}

#[test]
fn bounded_intermediates_fit_their_declared_widths() {
    let by_shift = drive_bounded(n_random());
    for (shift, seen) in &by_shift {
        let cfg = Config::parse(&format!("bounded-16-16-16-{shift}")).unwrap();
        let bad = verify(&table(&cfg), seen, None);
        assert!(
            bad.is_empty(),
            "UVT_SEED={} shift {shift}: {bad:#?}",
            seed()
        );
        // Every row of the bounded sample test was reached.
        let rows = table(&cfg);
        let n_rows = rows.rows().filter(|r| r.stage == "sample").count();
        assert_eq!(
            seen.0.len(),
            n_rows,
            "shift {shift}: rows reached {:?}",
            seen.0.keys()
        );
    }
}

/// The self-test: one width declared one bit too narrow is caught, for every row whose declared
/// width the corners attain (steps 1–4; the products of steps 5, 6 and 8 stay 1–3 bits below
/// their bounds at these corners, see the report of `uvt widths`).
#[test]
fn narrowing_a_width_fails() {
    let by_shift = drive_bounded(3);
    let cfg = Config::parse("bounded-16-16-16-20").unwrap();
    let seen = &by_shift[&20];
    assert!(verify(&table(&cfg), seen, None).is_empty());
    for row in [
        "1 lerp",
        "1 lerped",
        "2 `x",
        "3 offset",
        "2 lens product",
        "4 `A + 2^(S−1)`",
        "4 rounded offset",
    ] {
        let bad = verify(&table(&cfg), seen, Some(row));
        assert_eq!(bad.len(), 1, "narrowing {row:?} must fail: {bad:?}");
    }
}

/// The exact test: positions, normals, edge values, det and the depth sums at the corners,
/// shadowed in i128 where they fit and read from `sample_eval` (192-bit) where they do not.
#[test]
fn exact_intermediates_fit_their_declared_widths() {
    let cfg = Config::parse("exact-16-16-16").unwrap();
    let t = table(&cfg);
    let mut seen = Seen::default();
    let rowbits = |p: &str| t.find("sample", p).unwrap().bits();
    for tri in triangles(seed(), n_random()) {
        for vp in viewports() {
            let setup = Setup::unculled::<DefaultPrecision>(
                &tri,
                Viewport::new(vp.0 as u16, vp.1 as u16).unwrap(),
            );
            for s in samples() {
                let mut ops = Ops::default();
                let (p, _) = crate::sample::exact::positions::<Full>(&setup, &s, &mut ops);
                for q in p.iter() {
                    for &c in &q[..3] {
                        seen.see("sample", "vertex P", i128::from(c));
                    }
                }
                let pos = ScreenPos::of(vp.0 as u16 - 1, 0, &s);
                let d = crate::sample::pos::direction(setup.viewport(), pos);
                for &x in &d {
                    seen.see("sample", "direction", i128::from(x));
                }
                let cross = |a: &[i64; 4], b: &[i64; 4]| {
                    let [ax, ay, aw, _] = a.map(i128::from);
                    let [bx, by, bw, _] = b.map(i128::from);
                    [ay * bw - aw * by, aw * bx - ax * bw, ax * by - ay * bx]
                };
                for (i, j) in [(1, 2), (2, 0), (0, 1)] {
                    for c in cross(&p[i], &p[j]) {
                        seen.see("sample", "edge normal", c);
                    }
                }
                let ev = exact::eval::<Full>(&setup, pos, &s, &mut ops);
                let ctx = format!("UVT_SEED={} {tri:?} {s:?}", seed());
                for e in ev.e {
                    assert!(e.bit_len() < rowbits("edge value"), "E {e:?}: {ctx}");
                }
                assert!(ev.det.bit_len() < rowbits("`det"), "det: {ctx}");
            }
        }
    }
    let bad = verify(&t, &seen, None);
    assert!(bad.is_empty(), "{bad:#?}");
}

/// Setup and the bounds: the products the width table declares, at the extreme corners with
/// the widest epsilon (offset shift 32) and the exact one, on both extreme viewports.
#[test]
fn setup_and_bounds_products_fit_their_declared_widths() {
    for off in [None, Some(OFFSET_SHIFT_MAX)] {
        let cfg = match off {
            None => Config::parse("exact-16-16-16").unwrap(),
            Some(_) => Config::of::<Bounded<16, 16, 16, 32>>(),
        };
        let t = table(&cfg);
        let (ex, ew) = crate::widths::row::eps_max(&cfg);
        let (ex, ew) = (i128::from(ex), i128::from(ew));
        let mut seen = Seen::default();
        let e = i128::from(crate::config::formats::MAX_VIEWPORT);
        for tri in triangles(seed(), n_random()) {
            let mut pts = Vec::new();
            for p in tri.v.iter().flatten() {
                for axis in 0..2 {
                    let (a, cs) = crate::setup::boxes::axis_coord(p, axis);
                    let (a, cs, w) = (i128::from(a), i128::from(cs), i128::from(p[W]));
                    for dw in [-ew, ew] {
                        for s in [-1, 1] {
                            let corner = a + s * (cs.abs() + ex);
                            seen.see("setup", "corner `a", corner);
                            seen.see("setup", "corner `w", w + dw);
                            pts.push((corner, w + dw));
                            let num = (a + s * cs + s * ex + w + dw) * e * (1 << 16);
                            seen.see("setup", "projection numerator", num);
                            seen.see("setup", "frustum distance", w + dw + s * a + cs.abs() + ex);
                        }
                    }
                    let aw = a + w;
                    for xi in [0, e] {
                        let delta = aw * e - 2 * w * xi;
                        let bias = (cs.abs() + ex + ew) * e;
                        seen.see("bounds/tri", "dual", delta - bias);
                        seen.see("bounds/tri", "dual", delta + bias);
                        seen.see("bounds/tile", "bounding line", (delta + bias) * e);
                    }
                }
            }
            for &(ai, wi) in &pts {
                for &(aj, wj) in &pts {
                    seen.see("setup", "separating-line cross", ai * wj - wi * aj);
                    seen.see("setup", "separating-line dot", ai * aj + wi * wj);
                }
            }
        }
        let bad = verify(&t, &seen, None);
        assert!(bad.is_empty(), "{cfg}: {bad:#?}");
    }
}
