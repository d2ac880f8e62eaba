//! The bare-metal Cortex-M program of `m4_stages` (`main.rs`): the workload linked in, SysTick
//! laps under QEMU `-icount shift=0`, output over semihosting.

use cortex_m::peripheral::syst::SystClkSource;
use cortex_m::peripheral::SYST;
use cortex_m_rt::entry;
use cortex_m_semihosting::{debug, hprintln};
use uvt_demo::workload::Workload;

/// Instructions per SysTick tick under `-icount shift=0` on mps2-an386 (25 MHz SYSCLK).
const INSN_PER_TICK: u64 = 40;

/// The workload file of `UVT_M4_WORKLOAD` (copied by `build.rs`; empty without it).
static WORKLOAD: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/workload.bin"));

#[entry]
fn main() -> ! {
    let Some(mut cp) = cortex_m::Peripherals::take() else {
        debug::exit(debug::EXIT_FAILURE);
        loop {
            cortex_m::asm::wfi();
        }
    };
    cp.SYST.set_clock_source(SystClkSource::Core);
    cp.SYST.set_reload(0x00ff_ffff);
    cp.SYST.clear_current();
    cp.SYST.enable_counter();
    // Instructions since the previous call (the 24-bit down-counter, wrapping: every lap is
    // far below its 671 M-instruction period).
    let mut last = SYST::get_current();
    let mut lap = move || {
        let now = SYST::get_current();
        let t = u64::from(last.wrapping_sub(now) & 0x00ff_ffff);
        last = now;
        t * INSN_PER_TICK
    };
    // Calibration: delay(n) runs n + 1 iterations of a 2-instruction loop.
    let _ = lap();
    cortex_m::asm::delay(4_000_000);
    hprintln!("calibration delay(4000000) insn={}", lap());
    let res = Workload::parse(WORKLOAD).and_then(|w| {
        let h = w.header();
        hprintln!("workload every={} spp={}", h.every, h.spp);
        let z = crate::run_all(&w, &mut lap, |n, k, c| line!(hprintln, n, k, c))?;
        zline!(hprintln, h.bounds_tile, &z);
        Ok(())
    });
    match res {
        Ok(()) => debug::exit(debug::EXIT_SUCCESS),
        Err(e) => {
            hprintln!("error {}", e);
            debug::exit(debug::EXIT_FAILURE);
        }
    }
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
