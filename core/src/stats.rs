//! Counters: what each stage did, so STE and operation counts are measured, not estimated.
//!
//! Operation counts are tallies placed by hand beside the arithmetic they count (one per add,
//! subtract, multiply, divide, compare, min or max on the executed path); they compare with
//! Laine 2011 §4.1 (~500 per setup, ~40 per tile, ~25 per sample test) in kind, not to the gate.

/// Arithmetic operations per stage.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Ops {
    /// triangle setup (including the bounds strategy's per-triangle preparation)
    pub setup: u64,
    /// per-tile bounds
    pub bounds: u64,
    /// sample tests
    pub sample: u64,
    /// per-sample predicates of a bounds strategy, run on every sample inside its tile's box
    /// before the sample test (0 for box-only strategies)
    pub predicate: u64,
}

impl Ops {
    /// Element-wise sum.
    pub fn add(&mut self, o: &Ops) {
        self.setup += o.setup;
        self.bounds += o.bounds;
        self.sample += o.sample;
        self.predicate += o.predicate;
    }
}

/// Frame counters.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// triangles submitted to setup
    pub triangles: u64,
    /// culled: outside the frustum or viewport for the whole shutter and lens
    pub culled_outside: u64,
    /// culled: degenerate at every (t, u, v)
    pub culled_degenerate: u64,
    /// visible triangles by class: static, motion, defocus, motion+defocus
    pub by_class: [u64; 4],
    /// bounds tiles whose bounds were computed
    pub tiles_visited: u64,
    /// bounds tiles whose bounds were empty (skipped without a sample test)
    pub tiles_skipped: u64,
    /// samples inside their tile's intervals (= sample tests run)
    pub samples_tested: u64,
    /// samples the sample test covered
    pub samples_covered: u64,
    /// operation counts
    pub ops: Ops,
}

impl Stats {
    /// Sample test efficiency covered / tested in parts per million (0 when nothing was tested).
    pub fn ste_ppm(&self) -> u64 {
        self.samples_covered
            .saturating_mul(1_000_000)
            .checked_div(self.samples_tested)
            .unwrap_or(0)
    }

    /// Element-wise sum.
    pub fn add(&mut self, o: &Stats) {
        self.triangles += o.triangles;
        self.culled_outside += o.culled_outside;
        self.culled_degenerate += o.culled_degenerate;
        for (a, b) in self.by_class.iter_mut().zip(o.by_class.iter()) {
            *a += b;
        }
        self.tiles_visited += o.tiles_visited;
        self.tiles_skipped += o.tiles_skipped;
        self.samples_tested += o.samples_tested;
        self.samples_covered += o.samples_covered;
        self.ops.add(&o.ops);
    }
}
