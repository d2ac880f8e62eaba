//! The core's two registries on the command line: configuration names
//! (`uvt_core::config::registry`: `--precision`, `--config`, `--configs`) and bounds strategy
//! names (`uvt_core::bounds::registry`: `--bounds`), parsed and refused with the list of what
//! is accepted. Every host option that names a configuration or a strategy reads it here; no
//! name is listed anywhere else in the host.
//!
//! - [`precision`]: a configuration the core runs — exactly the registry's names and `default`
//!   ([`registry::find`]); anything else (the old `POS/TUV/BND` tuple form included) is refused
//!   with every accepted name.
//! - [`model_config`]: a configuration of the parametric width table and cost model (`uvt
//!   widths`, `uvt cost`, `uvt units`) — any in-range `exact-…` or `bounded-…` name
//!   ([`Config::parse`]); a `planar-…` one is refused (those commands cover the exact and
//!   bounded datapaths).
//! - [`strategy`]: a bounds strategy of [`STRATEGIES`].

use anyhow::{anyhow, Result};
use uvt_core::bounds::registry::STRATEGIES;
use uvt_core::config::precision::{OFFSET_SHIFT_MAX, OFFSET_SHIFT_MIN};
use uvt_core::config::registry::{self, Config, Entry, CONFIGS, DEFAULT, PLANAR};

/// The registry's name of the default configuration ([`DEFAULT`]).
pub const DEFAULT_NAME: &str = match registry::name_of(DEFAULT) {
    Some(n) => n,
    None => panic!("the default configuration is in the registry"),
};

/// What `--precision` accepts besides the registry's names.
pub const DEFAULT_ALIAS: &str = "default";

/// Every name `--precision` accepts: [`DEFAULT_ALIAS`], then the registry's in its order.
pub fn precision_names() -> Vec<&'static str> {
    std::iter::once(DEFAULT_ALIAS)
        .chain(CONFIGS.iter().map(|e| e.name))
        .collect()
}

/// The configuration `--precision NAME` (or another option `opt` naming a configuration the
/// core runs) names: one of [`precision_names`]. The error lists every accepted name; an old
/// `POS/TUV/BND` tuple is told its registry name when it has one.
pub fn precision(opt: &str, name: &str) -> Result<Config> {
    registry::find(name).ok_or_else(|| {
        anyhow!(
            "{opt} {name:?}: not a configuration of the registry{} (accepted: {}; `uvt configs` lists them)",
            tuple_hint(name),
            precision_names().join(", ")
        )
    })
}

/// For an old `POS/TUV/BND` tuple: what it is called now (`P/T/B` ran the default
/// configuration when its bits are the default's, the exact test otherwise).
fn tuple_hint(name: &str) -> String {
    let bits: Option<Vec<u32>> = name.split('/').map(|x| x.trim().parse().ok()).collect();
    let Some([p, t, b]) = bits.as_deref().and_then(|v| <[u32; 3]>::try_from(v).ok()) else {
        return String::new();
    };
    let same = |c: &Config| (c.pos(), c.tuv(), c.bnd()) == (p, t, b);
    let now = if same(&DEFAULT) {
        Some(format!("{DEFAULT_ALIAS} ({DEFAULT})"))
    } else {
        CONFIGS
            .iter()
            .find(|e| e.config.off().is_none() && same(&e.config))
            .map(|e| e.name.to_string())
    };
    match now {
        Some(n) => format!("; the POS/TUV/BND form is gone: {name} is now {n}"),
        None => "; the POS/TUV/BND form is gone".to_string(),
    }
}

/// The configuration of `--config NAME` of `uvt widths`, `uvt cost` and `uvt units`: any
/// in-range `exact-P-T-B` or `bounded-P-T-B-O` ([`Config::parse`]); a `planar-…` name is
/// refused (module docs).
pub fn model_config(name: &str) -> Result<Config> {
    let cfg = Config::parse(name).ok_or_else(|| {
        anyhow!(
            "--config {name:?}: not a configuration (exact-P-T-B or bounded-P-T-B-O; P and T in 2..=16, B in 0..=16, O in {OFFSET_SHIFT_MIN}..={OFFSET_SHIFT_MAX})"
        )
    })?;
    if cfg.planar() {
        return Err(anyhow!(
            "--config {name:?}: a planar configuration; `uvt widths`, `uvt cost` and `uvt units` cover the exact and bounded datapaths (exact-P-T-B, bounded-P-T-B-O): its moving and defocused classes run {} (use that name), and `uvt units` costs the static-only unit at {PLANAR} in its last section",
            cfg.bounded_base()
        ));
    }
    Ok(cfg)
}

/// The strategy `opt NAME` names, as the registry spells it: one of [`STRATEGIES`]; the error
/// lists them.
pub fn strategy(opt: &str, name: &str) -> Result<&'static str> {
    STRATEGIES
        .iter()
        .copied()
        .find(|s| *s == name)
        .ok_or_else(|| {
            anyhow!(
                "{opt} {name:?}: unknown bounds strategy (accepted: {}; `uvt configs --strategies` lists them)",
                STRATEGIES.join(", ")
            )
        })
}

/// The kind of a configuration: `exact`, `bounded` or `planar` (its name's first word).
pub fn kind(cfg: &Config) -> &'static str {
    match (cfg.off(), cfg.planar()) {
        (None, _) => "exact",
        (Some(_), false) => "bounded",
        (Some(_), true) => "planar",
    }
}

/// `uvt configs`: one line per registry configuration — name, kind, `sweep` when the precision
/// sweep runs it (else `-`), and `default` for [`DEFAULT`] — in the registry's order.
pub fn configs_text() -> String {
    let w = CONFIGS.iter().map(|e| e.name.len()).max().unwrap_or(0);
    CONFIGS
        .iter()
        .map(|e| {
            let line = format!(
                "{:w$}  {:7}  {:5}{}",
                e.name,
                kind(&e.config),
                if e.sweep { "sweep" } else { "-" },
                if e.config == DEFAULT { "  default" } else { "" }
            );
            line.trim_end().to_string() + "\n"
        })
        .collect()
}

/// The registry entries of the precision sweep, then the planar configuration: what `uvt
/// precision` runs by default.
const fn swept(e: &Entry, with_planar: bool) -> bool {
    e.sweep || (with_planar && e.config.same(&PLANAR))
}

/// How many registry entries [`swept`] keeps.
pub const fn swept_count(with_planar: bool) -> usize {
    let mut n = 0;
    let mut i = 0;
    while i < CONFIGS.len() {
        if swept(&CONFIGS[i], with_planar) {
            n += 1;
        }
        i += 1;
    }
    n
}

/// The names of the registry entries [`swept`] keeps, in the registry's order, as a constant
/// (`N` = [`swept_count`]).
pub const fn swept_names<const N: usize>(with_planar: bool) -> [&'static str; N] {
    let mut out = [""; N];
    let (mut i, mut k) = (0, 0);
    while i < CONFIGS.len() {
        if swept(&CONFIGS[i], with_planar) {
            out[k] = CONFIGS[i].name;
            k += 1;
        }
        i += 1;
    }
    assert!(k == N, "swept_names: N is not swept_count");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn precision_takes_the_registry_names_only() {
        for e in CONFIGS {
            assert_eq!(precision("--precision", e.name).unwrap(), e.config);
        }
        assert_eq!(precision("--precision", DEFAULT_ALIAS).unwrap(), DEFAULT);
        let all = precision_names().join(", ");
        for bad in [
            "16/16/16",
            "12/12/8",
            "exact-9-9-9",
            "bounded-16-16-16-21",
            "",
        ] {
            let e = precision("--precision", bad).unwrap_err().to_string();
            assert!(e.contains(&all) && e.contains("--precision"), "{e}");
        }
        let e = precision("--precision", "16/16/16")
            .unwrap_err()
            .to_string();
        assert!(e.contains(&format!("now default ({DEFAULT})")), "{e}");
        let e = precision("--precision", "12/12/8").unwrap_err().to_string();
        assert!(e.contains("now exact-12-12-8"), "{e}");
    }

    #[test]
    fn model_config_refuses_planar() {
        assert_eq!(
            model_config("exact-12-12-12").unwrap().to_string(),
            "exact-12-12-12"
        );
        assert_eq!(model_config(DEFAULT_NAME).unwrap(), DEFAULT);
        let e = model_config(&PLANAR.to_string()).unwrap_err().to_string();
        assert!(e.contains("planar") && e.contains(DEFAULT_NAME), "{e}");
        assert!(model_config("16/16/16").is_err());
    }

    #[test]
    fn swept_names_read_the_registry() {
        let sweep: [&str; swept_count(false)] = swept_names(false);
        let with: [&str; swept_count(true)] = swept_names(true);
        assert!(sweep.iter().copied().eq(registry::sweep().map(|e| e.name)));
        assert_eq!(with.len(), sweep.len() + 1);
        assert_eq!(with[sweep.len()], PLANAR.to_string());
        assert_eq!(strategy("--bounds", "best").unwrap(), "best");
        assert!(strategy("--bounds", "laine").is_err());
    }
}
