//! Comparing two renderers tile by tile (the specialised units' tests against the full unit):
//! every pixel's covered / written counts and every sample's depth and colour, with the
//! difference reported in decimal and hex.

use uvt_core::{Stats, TileBuffer};

/// The first difference between the full unit's tile `full` and the `name`d unit's tile
/// `unit`, both rendered at screen tile (`x0`, `y0`): a pixel's covered / written counts or a
/// sample's depth or colour.
pub fn same_tile(
    full: &TileBuffer<8, 8, 4>,
    unit: &TileBuffer<8, 8, 4>,
    x0: u16,
    y0: u16,
    name: &str,
) -> Result<(), String> {
    for ty in 0..8usize {
        for tx in 0..8usize {
            let (pa, pb) = (full.pixel_stats(tx, ty), unit.pixel_stats(tx, ty));
            let (x, y) = (x0 as usize + tx, y0 as usize + ty);
            if (pa.covered, pa.written) != (pb.covered, pb.written) {
                return Err(format!(
                    "pixel ({x}, {y}): covered/written full {}/{}, {name} {}/{}",
                    pa.covered, pa.written, pb.covered, pb.written
                ));
            }
        }
    }
    same_samples(full, unit, x0, y0, ("full", name))
}

/// The first sample whose depth or colour differs between tiles `a` and `b` (named
/// `names.0`, `names.1`), both rendered at screen tile (`x0`, `y0`).
pub fn same_samples(
    a: &TileBuffer<8, 8, 4>,
    b: &TileBuffer<8, 8, 4>,
    x0: u16,
    y0: u16,
    names: (&str, &str),
) -> Result<(), String> {
    for ty in 0..8usize {
        for tx in 0..8usize {
            let (x, y) = (x0 as usize + tx, y0 as usize + ty);
            for s in 0..4 {
                let (da, db) = (a.depth(tx, ty, s), b.depth(tx, ty, s));
                let (ca, cb) = (a.sample_color(tx, ty, s), b.sample_color(tx, ty, s));
                if da != db || ca != cb {
                    let hex = |d: Option<i32>| d.map(|d| format!("{d} ({d:#010x})"));
                    return Err(format!(
                        "pixel ({x}, {y}) sample {s}: {} depth {:?} color {ca:?}, \
                         {} depth {:?} color {cb:?}",
                        names.0,
                        hex(da),
                        names.1,
                        hex(db)
                    ));
                }
            }
        }
    }
    Ok(())
}

/// The whole-frame counters both units must share: covered, written and occluded samples.
pub fn same_counts(full: Stats, unit: Stats, name: &str) -> Result<(), String> {
    let key = |s: Stats| (s.samples_covered, s.samples_written, s.samples_occluded);
    if key(full) != key(unit) {
        return Err(format!(
            "covered/written/occluded: full {:?}, {name} {:?}",
            key(full),
            key(unit)
        ));
    }
    Ok(())
}
