//! The width table as Markdown: `uvt widths` and the generated section of `core/README.md`.

use crate::config::formats::{MAX_VIEWPORT, SUBPIXEL_BITS, TUV_FRAC};
use crate::config::registry::Config;
use crate::widths::mag::Mag;
use crate::widths::row::eps_max;
use crate::widths::row::exact_positions;
use crate::widths::row::ext;
use crate::widths::row::lim;
use crate::widths::stages::table;
use core::fmt;

/// The width table of `cfg` as Markdown (the `core/README.md` table; `uvt widths`).
pub fn write_markdown<W: fmt::Write>(out: &mut W, cfg: &Config) -> fmt::Result {
    let (ex, ew) = eps_max(cfg);
    writeln!(
        out,
        "Configuration `{cfg}` (domain: |clip| ≤ {}, t/u/v ≤ 2^{TUV_FRAC}, W, H ≤ {}, {} sub-pixel bits; ε_x ≤ {ex}, ε_w ≤ {ew} raw):",
        lim(),
        MAX_VIEWPORT,
        SUBPIXEL_BITS
    )?;
    writeln!(out)?;
    writeln!(
        out,
        "| stage | signal | bound on \\|raw\\| | bits | Rust type | multiplier (count) | note |"
    )?;
    writeln!(out, "|---|---|---|---|---|---|---|")?;
    for r in table(cfg).rows() {
        write!(
            out,
            "| {} | {} | {} | {} | {} | ",
            r.stage,
            r.signal,
            r.bound,
            r.bits(),
            r.ty
        )?;
        let mut any = false;
        for m in r.mul.iter().flatten() {
            let sep = if any { ", " } else { "" };
            write!(out, "{sep}{} × {} ({})", m.a, m.b, m.count)?;
            any = true;
        }
        if !any {
            write!(out, "–")?;
        }
        writeln!(out, " | {} |", r.note)?;
    }
    Ok(())
}

/// The per-class widths of the exact sample test as Markdown.
pub fn write_class_markdown<W: fmt::Write>(out: &mut W) -> fmt::Result {
    writeln!(
        out,
        "| class | P frac bits | \\|P\\| | P bits | n bits | E bits | det bits |"
    )?;
    writeln!(out, "|---|---|---|---|---|---|---|")?;
    let e = ext();
    let d = Mag::pow2(SUBPIXEL_BITS).mul(e).mul(e);
    for (name, f, p) in exact_positions() {
        let n = p.mul(p).times(2);
        writeln!(
            out,
            "| {name} | {f} | {p} | {} | {} | {} | {} |",
            p.bits(),
            n.bits(),
            n.mul(d).times(3).bits(),
            p.mul(n).times(3).bits()
        )?;
    }
    Ok(())
}

/// The configurations of `core/README.md`'s width section: the exact test and the bounded
/// default.
pub const README_CONFIGS: [Config; 2] = [
    Config::of::<crate::config::precision::Exact>(),
    Config::of::<crate::config::precision::BoundedPrecision>(),
];

/// The whole generated width section of `core/README.md` (`uvt widths` with no `--config`):
/// each configuration's table, then the exact test's widths per class.
pub fn write_readme<W: fmt::Write>(out: &mut W) -> fmt::Result {
    for cfg in README_CONFIGS.iter() {
        write_markdown(out, cfg)?;
        writeln!(out)?;
    }
    writeln!(
        out,
        "The exact sample test per class (the table above is class both):"
    )?;
    writeln!(out)?;
    write_class_markdown(out)
}
