//! What a frame run measures: the counters of one frame ([`FrameStats`]) and the rendered
//! frame ([`Frame`]: counters, image, heat map, wall time).

use std::time::Duration;

use uvt_core::{Ops, Rgb888, Stats};

/// Counters of one frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct FrameStats {
    /// triangles submitted
    pub triangles: u64,
    /// culled outside
    pub culled_outside: u64,
    /// culled degenerate
    pub culled_degenerate: u64,
    /// visible by class: static, motion, defocus, motion+defocus
    pub by_class: [u64; 4],
    /// bounds tiles computed
    pub tiles_visited: u64,
    /// of which empty
    pub tiles_skipped: u64,
    /// kept bounds tiles Zmax culling skipped (0 without it, [`RunOpts::zmax`](super::opts::RunOpts::zmax))
    pub tiles_zculled: u64,
    /// samples of the kept bounds tiles (each put through the tile's box and predicate)
    pub samples_admitted: u64,
    /// samples tested (inside the tile intervals)
    pub samples_tested: u64,
    /// samples covered
    pub samples_covered: u64,
    /// covered samples that passed the depth test and were stored (`uvt_core::Stats::samples_written`)
    pub samples_written: u64,
    /// samples the bounding-box scan tests: all samples of every footprint pixel
    pub footprint_samples: u64,
    /// samples inside the per-tile oracle boxes (counted only when the run has the oracle,
    /// [`RunOpts::oracle`](super::opts::RunOpts::oracle); 0 otherwise, so that runs without it do
    /// not pay its bookkeeping)
    pub oracle_tested: u64,
    /// operation counts (fixed pipeline only)
    pub ops_setup: u64,
    /// per-tile bounds ops
    pub ops_bounds: u64,
    /// sample-test ops
    pub ops_sample: u64,
    /// per-sample predicate ops of the bounds strategy
    pub ops_predicate: u64,
    /// per-row span ops of the bounds strategy
    pub ops_rows: u64,
    /// Zmax ops: depth floors, tile-maximum reads and comparisons (`uvt_core::Ops::zmax`)
    pub ops_zmax: u64,
}

impl FrameStats {
    pub(super) fn add(&mut self, o: &FrameStats) {
        let a = [
            &mut self.triangles,
            &mut self.culled_outside,
            &mut self.culled_degenerate,
            &mut self.tiles_visited,
            &mut self.tiles_skipped,
            &mut self.tiles_zculled,
            &mut self.samples_admitted,
            &mut self.samples_tested,
            &mut self.samples_covered,
            &mut self.samples_written,
            &mut self.footprint_samples,
            &mut self.oracle_tested,
            &mut self.ops_setup,
            &mut self.ops_bounds,
            &mut self.ops_sample,
            &mut self.ops_predicate,
            &mut self.ops_rows,
            &mut self.ops_zmax,
        ];
        let b = [
            o.triangles,
            o.culled_outside,
            o.culled_degenerate,
            o.tiles_visited,
            o.tiles_skipped,
            o.tiles_zculled,
            o.samples_admitted,
            o.samples_tested,
            o.samples_covered,
            o.samples_written,
            o.footprint_samples,
            o.oracle_tested,
            o.ops_setup,
            o.ops_bounds,
            o.ops_sample,
            o.ops_predicate,
            o.ops_rows,
            o.ops_zmax,
        ];
        for (x, y) in a.into_iter().zip(b) {
            *x += y;
        }
        for (x, y) in self.by_class.iter_mut().zip(o.by_class) {
            *x += y;
        }
    }
    /// The core's counters of a frame or part of it ([`uvt_core::Stats`]); the host's own
    /// (`samples_admitted`, `footprint_samples`, `oracle_tested`) are 0.
    pub fn from_core(s: &Stats) -> FrameStats {
        let mut f = FrameStats {
            triangles: s.triangles,
            culled_outside: s.culled_outside,
            culled_degenerate: s.culled_degenerate,
            by_class: s.by_class,
            tiles_visited: s.tiles_visited,
            tiles_skipped: s.tiles_skipped,
            tiles_zculled: s.tiles_zculled,
            samples_tested: s.samples_tested,
            samples_covered: s.samples_covered,
            samples_written: s.samples_written,
            ..Default::default()
        };
        f.add_ops(&s.ops);
        f
    }
    pub(super) fn add_ops(&mut self, o: &Ops) {
        self.ops_setup += o.setup;
        self.ops_bounds += o.bounds;
        self.ops_sample += o.sample;
        self.ops_predicate += o.predicate;
        self.ops_rows += o.rows;
        self.ops_zmax += o.zmax;
    }
    /// STE of the pipeline's bounds (covered / tested), in [0, 1].
    pub fn ste(&self) -> f64 {
        ratio(self.samples_covered, self.samples_tested)
    }
    /// STE of the bounding-box scan.
    pub fn ste_bbox(&self) -> f64 {
        ratio(self.samples_covered, self.footprint_samples)
    }
    /// STE of the oracle boxes.
    pub fn ste_oracle(&self) -> f64 {
        ratio(self.samples_covered, self.oracle_tested)
    }
}

fn ratio(a: u64, b: u64) -> f64 {
    if b == 0 {
        0.0
    } else {
        a as f64 / b as f64
    }
}

/// A rendered frame.
pub struct Frame {
    /// counters
    pub stats: FrameStats,
    /// resolved RGB per pixel, row-major (empty if not requested)
    pub image: Vec<[u8; 3]>,
    /// every sample's colour, row-major by pixel, then by sample (the core's frames with the
    /// image kept; empty otherwise)
    pub samples: Vec<Rgb888>,
    /// sample tests per pixel, row-major
    pub heat: Vec<u32>,
    /// wall time
    pub time: Duration,
}
