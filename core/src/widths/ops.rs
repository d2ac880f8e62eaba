//! A bounds strategy's operators by width, stage by stage: the inventory the hardware cost of a
//! strategy is computed from (`uvt cost --strategies`; the tiling rule is the host's
//! `config/multipliers.rs`).
//!
//! Each [`Op`] is one kind of operator of one stage on the stage's **worst-case path** (no early
//! exit, every loop at its bound), with its operand widths derived by [`Mag`] from the domain
//! constants (the same bounds the code's range comments state), and how many the stage runs per
//! item: per triangle (the strategy's `prepare`), per bounds tile, per row span, per sample
//! (the predicate). A fully parallel unit instantiates `count` operators of the kind per stage;
//! an iterative one runs `count` operations on one operator — the same number read as work.
//!
//! An operator is counted where the code's op tally ([`crate::stats::Ops`]) counts one: adds,
//! subtracts, multiplies, divides, compares, min and max; negations, absolute values, shifts by
//! constants and selects are wiring and muxes, not listed.
//!
//! [`Mag`]: crate::widths::mag::Mag

use crate::config::class::Class;

/// What one operator does, with its widths (bits, sign included).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OpKind {
    /// signed `a × b` multiplier
    Mul {
        /// first operand's width
        a: u32,
        /// second operand's width
        b: u32,
    },
    /// adder or subtractor of `bits`-bit operands (its result width)
    Add {
        /// width
        bits: u32,
    },
    /// comparator, min or max of two `bits`-bit values
    Cmp {
        /// width
        bits: u32,
    },
    /// divider giving `quot` quotient bits for a `den`-bit divisor (restoring: `quot` steps of a
    /// `den + 1`-bit subtractor)
    Div {
        /// divisor width
        den: u32,
        /// quotient bits
        quot: u32,
    },
}

/// The stage an operator belongs to (what its count is per).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Stage {
    /// per triangle: the strategy's `prepare` (part of setup)
    Triangle,
    /// per bounds tile: `tile` / `span_tile`
    Tile,
    /// per row of bounds tiles: `row_span`
    Row,
    /// per sample inside the tile's box: the predicate
    Predicate,
}

impl Stage {
    /// Every stage, in order.
    pub const ALL: [Stage; 4] = [Stage::Triangle, Stage::Tile, Stage::Row, Stage::Predicate];
    /// Name for tables: "triangle", "tile", "row", "sample".
    pub const fn name(self) -> &'static str {
        match self {
            Stage::Triangle => "triangle",
            Stage::Tile => "tile",
            Stage::Row => "row",
            Stage::Predicate => "sample",
        }
    }
}

/// The classes an operator runs for: a set of [`Class::index`] bits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Classes(u8);

impl Classes {
    /// every class
    pub const ALL: Classes = Classes(0b1111);
    /// the moving classes (motion, motion + defocus)
    pub const MOTION: Classes = Classes(0b1010);
    /// the defocused classes (defocus, motion + defocus)
    pub const DEFOCUS: Classes = Classes(0b1100);
    /// motion + defocus only
    pub const BOTH: Classes = Classes(0b1000);
    /// motion only
    pub const MOTION_ONLY: Classes = Classes(0b0010);
    /// static only
    pub const STATIC: Classes = Classes(0b0001);
    /// Whether `c` is in the set.
    pub fn has(self, c: Class) -> bool {
        let bit = match c {
            Class::Static => 1,
            Class::Motion => 2,
            Class::Defocus => 4,
            Class::MotionDefocus => 8,
        };
        self.0 & bit != 0
    }
}

/// One kind of operator of one stage and how many of it the stage's worst-case path runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Op {
    /// stage
    pub stage: Stage,
    /// what it computes (formula, as in the code)
    pub what: &'static str,
    /// operator and widths
    pub kind: OpKind,
    /// operations per item of the stage (per triangle, tile, row or sample), worst case
    pub count: u32,
    /// the classes it runs for
    pub classes: Classes,
}

/// A strategy's operators (no heap: up to [`Inventory::CAP`]).
#[derive(Clone, Copy, Debug)]
pub struct Inventory {
    ops: [Option<Op>; Inventory::CAP],
    full: bool,
}

impl Default for Inventory {
    fn default() -> Self {
        Inventory {
            ops: [None; Inventory::CAP],
            full: false,
        }
    }
}

impl Inventory {
    /// Capacity.
    pub const CAP: usize = 256;
    /// Add one operator (a full inventory records that it dropped one: [`Self::is_complete`]).
    pub fn push(&mut self, op: Op) {
        match self.ops.iter_mut().find(|s| s.is_none()) {
            Some(slot) => *slot = Some(op),
            None => self.full = true,
        }
    }
    /// Shorthand for [`Self::push`].
    pub fn op(&mut self, stage: Stage, what: &'static str, kind: OpKind, count: u32, cl: Classes) {
        self.push(Op {
            stage,
            what,
            kind,
            count,
            classes: cl,
        });
    }
    /// Add every operator of `o`.
    pub fn extend(&mut self, o: &Inventory) {
        for op in o.ops() {
            self.push(*op);
        }
        self.full |= o.full;
    }
    /// Whether every pushed operator was kept (false: [`Self::CAP`] is too small).
    pub fn is_complete(&self) -> bool {
        !self.full
    }
    /// The operators in order.
    pub fn ops(&self) -> impl Iterator<Item = &Op> {
        self.ops.iter().flatten()
    }
    /// Operations per item of `stage` for a triangle of class `c` (Σ count, saturating).
    pub fn count(&self, stage: Stage, c: Class) -> u64 {
        self.ops()
            .filter(|o| o.stage == stage && o.classes.has(c))
            .fold(0u64, |s, o| s.saturating_add(u64::from(o.count)))
    }
}
