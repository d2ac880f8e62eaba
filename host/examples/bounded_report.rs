//! Measurement for issue 10 phase 1: the bounded sample test (`Bounded<16, 16, 16, OFF>`) on the
//! benchmark scenes at `--quick` size, against the exact core and the f64 reference; the
//! violations of its own (ε-widened) Laine2011 bounds, and of bounds built with the analytic ε
//! scaled down (the smallest margin with zero violations); the STE lost to the margin; host
//! ns per sample test, exact against bounded.
//!
//! Run once, release: `cargo run --release -p uvt-host --example bounded_report [OFF]`
//! (OFF = 20 by default; 20, 24 or 28). Brute force per triangle over the union of the bounded
//! and the reference footprints, widened by 2 px each side.

use std::hint::black_box;
use std::time::Instant;

use rayon::prelude::*;
use uvt_core::bounds::strategy::BoundsStrategy;
use uvt_core::config::precision::DefaultPrecision;
use uvt_core::config::unit::Full;
use uvt_core::{
    sample, setup_scaled, Bounded, Eps, Laine2011, Ops, Outcome, PixelRect, Precision, ScreenPos,
    Setup, Triangle,
};
use uvt_host::reference;
use uvt_host::scene::builtin::{bench_scene, Bench, Blur};
use uvt_host::scene::pattern::Pattern;

/// ε scale levels (num/den of the analytic ε), largest first.
const LEVELS: [(u32, u32); 7] = [(1, 1), (1, 2), (1, 4), (1, 8), (1, 16), (1, 64), (0, 1)];

#[derive(Default, Clone)]
struct Acc {
    compared: u64,
    differ_exact: u64,
    max_px_exact: f64,
    differ_f64: u64,
    max_px_f64: f64,
    exact_differ_f64: u64,
    violations: [u64; LEVELS.len()],
    /// tested, covered per level (bounded test), and for the exact configuration
    tested: [u64; LEVELS.len()],
    covered: [u64; LEVELS.len()],
    tested_exact: u64,
    covered_exact: u64,
}

impl Acc {
    fn add(&mut self, o: &Acc) {
        self.compared += o.compared;
        self.differ_exact += o.differ_exact;
        self.max_px_exact = self.max_px_exact.max(o.max_px_exact);
        self.differ_f64 += o.differ_f64;
        self.max_px_f64 = self.max_px_f64.max(o.max_px_f64);
        self.exact_differ_f64 += o.exact_differ_f64;
        for k in 0..LEVELS.len() {
            self.violations[k] += o.violations[k];
            self.tested[k] += o.tested[k];
            self.covered[k] += o.covered[k];
        }
        self.tested_exact += o.tested_exact;
        self.covered_exact += o.covered_exact;
    }
}

fn cell(px: u16, py: u16, fp: PixelRect, bt: u16) -> PixelRect {
    PixelRect {
        x0: px - px % bt,
        y0: py - py % bt,
        x1: px - px % bt + bt,
        y1: py - py % bt + bt,
    }
    .intersect(&fp)
}

type Prepared = Option<(Setup, <Laine2011 as BoundsStrategy>::Coeffs)>;

fn prepared<P: Precision>(t: &Triangle, vp: uvt_core::Viewport, l: (u32, u32)) -> Prepared {
    let mut ops = Ops::default();
    match setup_scaled::<P>(t, vp, l.0, l.1, &mut ops) {
        Outcome::Visible(s) => {
            let c = Laine2011.prepare::<Full>(&s, &mut ops);
            Some((s, c))
        }
        Outcome::Culled(_) | Outcome::Refused(_) => None,
    }
}

/// Whether (px, py, sample) is tested by the renderer under `p` (footprint, tile box).
fn tested(p: &Prepared, px: u16, py: u16, bt: u16, q: &uvt_core::Sample) -> bool {
    let Some((s, c)) = p else { return false };
    if !s.footprint().contains(px, py) {
        return false;
    }
    let cl = cell(px, py, s.footprint(), bt);
    match Laine2011.tile::<Full>(s, c, cl, &mut Ops::default()) {
        Some(b) => b.contains(q.u().to_bits(), q.v().to_bits(), q.t().to_bits()),
        None => false,
    }
}

fn run<P: Precision + Sync>() {
    let shift = P::OFFSET_SHIFT.expect("bounded");
    println!("## Bounded<16, 16, 16, {shift}> at --quick size\n");
    println!("| scene | tris | ε x/y/w raw (px at w=1) | bounded ≠ exact (rate, max px) | bounded ≠ f64 (rate, max px) | exact ≠ f64 | violations at ε·1, ½, ¼, ⅛, 1/16, 1/64, 0 | STE bounded ε / ε=0 / exact | STE lost | ns/test exact / bounded |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    let mut total = Acc::default();
    for kind in [Bench::Game, Bench::Dense] {
        for row in Blur::ALL {
            let s = bench_scene(kind, row, true);
            let pat = Pattern::new(s.pattern, s.spp, s.seed);
            let vp = s.core_viewport();
            let v = s.viewport;
            let bt = u16::from(s.tile);
            let core: Vec<Triangle> = s
                .tris
                .iter()
                .map(|t| t.to_core_with::<P>().expect("bench scene in the domain"))
                .collect();
            let eps_md = Eps::of(Some(shift), uvt_core::Class::MotionDefocus, vp);
            let acc = s
                .tris
                .par_iter()
                .zip(core.par_iter())
                .map(|(st, ct)| {
                    let mut a = Acc::default();
                    let levels: Vec<Prepared> =
                        LEVELS.iter().map(|&l| prepared::<P>(ct, vp, l)).collect();
                    let exact_cfg = prepared::<uvt_core::DefaultPrecision>(ct, vp, (1, 1));
                    let rf = reference::setup::setup(st, v).ok();
                    let Some(region) = uvt_host::frame::compare::footprint_union(
                        levels[0].as_ref().map(|x| x.0.footprint()),
                        rf.as_ref().map(|x| x.footprint),
                    ) else {
                        return a;
                    };
                    let (x0, y0) = (region.x0.saturating_sub(2), region.y0.saturating_sub(2));
                    let (x1, y1) = (
                        (region.x1 + 2).min(vp.width()),
                        (region.y1 + 2).min(vp.height()),
                    );
                    let fb = Setup::unculled::<P>(ct, vp);
                    let fe = Setup::unculled::<DefaultPrecision>(ct, vp);
                    let mut ops = Ops::default();
                    for py in y0..y1 {
                        for px in x0..x1 {
                            for si in 0..pat.spp as usize {
                                let idx = pat.index(px, py, si);
                                let (q, e) = (&pat.quant[idx], &pat.exact[idx]);
                                let pos = ScreenPos::of(px, py, q);
                                let hb = sample::test::<P, Full>(&fb, pos, q, &mut ops).is_some();
                                let he =
                                    sample::test::<DefaultPrecision, Full>(&fe, pos, q, &mut ops)
                                        .is_some();
                                let (x, y) = (px as f64 + e[0], py as f64 + e[1]);
                                let hr =
                                    reference::sample::sample_test(st, v, x, y, e[2], e[3], e[4])
                                        .is_some();
                                a.compared += 1;
                                let dist = || {
                                    reference::sample::edge_distance_px(
                                        st, v, x, y, e[2], e[3], e[4],
                                    )
                                };
                                if hb != he {
                                    a.differ_exact += 1;
                                    a.max_px_exact = a.max_px_exact.max(dist());
                                }
                                if hb != hr {
                                    a.differ_f64 += 1;
                                    a.max_px_f64 = a.max_px_f64.max(dist());
                                }
                                a.exact_differ_f64 += u64::from(he != hr);
                                let te = tested(&exact_cfg, px, py, bt, q);
                                a.tested_exact += u64::from(te);
                                a.covered_exact += u64::from(te && he);
                                for (k, p) in levels.iter().enumerate() {
                                    let t = tested(p, px, py, bt, q);
                                    a.tested[k] += u64::from(t);
                                    a.covered[k] += u64::from(t && hb);
                                    a.violations[k] += u64::from(hb && !t);
                                }
                            }
                        }
                    }
                    a
                })
                .reduce(Acc::default, |mut x, y| {
                    x.add(&y);
                    x
                });
            // Host timing: every footprint sample of every visible triangle, exact then bounded
            // (single thread, release, one run).
            let ns = [false, true].map(|bounded| {
                let setups: Vec<Setup> = core
                    .iter()
                    .filter_map(|t| {
                        let p = if bounded {
                            prepared::<P>(t, vp, (1, 1))
                        } else {
                            prepared::<uvt_core::DefaultPrecision>(t, vp, (1, 1))
                        };
                        p.map(|x| x.0)
                    })
                    .collect();
                let mut ops = Ops::default();
                let (mut n, mut hits) = (0u64, 0u64);
                let start = Instant::now();
                for st in &setups {
                    let fp = st.footprint();
                    for py in fp.y0..fp.y1 {
                        for px in fp.x0..fp.x1 {
                            for si in 0..pat.spp as usize {
                                let q = &pat.quant[pat.index(px, py, si)];
                                let h = sample::test::<P, Full>(
                                    black_box(st),
                                    ScreenPos::of(px, py, q),
                                    q,
                                    &mut ops,
                                );
                                hits += u64::from(black_box(h).is_some());
                                n += 1;
                            }
                        }
                    }
                }
                black_box(hits);
                start.elapsed().as_nanos() as f64 / n.max(1) as f64
            });
            let ste = |c: u64, t: u64| c as f64 / t.max(1) as f64;
            let (s1, s0) = (
                ste(acc.covered[0], acc.tested[0]),
                ste(acc.covered[6], acc.tested[6]),
            );
            let px = |e: i32, ext: u16| f64::from(e) / 65536.0 * f64::from(ext) / 2.0;
            println!(
                "| {kind:?} {} | {} | {}/{}/{} ({:.4}/{:.4}) | {} ({:.1e}, {:.4}) | {} ({:.1e}, {:.4}) | {} | {:?} | {:.3}% / {:.3}% / {:.3}% | {:.3}% | {:.1} / {:.1} |",
                row.label(), s.tris.len(),
                eps_md.x()[0], eps_md.x()[1], eps_md.w(), px(eps_md.x()[0], vp.width()), px(eps_md.x()[1], vp.height()),
                acc.differ_exact, acc.differ_exact as f64 / acc.compared.max(1) as f64, acc.max_px_exact,
                acc.differ_f64, acc.differ_f64 as f64 / acc.compared.max(1) as f64, acc.max_px_f64,
                acc.exact_differ_f64, acc.violations,
                100.0 * s1, 100.0 * s0, 100.0 * ste(acc.covered_exact, acc.tested_exact),
                100.0 * (1.0 - s1 / s0.max(1e-12)), ns[0], ns[1]
            );
            total.add(&acc);
        }
    }
    println!(
        "\ntotal: compared {}, bounded ≠ exact {} (max {:.4} px), bounded ≠ f64 {} (max {:.4} px), exact ≠ f64 {}, violations per level {:?}",
        total.compared, total.differ_exact, total.max_px_exact, total.differ_f64, total.max_px_f64,
        total.exact_differ_f64, total.violations
    );
}

fn main() {
    let off: u32 = std::env::args()
        .nth(1)
        .map_or(20, |a| a.parse().expect("OFF: 20, 24 or 28"));
    match off {
        20 => run::<Bounded<16, 16, 16, 20>>(),
        24 => run::<Bounded<16, 16, 16, 24>>(),
        28 => run::<Bounded<16, 16, 16, 28>>(),
        other => panic!("OFF {other}: choose 20, 24 or 28"),
    }
}
