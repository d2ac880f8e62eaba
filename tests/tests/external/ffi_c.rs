//! The C library from C and C++: the generated header compiles warning-free as C11 and C++17,
//! `ffi/examples/first.c` (the recipe of docs/rtl.md) links against `libuvt_ffi.a` and prints
//! the model's answers, the typed API agrees with the record, and a refused record's message
//! names the field.

use std::process::Command;

#[test]
fn the_c_example_builds_and_runs() {
    let lib = uvt_tests::ffi::lib();
    let root = uvt_tests::ffi::root();
    let dir = tempfile::tempdir().unwrap();
    let exe = dir.path().join("first");
    for (compiler, std, src) in [
        ("cc", "-std=c11", root.join("ffi/examples/first.c")),
        ("c++", "-std=c++17", {
            let p = dir.path().join("first.cpp");
            std::fs::copy(root.join("ffi/examples/first.c"), &p).unwrap();
            p
        }),
    ] {
        let o = Command::new(compiler)
            .args([std, "-O2", "-Wall", "-Wextra", "-Werror", "-I"])
            .arg(&lib.include)
            .arg(&src)
            .arg(&lib.static_lib)
            .args(["-lpthread", "-ldl", "-lm", "-o"])
            .arg(&exe)
            .output()
            .expect("a C compiler (gcc)");
        assert!(
            o.status.success(),
            "{compiler} {}: {}",
            src.display(),
            String::from_utf8_lossy(&o.stderr)
        );
        let run = Command::new(&exe).output().unwrap();
        let out = String::from_utf8_lossy(&run.stdout);
        assert!(
            run.status.success(),
            "{out}{}",
            String::from_utf8_lossy(&run.stderr)
        );
        assert_eq!(
            out.lines().filter(|l| l.starts_with("record ")).count(),
            4,
            "{out}"
        );
        let typed = out
            .lines()
            .find(|l| l.starts_with("typed: 0 "))
            .expect(&out);
        // "typed: 0 covered C depth D (record: C D)"
        let w: Vec<&str> = typed.split_whitespace().collect();
        assert_eq!(
            (w[3], w[5]),
            (w[7].trim_start_matches('('), w[8].trim_end_matches(')')),
            "{typed}"
        );
        assert!(
            out.contains("flipped class: -4") && out.contains("field class"),
            "{out}"
        );
    }
}
