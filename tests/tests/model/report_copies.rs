//! The documentation's copies of committed reports are the reports: every block of README.md
//! and docs/*.md between `<!-- report:begin FILE#SECTION … -->` and `<!-- report:end -->`
//! equals that section of FILE as committed (`table-N`: the N-th run of lines starting with `|`;
//! `all`: the whole file). A report regenerated without splicing, or a table edited by hand,
//! fails here; `bash host/report/regen.sh` (or `uvt splice`) puts the report's part back.
//! Written apart from `uvt splice` (`host/src/splice.rs`), so that each checks the other.

use std::path::PathBuf;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// A marked copy: where it is, what it names, and its lines.
#[derive(Debug)]
struct Copy {
    line: usize,
    file: String,
    section: String,
    body: Vec<String>,
}

/// The report copies of a page's text; a begin without an end, or a begin without
/// `FILE#SECTION`, is an error naming its line.
fn copies(text: &str) -> Result<Vec<Copy>, String> {
    let mut out = Vec::new();
    let mut open: Option<Copy> = None;
    for (i, line) in text.lines().enumerate() {
        let t = line.trim();
        if let Some(rest) = t.strip_prefix("<!-- report:begin ") {
            if let Some(c) = &open {
                return Err(format!(
                    "line {}: a report block inside that of line {}",
                    i + 1,
                    c.line
                ));
            }
            let spec = rest.split_whitespace().next().unwrap_or("");
            let (file, section) = spec
                .split_once('#')
                .ok_or_else(|| format!("line {}: `report:begin` without FILE#SECTION", i + 1))?;
            open = Some(Copy {
                line: i + 1,
                file: file.to_string(),
                section: section.to_string(),
                body: Vec::new(),
            });
        } else if t == "<!-- report:end -->" {
            out.push(
                open.take()
                    .ok_or_else(|| format!("line {}: `report:end` without a begin", i + 1))?,
            );
        } else if let Some(c) = &mut open {
            c.body.push(line.to_string());
        }
    }
    match open {
        Some(c) => Err(format!("line {}: the report block has no end", c.line)),
        None => Ok(out),
    }
}

/// Section `section` of a report's text, as lines.
fn part(report: &str, section: &str) -> Result<Vec<String>, String> {
    let lines: Vec<String> = report.lines().map(str::to_string).collect();
    if section == "all" {
        let mut l = lines;
        while l.last().is_some_and(|x| x.is_empty()) {
            l.pop();
        }
        return Ok(l);
    }
    let n: usize = section
        .strip_prefix("table-")
        .and_then(|k| k.parse().ok())
        .ok_or_else(|| format!("section {section:?} is not table-N or all"))?;
    let tables: Vec<Vec<String>> = lines
        .split(|l| !l.starts_with('|'))
        .filter(|t| !t.is_empty())
        .map(<[String]>::to_vec)
        .collect();
    n.checked_sub(1)
        .and_then(|k| tables.get(k).cloned())
        .ok_or_else(|| {
            format!(
                "section {section:?}: the report has {} tables",
                tables.len()
            )
        })
}

/// Every difference of `page`'s copies from the reports `read` returns, as `page:line: why`.
fn differences(
    page: &str,
    text: &str,
    read: &dyn Fn(&str) -> Option<String>,
) -> (Vec<String>, usize) {
    let found = match copies(text) {
        Ok(c) => c,
        Err(e) => return (vec![format!("{page}: {e}")], 0),
    };
    let mut bad = Vec::new();
    for c in &found {
        let at = format!("{page}:{}: {}#{}", c.line, c.file, c.section);
        let Some(report) = read(&c.file) else {
            bad.push(format!("{at}: no such report"));
            continue;
        };
        match part(&report, &c.section) {
            Err(e) => bad.push(format!("{at}: {e}")),
            Ok(want) if want != c.body => {
                let k = want.iter().zip(&c.body).take_while(|(a, b)| a == b).count();
                bad.push(format!(
                    "{at}: differs from the report at the copy's line {} (report: {:?}, copy: {:?})",
                    k + 1,
                    want.get(k).map(String::as_str).unwrap_or("<end>"),
                    c.body.get(k).map(String::as_str).unwrap_or("<end>")
                ));
            }
            Ok(_) => {}
        }
    }
    (bad, found.len())
}

#[test]
fn every_report_copy_equals_its_report() {
    let r = root();
    let mut pages = vec![r.join("README.md")];
    let mut docs: Vec<PathBuf> = std::fs::read_dir(r.join("docs"))
        .expect("docs/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    docs.sort();
    pages.extend(docs);
    let read = |f: &str| std::fs::read_to_string(r.join(f)).ok();
    let (mut bad, mut n) = (Vec::new(), 0);
    for p in &pages {
        let text = std::fs::read_to_string(p).expect("page");
        let rel = p.strip_prefix(&r).unwrap().display().to_string();
        let (b, k) = differences(&rel, &text, &read);
        bad.extend(b);
        n += k;
    }
    assert!(n >= 11, "only {n} report copies found: the scan is broken");
    assert!(
        bad.is_empty(),
        "report copies that are not their reports (bash host/report/regen.sh --only docs, or \
         `uvt splice`, puts them back):\n{}",
        bad.join("\n")
    );
}

/// A copy that differs from its report, names a missing table or report, or lacks its end is
/// reported with its page and line.
#[test]
fn a_stale_copy_is_reported() {
    let report = "Title\n\n| a | b |\n|---|---|\n| 1 | 2 |\n\nnote\n\n| c |\n|---|\n| 3 |\n";
    let read = |f: &str| (f == "r.md").then(|| report.to_string());
    let page = "x\n<!-- report:begin r.md#table-2 (c) -->\n| c |\n|---|\n| 3 |\n<!-- report:end -->\n\
                <!-- report:begin r.md#table-1 -->\n| a | b |\n|---|---|\n| 1 | 9 |\n<!-- report:end -->\n\
                <!-- report:begin r.md#table-3 -->\n<!-- report:end -->\n\
                <!-- report:begin gone.md#all -->\n<!-- report:end -->\n";
    let (bad, n) = differences("p.md", page, &read);
    assert_eq!(n, 4);
    assert_eq!(
        bad,
        [
            "p.md:7: r.md#table-1: differs from the report at the copy's line 3 (report: \"| 1 | 2 |\", copy: \"| 1 | 9 |\")",
            "p.md:12: r.md#table-3: section \"table-3\": the report has 2 tables",
            "p.md:14: gone.md#all: no such report",
        ]
    );
    let whole = format!("<!-- report:begin r.md#all -->\n{report}<!-- report:end -->\n");
    assert_eq!(differences("p.md", &whole, &read), (vec![], 1));
    let (bad, _) = differences("p.md", "<!-- report:begin r.md#all -->\n| a |\n", &read);
    assert_eq!(bad, ["p.md: line 1: the report block has no end"]);
}
