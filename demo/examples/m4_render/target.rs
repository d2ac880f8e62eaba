//! The bare-metal Cortex-M program of `m4_render` (`main.rs`): SysTick-timed stage costs under
//! QEMU `-icount shift=0`, a painted stack and its peak, output over semihosting.

use cortex_m::peripheral::syst::SystClkSource;
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use uvt_demo as demo;

const PAINT: u32 = 0x5AA5_C33C;
/// Instructions per SysTick tick under `-icount shift=0` on mps2-an385/an386 (25 MHz SYSCLK).
const INSN_PER_TICK: u64 = 40;

extern "C" {
    static mut __sheap: u32;
    static _stack_start: u32;
}

fn sp() -> usize {
    cortex_m::register::msp::read() as usize
}

/// Fill the free stack below the current frame with a pattern.
fn paint() {
    let lo = core::ptr::addr_of!(__sheap) as usize;
    let hi = sp() - 256;
    let mut p = lo;
    while p < hi {
        // SAFETY: [__sheap, sp − 256) is unused RAM between .bss and the live stack.
        unsafe { core::ptr::write_volatile(p as *mut u32, PAINT) };
        p += 4;
    }
}

/// Deepest stack use since `paint`, in bytes.
fn peak() -> usize {
    let lo = core::ptr::addr_of!(__sheap) as usize;
    let top = core::ptr::addr_of!(_stack_start) as usize;
    let mut p = lo;
    // SAFETY: reading the painted region back.
    while p < top && unsafe { core::ptr::read_volatile(p as *const u32) } == PAINT {
        p += 4;
    }
    top - p
}

fn ticks(syst: &mut cortex_m::peripheral::SYST, f: impl FnOnce() -> u64) -> (u64, u64) {
    syst.clear_current();
    let start = cortex_m::peripheral::SYST::get_current();
    let calls = f();
    let end = cortex_m::peripheral::SYST::get_current();
    let t = (start.wrapping_sub(end) & 0x00ff_ffff) as u64;
    (calls, t * INSN_PER_TICK)
}

#[entry]
fn main() -> ! {
    // Taken once, at reset: always available (no panic message, so no formatting code).
    let Some(mut cp) = cortex_m::Peripherals::take() else {
        debug::exit(debug::EXIT_FAILURE);
        loop {
            cortex_m::asm::wfi();
        }
    };
    cp.SYST.set_clock_source(SystClkSource::Core);
    cp.SYST.set_reload(0x00ff_ffff);
    cp.SYST.enable_counter();
    paint();
    // Calibration: cortex-m 0.7's delay(n) runs n+1 iterations of a 2-instruction loop, so
    // 8,000,002 instructions are expected; this checks the 40-instructions-per-tick factor.
    let (_, cal) = ticks(&mut cp.SYST, || {
        cortex_m::asm::delay(4_000_000);
        0
    });
    if crate::UNIT.is_some() {
        unit_program(&mut cp.SYST, cal);
    }
    match demo::render::<uvt_core::DefaultPrecision, uvt_core::Full, uvt_core::Full>() {
        Ok(r) => {
            report!(hprintln, r);
        }
        Err(e) => {
            hprintln!("error {}", e);
            debug::exit(debug::EXIT_FAILURE);
        }
    }
    hprintln!("stack_peak_bytes {}", peak());
    hprintln!("calibration delay(4000000) insn={}", cal);
    // The fixed measurements (the README's table) only in the default build: a build for
    // one configuration measures that configuration alone, so every configuration's figures
    // come from the same code shape (more instantiations change the inlining and the count).
    if option_env!("UVT_M4_PREC").is_none() {
        let (c, i) = ticks(&mut cp.SYST, || {
            demo::cost::setup::<uvt_core::Exact, uvt_core::Full, uvt_core::Full>(20).unwrap_or(0)
        });
        hprintln!("cost setup calls={} insn={}", c, i);
        let (c, i) = ticks(&mut cp.SYST, || {
            demo::cost::bounds::<uvt_core::Exact, uvt_core::Full, uvt_core::Full>(5).unwrap_or(0)
        });
        hprintln!("cost bounds calls={} insn={}", c, i);
        let (c, i) = ticks(&mut cp.SYST, || {
            demo::cost::samples::<uvt_core::Exact, uvt_core::Full, uvt_core::Full>(2).unwrap_or(0)
        });
        hprintln!("cost sample calls={} insn={}", c, i);
        type B = uvt_core::BoundedPrecision;
        let (c, i) = ticks(&mut cp.SYST, || {
            demo::cost::setup::<B, uvt_core::Full, uvt_core::Full>(20).unwrap_or(0)
        });
        hprintln!("cost setup_bounded calls={} insn={}", c, i);
        let (c, i) = ticks(&mut cp.SYST, || {
            demo::cost::bounds::<B, uvt_core::Full, uvt_core::Full>(5).unwrap_or(0)
        });
        hprintln!("cost bounds_bounded calls={} insn={}", c, i);
        let (c, i) = ticks(&mut cp.SYST, || {
            demo::cost::samples::<B, uvt_core::Full, uvt_core::Full>(2).unwrap_or(0)
        });
        hprintln!("cost sample_bounded calls={} insn={}", c, i);
    }
    hprintln!("prec {}", crate::PREC);
    let (c, i) = ticks(&mut cp.SYST, || with_sel!(setup, 20));
    hprintln!("cost setup_sel calls={} insn={}", c, i);
    let (c, i) = ticks(&mut cp.SYST, || with_sel!(bounds, 5));
    hprintln!("cost bounds_sel calls={} insn={}", c, i);
    let (c, i) = ticks(&mut cp.SYST, || with_sel!(samples, 2));
    hprintln!("cost sample_sel calls={} insn={}", c, i);
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}

/// Output of the unit programs without `core::fmt` (the formatting machinery would be a
/// large shared part of every unit's flash): strings and numbers straight to semihosting.
struct Plain(Option<cortex_m_semihosting::hio::HostStream>);

impl Plain {
    fn s(&mut self, s: &str) -> &mut Self {
        self.b(s.as_bytes())
    }
    #[inline(never)]
    fn b(&mut self, b: &[u8]) -> &mut Self {
        if let Some(h) = self.0.as_mut() {
            // A failed host write loses output only; the test then finds the line missing.
            let _ = h.write_all(b);
        }
        self
    }
    /// `v` in decimal, as `{}` prints it. The divisor goes through `black_box` so that the
    /// loop stays one 64-bit division per digit instead of being unrolled into twenty
    /// multiply-by-reciprocal sequences (1.5 KB of every unit program's flash). No indexing that could panic (a bounds-check panic would link `core::fmt`): u64 has
    /// at most 20 digits, the buffer's length, so the loop ends by `v == 0` first.
    #[inline(never)]
    fn n(&mut self, v: u64) -> &mut Self {
        let ten = core::hint::black_box(10u64);
        let mut buf = [0u8; 20];
        let mut start = buf.len();
        let mut v = v;
        // A trip count that depends on `v` (not the buffer's 20), so the loop is not unrolled.
        loop {
            let q = v / ten;
            start = start.saturating_sub(1);
            if let Some(b) = buf.get_mut(start) {
                // v − 10q ∈ 0..=9.
                *b = b'0' + v.wrapping_sub(q.wrapping_mul(ten)) as u8;
            }
            v = q;
            if v == 0 {
                break;
            }
        }
        self.b(buf.get(start..).unwrap_or_default())
    }
    /// `v` as `{:#010x}` prints it.
    fn x(&mut self, v: u32) -> &mut Self {
        let mut buf = *b"0x00000000";
        for (k, b) in buf[2..].iter_mut().enumerate() {
            let d = (v >> (28 - 4 * k)) & 0xf;
            *b = b"0123456789abcdef"[d as usize];
        }
        self.b(&buf)
    }
    /// The checksum and counters lines as the unit program prints them (the harness
    /// program's copy; the unit program keeps its own, so its code is as before).
    fn result(&mut self, checksum: u32, s: &uvt_core::Stats) {
        self.s("checksum ").x(checksum).s("\n");
        self.s("stats triangles=").n(s.triangles);
        self.s(" culled_outside=").n(s.culled_outside);
        self.s(" culled_degenerate=").n(s.culled_degenerate);
        self.s(" static=")
            .n(s.by_class[0])
            .s(" motion=")
            .n(s.by_class[1]);
        self.s(" defocus=")
            .n(s.by_class[2])
            .s(" motion_defocus=")
            .n(s.by_class[3]);
        self.s(" tiles_visited=").n(s.tiles_visited);
        self.s(" tiles_skipped=").n(s.tiles_skipped);
        self.s(" samples_tested=").n(s.samples_tested);
        self.s(" samples_covered=").n(s.samples_covered);
        self.s(" ops_setup=")
            .n(s.ops.setup)
            .s(" ops_bounds=")
            .n(s.ops.bounds);
        self.s(" ops_sample=").n(s.ops.sample).s("\n");
    }
    fn cost(&mut self, name: &str, (calls, insn): (u64, u64)) {
        self.s("cost ")
            .s(name)
            .s(" calls=")
            .n(calls)
            .s(" insn=")
            .n(insn)
            .s("\n");
    }
}

/// The unit program (`UVT_M4_UNIT`): render and cost of the prims the unit accepts, at the
/// default configuration only. Prints the same lines as the other programs.
fn unit_program(syst: &mut cortex_m::peripheral::SYST, cal: u64) -> ! {
    let mut o = Plain(cortex_m_semihosting::hio::hstdout().ok());
    if crate::HARNESS {
        harness_program(o, cal);
    }
    let Ok(r) = with_unit!(demo::render,) else {
        o.s("error rendering the unit's prims\n");
        debug::exit(debug::EXIT_FAILURE);
        loop {
            cortex_m::asm::wfi();
        }
    };
    let s = r.stats;
    o.s("checksum ").x(r.checksum).s("\n");
    o.s("stats triangles=").n(s.triangles);
    o.s(" culled_outside=").n(s.culled_outside);
    o.s(" culled_degenerate=").n(s.culled_degenerate);
    o.s(" static=")
        .n(s.by_class[0])
        .s(" motion=")
        .n(s.by_class[1]);
    o.s(" defocus=")
        .n(s.by_class[2])
        .s(" motion_defocus=")
        .n(s.by_class[3]);
    o.s(" tiles_visited=").n(s.tiles_visited);
    o.s(" tiles_skipped=").n(s.tiles_skipped);
    o.s(" samples_tested=").n(s.samples_tested);
    o.s(" samples_covered=").n(s.samples_covered);
    o.s(" ops_setup=")
        .n(s.ops.setup)
        .s(" ops_bounds=")
        .n(s.ops.bounds);
    o.s(" ops_sample=").n(s.ops.sample).s("\n");
    o.s("stack_peak_bytes ").n(peak() as u64).s("\n");
    o.s("calibration delay(4000000) insn=").n(cal).s("\n");
    o.s("unit ").s(crate::UNIT.unwrap_or("")).s("\n");
    // Only the planar programs name their configuration: the default's program stays as
    // small as before the planar configuration (a constant condition, compiled out).
    if crate::UNIT_PLANAR {
        o.s("unit_prec ").s(crate::PREC).s("\n");
    }
    o.s("prims ")
        .s(uvt_core::config::unit::UNIT_NAMES[crate::PRIMS_SEL])
        .s("\n");
    let c = ticks(syst, || with_unit!(demo::cost::setup, 20).unwrap_or(0));
    o.cost("setup_unit", c);
    let c = ticks(syst, || with_unit!(demo::cost::bounds, 5).unwrap_or(0));
    o.cost("bounds_unit", c);
    let c = ticks(syst, || with_unit!(demo::cost::samples, 2).unwrap_or(0));
    o.cost("sample_unit", c);
    // The measuring loop alone (the same loop, the test replaced by `black_box`): only in
    // the calibration build (`UVT_M4_EMPTY`), so the measured programs stay as they are.
    if crate::EMPTY {
        let c = ticks(syst, || {
            with_unit!(demo::cost::samples_empty, 2).unwrap_or(0)
        });
        o.cost("sample_empty", c);
        let c = ticks(syst, || {
            with_unit!(demo::cost::bounds_empty, 5).unwrap_or(0)
        });
        o.cost("bounds_empty", c);
    }
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}

/// The harness program (`UVT_M4_HARNESS`): the unit program's output, stack painting and
/// timing code with no unit code linked (nothing rendered or measured), so its flash is
/// the part of every unit program that is not the unit.
fn harness_program(mut o: Plain, cal: u64) -> ! {
    // The demo scene (its data and checked constructors), built and not rendered.
    let scene = core::hint::black_box((demo::prims(), demo::viewport(), &demo::SAMPLES));
    let r = core::hint::black_box(demo::DemoResult {
        checksum: u32::from(scene.0.is_ok()),
        stats: uvt_core::Stats::default(),
    });
    o.result(r.checksum, &r.stats);
    o.s("stack_peak_bytes ").n(peak() as u64).s("\n");
    o.s("calibration delay(4000000) insn=").n(cal).s("\n");
    o.s("unit ").s(crate::UNIT.unwrap_or("")).s("\n");
    o.s("harness\n");
    o.cost("none", (0, 0));
    debug::exit(debug::EXIT_SUCCESS);
    loop {
        cortex_m::asm::wfi();
    }
}

#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    hprintln!("panic");
    debug::exit(debug::EXIT_FAILURE);
    loop {
        cortex_m::asm::wfi();
    }
}
