//! The selection of `uvt fit` (its driver is [`super::report`]): the classes of a scene's
//! primitives, the d_q of every configuration of the sweep and of the planar static configuration
//! for them ([`config_fits`], from [`crate::config::dq`]), the tolerance and the narrowest
//! configuration meeting it ([`narrowest`]).
//!
//! **Default tolerance: 1/32 px** ([`DEFAULT_TOLERANCE_PX`]), not the default configuration's
//! own d_q at the scene: the narrowest configuration meeting the default's own d_q is the
//! default itself (every narrower one of the sweep has a larger perturbation), so that choice
//! could never report a saving; 1/32 px is a fixed accuracy a hardware team can state (decisions
//! differ from the exact image only within 1/32 px of an edge) and lets the geometry decide.
//! A tolerance below the exact 16-fraction-bit configuration's d_q is unreachable (error).
//!
//! **Both forms of the statement** (`crate::config::dq`). A configuration meets the tolerance
//! when every primitive meets it by the one rule of `crate::config::dq::Statement::meets`: one
//! stated in pixels has d_q ≤ τ, however large d_q is; one stated in clip space only (a vertex
//! can reach the camera plane) has a backward error δ ≤ τ_c, the clip form of the tolerance
//! (`2τ/max(W, H)` unless `--clip-tolerance` gives it), and δ at most 1/16 of its own clip
//! extent (a larger δ says nothing about the primitive). No primitive is left without a
//! requirement.
//!
//! **Narrowest configuration**: the bounded configurations of the sweep and the planar static
//! configuration (`uvt_core::config::registry::PLANAR`, `crate::config::planar_static`: its own per-primitive d_q,
//! from each static triangle's rounding residual, nearest w and guard-band ratio; its cost per
//! unit: the planar test alone in the static-only unit, the bounded unit's plus the planar test's
//! in every other) ordered by their sample-test DSP48E1 estimate for the chosen unit, then Σ
//! bit-products (cheapest first); the first whose d_q meets the tolerance; the exact configuration
//! only when none does.
use anyhow::{anyhow, bail, Result};
use serde::Serialize;
use uvt_core::config::registry::{self, EXACT, PLANAR};
use uvt_core::{with_config, Class, Precision};

use crate::config::dq::{px_text, statements, Statement, Tolerance};
use crate::config::planar_static;
use crate::config::rounding::Rounding;
use crate::config::units::{unit_sample_cost, UnitCost};
use crate::scene::file::Scene;

/// The default tolerance (module docs).
pub const DEFAULT_TOLERANCE_PX: f64 = 1.0 / 32.0;

/// Bounds-tile sizes tried.
pub const TILES: [u8; 4] = [1, 2, 4, 8];

/// The scene's error statements at one configuration.
#[derive(Clone, Debug, Serialize)]
pub struct ConfigFit {
    /// configuration name
    pub config: String,
    /// largest d_q over the primitives stated in pixels (`None`: there are none)
    pub d_q_px: Option<f64>,
    /// the primitive attaining it
    pub worst_primitive: Option<usize>,
    /// largest backward error δ (clip units) over the primitives stated in clip space only
    /// (`None`: there are none)
    pub clip: Option<f64>,
    /// the primitive attaining it
    pub worst_clip_primitive: Option<usize>,
    /// largest δ as a share of the primitive's own clip extent over the primitives stated in
    /// clip space only (`None`: there are none); above 1/16 the statement says nothing
    /// (`crate::config::dq::Statement::informative`)
    pub clip_share: Option<f64>,
    /// the chosen unit's sample-test cost (`None`: exact, not modelled per unit)
    pub unit_cost: Option<UnitCost>,
    /// meets the tolerance in both forms
    pub meets: bool,
    /// primitives stated in clip space only at this configuration
    pub clip_primitives: Vec<usize>,
    /// every primitive's statement, in scene order (`None`: outside the core's domain)
    #[serde(skip)]
    pub statements: Vec<Option<Statement>>,
}

impl ConfigFit {
    fn new(
        config: String,
        statements: Vec<Option<Statement>>,
        unit_cost: Option<UnitCost>,
        tol: &Tolerance,
    ) -> ConfigFit {
        let (mut d_q_px, mut worst_primitive) = (None::<f64>, None);
        let (mut clip, mut worst_clip_primitive) = (None::<f64>, None);
        let mut clip_primitives = Vec::new();
        let mut clip_share = None::<f64>;
        let mut meets = true;
        for (i, st) in statements.iter().enumerate() {
            let Some(st) = st else { continue };
            meets &= st.meets(tol);
            match st.px {
                Some(d) if d_q_px.map_or(true, |m| d > m) => {
                    d_q_px = Some(d);
                    worst_primitive = Some(i);
                }
                Some(_) => {}
                None => {
                    clip_primitives.push(i);
                    clip_share = Some(clip_share.map_or(st.share(), |m| m.max(st.share())));
                    if clip.map_or(true, |m| st.clip > m) {
                        clip = Some(st.clip);
                        worst_clip_primitive = Some(i);
                    }
                }
            }
        }
        ConfigFit {
            config,
            d_q_px,
            worst_primitive,
            clip,
            worst_clip_primitive,
            clip_share,
            unit_cost,
            meets,
            clip_primitives,
            statements,
        }
    }
}

/// Classes of the scene's primitives (at the default precision's grids; a coarser grid can only
/// merge values, never make a static triangle move) and their counts.
pub fn classes(scene: &Scene) -> Result<Vec<Class>> {
    scene
        .tris
        .iter()
        .enumerate()
        .map(|(i, t)| {
            t.to_core()
                .map(|c| c.class())
                .map_err(|e| anyhow!("triangles[{i}]: {e}"))
        })
        .collect()
}

/// The statements of every configuration of the sweep and of the planar static configuration
/// (last) for the scene's primitives: each configuration's own ([`crate::config::dq::statements`]
/// of the triangles rounded to its grids, the perturbation of its own setup of each), the
/// statements `uvt render` and `uvt precision` count that configuration's differences under.
pub fn config_fits(scene: &Scene, unit: (bool, bool), tol: &Tolerance) -> Result<Vec<ConfigFit>> {
    let mut out = Vec::new();
    for cfg in registry::sweep()
        .map(|e| e.config)
        .chain(std::iter::once(PLANAR))
    {
        let st = with_config!(cfg, P => statements_at::<P>(scene))
            .ok_or_else(|| anyhow!("configuration {cfg} has no precision type"))??;
        let cost = if cfg.planar() {
            planar_static::unit_cost(unit.0, unit.1)
        } else {
            unit_sample_cost(&cfg, unit.0, unit.1)
        };
        out.push(ConfigFit::new(cfg.to_string(), st, cost, tol));
    }
    Ok(out)
}

/// The statements of the scene's primitives at `P` (rounded to `P`'s grids).
fn statements_at<P: Precision + Sync>(scene: &Scene) -> Result<Vec<Option<Statement>>> {
    let core = scene
        .tris
        .iter()
        .enumerate()
        .map(|(i, t)| {
            t.to_core_with::<P>()
                .map_err(|e| anyhow!("triangles[{i}]: {e}"))
        })
        .collect::<Result<Vec<_>>>()?;
    let r = Rounding::at(P::POS_FRAC, P::TUV_FRAC);
    Ok(statements::<P>(
        &scene.tris,
        &core,
        scene.core_viewport(),
        &r,
        1.0,
    ))
}

/// The narrowest configuration meeting the tolerance (module docs), or the unreachable error.
pub fn narrowest<'a>(fits: &'a [ConfigFit], tol: &Tolerance) -> Result<&'a ConfigFit> {
    let mut bounded: Vec<&ConfigFit> = fits.iter().filter(|f| f.unit_cost.is_some()).collect();
    bounded.sort_by_key(|f| {
        let c = f
            .unit_cost
            .as_ref()
            .map_or((0, 0), |c| (c.dsp48e1, c.bit_products));
        (c.0, c.1)
    });
    if let Some(f) = bounded.into_iter().find(|f| f.meets) {
        return Ok(f);
    }
    let exact_name = EXACT.to_string();
    let exact = fits
        .iter()
        .find(|f| f.config == exact_name)
        .ok_or_else(|| anyhow!("the sweep has no exact configuration"))?;
    if exact.meets {
        return Ok(exact);
    }
    bail!(
        "tolerance {} px (clip form {:.3e} clip units) is unreachable for this scene: even {} ({} fraction bits, exact test) states {} and {}",
        tol.px,
        tol.clip,
        exact.config,
        EXACT.pos(),
        exact.d_q_px.map_or("no primitive in pixels".into(), |d| format!(
            "a documented error distance of {} px (primitive {})",
            px_text(d),
            exact.worst_primitive.map_or("?".into(), |i| i.to_string())
        )),
        exact.clip.map_or("no primitive in clip space only".into(), |c| format!(
            "a backward error of {c:.3e} clip units (primitive {}, stated in clip space only; δ up to {:.3} of a primitive's own clip extent, at most 1/16 says something)",
            exact.worst_clip_primitive.map_or("?".into(), |i| i.to_string()),
            exact.clip_share.unwrap_or(0.0)
        )),
    )
}

/// Parse `--tolerance`: a finite number > 0 (px).
pub fn parse_tolerance(s: &str) -> Result<f64> {
    parse_positive(s, "--tolerance", "pixels, e.g. 0.03125")
}

/// Parse `--clip-tolerance`: a finite number > 0 (clip units).
pub fn parse_clip_tolerance(s: &str) -> Result<f64> {
    parse_positive(s, "--clip-tolerance", "clip units, e.g. 0.0001")
}

fn parse_positive(s: &str, option: &str, unit: &str) -> Result<f64> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| anyhow!("{option} {s:?}: not a number ({unit})"))?;
    if !v.is_finite() || v <= 0.0 {
        bail!("{option} {s:?}: must be a finite number greater than 0 ({unit})");
    }
    Ok(v)
}
