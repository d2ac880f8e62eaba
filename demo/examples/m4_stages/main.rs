//! The per-stage cost of every bounds strategy of the bench on a bench row's own triangles
//! (`uvt_demo::workload`): for each strategy and triangle class one line
//! `stage NAME CLASS triangles=… visible=… tiles=… admits=… tested=… covered=… ops=… insn=…`
//! (classes with no triangle left out), then Zmax culling's own calls
//! (`uvt_demo::zmax_cost`): `zmax floors=… checks=… refreshes=… bounds_tile=… spp=… insn=…`.
//!
//! On `thumbv7em-none-eabihf` it is a bare-metal Cortex-M4F program for QEMU's `mps2-an386`
//! (as `m4_render`: SysTick under `-icount shift=0` counts 40 instructions per tick, checked by
//! the calibration line); the workload file named by `UVT_M4_WORKLOAD` at build time is linked
//! in (`build.rs` copies it; without it the program has no work and says so). `insn` is
//! instructions: setup, tile walk, predicate, sample test (`uvt_demo::workload::stages`). On the
//! host the same program reads the file given as its argument and prints the same counts
//! (`insn=0,0,0,0`): `m4_report.sh --strategies` checks that both agree, so the Cortex-M ran
//! the same work with the same bits.
#![cfg_attr(target_os = "none", no_std)]
#![cfg_attr(target_os = "none", no_main)]

use uvt_core::bounds::registry::STRATEGIES;
use uvt_core::{with_strategy, BoundsStrategy, Class, DefaultPrecision, Sample, SamplePattern};
use uvt_demo::workload::{stages, FormatError, StageCost, Workload};
use uvt_demo::zmax_cost::{zmax_cost, ZmaxCost};

/// Most samples a workload's table may hold (block 8 × 8, 64 samples per pixel).
const MAX_SAMPLES: usize = 4096;

/// The strategies measured: the bench's (every registry strategy but the bounding-box scan).
fn measured() -> impl Iterator<Item = &'static str> {
    STRATEGIES
        .into_iter()
        .filter(|n| *n != uvt_core::BboxScan.name())
}

/// The sample table of `w`.
fn table(w: &Workload<'_>) -> Result<heapless::Vec<Sample, MAX_SAMPLES>, FormatError> {
    let mut v = heapless::Vec::new();
    for s in w.samples() {
        v.push(s?).map_err(|_| FormatError::Counts)?;
    }
    Ok(v)
}

/// Run every measured strategy on `w`, handing each result to `out`, then Zmax culling's calls.
fn run_all(
    w: &Workload<'_>,
    lap: &mut impl FnMut() -> u64,
    mut out: impl FnMut(&str, &str, &StageCost),
) -> Result<ZmaxCost, FormatError> {
    let samples = table(w)?;
    let h = w.header();
    let pattern = SamplePattern::new_with::<DefaultPrecision>(h.block, h.spp, &samples)
        .map_err(FormatError::Core)?;
    for name in measured() {
        let c = with_strategy!(name, s => stages::<DefaultPrecision, _>(s, w, &pattern, lap))
            .unwrap_or(Err(FormatError::Counts))?;
        for (class, c) in Class::ALL.iter().zip(c.iter()) {
            if c.triangles > 0 {
                out(name, class.name(), c);
            }
        }
    }
    zmax_cost::<DefaultPrecision>(w, lap)
}

/// Print one result line with `$out` (`println` on the host, `hprintln` on the target).
macro_rules! line {
    ($out:ident, $name:expr, $class:expr, $c:expr) => {{
        let c: &uvt_demo::workload::StageCost = $c;
        $out!(
            "stage {} {} triangles={} visible={} tiles={} admits={} tested={} covered={} ops={},{},{},{},{} insn={},{},{},{}",
            $name, $class, c.triangles, c.visible, c.tiles, c.admits, c.tested, c.covered,
            c.ops[0], c.ops[1], c.ops[2], c.ops[3], c.ops[4],
            c.insn[0], c.insn[1], c.insn[2], c.insn[3]
        );
    }};
}

/// Print the Zmax line with `$out`.
macro_rules! zline {
    ($out:ident, $bt:expr, $z:expr) => {{
        let z: &uvt_demo::zmax_cost::ZmaxCost = $z;
        $out!(
            "zmax floors={} checks={} refreshes={} bounds_tile={} spp={} insn={},{},{}",
            z.floors,
            z.checks,
            z.refreshes,
            $bt,
            uvt_demo::zmax_cost::S,
            z.insn[0],
            z.insn[1],
            z.insn[2]
        );
    }};
}

#[cfg(target_os = "none")]
mod target;

#[cfg(not(target_os = "none"))]
fn main() {
    let Some(path) = std::env::args().nth(1) else {
        eprintln!("usage: m4_stages WORKLOAD.bin");
        std::process::exit(2);
    };
    let bytes = match std::fs::read(&path) {
        Ok(b) => b,
        Err(e) => {
            eprintln!("error {path}: {e}");
            std::process::exit(1);
        }
    };
    let res = Workload::parse(&bytes).and_then(|w| {
        let h = w.header();
        println!("workload every={} spp={}", h.every, h.spp);
        let z = run_all(&w, &mut || 0, |n, k, c| line!(println, n, k, c))?;
        zline!(println, h.bounds_tile, &z);
        Ok(())
    });
    if let Err(e) = res {
        eprintln!("error {e}");
        std::process::exit(1);
    }
}
