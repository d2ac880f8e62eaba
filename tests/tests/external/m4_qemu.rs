//! The core on both emulated thumbv7 profiles: `demo/examples/m4_render/main.rs` is built for
//! `thumbv7em-none-eabihf` (Cortex-M4F, QEMU `mps2-an386`) and for `thumbv7m-none-eabi`
//! (Cortex-M3 without FPU, QEMU `mps2-an385`), run under `qemu-system-arm` with a time limit, and
//! its checksum and counters must equal the host's for the same scene through the same core.
//! Each unit variant's program (`UVT_M4_UNIT`, Cortex-M4F only) must equal the host render of
//! the same prims on the same unit; so must the full, motion-only and static-only programs at
//! the planar static configuration (`UVT_M4_PREC=planar-16-16-16-20`). The specialised programs
//! (motion-only: `motion_unit.rs`; static-only at planar: `static_unit.rs`) also render the
//! full unit's checksum and covered count on the same prims.

use std::path::PathBuf;
use std::process::Command;
use std::sync::Mutex;

/// The Cortex-M4F builds share one target directory and one output path: one build-and-run at
/// a time (`reports.rs`, in the same test binary, builds there too and holds it as well).
pub(crate) static M4F: Mutex<()> = Mutex::new(());

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The lines the program prints for checksum and counters, computed on the host.
fn host_lines() -> (String, String) {
    lines(
        uvt_demo::render::<uvt_core::DefaultPrecision, uvt_core::Full, uvt_core::Full>()
            .expect("demo renders on the host"),
    )
}

fn lines(r: uvt_demo::DemoResult) -> (String, String) {
    let s = r.stats;
    (
        format!("checksum {:#010x}", r.checksum),
        format!(
            "stats triangles={} culled_outside={} culled_degenerate={} static={} motion={} defocus={} motion_defocus={} tiles_visited={} tiles_skipped={} samples_tested={} samples_covered={} ops_setup={} ops_bounds={} ops_sample={}",
            s.triangles, s.culled_outside, s.culled_degenerate, s.by_class[0], s.by_class[1], s.by_class[2], s.by_class[3],
            s.tiles_visited, s.tiles_skipped, s.samples_tested, s.samples_covered, s.ops.setup, s.ops.bounds, s.ops.sample
        ),
    )
}

/// Build the program for `target`, run it on QEMU's `machine` with `cpu`, and check it against the
/// host.
fn bit_exact_under_qemu(target: &str, machine: &str, cpu: &str) {
    let _one = M4F.lock().unwrap_or_else(|e| e.into_inner());
    let text = build_and_run(target, machine, cpu, None);
    check_output(&text, host_lines(), target, machine, cpu);
}

/// Build `m4_render` for `target` (as unit `unit`'s program, or the default program) and run it
/// on QEMU's `machine`; its standard output.
fn build_and_run(target: &str, machine: &str, cpu: &str, unit: Option<&str>) -> String {
    build_and_run_at(target, machine, cpu, unit, None)
}

/// [`build_and_run`] at configuration `prec` (`UVT_M4_PREC`; `None`: the default).
fn build_and_run_at(
    target: &str,
    machine: &str,
    cpu: &str,
    unit: Option<&str>,
    prec: Option<&str>,
) -> String {
    // Build in a separate target directory so the outer `cargo test` lock is not contended.
    let tdir = root().join("target").join("m4-test");
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let mut cmd = Command::new(cargo);
    match unit {
        Some(u) => cmd.env("UVT_M4_UNIT", u),
        None => cmd.env_remove("UVT_M4_UNIT"),
    };
    match prec {
        Some(p) => cmd.env("UVT_M4_PREC", p),
        None => cmd.env_remove("UVT_M4_PREC"),
    };
    let st = cmd
        .current_dir(root())
        .args([
            "build",
            "--release",
            "-p",
            "uvt-demo",
            "--example",
            "m4_render",
            "--target",
            target,
        ])
        .env("CARGO_TARGET_DIR", &tdir)
        .status()
        .expect("run cargo");
    assert!(
        st.success(),
        "building the bare-metal program for {target} failed (is the target installed? tests/run.sh installs it)"
    );
    let elf = tdir.join(target).join("release/examples/m4_render");
    let out = Command::new("timeout")
        .args(["120", "qemu-system-arm", "-machine", machine, "-cpu", cpu, "-nographic", "-monitor", "none",
               "-semihosting-config", "enable=on,target=native", "-icount", "shift=0", "-kernel"])
        .arg(&elf)
        .output()
        .expect("qemu-system-arm not runnable: tests/run.sh installs the Debian package qemu-system-arm");
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "qemu {machine} ({target}, unit {unit:?}) exited {:?} (124 = time limit)\nstdout:\n{text}\nstderr:\n{}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    text
}

/// The program's checksum and counters lines equal the host's; calibration and stack
/// plausible.
fn check_output(text: &str, host: (String, String), target: &str, machine: &str, cpu: &str) {
    let line = |p: &str| {
        text.lines()
            .find(|l| l.starts_with(p))
            .unwrap_or_else(|| panic!("no '{p}' line in:\n{text}"))
            .to_string()
    };
    let (checksum, stats) = host;
    assert_eq!(
        line("checksum "),
        checksum,
        "image checksum differs between {cpu} ({target}) and host"
    );
    assert_eq!(
        line("stats "),
        stats,
        "counters differ between {cpu} ({target}) and host"
    );
    // The cost measurement's calibration: 8,000,002 instructions, SysTick resolution 40 (both
    // boards clock SysTick at 25 MHz; this check is what establishes it on each run).
    let cal: u64 = line("calibration ")
        .rsplit('=')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(
        cal.abs_diff(8_000_002) <= 80,
        "instruction calibration off on {machine}: {cal}"
    );
    let stack: u64 = line("stack_peak_bytes ")
        .rsplit(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(
        stack > 1024 && stack < 1 << 20,
        "implausible stack peak {stack} on {machine}"
    );
}

#[test]
fn cortex_m4f_under_qemu_is_bit_exact_with_host() {
    bit_exact_under_qemu("thumbv7em-none-eabihf", "mps2-an386", "cortex-m4");
}

#[test]
fn cortex_m3_under_qemu_is_bit_exact_with_host() {
    bit_exact_under_qemu("thumbv7m-none-eabi", "mps2-an385", "cortex-m3");
}

/// Each unit variant's Cortex-M4F program (the demo prims the unit accepts, default
/// configuration) against the host render of the same prims on the same unit.
#[test]
fn cortex_m4f_unit_programs_are_bit_exact_with_host() {
    use uvt_core::{DefocusOnly, Full, MotionOnly, StaticOnly, Unit};
    use uvt_demo::render;
    let _one = M4F.lock().unwrap_or_else(|e| e.into_inner());
    let host = [
        (
            Full::NAME,
            render::<uvt_core::DefaultPrecision, Full, Full>(),
        ),
        (
            MotionOnly::NAME,
            render::<uvt_core::DefaultPrecision, MotionOnly, MotionOnly>(),
        ),
        (
            DefocusOnly::NAME,
            render::<uvt_core::DefaultPrecision, DefocusOnly, DefocusOnly>(),
        ),
        (
            StaticOnly::NAME,
            render::<uvt_core::DefaultPrecision, StaticOnly, StaticOnly>(),
        ),
    ];
    for (name, r) in host {
        let r = r.unwrap_or_else(|e| panic!("unit {name}: host render: {e}"));
        let text = build_and_run(
            "thumbv7em-none-eabihf",
            "mps2-an386",
            "cortex-m4",
            Some(name),
        );
        assert!(
            text.lines().any(|l| l == format!("unit {name}")),
            "the program was not built for unit {name}:\n{text}"
        );
        let cpu = format!("cortex-m4 (unit {name})");
        check_output(&text, lines(r), "thumbv7em-none-eabihf", "mps2-an386", &cpu);
        if name == MotionOnly::NAME {
            let full = uvt_demo::render::<uvt_core::DefaultPrecision, Full, MotionOnly>()
                .unwrap_or_else(|e| panic!("full unit on the motion-only prims: {e}"));
            matches_full(&text, &full, "motion-only program");
        }
    }
}

/// A specialised unit program's output has the full unit's checksum and covered count on the
/// same prims (`full`).
fn matches_full(text: &str, full: &uvt_demo::DemoResult, what: &str) {
    let want = format!("checksum {:#010x}", full.checksum);
    assert!(
        text.lines().any(|l| l == want),
        "{what} against the full unit on its prims: expected '{want}' ({}), program \
         output:\n{text}",
        full.checksum
    );
    let covered = format!(" samples_covered={} ", full.stats.samples_covered);
    assert!(
        text.lines()
            .any(|l| l.starts_with("stats ") && l.contains(&covered)),
        "{what}: expected '{covered}' (the full unit's), program output:\n{text}"
    );
}

/// The full, motion-only and static-only Cortex-M4F programs at the planar static
/// configuration (`planar-16-16-16-20`) against the host render of the same prims on the same
/// unit at `PlanarPrecision`; the specialised programs also against the host's full unit on
/// their prims (checksum and covered count).
#[test]
fn cortex_m4f_planar_unit_programs_are_bit_exact_with_host() {
    use uvt_core::{Full, MotionOnly, PlanarPrecision, StaticOnly, Unit};
    use uvt_demo::render;
    let _one = M4F.lock().unwrap_or_else(|e| e.into_inner());
    let host = [
        (Full::NAME, render::<PlanarPrecision, Full, Full>()),
        (
            MotionOnly::NAME,
            render::<PlanarPrecision, MotionOnly, MotionOnly>(),
        ),
        (
            StaticOnly::NAME,
            render::<PlanarPrecision, StaticOnly, StaticOnly>(),
        ),
    ];
    for (name, r) in host {
        let r = r.unwrap_or_else(|e| panic!("unit {name} (planar): host render: {e}"));
        let text = build_and_run_at(
            "thumbv7em-none-eabihf",
            "mps2-an386",
            "cortex-m4",
            Some(name),
            Some("planar-16-16-16-20"),
        );
        assert!(
            text.lines().any(|l| l == "unit_prec planar-16-16-16-20"),
            "the program was not built at planar-16-16-16-20:\n{text}"
        );
        let cpu = format!("cortex-m4 (unit {name}, planar-16-16-16-20)");
        check_output(&text, lines(r), "thumbv7em-none-eabihf", "mps2-an386", &cpu);
        // The specialised programs (static-only: `static_unit.rs`, motion-only:
        // `motion_unit.rs`): image and covered count are the full unit's on the same prims.
        let full = if name == StaticOnly::NAME {
            render::<PlanarPrecision, Full, StaticOnly>()
        } else if name == MotionOnly::NAME {
            render::<PlanarPrecision, Full, MotionOnly>()
        } else {
            continue;
        };
        let full = full.unwrap_or_else(|e| panic!("full unit on the {name} prims (planar): {e}"));
        matches_full(&text, &full, &format!("{name} planar program"));
    }
}

/// The symbol names (raw, mangled) of the unit program `unit` built at `prec` for the
/// Cortex-M4F (the build of [`build_and_run_at`], read with `readelf`).
fn symbols_of(unit: &str, prec: Option<&str>) -> String {
    let _ = build_and_run_at(
        "thumbv7em-none-eabihf",
        "mps2-an386",
        "cortex-m4",
        Some(unit),
        prec,
    );
    let elf = root()
        .join("target")
        .join("m4-test")
        .join("thumbv7em-none-eabihf/release/examples/m4_render");
    let out = Command::new("readelf")
        .args(["-sW"])
        .arg(&elf)
        .output()
        .expect("readelf not runnable (Debian package binutils)");
    assert!(out.status.success(), "readelf {}", elf.display());
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// What `Renderer<_, _, P, U>` links is the pipeline `uvt_core::units::select` picks, checked
/// by symbol in the Cortex-M4F unit programs: the static-only program at the planar
/// configuration links the static-only unit's code and no bounded sample test, no general
/// pipeline and no Laine 2011 bounds; the motion-only programs (default and planar) link the
/// motion-only unit's code and neither the general pipeline nor Laine 2011 bounds. The full
/// unit's program links the symbols the others must not (so each absence is a real one).
#[test]
fn cortex_m4f_unit_programs_link_the_picked_pipeline() {
    let _one = M4F.lock().unwrap_or_else(|e| e.into_inner());
    const BOUNDED: &str = "6sample7bounded";
    const GENERAL: &str = "5units7general";
    const LAINE: &str = "Laine2011";
    const STATIC: &str = "5units11static_only";
    const MOTION: &str = "5units11motion_only";
    let planar = Some("planar-16-16-16-20");
    let full = symbols_of("full", planar);
    for s in [BOUNDED, LAINE] {
        assert!(
            full.contains(s),
            "the full unit's program has no symbol with {s:?}"
        );
    }
    let st = symbols_of("static-only", planar);
    assert!(
        st.contains(STATIC),
        "static-only@planar: no static-only unit symbol"
    );
    for s in [BOUNDED, GENERAL, LAINE, MOTION] {
        assert!(
            !st.contains(s),
            "static-only@planar links a symbol with {s:?}"
        );
    }
    for prec in [None, planar] {
        let mo = symbols_of("motion-only", prec);
        assert!(
            mo.contains(MOTION),
            "motion-only ({prec:?}): no motion-only unit symbol"
        );
        for s in [GENERAL, LAINE] {
            assert!(
                !mo.contains(s),
                "motion-only ({prec:?}) links a symbol with {s:?}"
            );
        }
    }
}
