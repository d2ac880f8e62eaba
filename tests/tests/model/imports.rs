//! Import circles: no source file of a listed crate may, directly or through others, use
//! something from a file that uses something from it. Files are nodes; an edge runs from a file
//! to every module file it names in a path: `use crate::…`, `use super::…`, `use self::…` (grouped
//! forms `use crate::{a::b, c::{d, e}}` included), a path starting with a module the file declares
//! (`mod x;` … `use x::Y`), and the same paths inline in code (`crate::x::f()`, and `x::f()` after
//! `use crate::x;` or a glob that brings module `x` in). Comments, string and char literals are
//! stripped first, and so are `#[cfg(test)]` items: a test module may use any file. A path
//! resolves to the deepest existing module file (`a/b.rs` or `a/b/mod.rs`); `crate::X` naming a
//! root re-export resolves to `lib.rs`, and as the root declares every module, any import of it is
//! a circle (`x.rs -> lib.rs (X) -> x.rs`). `mod x;` declarations are not edges (the root's own
//! `pub use` facade is not checked either), nor is `$crate::…` in a macro body (it resolves where
//! the macro is expanded); an edge from a file to itself is ignored. Every circle
//! (strongly connected component, Tarjan) is printed as `a.rs -> b.rs (names a.rs uses) -> … ->
//! a.rs`, one line per edge of the circle.
//!
//! `UVT_IMPORTS=core/src,host/src` checks those folders instead of [`CRATES`];
//! `UVT_IMPORTS_DUMP=1` (with `-- --nocapture`) prints every edge.
use std::collections::{BTreeMap, BTreeSet, VecDeque};
use std::path::Path;

/// The crate source folders (relative to the workspace root) that must have no import circle.
/// Every crate of the workspace.
const CRATES: &[&str] = &[
    "core/src",
    "demo/src",
    "ffi/src",
    "host/src",
    "records/src",
    "testkit/src",
];

/// Root files of a crate folder that are not part of its library (binaries).
const SKIP: &[&str] = &["main.rs"];

/// What the source file (a key of [`Graph::edges`]) uses from each file it imports.
type Uses = BTreeMap<String, BTreeSet<String>>;

/// The file-level import graph of one crate folder.
struct Graph {
    /// Every file, by path relative to the folder (`a/b.rs`), with the names it uses per target.
    edges: BTreeMap<String, Uses>,
}

/// One lexical token of stripped source.
#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Ident(String),
    Path, // `::`
    Punct(char),
}

/// Source with comments, string and char literals blanked (lifetimes kept).
fn strip(src: &str) -> String {
    let c: Vec<char> = src.chars().collect();
    let mut out = String::with_capacity(src.len());
    let ident = |ch: char| ch.is_alphanumeric() || ch == '_';
    let mut i = 0;
    while i < c.len() {
        let prev_ident = i > 0 && ident(c[i - 1]);
        if c[i] == '/' && c.get(i + 1) == Some(&'/') {
            while i < c.len() && c[i] != '\n' {
                i += 1;
            }
        } else if c[i] == '/' && c.get(i + 1) == Some(&'*') {
            let mut depth = 0;
            while i < c.len() {
                if c[i] == '/' && c.get(i + 1) == Some(&'*') {
                    depth += 1;
                    i += 2;
                } else if c[i] == '*' && c.get(i + 1) == Some(&'/') {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
            out.push(' ');
        } else if c[i] == 'r'
            && (!prev_ident || (c[i - 1] == 'b' && (i < 2 || !ident(c[i - 2]))))
            && matches!(c.get(i + 1), Some('"') | Some('#'))
        {
            // raw string r"…", r#"…"# (or a raw identifier r#name, kept)
            let mut j = i + 1;
            while c.get(j) == Some(&'#') {
                j += 1;
            }
            if c.get(j) != Some(&'"') {
                out.push(c[i]);
                i += 1;
                continue;
            }
            let hashes = j - i - 1;
            j += 1;
            while j < c.len() && !(c[j] == '"' && (1..=hashes).all(|k| c.get(j + k) == Some(&'#')))
            {
                j += 1;
            }
            i = j + 1 + hashes;
            out.push(' ');
        } else if c[i] == '"' {
            i += 1;
            while i < c.len() && c[i] != '"' {
                i += if c[i] == '\\' { 2 } else { 1 };
            }
            i += 1;
            out.push(' ');
        } else if c[i] == '\'' && (c.get(i + 1) == Some(&'\\') || c.get(i + 2) == Some(&'\'')) {
            // char literal ('x', '\n', '\''); a lifetime or label ('a) is kept
            i += 2;
            while i < c.len() && c[i] != '\'' {
                i += if c[i] == '\\' { 2 } else { 1 };
            }
            i += 1;
            out.push(' ');
        } else {
            out.push(c[i]);
            i += 1;
        }
    }
    out
}

fn tokens(src: &str) -> Vec<Tok> {
    let c: Vec<char> = strip(src).chars().collect();
    let mut t = Vec::new();
    let mut i = 0;
    while i < c.len() {
        if c[i].is_alphanumeric() || c[i] == '_' {
            let s = i;
            while i < c.len() && (c[i].is_alphanumeric() || c[i] == '_') {
                i += 1;
            }
            t.push(Tok::Ident(c[s..i].iter().collect()));
        } else if c[i] == ':' && c.get(i + 1) == Some(&':') {
            t.push(Tok::Path);
            i += 2;
        } else {
            if !c[i].is_whitespace() {
                t.push(Tok::Punct(c[i]));
            }
            i += 1;
        }
    }
    without_tests(t)
}

/// Tokens without `#[cfg(test)]` items.
fn without_tests(t: Vec<Tok>) -> Vec<Tok> {
    let attr: Vec<Tok> = ["#", "[", "cfg", "(", "test", ")", "]"]
        .iter()
        .map(|s| match *s {
            "cfg" | "test" => Tok::Ident(s.to_string()),
            _ => Tok::Punct(s.chars().next().unwrap()),
        })
        .collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < t.len() {
        if t[i..].starts_with(&attr) {
            i += attr.len();
            let mut depth = 0;
            while i < t.len() {
                match t[i] {
                    Tok::Punct('{') => depth += 1,
                    Tok::Punct('}') => {
                        depth -= 1;
                        if depth == 0 {
                            i += 1;
                            break;
                        }
                    }
                    Tok::Punct(';') if depth == 0 => {
                        i += 1;
                        break;
                    }
                    _ => {}
                }
                i += 1;
            }
            continue;
        }
        out.push(t[i].clone());
        i += 1;
    }
    out
}

fn is(t: Option<&Tok>, s: &str) -> bool {
    matches!(t, Some(Tok::Ident(x)) if x == s)
}

/// Module scopes of each token: the file's module path plus the inline `mod x { … }` it is in;
/// and every module declared in the file (`mod x;` or `mod x { … }`), by absolute path.
fn scopes(t: &[Tok], file_mod: &[String]) -> (Vec<Vec<String>>, BTreeSet<Vec<String>>) {
    let mut scope = file_mod.to_vec();
    let mut open: Vec<usize> = Vec::new(); // brace depth at which each inline module opened
    let mut depth = 0usize;
    let mut at = Vec::with_capacity(t.len());
    let mut declared = BTreeSet::new();
    for i in 0..t.len() {
        at.push(scope.clone());
        match &t[i] {
            Tok::Ident(m) if m == "mod" => {
                if let Some(Tok::Ident(name)) = t.get(i + 1) {
                    let mut p = scope.clone();
                    p.push(name.clone());
                    declared.insert(p);
                    if t.get(i + 2) == Some(&Tok::Punct('{')) {
                        scope.push(name.clone());
                        open.push(depth + 1);
                    }
                }
            }
            Tok::Punct('{') => depth += 1,
            Tok::Punct('}') => {
                if open.last() == Some(&depth) {
                    open.pop();
                    scope.pop();
                }
                depth = depth.saturating_sub(1);
            }
            _ => {}
        }
    }
    (at, declared)
}

/// A path a file names (absolute module path, as segments), and for a `use` the name it binds.
type Named = (Vec<String>, Option<String>);

/// Parses the rest of a path or use tree at `t[*i]` (just after a `::`), pushing every full path.
fn tree(t: &[Tok], i: &mut usize, mut prefix: Vec<String>, out: &mut Vec<Named>) {
    let alias = |i: &mut usize, name: Option<String>| {
        if is(t.get(*i), "as") {
            *i += 2;
            return t.get(*i - 1).and_then(|a| match a {
                Tok::Ident(a) if a != "_" => Some(a.clone()),
                _ => None,
            });
        }
        name
    };
    loop {
        match t.get(*i) {
            Some(Tok::Punct('{')) => {
                *i += 1;
                while *i < t.len() && t[*i] != Tok::Punct('}') {
                    let before = *i;
                    tree(t, i, prefix.clone(), out);
                    if t.get(*i) == Some(&Tok::Punct(',')) {
                        *i += 1;
                    }
                    if *i == before {
                        *i += 1; // not a path: skip the token
                    }
                }
                *i += 1;
                return;
            }
            Some(Tok::Punct('*')) => {
                *i += 1;
                prefix.push("*".into());
                out.push((prefix, None));
                return;
            }
            Some(Tok::Ident(s)) if s == "self" => {
                *i += 1;
                let name = alias(i, prefix.last().cloned());
                out.push((prefix, name));
                return;
            }
            Some(Tok::Ident(s)) if s == "super" => {
                *i += 1;
                prefix.pop();
                if t.get(*i) == Some(&Tok::Path) {
                    *i += 1;
                    continue;
                }
                out.push((prefix, None));
                return;
            }
            Some(Tok::Ident(s)) => {
                *i += 1;
                prefix.push(s.clone());
                if t.get(*i) == Some(&Tok::Path) {
                    *i += 1;
                    continue;
                }
                let name = alias(i, Some(s.clone()));
                out.push((prefix, name));
                return;
            }
            _ => {
                out.push((prefix, None));
                return;
            }
        }
    }
}

/// Every absolute module path (as segments) a file names: `crate::…`, `super::…`, `self::…`,
/// paths starting with a module the file declares, and inline paths starting with a name a `use`
/// of the file binds (`use crate::a;` … `a::f()`) or a module a glob brings in (`use super::*;`
/// … `b::f()`). `modules` are the crate's module paths.
fn paths(src: &str, file_mod: &[String], modules: &BTreeSet<Vec<String>>) -> Vec<Vec<String>> {
    let t = tokens(src);
    let (at, declared) = scopes(&t, file_mod);
    // The base path a path starting at t[i] resolves from, if it names this crate.
    let start = |i: usize| -> Option<Vec<String>> {
        let Tok::Ident(s) = &t[i] else { return None };
        let after_path = i > 0 && (t[i - 1] == Tok::Path || t[i - 1] == Tok::Punct('.'));
        let visibility = i > 1 && is(t.get(i - 1), "in") && t[i - 2] == Tok::Punct('('); // pub(in crate::x)
                                                                                         // `$crate::…` in a macro's body names the crate where the macro is expanded, not a
                                                                                         // module the defining file imports.
        let macro_crate = i > 0 && t[i - 1] == Tok::Punct('$');
        if after_path || visibility || macro_crate || t.get(i + 1) != Some(&Tok::Path) {
            return None;
        }
        let scope = &at[i];
        match s.as_str() {
            "crate" => Some(Vec::new()),
            "self" => Some(scope.clone()),
            "super" => Some(scope[..scope.len().saturating_sub(1)].to_vec()),
            name => {
                let mut p = scope.clone();
                p.push(name.to_string());
                declared.contains(&p).then_some(p)
            }
        }
    };
    // `use` statements first (token ranges kept so the inline scan skips them), with what they
    // bind.
    let mut out: Vec<Named> = Vec::new();
    let mut in_use = vec![false; t.len()];
    let mut i = 0;
    while i < t.len() {
        if !is(t.get(i), "use") {
            i += 1;
            continue;
        }
        let from = i;
        i += 1;
        if t.get(i) == Some(&Tok::Path) {
            i += 1; // use ::extern_crate
        } else if let Some(base) = start(i) {
            i += 2;
            tree(&t, &mut i, base, &mut out);
        }
        while i < t.len() && t[i] != Tok::Punct(';') {
            i += 1;
        }
        in_use[from..i.min(t.len())]
            .iter_mut()
            .for_each(|u| *u = true);
    }
    let bound: BTreeMap<String, Vec<String>> = out
        .iter()
        .filter_map(|(p, n)| n.clone().map(|n| (n, p.clone())))
        .collect();
    let globs: Vec<Vec<String>> = out
        .iter()
        .filter(|(p, _)| p.last().map(String::as_str) == Some("*"))
        .map(|(p, _)| p[..p.len() - 1].to_vec())
        .collect();
    let mut i = 0;
    while i < t.len() {
        if in_use[i] {
            i += 1;
            continue;
        }
        let base = start(i).or_else(|| {
            let Tok::Ident(s) = &t[i] else { return None };
            let after_path = i > 0 && (t[i - 1] == Tok::Path || t[i - 1] == Tok::Punct('.'));
            if after_path || t.get(i + 1) != Some(&Tok::Path) {
                return None;
            }
            bound.get(s).cloned().or_else(|| {
                globs.iter().find_map(|g| {
                    let mut p = g.clone();
                    p.push(s.clone());
                    modules.contains(&p).then_some(p)
                })
            })
        });
        match base {
            Some(base) => {
                i += 2;
                tree(&t, &mut i, base, &mut out);
            }
            None => i += 1,
        }
    }
    out.into_iter().map(|(p, _)| p).collect()
}

impl Graph {
    /// Reads every `.rs` file under `dir` (except [`SKIP`]) and resolves its paths.
    fn read(dir: &Path) -> Graph {
        let mut files = Vec::new();
        collect(dir, dir, &mut files);
        assert!(
            files.iter().any(|f| f == "lib.rs"),
            "{}: no lib.rs",
            dir.display()
        );
        let modules: BTreeMap<Vec<String>, String> =
            files.iter().map(|f| (module_of(f), f.clone())).collect();
        let paths_of: BTreeSet<Vec<String>> = modules.keys().cloned().collect();
        let mut edges = BTreeMap::new();
        for f in &files {
            let src = std::fs::read_to_string(dir.join(f)).unwrap();
            let mut uses = Uses::new();
            for p in paths(&src, &module_of(f), &paths_of) {
                let k = (0..=p.len())
                    .rev()
                    .find(|&k| modules.contains_key(&p[..k]))
                    .unwrap();
                let to = &modules[&p[..k]];
                if to == f {
                    continue;
                }
                let name = match (p.get(k), k) {
                    (Some(n), _) => n.clone(),
                    (None, 0) => "crate".into(),
                    (None, _) => p[k - 1].clone(),
                };
                uses.entry(to.clone()).or_default().insert(name);
            }
            edges.insert(f.clone(), uses);
        }
        Graph { edges }
    }

    /// Every circle, one line per edge in it: `a.rs -> b.rs (names) -> … -> a.rs (names)`.
    fn circles(&self) -> Vec<String> {
        // The root declares every module: an import of it closes a circle by itself.
        let mut found = Vec::new();
        for (f, uses) in &self.edges {
            if let Some(names) = uses.get("lib.rs") {
                found.push(format!(
                    "{f} -> lib.rs ({}) -> {f} (declared by lib.rs: import from the module itself)",
                    join(names)
                ));
            }
        }
        let names: Vec<&String> = self.edges.keys().collect();
        let index: BTreeMap<&String, usize> =
            names.iter().enumerate().map(|(i, n)| (*n, i)).collect();
        let succ: Vec<Vec<usize>> = names
            .iter()
            .map(|n| {
                if n.as_str() == "lib.rs" {
                    return Vec::new(); // the root's facade runs down by definition
                }
                self.edges[*n]
                    .keys()
                    .filter_map(|t| index.get(t).copied())
                    .collect()
            })
            .collect();
        for scc in tarjan(&succ) {
            if scc.len() < 2 {
                continue;
            }
            let inside: BTreeSet<usize> = scc.iter().copied().collect();
            let mut lines = BTreeSet::new();
            for &u in &scc {
                for &v in succ[u].iter().filter(|v| inside.contains(v)) {
                    // shortest way back from v to u inside the component
                    let mut cycle = back(&succ, &inside, v, u);
                    cycle.insert(0, u);
                    let m = (0..cycle.len() - 1)
                        .min_by_key(|&k| names[cycle[k]])
                        .unwrap();
                    let mut ring: Vec<usize> = cycle[m..cycle.len() - 1].to_vec();
                    ring.extend_from_slice(&cycle[..=m]);
                    let mut s = names[ring[0]].clone();
                    for w in ring.windows(2) {
                        s += &format!(
                            " -> {} ({})",
                            names[w[1]],
                            join(&self.edges[names[w[0]]][names[w[1]]])
                        );
                    }
                    lines.insert(s);
                }
            }
            let mut members: Vec<&str> = scc.iter().map(|&k| names[k].as_str()).collect();
            members.sort();
            found.push(format!(
                "circle of {} files ({}):\n  {}",
                scc.len(),
                members.join(", "),
                lines.into_iter().collect::<Vec<_>>().join("\n  ")
            ));
        }
        found
    }
}

fn join(names: &BTreeSet<String>) -> String {
    names.iter().cloned().collect::<Vec<_>>().join(", ")
}

/// The module path of a file: `lib.rs` → [], `a/mod.rs` → [a], `a/b.rs` → [a, b].
fn module_of(file: &str) -> Vec<String> {
    let mut p: Vec<String> = file
        .trim_end_matches(".rs")
        .split('/')
        .map(String::from)
        .collect();
    if matches!(p.last().map(String::as_str), Some("lib") | Some("mod")) {
        p.pop();
    }
    p
}

fn collect(root: &Path, dir: &Path, out: &mut Vec<String>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for p in entries {
        let rel = p
            .strip_prefix(root)
            .unwrap()
            .to_string_lossy()
            .replace('\\', "/");
        if p.is_dir() {
            collect(root, &p, out);
        } else if rel.ends_with(".rs") && !SKIP.contains(&rel.as_str()) {
            out.push(rel);
        }
    }
}

/// Shortest path from `from` to `to` inside `inside` (both included).
fn back(succ: &[Vec<usize>], inside: &BTreeSet<usize>, from: usize, to: usize) -> Vec<usize> {
    let mut prev = BTreeMap::from([(from, from)]);
    let mut queue = VecDeque::from([from]);
    while let Some(u) = queue.pop_front() {
        if u == to {
            break;
        }
        for &v in succ[u].iter().filter(|v| inside.contains(v)) {
            if let std::collections::btree_map::Entry::Vacant(e) = prev.entry(v) {
                e.insert(u);
                queue.push_back(v);
            }
        }
    }
    let mut path = vec![to];
    while *path.last().unwrap() != from {
        path.push(prev[path.last().unwrap()]);
    }
    path.reverse();
    path
}

/// Strongly connected components (Tarjan).
fn tarjan(succ: &[Vec<usize>]) -> Vec<Vec<usize>> {
    struct St<'a> {
        succ: &'a [Vec<usize>],
        index: Vec<Option<usize>>,
        low: Vec<usize>,
        on: Vec<bool>,
        stack: Vec<usize>,
        next: usize,
        out: Vec<Vec<usize>>,
    }
    fn visit(s: &mut St, v: usize) {
        s.index[v] = Some(s.next);
        s.low[v] = s.next;
        s.next += 1;
        s.stack.push(v);
        s.on[v] = true;
        for k in 0..s.succ[v].len() {
            let w = s.succ[v][k];
            match s.index[w] {
                None => {
                    visit(s, w);
                    s.low[v] = s.low[v].min(s.low[w]);
                }
                Some(iw) if s.on[w] => s.low[v] = s.low[v].min(iw),
                Some(_) => {}
            }
        }
        if Some(s.low[v]) == s.index[v] {
            let mut c = Vec::new();
            loop {
                let w = s.stack.pop().unwrap();
                s.on[w] = false;
                c.push(w);
                if w == v {
                    break;
                }
            }
            s.out.push(c);
        }
    }
    let n = succ.len();
    let mut s = St {
        succ,
        index: vec![None; n],
        low: vec![0; n],
        on: vec![false; n],
        stack: Vec::new(),
        next: 0,
        out: Vec::new(),
    };
    for v in 0..n {
        if s.index[v].is_none() {
            visit(&mut s, v);
        }
    }
    s.out
}

fn check(dir: &Path) -> Result<(), String> {
    let g = Graph::read(dir);
    if std::env::var("UVT_IMPORTS_DUMP").is_ok() {
        for (f, uses) in &g.edges {
            for (t, n) in uses {
                println!("{f} -> {t} ({})", join(n));
            }
        }
    }
    let circles = g.circles();
    if circles.is_empty() {
        return Ok(());
    }
    Err(format!(
        "{}: {} import circle(s); cut each (move the shared item into a file below both):\n{}",
        dir.display(),
        circles.len(),
        circles.join("\n")
    ))
}

#[test]
fn no_import_circles() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let list = std::env::var("UVT_IMPORTS").ok();
    let crates: Vec<&str> = match &list {
        Some(l) => l
            .split(',')
            .map(str::trim)
            .filter(|s| !s.is_empty())
            .collect(),
        None => CRATES.to_vec(),
    };
    let errors: Vec<String> = crates
        .iter()
        .filter_map(|c| check(&root.join(c)).err())
        .collect();
    assert!(errors.is_empty(), "\n{}", errors.join("\n\n"));
}

/// Writes `files` (path, source) under a fresh temporary folder and checks it.
fn check_tree(files: &[(&str, &str)]) -> Result<(), String> {
    let dir = tempfile::tempdir().unwrap();
    for (p, src) in files {
        let p = dir.path().join(p);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, src).unwrap();
    }
    check(dir.path()).map_err(|e| e.replace(&dir.path().display().to_string(), "<tmp>"))
}

#[test]
fn a_two_file_circle_is_reported() {
    let e = check_tree(&[
        ("lib.rs", "pub mod a;\npub mod b;\n"),
        (
            "a.rs",
            "use crate::b::{B, self};\npub struct A;\npub fn list() -> [u8; 0] { b::g(); [] }\n",
        ),
        (
            "b.rs",
            "pub struct B;\npub fn g() {}\n\
             pub fn f() -> crate::a::A { for _ in crate::a::list() {} crate::a::A }\n",
        ),
        ("main.rs", "use crate::a::A; fn main() {}\n"),
    ])
    .unwrap_err();
    assert!(e.contains("circle of 2 files (a.rs, b.rs)"), "{e}");
    assert!(
        e.contains("a.rs -> b.rs (B, b, g) -> a.rs (A, list)"),
        "{e}"
    );
}

#[test]
fn a_tree_without_circle_passes() {
    let ok = check_tree(&[
        ("lib.rs", "pub mod a;\npub mod b;\npub mod c;\npub use a::A;\n"),
        ("a.rs", "use crate::{b::B, c::{self, C}};\npub struct A(B, C);\n"),
        // comments, strings, char literals and test items name nothing (a.rs uses b.rs); an inline
        // module's super is its file
        (
            "b.rs",
            "// use crate::a::A;\n/* crate::a::A /* nested */ */\npub struct B;\n\
             const S: &str = \"crate::a::A\"; const R: &str = r#\"crate::a\"#; const Q: char = '\"';\n\
             fn f<'a>(x: &'a str) -> &'a str { x }\n\
             mod inner { pub fn h() -> super::B { super::B } }\n\
             #[cfg(test)] mod tests { use super::*; use crate::a::A; fn t() -> (A, B) { (A, B) } }\n",
        ),
        ("c/mod.rs", "mod d;\npub use self::d::C;\n"),
        ("c/d.rs", "pub struct C;\npub fn g() -> super::super::b::B { crate::b::B }\n"),
    ]);
    assert_eq!(ok, Ok(()));
}

#[test]
fn a_folder_and_its_child_circle_and_root_imports_are_reported() {
    let e = check_tree(&[
        (
            "lib.rs",
            "pub mod v;\npub mod w;\npub mod z;\npub use w::W;\n",
        ),
        (
            "v/mod.rs",
            "mod x;\npub struct Shared;\npub fn f() { x::g() }\n",
        ),
        ("v/x.rs", "pub fn g() { let _ = super::Shared; }\n"),
        ("w.rs", "pub struct W;\nfn h() -> self::W { W }\n"),
        ("z.rs", "fn k() -> crate::W { crate::W }\n"),
    ])
    .unwrap_err();
    assert!(
        e.contains("v/mod.rs -> v/x.rs (g) -> v/mod.rs (Shared)"),
        "{e}"
    );
    assert!(e.contains("z.rs -> lib.rs (W) -> z.rs"), "{e}");
    assert!(!e.contains("w.rs"), "w.rs names only itself: {e}");
}
