//! How many static triangles of the bench scenes (`host/src/scene/builtin.rs`, full and quick size)
//! get a larger conservative epsilon at the planar static configuration (`planar.rs`,
//! per triangle) than at the default configuration (`Eps::of`, per viewport), and how many the
//! planar setup culls because rounding made them degenerate (det P' = 0; the exact configuration
//! keeps them). Every triangle is made static (its t0 vertices, CoC 0), so every row counts.
//! Run: `cargo run --release -p uvt-tests --example planar_eps`.

use uvt_core::config::unit::Full;
use uvt_core::setup::eps::Eps;
use uvt_core::{
    setup, Class, DefaultPrecision, Exact, Outcome, PlanarPrecision, Precision, Triangle,
};
use uvt_host::scene::builtin::{self, Bench, Blur};

fn main() {
    println!("| scene | size | static triangles visible (exact) | planar ε > default ε | planar culled (exact visible) | largest planar ε (raw) | default ε (raw) | planar ε_w > 0 | hull faces dropped (a vertex w ≤ ε_w) |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for quick in [false, true] {
        for bench in [Bench::Game, Bench::Dense] {
            let scene = builtin::bench_scene(bench, Blur::Static, quick);
            let vp = scene.core_viewport();
            let tris = scene.core_tris().expect("built-in scene converts");
            let dflt = Eps::of(
                <DefaultPrecision as Precision>::OFFSET_SHIFT,
                Class::Static,
                vp,
            );
            let (mut vis, mut larger, mut culled, mut max) = (0u64, 0u64, 0u64, 0i32);
            let (mut ew, mut nohull) = (0u64, 0u64);
            for t in tris.iter() {
                let mut v = t.vertices(0);
                for x in v.iter_mut() {
                    x.coc = uvt_core::Coord::from_bits(0);
                }
                let t = Triangle::new_static(v).expect("static");
                assert_eq!(t.class(), Class::Static);
                let ops = &mut Default::default();
                if !matches!(setup::<Exact, Full>(&t, vp, ops), Outcome::Visible(_)) {
                    continue;
                }
                vis += 1;
                match setup::<PlanarPrecision, Full>(&t, vp, ops) {
                    Outcome::Visible(s) => {
                        let e = s.eps();
                        let m = e.x()[0].max(e.x()[1]).max(e.w());
                        ew += u64::from(e.w() > 0);
                        // `HullCull` keeps faces only when every hull point has w > ε_w
                        // (`strategies::hull::eps_margin`); a static triangle's hull points
                        // are its vertices.
                        nohull += u64::from(
                            e.w() > 0 && t.vertices(0).iter().any(|v| v.bits()[3] <= e.w()),
                        );
                        max = max.max(m);
                        larger += u64::from(
                            e.x()[0] > dflt.x()[0] || e.x()[1] > dflt.x()[1] || e.w() > dflt.w(),
                        );
                    }
                    Outcome::Culled(_) | Outcome::Refused(_) => culled += 1,
                }
            }
            println!(
                "| {:?} | {} {}x{} | {vis} | {larger} | {culled} | {max} | x {:?}, w {} | {ew} | {nohull} |",
                bench,
                if quick { "quick" } else { "full" },
                vp.width(),
                vp.height(),
                dflt.x(),
                dflt.w()
            );
        }
    }
}
