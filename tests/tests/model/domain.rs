//! The declared domain: inside it nothing panics or overflows (tests run with overflow checks);
//! outside it every constructor returns an error naming the culprit.

use proptest::prelude::*;
use uvt_core::bounds::strategy::BoundsStrategy;
use uvt_core::config::precision::DefaultPrecision;
use uvt_core::config::unit::Full;
use uvt_core::setup::Outcome;
use uvt_core::*;
use uvt_tests::*;

const LIM: i32 = 1 << 29;

#[test]
fn coordinate_domain_edges() {
    let ok = Vertex::from_bits([LIM, -LIM, LIM, LIM, -LIM]);
    assert!(Triangle::new([ok; 3], [ok; 3]).is_ok());
    for (field, idx) in [
        (Field::X, 0),
        (Field::Y, 1),
        (Field::Z, 2),
        (Field::W, 3),
        (Field::Coc, 4),
    ] {
        for bad in [LIM + 1, -LIM - 1, i32::MIN, i32::MAX] {
            let mut b = [0; 5];
            b[idx] = bad;
            let e = Triangle::new([ok; 3], [ok, Vertex::from_bits(b), ok]).unwrap_err();
            assert_eq!(
                e,
                Error::CoordOutOfDomain {
                    vertex: 1,
                    time: 1,
                    field,
                    raw: bad
                }
            );
            let msg = e.to_string();
            assert!(
                msg.contains("vertex 1") && msg.contains(&format!("{field}")),
                "{msg}"
            );
        }
    }
}

#[test]
fn viewport_and_pattern_errors() {
    assert_eq!(
        Viewport::new(0, 5),
        Err(Error::Viewport {
            width: 0,
            height: 5
        })
    );
    assert_eq!(
        Viewport::new(2049, 5),
        Err(Error::Viewport {
            width: 2049,
            height: 5
        })
    );
    assert!(Viewport::new(2048, 2048).is_ok());
    let s = Sample::default();
    assert!(matches!(
        SamplePattern::new(2, 4, &[s; 15]),
        Err(Error::PatternShape { len: 15, .. })
    ));
    assert!(matches!(
        SamplePattern::new(0, 4, &[]),
        Err(Error::PatternShape { .. })
    ));
    assert!(matches!(
        SamplePattern::new(1, 65, &[s; 65]),
        Err(Error::PatternShape { .. })
    ));
}

/// `Sample::new` refuses t outside [0, 1] and u, v outside [-1, 1], naming field and raw bits;
/// the ends of the domain are accepted. (Before, `Sample` had public fields and a t = 256
/// reached the sample test's 2^70 products with no error.)
#[test]
fn sample_constructor_checks_each_field() {
    let z = SubPixel::from_bits(0);
    let mk = |u: i32, v: i32, t: i32| {
        Sample::new(
            z,
            z,
            Lens::from_bits(u),
            Lens::from_bits(v),
            Time::from_bits(t),
        )
    };
    for (u, v, t) in [(-65536, -65536, 0), (65536, 65536, 65536), (0, 0, 1)] {
        let s = mk(u, v, t).unwrap();
        assert_eq!(
            (s.u().to_bits(), s.v().to_bits(), s.t().to_bits()),
            (u, v, t)
        );
    }
    let cases = [
        ((0, 0, -1), SampleField::T, -1),
        ((0, 0, 65537), SampleField::T, 65537),
        ((0, 0, 256 << 16), SampleField::T, 256 << 16),
        ((0, 0, i32::MIN), SampleField::T, i32::MIN),
        ((65537, 0, 0), SampleField::U, 65537),
        ((-65537, 0, 0), SampleField::U, -65537),
        ((0, 65537, 0), SampleField::V, 65537),
        ((0, i32::MIN, 0), SampleField::V, i32::MIN),
    ];
    for ((u, v, t), field, raw) in cases {
        let e = mk(u, v, t).unwrap_err();
        assert_eq!(
            e,
            Error::SampleOutOfDomain { field, raw },
            "u={u} v={v} t={t}"
        );
        let msg = e.to_string();
        assert!(msg.contains(&format!("{field} = raw")), "{msg}");
        assert!(msg.contains(&format!("{raw}")), "{msg}");
    }
}

/// `Interval::new` keeps -1 <= lo <= hi <= 1 (raw); the accessors return what was given.
#[test]
fn interval_constructor_checks_its_invariant() {
    let i = Interval::new(-65536, 65536).unwrap();
    assert_eq!((i.lo(), i.hi()), (-65536, 65536));
    assert_eq!(Interval::new(5, 5).unwrap().lo(), 5);
    for (lo, hi) in [(1, 0), (-65537, 0), (0, 65537), (i32::MIN, i32::MAX)] {
        assert_eq!(
            Interval::new(lo, hi),
            Err(Error::Interval { lo, hi }),
            "{lo} {hi}"
        );
    }
}

#[test]
fn renderer_errors() {
    let vp = Viewport::new(8, 8).unwrap();
    let v = [
        [-0.5, -0.5, 0.0, 1.0, 0.0],
        [0.5, -0.5, 0.0, 1.0, 0.0],
        [0.0, 0.5, 0.0, 1.0, 0.0],
    ];
    let p = Prim {
        tri: tri(v, v),
        color: Rgb888::new(1, 2, 3),
    };
    assert_eq!(
        Renderer::<Laine2011, 1>::new(Laine2011, vp, &[p, p]).err(),
        Some(Error::TooManyTriangles { capacity: 1 })
    );
    let mut r = Renderer::<Laine2011, 2>::new(Laine2011, vp, &[p, p]).unwrap();
    let samples = [Sample::default(); 4];
    let pat = SamplePattern::new(1, 4, &samples).unwrap();
    let mut fb = TileBuffer::<8, 8, 2>::new(Rgb888::new(0, 0, 0));
    assert_eq!(
        r.render_tile(0, 0, &pat, 1, Rgb888::new(0, 0, 0), &mut fb),
        Err(Error::SppMismatch {
            tile: 2,
            pattern: 4
        })
    );
    let mut fb = TileBuffer::<8, 8, 4>::new(Rgb888::new(0, 0, 0));
    assert_eq!(
        r.render_tile(0, 0, &pat, 3, Rgb888::new(0, 0, 0), &mut fb),
        Err(Error::BoundsTile { size: 3 })
    );
    assert_eq!(
        r.render_tile(8, 0, &pat, 1, Rgb888::new(0, 0, 0), &mut fb),
        Err(Error::PixelOutOfRange)
    );
    assert_eq!(
        r.render_tile(0, 0, &pat, 8, Rgb888::new(0, 0, 0), &mut fb),
        Ok(())
    );
}

/// `Raster::load` replaces the triangles and counters; on an error nothing half-loaded stays
/// (no triangle, so the tile is the clear color), and a renderer loaded in place equals `new`'s.
#[test]
fn renderer_load_in_place() {
    let vp = Viewport::new(8, 8).unwrap();
    let v = [
        [-0.5, -0.5, 0.0, 1.0, 0.0],
        [0.5, -0.5, 0.0, 1.0, 0.0],
        [0.0, 0.5, 0.0, 1.0, 0.0],
    ];
    let p = Prim {
        tri: tri(v, v),
        color: Rgb888::new(1, 2, 3),
    };
    let samples = [Sample::default(); 4];
    let pat = SamplePattern::new(1, 4, &samples).unwrap();
    let clear = Rgb888::new(9, 9, 9);
    let image = |r: &mut Renderer<Laine2011, 1>| {
        let mut fb = TileBuffer::<8, 8, 4>::new(clear);
        r.render_tile(0, 0, &pat, 1, clear, &mut fb).unwrap();
        (0..8u16)
            .flat_map(|y| (0..8u16).map(move |x| (x, y)))
            .map(|(x, y)| fb.resolve(x.into(), y.into()))
            .collect::<Vec<_>>()
    };
    let mut fresh = Renderer::<Laine2011, 1>::new(Laine2011, vp, &[p]).unwrap();
    let mut r = Renderer::<Laine2011, 1>::empty(Laine2011, vp);
    assert_eq!(r.entries().count(), 0);
    assert!(image(&mut r).iter().all(|c| *c == clear));
    r.load(&[p]).unwrap();
    assert_eq!(r.stats, fresh.stats);
    assert_eq!(image(&mut r), image(&mut fresh));
    assert!(image(&mut r).contains(&p.color));
    assert_eq!(
        r.load(&[p, p]),
        Err(Error::TooManyTriangles { capacity: 1 })
    );
    assert_eq!(r.entries().count(), 0);
    assert!(image(&mut r).iter().all(|c| *c == clear));
    r.load(&[p]).unwrap();
    assert_eq!(r.entries().count(), 1);
    assert_eq!(r.stats.triangles, 1);
}

/// Raw values biased toward the domain's edges and the singular spots (0, ±1 LSB).
fn raw() -> impl Strategy<Value = i32> {
    prop_oneof![
        Just(LIM),
        Just(-LIM),
        Just(LIM - 1),
        Just(-LIM + 1),
        Just(0),
        Just(1),
        Just(-1),
        -LIM..=LIM,
        -65536i32..=65536,
    ]
}

fn vertex() -> impl Strategy<Value = Vertex> {
    proptest::array::uniform5(raw()).prop_map(Vertex::from_bits)
}

fn sample() -> impl Strategy<Value = Sample> {
    (
        any::<u8>(),
        any::<u8>(),
        -65536i32..=65536,
        -65536i32..=65536,
        0i32..=65536,
    )
        .prop_map(|(sx, sy, u, v, t)| sample_raw(sx, sy, u, v, t))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(256, 20000), failure_persistence: None, ..ProptestConfig::default() })]

    /// Any in-domain triangle on the largest viewport: setup, every tile size's bounds at the
    /// footprint's corners and centre, and sample tests anywhere, without panic or overflow.
    #[test]
    fn no_panic_in_domain(v0 in proptest::array::uniform3(vertex()), v1 in proptest::array::uniform3(vertex()),
                          smps in proptest::collection::vec(sample(), 8), px in 0u16..2048, py in 0u16..2048) {
        let t = Triangle::new(v0, v1).unwrap();
        let vp = Viewport::new(2048, 2048).unwrap();
        let mut ops = Ops::default();
        if let Outcome::Visible(s) = setup::<DefaultPrecision, Full>(&t, vp, &mut ops) {
            let co = Laine2011.prepare::<Full>(&s, &mut ops);
            let fp = s.footprint();
            for bt in [1u16, 2, 4, 8] {
                for (x, y) in [(fp.x0, fp.y0), (fp.x1 - 1, fp.y1 - 1), ((fp.x0 + fp.x1) / 2, (fp.y0 + fp.y1) / 2)] {
                    let cell = PixelRect { x0: x - x % bt, y0: y - y % bt, x1: x - x % bt + bt, y1: y - y % bt + bt }.intersect(&fp);
                    let _ = Laine2011.tile::<Full>(&s, &co, cell, &mut ops);
                }
            }
        }
        let full = Setup::unculled::<DefaultPrecision>(&t, vp);
        for s in &smps {
            let _ = uvt_core::sample::test::<DefaultPrecision, Full>(&full, ScreenPos::of(px, py, s), s, &mut ops);
            let _ = uvt_core::sample::test::<DefaultPrecision, Full>(&full, ScreenPos::of(2047, 2047, s), s, &mut ops);
            let _ = uvt_core::sample::test::<DefaultPrecision, Full>(&full, ScreenPos::of(0, 0, s), s, &mut ops);
        }
    }

    /// Any raw i32 at all: the constructor either accepts (inside the domain) or names the field.
    #[test]
    fn errors_not_panics_outside_domain(b in proptest::array::uniform5(any::<i32>())) {
        let v = Vertex::from_bits(b);
        let inside = b.iter().all(|x| x.unsigned_abs() <= LIM as u32);
        match Triangle::new([v; 3], [v; 3]) {
            Ok(_) => prop_assert!(inside),
            Err(Error::CoordOutOfDomain { raw, .. }) => prop_assert!(!inside && raw.unsigned_abs() > LIM as u32),
            Err(e) => prop_assert!(false, "unexpected {e:?}"),
        }
    }
}
