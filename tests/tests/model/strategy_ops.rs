//! Every strategy's operator inventory (`uvt_core::widths::strategies`, the input of the
//! hardware cost `uvt cost --strategies`) against the code's own op tallies (`Ops`): for
//! seeded-random triangles of every kind (`UVT_SEED`, printed on failure; more with
//! `UVT_EXTENSIVE=1`), at the exact and the default bounded precision and bounds tiles 1, 2, 4
//! and 8, per triangle (`prepare`), per tile, per row span and per predicate call:
//! - the tally never exceeds the inventory's worst-case count for the triangle's class (an
//!   inventory that leaves out a block the code counts fails), and
//! - a stage of a class has operators in the inventory if and only if the code counted
//!   operations there for some triangle of the sweep (an inventory listing hardware the code
//!   never runs fails, as does one missing a stage).

use std::collections::BTreeMap;
use uvt_core::bounds::registry::STRATEGIES;
use uvt_core::bounds::strategy::{BoundsStrategy, TileBounds};
use uvt_core::config::class::Class;
use uvt_core::config::registry::Config;
use uvt_core::config::unit::Full;
use uvt_core::widths::ops::{Inventory, Stage};
use uvt_core::widths::strategies::inventory;
use uvt_core::{setup, DefaultPrecision, Exact, Ops, Outcome, Precision, Triangle, Viewport};
use uvt_tests::kinds::{make, ALL_KINDS, NP};
use uvt_tests::*;

/// Largest tally seen per (stage, class index).
type Seen = BTreeMap<(Stage, usize), u64>;

/// One triangle through strategy `b` at precision `P`: every tally against `inv`.
fn check<B: BoundsStrategy, P: Precision>(
    b: &B,
    inv: &Inventory,
    t: &Triangle,
    rng: &mut Rng,
    seen: &mut Seen,
) -> Result<(), String> {
    let vp = Viewport::new(64, 48).unwrap();
    let mut ops = Ops::default();
    let Outcome::Visible(s) = setup::<P, Full>(t, vp, &mut ops) else {
        return Ok(());
    };
    let class = s.class();
    let mut note = |stage: Stage, n: u64| -> Result<(), String> {
        let cap = inv.count(stage, class);
        let m = seen.entry((stage, class.index())).or_insert(0);
        *m = (*m).max(n);
        if n > cap {
            return Err(format!(
                "{}: {} ops per {} ({n:#x}) for class {}, the inventory's worst case is {cap} ({cap:#x})",
                b.name(),
                n,
                stage.name(),
                class.name()
            ));
        }
        Ok(())
    };
    let mut o = Ops::default();
    let c = b.prepare::<Full>(&s, &mut o);
    note(Stage::Triangle, o.setup)?;
    let fp = s.footprint();
    for bt in [1u16, 2, 4, 8] {
        for row in fp.rows(bt) {
            let mut o = Ops::default();
            let _ = b.row_span(&s, &c, row, bt, &mut o);
            note(Stage::Row, o.rows)?;
            for cell in row.cells(bt) {
                let mut o = Ops::default();
                let tile = b.tile::<Full>(&s, &c, cell, &mut o);
                note(Stage::Tile, o.bounds)?;
                let Some(tile) = tile else { continue };
                for _ in 0..4 {
                    let one = 1i64 << 16;
                    let u = rng.below(2 * one as u64 + 1) as i64 - one;
                    let v = rng.below(2 * one as u64 + 1) as i64 - one;
                    let tt = rng.below(one as u64 + 1) as i64;
                    let mut o = Ops::default();
                    let _ = tile.predicate(u as i32, v as i32, tt as i32, &mut o);
                    note(Stage::Predicate, o.predicate)?;
                }
            }
        }
    }
    Ok(())
}

fn sweep<B: BoundsStrategy>(b: &B, name: &str, seed: u64) -> Result<(), String> {
    let cfg = Config::of::<DefaultPrecision>();
    let inv = inventory(name, &cfg).ok_or(format!("{name}: no inventory"))?;
    if !inv.is_complete() {
        return Err(format!("{name}: the inventory overflowed its capacity"));
    }
    let mut rng = Rng(seed ^ 0x0b5);
    let mut seen = Seen::new();
    for case in 0..cases(240, 6000) {
        let k = case as usize % ALL_KINDS.len();
        let mut p = [0.0; NP];
        p.iter_mut().for_each(|x| *x = rng.range(-1.0, 1.0));
        let t = make(ALL_KINDS[k], &p);
        check::<B, Exact>(b, &inv, &t, &mut rng, &mut seen)
            .and_then(|_| check::<B, DefaultPrecision>(b, &inv, &t, &mut rng, &mut seen))
            .map_err(|e| {
                format!(
                    "{e}\n  kind {:?}, case {case}, rerun with UVT_SEED={seed}\n{}",
                    ALL_KINDS[k],
                    dump(&t)
                )
            })?;
    }
    for stage in Stage::ALL {
        for c in Class::ALL {
            let have = inv.count(stage, c);
            let max = seen.get(&(stage, c.index())).copied().unwrap_or(0);
            println!(
                "{name:12} {:9} {:15} inventory {have:6}  tally max {max:6}",
                stage.name(),
                c.name()
            );
            if (have > 0) != (max > 0) {
                return Err(format!(
                    "{name}: per {} for class {}: the inventory lists {have} ops, the code's \
                     tally reached {max} over the sweep (UVT_SEED={seed})",
                    stage.name(),
                    c.name()
                ));
            }
        }
    }
    Ok(())
}

#[test]
fn every_strategy_inventory_covers_the_code_tallies() {
    let seed = seed();
    let mut failed = Vec::new();
    for name in STRATEGIES {
        let r = uvt_core::with_strategy!(name, s => sweep(&s, name, seed))
            .unwrap_or_else(|| Err(format!("{name}: not a strategy")));
        if let Err(e) = r {
            failed.push(e);
        }
    }
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}
