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
use uvt_core::Class;

use crate::config::dq::{eps_clip, prim_dq};
use crate::config::planar_static;
use crate::config::units::{unit_sample_cost, UnitCost};
use crate::frame::compare::Rounding;
use crate::scene::file::Scene;

/// The default tolerance (module docs).
pub const DEFAULT_TOLERANCE_PX: f64 = 1.0 / 32.0;

/// Bounds-tile sizes tried.
pub const TILES: [u8; 4] = [1, 2, 4, 8];

/// The scene's d_q at one configuration.
#[derive(Clone, Debug, Serialize)]
pub struct ConfigFit {
    /// configuration name
    pub config: String,
    /// largest d_q over primitives with a screen-space bound (px; 0 if there are none)
    pub d_q_px: f64,
    /// the primitive attaining it
    pub worst_primitive: Option<usize>,
    /// the chosen unit's sample-test cost (`None`: exact, not modelled per unit)
    pub unit_cost: Option<UnitCost>,
    /// meets the tolerance
    pub meets: bool,
    /// primitives without a screen-space bound at this configuration
    pub unbounded: Vec<usize>,
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

/// d_q of every configuration of the sweep and of the planar static configuration
/// (`crate::config::planar_static`, last) for the scene's primitives and their classes, and the
/// primitives without a screen-space bound in some configuration (the same for every configuration
/// up to ε).
pub fn config_fits(
    scene: &Scene,
    classes: &[Class],
    unit: (bool, bool),
    tol: f64,
) -> (Vec<ConfigFit>, Vec<usize>) {
    let vp = scene.core_viewport();
    let mut unbounded = Vec::new();
    let mut out = Vec::new();
    let mut push = |config: &str, dqs: &mut dyn Iterator<Item = Option<f64>>, cost| {
        let (d, worst, unb) = worst_dq(dqs);
        if unb.len() > unbounded.len() {
            unbounded = unb.clone();
        }
        out.push(ConfigFit {
            config: config.to_string(),
            d_q_px: d,
            worst_primitive: worst,
            unit_cost: cost,
            meets: d <= tol,
            unbounded: unb,
        });
    };
    for e in registry::sweep() {
        let (name, cfg) = (e.name, e.config);
        let r = Rounding::at(cfg.pos(), cfg.tuv());
        let mut dqs = scene
            .tris
            .iter()
            .zip(classes)
            .map(|(t, c)| prim_dq(t, scene.viewport, &r, eps_clip(&cfg, *c, vp)));
        push(name, &mut dqs, unit_sample_cost(&cfg, unit.0, unit.1));
    }
    // The planar static configuration (`crate::config::planar_static`): per-primitive ε for static
    // triangles.
    let mut dqs = scene.tris.iter().zip(classes).map(|(t, c)| {
        let core = t.to_core().ok()?;
        planar_static::prim_dq(t, &core, *c, scene.viewport, 1.0)
    });
    push(
        &PLANAR.to_string(),
        &mut dqs,
        planar_static::unit_cost(unit.0, unit.1),
    );
    (out, unbounded)
}

/// The largest of the primitives' d_q (`None`: no screen-space bound), the primitive it
/// belongs to, and the primitives without a bound.
fn worst_dq(dqs: &mut dyn Iterator<Item = Option<f64>>) -> (f64, Option<usize>, Vec<usize>) {
    let (mut d, mut worst) = (0.0f64, None);
    let mut unb = Vec::new();
    for (i, x) in dqs.enumerate() {
        match x {
            Some(x) if x > d => {
                d = x;
                worst = Some(i);
            }
            Some(_) => {}
            None => unb.push(i),
        }
    }
    (d, worst, unb)
}

/// The narrowest configuration meeting the tolerance (module docs), or the unreachable error.
pub fn narrowest(fits: &[ConfigFit], tol: f64) -> Result<&ConfigFit> {
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
        "tolerance {tol} px is unreachable for this scene: even {} ({} fraction bits, exact test) has a documented error distance of {:.6} px (primitive {}); the smallest tolerance it meets is {:.6} px",
        exact.config,
        EXACT.pos(),
        exact.d_q_px,
        exact.worst_primitive.map_or("?".into(), |i| i.to_string()),
        exact.d_q_px
    )
}

/// Parse `--tolerance`: a finite number > 0 (px).
pub fn parse_tolerance(s: &str) -> Result<f64> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| anyhow!("--tolerance {s:?}: not a number (pixels, e.g. 0.03125)"))?;
    if !v.is_finite() || v <= 0.0 {
        bail!("--tolerance {s:?}: must be a finite number of pixels greater than 0");
    }
    Ok(v)
}
