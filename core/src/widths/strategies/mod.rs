//! Every registry strategy's operators by width ([`inventory`]), composed from the operators of
//! its parts, one file per part: the composed strategies run their parts' code (the hull's cull
//! in front of the inner strategy's bounds; `auto` holds every candidate's unit and picks per
//! triangle), so their inventories are the sums of their parts'.

pub mod edge_time;
pub mod hull;
pub mod hyper;
pub mod laine;
pub mod lens_time;

use crate::bounds::auto::Auto;
use crate::bounds::bbox::BboxScan;
use crate::bounds::composed::BEST_SLABS;
use crate::bounds::edge_time::EdgeTime;
use crate::bounds::hull::HullCull;
use crate::bounds::hyper::Hyper;
use crate::bounds::laine::Laine2011;
use crate::bounds::lens_time::LensTime;
use crate::config::registry::Config;
use crate::widths::ops::{Classes, Inventory, OpKind, Stage};
use crate::widths::row::ext;

/// The operators of the strategy named `name` (one of
/// [`STRATEGIES`](crate::bounds::registry::STRATEGIES), through
/// [`with_strategy!`](crate::with_strategy)) at configuration `cfg`; `None` for any other name.
pub fn inventory(name: &str, cfg: &Config) -> Option<Inventory> {
    with_strategy!(name, s => of(&s, cfg))
}

/// The operators of strategy `s` at configuration `cfg`.
pub fn of<S: Operators>(_: &S, cfg: &Config) -> Inventory {
    let mut inv = Inventory::default();
    S::push(&mut inv, cfg);
    inv
}

/// A strategy's operators by width, composed as the strategy is composed: a part's own
/// operators ([`laine`], [`hull`], …), then its inner strategy's. Every strategy of the registry
/// has them (a test and [`inventory`] check it).
pub trait Operators {
    /// Push the strategy's operators at configuration `cfg`.
    fn push(inv: &mut Inventory, cfg: &Config);
}

impl Operators for BboxScan {
    /// The bounding-box scan computes no bounds.
    fn push(_: &mut Inventory, _: &Config) {}
}

impl Operators for Laine2011 {
    fn push(inv: &mut Inventory, cfg: &Config) {
        laine::push(inv, cfg);
    }
}

/// Lens-dependent time bounds on Laine 2011's, at the registry's slab count.
impl Operators for LensTime<BEST_SLABS> {
    fn push(inv: &mut Inventory, cfg: &Config) {
        laine::push(inv, cfg);
        lens_time::push(inv, cfg);
    }
}

/// The bilinear surfaces on Laine 2011's bounds.
impl Operators for Hyper {
    fn push(inv: &mut Inventory, cfg: &Config) {
        laine::push(inv, cfg);
        hyper::push(inv, cfg);
    }
}

/// Swept-hull culling in front of the inner strategy.
impl<S: Operators> Operators for HullCull<S> {
    fn push(inv: &mut Inventory, cfg: &Config) {
        hull::push(inv, cfg);
        S::push(inv, cfg);
    }
}

/// The edge-direction time bound in front of the inner strategy.
impl<S: Operators> Operators for EdgeTime<S> {
    fn push(inv: &mut Inventory, cfg: &Config) {
        edge_time::push(inv, cfg);
        S::push(inv, cfg);
    }
}

/// `auto`: its pick and travel limit, and every candidate's unit ([`Pick`](crate::bounds::auto::tier::Pick)):
/// the largest candidate's operators, hull+edge-t's, hold the others' (hull's, Laine 2011's).
impl Operators for Auto {
    fn push(inv: &mut Inventory, cfg: &Config) {
        auto_pick(inv);
        auto_travel(inv, cfg);
        <HullEdge as Operators>::push(inv, cfg);
    }
}

/// The type of `auto`'s largest candidate.
type HullEdge = HullCull<EdgeTime<Laine2011>>;

/// `Auto::pick`: the footprint check (its area against the least of the tier's two areas), then
/// the own extent's area (`Auto::area`) and the tier compare, per triangle, every class (the
/// unit builds the whole path; the check only spares its time). The lens-corner box ends are
/// counted at their 64-bit container (floored to pixels, they are not clamped to the viewport);
/// the least side is then ≤ the footprint's.
fn auto_pick(inv: &mut Inventory) {
    let side = ext().bits();
    let area = side.saturating_mul(2);
    let tri = Stage::Triangle;
    inv.op(
        tri,
        "footprint sides `x1 − x0`, `y1 − y0`",
        OpKind::Add { bits: side },
        2,
        Classes::ALL,
    );
    inv.op(
        tri,
        "footprint's area (the check)",
        OpKind::Mul { a: side, b: side },
        1,
        Classes::ALL,
    );
    inv.op(
        tri,
        "least of the tier's areas `min(hull_from, edge_from)`",
        OpKind::Cmp { bits: 32 },
        1,
        Classes::ALL,
    );
    inv.op(
        tri,
        "footprint check `area < min(…)`",
        OpKind::Cmp { bits: 32 },
        1,
        Classes::ALL,
    );
    inv.op(
        tri,
        "own sides `⌊hi⌋ − ⌊lo⌋ + 1`, 2 axes × 2 lens corners",
        OpKind::Add { bits: 64 },
        2 * 2 * 2,
        Classes::ALL,
    );
    inv.op(
        tri,
        "least side per axis (2 corners, footprint)",
        OpKind::Cmp { bits: 64 },
        2 * 2,
        Classes::ALL,
    );
    inv.op(
        tri,
        "own extent's area",
        OpKind::Mul { a: side, b: side },
        1,
        Classes::ALL,
    );
    inv.op(
        tri,
        "tier compares `area ≥ edge_from`, `area ≥ hull_from`",
        OpKind::Cmp { bits: area },
        2,
        Classes::ALL,
    );
}

/// `Auto::start_area` and the travel limit (`Tier::pick_travel`), per moving triangle whose
/// area picks hull+edge-t under a tier with a limit: the lens-corner boxes of the three
/// shutter-open vertices (`setup::boxes::start_boxes`, setup's box path on three points
/// without ε: corner points, the camera-plane test per side, the ratio compares by
/// cross-multiplication, one projection per box end), their area as the own extent's, and the
/// limit's multiply and compare. The rule's tiers without a limit never run it; the unit builds
/// it for the moving classes.
// Counts are products of small constants (axes 2, lens corners 2, box ends 2, points 3).
#[allow(clippy::arithmetic_side_effects)]
fn auto_travel(inv: &mut Inventory, cfg: &Config) {
    let t = crate::widths::stages::table(cfg);
    let num = laine::row_bits(&t, "setup", "projection numerator");
    let quot = laine::row_bits(&t, "setup", "box coordinate");
    let side = ext().bits();
    let (tri, m) = (Stage::Triangle, Classes::MOTION);
    inv.op(
        tri,
        "start box: corner points `a ± |c|`, `a + u·c` (2 axes × 3 points × 2)",
        OpKind::Add { bits: 32 },
        2 * 3 * 2 * 2,
        m,
    );
    inv.op(
        tri,
        "start box: camera-plane test products (2 axes × 2 sides × (2 per point + 2))",
        OpKind::Mul { a: 32, b: 32 },
        2 * 2 * (2 * 3 + 2),
        m,
    );
    inv.op(
        tri,
        "start box: camera-plane test compares and sum (2 axes × 2 sides × 4)",
        OpKind::Cmp { bits: 64 },
        2 * 2 * 4,
        m,
    );
    inv.op(
        tri,
        "start box: ratio products `a·w′`, `a′·w` (2 axes × 2 lens corners × 2 ends × 3 points × 2)",
        OpKind::Mul { a: 32, b: 32 },
        2 * 2 * 2 * 3 * 2,
        m,
    );
    inv.op(
        tri,
        "start box: ratio compares (2 axes × 2 lens corners × 2 ends × 3 points)",
        OpKind::Cmp { bits: 64 },
        2 * 2 * 2 * 3,
        m,
    );
    inv.op(
        tri,
        "start box: projection numerator `(a + w)·E·2^BND` (2 axes × 2 lens corners × 2 ends)",
        OpKind::Mul { a: 33, b: side },
        2 * 2 * 2,
        m,
    );
    inv.op(
        tri,
        "start box: box end `num / 2w`",
        OpKind::Div {
            den: 31,
            quot: quot.max(num.saturating_sub(31)),
        },
        2 * 2 * 2,
        m,
    );
    inv.op(
        tri,
        "start sides `⌊hi⌋ − ⌊lo⌋ + 1`, 2 axes × 2 lens corners",
        OpKind::Add { bits: 64 },
        2 * 2 * 2,
        m,
    );
    inv.op(
        tri,
        "least start side per axis (2 corners, footprint)",
        OpKind::Cmp { bits: 64 },
        2 * 2,
        m,
    );
    inv.op(
        tri,
        "start box's area",
        OpKind::Mul { a: side, b: side },
        1,
        m,
    );
    inv.op(
        tri,
        "travel limit `edge_travel × start`",
        OpKind::Mul { a: 32, b: side * 2 },
        1,
        m,
    );
    inv.op(
        tri,
        "travel compare `area > edge_travel × start`",
        OpKind::Cmp { bits: 32 },
        1,
        m,
    );
}
