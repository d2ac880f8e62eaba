//! The documentation points at what exists: every repository path a page names in backticks
//! (`core/src/…`, `host/…`, `demo/…`, `tests/…`, `testkit/…`, `vectors/…`, `docs/…`, `ffi/…`,
//! `records/…`) exists,
//! every relative Markdown link resolves, and README.md stays a page a newcomer reads in five
//! minutes (at most 200 lines, the two commands near the top). Pages: README.md, docs/*.md and
//! the crate READMEs.

use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The pages checked.
fn pages() -> Vec<PathBuf> {
    let r = root();
    let mut v = vec![
        r.join("README.md"),
        r.join("core/README.md"),
        r.join("vectors/README.md"),
        r.join("vectors/dpi/README.md"),
        r.join("vectors/cocotb/README.md"),
        r.join("host/scenes/README.md"),
    ];
    let mut docs: Vec<PathBuf> = std::fs::read_dir(r.join("docs"))
        .expect("docs/ exists")
        .map(|e| e.expect("docs entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    docs.sort();
    v.extend(docs);
    v
}

/// Repository paths named in backticks: a top-level folder of the repository, then a path of
/// file-name characters (globs and placeholders like `{a,b}` or `*` are not paths).
fn named_paths(text: &str) -> Vec<String> {
    const TOP: [&str; 9] = [
        "core/", "host/", "demo/", "tests/", "testkit/", "vectors/", "docs/", "ffi/", "records/",
    ];
    let mut out = Vec::new();
    for span in text.split('`').skip(1).step_by(2) {
        let word = span.split_whitespace().next().unwrap_or("");
        let ok = |c: char| c.is_ascii_alphanumeric() || "/._-".contains(c);
        if TOP.iter().any(|t| word.starts_with(t)) && word.chars().all(ok) && word.contains('.') {
            out.push(word.trim_end_matches('.').to_string());
        }
    }
    out
}

/// Relative link targets of `[text](target)` (not URLs, not anchors alone).
fn links(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    for part in text.split("](").skip(1) {
        let Some(end) = part.find(')') else { continue };
        let target = &part[..end];
        let target = target.split('#').next().unwrap_or("");
        if target.is_empty() || target.contains("://") || target.contains(' ') {
            continue;
        }
        out.push(target.to_string());
    }
    out
}

#[test]
fn every_named_path_and_link_exists() {
    let r = root();
    let mut missing = Vec::new();
    let mut checked = 0;
    for page in pages() {
        let text = std::fs::read_to_string(&page).expect("page readable");
        let rel = page.strip_prefix(&r).unwrap_or(&page).display().to_string();
        for p in named_paths(&text) {
            checked += 1;
            if !r.join(&p).exists() {
                missing.push(format!("{rel}: `{p}`"));
            }
        }
        let dir = page.parent().unwrap_or(Path::new("."));
        for l in links(&text) {
            checked += 1;
            if !dir.join(&l).exists() {
                missing.push(format!("{rel}: link ({l})"));
            }
        }
    }
    assert!(
        checked > 100,
        "only {checked} paths and links found: the scan is broken"
    );
    assert!(
        missing.is_empty(),
        "paths and links that do not exist:\n{}",
        missing.join("\n")
    );
}

#[test]
fn readme_is_short_and_starts_with_the_two_commands() {
    let text = std::fs::read_to_string(root().join("README.md")).expect("README.md");
    let n = text.lines().count();
    assert!(
        n <= 200,
        "README.md has {n} lines (at most 200; the rest belongs in docs/)"
    );
    let head: String = text.lines().take(40).collect::<Vec<_>>().join("\n");
    for cmd in [
        "cargo run --release -p uvt-host -- render --out out",
        "bash tests/run.sh",
    ] {
        assert!(
            head.contains(cmd),
            "README.md's first 40 lines lack `{cmd}`"
        );
    }
}

/// The scan finds what it should (so an empty result above means something).
#[test]
fn the_scan_finds_paths_and_links() {
    let t = "see `core/src/setup/mod.rs` and `host/src/x.rs`, not `core/` or `{a,b}.rs`; \
             [a](docs/units.md#x) [b](https://x.y) [c](#anchor)";
    assert_eq!(named_paths(t), ["core/src/setup/mod.rs", "host/src/x.rs"]);
    assert_eq!(links(t), ["docs/units.md"]);
}
