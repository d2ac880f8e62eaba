//! `uvt bench-ste`: the STE table in the layout of Laine 2011 Table 1, columns bbox scan, uvt fixed,
//! uvt f64 and the oracle box, for the 'game' and 'dense' scenes in seven rows each.

use serde::Serialize;
use uvt_core::Laine2011;

use crate::frame::{run, Fixed, Reference, RunOpts};
use crate::pattern::Pattern;
use crate::scenes::{bench, Bench, Row};

/// One row of the table.
#[derive(Clone, Debug, Serialize)]
pub struct BenchRow {
    /// scene
    pub scene: Bench,
    /// row
    pub row: Row,
    /// triangles submitted
    pub triangles: usize,
    /// average covered area of a visible triangle, pixels (covered samples / spp / visible)
    pub avg_area_px: f64,
    /// STE of the bounding-box scan
    pub bbox: f64,
    /// STE of the core
    pub fixed: f64,
    /// STE of the f64 reference
    pub f64: f64,
    /// STE of the oracle boxes (from the core's coverage)
    pub oracle: f64,
    /// wall ms of the core's frame
    pub fixed_ms: f64,
    /// wall ms of the reference's frame
    pub f64_ms: f64,
    /// ops per setup / tile / sample test
    pub ops: [f64; 3],
}

/// Run the benchmark table.
pub fn run_table(quick: bool, scenes: &[Bench], rows: &[Row]) -> Vec<BenchRow> {
    let mut out = Vec::new();
    let total = scenes.len() * rows.len();
    for &kind in scenes {
        for &row in rows {
            // Progress as plain lines on stderr (readable in logs, not only on a terminal).
            eprintln!(
                "bench-ste: row {} of {total}: {kind:?} {}",
                out.len() + 1,
                row.label()
            );
            let s = bench(kind, row, quick);
            let pattern = Pattern::new(s.pattern, s.spp, s.seed);
            let core = s.core_tris().expect("built-in scene converts");
            let vp = s.core_viewport();
            let colors = s.colors();
            let o = RunOpts::for_scene(&s, &colors);
            let f = run(
                &Fixed::new(Laine2011, vp, &core, &pattern),
                &pattern,
                &RunOpts {
                    oracle: Some(&s.tris),
                    ..o
                },
            );
            let r = run(
                &Reference {
                    vp: s.viewport,
                    tris: &s.tris,
                    pattern: &pattern,
                },
                &pattern,
                &o,
            );
            let st = &f.stats;
            let visible: u64 = st.by_class.iter().sum();
            let per = |a: u64, b: u64| if b == 0 { 0.0 } else { a as f64 / b as f64 };
            out.push(BenchRow {
                scene: kind,
                row,
                triangles: s.tris.len(),
                avg_area_px: per(st.samples_covered, visible * s.spp as u64),
                bbox: st.ste_bbox(),
                fixed: st.ste(),
                f64: r.stats.ste(),
                oracle: st.ste_oracle(),
                fixed_ms: f.time.as_secs_f64() * 1e3,
                f64_ms: r.time.as_secs_f64() * 1e3,
                ops: [
                    per(st.ops_setup, st.triangles),
                    per(st.ops_bounds, st.tiles_visited),
                    per(st.ops_sample, st.samples_tested),
                ],
            });
        }
    }
    out
}

/// The table as Markdown, STE in percent (Laine's layout: scene rows, method columns).
pub fn table_md(rows: &[BenchRow]) -> String {
    let mut s = String::from("| Scene | Bbox scan | uvt fixed | uvt f64 | oracle | avg area px | fixed ms | f64 ms |\n|---|---|---|---|---|---|---|---|\n");
    for r in rows {
        let name = if r.row == Row::Static {
            match r.scene {
                Bench::Game => "GAME",
                Bench::Dense => "DENSE",
            }
            .to_string()
        } else {
            format!("  {}", r.row.label())
        };
        s += &format!(
            "| {name} | {:.2} | {:.2} | {:.2} | {:.2} | {:.2} | {:.0} | {:.0} |\n",
            100.0 * r.bbox,
            100.0 * r.fixed,
            100.0 * r.f64,
            100.0 * r.oracle,
            r.avg_area_px,
            r.fixed_ms,
            r.f64_ms
        );
    }
    s
}
