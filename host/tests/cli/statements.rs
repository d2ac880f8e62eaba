//! The error statement of every primitive (`uvt_host::config::dq`): every primitive of every
//! configuration has a finite backward error; where the pixel form applies it is at most the
//! viewport's diagonal; a camera-plane crosser is stated in clip space; `uvt fit`'s
//! confirmation fails a configuration whose clip-space statement misses the tolerance
//! (`crossing_camera_plane.json` at `bounded-8-8-8-28`); `domain_edge.json`'s once astronomical
//! d_q is now a finite clip-space statement.

use std::path::Path;

use uvt_core::config::registry::{self, DEFAULT};
use uvt_host::config::dq::pixel_limit;
use uvt_host::config::dq::Tolerance;
use uvt_host::fit::confirm::confirm;
use uvt_host::fit::select::{classes, config_fits, DEFAULT_TOLERANCE_PX};
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
        let cls = classes(&s).unwrap();
        let tol = Tolerance::new(DEFAULT_TOLERANCE_PX, None, s.viewport);
        for f in config_fits(&s, &cls, (true, true), &tol) {
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
                        assert!(d > 0.0 && d <= pixel_limit(s.viewport), "{name}: {d}");
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
    let cls = classes(&s).unwrap();
    let tol = Tolerance::new(DEFAULT_TOLERANCE_PX, None, s.viewport);
    let fits = config_fits(&s, &cls, (true, true), &tol);
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
fn domain_edge_is_stated_finitely() {
    let s = stress("domain_edge.json");
    let cls = classes(&s).unwrap();
    let tol = Tolerance::new(DEFAULT_TOLERANCE_PX, None, s.viewport);
    let fits = config_fits(&s, &cls, (true, true), &tol);
    let exact = fits
        .iter()
        .find(|f| f.config == registry::EXACT.to_string())
        .unwrap();
    // Primitive 0 (every w = 8191.99) in pixels; primitive 1 (a vertex at w = 2^-16, x = 8191.99:
    // its projection moves by ≈ 8·10^11 px) in clip space, δ dominated by the u rounding times
    // the CoC of ≈ 4096 clip units.
    let (p0, p1) = (exact.statements[0].unwrap(), exact.statements[1].unwrap());
    assert!(p0.px.unwrap() < 0.035, "{p0:?}");
    assert!(p1.px.is_none(), "{p1:?}");
    assert!(p1.clip > 0.04 && p1.clip < 0.05, "{p1:?}");
}
