//! `core/README.md`'s hardware-cost paragraph quotes `uvt cost`, and `docs/bounds.md` holds
//! `uvt cost --strategies`: their figures must be what the command prints today (the width table
//! above it is checked by `core/src/widths/mod.rs`).

use uvt_host::config::multipliers::summary_md;

/// `12648` → `12 648` (the README's thousands separator).
fn spaced(n: &str) -> String {
    let d: Vec<char> = n.chars().collect();
    let mut s = String::new();
    for (i, c) in d.iter().enumerate() {
        if i > 0 && (d.len() - i) % 3 == 0 {
            s.push(' ');
        }
        s.push(*c);
    }
    s
}

/// The cells of `uvt cost`'s row for (configuration, stage).
fn row(table: &str, config: &str, stage: &str) -> Vec<String> {
    table
        .lines()
        .find(|l| l.starts_with(&format!("| {config} | {stage} |")))
        .unwrap_or_else(|| panic!("no row {config} {stage} in:\n{table}"))
        .trim_matches('|')
        .split('|')
        .map(|c| c.trim().to_string())
        .collect()
}

/// The leading integers of a cell: `414 (100.0% of exact) + 12648 LUT bits` → [414, 12648].
fn ints(cell: &str) -> Vec<String> {
    cell.split(|c: char| !c.is_ascii_digit() && c != '.')
        .filter(|w| !w.is_empty() && !w.contains('.'))
        .map(str::to_string)
        .collect()
}

#[test]
fn core_readme_cost_paragraph_is_what_uvt_cost_prints() {
    let table = summary_md();
    let readme =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../core/README.md")).unwrap();
    let text = readme.split_whitespace().collect::<Vec<_>>().join(" ");
    let exact = row(&table, "exact-16-16-16", "sample");
    let (ed, em) = (ints(&exact[4]), ints(&exact[5]));
    let want = format!(
        "`exact-16-16-16` {} bit-products, {} DSP48E1 + {} LUT bits, {} MULT18X18D",
        spaced(&exact[3]),
        ed[0],
        spaced(&ed[1]),
        em[0]
    );
    let def = row(&table, "bounded-16-16-16-20", "sample");
    let (dd, dm) = (ints(&def[4]), ints(&def[5]));
    let pct = def[4].split('(').nth(1).unwrap().split('%').next().unwrap();
    let want_def = format!(
        "`bounded-16-16-16-20` {}, {} ({pct}% of the exact figure) + {} LUT bits, {}",
        spaced(&def[3]),
        dd[0],
        spaced(&dd[1]),
        dm[0]
    );
    let narrow = row(&table, "bounded-8-8-8-28", "sample");
    let want_narrow = format!(
        "`bounded-8-8-8-28` {}, {}, {}",
        spaced(&narrow[3]),
        ints(&narrow[4])[0],
        ints(&narrow[5])[0]
    );
    let setup = format!(
        "{} DSP48E1 exact and {} bounded",
        spaced(&ints(&row(&table, "exact-16-16-16", "setup")[4])[0]),
        spaced(&ints(&row(&table, "bounded-16-16-16-20", "setup")[4])[0])
    );
    for w in [want, want_def, want_narrow, setup] {
        assert!(
            text.contains(&w),
            "core/README.md lacks `{w}` (what `uvt cost` prints); regenerate the paragraph"
        );
    }
}

/// `docs/bounds.md`'s hardware figure per strategy and stage is what `uvt cost --strategies`
/// prints today at the default configuration.
#[test]
fn bounds_doc_strategy_figures_are_what_uvt_cost_prints() {
    let want =
        uvt_host::config::strategy_cost::strategies_md(&uvt_core::config::registry::Config::of::<
            uvt_core::DefaultPrecision,
        >());
    let doc =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/bounds.md")).unwrap();
    let begin = doc
        .find("<!-- strategy-cost:begin")
        .expect("begin marker in docs/bounds.md");
    let body = &doc[begin..];
    let body = &body[body.find('\n').unwrap() + 1..];
    let end = body
        .find("<!-- strategy-cost:end -->")
        .expect("end marker in docs/bounds.md");
    assert_eq!(
        body[..end].trim(),
        want.trim(),
        "docs/bounds.md's strategy cost section differs from `uvt cost --strategies`; regenerate it"
    );
}
