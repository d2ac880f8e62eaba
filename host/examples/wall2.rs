use uvt_core::bounds::auto::{Auto, Tier};
use uvt_core::Laine2011;
use uvt_host::bench::strategy::run_one;
use uvt_host::frame::driver::RunOpts;
use uvt_host::scene::builtin::{bench_scene, Bench, Blur};
use uvt_host::scene::pattern::Pattern;
fn main() {
    let n: usize = std::env::args().nth(1).unwrap().parse().unwrap();
    let s = bench_scene(Bench::Dense, Blur::Defocus2, false);
    let pattern = Pattern::new(s.pattern, s.spp, s.seed);
    let core = s.core_tris().unwrap();
    let vp = s.core_viewport();
    let colors = s.colors();
    let o = RunOpts {
        tile: 1,
        ..RunOpts::for_scene(&s, &colors)
    };
    let _ = run_one::<_, uvt_core::DefaultPrecision>(Laine2011, vp, &core, &pattern, &o);
    for _ in 0..n {
        let a = run_one::<_, uvt_core::DefaultPrecision>(Laine2011, vp, &core, &pattern, &o)
            .0
            .ms;
        let b = run_one::<_, uvt_core::DefaultPrecision>(
            Auto::with_rule([Tier::LAINE; 4]),
            vp,
            &core,
            &pattern,
            &o,
        )
        .0
        .ms;
        let c = run_one::<_, uvt_core::DefaultPrecision>(Auto::new(), vp, &core, &pattern, &o)
            .0
            .ms;
        println!("laine {a:.0} auto-all-laine {b:.0} auto {c:.0}");
    }
}
