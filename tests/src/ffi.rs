//! The C library for the RTL tests that link the model (`tests/tests/external/dpi.rs`,
//! `tests/tests/external/cocotb.rs`): `cargo build --release -p uvt-ffi` once per test process, into the
//! workspace's own target folder, and the paths of what it made.

use std::path::PathBuf;
use std::process::Command;
use std::sync::OnceLock;

/// What the build made: the static library, the shared library and the header folder.
#[derive(Clone, Debug)]
pub struct Lib {
    /// `target/release/libuvt_ffi.a`
    pub static_lib: PathBuf,
    /// `target/release/libuvt_ffi.so`
    pub shared_lib: PathBuf,
    /// `ffi/include` (holds `uvt.h`)
    pub include: PathBuf,
}

/// The workspace root.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .canonicalize()
        .expect("workspace root")
}

/// Build the library (once per process; cargo makes it a no-op when it is current). Panics with
/// cargo's output if the build fails.
pub fn lib() -> Lib {
    static LIB: OnceLock<Lib> = OnceLock::new();
    LIB.get_or_init(|| {
        let root = root();
        let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
        let o = Command::new(cargo)
            .current_dir(&root)
            .args(["build", "--locked", "--release", "-p", "uvt-ffi"])
            .output()
            .expect("cargo");
        assert!(
            o.status.success(),
            "cargo build --release -p uvt-ffi failed: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        let target = std::env::var("CARGO_TARGET_DIR")
            .map(PathBuf::from)
            .unwrap_or_else(|_| root.join("target"));
        Lib {
            static_lib: target.join("release/libuvt_ffi.a"),
            shared_lib: target.join("release/libuvt_ffi.so"),
            include: root.join("ffi/include"),
        }
    })
    .clone()
}
