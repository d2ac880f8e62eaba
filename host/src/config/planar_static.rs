//! The planar static configuration ([`PLANAR`] of the registry, `planar-16-16-16-20`:
//! `uvt_core::PlanarPrecision`, `core/src/sample/planar.rs`) in the host tools: its documented error distance d_q per
//! primitive, its sample-test multipliers per unit, and the triangles its vertex rounding makes
//! degenerate. `uvt precision`, `uvt fit` (and its confirmation) and `uvt bench-ste --precision`
//! use these.
//!
//! **d_q per primitive** (px; [`prim_dq`]). A static triangle is decided exactly on its rounded
//! vertices `2^s_k·P'_k`, which lie within the setup's per-triangle ε (the exact rounding
//! residual per component, maximum over the vertices, ≤ 2^(s_k−1) ≤ 2^-16 of the vertex's
//! largest component) of the grid triangle (`planar.rs`, "Conservative epsilon"). That is the
//! vertex perturbation of [`super::dq::prim_dq`] with `eps = ε` on top of the 16-bit input
//! rounding: vertex k moves on screen by at most `(Δx_k + ρ_k·Δw_k)/(w_k − Δw_k)·W/2` px with
//! `ρ_k = |x_k|/w_k` its guard-band ratio and `w_k` its w (nearest w: static), likewise in y; d_q
//! is the largest over vertices and axes plus the 1/256 px sub-pixel floor. A far off-screen
//! vertex at small w (ρ up to 2^13, ε up to ¼ clip unit) therefore gets a large d_q — `uvt fit`
//! then does not pick the configuration at a small tolerance. A vertex with `w_k ≤ Δw_k` (or a d_q beyond the viewport's
//! diagonal) is stated in clip space ([`statement`]; `super::dq`, "The error statement of every
//! primitive"). Moving and defocused classes run the
//! bounded test of `bounded-16-16-16-20`: their d_q is that configuration's.
//!
//! **Sample-test multipliers** ([`planar_sample_cost`]), from the implementation in
//! `planar.rs`: the direction `d` (as the exact test's width table counts it: 3 products of the
//! 21-bit `|2xs − 256W| ≤ 2^19` by the 13-bit viewport extent), the edge values `E_k = n_k·d`
//! (9 products; `|n| ≤ 2·(2^15 − 1)² < 2^31`: 32 bits signed; `|d| ≤ 2^30`: 32 bits signed) and
//! the depth `Σ G_i·d_i` (3 products; `G ∈ [−2^31, 2^31)`: 32 bits; d 32 bits). The static-only
//! unit at this configuration has only these; every other unit also carries the bounded
//! datapath for its moving / defocused classes, so its cost is the bounded unit's plus these
//! (no sharing of multipliers between the two datapaths is modelled).

use uvt_core::config::registry::{Config, PLANAR};
use uvt_core::config::unit::Full;
use uvt_core::{Class, Outcome, PlanarPrecision, Setup, Viewport};

use crate::config::rounding::{eps_of, Rounding};
use crate::scene::file::Scene;
use crate::scene::tri::SceneTri;

use super::dq::eps_clip;
use super::multipliers::{dsp48e1, ecp5};
use super::units::{unit_sample_cost, UnitCost};

/// The bounded configuration its moving and defocused classes run.
pub const BASE: Config = PLANAR.bounded_base();

/// The planar sample test's multipliers `(a bits, b bits, count)` (module docs).
pub const PRODUCTS: [(u32, u32, u32); 3] = [(21, 13, 3), (32, 32, 9), (32, 32, 3)];

/// The planar sample test's cost ([`PRODUCTS`]).
pub fn planar_sample_cost() -> UnitCost {
    let mut c = UnitCost::default();
    for (a, b, n) in PRODUCTS {
        let n = u64::from(n);
        c.products += n;
        c.bit_products += n * u64::from(a) * u64::from(b);
        c.dsp48e1 += n * u64::from(dsp48e1(a, b));
        c.ecp5 += n * u64::from(ecp5(a, b));
    }
    c
}

/// The sample-test cost of the unit with the given terms at this configuration (module docs).
pub fn unit_cost(motion: bool, defocus: bool) -> Option<UnitCost> {
    let p = planar_sample_cost();
    if !motion && !defocus {
        return Some(p);
    }
    let b = unit_sample_cost(&BASE, motion, defocus)?;
    Some(UnitCost {
        products: b.products + p.products,
        bit_products: b.bit_products + p.bit_products,
        dsp48e1: b.dsp48e1 + p.dsp48e1,
        ecp5: b.ecp5 + p.ecp5,
    })
}

/// The datapath perturbation (clip units x, y, w) of triangle `core` of class `class` at this
/// configuration: the exact rounding residual for a static triangle, the bounded base's ε
/// otherwise.
pub fn eps(core: &uvt_core::Triangle, class: Class, vp: Viewport) -> [f64; 3] {
    if class == Class::Static {
        eps_of(&Setup::unculled::<PlanarPrecision>(core, vp))
    } else {
        eps_clip(&BASE, class, vp)
    }
}

/// d_q (px) of one primitive at this configuration, `None` without a screen-space bound
/// (module docs). `scale` multiplies the perturbation terms (1 for the documented d_q; tests
/// use 1/2 to show a measured difference exceeds a halved d_q).
pub fn prim_dq(
    tri: &SceneTri,
    core: &uvt_core::Triangle,
    class: Class,
    vp: (u16, u16),
    scale: f64,
) -> Option<f64> {
    let cvp = Viewport::new(vp.0, vp.1).ok()?;
    let r = Rounding::at(16, 16);
    let d = super::dq::prim_dq(tri, vp, &r, eps(core, class, cvp))?;
    Some(d * scale)
}

/// Static triangles the planar setup culls as degenerate (`det P' = 0` after the vertex
/// rounding) that the default configuration does not cull as degenerate: `(count, static
/// triangles)`. Such a triangle covers no sample at this configuration (a sliver; a watertight
/// mesh stays watertight, `planar.rs`).
pub fn degenerate(scene: &Scene) -> (u64, u64) {
    let vp = scene.core_viewport();
    let (mut n, mut stat) = (0u64, 0u64);
    for t in &scene.tris {
        let Ok(c) = t.to_core() else { continue };
        if c.class() != Class::Static {
            continue;
        }
        stat += 1;
        let cull = |o: Outcome| matches!(o, Outcome::Culled(uvt_core::Cull::Degenerate));
        let mut ops = uvt_core::Ops::default();
        let pl = cull(uvt_core::setup::<PlanarPrecision, Full>(&c, vp, &mut ops));
        let def = cull(uvt_core::setup::<uvt_core::DefaultPrecision, Full>(
            &c, vp, &mut ops,
        ));
        n += u64::from(pl && !def);
    }
    (n, stat)
}
