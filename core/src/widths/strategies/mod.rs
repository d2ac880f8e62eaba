//! Every registry strategy's operators by width ([`inventory`]), composed from the operators of
//! its parts, one file per part: the composed strategies run their parts' code (the hull's cull
//! in front of the inner strategy's bounds; `auto` holds every candidate's unit and picks per
//! triangle), so their inventories are the sums of their parts'.

pub mod edge_time;
pub mod hull;
pub mod hyper;
pub mod laine;
pub mod lens_time;

use crate::config::registry::Config;
use crate::widths::ops::{Classes, Inventory, OpKind, Stage};
use crate::widths::row::ext;

/// The operators of the strategy named `name` (one of
/// [`STRATEGIES`](crate::bounds::registry::STRATEGIES)) at configuration `cfg`; `None` for any
/// other name.
pub fn inventory(name: &str, cfg: &Config) -> Option<Inventory> {
    let mut inv = Inventory::default();
    let i = &mut inv;
    match name {
        "bbox" => {}
        "laine2011" => laine::push(i, cfg),
        "hull" => {
            hull::push(i, cfg);
            laine::push(i, cfg);
        }
        "lens-t" => {
            laine::push(i, cfg);
            lens_time::push(i, cfg);
        }
        "hyper" => {
            laine::push(i, cfg);
            hyper::push(i, cfg);
        }
        "hull+lens-t" => {
            hull::push(i, cfg);
            laine::push(i, cfg);
            lens_time::push(i, cfg);
        }
        "hull+edge-t" => {
            hull::push(i, cfg);
            edge_time::push(i, cfg);
            laine::push(i, cfg);
        }
        "best" => {
            hull::push(i, cfg);
            edge_time::push(i, cfg);
            laine::push(i, cfg);
            hyper::push(i, cfg);
        }
        "auto" => {
            auto_pick(i);
            hull::push(i, cfg);
            edge_time::push(i, cfg);
            laine::push(i, cfg);
        }
        _ => return None,
    }
    Some(inv)
}

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
