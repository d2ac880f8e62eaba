//! The confirming half of `uvt fit` ([`super::select`] has the selection, [`super::search`] the
//! strategy and tile-size search): the confirmation render — a brute-force pass over every
//! footprint sample (conservativeness of the chosen strategy and tile size, decisions against the
//! f64 reference, `compare.rs`'s rigorous per-sample check, and per primitive what a user sees:
//! its covered samples against the reference's, every primitive with a failing decision named) and the chosen unit's frame against
//! the full unit's, sample by sample — the general pipeline on the unit and, where the unit has
//! its own, the pipeline its `uvt_core::Renderer<B, N, P, U>` runs — each the core's own loop
//! ([`crate::frame::core_frame`]).

use serde::Serialize;
use uvt_core::bounds::any::AnyStrategy;
use uvt_core::bounds::strategy::BoundsStrategy;
use uvt_core::config::registry::Config;
use uvt_core::{
    with_config, DefocusOnly, Engine, Full, General, Laine2011, MotionOnly, NoZmax, Pipeline,
    PipelineOf, Precision, Rgb888, SamplePattern, Select, StaticOnly, Triangle, Unit,
};

use crate::compare::pass::{compare, PrimFail, Spec};
use crate::config::dq::{Statement, Tolerance};
use crate::config::rounding::Rounding;
use crate::frame::core_frame::run_core;
use crate::frame::opts::RunOpts;
use crate::scene::file::Scene;
use crate::scene::pattern::Pattern;

use super::search::inputs;

/// What the confirmation measured.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Confirm {
    /// (triangle, sample) pairs compared with the f64 reference
    pub compared: u64,
    /// decisions differing from the reference
    pub differ: u64,
    /// covered samples outside the chosen strategy's bounds at the chosen tile size, or culled
    /// by setup (must be 0)
    pub violations: u64,
    /// differing decisions that no input rounding or datapath perturbation explains
    /// (`compare.rs`'s rigorous check; must be 0)
    pub beyond_bound: u64,
    /// differing decisions of primitives stated in pixels (`crate::config::dq`)
    pub differ_px: u64,
    /// of those, farther than the primitive's own d_q from the nearest edge (the statement fails;
    /// must be 0)
    pub beyond_statement: u64,
    /// of those, farther than the tolerance from the nearest edge (must be 0)
    pub beyond_tolerance: u64,
    /// largest distance (px) of such a difference from the nearest edge
    pub max_distance_px: f64,
    /// differing decisions of primitives stated in clip space only
    pub differ_clip: u64,
    /// of those, not consistent with a triangle within the clip tolerance (no edge value or det
    /// within its bound for a perturbation of τ_c: `compare::check_sample_within`; must be 0)
    pub beyond_tolerance_clip: u64,
    /// the largest backward error δ (clip units) of a primitive with such a difference
    pub max_clip: f64,
    /// their largest distance (px) from the nearest edge (measured; the clip statement does not
    /// bound it)
    pub max_distance_clip_px: f64,
    /// of those, of primitives whose δ is not small against their own extent (each fails)
    pub differ_clip_uninformative: u64,
    /// samples covered by the configuration and by the f64 reference
    pub covered: [u64; 2],
    /// primitives the reference draws and the configuration does not, and the other way round
    pub lost_gained: [u64; 2],
    /// every primitive with a failing decision, named (`crate::compare::pass::PrimFail`; must
    /// be empty)
    pub failing: Vec<PrimFail>,
    /// the chosen unit's renderer produced the full unit's colour at every sample, the same
    /// resolved image and the same tested / covered counts
    pub identical_to_full: Option<bool>,
    /// why the renderer comparison could not run (e.g. a refused class, too many setups)
    pub renderer_error: Option<String>,
    /// samples tested and covered by the chosen unit's renderer
    pub unit_tested_covered: [u64; 2],
    /// the unit's specialised renderer at this configuration (`uvt_core::StaticRenderer` for
    /// the static-only unit at a planar configuration, `uvt_core::MotionRenderer` for the
    /// motion-only unit at a bounded or planar one — the renderers of the unit's Cortex-M
    /// programs, with their own tile cull): its name, whether it produced the full unit's
    /// colour at every sample and the same image, and its tested / covered counts; `None`
    /// when the unit has none at this configuration
    pub specialised: Option<Specialised>,
}

/// The specialised renderer's comparison with the full unit ([`Confirm::specialised`]).
#[derive(Clone, Debug, Default, Serialize)]
pub struct Specialised {
    /// `StaticRenderer` or `MotionRenderer`
    pub renderer: &'static str,
    /// every sample's colour and the resolved image equal the full unit's (the counters differ:
    /// its own tile cull tests other samples)
    pub identical_to_full: Option<bool>,
    /// why it could not run
    pub error: Option<String>,
    /// samples tested and covered by it
    pub tested_covered: [u64; 2],
}

impl Confirm {
    /// Every confirmation holds.
    pub fn ok(&self) -> bool {
        self.violations == 0
            && self.failing.is_empty()
            && self.beyond_bound == 0
            && self.beyond_statement == 0
            && self.beyond_tolerance == 0
            && self.beyond_tolerance_clip == 0
            && self.identical_to_full == Some(true)
            && self
                .specialised
                .as_ref()
                .map_or(true, |x| x.identical_to_full == Some(true))
    }
}

/// Confirm the choice (module docs); `statements[i]`: primitive i's error statement at `config`
/// (`crate::fit::select::ConfigFit::statements`). The strategy runs as
/// [`AnyStrategy`] (its own code, picked by name once per call: one instance of the checks per
/// configuration, not per configuration and strategy). `None` for a configuration outside the
/// registry or a strategy outside its list.
pub fn confirm(
    scene: &Scene,
    config: Config,
    strategy: &str,
    tile: u8,
    unit: &str,
    tol: &Tolerance,
    statements: &[Option<Statement>],
) -> Option<anyhow::Result<Confirm>> {
    let s = AnyStrategy::named(strategy)?;
    with_config!(config, P => confirm_at::<P, _>(scene, s, tile, unit, tol, statements))
}

fn confirm_at<P: Precision + Sync, B>(
    scene: &Scene,
    strat: B,
    tile: u8,
    unit: &str,
    tol: &Tolerance,
    statements: &[Option<Statement>],
) -> anyhow::Result<Confirm>
where
    B: BoundsStrategy + Sync + Send + Copy + 'static,
    B::Coeffs: Send + Sync,
    (P, Full): Select<B>,
    (P, DefocusOnly): Select<B>,
    (P, StaticOnly): Select<B> + Select<Laine2011>,
    (P, MotionOnly): Select<B> + Select<Laine2011>,
    PipelineOf<Laine2011, P, StaticOnly>: Sync,
    PipelineOf<Laine2011, P, MotionOnly>: Sync,
    <PipelineOf<Laine2011, P, StaticOnly> as Pipeline>::Entry: Send + Sync,
    <PipelineOf<Laine2011, P, MotionOnly> as Pipeline>::Entry: Send + Sync,
{
    let (core, pat) = inputs::<P>(scene)?;
    let mut c = brute_force::<P, B>(scene, &core, &pat, strat, tile, tol, statements);
    let colors = scene.colors();
    let o = RunOpts {
        tile,
        clear: CLEAR,
        image: true,
        ..RunOpts::for_scene(scene, &colors)
    };
    let table = SamplePattern::new_with::<P>(pat.block, pat.spp, &pat.quant)
        .map_err(|e| anyhow::anyhow!("sample table: {e}"))?;
    let vp = scene.core_viewport();
    let band = |f: &dyn Fn() -> Result<crate::frame::counters::Frame, uvt_core::Error>| {
        f().map(Frame::of).map_err(|e| e.to_string())
    };
    let full = band(&|| frame::<General<B, P, Full>>(strat, vp, &core, &table, &o));
    let mine = match unit {
        "full" => band(&|| frame::<General<B, P, Full>>(strat, vp, &core, &table, &o)),
        "motion-only" => band(&|| frame::<General<B, P, MotionOnly>>(strat, vp, &core, &table, &o)),
        "defocus-only" => {
            band(&|| frame::<General<B, P, DefocusOnly>>(strat, vp, &core, &table, &o))
        }
        "static-only" => band(&|| frame::<General<B, P, StaticOnly>>(strat, vp, &core, &table, &o)),
        u => Err(format!("unknown unit {u}")),
    };
    let spec = match unit {
        "static-only" => specialised::<P, StaticOnly>(vp, &core, &table, &o),
        "motion-only" => specialised::<P, MotionOnly>(vp, &core, &table, &o),
        _ => None,
    };
    let (full, mine) = match (full, mine) {
        (Ok(full), Ok(mine)) => (full, mine),
        (Err(e), _) | (_, Err(e)) => {
            c.renderer_error = Some(e);
            return Ok(c);
        }
    };
    c.identical_to_full = Some(full == mine);
    c.unit_tested_covered = [mine.tested, mine.covered];
    c.specialised = spec.map(|(renderer, got)| match &got {
        Ok(f) => Specialised {
            renderer,
            identical_to_full: Some(f.samples == full.samples && f.image == full.image),
            error: None,
            tested_covered: [f.tested, f.covered],
        },
        Err(e) => Specialised {
            renderer,
            identical_to_full: None,
            error: Some(e.clone()),
            tested_covered: [0, 0],
        },
    });
    Ok(c)
}

/// Background of the confirmation renders (as `uvt render`).
const CLEAR: [u8; 3] = [24, 24, 32];

/// What the confirmation compares of a render: every sample's colour, the resolved image, the
/// counters.
#[derive(PartialEq)]
struct Frame {
    samples: Vec<Rgb888>,
    image: Vec<Rgb888>,
    tested: u64,
    covered: u64,
}

impl Frame {
    /// The comparison's view of a frame of the core.
    fn of(f: crate::frame::counters::Frame) -> Frame {
        Frame {
            samples: f.samples,
            image: f
                .image
                .iter()
                .map(|p| Rgb888::new(p[0], p[1], p[2]))
                .collect(),
            tested: f.stats.samples_tested,
            covered: f.stats.samples_covered,
        }
    }
}

/// The core's frame ([`run_core`], in bands) of pipeline `L` with bounds strategy `strat`.
fn frame<L: Pipeline + Sync>(
    strat: L::Bounds,
    vp: uvt_core::Viewport,
    core: &[Triangle],
    table: &SamplePattern<'_>,
    o: &RunOpts<'_>,
) -> Result<crate::frame::counters::Frame, uvt_core::Error>
where
    L::Entry: Send + Sync,
{
    run_core(&Engine::<L, NoZmax>::new(strat, vp), core, table, o)
}

/// The renderer a user instantiates for unit `U` at precision `P`, `Renderer<B, N, P, U>`, when
/// it runs the unit's own pipeline (`uvt_core::units::select`): its name and frame; `None`
/// where it runs the general pipeline. The unit's own pipeline culls with its own tests and
/// does not use the bounds strategy `B` (the type keeps it, unused), so it is run with Laine
/// 2011 whatever was chosen: the same pipeline.
fn specialised<P: Precision, U: Unit>(
    vp: uvt_core::Viewport,
    core: &[Triangle],
    table: &SamplePattern<'_>,
    o: &RunOpts<'_>,
) -> Option<(&'static str, Result<Frame, String>)>
where
    (P, U): Select<Laine2011>,
    PipelineOf<Laine2011, P, U>: Sync,
    <PipelineOf<Laine2011, P, U> as Pipeline>::Entry: Send + Sync,
{
    let name = <PipelineOf<Laine2011, P, U> as Pipeline>::NAME;
    (name != <General<Laine2011, P, U> as Pipeline>::NAME).then(|| {
        let f = frame::<PipelineOf<Laine2011, P, U>>(Laine2011, vp, core, table, o);
        (name, f.map(Frame::of).map_err(|e| e.to_string()))
    })
}

/// Every footprint sample of every triangle: the one comparison ([`crate::compare::pass`]) of
/// the decisions at `P` against the reference, under the statements and the tolerance, and the
/// conservativeness of `strat` at `tile`.
fn brute_force<P: Precision + Sync, B: BoundsStrategy + Sync>(
    scene: &Scene,
    core: &[Triangle],
    pat: &Pattern,
    strat: B,
    tile: u8,
    tol: &Tolerance,
    statements: &[Option<Statement>],
) -> Confirm
where
    B::Coeffs: Send + Sync,
{
    let spec = Spec {
        strategy: strat,
        tiles: vec![tile],
        statements: statements.to_vec(),
        tolerance: Some(*tol),
        rounding: Rounding::at(P::POS_FRAC, P::TUV_FRAC),
    };
    let c = compare::<P, B>(&scene.tris, core, scene.core_viewport(), pat, &spec);
    Confirm {
        compared: c.compared,
        differ: c.differ,
        violations: c.violations(),
        beyond_bound: c.beyond_bound,
        differ_px: c.differ_px,
        beyond_statement: c.beyond_statement,
        beyond_tolerance: c.beyond_tolerance,
        max_distance_px: c.max_distance_stated_px,
        differ_clip: c.differ_clip,
        beyond_tolerance_clip: c.beyond_tolerance_clip,
        max_clip: c.max_clip,
        max_distance_clip_px: c.max_distance_clip_px,
        differ_clip_uninformative: c.differ_clip_uninformative,
        covered: [c.core_covered, c.reference_covered],
        lost_gained: [c.lost, c.gained],
        failing: c.failing,
        ..Confirm::default()
    }
}
