//! The planar static configuration (`planar-16-16-16-20`) in the host tools: its documented
//! per-primitive d_q bounds every measured decision difference against the f64 reference (and a
//! deliberately halved d_q is caught on a guard-band scene); `uvt fit` never picks it where its
//! d_q exceeds the tolerance, and picks it for a static-only scene it fits when it is the
//! cheapest; the degenerate count is reported.

use std::path::Path;

use uvt_core::config::registry::PLANAR;
use uvt_host::config::dq::Tolerance;
use uvt_host::fit::select::{config_fits, DEFAULT_TOLERANCE_PX};
use uvt_host::precision::measure::planar_decisions;
use uvt_host::scene::file::Scene;

/// A static scene from its triangles' t0 vertices `[x, y, z, w]`.
fn scene(name: &str, vp: (u16, u16), spp: u16, tris: &[[[f64; 4]; 3]]) -> Scene {
    let t: Vec<String> = tris
        .iter()
        .map(|v| {
            let p: Vec<String> = v
                .iter()
                .map(|q| format!("[{},{},{},{}]", q[0], q[1], q[2], q[3]))
                .collect();
            format!("{{\"t0\":[{}]}}", p.join(","))
        })
        .collect();
    let text = format!(
        r#"{{"format":"uvt-scene","version":1,"viewport":[{},{}],"spp":{spp},"tile":1,"samples":{{"pattern":"sobol","seed":5}},"triangles":[{}]}}"#,
        vp.0,
        vp.1,
        t.join(",")
    );
    Scene::parse(&text, name, Path::new(".")).expect("test scene parses")
}

/// `uvt fit` on a loaded scene with no M4 figures (the confirmation renders; only the M4 rows of
/// the report are "not measured").
fn fit_without_m4(s: &Scene, tol: Option<f64>) -> uvt_host::fit::report::Fit {
    let none = Path::new("/nonexistent");
    uvt_host::fit::report::fit(s, tol, None, None, none, None, none).unwrap()
}

/// Guard band: two vertices at x = ±8000 clip units, w = 1 (NDC ±8000), y = 0.37 — their
/// largest component rounds with a step of 2^14 raw (¼ clip unit), so y = 0.37 moves by 0.12
/// (0.12 NDC, ≈ 3.8 px on 64 px): the horizontal edge across the screen moves that far.
fn guard_band() -> Scene {
    scene(
        "guard band",
        (64, 64),
        16,
        &[
            [
                [-8000.0, 0.37, 0.5, 1.0],
                [8000.0, 0.37, 0.5, 1.0],
                [0.0, -0.9, 0.5, 1.0],
            ],
            [
                [8000.0, -0.61, 0.3, 1.0],
                [-8000.0, -0.61, 0.3, 1.0],
                [0.1, 0.95, 0.3, 1.0],
            ],
        ],
    )
}

/// In view, w from 1 to 3: planar d_q well below 1/32 px on 32 px.
fn benign() -> Scene {
    scene(
        "benign",
        (32, 32),
        8,
        &[
            [
                [-0.8, -0.7, 0.5, 1.0],
                [0.9, -0.6, 0.6, 1.5],
                [0.1, 2.1, 0.9, 3.0],
            ],
            [
                [0.9, -0.6, 0.6, 1.5],
                [-0.8, -0.7, 0.5, 1.0],
                [-0.3, -2.5, 0.5, 2.7],
            ],
        ],
    )
}

#[test]
fn planar_dq_bounds_every_difference_and_a_halved_dq_is_caught() {
    let s = guard_band();
    let r = planar_decisions(&s, 1.0).unwrap();
    let dq = r.d_q[0];
    println!(
        "guard band: {} of {} decisions differ, max {:.4} px; planar d_q {dq:.4} px; beyond d_q {}; beyond bound {} (ratio {:.3}); violations {}; degenerate {}",
        r.differ, r.compared, r.max_differ_px, r.beyond_dq, r.beyond_bound, r.max_ratio, r.violations, r.degenerate
    );
    assert!(r.differ > 0, "the guard-band scene exercises no difference");
    assert_eq!(
        r.beyond_dq, 0,
        "a difference beyond the documented d_q: {r:?}"
    );
    assert_eq!(r.beyond_bound, 0, "{r:?}");
    assert_eq!(r.violations, 0, "{r:?}");
    assert!(
        r.max_differ_px > 1.0,
        "the rounding moved the edge by less than 1 px: {r:?}"
    );
    let h = planar_decisions(&s, 0.5).unwrap();
    assert!(
        h.beyond_dq > 0,
        "a halved d_q ({:.4} px) must be exceeded by the measured {:.4} px: {h:?}",
        dq / 2.0,
        h.max_differ_px
    );
    println!("halved d_q: {} differences beyond it", h.beyond_dq);
}

#[test]
fn fit_never_picks_planar_beyond_the_tolerance() {
    let s = guard_band();
    let planar = |tol: f64| {
        let fits = config_fits(&s, (false, false), &Tolerance::new(tol, None, s.viewport)).unwrap();
        fits.into_iter()
            .find(|f| f.config == PLANAR.to_string())
            .expect("fit lists the planar configuration")
    };
    // The exact configuration reaches ≈ 1.96 px here (w's input rounding times the guard-band
    // ratio 8000), the planar one ≈ 3.84 px (the vertex rounding): at 2.5 px only the former.
    let tol = 2.5;
    let pl = planar(tol);
    assert!(
        pl.d_q_px.unwrap() > tol && !pl.meets,
        "planar d_q {:?} px on the guard-band scene",
        pl.d_q_px
    );
    let f = fit_without_m4(&s, Some(tol));
    assert_eq!(f.unit, "static-only");
    assert_ne!(f.config, PLANAR.to_string(), "{}", f.config);
    assert!(f.ok, "{:?}", f.confirm);
    println!("guard band at {tol} px: fit picks {}", f.config);
    // Above the planar d_q it meets and, the cheapest static-only sample test, is picked.
    let tol = pl.d_q_px.unwrap() * 1.01;
    assert!(planar(tol).meets);
    let f = fit_without_m4(&s, Some(tol));
    assert_eq!(f.config, PLANAR.to_string());
    assert!(f.ok, "{:?}", f.confirm);
    println!("guard band at {tol:.4} px: fit picks {}", f.config);
}

#[test]
fn fit_picks_planar_for_a_benign_static_scene_when_cheapest() {
    let s = benign();
    let fits = config_fits(
        &s,
        (false, false),
        &Tolerance::new(DEFAULT_TOLERANCE_PX, None, s.viewport),
    )
    .unwrap();
    for f in &fits {
        println!(
            "{}: d_q {:?} px, DSP48E1 {:?}, Σ bit-products {:?}",
            f.config,
            f.d_q_px,
            f.unit_cost.as_ref().map(|c| c.dsp48e1),
            f.unit_cost.as_ref().map(|c| c.bit_products)
        );
    }
    let pl = fits
        .iter()
        .find(|f| f.config == PLANAR.to_string())
        .unwrap();
    assert!(pl.meets, "planar d_q {:?} px", pl.d_q_px);
    let key = |f: &uvt_host::fit::select::ConfigFit| {
        f.unit_cost
            .as_ref()
            .map(|c| (c.dsp48e1, c.bit_products))
            .unwrap_or((u64::MAX, u64::MAX))
    };
    let cheapest = fits
        .iter()
        .filter(|f| f.meets && f.unit_cost.is_some())
        .min_by_key(|f| key(f))
        .unwrap();
    let f = fit_without_m4(&s, None);
    assert_eq!(f.config, cheapest.config);
    assert!(f.ok, "{:?}", f.confirm);
    println!(
        "benign static scene: fit picks {} (planar {} of {} static triangles degenerate)",
        f.config, f.planar_degenerate.0, f.planar_degenerate.1
    );
}
