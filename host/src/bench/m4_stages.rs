//! The Cortex-M4F instructions per stage of every bounds strategy on the bench rows' own
//! triangles at both bench sizes ([`Size`]), as `bash demo/m4_report.sh --strategies` writes them
//! (`host/report/m4_strategies.json`; the harness is `demo/examples/m4_stages`), and the
//! per-call figures read from them: instructions per setup (per submitted triangle), per
//! visited bounds tile (row spans and tile bounds), per sample put through the box and
//! predicate, and per sample test.

use std::collections::BTreeMap;
use std::path::Path;

use anyhow::Context;
use serde::Deserialize;

/// The committed file (relative to the repository root).
pub const DEFAULT_PATH: &str = "host/report/m4_strategies.json";

/// The committed file's text, built in: every command reads the same figures wherever it runs.
const COMMITTED: &str = include_str!("../../report/m4_strategies.json");

/// The occlusion rows' file (`bash demo/m4_report.sh --zmax`), relative to the repository root.
pub const ZMAX_PATH: &str = "host/report/m4_zmax.json";

/// [`ZMAX_PATH`]'s text, built in.
const COMMITTED_ZMAX: &str = include_str!("../../report/m4_zmax.json");

/// `text` (the built-in copy of `path`) parsed once into `cell`; the error names the file.
fn parse_once(
    cell: &'static std::sync::OnceLock<Result<M4Stages, String>>,
    text: &str,
    path: &str,
) -> anyhow::Result<&'static M4Stages> {
    cell.get_or_init(|| serde_json::from_str(text).map_err(|e| e.to_string()))
        .as_ref()
        .map_err(|e| anyhow::anyhow!("{path} (built in): {e}"))
}

/// The committed figures ([`DEFAULT_PATH`], built in); the error says why they do not parse.
pub fn committed() -> anyhow::Result<&'static M4Stages> {
    static PARSED: std::sync::OnceLock<Result<M4Stages, String>> = std::sync::OnceLock::new();
    parse_once(&PARSED, COMMITTED, DEFAULT_PATH)
}

/// The occlusion rows' committed figures ([`ZMAX_PATH`], built in).
pub fn committed_zmax() -> anyhow::Result<&'static M4Stages> {
    static PARSED: std::sync::OnceLock<Result<M4Stages, String>> = std::sync::OnceLock::new();
    parse_once(&PARSED, COMMITTED_ZMAX, ZMAX_PATH)
}

/// `a / b`, 0 when `b` is 0.
pub(super) fn per(a: u64, b: u64) -> f64 {
    if b == 0 {
        0.0
    } else {
        a as f64 / b as f64
    }
}

/// One strategy on one class of one row.
#[derive(Clone, Debug, Deserialize)]
pub struct StageLine {
    /// registry name
    pub strategy: String,
    /// triangle class name
    pub class: String,
    /// triangles set up
    pub triangles: u64,
    /// visible ones
    pub visible: u64,
    /// bounds tiles visited
    pub tiles: u64,
    /// samples of kept tiles put through the box and predicate
    pub admits: u64,
    /// samples tested
    pub tested: u64,
    /// samples covered
    pub covered: u64,
    /// core ops: setup, bounds, rows, predicate, sample
    pub ops: [u64; 5],
    /// instructions: setup, tile walk, predicate, sample test
    pub insn: [u64; 4],
}

/// Zmax culling's own calls on one row (`demo/src/zmax_cost.rs`).
#[derive(Clone, Copy, Debug, Deserialize)]
pub struct ZmaxLine {
    /// depth floors timed (one per visible triangle)
    pub floors: u64,
    /// tile checks timed
    pub checks: u64,
    /// register refreshes timed
    pub refreshes: u64,
    /// bounds tile of the checks
    pub bounds_tile: u32,
    /// samples per pixel of the refreshes
    pub spp: u32,
    /// instructions: floors, checks, refreshes
    pub insn: [u64; 3],
}

impl ZmaxLine {
    /// Instructions per call of each of the three calls.
    pub fn per_call(&self) -> ZmaxPerCall {
        ZmaxPerCall {
            floor: per(self.insn[0], self.floors),
            check: per(self.insn[1], self.checks),
            refresh: per(self.insn[2], self.refreshes),
        }
    }
}

/// Cortex-M4F instructions per call of Zmax culling's three calls.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ZmaxPerCall {
    /// per visible triangle (the depth floor)
    pub floor: f64,
    /// per kept bounds tile (the tile's maximum from its registers and the comparison)
    pub check: f64,
    /// per written sample (the pixel's register refresh)
    pub refresh: f64,
}

impl ZmaxPerCall {
    /// Zmax's instructions in a frame with `visible` triangles, `checks` kept bounds tiles
    /// checked and `written` samples stored.
    pub fn total(&self, visible: u64, checks: u64, written: u64) -> f64 {
        self.floor * visible as f64 + self.check * checks as f64 + self.refresh * written as f64
    }
}

/// The bench size a row was measured at. The instructions per call depend on it (a triangle's
/// tiles, row spans and samples per tile change with the resolution, and so do `auto`'s picks),
/// so a row's figures are read at the size of the run that uses them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Size {
    /// the quick size (`--quick`: a quarter of the resolution and tessellation)
    Quick,
    /// the full size
    Full,
}

impl Size {
    /// The size of a run with `quick` set or not.
    pub fn of(quick: bool) -> Size {
        if quick {
            Size::Quick
        } else {
            Size::Full
        }
    }
    /// Whether it is the quick size.
    pub fn is_quick(self) -> bool {
        self == Size::Quick
    }
    /// `quick` or `full`, as in the file.
    pub fn name(self) -> &'static str {
        match self {
            Size::Quick => "quick",
            Size::Full => "full",
        }
    }
}

/// One bench row's lines.
#[derive(Clone, Debug, Deserialize)]
pub struct StageRow {
    /// game or dense
    pub scene: String,
    /// row name (`Blur::name`)
    pub row: String,
    /// the bench size of the row's triangles
    pub size: Size,
    /// every `every`-th triangle of the row at that size
    pub every: u32,
    /// per strategy and class
    pub stages: Vec<StageLine>,
    /// Zmax culling's calls (files written before they were measured have none)
    #[serde(default)]
    pub zmax: Option<ZmaxLine>,
}

/// The file.
#[derive(Clone, Debug, Deserialize)]
pub struct M4Stages {
    /// how it was measured
    pub target: String,
    /// the rows
    pub rows: Vec<StageRow>,
}

impl M4Stages {
    /// Read `path`; the error names it.
    pub fn load(path: &Path) -> anyhow::Result<M4Stages> {
        let text =
            std::fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))?;
        serde_json::from_str(&text).with_context(|| format!("parsing {}", path.display()))
    }

    /// The lines of row (`scene`, `row`) measured at `size`.
    pub fn row(&self, scene: &str, row: &str, size: Size) -> Option<&StageRow> {
        self.rows
            .iter()
            .find(|r| r.scene == scene && r.row == row && r.size == size)
    }
}

impl M4Stages {
    /// Per-call figures of `strategy` pooled over every class of the quick rows (for a scene
    /// that is not a bench row: `uvt fit`'s search and `uvt converge`, whose scenes are of the
    /// quick rows' kind of size).
    pub fn pooled(&self, strategy: &str) -> Option<PerCall> {
        let mut s = StageSum::default();
        for l in self
            .rows
            .iter()
            .filter(|r| r.size.is_quick())
            .flat_map(|r| &r.stages)
        {
            if l.strategy == strategy {
                s.add(l);
            }
        }
        (s.triangles > 0).then(|| s.per_call())
    }
}

impl M4Stages {
    /// Zmax's per-call figures pooled over every row that has them; `None` if none has.
    pub fn zmax_pooled(&self) -> Option<ZmaxPerCall> {
        let mut lines = self.rows.iter().filter_map(|r| r.zmax);
        let first = lines.next()?;
        let sum = lines.fold(first, |mut a, l| {
            a.floors += l.floors;
            a.checks += l.checks;
            a.refreshes += l.refreshes;
            for (x, y) in a.insn.iter_mut().zip(l.insn) {
                *x += y;
            }
            a
        });
        Some(sum.per_call())
    }
}

impl StageRow {
    /// Zmax's per-call figures of this row, if it has them.
    pub fn zmax_per_call(&self) -> Option<ZmaxPerCall> {
        self.zmax.map(|z| z.per_call())
    }

    /// Per-call figures of every (strategy, class) on this row.
    pub fn per_class(&self) -> BTreeMap<(String, String), PerCall> {
        let mut m: BTreeMap<(String, String), StageSum> = BTreeMap::new();
        for l in &self.stages {
            m.entry((l.strategy.clone(), l.class.clone()))
                .or_default()
                .add(l);
        }
        m.into_iter().map(|(k, s)| (k, s.per_call())).collect()
    }

    /// Per-call figures of `strategy` on this row, pooled over its classes.
    pub fn per_call(&self, strategy: &str) -> Option<PerCall> {
        let mut s = StageSum::default();
        for l in self.stages.iter().filter(|l| l.strategy == strategy) {
            s.add(l);
        }
        (s.triangles > 0).then(|| s.per_call())
    }
}

/// Sums of counts and instructions.
#[derive(Clone, Copy, Debug, Default)]
struct StageSum {
    triangles: u64,
    tiles: u64,
    admits: u64,
    tested: u64,
    insn: [u64; 4],
}

impl StageSum {
    fn add(&mut self, l: &StageLine) {
        self.triangles += l.triangles;
        self.tiles += l.tiles;
        self.admits += l.admits;
        self.tested += l.tested;
        for (a, b) in self.insn.iter_mut().zip(l.insn) {
            *a += b;
        }
    }
    fn per_call(&self) -> PerCall {
        PerCall {
            setup: per(self.insn[0], self.triangles),
            tile: per(self.insn[1], self.tiles),
            admit: per(self.insn[2], self.admits),
            test: per(self.insn[3], self.tested),
        }
    }
}

/// Cortex-M4F instructions per call of each stage.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PerCall {
    /// per submitted triangle (setup and the strategy's preparation)
    pub setup: f64,
    /// per visited bounds tile (row spans and tile bounds)
    pub tile: f64,
    /// per sample of a kept tile (sample loop, box and predicate)
    pub admit: f64,
    /// per sample test
    pub test: f64,
}

impl PerCall {
    /// The instructions of a frame with these counts.
    pub fn total(&self, triangles: u64, tiles: u64, admits: u64, tested: u64) -> f64 {
        self.setup * triangles as f64
            + self.tile * tiles as f64
            + self.admit * admits as f64
            + self.test * tested as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bench::strategy::strategies;

    /// The occlusion rows' file holds every row `uvt bench-zmax` reads at both sizes, each with
    /// every bench strategy and Zmax's calls, every per-call figure measured (non-zero).
    #[test]
    fn occlusion_rows_have_every_figure_bench_zmax_reads() {
        let z = committed_zmax().expect("m4_zmax.json parses");
        for (row, size) in ["static", "motion", "defocus", "both"]
            .into_iter()
            .flat_map(|r| [(r, Size::Quick), (r, Size::Full)])
        {
            let r = z
                .row("occluded", row, size)
                .unwrap_or_else(|| panic!("row occluded {row} ({})", size.name()));
            let zc = r
                .zmax_per_call()
                .unwrap_or_else(|| panic!("zmax line, occluded {row}"));
            assert!(
                zc.floor > 0.0 && zc.check > 0.0 && zc.refresh > 0.0,
                "occluded {row}: {zc:?}"
            );
            let line = r.zmax.expect("zmax line");
            assert_eq!((line.bounds_tile, line.spp), (1, 16), "occluded {row}");
            for name in strategies() {
                let pc = r
                    .per_call(name)
                    .unwrap_or_else(|| panic!("{name} on occluded {row}"));
                assert!(
                    pc.setup > 0.0 && pc.tile > 0.0 && pc.test > 0.0,
                    "{name} {row}: {pc:?}"
                );
            }
        }
        assert!(z.zmax_pooled().is_some());
    }

    /// The strategies' file holds every bench row at both sizes with every bench strategy, so
    /// `uvt bench-ste` reads each row's own figures at the size it runs.
    #[test]
    fn every_bench_row_is_measured_at_both_sizes() {
        use crate::scene::builtin::{Bench, Blur};
        let f = committed().expect("m4_strategies.json parses");
        for kind in [Bench::Game, Bench::Dense] {
            for row in Blur::ALL {
                for size in [Size::Quick, Size::Full] {
                    let r = f.row(kind.name(), &row.name(), size).unwrap_or_else(|| {
                        panic!("{} {} ({})", kind.name(), row.name(), size.name())
                    });
                    for name in strategies() {
                        assert!(
                            r.per_call(name).is_some_and(|pc| pc.setup > 0.0),
                            "{name} on {} {} ({})",
                            kind.name(),
                            row.name(),
                            size.name()
                        );
                    }
                }
            }
        }
    }

    /// Every stage of every line of both files costs at least one Cortex-M4F instruction per core
    /// op it counts (setup; tile bounds and row spans; predicate; sample test). The stages after
    /// setup are differences of walks (`uvt_demo::workload::stage_one`): a walk that did more
    /// than its stage's work in one pass shows here. The files made before the walks were
    /// mended had 16 lines under it (the sample test at 0 to 0.6 instructions per op on the
    /// full-size dense rows).
    #[test]
    fn every_stage_costs_at_least_an_instruction_per_op() {
        for f in [committed(), committed_zmax()] {
            let f = f.expect("stage file parses");
            for r in &f.rows {
                for l in &r.stages {
                    let (o, i) = (l.ops, l.insn);
                    let stages = [
                        ("setup", i[0], o[0]),
                        ("tile", i[1], o[1] + o[2]),
                        ("predicate", i[2], o[3]),
                        ("sample test", i[3], o[4]),
                    ];
                    for (stage, insn, ops) in stages {
                        assert!(
                            insn >= ops,
                            "{} {} ({}) {} {}: {stage} {insn} ({insn:#x}) instructions < {ops} ({ops:#x}) ops",
                            r.scene,
                            r.row,
                            r.size.name(),
                            l.strategy,
                            l.class
                        );
                    }
                }
            }
        }
    }
}
