//! The error statement of every primitive (`uvt_host::config::dq`): every primitive of every
//! configuration has a finite backward error; a camera-plane crosser is stated in clip space;
//! `uvt fit`'s confirmation fails a configuration whose clip-space statement misses the
//! tolerance (`crossing_camera_plane.json` at `bounded-8-8-8-28`) or says nothing about the
//! primitive (δ above 1/16 of its extent, whatever the clip tolerance); a primitive fully in
//! front is held to its pixel bound however large (`domain_edge.json`, and a triangle near the
//! camera that narrow configurations lose entirely: issue 50).

use std::path::Path;

use uvt_core::config::registry::{self, DEFAULT};
use uvt_host::config::dq::Tolerance;
use uvt_host::fit::confirm::confirm;
use uvt_host::fit::select::{config_fits, DEFAULT_TOLERANCE_PX};
use uvt_host::scene::file::Scene;

fn stress(name: &str) -> Scene {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("stress")
        .join(name);
    Scene::load(&p).unwrap_or_else(|e| panic!("{name}: {e:#}"))
}

#[test]
fn every_primitive_of_every_stress_scene_has_a_finite_statement() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("stress");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".json"))
        .collect();
    names.sort();
    let (mut px, mut clip) = (0, 0);
    for name in &names {
        let s = stress(name);
        let tol = Tolerance::new(DEFAULT_TOLERANCE_PX, None, s.viewport);
        for f in config_fits(&s, (true, true), &tol).unwrap() {
            assert_eq!(f.statements.len(), s.tris.len());
            for (i, st) in f.statements.iter().enumerate() {
                let st = st.unwrap_or_else(|| panic!("{name} {}: primitive {i}", f.config));
                assert!(
                    st.clip.is_finite() && st.clip > 0.0,
                    "{name} {} primitive {i}: δ {}",
                    f.config,
                    st.clip
                );
                match st.px {
                    Some(d) => {
                        assert!(d > 0.0 && d.is_finite(), "{name}: {d}");
                        px += 1;
                    }
                    None => clip += 1,
                }
            }
        }
    }
    println!("statements: {px} in pixels, {clip} in clip space only");
    assert!(
        px > 0 && clip > 0,
        "both forms are exercised: {px} / {clip}"
    );
}

#[test]
fn a_camera_plane_crosser_is_stated_in_clip_space_and_a_narrow_configuration_fails() {
    let s = stress("crossing_camera_plane.json");
    let tol = Tolerance::new(DEFAULT_TOLERANCE_PX, None, s.viewport);
    let fits = config_fits(&s, (true, true), &tol).unwrap();
    let narrow = fits
        .iter()
        .find(|f| f.config == "bounded-8-8-8-28")
        .unwrap();
    assert!(!narrow.clip_primitives.is_empty(), "{narrow:?}");
    assert!(
        narrow.clip.unwrap() > tol.clip && !narrow.meets,
        "bounded-8-8-8-28: δ {:?} against {}",
        narrow.clip,
        tol.clip
    );
    // Confirmed anyway, its differing decisions are not within the tolerance: it fails.
    let cfg = registry::find("bounded-8-8-8-28").unwrap();
    let c = confirm(&s, cfg, "laine2011", 1, "full", &tol, &narrow.statements)
        .unwrap()
        .unwrap();
    println!(
        "bounded-8-8-8-28: {} differing, {} stated in clip space, {} beyond the clip tolerance, largest distance {:.2} px",
        c.differ, c.differ_clip, c.beyond_tolerance_clip, c.max_distance_clip_px
    );
    assert!(c.differ_clip > 0, "{c:?}");
    assert!(c.beyond_tolerance_clip > 0, "{c:?}");
    assert!(!c.ok(), "{c:?}");
    assert_eq!(c.beyond_bound, 0, "its own statement holds: {c:?}");
    // The default configuration meets it, and its confirmation holds.
    let def = fits
        .iter()
        .find(|f| f.config == DEFAULT.to_string())
        .unwrap();
    assert!(def.meets, "{def:?}");
    let c = confirm(&s, DEFAULT, "laine2011", 1, "full", &tol, &def.statements)
        .unwrap()
        .unwrap();
    assert_eq!(
        c.beyond_tolerance_clip + c.beyond_bound + c.violations,
        0,
        "{c:?}"
    );
}

#[test]
fn domain_edge_is_held_to_its_pixel_bound() {
    let s = stress("domain_edge.json");
    let tol = Tolerance::new(DEFAULT_TOLERANCE_PX, None, s.viewport);
    let fits = config_fits(&s, (true, true), &tol).unwrap();
    let exact = fits
        .iter()
        .find(|f| f.config == registry::EXACT.to_string())
        .unwrap();
    // Primitive 0 (every w = 8191.99) needs 0.033 px; primitive 1 (a vertex at w = 2^-16,
    // x = 8191.99: d_q 1.17·10^12 px) is fully in front, so it is held to
    // that pixel bound (before issue 50 a d_q beyond the viewport's diagonal moved it to the
    // clip statement, δ ≈ 0.044, which a clip tolerance of 0.05 met).
    let (p0, p1) = (exact.statements[0].unwrap(), exact.statements[1].unwrap());
    assert!(p0.px.unwrap() < 0.035, "{p0:?}");
    let d1 = p1.px.unwrap_or_else(|| panic!("stated in pixels: {p1:?}"));
    assert!(d1 > 1e11 && d1 < 1e13, "{p1:?}");
    assert!(p1.clip > 0.04 && p1.clip < 0.05, "{p1:?}");
    // At every configuration with 16 position fraction bits it stays in pixels and meets no
    // tolerance below its d_q; on a coarser grid its vertex at w = 2^-16 lies within the
    // rounding of w of the camera plane, so only there is it stated in clip space.
    let big = Tolerance::new(1e6, Some(1.0), s.viewport);
    for f in &fits {
        let st = f.statements[1].unwrap();
        let pos = registry::find(&f.config).unwrap().pos();
        assert_eq!(st.px.is_some(), pos == 16, "{}: {st:?}", f.config);
        if pos == 16 {
            assert!(!st.meets(&big), "{}: {st:?}", f.config);
        }
    }
}

/// The scene of issue 50: one triangle fully in front of the camera but close to it (every
/// vertex at w = 0.00166, about 0.003 clip units across), per-vertex CoC, 96 × 54, 4 spp.
pub(crate) const NEAR_CAMERA: &str = r#"{"format":"uvt-scene","version":1,"viewport":[96,54],
    "spp":4,"tile":2,"samples":{"pattern":"sobol","seed":5},
    "triangles":[{"t0":[[-0.0013,-0.0011,0.0008,0.00166,0.00002],
                        [0.0016,-0.0007,0.0008,0.00166,0.00006],
                        [0.0001,0.0013,0.0008,0.00166,0.0001]]}]}"#;

fn near_camera() -> Scene {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("near_camera.json");
    std::fs::write(&p, NEAR_CAMERA).unwrap();
    Scene::load(&p).unwrap()
}

#[test]
fn a_triangle_near_the_camera_is_held_to_its_pixel_bound_and_never_lost() {
    let s = near_camera();
    let tol = Tolerance::new(1.0, None, s.viewport);
    let fits = config_fits(&s, (true, true), &tol).unwrap();
    let mut lost = 0;
    for f in &fits {
        let st = f.statements[0].unwrap();
        let cfg = registry::find(&f.config).unwrap();
        // Fully in front of the camera: stated in pixels at every configuration (a camera-plane
        // crosser only is stated in clip space), and it meets 1 px by its d_q alone.
        if f.config != "bounded-8-8-8-28" {
            let d = st.px.unwrap_or_else(|| panic!("{}: {st:?}", f.config));
            assert_eq!(f.meets, d <= 1.0, "{}: {f:?}", f.config);
        }
        // Confirmed at 1 px whatever it states: a configuration that loses the triangle (or
        // draws it beyond its tolerance) fails, naming primitive 0; one that meets passes.
        let c = confirm(&s, cfg, "laine2011", 1, "full", &tol, &f.statements)
            .unwrap()
            .unwrap();
        println!(
            "{}: meets {}, covered {:?}, lost/gained {:?}, failing {:?}",
            f.config, f.meets, c.covered, c.lost_gained, c.failing
        );
        assert!(c.covered[1] > 5000, "{}: {c:?}", f.config);
        if f.meets {
            assert!(c.ok(), "{}: {c:?}", f.config);
            assert!(c.covered[0] > 0 && c.lost_gained == [0, 0], "{}", f.config);
        } else {
            assert!(!c.ok(), "{}: {c:?}", f.config);
            assert_eq!(c.failing.len(), 1, "{}: {c:?}", f.config);
            let p = &c.failing[0];
            assert_eq!(p.primitive, 0, "{}: {p:?}", f.config);
            assert_eq!(
                (p.core_covered, p.reference_covered),
                (c.covered[0], c.covered[1])
            );
        }
        if c.covered[0] == 0 {
            lost += 1;
            assert!(!f.meets && c.lost_gained == [1, 0], "{}: {c:?}", f.config);
        }
    }
    // The narrow configurations do lose it (what issue 50 found passing at bounded-12-12-12-24).
    assert!(lost >= 2, "{lost}");
    let twelve = fits
        .iter()
        .find(|f| f.config == "bounded-12-12-12-24")
        .unwrap();
    assert!(
        !twelve.meets && twelve.d_q_px.unwrap() > 100.0,
        "{twelve:?}"
    );
}

#[test]
fn a_clip_statement_larger_than_the_primitive_meets_no_tolerance() {
    // crossing_camera_plane.json's crosser at the narrow configurations: δ within a clip
    // tolerance of 10 clip units, but above 1/16 of the primitive's own extent.
    let s = stress("crossing_camera_plane.json");
    let tol = Tolerance::new(1000.0, Some(10.0), s.viewport);
    let fits = config_fits(&s, (true, true), &tol).unwrap();
    let mut said_nothing = 0;
    for f in &fits {
        for st in f.statements.iter().flatten().filter(|st| st.px.is_none()) {
            assert!(
                st.extent > 0.0 && st.clip <= tol.clip,
                "{}: {st:?}",
                f.config
            );
            assert_eq!(st.informative(), st.clip <= st.extent / 16.0);
            assert_eq!(st.meets(&tol), st.informative(), "{}: {st:?}", f.config);
        }
        if f.clip_share.is_some_and(|x| x > 1.0 / 16.0) {
            said_nothing += 1;
            assert!(!f.meets, "{f:?}");
        }
    }
    assert!(said_nothing >= 2, "{said_nothing}");
    // Confirmed anyway, every differing decision of such a primitive fails, and it is named.
    let f = fits
        .iter()
        .find(|f| f.config == "bounded-8-8-8-28")
        .unwrap();
    let c = confirm(
        &s,
        registry::find(&f.config).unwrap(),
        "laine2011",
        1,
        "full",
        &tol,
        &f.statements,
    )
    .unwrap()
    .unwrap();
    assert!(c.differ_clip_uninformative > 0, "{c:?}");
    assert_eq!(c.beyond_tolerance_clip, c.differ_clip, "{c:?}");
    assert!(!c.ok() && !c.failing.is_empty(), "{c:?}");
    assert!(
        c.failing
            .iter()
            .all(|p| p.stated == "clip" && p.why.iter().any(|w| w.contains("says nothing"))),
        "{:?}",
        c.failing
    );
}
