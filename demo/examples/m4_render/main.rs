//! The built-in demo scene (`uvt_demo`) rendered through the tile framebuffer, printing the
//! image checksum, the core's counters and per-stage cost.
//!
//! On `thumbv7em-none-eabihf` it is a bare-metal Cortex-M4F program for QEMU's `mps2-an386`, and
//! the same source on `thumbv7m-none-eabi` (no FPU; the program uses none) a Cortex-M3 program for
//! `mps2-an385` (cortex-m-rt, output over semihosting; both boards have 4 MiB SSRAM at 0x0 and at
//! 0x2000_0000, `memory.x`). Run under `-icount shift=0` QEMU advances virtual time 1 ns per
//! executed instruction and SysTick counts the 25 MHz system clock of both boards, so one SysTick
//! tick is 40 instructions (checked on every run by the calibration line): the cost lines report
//! instructions per stage call. It also paints the stack and reports its peak use. On the host the
//! same program prints the same checksum and counters, and the cost in nanoseconds.
//!
//! **Per configuration.** `UVT_M4_PREC` at build time (`option_env!`) names one configuration of
//! the precision sweep (`exact-16-16-16`, `bounded-16-16-16-20`, …, `bounded-8-8-8-28`; default:
//! the core's `DefaultPrecision`); the program then also prints `prec NAME` and the cost lines
//! `setup_sel`, `bounds_sel`, `sample_sel` of that configuration (one instantiation per build;
//! an unknown name fails the build). `m4_report.sh --sweep` builds and runs every one.
//!
//! **Per unit.** `UVT_M4_UNIT` at build time (`full`, `motion-only`, `defocus-only`,
//! `static-only`; an unknown name fails the build) makes it the program of that unit variant
//! (`uvt_core::config::unit`) instead: only the default configuration (`DefaultPrecision`), only the
//! demo prims the unit accepts, rendered with `Renderer<Laine2011, _, DefaultPrecision, U>`
//! (checksum and counters) and the cost lines `setup_unit`, `bounds_unit`, `sample_unit` of
//! those prims on `U`. Nothing of the precision sweep or the exact configuration is in it, so
//! the `full` program is the same program with `U = Full`. With `UVT_M4_PREC=planar-16-16-16-20`
//! the unit program is built at the planar static configuration (`uvt_core::PlanarPrecision`)
//! instead of the default (and prints `unit_prec NAME`). `m4_report.sh --units` builds and
//! runs all four (and the full unit on each narrower unit's prims: `UVT_M4_PRIMS`).
#![cfg_attr(target_os = "none", no_std)]
#![cfg_attr(target_os = "none", no_main)]

use uvt_core::config::registry::{self, Config};

/// The configuration chosen at build time: `UVT_M4_PREC`, a name of the configuration registry
/// (`uvt_core::config::registry`; an unknown name fails the build), or the default.
const SEL: Config = match registry::find(match option_env!("UVT_M4_PREC") {
    Some(s) => s,
    None => "default",
}) {
    Some(c) => c,
    None => panic!("UVT_M4_PREC must name a configuration of uvt_core::config::registry"),
};

/// Its registry name.
const PREC: &str = match registry::name_of(SEL) {
    Some(n) => n,
    None => "?",
};

const fn same(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

/// `f::<P, Full, Full>(reps)` for the selected configuration `P` (a constant condition per
/// registry entry: one instantiation kept).
macro_rules! with_sel {
    ($f:ident, $reps:expr) => {{
        use uvt_core::Full;
        use uvt_demo::cost::$f as f;
        uvt_core::with_config!(crate::SEL, P => f::<P, Full, Full>($reps))
            .and_then(|r| r.ok())
            .unwrap_or(0)
    }};
}

/// The unit chosen at build time (`UVT_M4_UNIT`); `None`: the precision program.
const UNIT: Option<&str> = option_env!("UVT_M4_UNIT");

/// Index of `UNIT` in `uvt_core::config::unit::UNIT_NAMES` (0 without `UVT_M4_UNIT`); an unknown name
/// is a build error.
const UNIT_SEL: usize = match UNIT {
    None => 0,
    Some(u) => {
        let names = uvt_core::config::unit::UNIT_NAMES;
        let mut i = 0;
        while i < names.len() && !same(names[i], u) {
            i += 1;
        }
        assert!(
            i < names.len(),
            "UVT_M4_UNIT must be full, motion-only, defocus-only or static-only"
        );
        i
    }
};

/// `UVT_M4_HARNESS` (with `UVT_M4_UNIT`): build the harness program — the unit program with
/// no unit code linked (`m4_report.sh --units` measures its flash beside the units').
#[cfg_attr(not(target_os = "none"), allow(dead_code))]
const HARNESS: bool = option_env!("UVT_M4_HARNESS").is_some();

/// `UVT_M4_EMPTY` (with `UVT_M4_UNIT`): also measure the sample-test loop with the test
/// replaced by `black_box` (`cost sample_empty`, the harness's own cost per call), and the
/// tile-bounds loop the same way (`cost bounds_empty`).
#[cfg_attr(not(target_os = "none"), allow(dead_code))]
const EMPTY: bool = option_env!("UVT_M4_EMPTY").is_some();

/// Optional `UVT_M4_PRIMS` (a unit name; default `UVT_M4_UNIT`): run the unit on the demo
/// prims *this* unit accepts — e.g. the full unit on the static-only unit's prims, to compare
/// the two on the same work. Its index in `UNIT_NAMES`; an unknown name is a build error.
const PRIMS_SEL: usize = match option_env!("UVT_M4_PRIMS") {
    None => UNIT_SEL,
    Some(u) => {
        let names = uvt_core::config::unit::UNIT_NAMES;
        let mut i = 0;
        while i < names.len() && !same(names[i], u) {
            i += 1;
        }
        assert!(
            i < names.len(),
            "UVT_M4_PRIMS must be full, motion-only, defocus-only or static-only"
        );
        i
    }
};

/// The unit programs' configuration: the default, or the planar static one
/// (`UVT_M4_PREC=planar-16-16-16-20`); any other `UVT_M4_PREC` with `UVT_M4_UNIT` is a build
/// error.
const UNIT_PLANAR: bool = {
    let planar = SEL.same(&registry::PLANAR);
    assert!(
        UNIT.is_none() || planar || SEL.same(&registry::DEFAULT),
        "UVT_M4_UNIT builds the default configuration or planar-16-16-16-20 only"
    );
    planar
};

/// `f::<P, U, V>(args)` for the selected configuration `P` (the default or the planar one),
/// unit `U` and prims unit `V` (constant matches: one instantiation kept).
macro_rules! with_unit {
    ($($f:ident)::+, $($arg:expr),*) => {{
        use uvt_core::{DefocusOnly, Full, MotionOnly, StaticOnly};
        match crate::UNIT_SEL {
            0 => with_unit!(@p Full, $($f)::+, $($arg),*),
            1 => with_unit!(@p MotionOnly, $($f)::+, $($arg),*),
            2 => with_unit!(@p DefocusOnly, $($f)::+, $($arg),*),
            _ => with_unit!(@p StaticOnly, $($f)::+, $($arg),*),
        }
    }};
    (@p $u:ident, $($f:ident)::+, $($arg:expr),*) => {
        if crate::UNIT_PLANAR {
            with_unit!(@v uvt_core::PlanarPrecision, $u, $($f)::+, $($arg),*)
        } else {
            with_unit!(@v uvt_core::DefaultPrecision, $u, $($f)::+, $($arg),*)
        }
    };
    (@v $p:ty, $u:ident, $($f:ident)::+, $($arg:expr),*) => {
        match crate::PRIMS_SEL {
            0 => $($f)::+::<$p, $u, Full>($($arg),*),
            1 => $($f)::+::<$p, $u, MotionOnly>($($arg),*),
            2 => $($f)::+::<$p, $u, DefocusOnly>($($arg),*),
            _ => $($f)::+::<$p, $u, StaticOnly>($($arg),*),
        }
    };
}

/// Print the checksum and counters lines (identical format on target and host).
macro_rules! report {
    ($out:ident, $r:expr) => {{
        let r = $r;
        let s = r.stats;
        $out!("checksum {:#010x}", r.checksum);
        $out!(
            "stats triangles={} culled_outside={} culled_degenerate={} static={} motion={} defocus={} motion_defocus={} tiles_visited={} tiles_skipped={} samples_tested={} samples_covered={} ops_setup={} ops_bounds={} ops_sample={}",
            s.triangles, s.culled_outside, s.culled_degenerate, s.by_class[0], s.by_class[1], s.by_class[2], s.by_class[3],
            s.tiles_visited, s.tiles_skipped, s.samples_tested, s.samples_covered, s.ops.setup, s.ops.bounds, s.ops.sample
        );
    }};
}

#[cfg(target_os = "none")]
mod target;

#[cfg(not(target_os = "none"))]
fn main() {
    use uvt_demo as demo;
    if let Some(name) = UNIT {
        match with_unit!(demo::render,) {
            Ok(r) => report!(println, r),
            Err(e) => {
                eprintln!("error {e}");
                std::process::exit(1);
            }
        }
        println!("unit {name}");
        println!("unit_prec {PREC}");
        println!("prims {}", uvt_core::config::unit::UNIT_NAMES[PRIMS_SEL]);
        return;
    }
    match demo::render::<uvt_core::DefaultPrecision, uvt_core::Full, uvt_core::Full>() {
        Ok(r) => report!(println, r),
        Err(e) => {
            eprintln!("error {e}");
            std::process::exit(1);
        }
    }
    let time = |name: &str, f: &dyn Fn() -> u64| {
        let t = std::time::Instant::now();
        let calls = f();
        println!("cost {name} calls={calls} ns={}", t.elapsed().as_nanos());
    };
    if option_env!("UVT_M4_PREC").is_none() {
        time("setup", &|| {
            demo::cost::setup::<uvt_core::Exact, uvt_core::Full, uvt_core::Full>(2000).unwrap_or(0)
        });
        time("bounds", &|| {
            demo::cost::bounds::<uvt_core::Exact, uvt_core::Full, uvt_core::Full>(500).unwrap_or(0)
        });
        time("sample", &|| {
            demo::cost::samples::<uvt_core::Exact, uvt_core::Full, uvt_core::Full>(200).unwrap_or(0)
        });
        type B = uvt_core::BoundedPrecision;
        time("setup_bounded", &|| {
            demo::cost::setup::<B, uvt_core::Full, uvt_core::Full>(2000).unwrap_or(0)
        });
        time("bounds_bounded", &|| {
            demo::cost::bounds::<B, uvt_core::Full, uvt_core::Full>(500).unwrap_or(0)
        });
        time("sample_bounded", &|| {
            demo::cost::samples::<B, uvt_core::Full, uvt_core::Full>(200).unwrap_or(0)
        });
    }
    println!("prec {PREC}");
    time("setup_sel", &|| with_sel!(setup, 2000));
    time("bounds_sel", &|| with_sel!(bounds, 500));
    time("sample_sel", &|| with_sel!(samples, 200));
}
