//! Measured sample test efficiency: a small triangle moving across the screen. The bounding-box
//! scan tests every sample of the swept footprint (S·(X+1) per pixel row, Laine 2011 §2); the
//! dual-space t bounds test only the samples whose t can reach each pixel, so their STE must stay
//! far above it. The swept-hull and lens-slab strategies must beat Laine 2011 where they should.

use uvt_core::*;
use uvt_tests::*;

#[test]
fn moving_small_triangle_ste_far_above_bbox_scan() {
    let vp = Viewport::new(64, 16).unwrap();
    let mut rng = Rng(seed());
    let samples = random_samples(&mut rng, 4, 16);
    let pat = SamplePattern::new(4, 16, &samples).unwrap();
    // ~8 px² triangle at w = 2, moving 40 px (1.25 NDC) to the right.
    let w = 2.0;
    let p = |x: f64, y: f64| [x * w, y * w, 0.5 * w, w, 0.0];
    let t0 = [p(-0.75, -0.25), p(-0.63, -0.25), p(-0.69, 0.25)];
    let t1 = t0.map(|v| [v[0] + 1.25 * w, v[1], v[2], v[3], v[4]]);
    let prims = [Prim {
        tri: tri(t0, t1),
        color: Rgb888::new(255, 255, 255),
    }];
    let laine = render_stats(Laine2011, &prims, vp, &pat, 1);
    let bbox = render_stats(BboxScan, &prims, vp, &pat, 1);
    // Both must agree on what is covered (bounds never change the image).
    assert_eq!(
        laine.samples_covered, bbox.samples_covered,
        "covered differs: bounds culled a covered sample"
    );
    assert!(
        laine.samples_covered > 50,
        "too few covered samples to measure: {laine:?}"
    );
    let (sl, sb) = (laine.ste_ppm(), bbox.ste_ppm());
    println!(
        "STE laine {:.2}% bbox {:.2}% ratio {:.1}",
        sl as f64 / 1e4,
        sb as f64 / 1e4,
        sl as f64 / sb as f64
    );
    assert!(
        sl >= 5 * sb,
        "STE laine {sl} ppm is not far above bbox {sb} ppm"
    );
    assert_eq!(laine.by_class, [0, 1, 0, 0]);
}

/// Swept-hull culling on a static triangle is the hierarchical tile-vs-triangle test: a right
/// triangle covers half its bounding box, so Laine 2011 (which tests the whole footprint of a
/// static triangle) measures about 50% STE, and the hull, which skips 1×1 tiles outside the
/// triangle, must be far above it; both cover exactly the same samples.
#[test]
fn static_triangle_hull_culls_pixels_outside() {
    let vp = Viewport::new(64, 64).unwrap();
    let mut rng = Rng(seed());
    let samples = random_samples(&mut rng, 4, 16);
    let pat = SamplePattern::new(4, 16, &samples).unwrap();
    let p = |x: f64, y: f64| [x, y, 0.5, 1.0, 0.0];
    let t = [p(-0.9, -0.9), p(0.9, -0.9), p(-0.9, 0.9)];
    let prims = [Prim {
        tri: tri(t, t),
        color: Rgb888::new(255, 255, 255),
    }];
    let laine = render_stats(Laine2011, &prims, vp, &pat, 1);
    let hull = render_stats(uvt_core::bounds::registry::hull(), &prims, vp, &pat, 1);
    assert_eq!(
        laine.samples_covered, hull.samples_covered,
        "hull culled coverage"
    );
    let (sl, sh) = (laine.ste_ppm(), hull.ste_ppm());
    println!("static: STE laine {sl} ppm, hull {sh} ppm");
    assert!(
        sh * 10 >= sl * 17,
        "hull STE {sh} ppm not ≥ 1.7× laine {sl} ppm"
    );
    assert_eq!(hull.ops.predicate, 0, "hull has no per-sample predicate");
}

/// Motion + defocus: the lens-slab time bounds and the bilinear surfaces follow the (u, t) /
/// (v, t) coupling and must test clearly fewer samples than Laine 2011's box while covering the
/// same samples; the per-sample predicate is counted.
#[test]
fn moving_defocused_triangle_lens_slabs_beat_laine() {
    let vp = Viewport::new(64, 32).unwrap();
    let mut rng = Rng(seed() ^ 0x51ab);
    let samples = random_samples(&mut rng, 4, 16);
    let pat = SamplePattern::new(4, 16, &samples).unwrap();
    // ~50 px² triangle at w = 2 moving 24 px right with a CoC of ~3 px radius.
    let w = 2.0;
    let p = |x: f64, y: f64| [x * w, y * w, 0.5 * w, w, 0.2 * w];
    let t0 = [p(-0.6, -0.3), p(-0.3, -0.3), p(-0.45, 0.3)];
    let t1 = t0.map(|v| [v[0] + 0.75 * w, v[1], v[2], v[3], v[4]]);
    let prims = [Prim {
        tri: tri(t0, t1),
        color: Rgb888::new(255, 255, 255),
    }];
    let laine = render_stats(Laine2011, &prims, vp, &pat, 1);
    let lens = render_stats(
        uvt_core::bounds::lens_time::LensTime::<4>,
        &prims,
        vp,
        &pat,
        1,
    );
    let best = render_stats(uvt_core::bounds::registry::best(), &prims, vp, &pat, 1);
    assert_eq!(laine.by_class, [0, 0, 0, 1]);
    for s in [&lens, &best] {
        assert_eq!(s.samples_covered, laine.samples_covered, "coverage differs");
        assert!(s.ops.predicate > 0, "predicate ops not counted: {s:?}");
    }
    assert!(laine.samples_covered > 200, "too few covered: {laine:?}");
    let (sl, sn, sb) = (laine.ste_ppm(), lens.ste_ppm(), best.ste_ppm());
    println!("both: STE laine {sl} ppm, lens-t {sn} ppm, best {sb} ppm");
    assert!(
        sn * 10 >= sl * 12,
        "lens-t {sn} ppm not ≥ 1.2× laine {sl} ppm"
    );
    assert!(sb >= sn, "best {sb} ppm below lens-t {sn} ppm");
    let hyper = render_stats(uvt_core::bounds::hyper::Hyper, &prims, vp, &pat, 1);
    assert_eq!(
        hyper.samples_covered, laine.samples_covered,
        "coverage differs"
    );
    let sh = hyper.ste_ppm();
    println!("both: STE hyper {sh} ppm");
    assert!(
        sh * 10 >= sl * 12,
        "hyper {sh} ppm not ≥ 1.2× laine {sl} ppm"
    );
}
