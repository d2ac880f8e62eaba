//! `uvt splice`: the documentation's copies of reports and of command outputs, refreshed in
//! place. A copy is a **block**: the lines between a line `<!-- NAME:begin … -->` and the next
//! line `<!-- NAME:end -->` of a Markdown page.
//!
//! - **Report blocks** (`NAME` = `report`) copy part of a committed report: the begin line
//!   names it as `FILE#SECTION` right after `report:begin`, FILE relative to the repository root
//!   and SECTION `table-N` (the N-th Markdown table of the file: its N-th run of lines that
//!   start with `|`, counted from 1) or `all` (the whole file). [`splice_reports`] sets every
//!   report block of README.md and docs/*.md to its section of the report as committed now;
//!   `tests/tests/model/report_copies.rs` fails when one differs.
//! - **Command blocks** (any other `NAME`: `widths` in core/README.md, `strategy-cost` in
//!   docs/bounds.md, `m4-report` in docs/performance.md) copy a command's output, which
//!   [`splice_block`] puts in; their own tests compare them with the command.
//!
//! `host/report/regen.sh` runs both after the commands. A page is written through a temporary
//! file in its folder and renamed, so nothing is half-written.

use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Context, Result};

/// One block of a page: its name, the line numbers (1-based) of its begin and end lines, and
/// for a report block the report's path and section.
#[derive(Clone, Debug, PartialEq)]
pub struct Block {
    /// the marker's name (`report`, `widths`, …)
    pub name: String,
    /// line of `<!-- NAME:begin … -->`
    pub begin: usize,
    /// line of `<!-- NAME:end -->`
    pub end: usize,
    /// a report block's `FILE#SECTION`
    pub source: Option<(String, String)>,
}

/// The blocks of a page's text, in order; an unclosed or nested block is an error.
pub fn blocks(text: &str) -> Result<Vec<Block>> {
    let mut out = Vec::new();
    let mut open: Option<Block> = None;
    for (i, line) in text.lines().enumerate() {
        let n = i + 1;
        let Some(rest) = line.trim().strip_prefix("<!-- ") else {
            continue;
        };
        if let Some((name, tail)) = rest.split_once(":begin") {
            if name.is_empty() || name.contains(char::is_whitespace) {
                continue;
            }
            if let Some(b) = &open {
                bail!(
                    "line {n}: `{name}:begin` inside the block `{}` of line {}",
                    b.name,
                    b.begin
                );
            }
            let source = if name == "report" {
                let spec = tail.split_whitespace().next().unwrap_or("");
                let (file, section) = spec.split_once('#').ok_or_else(|| {
                    anyhow!("line {n}: a report block names FILE#SECTION after `report:begin`")
                })?;
                Some((file.to_string(), section.to_string()))
            } else {
                None
            };
            open = Some(Block {
                name: name.to_string(),
                begin: n,
                end: 0,
                source,
            });
        } else if let Some(name) = rest.strip_suffix(":end -->") {
            match open.take() {
                Some(mut b) if b.name == name => {
                    b.end = n;
                    out.push(b);
                }
                Some(b) => bail!(
                    "line {n}: `{name}:end` closes the block `{}` of line {}",
                    b.name,
                    b.begin
                ),
                None => bail!("line {n}: `{name}:end` without a begin"),
            }
        }
    }
    if let Some(b) = open {
        bail!("line {}: the block `{}` has no end line", b.begin, b.name);
    }
    Ok(out)
}

/// Section `section` of a report's text: `table-N` or `all` (module docs), without its final
/// line break.
pub fn section(report: &str, section: &str) -> Result<String> {
    if section == "all" {
        return Ok(report.trim_end_matches('\n').to_string());
    }
    let n: usize = section
        .strip_prefix("table-")
        .and_then(|k| k.parse().ok())
        .filter(|&k| k >= 1)
        .ok_or_else(|| anyhow!("section `{section}`: not `table-N` (N ≥ 1) or `all`"))?;
    let lines: Vec<&str> = report.lines().collect();
    let mut k = 0;
    let mut i = 0;
    while i < lines.len() {
        if !lines[i].starts_with('|') {
            i += 1;
            continue;
        }
        let j = (i..lines.len())
            .find(|&j| !lines[j].starts_with('|'))
            .unwrap_or(lines.len());
        k += 1;
        if k == n {
            return Ok(lines[i..j].join("\n"));
        }
        i = j;
    }
    bail!("section `{section}`: the report has {k} tables")
}

/// `text` with the body of `block` (the lines between its begin and end lines) set to `body`.
fn with_body(text: &str, block: &Block, body: &str) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let mut out: Vec<&str> = lines[..block.begin].to_vec();
    let body = body.trim_end();
    if !body.is_empty() {
        out.extend(body.lines());
    }
    out.extend(&lines[block.end - 1..]);
    let mut s = out.join("\n");
    if text.ends_with('\n') {
        s.push('\n');
    }
    s
}

/// The body of `block` in `text`.
fn body_of(text: &str, block: &Block) -> String {
    let lines: Vec<&str> = text.lines().collect();
    lines[block.begin..block.end - 1].join("\n")
}

/// Write `text` to `path` through a temporary file in the same folder.
fn write_atomic(path: &Path, text: &str) -> Result<()> {
    let name = path
        .file_name()
        .ok_or_else(|| anyhow!("{}: not a file name", path.display()))?;
    let tmp = path.with_file_name(format!(".{}.tmp", name.to_string_lossy()));
    std::fs::write(&tmp, text).with_context(|| format!("cannot write {}", tmp.display()))?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        anyhow!("cannot write {}: {e}", path.display())
    })
}

/// The pages whose report blocks are spliced: README.md and docs/*.md under `root`.
pub fn pages(root: &Path) -> Result<Vec<PathBuf>> {
    let mut v = vec![root.join("README.md")];
    let docs = root.join("docs");
    let mut more: Vec<PathBuf> = std::fs::read_dir(&docs)
        .with_context(|| format!("cannot read {}", docs.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    more.sort();
    v.extend(more);
    Ok(v)
}

/// One report block's state after [`splice_reports`].
#[derive(Clone, Debug)]
pub struct Spliced {
    /// `page:line`
    pub at: String,
    /// `FILE#SECTION`
    pub source: String,
    /// whether its body differed from the report (and, unless checking, was replaced)
    pub changed: bool,
}

/// Set every report block of the pages under `root` to its section of the report; with
/// `check`, change nothing and only say which differ.
pub fn splice_reports(root: &Path, check: bool) -> Result<Vec<Spliced>> {
    let mut out = Vec::new();
    for page in pages(root)? {
        let rel = page
            .strip_prefix(root)
            .unwrap_or(&page)
            .display()
            .to_string();
        let mut text = std::fs::read_to_string(&page)
            .with_context(|| format!("cannot read {}", page.display()))?;
        let found = blocks(&text).with_context(|| rel.clone())?;
        let mut changed = false;
        // From the last block up, so that earlier blocks' line numbers stay valid.
        for b in found.iter().rev() {
            let Some((file, sec)) = &b.source else {
                continue;
            };
            let path = root.join(file);
            let report = std::fs::read_to_string(&path)
                .with_context(|| format!("{rel}:{}: cannot read {}", b.begin, path.display()))?;
            let want =
                section(&report, sec).with_context(|| format!("{rel}:{}: {file}", b.begin))?;
            let differs = body_of(&text, b) != want;
            if differs && !check {
                text = with_body(&text, b, &want);
            }
            changed |= differs;
            out.push(Spliced {
                at: format!("{rel}:{}", b.begin),
                source: format!("{file}#{sec}"),
                changed: differs,
            });
        }
        if changed && !check {
            write_atomic(&page, &text)?;
        }
    }
    out.sort_by(|a, b| a.at.cmp(&b.at));
    Ok(out)
}

/// Set the body of the one block named `name` of `page` to `body` (its trailing white space
/// trimmed); whether it changed.
pub fn splice_block(page: &Path, name: &str, body: &str) -> Result<bool> {
    let text =
        std::fs::read_to_string(page).with_context(|| format!("cannot read {}", page.display()))?;
    let found: Vec<Block> = blocks(&text)
        .with_context(|| page.display().to_string())?
        .into_iter()
        .filter(|b| b.name == name)
        .collect();
    let [b] = found.as_slice() else {
        bail!(
            "{}: {} blocks named `{name}` (one expected)",
            page.display(),
            found.len()
        );
    };
    if body_of(&text, b) == body.trim_end() {
        return Ok(false);
    }
    write_atomic(page, &with_body(&text, b, body))?;
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    const REPORT: &str = "Head\n\n| a | b |\n|---|---|\n| 1 | 2 |\n\ntext\n| c |\n|---|\n";

    #[test]
    fn sections() {
        assert_eq!(
            section(REPORT, "table-1").unwrap(),
            "| a | b |\n|---|---|\n| 1 | 2 |"
        );
        assert_eq!(section(REPORT, "table-2").unwrap(), "| c |\n|---|");
        assert!(section(REPORT, "table-3").is_err());
        assert!(section(REPORT, "table-0").is_err());
        assert_eq!(section(REPORT, "all").unwrap(), REPORT.trim_end());
    }

    #[test]
    fn blocks_and_bodies() {
        let page =
            "x\n<!-- report:begin host/r.md#table-2 (why) -->\n| old |\n<!-- report:end -->\n\
                    <!-- widths:begin -->\n<!-- widths:end -->\nend\n";
        let b = blocks(page).unwrap();
        assert_eq!(b.len(), 2);
        assert_eq!(
            b[0].source,
            Some(("host/r.md".to_string(), "table-2".to_string()))
        );
        assert_eq!((b[0].begin, b[0].end, b[1].begin, b[1].end), (2, 4, 5, 6));
        assert_eq!(body_of(page, &b[0]), "| old |");
        let new = with_body(page, &b[1], "line 1\nline 2\n\n");
        assert!(new.contains("<!-- widths:begin -->\nline 1\nline 2\n<!-- widths:end -->\nend\n"));
        let new = with_body(page, &b[0], "");
        assert!(new
            .starts_with("x\n<!-- report:begin host/r.md#table-2 (why) -->\n<!-- report:end -->"));
        assert!(blocks("<!-- a:begin -->\n<!-- b:begin -->\n").is_err());
        assert!(blocks("<!-- a:begin -->\n").is_err());
        assert!(blocks("<!-- a:end -->\n").is_err());
        assert!(blocks("<!-- report:begin host/r.md -->\n<!-- report:end -->\n").is_err());
    }
}
