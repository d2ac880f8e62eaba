//! Measurement: the smallest conservative margin with zero violations for the bounded sample
//! test on the adversarial triangle kinds of the conservativeness tests (static, moving,
//! defocused, both, camera-plane crossing, domain extremes, slivers with orientation flips, w = 0
//! vertices), beside the analytic epsilon. For each offset grid and each scale of the analytic ε
//! (1, ½, ¼, ⅛, 1/16, 0) it counts the triangles with a violation (whole-viewport brute force,
//! Laine2011 at tiles 1 and 4 and BboxScan). Seeded (`UVT_SEED`); `cargo run --release -p
//! uvt-tests --example bounded_margin [cases]`.

use uvt_core::{Bounded, Laine2011, Precision, SamplePattern, Viewport};
use uvt_tests::kinds::{make, ALL_KINDS, NP};
use uvt_tests::*;

const SCALES: [(u32, u32); 6] = [(1, 1), (1, 2), (1, 4), (1, 8), (1, 16), (0, 1)];

fn sweep<P: Precision>(cases: u32, seed: u64) {
    let kinds = ALL_KINDS;
    let vp = Viewport::new(24, 20).unwrap();
    let mut bad = [[0u32; SCALES.len()]; 8];
    let mut rng = Rng(seed);
    for case in 0..cases {
        let ki = case as usize % kinds.len();
        let mut p = [0.0; NP];
        p.iter_mut().for_each(|x| *x = rng.range(-1.0, 1.0));
        let t = make(kinds[ki], &p);
        let samples = random_samples(&mut rng, 2, 8);
        let pat = SamplePattern::new(2, 8, &samples).unwrap();
        for (si, &sc) in SCALES.iter().enumerate() {
            let fail =
                [1u16, 4].iter().any(|&bt| {
                    check_conservative_scaled::<_, P>(&Laine2011, &t, vp, &pat, bt, sc).is_err()
                }) || check_conservative_scaled::<_, P>(&uvt_core::BboxScan, &t, vp, &pat, 1, sc)
                    .is_err();
            bad[ki][si] += u32::from(fail);
        }
    }
    println!(
        "### OFF = {} (24×20 viewport: ε_x = {:?} raw for class both), {cases} triangles, seed {seed}\n",
        P::OFFSET_SHIFT.unwrap_or(0),
        uvt_core::Eps::of(P::OFFSET_SHIFT, uvt_core::Class::MotionDefocus, vp).x()
    );
    println!("| kind | triangles with a violation at ε·1 | ½ | ¼ | ⅛ | 1/16 | 0 |\n|---|---|---|---|---|---|---|");
    for (k, row) in kinds.iter().zip(bad.iter()) {
        let cells: Vec<String> = row.iter().map(|x| x.to_string()).collect();
        println!("| {k:?} | {} |", cells.join(" | "));
    }
    println!();
}

fn main() {
    let cases: u32 = std::env::args()
        .nth(1)
        .map_or(800, |a| a.parse().expect("cases"));
    let seed = seed();
    sweep::<Bounded<16, 16, 16, 20>>(cases, seed);
    sweep::<Bounded<16, 16, 16, 24>>(cases, seed);
    sweep::<Bounded<16, 16, 16, 28>>(cases, seed);
}
