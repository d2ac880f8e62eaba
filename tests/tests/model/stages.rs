//! Hand-computed cases per pipeline stage, compared bit for bit. Each expected value is derived
//! in the comment above it; a failure prints inputs, expected and observed as decimal and hex.
//! The stages are those of the exact configuration (`Exact`); the bounded test has its own hand
//! cases in `bounded.rs`.

use uvt_core::bounds::strategy::BoundsStrategy;
use uvt_core::config::formats::{DEPTH_EMPTY, DEPTH_FAR, DEPTH_NEAR};
use uvt_core::config::unit::Full;
use uvt_core::setup::boxes::AxisBoxes;
use uvt_core::setup::{Cull, Outcome};
use uvt_core::*;
use uvt_tests::*;

#[track_caller]
fn same(what: &str, t: &Triangle, expected: i128, observed: i128) {
    assert!(
        expected == observed,
        "{what}: expected {expected} ({expected:#x}), observed {observed} ({observed:#x})\ninputs:\n{}",
        dump(t)
    );
}

fn visible(t: &Triangle, vp: Viewport) -> Setup {
    match setup::<Exact, Full>(t, vp, &mut Ops::default()) {
        Outcome::Visible(s) => s,
        o => panic!("expected visible, got {o:?}\n{}", dump(t)),
    }
}

fn stat(p: [[f64; 5]; 3]) -> Triangle {
    tri(p, p)
}

const ONE: i128 = 65536;

/// NDC (−½,−½), (½,−½), (0,½) at w = 1 on 16×16: pixel x = (x+1)·8 ∈ {4, 12, 8}, rows
/// (1−y)·8 ∈ {12, 12, 4}; boxes [4, 12] px on both axes, footprint [4, 13) (floor(max)+1).
#[test]
fn setup_static_boxes_and_footprint() {
    let vp = Viewport::new(16, 16).unwrap();
    let t = stat([
        [-0.5, -0.5, 0.25, 1.0, 0.0],
        [0.5, -0.5, 0.25, 1.0, 0.0],
        [0.0, 0.5, 0.25, 1.0, 0.0],
    ]);
    let s = visible(&t, vp);
    assert_eq!(s.class(), Class::Static);
    let b = AxisBoxes {
        lo: Some([4 << 16; 2]),
        hi: Some([12 << 16; 2]),
    };
    assert_eq!(s.axes(), [b, b], "\n{}", dump(&t));
    assert_eq!(
        s.footprint(),
        PixelRect {
            x0: 4,
            y0: 4,
            x1: 13,
            y1: 13
        }
    );
    assert_eq!(s.span(), Interval::UNIT);
}

/// (x, w) = (0, 1), (1, 1), (1, −1): the hull meets w = 0 only at x ∈ [½, 1] (right of the
/// camera), so the right side is unbounded and the left is the front minimum (0+1)·8 = 8 px.
/// In y, the points (−y, w) = (0, 1), (−½, 1), (0, −1) have a segment through the camera point,
/// so both row sides are unbounded. Footprint: columns [8, 16), rows [0, 16).
#[test]
fn setup_separating_line_behind_camera() {
    let vp = Viewport::new(16, 16).unwrap();
    let t = stat([
        [0.0, 0.0, 0.0, 1.0, 0.0],
        [1.0, 0.5, 0.0, 1.0, 0.0],
        [1.0, 0.0, 0.0, -1.0, 0.0],
    ]);
    let s = visible(&t, vp);
    assert_eq!(
        s.axes()[0],
        AxisBoxes {
            lo: Some([8 << 16; 2]),
            hi: None
        },
        "\n{}",
        dump(&t)
    );
    assert_eq!(s.axes()[1], AxisBoxes { lo: None, hi: None });
    assert_eq!(
        s.footprint(),
        PixelRect {
            x0: 8,
            y0: 0,
            x1: 16,
            y1: 16
        }
    );
}

/// Plane w − x ≥ 0: raw max(w − x) is 65536 + 6554 = 72090 at t = 0 (x = −0.1 rounds to −6554)
/// and 65536 − 190054 = −124518 at t = 1 (x = 2.9). Chord ≥ 0 for t ≤ 72090 / 196608 =
/// 24030 / 65536 exactly, so the span is [0, 24030].
#[test]
fn setup_frustum_time_span() {
    let vp = Viewport::new(16, 16).unwrap();
    let t = tri(
        [
            [-0.1, -0.1, 0.0, 1.0, 0.0],
            [0.1, -0.1, 0.0, 1.0, 0.0],
            [0.0, 0.1, 0.0, 1.0, 0.0],
        ],
        [
            [2.9, -0.1, 0.0, 1.0, 0.0],
            [3.1, -0.1, 0.0, 1.0, 0.0],
            [3.0, 0.1, 0.0, 1.0, 0.0],
        ],
    );
    let s = visible(&t, vp);
    assert_eq!(s.class(), Class::Motion);
    same("span.lo", &t, 0, s.span().lo() as i128);
    same("span.hi", &t, 24030, s.span().hi() as i128);
}

#[test]
fn setup_classify_and_cull() {
    let vp = Viewport::new(16, 16).unwrap();
    let base = [
        [-0.5, -0.5, 0.0, 1.0, 0.0],
        [0.5, -0.5, 0.0, 1.0, 0.0],
        [0.0, 0.5, 0.0, 1.0, 0.0],
    ];
    let mut z_moves = base;
    z_moves[0][2] = 0.5;
    let mut defocus = base;
    defocus.iter_mut().for_each(|v| v[4] = 0.1);
    let mut coc_changes = defocus;
    coc_changes[1][4] = 0.2;
    let mut ops = Ops::default();
    let class = |t: &Triangle| t.class();
    assert_eq!(class(&stat(base)), Class::Static);
    assert_eq!(
        class(&tri(base, z_moves)),
        Class::Motion,
        "z motion changes depth over t"
    );
    assert_eq!(class(&stat(defocus)), Class::Defocus);
    assert_eq!(
        class(&tri(defocus, coc_changes)),
        Class::MotionDefocus,
        "a changing CoC is motion"
    );
    // collinear at every t → degenerate
    let line = [
        [-0.5, 0.0, 0.0, 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0, 0.0],
        [0.5, 0.0, 0.0, 1.0, 0.0],
    ];
    assert_eq!(
        setup::<Exact, Full>(&stat(line), vp, &mut ops),
        Outcome::Culled(Cull::Degenerate)
    );
    // zero area at t = 0 only → visible
    assert!(matches!(
        setup::<Exact, Full>(&tri(line, base), vp, &mut ops),
        Outcome::Visible(_)
    ));
    // wholly right of the frustum for the whole shutter → outside
    let right = base.map(|v| [v[0] + 3.0, v[1], v[2], v[3], v[4]]);
    assert_eq!(
        setup::<Exact, Full>(&tri(right, right), vp, &mut ops),
        Outcome::Culled(Cull::Outside)
    );
    // all behind the camera → outside
    let behind = base.map(|v| [v[0], v[1], v[2], -1.0, v[4]]);
    assert_eq!(
        setup::<Exact, Full>(&stat(behind), vp, &mut ops),
        Outcome::Culled(Cull::Outside)
    );
}

/// Static triangle, CoC 0.25 everywhere, w = 1, NDC x ∈ {−⅛, ⅛, 0} → pixels {7, 9, 8}, lens u
/// moves them by 2u px: boxes [5, 7] at u = −1 and [9, 11] at u = +1. Tile column [10, 11):
/// the max side 7 + 4s ≥ 10 gives s ≥ ¾, u ≥ ½ → u ∈ [32768, 65536]. Rows: y ∈ {−⅛, −⅛, ⅛} →
/// rows {9, 9, 7}; v moves them by −2v: [9, 11] at v = −1, [5, 7] at v = +1. Tile row [8, 9):
/// 11 − 4s ≥ 8 gives s ≤ ¾, v ≤ ½ → v ∈ [−65536, 32768]. No motion: t = [0, 1].
#[test]
fn bounds_lens_intervals() {
    let vp = Viewport::new(16, 16).unwrap();
    let t = stat([
        [-0.125, -0.125, 0.0, 1.0, 0.25],
        [0.125, -0.125, 0.0, 1.0, 0.25],
        [0.0, 0.125, 0.0, 1.0, 0.25],
    ]);
    let s = visible(&t, vp);
    assert_eq!(s.class(), Class::Defocus);
    let mut ops = Ops::default();
    let co = Laine2011.prepare::<Full>(&s, &mut ops);
    let b = Laine2011
        .tile::<Full>(
            &s,
            &co,
            PixelRect {
                x0: 10,
                y0: 8,
                x1: 11,
                y1: 9,
            },
            &mut ops,
        )
        .expect("non-empty");
    same("u.lo", &t, 32768, b.u.lo() as i128);
    same("u.hi", &t, ONE, b.u.hi() as i128);
    same("v.lo", &t, -ONE, b.v.lo() as i128);
    same("v.hi", &t, 32768, b.v.hi() as i128);
    assert_eq!(b.t, Interval::UNIT);
    // A column the box never reaches at any lens point: [14, 15) needs 7 + 4s ≥ 14 → empty.
    assert_eq!(
        Laine2011.tile::<Full>(
            &s,
            &co,
            PixelRect {
                x0: 14,
                y0: 8,
                x1: 15,
                y1: 9
            },
            &mut ops
        ),
        None
    );
}

/// Motion along x at w = 1: pixels {2, 3, 2} at t = 0 to {12, 13, 12} at t = 1. In dual space
/// δ = 2(p − ξ). Tile column [8, 9]: δmin ≤ 0 needs −14 + 20t ≤ 0 (t ≤ 0.7 → ceil 45875.2 =
/// 45876); δmax ≥ 0 needs −10 + 20t ≥ 0 (t ≥ ½ = 32768). The y axis does not move: full.
#[test]
fn bounds_time_interval_dual_space() {
    let vp = Viewport::new(16, 16).unwrap();
    let t = tri(
        [
            [-0.75, -0.125, 0.0, 1.0, 0.0],
            [-0.625, -0.125, 0.0, 1.0, 0.0],
            [-0.75, 0.125, 0.0, 1.0, 0.0],
        ],
        [
            [0.5, -0.125, 0.0, 1.0, 0.0],
            [0.625, -0.125, 0.0, 1.0, 0.0],
            [0.5, 0.125, 0.0, 1.0, 0.0],
        ],
    );
    let s = visible(&t, vp);
    assert_eq!(
        s.footprint(),
        PixelRect {
            x0: 2,
            y0: 7,
            x1: 14,
            y1: 10
        }
    );
    let mut ops = Ops::default();
    let co = Laine2011.prepare::<Full>(&s, &mut ops);
    let b = Laine2011
        .tile::<Full>(
            &s,
            &co,
            PixelRect {
                x0: 8,
                y0: 8,
                x1: 9,
                y1: 9,
            },
            &mut ops,
        )
        .expect("non-empty");
    same("t.lo", &t, 32768, b.t.lo() as i128);
    same("t.hi", &t, 45876, b.t.hi() as i128);
    assert_eq!((b.u, b.v), (Interval::LENS, Interval::LENS));
}

fn smp(sx: u8, sy: u8, u: i32, v: i32, t: i32) -> Sample {
    sample_raw(sx, sy, u, v, t)
}

/// The static triangle of the first test with z = w/4: the screen centre (pixel (8,8), sub-pixel
/// 0) is inside with depth exactly ¼ = 0x400000; pixel (1,1) is outside.
#[test]
fn sample_test_coverage_and_depth() {
    let vp = Viewport::new(16, 16).unwrap();
    let t = stat([
        [-0.5, -0.5, 0.25, 1.0, 0.0],
        [0.5, -0.5, 0.25, 1.0, 0.0],
        [0.0, 0.5, 0.25, 1.0, 0.0],
    ]);
    let s = visible(&t, vp);
    let mut ops = Ops::default();
    let s0 = smp(0, 0, 0, 0, 0);
    let hit = uvt_core::sample::test::<Exact, Full>(&s, ScreenPos::of(8, 8, &s0), &s0, &mut ops)
        .expect("centre covered");
    same("depth", &t, 0x400000, hit.depth as i128);
    assert_eq!(
        uvt_core::sample::test::<Exact, Full>(&s, ScreenPos::of(1, 1, &s0), &s0, &mut ops),
        None
    );
    // Same triangle moving +1 NDC in x over the shutter, z = w/2 at t = 1: at t = ½ it has
    // moved ½ (4 px) and its depth is (¼ + ½)/2 = ⅜ = 0x600000. At t = ½ its left edge crosses
    // y = 0 at x = ¼, so pixel (11, 8) (NDC 0.375, 0) is inside. Pixel (14, 10) (NDC 0.75, −0.25)
    // is right of the t = 0 triangle (edge at 0.375) and inside at t = 1 (edges at 0.625, 1.375).
    let m = tri(
        [
            [-0.5, -0.5, 0.25, 1.0, 0.0],
            [0.5, -0.5, 0.25, 1.0, 0.0],
            [0.0, 0.5, 0.25, 1.0, 0.0],
        ],
        [
            [0.5, -0.5, 0.5, 1.0, 0.0],
            [1.5, -0.5, 0.5, 1.0, 0.0],
            [1.0, 0.5, 0.5, 1.0, 0.0],
        ],
    );
    let sm = visible(&m, vp);
    let half = smp(0, 0, 0, 0, 32768);
    let hit =
        uvt_core::sample::test::<Exact, Full>(&sm, ScreenPos::of(11, 8, &half), &half, &mut ops)
            .expect("covered at t=½");
    same("depth at t=½", &m, 0x600000, hit.depth as i128);
    let (early, late) = (smp(0, 0, 0, 0, 0), smp(0, 0, 0, 0, 65536));
    assert_eq!(
        uvt_core::sample::test::<Exact, Full>(&sm, ScreenPos::of(14, 10, &early), &early, &mut ops),
        None
    );
    assert!(uvt_core::sample::test::<Exact, Full>(
        &sm,
        ScreenPos::of(14, 10, &late),
        &late,
        &mut ops
    )
    .is_some());
}

/// Two triangles sharing the vertical edge x = 0: a sample exactly on it goes to the right-hand
/// triangle only (the fill rule's perturbation moves samples toward +x), at any t and lens point.
#[test]
fn sample_test_fill_rule_shared_edge() {
    let vp = Viewport::new(16, 16).unwrap();
    let (top, bot) = ([0.0, 0.5, 0.0, 1.0, 0.1], [0.0, -0.5, 0.0, 1.0, 0.1]);
    let left = stat([top, bot, [-0.5, 0.0, 0.0, 1.0, 0.1]]);
    let right = stat([bot, top, [0.5, 0.0, 0.0, 1.0, 0.1]]);
    let (l, r) = (
        Setup::unculled::<Exact>(&left, vp),
        Setup::unculled::<Exact>(&right, vp),
    );
    let mut ops = Ops::default();
    // u = 0: the edge stays at x = 0 (pixel column 8, sub-pixel 0); also u = ±1 moves it by
    // ±0.1·8 = 0.8 px, which is not on a sample, so use u = 0 and vary v and y.
    for (py, v) in [(6u16, 0), (8, 65536), (9, -65536), (7, 12345)] {
        let s0 = smp(0, 0, 0, v, 0);
        let pos = ScreenPos::of(8, py, &s0);
        let (hl, hr) = (
            uvt_core::sample::test::<Exact, Full>(&l, pos, &s0, &mut ops),
            uvt_core::sample::test::<Exact, Full>(&r, pos, &s0, &mut ops),
        );
        assert!(
            hl.is_none() && hr.is_some(),
            "row {py} v {v}: left {hl:?} right {hr:?}"
        );
    }
}

/// Resolve rounds half up per channel: (Σ + S/2)/S. With S = 4 and red 255 in one sample:
/// (255 + 2)/4 = 64; values 1,1,0,0 → (2+2)/4 = 1; 1,0,0,0 → (1+2)/4 = 0.
#[test]
fn tile_resolve_rounding_and_depth_test() {
    let mut fb = TileBuffer::<2, 1, 4>::new(Rgb888::new(0, 0, 0));
    let (w, o) = (Some(DepthTest::Written), Some(DepthTest::Occluded));
    assert_eq!(fb.write(0, 0, 0, Rgb888::new(255, 1, 1), 100), w);
    assert_eq!(fb.write(0, 0, 1, Rgb888::new(0, 1, 0), 100), w);
    assert_eq!(fb.resolve(0, 0), Rgb888::new(64, 1, 0));
    // the empty value is not a depth: refused, slot unchanged
    assert_eq!(fb.depth(1, 0, 0), Some(DEPTH_EMPTY));
    assert_eq!(fb.write(1, 0, 0, Rgb888::new(9, 9, 9), DEPTH_EMPTY), None);
    assert_eq!(fb.depth(1, 0, 0), Some(DEPTH_EMPTY));
    // the far end is written into an empty slot
    assert_eq!(fb.write(1, 0, 1, Rgb888::new(3, 3, 3), DEPTH_FAR), w);
    assert_eq!(fb.write(1, 0, 1, Rgb888::new(2, 2, 2), DEPTH_FAR), o);
    assert_eq!(fb.sample_color(1, 0, 1), Some(Rgb888::new(3, 3, 3)));
    // depth test: strictly nearer wins, ties keep the first writer
    assert_eq!(fb.write(1, 0, 0, Rgb888::new(9, 9, 9), 20), w);
    assert_eq!(fb.write(1, 0, 0, Rgb888::new(7, 7, 7), 20), o);
    assert_eq!(fb.write(1, 0, 0, Rgb888::new(4, 4, 4), 5), w);
    assert_eq!(fb.write(1, 0, 0, Rgb888::new(6, 6, 6), DEPTH_NEAR), w);
    assert_eq!(fb.sample_color(1, 0, 0), Some(Rgb888::new(6, 6, 6)));
    assert_eq!(fb.depth(1, 0, 0), Some(DEPTH_NEAR));
    // out of range: refused, no panic
    assert_eq!(fb.write(5, 5, 9, Rgb888::new(1, 1, 1), 0), None);
    assert_eq!(fb.depth(2, 0, 0), None);
}

/// The renderer drawing into an embedded-graphics `DrawTarget` produces the same image as
/// `render_with` (the demo scene's FNV-1a checksum, row-major RGB).
#[test]
fn tile_render_into_draw_target() {
    use embedded_graphics_core::draw_target::DrawTarget;
    use embedded_graphics_core::geometry::{OriginDimensions, Size};
    use embedded_graphics_core::pixelcolor::RgbColor;
    use embedded_graphics_core::Pixel;
    struct Img(Vec<Rgb888>);
    impl OriginDimensions for Img {
        fn size(&self) -> Size {
            Size::new(32, 32)
        }
    }
    impl DrawTarget for Img {
        type Color = Rgb888;
        type Error = core::convert::Infallible;
        fn draw_iter<I: IntoIterator<Item = Pixel<Rgb888>>>(
            &mut self,
            pixels: I,
        ) -> Result<(), Self::Error> {
            for Pixel(p, c) in pixels {
                if let Some(slot) = self.0.get_mut((p.y * 32 + p.x) as usize) {
                    *slot = c;
                }
            }
            Ok(())
        }
    }
    let prims = uvt_demo::prims().unwrap();
    let pattern = SamplePattern::new(4, 4, &uvt_demo::SAMPLES).unwrap();
    let mut r =
        Renderer::<Laine2011, 8>::new(Laine2011, uvt_demo::viewport().unwrap(), &prims).unwrap();
    let mut img = Img(vec![Rgb888::BLACK; 32 * 32]);
    r.render::<_, 8, 8, 4>(
        &pattern,
        uvt_demo::BOUNDS_TILE,
        Rgb888::new(16, 16, 24),
        &mut img,
    )
    .unwrap();
    let mut h = 0x811c_9dc5u32;
    for c in &img.0 {
        for b in [c.r(), c.g(), c.b()] {
            h = (h ^ b as u32).wrapping_mul(0x0100_0193);
        }
    }
    assert_eq!(
        h,
        uvt_demo::render::<uvt_core::DefaultPrecision, uvt_core::Full, uvt_core::Full>()
            .unwrap()
            .checksum
    );
}
