//! The search behind the axis-aligned limit: the box of a covered set in a 5D integer domain,
//! estimated from inside.
//!
//! The set is given only by a membership predicate (`covered`) over the integer points of a
//! domain box; the search keeps the bounding box of the covered points it has found, so the
//! estimate is always *inside* the true box of the set (every face it reports is attained by a
//! covered point). It finds points in two ways:
//! - **dense points**: a 5D Owen-scrambled Sobol sequence over the domain (nested: a second call
//!   continues the same sequence);
//! - **face search**: each of the 6 faces of dimensions 2..5 (the box's u, v, t) is pushed outward
//!   from the covered point on it by a (1+1) evolution strategy on the integer grid — a proposal
//!   moves the face's coordinate outward (or keeps it) and a random subset of the other four
//!   coordinates by a rounded Gaussian step, clamped to the domain; it is accepted if covered;
//!   each coordinate's step size doubles on success and shrinks by 0.84 on failure (the 1/5
//!   success rule); a successful step is repeated with doubling length while it stays covered
//!   (a pattern move along the ridge), and every second proposal steps along the evolution path
//!   (the decaying sum of successful displacements), so the walk follows thin tubes and wedges
//!   of the set to their tips — and ends with a bisection along the face's axis. Extremes of coverage sets of moving, defocused triangles
//!   sit at such tips (a vertex entering a tile corner at an interior lens position), which a
//!   uniform density reaches only slowly.
//!
//! A set that does not depend on some dimensions (the oracle's (u, v, t) search of a motion-only
//! or defocus-only triangle, or x, y collapsed to one point) marks only the others active
//! ([`BoxSearch::with_active`]): dense points and random moves then vary only those.
//!
//! Deterministic: the Sobol seed and the step generator's seed are arguments.

use rand::{Rng, SeedableRng};
use rand_pcg::Pcg64;

/// An integer point: in the oracle, x and y in 1/256 px (absolute), then u, v, t raw.
pub type P5 = [i32; 5];

/// A box: per dimension `[lo, hi]`.
pub type Bounds5 = [[i32; 2]; 5];

/// The effort of one estimate: dense points and face-search proposals.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct Effort {
    /// dense points (per pixel in the oracle; a count for [`BoxSearch::dense`])
    pub density: u32,
    /// face-search proposals per face (6 faces)
    pub steps: u32,
}

/// The inner estimate of a covered set's box, with the covered point on each face.
#[derive(Clone, Debug)]
pub struct BoxSearch {
    lo: P5,
    hi: P5,
    sobol_seed: u32,
    rng: Pcg64,
    /// box of the covered points found (per dimension `[lo, hi]`) and the covered point on
    /// each face (dimension, side)
    found: Option<(Bounds5, [[P5; 2]; 5])>,
    /// dense points drawn so far (the next index of the Sobol sequence)
    drawn: u32,
    /// dimensions the dense points vary (the others stay at `lo`)
    active: [bool; 5],
}

impl BoxSearch {
    /// An empty search over the integer box `[lo, hi]` (`lo ≤ hi` in every dimension).
    pub fn new(lo: P5, hi: P5, seed: u64) -> BoxSearch {
        BoxSearch {
            lo,
            hi,
            // The Sobol scramble seed: the low 32 bits of `seed`.
            sobol_seed: seed as u32,
            rng: Pcg64::seed_from_u64(seed),
            found: None,
            drawn: 0,
            active: [true; 5],
        }
    }

    /// The same search with dense points varying only the `active` dimensions (the others stay
    /// at their `lo`; Sobol dimensions are assigned in order to the active ones, so a 1D or 2D
    /// set gets the sequence's best-stratified first dimensions). For a set that does not depend
    /// on a dimension; the face search still pushes every face of dimensions 2..5.
    pub fn with_active(mut self, active: [bool; 5]) -> BoxSearch {
        self.active = active;
        self
    }

    /// The covered point found on each face (dimension, side: 0 low, 1 high).
    pub fn faces(&self) -> Option<[[P5; 2]; 5]> {
        self.found.map(|f| f.1)
    }

    /// The box of the covered points found so far (`None`: none found).
    pub fn bounds(&self) -> Option<Bounds5> {
        self.found.map(|f| f.0)
    }

    /// Add covered point `p` to the box.
    pub fn grow(&mut self, p: P5) {
        match &mut self.found {
            None => self.found = Some((p.map(|x| [x, x]), [[p; 2]; 5])),
            Some((b, ext)) => {
                for (d, x) in p.into_iter().enumerate() {
                    if x < b[d][0] {
                        b[d][0] = x;
                        ext[d][0] = p;
                    }
                    if x > b[d][1] {
                        b[d][1] = x;
                        ext[d][1] = p;
                    }
                }
            }
        }
    }

    /// Draw dense points until `n` have been drawn in total (continuing the sequence).
    pub fn dense(&mut self, n: u32, covered: &mut impl FnMut(&P5) -> bool) {
        while self.drawn < n {
            let i = self.drawn;
            self.drawn += 1;
            let mut p = self.lo;
            let mut sd = 0u32;
            for (d, x) in p.iter_mut().enumerate() {
                if !self.active[d] {
                    continue;
                }
                let span = (self.hi[d] - self.lo[d]) as f64 + 1.0;
                let r = sobol_burley::sample(i, sd, self.sobol_seed) as f64;
                sd += 1;
                *x = (self.lo[d] + (r * span).floor() as i32).min(self.hi[d]);
            }
            if covered(&p) {
                self.grow(p);
            }
        }
    }

    /// Push each face of dimensions 2..5 outward with `steps` proposals, in two passes (a point
    /// found for one face may start another face further out).
    pub fn push_faces(&mut self, steps: u32, covered: &mut impl FnMut(&P5) -> bool) {
        if self.found.is_none() {
            return;
        }
        for pass in 0..2 {
            let n = if pass == 0 {
                steps / 2
            } else {
                steps - steps / 2
            };
            for k in 2..5 {
                for side in 0..2 {
                    self.push_face(k, side, n, covered);
                }
            }
        }
    }

    fn push_face(
        &mut self,
        k: usize,
        side: usize,
        steps: u32,
        covered: &mut impl FnMut(&P5) -> bool,
    ) {
        let (end, dir) = if side == 0 {
            (self.lo[k], -1)
        } else {
            (self.hi[k], 1)
        };
        let Some((_, ext)) = self.found else {
            return;
        };
        let mut p = ext[k][side];
        let (lo, hi, active) = (self.lo, self.hi, self.active);
        let range = |d: usize| ((hi[d] - lo[d]) as f64).max(1.0);
        let mut sigma: [f64; 5] = core::array::from_fn(|d| range(d) / 4.0);
        // The evolution path: a decaying sum of successful displacements (the direction of
        // the ridge the walk follows) and the step scale along it.
        let (mut path, mut along) = ([0.0f64; 5], 1.0f64);
        for it in 0..steps {
            if p[k] == end {
                return;
            }
            let use_path = it % 2 == 1 && path.iter().any(|x| x.abs() >= 1.0);
            let mut q = p;
            let mut moved = [false; 5];
            if use_path {
                // Along the path (a random length), with a little noise in every coordinate.
                let g = along * self.gauss().abs();
                for j in (0..5).filter(|&j| j == k || active[j]) {
                    let n = 0.1 * sigma[j] * self.gauss();
                    q[j] = (p[j] as f64 + (g * path[j] + n).round())
                        .clamp(lo[j] as f64, hi[j] as f64) as i32;
                }
            } else {
                // The face coordinate moves outward (or stays); each other one with
                // probability 1/2.
                moved[k] = true;
                let g = self.gauss().abs();
                q[k] = (p[k] as f64 + dir as f64 * (sigma[k] * g).round())
                    .clamp(lo[k] as f64, hi[k] as f64) as i32;
                for j in (0..5).filter(|&j| j != k && active[j]) {
                    if self.rng.gen::<bool>() {
                        moved[j] = true;
                        let g = self.gauss();
                        q[j] = (p[j] as f64 + (sigma[j] * g).round())
                            .clamp(lo[j] as f64, hi[j] as f64)
                            as i32;
                    }
                }
            }
            let ok = q != p && dir * (q[k] - p[k]) >= 0 && covered(&q);
            if ok {
                self.grow(q);
                // Pattern move: repeat the successful step, doubling it, while covered and not
                // inward (a straight ridge — a vertex's track — is followed at once).
                let d: P5 = core::array::from_fn(|j| q[j] - p[j]);
                let start = p;
                p = q;
                for m in 0..12 {
                    let r: P5 = core::array::from_fn(|j| {
                        (p[j].saturating_add(d[j].saturating_mul(1 << m))).clamp(lo[j], hi[j])
                    });
                    if r == p || dir * (r[k] - p[k]) < 0 || !covered(&r) {
                        break;
                    }
                    self.grow(r);
                    p = r;
                }
                for j in 0..5 {
                    path[j] = 0.5 * path[j] + (p[j] - start[j]) as f64;
                }
            }
            if use_path {
                along = if ok { along * 2.0 } else { along * 0.84 }.clamp(1.0 / 64.0, 64.0);
            }
            for j in (0..5).filter(|&j| moved[j]) {
                sigma[j] = if ok {
                    (sigma[j] * 2.0).min(range(j))
                } else {
                    (sigma[j] * 0.84).max(0.5)
                };
            }
        }
        self.bisect(p, k, end, 1, covered);
    }

    /// Bisect along axis `k` from covered `p` toward `target` until the covered and uncovered
    /// ends are at most `tol` apart; every covered point found is added to the box, and the
    /// farthest one is returned (`p` itself if none beyond it is found). It finds *a* boundary
    /// of the covered set on that line (the set need not be an interval there), so the result
    /// is covered but not necessarily the farthest covered point of the line.
    fn bisect(
        &mut self,
        p: P5,
        k: usize,
        target: i32,
        tol: i32,
        covered: &mut impl FnMut(&P5) -> bool,
    ) -> P5 {
        let mut far = p;
        far[k] = target;
        if far == p {
            return p;
        }
        if covered(&far) {
            self.grow(far);
            return far;
        }
        let (mut inside, mut out) = (p[k], target);
        // |out − inside| ≤ 2^17 + 1 (raw u, v, t) or 2^25 (x, y in 1/256 px): no overflow.
        while (out - inside).abs() > tol.max(1) {
            let mid = inside + (out - inside) / 2;
            let mut q = p;
            q[k] = mid;
            if covered(&q) {
                self.grow(q);
                inside = mid;
            } else {
                out = mid;
            }
        }
        let mut q = p;
        q[k] = inside;
        q
    }

    /// Test the points `pts` (clamped into the domain; inactive dimensions set to their `lo`)
    /// and add the covered ones to the box: seeds from outside knowledge of the set (the
    /// oracle's centre line of the tile's coverage), which only choose where to look.
    pub fn seed(
        &mut self,
        pts: impl IntoIterator<Item = P5>,
        covered: &mut impl FnMut(&P5) -> bool,
    ) {
        for p in pts {
            let q: P5 = core::array::from_fn(|d| {
                if self.active[d] {
                    p[d].clamp(self.lo[d], self.hi[d])
                } else {
                    self.lo[d]
                }
            });
            if covered(&q) {
                self.grow(q);
            }
        }
    }

    /// Push each face of dimensions 2..5 by line searches from its covered point: for every
    /// other active dimension `j` and each end of the domain in `j`, bisect along `j` toward
    /// that end (to 1/256 of the domain), then along the face's axis toward the domain's end
    /// (to the grid step); the farthest point reached becomes the face's point. The extremes of
    /// a thin slanted tube (a small triangle moving while defocused) lie where the tube leaves
    /// the domain through another dimension's end, a wedge tip that these two moves reach
    /// directly and a random walk only slowly.
    pub fn push_lines(&mut self, covered: &mut impl FnMut(&P5) -> bool) {
        for k in 2..5 {
            for side in 0..2 {
                self.push_line(k, side, covered);
            }
        }
    }

    fn push_line(&mut self, k: usize, side: usize, covered: &mut impl FnMut(&P5) -> bool) {
        let Some((_, ext)) = self.found else {
            return;
        };
        let (end, dir) = if side == 0 {
            (self.lo[k], -1)
        } else {
            (self.hi[k], 1)
        };
        let mut p = ext[k][side];
        let active = self.active;
        let tol_k = (self.hi[k] - self.lo[k]) / 4096;
        for j in (0..5).filter(|&j| j != k && active[j]) {
            for target in [self.lo[j], self.hi[j]] {
                if p[k] == end {
                    return;
                }
                let tol = (self.hi[j] - self.lo[j]) / 256;
                let q = self.bisect(p, j, target, tol, covered);
                if q == p {
                    continue;
                }
                let r = self.bisect(q, k, end, tol_k, covered);
                if dir * (r[k] - p[k]) > 0 {
                    p = r;
                }
            }
        }
    }

    /// A standard normal deviate (Box–Muller).
    fn gauss(&mut self) -> f64 {
        let a: f64 = 1.0 - self.rng.gen::<f64>();
        let b: f64 = self.rng.gen::<f64>();
        (-2.0 * a.ln()).sqrt() * (std::f64::consts::TAU * b).cos()
    }
}
