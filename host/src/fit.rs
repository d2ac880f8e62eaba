//! `uvt fit SCENE.json`: which rasterizer unit a scene needs, and what it saves — the smallest
//! unit variant (`uvt_core::config::unit`) that accepts every primitive's class, the narrowest
//! configuration of the precision sweep ([`crate::cost::SWEEP`]) whose documented error
//! distance meets the tolerance *for this scene's geometry*, the bounds strategy and tile size
//! with the most covered samples per unit of cost; then a render with that choice to confirm it
//! (`crate::fit_confirm`). `uvt units` prints the variant table ([`units_md`]).
//!
//! **Documented error distance d_q of a primitive** (px). The same terms as the rigorous
//! per-sample check of `compare.rs` (module docs there: "Rounding", "Vertex perturbation"),
//! written per vertex instead of per sample: vertex k moves in clip space by at most
//! `Δx_k = 2δp + δt|x1 − x0| + δt|c1 − c0| + δt·max(|c0|, |c1|) + ε_x` (position rounding of x
//! and of the CoC, t rounding times the screen travel and the CoC change, u rounding times the
//! CoC, and the bounded datapath's perturbation `ε` of `Eps::of` for the primitive's class),
//! `Δy_k` likewise, `Δw_k = δp + δt|w1 − w0| + ε_w`, with `δp = 2^-(POS+1)` and
//! `δt = 2^-17 (+ 2^-(TUV+1) when TUV < 16)` ([`Rounding::at`]). Its projection moves by
//! `|x'/w' − x/w| = |Δx·w − x·Δw|/(w·w') ≤ (Δx_k + ρ_k·Δw_k)/(w_min − Δw_k)` where
//! `w_min = min(w0, w1)` is the vertex's nearest w over the shutter and
//! `ρ_k = max over both ends of (|x| + |c|)/w` its largest |x/w| over shutter and lens (the
//! guard band: a vertex far outside the view multiplies the w error) — both ends suffice because
//! `|x(t)| + |c(t)|` is at most the lerp of the ends' values and w(t) is the lerp of positive
//! ends. In pixels that is `·W/2` (x) and `·H/2` (y). d_q of the primitive is the largest of
//! these over its vertices and both axes, plus the sample position's sub-pixel floor (1/256 px).
//! A point of an edge between two vertices in front of the camera is a convex combination of
//! their projections, so it moves by at most the larger vertex displacement. **No screen-space
//! bound** exists when some vertex has `w_min ≤ Δw_k` (it can reach the camera plane): such
//! primitives are counted separately and the confirmation reports their measured distances.
//! The scene's d_q of a configuration is the maximum over the other primitives.
//!
//! **Default tolerance: 1/32 px** ([`DEFAULT_TOLERANCE_PX`]), not the default configuration's
//! own d_q at the scene: the narrowest configuration meeting the default's own d_q is the
//! default itself (every narrower one of the sweep has a larger perturbation), so that choice
//! could never report a saving; 1/32 px is a fixed accuracy a hardware team can state (decisions
//! differ from the exact image only within 1/32 px of an edge) and lets the geometry decide.
//! A tolerance below the exact 16-fraction-bit configuration's d_q is unreachable (error).
//!
//! **Narrowest configuration**: the bounded configurations of the sweep and the planar static
//! configuration `planar-16-16-16-20` (`crate::planar`: its own per-primitive d_q, from each
//! static triangle's rounding residual, nearest w and guard-band ratio; its cost per unit: the
//! planar test alone in the static-only unit, the bounded unit's plus the planar test's in every
//! other) ordered by their sample-test DSP48E1 estimate for the chosen unit, then Σ
//! bit-products (cheapest first); the first whose d_q meets the tolerance; the exact
//! configuration only when none does.
//!
//! **Cost of a bounds strategy and tile size** (from the bench machinery's counters, one frame
//! of the scene at the chosen configuration): `setup ops + tile-bounds ops + per-sample predicate
//! ops + sample tests × s`, with `s` the counted operations per sample test of that frame times
//! the sample test's width factor `Σ bit-products / (products · 32 · 32)` of the chosen unit and
//! configuration (its products in units of a 32 × 32 product; the counters count ≤ 32-bit
//! operations). Every strategy covers the same samples (bounds are conservative), so the score —
//! covered samples per unit of cost, i.e. STE per unit of per-test cost — ranks by total cost;
//! ties go to the earlier strategy of [`crate::bench::STRATEGIES`] and the smaller tile.

use std::path::Path;

use anyhow::{anyhow, bail, Context, Result};
use serde::{Deserialize, Serialize};
use uvt_core::widths::{table, Config};
use uvt_core::{Class, Viewport};

use crate::compare::Rounding;
use crate::cost::{dsp48e1, ecp5, SWEEP};
use crate::scene::{Scene, SceneTri};

/// The default tolerance (module docs).
pub const DEFAULT_TOLERANCE_PX: f64 = 1.0 / 32.0;

/// Bounds-tile sizes tried.
pub const TILES: [u8; 4] = [1, 2, 4, 8];

/// The four units, widest first: name, has motion terms, has defocus terms.
pub const UNITS: [(&str, bool, bool); 4] = [
    (uvt_core::Full::NAME, true, true),
    (uvt_core::MotionOnly::NAME, true, false),
    (uvt_core::DefocusOnly::NAME, false, true),
    (uvt_core::StaticOnly::NAME, false, false),
];

use uvt_core::Unit as _;

/// The smallest unit accepting classes with (any motion, any defocus).
pub fn unit_for(motion: bool, defocus: bool) -> &'static str {
    UNITS
        .iter()
        .rev()
        .find(|u| (u.1 || !motion) && (u.2 || !defocus))
        .map_or(uvt_core::Full::NAME, |u| u.0)
}

/// (motion, defocus) terms of unit `name`.
pub fn unit_terms(name: &str) -> Option<(bool, bool)> {
    UNITS.iter().find(|u| u.0 == name).map(|u| (u.1, u.2))
}

/// The sample test's multipliers of one unit at one configuration.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct UnitCost {
    /// products
    pub products: u64,
    /// Σ count·a·b
    pub bit_products: u64,
    /// DSP48E1 (25 × 18) estimate
    pub dsp48e1: u64,
    /// ECP5 MULT18X18D estimate
    pub ecp5: u64,
}

/// Fields lerped by step 1 of the bounded test (x, y, w, z, CoC; `bounded.rs`).
const LERP_FIELDS: u32 = 5;

/// The sample-test cost of the unit with the given terms at a bounded `cfg`, from the width
/// table's `sample` rows restricted to the stages the unit has (`core/src/bounded.rs`
/// `vertex`/`eval_class`): `1 lerp` — x, y, w, z lerps when the unit has motion, the CoC lerp
/// only with motion and defocus (4 or 5 of the 5 fields; none without motion: static and
/// defocus-only triangles read the t0 values, the depth's z included); `2 lens` only with
/// defocus; offsets, edges, orientation (its rare path serves w ≤ 0 vertices, which static
/// triangles have too) and depth in every unit. `None` for an exact configuration (its rows are
/// sized for the widest class; a per-unit table is not modelled) or a lerp row whose count is
/// not a multiple of the five fields.
pub fn unit_sample_cost(cfg: &Config, motion: bool, defocus: bool) -> Option<UnitCost> {
    cfg.off()?;
    let t = table(cfg);
    let mut c = UnitCost::default();
    for r in t.rows().filter(|r| r.stage == "sample") {
        for m in r.mul.iter().flatten() {
            let count = if r.signal.starts_with("1 lerp") {
                if m.count % LERP_FIELDS != 0 {
                    return None;
                }
                let fields = match (motion, defocus) {
                    (false, _) => 0,
                    (true, false) => 4,
                    (true, true) => 5,
                };
                m.count / LERP_FIELDS * fields
            } else if r.signal.starts_with("2 lens") {
                if defocus {
                    m.count
                } else {
                    0
                }
            } else {
                m.count
            };
            let n = u64::from(count);
            c.products += n;
            c.bit_products += n * u64::from(m.a) * u64::from(m.b);
            c.dsp48e1 += n * u64::from(dsp48e1(m.a, m.b));
            c.ecp5 += n * u64::from(ecp5(m.a, m.b));
        }
    }
    Some(c)
}

/// The full unit's sample-test cost at any configuration (the whole `sample` stage).
pub fn full_sample_cost(cfg: &Config) -> UnitCost {
    let s = crate::cost::sample_cost(cfg);
    UnitCost {
        products: s.products,
        bit_products: s.bit_products,
        dsp48e1: s.dsp48e1,
        ecp5: s.ecp5,
    }
}

/// One unit of `m4_units.json` (`core/examples/m4_report.sh --units`).
#[derive(Clone, Debug, Deserialize, Serialize)]
pub struct M4Unit {
    /// unit name
    pub unit: String,
    /// flash bytes (.vector_table + .text + .rodata)
    pub flash: u64,
    /// .text bytes
    pub text: u64,
    /// RAM bytes (.data + .bss)
    pub ram: u64,
    /// peak stack bytes
    pub stack: u64,
    /// Cortex-M4F instructions per setup
    pub setup: f64,
    /// per tile bounds
    pub bounds: f64,
    /// per sample test
    pub sample: f64,
    /// image checksum
    pub checksum: String,
}

/// The full unit's instructions on the primitives a narrower unit accepts
/// (`full_on_unit_prims` of `m4_units.json`): the same work as that unit's row.
#[derive(Clone, Debug, Deserialize, Serialize)]
pub struct M4FullOn {
    /// the narrower unit whose primitives the full unit rendered
    pub prims: String,
    /// instructions per setup
    pub setup: f64,
    /// per tile bounds
    pub bounds: f64,
    /// per sample test
    pub sample: f64,
}

#[derive(Deserialize)]
struct M4Units {
    units: Vec<M4Unit>,
    #[serde(default)]
    full_on_unit_prims: Vec<M4FullOn>,
}

/// `m4_units.json`: the units and the full unit's instructions on each narrower unit's
/// primitives.
pub type M4Data = (Vec<M4Unit>, Vec<M4FullOn>);

/// Read `m4_units.json` if it exists (`None` if absent); a file that exists but does not parse
/// is an error naming it.
pub fn load_m4_units(path: &Path) -> Result<Option<M4Data>> {
    if !path.exists() {
        return Ok(None);
    }
    let text =
        std::fs::read_to_string(path).with_context(|| format!("cannot read {}", path.display()))?;
    let f: M4Units = serde_json::from_str(&text).with_context(|| {
        format!(
            "{}: not an m4_report.sh --units JSON ({{\"units\":[{{\"unit\":…,\"flash\":…}}]}})",
            path.display()
        )
    })?;
    Ok(Some((f.units, f.full_on_unit_prims)))
}

/// Markdown: the unit-variant table (`uvt units`) at configuration `cfg`, with the RTL unit
/// variants' synthesized counts (`synth`, the `"units"` of `synth_path`) where they were
/// synthesized at `cfg`.
pub fn units_md(
    cfg: &Config,
    m4: Option<&[M4Unit]>,
    m4_path: &Path,
    synth: Option<&[crate::synth::Unit]>,
    synth_path: &Path,
) -> String {
    let mut s = format!(
        "Unit variants at `{cfg}`: sample-test multipliers from the width table's `sample` rows restricted to the unit's stages (`uvt cost --config {cfg}`), Cortex-M4F figures from `{}`, synthesized counts of the RTL unit (`vectors/rtl/uvt_bsample.v`, Yosys) from `{}`.\n\n| unit | accepts | flash bytes | RAM bytes (.data+.bss / stack) | M4F insn setup / tile / sample | sample test DSP48E1 estimate | synthesized DSP48E1 / LUT / FF | MULT18X18D estimate | synthesized MULT18X18D / LUT4 / FF | Σ bit-products | products |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
        m4_path.display(),
        synth_path.display()
    );
    for (name, motion, defocus) in UNITS {
        let acc: Vec<&str> = [
            Class::Static,
            Class::Motion,
            Class::Defocus,
            Class::MotionDefocus,
        ]
        .into_iter()
        .filter(|c| (motion || !c.motion()) && (defocus || !c.defocus()))
        .map(Class::name)
        .collect();
        let row = m4.and_then(|m| m.iter().find(|u| u.unit == name));
        let nm = "not measured".to_string();
        let (flash, ram, insn) = match row {
            Some(u) => (
                u.flash.to_string(),
                format!("{} / {}", u.ram, u.stack),
                format!("{:.0} / {:.0} / {:.0}", u.setup, u.bounds, u.sample),
            ),
            None => (nm.clone(), nm.clone(), nm),
        };
        let c = unit_sample_cost(cfg, motion, defocus);
        let f = |g: fn(&UnitCost) -> u64| {
            c.as_ref()
                .map_or("not modelled (exact)".into(), |c| g(c).to_string())
        };
        let syn = synth.and_then(|v| {
            v.iter()
                .find(|u| u.unit == name && u.name == cfg.to_string())
        });
        let (sx, se) = syn.map_or(("not synthesized".into(), "not synthesized".into()), |u| {
            (
                format!("{} / {} / {}", u.xilinx.dsp48e1, u.xilinx.lut, u.xilinx.ff),
                format!("{} / {} / {}", u.ecp5.mult18x18d, u.ecp5.lut4, u.ecp5.ff),
            )
        });
        s += &format!(
            "| {name} | {} | {flash} | {ram} | {insn} | {} | {sx} | {} | {se} | {} | {} |\n",
            acc.join(", "),
            f(|c| c.dsp48e1),
            f(|c| c.ecp5),
            f(|c| c.bit_products),
            f(|c| c.products)
        );
    }
    if !synth.is_some_and(|v| v.iter().any(|u| u.name == cfg.to_string())) {
        s += &format!(
            "\nsynthesized: none at `{cfg}` in `{}` (`bash vectors/rtl/synth.sh` synthesizes every unit at the default configuration).\n",
            synth_path.display()
        );
    }
    if m4.is_none() {
        s += &format!(
            "\nflash, RAM and M4F instructions: not measured (`{}` absent; `bash core/examples/m4_report.sh --units` writes it).\n",
            m4_path.display()
        );
    }
    s
}

/// d_q of one primitive (px; module docs) with rounding `r` and datapath perturbation `eps`
/// (raw clip units x, y, w); `None` when some vertex can reach the camera plane.
pub fn prim_dq(tri: &SceneTri, vp: (u16, u16), r: &Rounding, eps: [f64; 3]) -> Option<f64> {
    let half = [f64::from(vp.0) / 2.0, f64::from(vp.1) / 2.0];
    let mut d: f64 = 0.0;
    for k in 0..3 {
        let (a, b) = (tri.t0[k], tri.t1[k]);
        let cmax = a[4].abs().max(b[4].abs());
        let lens = r.pos + r.tuv * (b[4] - a[4]).abs() + r.tuv * cmax;
        let dw = r.pos + r.tuv * (b[3] - a[3]).abs() + eps[2];
        let wmin = a[3].min(b[3]);
        // NaN-safe: anything but "in front by more than Δw" has no bound.
        if wmin.partial_cmp(&dw) != Some(std::cmp::Ordering::Greater) {
            return None;
        }
        for (axis, e) in [(0usize, eps[0]), (1, eps[1])] {
            let dx = r.pos + r.tuv * (b[axis] - a[axis]).abs() + lens + e;
            let rho =
                ((a[axis].abs() + a[4].abs()) / a[3]).max((b[axis].abs() + b[4].abs()) / b[3]);
            let px = (dx + rho * dw) / (wmin - dw) * half[axis];
            d = d.max(px);
        }
    }
    Some(d + r.sub)
}

/// The datapath perturbation of `cfg` for a primitive of `class` in `vp`, clip units.
pub fn eps_clip(cfg: &Config, class: Class, vp: Viewport) -> [f64; 3] {
    let e = uvt_core::Eps::of(cfg.off(), class, vp);
    let raw = |v: i32| f64::from(v) / 65536.0;
    [raw(e.x()[0]), raw(e.x()[1]), raw(e.w())]
}

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
/// (`crate::planar`, last) for the scene's primitives and their classes, and the primitives
/// without a screen-space bound in some configuration (the same for every configuration up to
/// ε).
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
    for name in SWEEP {
        let Some(cfg) = Config::parse(name) else {
            continue;
        };
        let r = Rounding::at(cfg.pos(), cfg.tuv());
        let mut dqs = scene
            .tris
            .iter()
            .zip(classes)
            .map(|(t, c)| prim_dq(t, scene.viewport, &r, eps_clip(&cfg, *c, vp)));
        push(name, &mut dqs, unit_sample_cost(&cfg, unit.0, unit.1));
    }
    // The planar static configuration (`crate::planar`): per-primitive ε for static triangles.
    let mut dqs = scene.tris.iter().zip(classes).map(|(t, c)| {
        let core = t.to_core().ok()?;
        crate::planar::prim_dq(t, &core, *c, scene.viewport, 1.0)
    });
    push(
        crate::planar::NAME,
        &mut dqs,
        crate::planar::unit_cost(unit.0, unit.1),
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
    let exact = fits
        .iter()
        .find(|f| f.config == SWEEP[0])
        .ok_or_else(|| anyhow!("the sweep has no exact configuration"))?;
    if exact.meets {
        return Ok(exact);
    }
    bail!(
        "tolerance {tol} px is unreachable for this scene: even {} (16 fraction bits, exact test) has a documented error distance of {:.6} px (primitive {}); the smallest tolerance it meets is {:.6} px",
        exact.config,
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
