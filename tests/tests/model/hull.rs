//! The hull's cap on stored faces ([`KEPT_FACES`]) against the bench scenes: on every quick
//! bench row, every visible triangle keeps fewer faces than the cap, so the cap dropped none
//! and every hull strategy's decisions there are those of the uncapped per-tile form (which
//! `core/src/verify/hull_reference.rs` checks against the direct per-face test). The largest
//! count per row is printed; the check fails when a scene change makes a triangle reach the cap.

use uvt_core::bounds::hull::tiles::KEPT_FACES;
use uvt_core::bounds::registry::hull;
use uvt_core::{setup, BoundsStrategy, DefaultPrecision, Full, Ops, Outcome};
use uvt_host::scene::builtin::{bench_scene, Bench, Blur};

#[test]
fn no_bench_triangle_reaches_the_face_cap() {
    type P = DefaultPrecision;
    let mut most_overall = 0usize;
    for kind in Bench::ALL {
        for row in Blur::ALL {
            let s = bench_scene(kind, row, true);
            let vp = s.core_viewport();
            let mut most = 0usize;
            for (i, t) in s.tris.iter().enumerate() {
                let t = t.to_core_with::<P>().expect("bench triangle");
                let mut ops = Ops::default();
                if let Outcome::Visible(st) = setup::<P, Full>(&t, vp, &mut ops) {
                    let (tiles, _) = hull().prepare::<Full>(&st, &mut ops);
                    let n = tiles.faces().len();
                    assert!(
                        n < KEPT_FACES,
                        "{} {}: triangle {i} keeps {n} faces (cap {KEPT_FACES})",
                        kind.name(),
                        row.name()
                    );
                    most = most.max(n);
                }
            }
            println!("{} {}: at most {most} faces kept", kind.name(), row.name());
            most_overall = most_overall.max(most);
        }
    }
    assert!(
        most_overall >= 3,
        "no triangle keeps 3 faces: {most_overall}"
    );
}
