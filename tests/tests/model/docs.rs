//! The documentation points at what exists: every repository path named in a page (README.md,
//! docs/*.md, every README.md of the crates' folders) or in a source comment (`//`, `//!`, `///`
//! of every `.rs`; `#` of `.sh`, `.py`, `.toml`; `//` of `.v`, `.sv`, `.c`, `.h`, `.cpp`)
//! exists, every relative Markdown link resolves, and README.md stays a page a newcomer reads in
//! five minutes (at most 200 lines, the two commands near the top).
//!
//! **What a path is.** A word that starts with a top-level folder of the repository (`core/`,
//! `host/`, `demo/`, `tests/`, `testkit/`, `vectors/`, `docs/`, `ffi/`, `records/`) and goes on
//! in file-name characters, in backticks or not; a sentence's final `.` is not part of it.
//! - With an extension (`core/src/setup/mod.rs`, `host/report/m4.json`) it must be a file.
//! - Without one it must be a folder when it is in backticks, ends with `/` or has three or more
//!   parts (so a renamed folder is caught, while core/reference in a sentence is prose).
//! - `{a,b}` is expanded (`host/report/bench-ste-quick.{md,json}` names two files).
//! - Not paths: globs and ellipses (`*`, `…`), and placeholders — a part written in capitals
//!   that names no file or folder of the repository (`vectors/NAME/`, `host/report/OUT.json`;
//!   `README.md` is a real name) or a one-letter part (`a/b.rs`).
//! - A relative path in backticks with an extension (`hull/wrap.rs`, `verify/planar_corners.rs`)
//!   must be the end of some file's path in the repository (not under `target/` or `out/`, the
//!   build's and the commands' outputs).
//!
//! A failure lists `file:line: path` per missing path.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The top-level folders a repository path starts with.
const TOP: [&str; 10] = [
    "core", "host", "demo", "tests", "testkit", "vectors", "docs", "ffi", "records", "py",
];

/// The repository as the scan sees it: every file under the top-level folders and at the root
/// (build outputs, hidden folders and Python caches left out), by path relative to the root.
struct Repo {
    root: PathBuf,
    files: Vec<String>,
    /// every file and folder name, for telling a placeholder (`NAME`) from a real name
    names: BTreeSet<String>,
}

impl Repo {
    fn read() -> Repo {
        let root = root();
        let mut files = Vec::new();
        let mut names = BTreeSet::new();
        let mut entries: Vec<_> = std::fs::read_dir(&root)
            .expect("repository root")
            .map(|e| e.expect("root entry").path())
            .collect();
        entries.sort();
        for p in entries {
            let name = p.file_name().unwrap().to_string_lossy().to_string();
            if p.is_file() {
                names.insert(name.clone());
                files.push(name);
            } else if TOP.contains(&name.as_str()) {
                names.insert(name.clone());
                walk(&root, &p, &mut files, &mut names);
            }
        }
        Repo { root, files, names }
    }

    fn is_file(&self, p: &str) -> bool {
        self.root.join(p).is_file()
    }

    fn is_dir(&self, p: &str) -> bool {
        self.root.join(p).is_dir()
    }

    /// Whether some file's path ends with `tail` (a whole-part match).
    fn has_tail(&self, tail: &str) -> bool {
        self.files
            .iter()
            .any(|f| f == tail || f.ends_with(&format!("/{tail}")))
    }
}

fn walk(root: &Path, dir: &Path, files: &mut Vec<String>, names: &mut BTreeSet<String>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .expect("folder readable")
        .map(|e| e.expect("entry").path())
        .collect();
    entries.sort();
    for p in entries {
        let name = p.file_name().unwrap().to_string_lossy().to_string();
        if name.starts_with('.') || name == "target" || name == "__pycache__" {
            continue;
        }
        names.insert(name);
        if p.is_dir() {
            walk(root, &p, files, names);
        } else {
            let rel = p
                .strip_prefix(root)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            files.push(rel);
        }
    }
}

/// How a file is read: a Markdown page (every line), or a source whose comments are read
/// (`//` or `#` comments).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Read {
    Page,
    Slashes,
    Hash,
}

fn read_of(path: &str) -> Option<Read> {
    let name = path.rsplit('/').next().unwrap_or(path);
    let ext = name.rsplit_once('.').map(|(_, e)| e)?;
    if path.starts_with("docs/") && ext == "md" || name == "README.md" {
        return Some(Read::Page);
    }
    match ext {
        "rs" | "v" | "sv" | "c" | "h" | "cpp" => Some(Read::Slashes),
        "sh" | "py" | "toml" => Some(Read::Hash),
        _ => None,
    }
}

/// The comment of a source line, from its `//` or `#` on (none inside a string literal).
fn comment(read: Read, line: &str) -> Option<&str> {
    let quotes_even = |pre: &str, q: char| {
        let pre = pre.replace("\\\"", "").replace("'\"'", "");
        pre.chars().filter(|&c| c == q).count() % 2 == 0
    };
    match read {
        Read::Page => Some(line),
        Read::Slashes => line
            .match_indices("//")
            .map(|(i, _)| i)
            .find(|&i| quotes_even(&line[..i], '"'))
            .map(|i| &line[i..]),
        Read::Hash => line
            .char_indices()
            .filter(|&(i, c)| c == '#' && (i == 0 || line[..i].ends_with([' ', '\t'])))
            .map(|(i, _)| i)
            .find(|&i| quotes_even(&line[..i], '"') && quotes_even(&line[..i], '\''))
            .map(|i| &line[i..]),
    }
}

/// What a named path must be.
#[derive(Clone, Debug, PartialEq)]
enum Claim {
    /// a file at this path from the root
    File(String),
    /// a folder at this path from the root
    Dir(String),
    /// the end of some file's path (a relative path in backticks)
    Tail(String),
}

fn path_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || "_./-".contains(c)
}

/// The extension of a path's last part, if it has one (`m4.json`: `json`; `b.1`: none).
fn has_ext(part: &str) -> bool {
    part.rsplit_once('.').is_some_and(|(stem, e)| {
        !stem.is_empty()
            && e.starts_with(|c: char| c.is_ascii_alphabetic())
            && e.chars().all(|c| c.is_ascii_alphanumeric())
    })
}

/// A part that stands for any name: capitals naming nothing in the repository (`NAME`,
/// `OUT.json`), or one lower-case letter (`a/b.rs`).
fn placeholder(repo: &Repo, part: &str) -> bool {
    let stem = part.split('.').next().unwrap_or(part);
    let caps = stem.chars().any(|c| c.is_ascii_uppercase())
        && !stem.chars().any(|c| c.is_ascii_lowercase());
    let letter = stem.len() == 1 && stem.chars().all(|c| c.is_ascii_lowercase());
    (caps && !repo.names.contains(part)) || letter
}

/// `a/{b,c}.rs` as `a/b.rs`, `a/c.rs` (braces not nested).
fn expand(word: &str) -> Vec<String> {
    match (word.find('{'), word.find('}')) {
        (Some(i), Some(j)) if i < j => word[i + 1..j]
            .split(',')
            .flat_map(|alt| expand(&format!("{}{alt}{}", &word[..i], &word[j + 1..])))
            .collect(),
        _ => vec![word.to_string()],
    }
}

/// The claim of a word that starts with a top-level folder (`ticked`: inside backticks).
fn top_claims(repo: &Repo, word: &str, ticked: bool) -> Vec<Claim> {
    let word = word.trim_end_matches('.');
    if word.contains(['*', '…']) || word.contains("...") {
        return Vec::new();
    }
    if word.contains(['{', '}']) {
        if word.matches('{').count() != 1 || word.matches('}').count() != 1 {
            return Vec::new();
        }
        return expand(word)
            .iter()
            .flat_map(|w| top_claims(repo, w, ticked))
            .collect();
    }
    let parts: Vec<&str> = word.split('/').filter(|p| !p.is_empty()).collect();
    if parts.iter().any(|p| placeholder(repo, p)) {
        return Vec::new();
    }
    if has_ext(parts[parts.len() - 1]) {
        vec![Claim::File(word.to_string())]
    } else if ticked || word.ends_with('/') || parts.len() >= 3 {
        vec![Claim::Dir(word.to_string())]
    } else {
        Vec::new()
    }
}

/// The claim of a backticked span that is a relative path with an extension.
fn tail_claim(repo: &Repo, span: &str) -> Option<Claim> {
    let w = span.trim();
    let skip = ["target/", "out/", "/", "."];
    if w.is_empty()
        || !w.contains('/')
        || !w.chars().all(path_char)
        || TOP.iter().any(|t| w.starts_with(&format!("{t}/")))
        || skip.iter().any(|s| w.starts_with(s))
    {
        return None;
    }
    let parts: Vec<&str> = w.split('/').filter(|p| !p.is_empty()).collect();
    if !has_ext(parts[parts.len() - 1]) || parts.iter().any(|p| placeholder(repo, p)) {
        return None;
    }
    Some(Claim::Tail(w.to_string()))
}

/// Every path claim of a file's text, with its line number (1-based). A backtick span may wrap
/// onto the next line; a blank line (or a line that is not a comment) and a fence line end it.
fn claims(repo: &Repo, read: Read, text: &str) -> Vec<(usize, Claim)> {
    let mut out = Vec::new();
    let mut ticked = false;
    let mut span = String::new();
    for (n, line) in text.lines().enumerate() {
        let Some(c) = comment(read, line) else {
            ticked = false;
            continue;
        };
        if c.trim().is_empty() || c.trim_start().starts_with("```") {
            ticked = false;
            continue;
        }
        let chars: Vec<(usize, char)> = c.char_indices().collect();
        let mut k = 0;
        while k < chars.len() {
            let (i, ch) = chars[k];
            if ch == '`' {
                if ticked {
                    out.extend(tail_claim(repo, &span).map(|cl| (n + 1, cl)));
                }
                span.clear();
                ticked = !ticked;
                k += 1;
                continue;
            }
            let starts = (k == 0 || !path_char(chars[k - 1].1))
                && TOP.iter().any(|t| c[i..].starts_with(&format!("{t}/")));
            if !starts {
                if ticked {
                    span.push(ch);
                }
                k += 1;
                continue;
            }
            let mut braces = 0;
            let mut m = k;
            while m < chars.len() {
                let x = chars[m].1;
                if !(path_char(x) || "*…{}".contains(x) || (x == ',' && braces > 0)) {
                    break;
                }
                braces += i32::from(x == '{') - i32::from(x == '}');
                m += 1;
            }
            let end = chars.get(m).map_or(c.len(), |&(j, _)| j);
            let word = &c[i..end];
            out.extend(
                top_claims(repo, word, ticked)
                    .into_iter()
                    .map(|cl| (n + 1, cl)),
            );
            if ticked {
                span.push_str(word);
            }
            k = m;
        }
        if ticked {
            span.push(' ');
        }
    }
    out
}

/// `file:line: path (why)` for every claim of `text` that the repository does not hold; and
/// how many claims were checked.
fn missing_in(repo: &Repo, file: &str, read: Read, text: &str) -> (Vec<String>, usize) {
    let all = claims(repo, read, text);
    let n = all.len();
    let missing = all
        .into_iter()
        .filter_map(|(line, c)| match c {
            Claim::File(p) if !repo.is_file(&p) => {
                Some(format!("{file}:{line}: {p} (no such file)"))
            }
            Claim::Dir(p) if !repo.is_dir(&p) => {
                Some(format!("{file}:{line}: {p} (no such folder)"))
            }
            Claim::Tail(p) if !repo.has_tail(&p) => {
                Some(format!("{file}:{line}: {p} (no file's path ends so)"))
            }
            _ => None,
        })
        .collect();
    (missing, n)
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

/// Every scanned file of `repo` read as `which` (pages, or sources) with its missing paths.
fn scan(repo: &Repo, pages: bool) -> (Vec<String>, usize, usize) {
    let mut missing = Vec::new();
    let (mut files, mut checked) = (0, 0);
    for f in &repo.files {
        let Some(read) = read_of(f) else { continue };
        if (read == Read::Page) != pages {
            continue;
        }
        let text = std::fs::read_to_string(repo.root.join(f)).expect("text file");
        let (m, n) = missing_in(repo, f, read, &text);
        files += 1;
        checked += n;
        missing.extend(m);
        if pages {
            let dir = repo.root.join(f);
            let dir = dir.parent().unwrap_or(Path::new("."));
            for l in links(&text) {
                checked += 1;
                if !dir.join(&l).exists() {
                    missing.push(format!("{f}: link ({l})"));
                }
            }
        }
    }
    (missing, files, checked)
}

#[test]
fn every_named_path_and_link_exists() {
    let repo = Repo::read();
    let (missing, files, checked) = scan(&repo, true);
    assert!(
        files >= 10 && checked > 300,
        "only {checked} paths and links in {files} pages: the scan is broken"
    );
    assert!(
        missing.is_empty(),
        "paths and links that do not exist:\n{}",
        missing.join("\n")
    );
}

#[test]
fn every_path_named_in_a_comment_exists() {
    let repo = Repo::read();
    let (missing, files, checked) = scan(&repo, false);
    assert!(
        files > 200 && checked > 150,
        "only {checked} paths in the comments of {files} sources: the scan is broken"
    );
    assert!(
        missing.is_empty(),
        "paths named in comments that do not exist:\n{}",
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

/// The scan finds what it should, and a missing path fails it with its file and line (so an
/// empty result above means something).
#[test]
fn a_missing_path_is_reported() {
    let repo = Repo::read();
    let page = "Real: `core/src/setup/mod.rs`, host/src/frame/ and `core/src/bounds` and \
                `hull/wrap.rs`; docs/bounds.md.\n\
                Stale: core/src/gone.rs, `core/src/strategies`, core/src/bounds/gone/deeper and\n\
                `hull/reference.rs`, host/report/bench-ste-quick.{md,txt}.\n\
                Not paths: `vectors/NAME/manifest.json`, host/report/OUT.json, core/src/*.rs,\n\
                core/src/…, `a/b.rs`, core/reference, 9 M tests/s, `target/release/uvt.h`.\n";
    let (missing, checked) = missing_in(&repo, "page.md", Read::Page, page);
    assert_eq!(
        missing,
        [
            "page.md:2: core/src/gone.rs (no such file)",
            "page.md:2: core/src/strategies (no such folder)",
            "page.md:2: core/src/bounds/gone/deeper (no such folder)",
            "page.md:3: hull/reference.rs (no file's path ends so)",
            "page.md:3: host/report/bench-ste-quick.txt (no such file)",
        ]
    );
    assert_eq!(checked, 11, "{:?}", claims(&repo, Read::Page, page));
    let rs = "let s = \"core/src/not_a_comment.rs\"; // see `host/src/cost.rs`\n\
              /// [`x`] (`core/src/setup/mod.rs`)\n";
    let (missing, _) = missing_in(&repo, "x.rs", Read::Slashes, rs);
    assert_eq!(missing, ["x.rs:1: host/src/cost.rs (no such file)"]);
    let sh = "echo \"# core/src/gone.sh\" ${#a[@]} # writes host/report/gone.json\n";
    let (missing, _) = missing_in(&repo, "x.sh", Read::Hash, sh);
    assert_eq!(missing, ["x.sh:1: host/report/gone.json (no such file)"]);
    assert_eq!(
        links("[a](docs/units.md#x) [b](https://x.y) [c](#anchor)"),
        ["docs/units.md"]
    );
}
