//! The camera's focus range (`host/src/scene/mesh.rs`, Wu et al. 2014): CoC 0 on the range,
//! ends included, a thin lens focused at the nearer end outside it, the plain thin lens at range
//! 0; triangles at the boundary depths classed static, just outside defocused; the example scene
//! renders with an in-focus object; bad ranges are refused with the key named.

use std::path::Path;

use glam::{DMat4, DVec3};
use uvt_core::Class;
use uvt_host::scene::file::Scene;
use uvt_host::scene::mesh::{to_clip, Camera, Instance, Lens, Mesh, Pose};

fn camera(aperture: f64, focus: f64, focus_range: f64) -> Camera {
    let pose = Pose {
        eye: DVec3::ZERO,
        target: DVec3::NEG_Z,
        up: DVec3::Y,
    };
    Camera {
        fov_y: 60.0,
        near: 0.1,
        far: 100.0,
        aperture,
        focus,
        focus_range,
        t0: pose,
        t1: pose,
    }
}

/// A small static triangle facing the camera at view distance `d` (w = d exactly).
fn class_at(cam: &Camera, d: f64) -> (Class, [f64; 3]) {
    let mesh = Mesh {
        pos: vec![
            DVec3::new(-0.3, -0.3, -d),
            DVec3::new(0.3, -0.3, -d),
            DVec3::new(0.0, 0.3, -d),
        ],
        tris: vec![[0, 1, 2]],
    };
    let inst = Instance {
        mesh,
        m0: DMat4::IDENTITY,
        m1: DMat4::IDENTITY,
        color: [9, 9, 9],
    };
    let tris = to_clip(cam, &[inst], (64, 64));
    assert_eq!(tris.len(), 1);
    assert!(tris[0].t0.iter().all(|v| v[3] == d), "w = d exactly");
    let coc = tris[0].t0.map(|v| v[4]);
    let core = Scene::builtin("focus", (64, 64), tris)
        .core_tris()
        .expect("in the domain");
    (core[0].class(), coc)
}

#[test]
fn coc_is_zero_on_the_range_and_grows_outside() {
    let lens = Lens {
        k: 0.1,
        near: 4.0,
        far: 6.0,
    };
    for w in [4.0, 4.5, 5.0, 6.0] {
        assert_eq!(lens.coc(w), 0.0, "w = {w}");
    }
    assert!(lens.coc(3.9) < 0.0 && lens.coc(6.1) > 0.0);
    // Continuous at both ends, and a thin lens focused at the nearer end outside.
    assert!(lens.coc(4.0 - 1e-9).abs() < 1e-9 && lens.coc(6.0 + 1e-9).abs() < 1e-9);
    assert!((lens.coc(2.0) - 0.1 * (2.0 / 4.0 - 1.0)).abs() < 1e-15);
    assert!((lens.coc(12.0) - 0.1 * (12.0 / 6.0 - 1.0)).abs() < 1e-15);
    // A pinhole has no CoC anywhere.
    let pin = Lens { k: 0.0, ..lens };
    assert_eq!(pin.coc(1.0), 0.0);
}

#[test]
fn range_zero_is_the_plain_thin_lens() {
    let cam = camera(0.05, 5.0, 0.0);
    let lens = cam.lens(1.0);
    let (a, b) = (lens.k / 5.0, -lens.k);
    for w in [0.5, 1.0, 3.0, 7.0, 40.0] {
        assert_eq!(lens.coc(w), a * w + b, "w = {w}");
    }
}

#[test]
fn boundary_depths_are_in_focus_and_just_outside_is_not() {
    let cam = camera(0.1, 5.0, 2.0);
    for d in [4.0, 5.0, 6.0] {
        let (class, coc) = class_at(&cam, d);
        assert_eq!(class, Class::Static, "d = {d}: CoC {coc:?}");
    }
    for d in [3.99, 6.01] {
        let (class, coc) = class_at(&cam, d);
        assert_eq!(class, Class::Defocus, "d = {d}: CoC {coc:?}");
    }
    // The same depths without a range: only the focus distance is sharp.
    let plain = camera(0.1, 5.0, 0.0);
    assert_eq!(class_at(&plain, 5.0).0, Class::Static);
    assert_eq!(class_at(&plain, 4.0).0, Class::Defocus);
    assert_eq!(class_at(&plain, 6.0).0, Class::Defocus);
}

#[test]
fn example_scene_has_an_in_focus_object() {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/focus_range.json");
    let s = Scene::load(&p).expect("example scene loads");
    let core = s.core_tris().expect("in the domain");
    let mut by = [0usize; 4];
    for t in &core {
        by[t.class().index()] += 1;
    }
    // The orange sphere (12 segments: 120 triangles) lies in the range at both ends: its
    // triangles move with the camera but have CoC 0 (motion class); the rest is blurred.
    assert!(by[Class::Motion.index()] >= 120, "{by:?}");
    assert!(by[Class::MotionDefocus.index()] > 0, "{by:?}");
}

#[test]
fn bad_ranges_are_refused_naming_the_key() {
    let scene = |cam: &str| {
        format!(
            r#"{{"format":"uvt-scene","version":1,"viewport":[8,8],"camera":{{{cam},"t0":{{}}}},"meshes":[]}}"#
        )
    };
    for (cam, want) in [
        (
            r#""aperture":0.1,"focus":2,"focus_range":-1"#,
            "camera.focus_range",
        ),
        (
            r#""aperture":0.1,"focus":2,"focus_range":4"#,
            "camera.focus_range",
        ),
        (
            r#""aperture":0.1,"focus":2,"focus_rang":1"#,
            "did you mean \"focus_range\"",
        ),
    ] {
        let e = match Scene::parse(&scene(cam), "t", Path::new(".")) {
            Ok(_) => panic!("accepted {cam}"),
            Err(e) => format!("{e:#}"),
        };
        assert!(e.contains(want), "{cam}: {e}");
    }
}
