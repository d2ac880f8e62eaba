//! For bare-metal targets only: put `memory.x` on the linker path and link the examples with
//! cortex-m-rt's `link.x`. Host builds are untouched. On every target: copy the workload file
//! named by `UVT_M4_WORKLOAD` (if any; else an empty file) to `OUT_DIR/workload.bin`, which the
//! bare-metal `m4_stages` links in.
use std::{env, fs, path::PathBuf};

fn main() {
    println!("cargo:rerun-if-changed=memory.x");
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-env-changed=UVT_M4_WORKLOAD");
    let out = PathBuf::from(env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    let work = match env::var_os("UVT_M4_WORKLOAD") {
        Some(p) => {
            println!("cargo:rerun-if-changed={}", PathBuf::from(&p).display());
            fs::read(&p)
                .unwrap_or_else(|e| panic!("UVT_M4_WORKLOAD {}: {e}", PathBuf::from(&p).display()))
        }
        None => Vec::new(),
    };
    fs::write(out.join("workload.bin"), work).expect("write workload.bin");
    if env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("none") {
        fs::write(out.join("memory.x"), include_bytes!("memory.x")).expect("write memory.x");
        println!("cargo:rustc-link-search={}", out.display());
        println!("cargo:rustc-link-arg-examples=-Tlink.x");
    }
}
