//! The committed header `include/uvt.h` is what cbindgen makes of the crate: a changed function
//! without a regenerated header fails here. `UVT_BLESS=1` rewrites it.

use std::path::PathBuf;

#[test]
fn header_is_current() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let cfg = cbindgen::Config::from_file(dir.join("cbindgen.toml")).expect("cbindgen.toml");
    let mut made = Vec::new();
    cbindgen::Builder::new()
        .with_config(cfg)
        .with_src(dir.join("src/lib.rs"))
        .generate()
        .expect("cbindgen parses the crate")
        .write(&mut made);
    let made = String::from_utf8(made).expect("utf-8");
    let path = dir.join("include/uvt.h");
    if std::env::var("UVT_BLESS").as_deref() == Ok("1") {
        std::fs::write(&path, &made).expect("write the header");
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    if committed != made {
        let first = committed
            .lines()
            .zip(made.lines())
            .position(|(a, b)| a != b)
            .map_or(committed.lines().count().min(made.lines().count()), |i| i);
        panic!(
            "ffi/include/uvt.h is not what cbindgen makes of ffi/src (first difference at line {}): \
             regenerate with `UVT_BLESS=1 cargo test -p uvt-ffi --test c_api header::`",
            first + 1
        );
    }
    for f in [
        "uvt_bsample",
        "uvt_psample",
        "uvt_gen",
        "uvt_tri_new",
        "uvt_last_error",
    ] {
        assert!(
            made.contains(&format!("{f}(")),
            "{f} missing from the header"
        );
    }
}
