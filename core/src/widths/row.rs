//! A row of the width table: a signal's magnitude bound, container and multiplier, and the
//! domain's operand magnitudes every row starts from.

use crate::config::class::Class;
use crate::config::formats::{COORD_LIMIT_RAW, MAX_VIEWPORT, TUV_FRAC};
use crate::config::registry::Config;
use crate::input::Viewport;
use crate::setup::eps::Eps;
use crate::widths::mag::Mag;

/// Significant bits (magnitude) the bounded test keeps of each edge value for the depth
/// interpolation: `|E''| < 2^24` (`bounded.rs`, step 8).
pub const BOUNDED_DEPTH_EDGE_BITS: u32 = 24;

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
    pub(crate) rows: [Option<Row>; Table::CAP],
}

impl Table {
    /// Capacity.
    pub const CAP: usize = 48;
    pub(crate) fn push(&mut self, r: Row) {
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
pub(crate) const fn lim() -> Mag {
    Mag::int(COORD_LIMIT_RAW.unsigned_abs() as u128)
}

pub(crate) const fn one() -> Mag {
    Mag::pow2(TUV_FRAC)
}

pub(crate) const fn ext() -> Mag {
    Mag::int(MAX_VIEWPORT as u128)
}

/// Width of an operand bounded by `m` whose low `zeros` bits are known zero (a value on a
/// coarser grid in the 16-fraction-bit container): the multiplier drops them.
pub(crate) const fn opw(m: Mag, zeros: u32) -> u32 {
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

/// The largest conservative epsilon over classes and viewports (x/y, w), raw clip units:
/// [`Eps::of`] at class both on a 1×1 viewport (ε falls with the extent).
pub fn eps_max(cfg: &Config) -> (u32, u32) {
    let Ok(vp) = Viewport::new(1, 1) else {
        return (0, 0);
    };
    let e = Eps::of(cfg.off(), Class::MotionDefocus, vp);
    let [x, _] = e.x();
    (x.unsigned_abs(), e.w().unsigned_abs())
}
