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
    /// per-row span steps of a bounds strategy ([`crate::BoundsStrategy::row_span`]; 0 for
    /// strategies without one)
    pub rows: u64,
    /// Zmax culling ([`crate::raster::zmax`]): each triangle's depth floor, and per kept bounds
    /// tile the reads of its stored maximum and the comparison (0 without Zmax)
    pub zmax: u64,
}

impl Ops {
    /// Element-wise sum (saturating: a counter stops at `u64::MAX`).
    pub fn add(&mut self, o: &Ops) {
        self.setup = self.setup.saturating_add(o.setup);
        self.bounds = self.bounds.saturating_add(o.bounds);
        self.sample = self.sample.saturating_add(o.sample);
        self.predicate = self.predicate.saturating_add(o.predicate);
        self.rows = self.rows.saturating_add(o.rows);
        self.zmax = self.zmax.saturating_add(o.zmax);
    }
    /// Count `n` row-span operations (saturating).
    #[inline]
    pub fn add_rows(&mut self, n: u64) {
        self.rows = self.rows.saturating_add(n);
    }
    /// Count `n` setup operations (saturating).
    #[inline]
    pub fn add_setup(&mut self, n: u64) {
        self.setup = self.setup.saturating_add(n);
    }
    /// Count `n` bounds operations (saturating).
    #[inline]
    pub fn add_bounds(&mut self, n: u64) {
        self.bounds = self.bounds.saturating_add(n);
    }
    /// Count `n` sample-test operations (saturating).
    #[inline]
    pub fn add_sample(&mut self, n: u64) {
        self.sample = self.sample.saturating_add(n);
    }
    /// Count `n` Zmax operations (saturating).
    #[inline]
    pub fn add_zmax(&mut self, n: u64) {
        self.zmax = self.zmax.saturating_add(n);
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
    /// bounds tiles of the footprints walked: those whose bounds were computed and those its
    /// row's span skipped ([`crate::BoundsStrategy::row_span`])
    pub tiles_visited: u64,
    /// bounds tiles whose bounds were empty or that a row span skipped (no sample test)
    pub tiles_skipped: u64,
    /// kept bounds tiles skipped by Zmax culling (the triangle is hidden there; 0 without it)
    pub tiles_zculled: u64,
    /// samples inside their tile's intervals (= sample tests run)
    pub samples_tested: u64,
    /// samples the sample test covered
    pub samples_covered: u64,
    /// covered samples written to the tile buffer (the slot was empty or farther)
    pub samples_written: u64,
    /// covered samples that failed the depth test against a value an earlier triangle wrote;
    /// `samples_covered = samples_written + samples_occluded` (the empty value is never a depth)
    pub samples_occluded: u64,
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

    /// Element-wise sum (saturating).
    pub fn add(&mut self, o: &Stats) {
        let sum = |a: &mut u64, b: u64| *a = a.saturating_add(b);
        sum(&mut self.triangles, o.triangles);
        sum(&mut self.culled_outside, o.culled_outside);
        sum(&mut self.culled_degenerate, o.culled_degenerate);
        for (a, b) in self.by_class.iter_mut().zip(o.by_class.iter()) {
            sum(a, *b);
        }
        sum(&mut self.tiles_visited, o.tiles_visited);
        sum(&mut self.tiles_skipped, o.tiles_skipped);
        sum(&mut self.tiles_zculled, o.tiles_zculled);
        sum(&mut self.samples_tested, o.samples_tested);
        sum(&mut self.samples_covered, o.samples_covered);
        sum(&mut self.samples_written, o.samples_written);
        sum(&mut self.samples_occluded, o.samples_occluded);
        self.ops.add(&o.ops);
    }

    /// Increment one counter by 1 (saturating).
    #[inline]
    pub(crate) fn inc(c: &mut u64) {
        *c = c.saturating_add(1);
    }
}
