//! Measured sample test efficiency: a small triangle moving across the screen. The bounding-box
//! scan tests every sample of the swept footprint (S·(X+1) per pixel row, Laine 2011 §2); the
//! dual-space t bounds test only the samples whose t can reach each pixel, so their STE must stay
//! far above it.

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
