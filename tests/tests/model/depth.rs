//! Depth format and the framebuffer: a sample the sample test covers is either written or
//! rejected by the depth test against an earlier triangle's value, never silently lost
//! (issue 9 item 1). Before the fix, z/w ≥ 128 and hits at w → 0+ both returned the raw value
//! the buffer clears to, and the strict depth test dropped them.

use embedded_graphics_core::pixelcolor::RgbColor;
use uvt_core::{Laine2011, Renderer, Rgb888, SamplePattern};
use uvt_tests::*;

const CLEAR: Rgb888 = Rgb888::new(0, 0, 0);
const RED: Rgb888 = Rgb888::new(255, 0, 0);

/// A static triangle at z/w = 200 (z = 200, w = 1): every covered sample is drawn.
#[test]
fn far_saturated_depth_is_written() {
    let t = tri(
        [
            [-0.5, -0.5, 200.0, 1.0, 0.0],
            [0.5, -0.5, 200.0, 1.0, 0.0],
            [0.0, 0.5, 200.0, 1.0, 0.0],
        ],
        [
            [-0.5, -0.5, 200.0, 1.0, 0.0],
            [0.5, -0.5, 200.0, 1.0, 0.0],
            [0.0, 0.5, 200.0, 1.0, 0.0],
        ],
    );
    let vp = uvt_core::Viewport::new(8, 8).unwrap();
    let mut rng = Rng(seed());
    let samples = random_samples(&mut rng, 2, 4);
    let pat = SamplePattern::new(2, 4, &samples).unwrap();
    let prims = [uvt_core::Prim { tri: t, color: RED }];
    let mut r = Renderer::<Laine2011, 1>::new(Laine2011, vp, &prims).unwrap();
    let (mut covered_px, mut drawn_px, mut covered) = (0u32, 0u32, 0u32);
    let mut bad = Vec::new();
    r.render_with::<4, 4, 4>(&pat, 1, CLEAR, |x, y, c, ps| {
        covered += ps.covered;
        if ps.covered > 0 {
            covered_px += 1;
            if c != CLEAR {
                drawn_px += 1;
            } else {
                bad.push((x, y, ps));
            }
        }
    })
    .unwrap();
    assert!(covered > 0, "seed {}: the triangle covers samples", seed());
    let st = r.stats;
    assert_eq!(
        st.samples_written,
        st.samples_covered,
        "seed {}: {st:?}",
        seed()
    );
    assert_eq!(st.samples_occluded, 0, "seed {}: {st:?}", seed());
    assert_eq!(
        drawn_px,
        covered_px,
        "seed {}: {covered} covered samples in {covered_px} pixels, {drawn_px} drawn; undrawn: {bad:?}",
        seed()
    );
}

/// The stress scene whose triangle crosses the camera plane: no covered sample that reaches an
/// empty slot is lost (independent count in `uvt_host::precision::measure::lost_samples`).
#[test]
fn crossing_camera_plane_loses_nothing() {
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../host/stress/crossing_camera_plane.json");
    let scene = uvt_host::scene::file::Scene::load(&path).unwrap();
    let (reached, lost) = uvt_host::precision::measure::lost_samples(&scene).unwrap();
    assert!(reached > 0, "the scene covers samples");
    assert_eq!(
        lost, 0,
        "{lost} of {reached} covered samples reaching an empty slot were lost"
    );
}

/// Overlapping triangles at different depths, one at the far saturation: covered = written +
/// occluded, with the occluded counted only against earlier writes, per frame and per pixel.
#[test]
fn covered_is_written_plus_occluded() {
    let mk = |z: f64, dx: f64| {
        let v = [
            [-0.6 + dx, -0.6, z, 1.0, 0.0],
            [0.6 + dx, -0.6, z, 1.0, 0.0],
            [dx, 0.6, z, 1.0, 0.0],
        ];
        tri(v, v)
    };
    let prims = [
        uvt_core::Prim {
            tri: mk(0.5, 0.0),
            color: RED,
        },
        uvt_core::Prim {
            tri: mk(0.25, 0.2),
            color: Rgb888::new(0, 255, 0),
        },
        uvt_core::Prim {
            tri: mk(300.0, -0.2),
            color: Rgb888::new(0, 0, 255),
        },
        uvt_core::Prim {
            tri: mk(0.5, 0.0),
            color: Rgb888::new(9, 9, 9),
        },
    ];
    let vp = uvt_core::Viewport::new(16, 16).unwrap();
    let mut rng = Rng(seed());
    let samples = random_samples(&mut rng, 2, 4);
    let pat = SamplePattern::new(2, 4, &samples).unwrap();
    let mut r = Renderer::<Laine2011, 4>::new(Laine2011, vp, &prims).unwrap();
    let (mut pw, mut pc) = (0u64, 0u64);
    r.render_with::<8, 8, 4>(&pat, 2, CLEAR, |_, _, _, ps| {
        pw += u64::from(ps.written);
        pc += u64::from(ps.covered);
    })
    .unwrap();
    let st = r.stats;
    assert!(
        st.samples_occluded > 0 && st.samples_written > 0,
        "seed {}: {st:?}",
        seed()
    );
    assert_eq!(
        st.samples_covered,
        st.samples_written + st.samples_occluded,
        "seed {}: {st:?}",
        seed()
    );
    assert_eq!(
        (pw, pc),
        (st.samples_written, st.samples_covered),
        "seed {}",
        seed()
    );
    // The last triangle repeats the first one's depth exactly: first writer keeps ties, so it is
    // occluded wherever the first triangle is, i.e. everywhere it covers.
    let tie = [
        prims[0],
        uvt_core::Prim {
            tri: prims[0].tri,
            color: Rgb888::new(0, 0, 255),
        },
    ];
    let mut r = Renderer::<Laine2011, 2>::new(Laine2011, vp, &tie).unwrap();
    let mut blue = 0;
    r.render_with::<8, 8, 4>(&pat, 2, CLEAR, |_, _, c, _| blue += u32::from(c.b()))
        .unwrap();
    let st = r.stats;
    assert_eq!(blue, 0, "seed {}: {st:?}", seed());
    assert_eq!(
        st.samples_written,
        st.samples_occluded,
        "seed {}: {st:?}",
        seed()
    );
}
