//! Precision as a parameter: the sweep stays conservative at every precision, its errors shrink
//! toward the default, and the stress scenes hold (no panic, no violation, differences from f64
//! only where the derived quantization bound of `host/src/compare/bound.rs` allows).

use uvt_core::{Error, Interval, Prec, Precision, Sample, SamplePattern, Triangle, Vertex};
use uvt_host::precision::row::CONFIGS;
use uvt_host::precision::sweep::{stress_row, stress_scenes, sweep, Sweep};
use uvt_host::scene::builtin::{Bench, Blur};

#[test]
fn sweep_is_conservative_and_converges_to_the_default() {
    let configs = vec![CONFIGS[0], CONFIGS[1], CONFIGS[6]];
    let rows = sweep(&Sweep {
        configs: configs.clone(),
        scenes: vec![Bench::Game, Bench::Dense],
        rows: vec![Blur::Both],
        tiles: vec![1, 2, 4, 8],
        shrink: 4,
    })
    .unwrap();
    assert_eq!(rows.len(), configs.len() * 4);
    for r in &rows {
        assert_eq!(r.violations, 0, "{r:?}");
        assert_eq!(r.beyond_bound, 0, "{r:?}");
        assert!(r.compared > 10_000, "{r:?}");
    }
    let rate = |r: &uvt_host::precision::row::PrecRow| r.differ as f64 / r.compared as f64;
    let at = |cfg: &str, tile: u8| {
        rows.iter()
            .find(|r| r.config == cfg && r.tile == tile)
            .unwrap()
    };
    for tile in [1u8, 2, 4, 8] {
        let (narrow, def) = (at(CONFIGS[6], tile), at(CONFIGS[0], tile));
        // The bounded default candidate: every differing decision of geometry at w ≥ 1 lies
        // within its documented d_q of an edge.
        let bounded = at(CONFIGS[1], tile);
        assert_eq!(bounded.beyond_dq, 0, "{bounded:?}");
        assert!(
            bounded.max_differ_px > 0.0 && bounded.d_q[0] > 0.0,
            "{bounded:?}"
        );
        assert!(
            rate(narrow) > rate(def),
            "narrow precision should err more: {} vs {}",
            rate(narrow),
            rate(def)
        );
        assert!(narrow.depth_lsb[0] > def.depth_lsb[0]);
        // At the default precision the core's STE is within 0.5% of the reference's.
        assert!(
            (def.ste[0] - def.ste[1]).abs() <= 0.005 * def.ste[1],
            "{def:?}"
        );
        // Narrow bounds can only be looser (outward rounding): STE not above the reference's.
        assert!(narrow.ste[0] <= narrow.ste[1] * 1.001, "{narrow:?}");
    }
}

#[test]
fn stress_scenes_hold() {
    let dir = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../host/stress");
    let scenes = stress_scenes(&dir).unwrap();
    assert_eq!(scenes.len(), 13, "the stress suite lists 13 cases");
    for s in &scenes {
        let r = stress_row(s).unwrap();
        assert_eq!(r.violations, 0, "{}: {r:?}", s.name);
        assert_eq!(r.beyond_bound, 0, "{}: {r:?}", s.name);
        assert_eq!(r.lost, 0, "{}: covered but not written: {r:?}", s.name);
    }
}

#[test]
fn precision_grids_are_enforced() {
    type P = Prec<8, 10, 4>;
    assert_eq!((P::POS_FRAC, P::TUV_FRAC, P::BOUND_FRAC), (8, 10, 4));
    let on = Vertex::from_bits([1 << 8, 0, 0, 1 << 16, 0]);
    let off = Vertex::from_bits([(1 << 8) + 1, 0, 0, 1 << 16, 0]);
    assert!(Triangle::new_with::<P>([on; 3], [on; 3]).is_ok());
    assert!(matches!(
        Triangle::new_with::<P>([on, off, on], [on; 3]),
        Err(Error::CoordOffGrid {
            vertex: 1,
            time: 0,
            frac: 8,
            ..
        })
    ));
    assert!(
        Triangle::new([on, off, on], [on; 3]).is_ok(),
        "the default accepts every I16F16 value"
    );
    let mut s = [Sample::default(); 1];
    s[0] = uvt_tests::sample_raw(0, 0, 0, 0, 64);
    assert!(SamplePattern::new_with::<P>(1, 1, &s).is_ok());
    s[0] = uvt_tests::sample_raw(0, 0, 0, 0, 65);
    assert_eq!(
        SamplePattern::new_with::<P>(1, 1, &s).unwrap_err(),
        Error::SampleOffGrid { index: 0, frac: 10 }
    );
    // Outward rounding to a coarser grid: 4 fraction bits = steps of 4096 raw.
    let i = Interval::new(5000, 5001).unwrap().round_out(4);
    assert_eq!(i, Interval::new(4096, 8192).unwrap());
    assert_eq!(
        Interval::new(-65536, 65535).unwrap().round_out(4),
        Interval::new(-65536, 65536).unwrap()
    );
    assert_eq!(
        Interval::new(7, 9).unwrap().round_out(16),
        Interval::new(7, 9).unwrap()
    );
}
