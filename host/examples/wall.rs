use uvt_host::bench::strategy::run_strategy;
use uvt_host::frame::driver::RunOpts;
use uvt_host::scene::builtin::{bench_scene, Bench, Blur};
use uvt_host::scene::pattern::Pattern;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let quick = args.get(1).map(|s| s == "quick").unwrap_or(false);
    let strats: Vec<&str> = args[2].split(',').collect();
    let n: usize = args[3].parse().unwrap();
    let row = match args.get(4).map(|s| s.as_str()).unwrap_or("defocus2") {
        "defocus2" => Blur::Defocus2,
        "defocus" => Blur::Defocus,
        "motion" => Blur::Motion,
        "static" => Blur::Static,
        "both" => Blur::Both,
        "motion2" => Blur::Motion2,
        _ => Blur::Both2,
    };
    let s = bench_scene(Bench::Dense, row, quick);
    let pattern = Pattern::new(s.pattern, s.spp, s.seed);
    let core = s.core_tris().unwrap();
    let vp = s.core_viewport();
    let colors = s.colors();
    let o = RunOpts {
        tile: 1,
        ..RunOpts::for_scene(&s, &colors)
    };
    let _ = run_strategy("laine2011", vp, &core, &pattern, &o);
    for _ in 0..n {
        for st in &strats {
            let r = run_strategy(st, vp, &core, &pattern, &o).unwrap();
            print!("{st} {:.0}  ", r.ms);
        }
        println!();
    }
}
