//! The bit width of every intermediate, **derived by code** from a configuration's constants
//! (`COORD_LIMIT_RAW`, `TUV_ONE`, `MAX_VIEWPORT`, `SUBPIXEL_BITS`, `DEPTH_*`, `RECIP_SHIFT`,
//! the precision's fraction bits and offset shift, and the conservative epsilon [`Eps::of`]).
//!
//! Every row is an upper bound on the magnitude of one signal ([`Mag`], `m·2^e`, exact integer
//! arithmetic, rounded up where it must round) built from the bounds of its operands by the
//! same formula the code evaluates; its width is the number of bits a two's-complement register
//! needs for every value in `[−bound, bound]` (sign included: +2^29 needs 31 bits). A product
//! row also carries its multiplier: the operand widths and how many such products the stage
//! forms — the hardware cost model (`host/src/cost.rs`) reads them from here.
//!
//! `core/README.md`'s width tables are the output of [`write_markdown`] (`uvt widths`), and a
//! test fails if they differ; `width_corners.rs` drives the domain's extreme corners through each
//! stage with a shadow `i128` computation and checks every intermediate against these widths.

use core::fmt;

use crate::config::class::Class;
use crate::config::formats::{
    COORD_LIMIT_RAW, DEPTH_EDGE_BITS, DEPTH_FRAC, MAX_VIEWPORT, RECIP_SHIFT, SUBPIXEL_BITS,
    TUV_FRAC,
};
use crate::config::precision::{Precision, OFFSET_SHIFT_MAX, OFFSET_SHIFT_MIN};
use crate::input::Viewport;
use crate::setup::eps::Eps;

/// Significant bits (magnitude) the bounded test keeps of each edge value for the depth
/// interpolation: `|E''| < 2^24` (`bounded.rs`, step 8).
pub const BOUNDED_DEPTH_EDGE_BITS: u32 = 24;

/// A non-negative magnitude bound `m·2^e` (exact; `m` odd or zero after normalisation).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mag {
    m: u128,
    e: u32,
}

impl Mag {
    /// Zero.
    pub const ZERO: Mag = Mag { m: 0, e: 0 };
    /// The integer `n`.
    pub const fn int(n: u128) -> Mag {
        Mag { m: n, e: 0 }.norm()
    }
    /// `2^k`.
    pub const fn pow2(k: u32) -> Mag {
        Mag { m: 1, e: k }
    }
    const fn norm(self) -> Mag {
        if self.m == 0 {
            return Mag::ZERO;
        }
        let tz = self.m.trailing_zeros();
        Mag {
            m: self.m.wrapping_shr(tz),
            e: self.e.saturating_add(tz),
        }
    }
    /// Magnitude bits: the bit length of `m·2^e`.
    pub const fn mag_bits(self) -> u32 {
        if self.m == 0 {
            return 0;
        }
        u128::BITS
            .saturating_sub(self.m.leading_zeros())
            .saturating_add(self.e)
    }
    /// Signed width (two's complement, sign included) of a register holding `[−self, self]`.
    pub const fn bits(self) -> u32 {
        self.mag_bits().saturating_add(1)
    }
    /// The value, when it fits `u128`.
    pub const fn to_u128(self) -> Option<u128> {
        if self.m == 0 {
            return Some(0);
        }
        if self.mag_bits() > u128::BITS {
            return None;
        }
        Some(self.m.wrapping_shl(self.e))
    }
    /// Product (exact while the mantissas' product fits `u128`, else rounded up).
    pub const fn mul(self, o: Mag) -> Mag {
        let e = self.e.saturating_add(o.e);
        match self.m.checked_mul(o.m) {
            Some(m) => Mag { m, e }.norm(),
            // Rounded up to a power of two (only for ≥ 128-bit mantissa products).
            None => Mag::pow2(
                e.saturating_add(self.mag_bits().saturating_sub(self.e))
                    .saturating_add(o.mag_bits().saturating_sub(o.e)),
            ),
        }
    }
    /// Sum (exact while the aligned mantissas fit `u128`, else rounded up).
    pub const fn add(self, o: Mag) -> Mag {
        if self.m == 0 {
            return o;
        }
        if o.m == 0 {
            return self;
        }
        let (lo, hi) = if self.e <= o.e { (self, o) } else { (o, self) };
        let d = hi.e.saturating_sub(lo.e);
        if d < 127 {
            if let Some(h) = hi.m.checked_mul(1u128.wrapping_shl(d)) {
                if let Some(m) = h.checked_add(lo.m) {
                    return Mag { m, e: lo.e }.norm();
                }
            }
        }
        // The smaller term is < 2^(mag_bits): round the sum up to the next power of two.
        let b = if hi.mag_bits() >= lo.mag_bits() {
            hi.mag_bits()
        } else {
            lo.mag_bits()
        };
        Mag::pow2(b.saturating_add(1))
    }
    /// `self·k` for a small constant.
    pub const fn times(self, k: u128) -> Mag {
        self.mul(Mag::int(k))
    }
    /// `floor(self / 2^s)` (exact).
    pub const fn shr_floor(self, s: u32) -> Mag {
        if self.e >= s {
            return Mag {
                m: self.m,
                e: self.e.wrapping_sub(s),
            };
        }
        let k = s.wrapping_sub(self.e);
        if k >= 128 {
            return Mag::ZERO;
        }
        Mag::int(self.m.wrapping_shr(k))
    }
    /// The larger of two bounds.
    pub const fn max(self, o: Mag) -> Mag {
        let (a, b) = (self.mag_bits(), o.mag_bits());
        if a != b {
            return if a > b { self } else { o };
        }
        // Same bit length: compare the mantissas aligned to the smaller exponent.
        let (s, t) = (self.shr_floor(0), o);
        if s.e <= t.e {
            let d = t.e.wrapping_sub(s.e);
            if t.m.wrapping_shl(d) >= s.m {
                t
            } else {
                s
            }
        } else {
            let d = s.e.wrapping_sub(t.e);
            if s.m.wrapping_shl(d) >= t.m {
                s
            } else {
                t
            }
        }
    }
}

impl fmt::Display for Mag {
    /// `n` below 2^20, `2^e` or `m·2^e` for small m, else the exact decimal (≤ 2^64) or `m·2^e`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.to_u128() {
            Some(v) if v < 1 << 20 => write!(f, "{v}"),
            _ if self.m == 1 => write!(f, "2^{}", self.e),
            _ if self.m < 1000 => write!(f, "{}·2^{}", self.m, self.e),
            Some(v) if v <= 1 << 64 => write!(f, "{v}"),
            _ => write!(f, "{}·2^{}", self.m, self.e),
        }
    }
}

/// A configuration of the sweep: `exact-P-T-B` (`Prec<P, T, B>`) or `bounded-P-T-B-O`
/// (`Bounded<P, T, B, O>`). Fields private; built by [`Config::of`] or [`Config::parse`], which
/// refuse anything outside the ranges the precision types accept.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Config {
    pos: u32,
    tuv: u32,
    bnd: u32,
    off: Option<u32>,
}

impl Config {
    /// The configuration of precision `P`.
    pub const fn of<P: Precision>() -> Config {
        Config {
            pos: P::POS_FRAC,
            tuv: P::TUV_FRAC,
            bnd: P::BOUND_FRAC,
            off: P::OFFSET_SHIFT,
        }
    }
    /// Parse `exact-P-T-B` or `bounded-P-T-B-O`; `None` for anything else or out of range
    /// (P, T ∈ 2..=16, B ∈ 0..=16, O ∈ `OFFSET_SHIFT_MIN..=OFFSET_SHIFT_MAX`).
    pub fn parse(name: &str) -> Option<Config> {
        let mut it = name.split('-');
        let kind = it.next()?;
        let mut num = || it.next().and_then(|s| s.parse::<u32>().ok());
        let (pos, tuv, bnd) = (num()?, num()?, num()?);
        let off = match kind {
            "exact" => None,
            "bounded" => Some(num()?),
            _ => return None,
        };
        if num().is_some() {
            return None;
        }
        let ok = (2..=16).contains(&pos)
            && (2..=16).contains(&tuv)
            && bnd <= 16
            && match off {
                None => true,
                Some(o) => (OFFSET_SHIFT_MIN..=OFFSET_SHIFT_MAX).contains(&o),
            };
        ok.then_some(Config { pos, tuv, bnd, off })
    }
    /// Fraction bits of positions.
    pub const fn pos(&self) -> u32 {
        self.pos
    }
    /// Fraction bits of t/u/v.
    pub const fn tuv(&self) -> u32 {
        self.tuv
    }
    /// Fraction bits of the bounds' pixel grid.
    pub const fn bnd(&self) -> u32 {
        self.bnd
    }
    /// Offset-grid shift of the bounded test (`None`: exact test).
    pub const fn off(&self) -> Option<u32> {
        self.off
    }
    /// The largest conservative epsilon over classes and viewports (x/y, w), raw clip units:
    /// [`Eps::of`] at class both on a 1×1 viewport (ε falls with the extent).
    pub fn eps_max(&self) -> (u32, u32) {
        let Ok(vp) = Viewport::new(1, 1) else {
            return (0, 0);
        };
        let e = Eps::of(self.off, Class::MotionDefocus, vp);
        let [x, _] = e.x();
        (x.unsigned_abs(), e.w().unsigned_abs())
    }
}

impl fmt::Display for Config {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.off {
            None => write!(f, "exact-{}-{}-{}", self.pos, self.tuv, self.bnd),
            Some(o) => write!(f, "bounded-{}-{}-{}-{o}", self.pos, self.tuv, self.bnd),
        }
    }
}

/// A multiplier of a stage: operand widths (signed, sign included) and how many such products
/// the stage forms (per triangle for setup, per tile for bounds, per sample for the sample test;
/// worst-case path, no early exit).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mul {
    /// width of the first operand (bits, sign included)
    pub a: u32,
    /// width of the second operand
    pub b: u32,
    /// products of this shape in the stage
    pub count: u32,
}

/// One signal of one stage.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Row {
    /// stage: `setup`, `bounds/tri` (per-triangle preparation), `bounds/tile`, `sample`, `tile`
    pub stage: &'static str,
    /// the signal (formula)
    pub signal: &'static str,
    /// bound on |raw value|
    pub bound: Mag,
    /// the Rust container the code computes it in
    pub ty: &'static str,
    /// rounding / note
    pub note: &'static str,
    /// the multipliers forming it (products of two variables), if any
    pub mul: [Option<Mul>; 2],
}

impl Row {
    /// Signed width (sign included).
    pub const fn bits(&self) -> u32 {
        self.bound.bits()
    }
    /// Bits of the Rust container (`i32` → 32, `Wide` → 192).
    pub fn container_bits(&self) -> u32 {
        let t = self.ty.split_whitespace().next().unwrap_or("");
        match t {
            "i32" | "u32" => 32,
            "i64" => 64,
            "i128" => 128,
            "`Wide`" => 192,
            _ => 0,
        }
    }
}

/// Up to [`Table::CAP`] rows (no heap).
#[derive(Clone, Copy, Debug)]
pub struct Table {
    rows: [Option<Row>; Table::CAP],
}

impl Table {
    /// Capacity.
    pub const CAP: usize = 48;
    fn push(&mut self, r: Row) {
        if let Some(slot) = self.rows.iter_mut().find(|s| s.is_none()) {
            *slot = Some(r);
        }
    }
    /// The rows in order.
    pub fn rows(&self) -> impl Iterator<Item = &Row> {
        self.rows.iter().flatten()
    }
    /// The row of `stage` whose signal starts with `prefix`.
    pub fn find(&self, stage: &str, prefix: &str) -> Option<&Row> {
        self.rows()
            .find(|r| r.stage == stage && r.signal.starts_with(prefix))
    }
}

/// The raw domain constants as bounds.
const fn lim() -> Mag {
    Mag::int(COORD_LIMIT_RAW.unsigned_abs() as u128)
}
const fn one() -> Mag {
    Mag::pow2(TUV_FRAC)
}
const fn ext() -> Mag {
    Mag::int(MAX_VIEWPORT as u128)
}
/// Width of an operand bounded by `m` whose low `zeros` bits are known zero (a value on a
/// coarser grid in the 16-fraction-bit container): the multiplier drops them.
const fn opw(m: Mag, zeros: u32) -> u32 {
    let b = m.bits().saturating_sub(zeros);
    if b < 2 {
        2
    } else {
        b
    }
}

/// Per-class sample-test positions of the exact test: `(class, F, |P| bound)`.
pub fn exact_positions() -> [(&'static str, u32, Mag); 4] {
    let lerp = lim().mul(one()); // q·2^16 + T·(r − q) = (2^16 − T)·q + T·r
    [
        ("static", 16, lim()),
        ("motion", 32, lerp),
        ("defocus", 32, lim().mul(one()).add(one().mul(lim()))),
        ("both", 48, lerp.mul(one()).add(one().mul(lerp))),
    ]
}

/// The width table of configuration `cfg`: setup, bounds, the sample test of its kind, tile.
// The plain operators here count multipliers (small constants, < 2^10) and subtract 1 from a
// shift ≥ 20 (`Bounded`'s offset shift, `TUV_FRAC`); the bounds themselves use `Mag`'s
// saturating arithmetic.
#[allow(clippy::arithmetic_side_effects)]
pub fn table(cfg: &Config) -> Table {
    let mut t = Table {
        rows: [None; Table::CAP],
    };
    let (ex, ew) = cfg.eps_max();
    let (ex, ew) = (Mag::int(u128::from(ex)), Mag::int(u128::from(ew)));
    let bounded = cfg.off.is_some();
    let w_corners: u32 = if bounded { 2 } else { 1 };
    let c = lim();
    let e = ext();
    let ew13 = e.bits();
    let r = |stage, signal, bound, ty, note, mul| Row {
        stage,
        signal,
        bound,
        ty,
        note,
        mul,
    };
    let mul = |a: u32, b: u32, count: u32| [Some(Mul { a, b, count }), None];
    let two = |x: Mul, y: Mul| [Some(x), Some(y)];

    // ---- setup ----
    let a_c = c.add(c).add(ex);
    let w_e = c.add(ew);
    t.push(r(
        "setup",
        "corner `a ± \\|c\\| ± ε_x`",
        a_c,
        "i64",
        "exact",
        [None, None],
    ));
    t.push(r(
        "setup",
        "corner `w ± ε_w`",
        w_e,
        "i64",
        "exact",
        [None, None],
    ));
    let n_pts = 6 * w_corners;
    let pairs = n_pts * (n_pts - 1) / 2 * 2 * 2; // per side, two sides, two axes
                                                 // Worst case (no early exit): per pair the cross product takes two a×w, the dot product
                                                 // one a×a and one w×w.
    t.push(r(
        "setup",
        "separating-line cross `a_i·w_j − w_i·a_j`",
        a_c.mul(w_e).times(2),
        "i128",
        "exact",
        mul(a_c.bits(), w_e.bits(), 2 * pairs),
    ));
    t.push(r(
        "setup",
        "separating-line dot `a_i·a_j + w_i·w_j`",
        a_c.mul(a_c).add(w_e.mul(w_e)),
        "i128",
        "exact",
        two(
            Mul {
                a: a_c.bits(),
                b: a_c.bits(),
                count: pairs,
            },
            Mul {
                a: w_e.bits(),
                b: w_e.bits(),
                count: pairs,
            },
        ),
    ));
    let aw = c.add(c).add(ex).add(c).add(ew);
    let num = aw.mul(e).mul(Mag::pow2(cfg.bnd));
    t.push(r(
        "setup",
        "projection numerator `(a + u·cs ± ε_x + w ± ε_w)·E·2^BND`",
        num,
        "i128",
        "exact (2^BND: shift)",
        mul(aw.bits(), ew13, 2 * 2 * 2 * 6 * w_corners * 2),
    ));
    t.push(r(
        "setup",
        "box coordinate `X = num / 2w` (BND frac px)",
        num.shr_floor(1),
        "i64",
        "floor (min) / ceil (max); divide",
        [None, None],
    ));
    let dist = c.add(c).add(c).add(ex).add(ew);
    t.push(r(
        "setup",
        "frustum distance `w ± a + \\|c\\| + ε`",
        dist,
        "i128",
        "exact",
        [None, None],
    ));
    t.push(r(
        "setup",
        "frustum solve numerator `n·2^16` (0 ≤ n < d ≤ 2·dist)",
        dist.times(2).mul(one()),
        "i128",
        "ceil/floor outward; divide",
        [None, None],
    ));
    if !bounded {
        let pxy = c.times(3).add(c.times(3));
        let pw = c.times(3);
        let evals = 4 * 2 * 2;
        t.push(r(
            "setup",
            "degeneracy minors `y·w`, `x·w`, `x·y` (t ∈ {0,⅓,⅔,1}·3)",
            pxy.mul(pxy).times(2),
            "i128",
            "exact",
            mul(pxy.bits(), pxy.bits(), 6 * evals),
        ));
        t.push(r(
            "setup",
            "degeneracy det `Σ ±x·(y·w − w·y)`",
            pxy.mul(pxy).mul(pw).times(6),
            "i128",
            "exact",
            mul(pxy.bits(), pxy.mul(pxy).times(2).bits(), 3 * evals),
        ));
    }
    t.push(r(
        "setup",
        "static edge normal `n = P×P` (static class)",
        c.mul(c).times(2),
        "i128",
        "exact",
        mul(c.bits(), c.bits(), 18),
    ));

    // ---- bounds, per triangle (Laine2011::prepare) ----
    let slope = num.shr_floor(1).times(2);
    t.push(r(
        "bounds/tri",
        "lens slope `d = m⁺ − m⁻`",
        slope,
        "i64",
        "exact",
        [None, None],
    ));
    let recip = Mag::pow2(RECIP_SHIFT);
    t.push(r(
        "bounds/tri",
        "reciprocal `2^80/\\|d\\|` (up and down)",
        recip,
        "i128",
        "ceil / floor; divide",
        [None, None],
    ));
    let delta = c
        .times(2)
        .mul(e)
        .add(c.times(2).mul(e))
        .add(c.add(ex).add(ew).mul(e));
    t.push(r(
        "bounds/tri",
        "dual δ = `(a+w)·E − 2wξ ∓ (\\|c\\| + ε_x + ε_w)·E`",
        delta,
        "i64",
        "exact",
        // per axis: 6 vertex-ends × 2 footprint ends × ((a+w)·E and w·ξ) + 6 biases
        mul(c.times(2).bits(), ew13, 2 * (6 * 2 * 2 + 6)),
    ));
    // ---- bounds, per tile ----
    t.push(r(
        "bounds/tile",
        "lens solve `n·r` (0 ≤ n < \\|d\\|)",
        recip.add(slope),
        "i128",
        "then ÷2^64, ceil/floor",
        mul(slope.bits(), recip.bits(), 4),
    ));
    let line = delta.mul(e);
    t.push(r(
        "bounds/tile",
        "bounding line `δ_a·(ξb − x) + δ_b·(x − ξa)`",
        line,
        "i128",
        "exact (no division)",
        mul(delta.bits(), ew13, 2 * 4 * 2 * 2),
    ));
    t.push(r(
        "bounds/tile",
        "t solve numerator `n·2^16` (0 ≤ n < d ≤ 2·line)",
        line.times(2).mul(one()),
        "i128",
        "ceil/floor outward; divide",
        [None, None],
    ));

    // ---- sample test ----
    let sub = Mag::pow2(SUBPIXEL_BITS);
    let t_op = opw(one(), 16u32.saturating_sub(cfg.tuv)); // T, U, V on the TUV grid
    let dq = c.times(2); // r − q
    let lerp = c.mul(one());
    match cfg.off {
        None => {
            let d = sub.mul(e).mul(e);
            let gx = sub.mul(e); // |2xs − 256W| ≤ 256W
            t.push(r(
                "sample",
                "direction `d`",
                d,
                "i64",
                "exact",
                mul(gx.bits(), ew13, 3),
            ));
            t.push(r(
                "sample",
                "lerp `q·2^16 + T·(r − q)`",
                lerp,
                "i64",
                "exact",
                mul(t_op, opw(dq, 16u32.saturating_sub(cfg.pos)), 15),
            ));
            let [_, _, _, (_, _, p)] = exact_positions();
            t.push(r(
                "sample",
                "vertex P at (t,u,v), 48 frac (both)",
                p,
                "i64",
                "exact",
                mul(t_op, lerp.bits(), 6),
            ));
            let n = p.mul(p).times(2);
            t.push(r(
                "sample",
                "edge normal `n = P×P`",
                n,
                "i128",
                "exact",
                mul(p.bits(), p.bits(), 18),
            ));
            let ev = n.mul(d).times(3);
            t.push(r(
                "sample",
                "edge value `E = n·d`",
                ev,
                "`Wide` (192)",
                "exact",
                mul(n.bits(), d.bits(), 9),
            ));
            let det = p.mul(n).times(3);
            t.push(r(
                "sample",
                "`det = P0·n0`",
                det,
                "`Wide` (192)",
                "exact",
                mul(p.bits(), n.bits(), 3),
            ));
            // 2^DEPTH_EDGE_BITS − 1 with DEPTH_EDGE_BITS ≤ 32: a constant shift, checked by the compiler.
            const ES: u128 = (1u128 << DEPTH_EDGE_BITS) - 1;
            let es = Mag::int(ES);
            let dn = es.mul(p).times(3);
            t.push(r(
                "sample",
                "depth `Σ E'·z`, `Σ E'·w` (E' = E floored to 32 significant bits, \\|E'\\| < 2^32)",
                dn,
                "i128",
                "floor",
                mul(es.bits(), p.bits(), 6),
            ));
            t.push(r(
                "sample",
                "depth quotient numerator `num·2^24`",
                dn.mul(Mag::pow2(DEPTH_FRAC)),
                "i128",
                "floor, saturate; divide",
                [None, None],
            ));
        }
        Some(s) => {
            t.push(r(
                "sample",
                "1 lerp `f0·2^16 + T·(f1 − f0)`",
                lerp,
                "i64",
                "exact",
                mul(t_op, opw(dq, 16u32.saturating_sub(cfg.pos)), 15),
            ));
            let ft = lerp.add(Mag::pow2(TUV_FRAC - 1)).shr_floor(TUV_FRAC);
            t.push(r(
                "sample",
                "1 lerped `f_t = rnd16(…)`",
                ft,
                "i64",
                "nearest, ties up",
                [None, None],
            ));
            t.push(r(
                "sample",
                "2 lens product `U·c_t`",
                one().mul(ft),
                "i64",
                "exact",
                mul(t_op, ft.bits(), 6),
            ));
            let x = ft.add(
                one()
                    .mul(ft)
                    .add(Mag::pow2(TUV_FRAC - 1))
                    .shr_floor(TUV_FRAC),
            );
            t.push(r(
                "sample",
                "2 `x = x_t + rnd16(U·c_t)`",
                x,
                "i64",
                "nearest, ties up",
                [None, None],
            ));
            let sw = sub.mul(e);
            let aa = sw.mul(x).add(sw.mul(ft));
            // The multipliers: W·x (the factor 256 is wiring, W ≤ 2^11) and
            // (2xs − 256W)·w (|2xs − 256W| ≤ 256W), six of each.
            t.push(r(
                "sample",
                "3 offset `A = 256W·x − (2xs − 256W)·w`",
                aa,
                "i64",
                "exact",
                two(
                    Mul {
                        a: ew13,
                        b: x.bits(),
                        count: 6,
                    },
                    Mul {
                        a: sw.bits(),
                        b: ft.bits(),
                        count: 6,
                    },
                ),
            ));
            let half = Mag::pow2(s.saturating_sub(1));
            t.push(r(
                "sample",
                "4 `A + 2^(S−1)`",
                aa.add(half),
                "i64",
                "exact",
                [None, None],
            ));
            let ap = aa.add(half).shr_floor(s);
            t.push(r(
                "sample",
                "4 rounded offset `a' = rnd_S(A)`",
                ap,
                "i64",
                "nearest, ties up",
                [None, None],
            ));
            let ep = ap.mul(ap).times(2);
            t.push(r(
                "sample",
                "5 edge `E' = a'·b' − a'·b'`",
                ep,
                "i64",
                "exact",
                mul(ap.bits(), ap.bits(), 6),
            ));
            t.push(r(
                "sample",
                "6 orientation (rare path) `Σ E'·w`",
                ep.mul(ft).times(3),
                "i128",
                "exact",
                mul(ep.bits(), ft.bits(), 3),
            ));
            // 2^BOUNDED_DEPTH_EDGE_BITS − 1 with BOUNDED_DEPTH_EDGE_BITS ≤ 32: a constant shift, checked by the compiler.
            const ES: u128 = (1u128 << BOUNDED_DEPTH_EDGE_BITS) - 1;
            let es = Mag::int(ES);
            let dn = es.mul(ft).times(3);
            t.push(r(
                "sample",
                "8 depth `Σ E''·z`, `Σ E''·w` (\\|E''\\| < 2^24)",
                dn,
                "i64",
                "floor",
                mul(es.bits(), ft.bits(), 6),
            ));
            t.push(r(
                "sample",
                "8 depth quotient numerator `num·2^24`",
                dn.mul(Mag::pow2(DEPTH_FRAC)),
                "i128",
                "floor, saturate; divide",
                [None, None],
            ));
        }
    }
    t.push(r(
        "tile",
        "resolve sum of S ≤ 64 channels",
        Mag::int(64 * 255),
        "u32",
        "`(Σ + S/2)/S`",
        [None, None],
    ));
    t
}

/// The width table of `cfg` as Markdown (the `core/README.md` table; `uvt widths`).
pub fn write_markdown<W: fmt::Write>(out: &mut W, cfg: &Config) -> fmt::Result {
    let (ex, ew) = cfg.eps_max();
    writeln!(
        out,
        "Configuration `{cfg}` (domain: |clip| ≤ {}, t/u/v ≤ 2^{TUV_FRAC}, W, H ≤ {}, {} sub-pixel bits; ε_x ≤ {ex}, ε_w ≤ {ew} raw):",
        lim(),
        MAX_VIEWPORT,
        SUBPIXEL_BITS
    )?;
    writeln!(out)?;
    writeln!(
        out,
        "| stage | signal | bound on \\|raw\\| | bits | Rust type | multiplier (count) | note |"
    )?;
    writeln!(out, "|---|---|---|---|---|---|---|")?;
    for r in table(cfg).rows() {
        write!(
            out,
            "| {} | {} | {} | {} | {} | ",
            r.stage,
            r.signal,
            r.bound,
            r.bits(),
            r.ty
        )?;
        let mut any = false;
        for m in r.mul.iter().flatten() {
            let sep = if any { ", " } else { "" };
            write!(out, "{sep}{} × {} ({})", m.a, m.b, m.count)?;
            any = true;
        }
        if !any {
            write!(out, "–")?;
        }
        writeln!(out, " | {} |", r.note)?;
    }
    Ok(())
}

/// The per-class widths of the exact sample test as Markdown.
pub fn write_class_markdown<W: fmt::Write>(out: &mut W) -> fmt::Result {
    writeln!(
        out,
        "| class | P frac bits | \\|P\\| | P bits | n bits | E bits | det bits |"
    )?;
    writeln!(out, "|---|---|---|---|---|---|---|")?;
    let e = ext();
    let d = Mag::pow2(SUBPIXEL_BITS).mul(e).mul(e);
    for (name, f, p) in exact_positions() {
        let n = p.mul(p).times(2);
        writeln!(
            out,
            "| {name} | {f} | {p} | {} | {} | {} | {} |",
            p.bits(),
            n.bits(),
            n.mul(d).times(3).bits(),
            p.mul(n).times(3).bits()
        )?;
    }
    Ok(())
}

/// The configurations of `core/README.md`'s width section: the exact test and the bounded
/// default.
pub const README_CONFIGS: [Config; 2] = [
    Config::of::<crate::config::precision::Exact>(),
    Config::of::<crate::config::precision::BoundedPrecision>(),
];

/// The whole generated width section of `core/README.md` (`uvt widths` with no `--config`):
/// each configuration's table, then the exact test's widths per class.
pub fn write_readme<W: fmt::Write>(out: &mut W) -> fmt::Result {
    for cfg in README_CONFIGS.iter() {
        write_markdown(out, cfg)?;
        writeln!(out)?;
    }
    writeln!(
        out,
        "The exact sample test per class (the table above is class both):"
    )?;
    writeln!(out)?;
    write_class_markdown(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn generated() -> String {
        let mut s = String::new();
        write_readme(&mut s).unwrap();
        s
    }

    #[test]
    fn readme_table_is_generated() {
        let readme = include_str!("../README.md");
        let begin = readme
            .find("<!-- widths:begin")
            .expect("begin marker in core/README.md");
        let body = &readme[begin..];
        let body = &body[body.find('\n').unwrap() + 1..];
        let end = body
            .find("<!-- widths:end -->")
            .expect("end marker in core/README.md");
        let want = generated();
        assert_eq!(
            body[..end].trim_end(),
            want.trim_end(),
            "core/README.md's width section differs from `uvt widths`; regenerate it"
        );
    }

    #[test]
    fn mag_hand_cases() {
        assert_eq!(Mag::pow2(29).bits(), 31, "+2^29 needs 31 bits with sign");
        assert_eq!(Mag::pow2(46).bits(), 48);
        assert_eq!(Mag::int((1 << 29) - 1).bits(), 30);
        assert_eq!(Mag::int(3).mul(Mag::pow2(155)).bits(), 158);
        assert_eq!(Mag::int(0).bits(), 1);
        assert_eq!(Mag::int(5).add(Mag::int(3)), Mag::pow2(3));
        assert_eq!(
            Mag::pow2(200).add(Mag::int(1)),
            Mag::pow2(202),
            "rounded up (both < 2^201)"
        );
        assert_eq!(Mag::int(7).shr_floor(1), Mag::int(3));
        assert_eq!(Mag::pow2(40).shr_floor(8), Mag::pow2(32));
        assert_eq!(Mag::int(6).max(Mag::int(5)), Mag::int(6));
        assert_eq!(Mag::int(3).mul(Mag::pow2(100)).to_u128(), Some(3 << 100));
        assert_eq!(Mag::pow2(130).to_u128(), None);
        assert_eq!(format!("{}", Mag::int(3).mul(Mag::pow2(56))), "3·2^56");
        assert_eq!(format!("{}", Mag::int(16320)), "16320");
    }

    #[test]
    fn config_names() {
        let c = Config::parse("bounded-16-16-16-20").unwrap();
        assert_eq!(
            c,
            Config::of::<crate::config::precision::BoundedPrecision>()
        );
        assert_eq!(format!("{c}"), "bounded-16-16-16-20");
        let e = Config::parse("exact-16-16-16").unwrap();
        assert_eq!(e, Config::of::<crate::config::precision::Exact>());
        for bad in [
            "exact-16-16",
            "exact-16-16-16-20",
            "bounded-16-16-16",
            "bounded-16-16-16-19",
            "bounded-16-16-16-33",
            "exact-17-16-16",
            "exact-1-16-16",
            "exact-16-16-17",
            "fast-16-16-16",
            "",
        ] {
            assert_eq!(Config::parse(bad), None, "{bad}");
        }
    }

    /// The entries issue 10 lists as wrong in the old hand-written table.
    #[test]
    fn corrected_entries() {
        let t = table(&Config::of::<crate::config::precision::Exact>());
        // Clip coordinates up to +2^29 raw: 31 bits with sign.
        let w = t.find("setup", "corner `w").unwrap();
        assert_eq!((w.bound, w.bits()), (Mag::pow2(29), 31));
        // 32-fraction-bit positions (defocus-only) reach 2^46: 48 bits.
        let [_, _, (name, f, p), _] = exact_positions();
        assert_eq!((name, f, p, p.bits()), ("defocus", 32, Mag::pow2(46), 48));
        // The separating-line products: 62 bits, formed in i128 by `crosses_camera_plane`.
        let s = t.find("setup", "separating-line cross").unwrap();
        assert_eq!((s.bits(), s.ty), (62, "i128"));
    }

    /// Every configuration of the sweep fits its declared containers, and the bounded sample
    /// test's multiplier operands stay ≤ 32 bits at the default's grid (issue 10, item 2).
    #[test]
    fn containers_hold_every_row() {
        for name in [
            "exact-16-16-16",
            "bounded-16-16-16-20",
            "bounded-16-16-16-24",
            "bounded-12-12-12-26",
            "bounded-8-8-8-28",
            "bounded-16-16-16-32",
        ] {
            let cfg = Config::parse(name).unwrap();
            for r in table(&cfg).rows() {
                assert!(
                    r.bits() <= r.container_bits(),
                    "{name}: {} needs {} bits in {}",
                    r.signal,
                    r.bits(),
                    r.ty
                );
            }
        }
        let t = table(&Config::of::<crate::config::precision::BoundedPrecision>());
        for r in t.rows().filter(|r| r.stage == "sample") {
            for m in r.mul.iter().flatten() {
                let rare = r.signal.starts_with("6 ");
                assert!(rare || (m.a <= 33 && m.b <= 33), "{}: {m:?}", r.signal);
            }
        }
    }
}
