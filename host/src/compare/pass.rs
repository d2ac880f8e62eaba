//! **The one comparison** of the core's decisions with the f64 reference's, used by `uvt render`,
//! `uvt precision`, `uvt stress` and `uvt fit`'s confirmation: for every triangle, every sample of
//! every pixel of the union of the core's and the reference's footprints (both are conservative,
//! so every covered sample is inside it) — the samples the bounds cull included — the core's
//! sample test at precision `P` ([`uvt_core::sample::test`] on the triangle's unculled setup:
//! the one place outside the oracle's limit search where the host calls it) against the
//! reference's ray test on the exact inputs. Per sample it checks:
//!
//! - **the decision**: a differing one is checked against the quantization bound
//!   ([`super::bound::check_sample_eps`]: *beyond bound* must be 0) and counted under its
//!   primitive's error statement ([`crate::config::dq`]): stated in pixels, it must lie within
//!   the primitive's own d_q of an edge (*beyond statement* must be 0) and, with a tolerance,
//!   within it; stated in clip space only, it is counted with its backward error δ and, with a
//!   tolerance, must be explained by a vertex move of the clip tolerance and the primitive's
//!   δ must be small against its own extent (`Statement::informative`); without a statement it
//!   fails;
//! - **per primitive, what a user sees**: the samples the core and the reference cover; a
//!   primitive one of them draws and the other does not is counted (*lost*, *gained*), and every
//!   primitive with a failing decision is listed by index with its covered samples on both sides
//!   and why it fails ([`PrimFail`]), so a report can name it;
//! - **the depth** of a sample both cover (LSBs of the I8F24 depth);
//! - **conservativeness** of the bounds strategy at every bounds-tile size asked: a sample the
//!   core covers must be admitted by its tile — row span, tile step and per-sample predicate,
//!   as the renderer walks ([`uvt_core::BoundsStrategy::row_span`], `span_tile`, `admits`) —
//!   and lie in the core's footprint (*violations* must be 0); beside it the tile's slack
//!   against the reference's f64 Laine 2011 box and the margin a covered sample needs outside
//!   that box (the measured epsilon).

use rayon::prelude::*;
use serde::Serialize;
use uvt_core::bounds::strategy::{BoundsStrategy, TileBounds};
use uvt_core::config::formats::DEPTH_FAR;
use uvt_core::{Full, Ops, Outcome, PixelRect, Precision, ScreenPos, Setup, Triangle, Viewport};

use crate::config::dq::{Statement, Tolerance};
use crate::config::rounding::{eps_of, Rounding};
use crate::reference;
use crate::scene::pattern::Pattern;
use crate::scene::tri::SceneTri;

use super::bound::{check_sample_eps, check_sample_within, footprint_union};

/// What a comparison checks beyond the decisions (module docs).
#[derive(Clone, Debug)]
pub struct Spec<B> {
    /// the bounds strategy whose conservativeness is checked
    pub strategy: B,
    /// the bounds-tile sizes it is checked at (1, 2, 4, 8)
    pub tiles: Vec<u8>,
    /// every primitive's error statement (`None`: none; its differing decisions fail)
    pub statements: Vec<Option<Statement>>,
    /// the tolerance the statements must also meet, if any (`uvt fit`)
    pub tolerance: Option<Tolerance>,
    /// the inputs' rounding the bound assumes
    pub rounding: Rounding,
}

impl Spec<uvt_core::Laine2011> {
    /// The decisions alone, at rounding `r`: no bounds-tile size, no statement (every differing
    /// decision counts as beyond its statement; the bound is checked all the same).
    pub fn decisions(r: Rounding) -> Self {
        Spec {
            strategy: uvt_core::Laine2011,
            tiles: Vec::new(),
            statements: Vec::new(),
            tolerance: None,
            rounding: r,
        }
    }
}

/// Conservativeness of the strategy at one bounds-tile size, and its slack (module docs).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct TileCheck {
    /// bounds-tile size
    pub tile: u8,
    /// samples the core covers that its setup, footprint or bounds exclude (must be 0)
    pub violations: u64,
    /// tile width (core's enclosing box − reference's box) summed and largest, per axis t, u, v
    pub slack_sum: [f64; 3],
    /// largest slack per axis
    pub slack_max: [f64; 3],
    /// tiles the slack was measured on
    pub slack_n: u64,
    /// smallest outward margin on the reference's boxes holding every sample the core covers,
    /// per axis t, u, v
    pub eps_measured: [f64; 3],
    /// samples the core covers outside the reference's footprint or in a tile it skips
    pub eps_outside: u64,
}

/// Everything one comparison measured (module docs).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Comparison {
    /// (triangle, sample) pairs compared
    pub compared: u64,
    /// decisions differing from the reference
    pub differ: u64,
    /// covered by the core only
    pub fixed_only: u64,
    /// covered by the reference only
    pub f64_only: u64,
    /// differences that no input rounding or datapath perturbation explains: no edge value or
    /// det within its bound (must be 0)
    pub beyond_bound: u64,
    /// largest check ratio of a differing sample (≤ 1 when `beyond_bound` is 0): how much of
    /// the bound the worst difference uses
    pub max_ratio: f64,
    /// largest distance in pixels of a differing sample from the nearest edge
    pub max_distance_px: f64,
    /// largest per-sample quantization distance (px) among differences explained by an edge
    pub max_bound_px: f64,
    /// differences explained only by det (near edge-on triangle at the sample's t, u, v)
    pub by_det: u64,
    /// differences on triangles with a vertex at w ≤ 0 at either end of the shutter
    pub behind: u64,
    /// differing decisions of primitives stated in pixels
    pub differ_px: u64,
    /// of those, farther than the primitive's own d_q from the nearest edge, plus every differing
    /// decision of a primitive without a statement (must be 0)
    pub beyond_statement: u64,
    /// largest distance (px) from the nearest edge of a difference stated in pixels
    pub max_distance_stated_px: f64,
    /// the largest d_q (px) of a primitive stated in pixels with a difference: how far the
    /// statements allow them to lie
    pub max_dq_px: f64,
    /// differing decisions of primitives stated in clip space only
    pub differ_clip: u64,
    /// the largest backward error δ (clip units) of a primitive with such a difference
    pub max_clip: f64,
    /// their largest distance (px) from the nearest edge (measured; the clip statement does not
    /// bound it)
    pub max_distance_clip_px: f64,
    /// with a tolerance: differences stated in pixels farther than it from the nearest edge
    pub beyond_tolerance: u64,
    /// with a tolerance: differences stated in clip space that no vertex move of the clip
    /// tolerance explains
    pub beyond_tolerance_clip: u64,
    /// depth error of samples both cover, LSBs: largest, sum and count
    pub depth_lsb_max: f64,
    /// sum of the depth errors
    pub depth_lsb_sum: f64,
    /// samples the depth error was measured on
    pub depth_n: u64,
    /// differing decisions of primitives stated in clip space only whose δ is not small against
    /// the primitive's own extent (`Statement::informative`: the statement says nothing)
    pub differ_clip_uninformative: u64,
    /// samples the core covers, summed over the primitives
    pub core_covered: u64,
    /// samples the reference covers, summed over the primitives
    pub reference_covered: u64,
    /// primitives the reference draws (covers a sample of) and the core does not
    pub lost: u64,
    /// primitives the core draws and the reference does not
    pub gained: u64,
    /// conservativeness per bounds-tile size, in the order asked
    pub tiles: Vec<TileCheck>,
    /// every primitive with a failing decision, in scene order
    pub failing: Vec<PrimFail>,
}

/// A primitive with a failing decision ([`Comparison::failing`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PrimFail {
    /// its index in the scene
    pub primitive: usize,
    /// its statement: `"pixels"`, `"clip"` or `"none"`
    pub stated: &'static str,
    /// d_q (px) or δ (clip units) of that statement
    pub bound: f64,
    /// samples the core covers
    pub core_covered: u64,
    /// samples the reference covers
    pub reference_covered: u64,
    /// its differing decisions
    pub differ: u64,
    /// of those, failing (beyond the bound, its statement or the tolerance)
    pub failing: u64,
    /// why, in words
    pub why: Vec<&'static str>,
}

impl Comparison {
    /// Differences per compared pair.
    pub fn rate(&self) -> f64 {
        if self.compared == 0 {
            0.0
        } else {
            self.differ as f64 / self.compared as f64
        }
    }

    /// Violations at every tile size.
    pub fn violations(&self) -> u64 {
        self.tiles.iter().map(|t| t.violations).sum()
    }

    fn add(&mut self, o: &Comparison) {
        let sums = [
            (&mut self.compared, o.compared),
            (&mut self.differ, o.differ),
            (&mut self.fixed_only, o.fixed_only),
            (&mut self.f64_only, o.f64_only),
            (&mut self.beyond_bound, o.beyond_bound),
            (&mut self.by_det, o.by_det),
            (&mut self.behind, o.behind),
            (&mut self.differ_px, o.differ_px),
            (&mut self.beyond_statement, o.beyond_statement),
            (&mut self.differ_clip, o.differ_clip),
            (&mut self.beyond_tolerance, o.beyond_tolerance),
            (&mut self.beyond_tolerance_clip, o.beyond_tolerance_clip),
            (
                &mut self.differ_clip_uninformative,
                o.differ_clip_uninformative,
            ),
            (&mut self.core_covered, o.core_covered),
            (&mut self.reference_covered, o.reference_covered),
            (&mut self.lost, o.lost),
            (&mut self.gained, o.gained),
            (&mut self.depth_n, o.depth_n),
        ];
        for (a, b) in sums {
            *a += b;
        }
        let maxima = [
            (&mut self.max_ratio, o.max_ratio),
            (&mut self.max_distance_px, o.max_distance_px),
            (&mut self.max_bound_px, o.max_bound_px),
            (&mut self.max_distance_stated_px, o.max_distance_stated_px),
            (&mut self.max_dq_px, o.max_dq_px),
            (&mut self.max_clip, o.max_clip),
            (&mut self.max_distance_clip_px, o.max_distance_clip_px),
            (&mut self.depth_lsb_max, o.depth_lsb_max),
        ];
        for (a, b) in maxima {
            *a = a.max(b);
        }
        self.depth_lsb_sum += o.depth_lsb_sum;
        self.failing.extend(o.failing.iter().cloned());
        for (a, b) in self.tiles.iter_mut().zip(&o.tiles) {
            a.violations += b.violations;
            a.slack_n += b.slack_n;
            a.eps_outside += b.eps_outside;
            for k in 0..3 {
                a.slack_sum[k] += b.slack_sum[k];
                a.slack_max[k] = a.slack_max[k].max(b.slack_max[k]);
                a.eps_measured[k] = a.eps_measured[k].max(b.eps_measured[k]);
            }
        }
    }

    /// One differing decision at `distance` px from the nearest edge, its bound check `c`, the
    /// check of the clip tolerance `within` (with a tolerance and a clip statement), under
    /// statement `st`. Whether it fails (beyond the bound, its statement or the tolerance).
    fn differs(
        &mut self,
        core_covers: bool,
        distance: f64,
        c: &super::bound::SampleCheck,
        st: Option<Statement>,
        tol: Option<Tolerance>,
        within: impl FnOnce(f64) -> f64,
    ) -> bool {
        let before = [
            self.beyond_bound,
            self.beyond_statement,
            self.beyond_tolerance,
            self.beyond_tolerance_clip,
        ];
        self.differ += 1;
        if core_covers {
            self.fixed_only += 1;
        } else {
            self.f64_only += 1;
        }
        self.max_distance_px = self.max_distance_px.max(distance);
        self.max_ratio = self.max_ratio.max(c.ratio);
        if c.ratio > 1.0 {
            self.beyond_bound += 1;
        } else if c.which == 3 {
            self.by_det += 1;
        } else if let Some(b) = c.bound_px {
            self.max_bound_px = self.max_bound_px.max(b);
        }
        self.behind += u64::from(c.behind);
        match st {
            Some(Statement { px: Some(dq), .. }) => {
                self.differ_px += 1;
                self.max_distance_stated_px = self.max_distance_stated_px.max(distance);
                self.max_dq_px = self.max_dq_px.max(dq);
                self.beyond_statement += u64::from(distance > dq);
                if let Some(t) = tol {
                    self.beyond_tolerance += u64::from(distance > t.px);
                }
            }
            Some(s @ Statement { px: None, .. }) => {
                self.differ_clip += 1;
                self.max_clip = self.max_clip.max(s.clip);
                self.max_distance_clip_px = self.max_distance_clip_px.max(distance);
                self.differ_clip_uninformative += u64::from(!s.informative());
                if let Some(t) = tol {
                    // A statement that says nothing meets no tolerance (`Statement::meets`).
                    self.beyond_tolerance_clip +=
                        u64::from(!s.informative() || within(t.clip) > 1.0);
                }
            }
            None => self.beyond_statement += 1,
        }
        before
            != [
                self.beyond_bound,
                self.beyond_statement,
                self.beyond_tolerance,
                self.beyond_tolerance_clip,
            ]
    }
}

/// The comparison (module docs) of the core at precision `P` — triangles `core` and table `pat`
/// on `P`'s grids — with the reference on the exact triangles `tris` (viewport `vp`), checking
/// `spec`. `spec.statements` has one entry per triangle (missing entries are `None`).
pub fn compare<P: Precision + Sync, B: BoundsStrategy + Sync>(
    tris: &[SceneTri],
    core: &[Triangle],
    vp: Viewport,
    pat: &Pattern,
    spec: &Spec<B>,
) -> Comparison
where
    B::Coeffs: Send + Sync,
{
    let empty = Comparison {
        tiles: spec
            .tiles
            .iter()
            .map(|&tile| TileCheck {
                tile,
                ..Default::default()
            })
            .collect(),
        ..Default::default()
    };
    let each = |i: usize| {
        let mut d = empty.clone();
        let statement = spec.statements.get(i).copied().flatten();
        if let (Some(st), Some(ct)) = (tris.get(i), core.get(i)) {
            one::<P, B>(i, st, ct, vp, pat, spec, statement, &mut d);
        }
        d
    };
    over_triangles(tris.len().min(core.len()), &each, &empty)
}

/// The comparisons of triangles `0..n` by `each`, in parallel, summed onto `empty`. Not generic:
/// the parallel iterator's machinery is compiled once, not once per precision and strategy.
fn over_triangles(
    n: usize,
    each: &(dyn Fn(usize) -> Comparison + Sync),
    empty: &Comparison,
) -> Comparison {
    (0..n).into_par_iter().map(each).reduce(
        || empty.clone(),
        |mut a, b| {
            a.add(&b);
            a
        },
    )
}

/// The bounds-tile cell of pixel (`px`, `py`) at size `bt`, clipped to `fp`.
fn cell_of(px: u16, py: u16, fp: PixelRect, bt: u16) -> PixelRect {
    PixelRect {
        x0: px - px % bt,
        y0: py - py % bt,
        x1: px - px % bt + bt,
        y1: py - py % bt + bt,
    }
    .intersect(&fp)
}

/// One triangle of [`compare`], primitive `index` of the scene.
#[allow(clippy::too_many_arguments)]
fn one<P: Precision, B: BoundsStrategy>(
    index: usize,
    st: &SceneTri,
    ct: &Triangle,
    vp: Viewport,
    pat: &Pattern,
    spec: &Spec<B>,
    statement: Option<Statement>,
    d: &mut Comparison,
) {
    let v = (vp.width(), vp.height());
    let mut ops = Ops::default();
    let fx = match uvt_core::setup::<P, Full>(ct, vp, &mut ops) {
        Outcome::Visible(x) => Some((x, spec.strategy.prepare::<Full>(&x, &mut ops))),
        Outcome::Culled(_) | Outcome::Refused(_) => None,
    };
    let rf = reference::setup::setup(st, v).ok();
    let Some(region) = footprint_union(
        fx.as_ref().map(|x| x.0.footprint()),
        rf.as_ref().map(|x| x.footprint),
    ) else {
        return;
    };
    // P's own sample test (exact, bounded or planar) on the unculled setup, and its
    // perturbation in the bound.
    let full = Setup::unculled::<P>(ct, vp);
    let eps = eps_of(&full);
    let r = &spec.rounding;
    let mut covered = [0u64; 2];
    let mut failing = 0u64;
    let mut tiles = Vec::with_capacity(spec.tiles.len());
    for py in region.y0..region.y1 {
        for px in region.x0..region.x1 {
            tiles.clear();
            for (ti, &t) in spec.tiles.iter().enumerate() {
                let bt = u16::from(t);
                // The core's tile as the renderer walks it: the row's span, then the tile.
                let core_tile = fx.as_ref().and_then(|(x, k)| {
                    let fp = x.footprint();
                    if !fp.contains(px, py) {
                        return None;
                    }
                    let cell = cell_of(px, py, fp, bt);
                    let row = PixelRect {
                        x0: fp.x0,
                        x1: fp.x1,
                        ..cell
                    };
                    let span = spec.strategy.row_span(x, k, row, bt, &mut ops);
                    if !span.admits(&cell) {
                        return None;
                    }
                    spec.strategy.span_tile::<Full>(x, k, &span, cell, &mut ops)
                });
                let ref_tile = rf.as_ref().and_then(|x| {
                    x.footprint
                        .contains(px, py)
                        .then(|| reference::bounds::tile(x, cell_of(px, py, x.footprint, bt)))
                });
                // Slack, once per cell (at its top-left pixel inside the region).
                let first_x = px % bt == 0 || px == region.x0;
                let first_y = py % bt == 0 || py == region.y0;
                if let (true, true, Some(fb), Some(Some(rb))) =
                    (first_x, first_y, &core_tile, &ref_tile)
                {
                    let fb = fb.uvt_box();
                    let w = [(fb.t, rb.t), (fb.u, rb.u), (fb.v, rb.v)];
                    let tc = &mut d.tiles[ti];
                    for (k, (fi, ri)) in w.iter().enumerate() {
                        let s = (fi.hi() - fi.lo()) as f64 / 65536.0 - (ri.1 - ri.0);
                        tc.slack_sum[k] += s;
                        tc.slack_max[k] = tc.slack_max[k].max(s);
                    }
                    tc.slack_n += 1;
                }
                tiles.push((core_tile, ref_tile));
            }
            for si in 0..usize::from(pat.spp) {
                let idx = pat.index(px, py, si);
                let (q, e) = (&pat.quant[idx], &pat.exact[idx]);
                let hf =
                    uvt_core::sample::test::<P, Full>(&full, ScreenPos::of(px, py, q), q, &mut ops);
                let (x, y) = (f64::from(px) + e[0], f64::from(py) + e[1]);
                let hr = reference::sample::sample_test(st, v, x, y, e[2], e[3], e[4]);
                d.compared += 1;
                covered[0] += u64::from(hf.is_some());
                covered[1] += u64::from(hr.is_some());
                if hf.is_some() != hr.is_some() {
                    let dist = reference::sample::edge_distance_px(st, v, x, y, e[2], e[3], e[4]);
                    let c = check_sample_eps(st, v, x, y, e[2], e[3], e[4], r, eps);
                    let within = |clip: f64| {
                        check_sample_within(st, v, x, y, e[2], e[3], e[4], r.sub, [clip; 3]).ratio
                    };
                    failing += u64::from(d.differs(
                        hf.is_some(),
                        dist,
                        &c,
                        statement,
                        spec.tolerance,
                        within,
                    ));
                }
                if let (Some(h), Some(z)) = (hf, hr) {
                    if h.depth != DEPTH_FAR && z.abs() < 128.0 {
                        let err = (f64::from(h.depth) - z * 16777216.0).abs();
                        d.depth_lsb_max = d.depth_lsb_max.max(err);
                        d.depth_lsb_sum += err;
                        d.depth_n += 1;
                    }
                }
                if hf.is_none() {
                    continue;
                }
                let (u, vv, t) = (q.u().to_bits(), q.v().to_bits(), q.t().to_bits());
                for (tc, (core_tile, ref_tile)) in d.tiles.iter_mut().zip(&tiles) {
                    let admitted = core_tile
                        .as_ref()
                        .is_some_and(|b| b.admits(u, vv, t, &mut ops));
                    tc.violations += u64::from(!admitted);
                    match ref_tile {
                        Some(Some(rb)) => {
                            let s3 = [t, u, vv].map(|x| f64::from(x) / 65536.0);
                            let r3 = [rb.t, rb.u, rb.v];
                            for k in 0..3 {
                                let out = (r3[k].0 - s3[k]).max(s3[k] - r3[k].1).max(0.0);
                                tc.eps_measured[k] = tc.eps_measured[k].max(out);
                            }
                        }
                        _ => tc.eps_outside += 1,
                    }
                }
            }
        }
    }
    per_primitive(
        d,
        index,
        statement,
        spec.tolerance.is_some(),
        covered,
        failing,
    );
}

/// The per-primitive verdict of [`one`] (module docs): `d` holds primitive `index`'s counts alone,
/// `covered` its samples covered by the core and by the reference.
fn per_primitive(
    d: &mut Comparison,
    index: usize,
    st: Option<Statement>,
    tolerance: bool,
    covered: [u64; 2],
    failing: u64,
) {
    d.core_covered += covered[0];
    d.reference_covered += covered[1];
    d.lost += u64::from(covered[1] > 0 && covered[0] == 0);
    d.gained += u64::from(covered[0] > 0 && covered[1] == 0);
    let clip_says_nothing = tolerance && d.differ_clip_uninformative > 0;
    let why: Vec<&'static str> = [
        (d.beyond_bound > 0, "differs where no rounding explains it"),
        (d.beyond_statement > 0, "differs beyond its statement"),
        (
            d.beyond_tolerance > 0,
            "differs farther than the tolerance from an edge",
        ),
        (
            clip_says_nothing,
            "its clip statement says nothing: δ above 1/16 of its extent",
        ),
        (
            d.beyond_tolerance_clip > 0 && !clip_says_nothing,
            "differs beyond a vertex move of the clip tolerance",
        ),
    ]
    .into_iter()
    .filter_map(|(f, w)| f.then_some(w))
    .collect();
    if why.is_empty() {
        return;
    }
    let (stated, bound) = match st {
        Some(Statement { px: Some(dq), .. }) => ("pixels", dq),
        Some(s) => ("clip", s.clip),
        None => ("none", f64::NAN),
    };
    d.failing.push(PrimFail {
        primitive: index,
        stated,
        bound,
        core_covered: covered[0],
        reference_covered: covered[1],
        differ: d.differ,
        failing,
        why,
    });
}

/// The primitives a comparison fails on ([`Comparison::failing`]), named (at most the first 20), as Markdown.
pub fn failing_md(failing: &[PrimFail]) -> String {
    if failing.is_empty() {
        return String::new();
    }
    let mut s = format!(
        "\n{} primitive(s) fail{}:\n\n| primitive | stated in | d_q px / δ clip units | covered (configuration / f64) | differing | failing | why |\n|---|---|---|---|---|---|---|\n",
        failing.len(),
        if failing.len() > 20 { " (the first 20)" } else { "" }
    );
    for p in failing.iter().take(20) {
        s += &format!(
            "| {} | {} | {:.3e} | {} / {} | {} | {} | {} |\n",
            p.primitive,
            p.stated,
            p.bound,
            p.core_covered,
            p.reference_covered,
            p.differ,
            p.failing,
            p.why.join("; ")
        );
    }
    s
}
