//! Every named configuration, defined once: the libm-test registry of uvt. A [`Config`] is a
//! precision's fraction bits and datapath, named `exact-P-T-B` ([`Prec<P, T, B>`]: the exact
//! sample test), `bounded-P-T-B-O` ([`Bounded<P, T, B, O>`]: the hardware-width test on an
//! offset grid `2^O`) or `planar-P-T-B-O` ([`Planar<P, T, B, O>`]: the bounded test plus the
//! planar static test). [`CONFIGS`] lists the configurations the tools and programs are built
//! for, each with its precision type; [`with_config!`](crate::with_config) binds a type alias to
//! the type of a listed configuration. Every command-line option, report, cost table, Cortex-M
//! program and vector manifest reads its names from here.
//!
//! | name | type | in the precision sweep |
//! |---|---|---|
//! | `exact-16-16-16` | [`crate::Exact`] | yes |
//! | `bounded-16-16-16-20` | [`crate::BoundedPrecision`], the default | yes |
//! | `bounded-16-16-16-22`, `-24` | `Bounded<16, 16, 16, 22>`, `…24` | yes |
//! | `bounded-12-12-12-24`, `-26` | `Bounded<12, 12, 12, 24>`, `…26` | yes |
//! | `bounded-8-8-8-28` | `Bounded<8, 8, 8, 28>` | yes |
//! | `planar-16-16-16-20` | [`crate::PlanarPrecision`] | beside it |
//! | `exact-12-12-8`, `exact-8-8-4`, `exact-6-6-2` | `Prec<12, 12, 8>`, … | no (narrower exact inputs) |
//!
//! [`Prec<P, T, B>`]: crate::config::precision::Prec
//! [`Bounded<P, T, B, O>`]: crate::config::precision::Bounded
//! [`Planar<P, T, B, O>`]: crate::config::precision::Planar

use core::fmt;

use crate::config::precision::{Precision, OFFSET_SHIFT_MAX, OFFSET_SHIFT_MIN};

/// A precision configuration by value: its fraction bits and datapath. Fields private; built by
/// [`Config::of`] or [`Config::parse`], which refuse anything outside the ranges the precision
/// types accept (P, T ∈ 2..=16, B ∈ 0..=16, O ∈ [`OFFSET_SHIFT_MIN`]..=[`OFFSET_SHIFT_MAX`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Config {
    pos: u32,
    tuv: u32,
    bnd: u32,
    off: Option<u32>,
    planar: bool,
}

impl Config {
    /// The configuration of precision `P`.
    pub const fn of<P: Precision>() -> Config {
        Config {
            pos: P::POS_FRAC,
            tuv: P::TUV_FRAC,
            bnd: P::BOUND_FRAC,
            off: P::OFFSET_SHIFT,
            planar: P::PLANAR,
        }
    }
    /// Parse `exact-P-T-B`, `bounded-P-T-B-O` or `planar-P-T-B-O`; `None` for anything else or
    /// out of range. Any value in range parses (the width table and the cost model take every
    /// one); [`find`] gives only the configurations of [`CONFIGS`].
    pub fn parse(name: &str) -> Option<Config> {
        let mut it = name.split('-');
        let kind = it.next()?;
        let mut num = || it.next().and_then(|s| s.parse::<u32>().ok());
        let (pos, tuv, bnd) = (num()?, num()?, num()?);
        let (off, planar) = match kind {
            "exact" => (None, false),
            "bounded" => (Some(num()?), false),
            "planar" => (Some(num()?), true),
            _ => return None,
        };
        if num().is_some() {
            return None;
        }
        let ok = (2..=16).contains(&pos)
            && (2..=16).contains(&tuv)
            && bnd <= 16
            && match off {
                None => true,
                Some(o) => (OFFSET_SHIFT_MIN..=OFFSET_SHIFT_MAX).contains(&o),
            };
        ok.then_some(Config {
            pos,
            tuv,
            bnd,
            off,
            planar,
        })
    }
    /// Fraction bits of positions.
    pub const fn pos(&self) -> u32 {
        self.pos
    }
    /// Fraction bits of t/u/v.
    pub const fn tuv(&self) -> u32 {
        self.tuv
    }
    /// Fraction bits of the bounds' pixel grid.
    pub const fn bnd(&self) -> u32 {
        self.bnd
    }
    /// Offset-grid shift of the bounded test (`None`: the exact test).
    pub const fn off(&self) -> Option<u32> {
        self.off
    }
    /// Whether static triangles take the planar test (a `planar-…` configuration).
    pub const fn planar(&self) -> bool {
        self.planar
    }
    /// The configuration with the same bits and the bounded test for every class: a planar
    /// configuration's moving and defocused classes run it (itself for the others).
    pub const fn bounded_base(&self) -> Config {
        Config {
            planar: false,
            ..*self
        }
    }
    /// Equality in a constant context (what `==` gives).
    pub const fn same(&self, o: &Config) -> bool {
        let off = match (self.off, o.off) {
            (None, None) => true,
            (Some(a), Some(b)) => a == b,
            _ => false,
        };
        self.pos == o.pos
            && self.tuv == o.tuv
            && self.bnd == o.bnd
            && off
            && self.planar == o.planar
    }
}

impl fmt::Display for Config {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (p, t, b) = (self.pos, self.tuv, self.bnd);
        match (self.off, self.planar) {
            (None, _) => write!(f, "exact-{p}-{t}-{b}"),
            (Some(o), false) => write!(f, "bounded-{p}-{t}-{b}-{o}"),
            (Some(o), true) => write!(f, "planar-{p}-{t}-{b}-{o}"),
        }
    }
}

/// One configuration of the registry: its name, its value and whether the precision sweep
/// (`uvt precision`, `demo/m4_report.sh --sweep`) runs it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Entry {
    /// the name (`Config`'s `Display`; a test checks that they agree)
    pub name: &'static str,
    /// the value
    pub config: Config,
    /// a configuration of the precision sweep
    pub sweep: bool,
}

/// The registry's one list: `$callback!` receives every entry as `name => Type, sweep`, in the
/// order of [`CONFIGS`] (the sweep's order: exact first, then bounded from the default down to
/// the narrowest; then the planar configuration and the narrower exact ones). Internal: use
/// [`CONFIGS`] and [`with_config!`](crate::with_config).
#[doc(hidden)]
#[macro_export]
macro_rules! __uvt_configs {
    ($callback:ident!($($pre:tt)*)) => {
        $crate::$callback!($($pre)*
            "exact-16-16-16" => $crate::config::precision::Prec<16, 16, 16>, true;
            "bounded-16-16-16-20" => $crate::config::precision::Bounded<16, 16, 16, 20>, true;
            "bounded-16-16-16-22" => $crate::config::precision::Bounded<16, 16, 16, 22>, true;
            "bounded-16-16-16-24" => $crate::config::precision::Bounded<16, 16, 16, 24>, true;
            "bounded-12-12-12-24" => $crate::config::precision::Bounded<12, 12, 12, 24>, true;
            "bounded-12-12-12-26" => $crate::config::precision::Bounded<12, 12, 12, 26>, true;
            "bounded-8-8-8-28" => $crate::config::precision::Bounded<8, 8, 8, 28>, true;
            "planar-16-16-16-20" => $crate::config::precision::Planar<16, 16, 16, 20>, false;
            "exact-12-12-8" => $crate::config::precision::Prec<12, 12, 8>, false;
            "exact-8-8-4" => $crate::config::precision::Prec<8, 8, 4>, false;
            "exact-6-6-2" => $crate::config::precision::Prec<6, 6, 2>, false;
        )
    };
}

/// The entries of [`__uvt_configs`] as an array.
#[doc(hidden)]
#[macro_export]
macro_rules! __uvt_config_array {
    ($($name:literal => $ty:ty, $sweep:literal;)*) => {
        [$($crate::config::registry::Entry {
            name: $name,
            config: $crate::config::registry::Config::of::<$ty>(),
            sweep: $sweep,
        },)*]
    };
}

/// The dispatch of [`with_config!`](crate::with_config) over the entries.
#[doc(hidden)]
#[macro_export]
macro_rules! __uvt_config_dispatch {
    ($cfg:ident, $P:ident, $body:expr; $($name:literal => $ty:ty, $sweep:literal;)*) => {
        $(if $crate::config::registry::Config::same(
            &$cfg,
            &$crate::config::registry::Config::of::<$ty>(),
        ) {
            type $P = $ty;
            ::core::option::Option::Some($body)
        } else)* {
            ::core::option::Option::None
        }
    };
}

/// `with_config!(cfg, P => body)`: `Some(body)` with the type alias `P` bound to the precision
/// type of configuration `cfg` (a [`Config`]) if it is one of [`CONFIGS`], else `None`. The
/// only place a configuration's value meets its type:
///
/// ```
/// use uvt_core::config::registry::find;
/// use uvt_core::{with_config, Precision};
/// let cfg = find("bounded-12-12-12-24").unwrap();
/// assert_eq!(with_config!(cfg, P => P::POS_FRAC), Some(12));
/// assert_eq!(with_config!(uvt_core::config::registry::Config::parse("exact-9-9-9").unwrap(), P => 0), None);
/// ```
#[macro_export]
macro_rules! with_config {
    ($cfg:expr, $P:ident => $body:expr) => {{
        let cfg: $crate::config::registry::Config = $cfg;
        $crate::__uvt_configs!(__uvt_config_dispatch!(cfg, $P, $body;))
    }};
}

/// Every configuration of the registry (module docs), in the sweep's order.
pub const CONFIGS: [Entry; 11] = __uvt_configs!(__uvt_config_array!());

/// The default configuration: [`crate::DefaultPrecision`].
pub const DEFAULT: Config = Config::of::<crate::config::precision::DefaultPrecision>();

/// The exact configuration the golden vectors and the width table start from: [`crate::Exact`].
pub const EXACT: Config = Config::of::<crate::config::precision::Exact>();

/// The planar static configuration: [`crate::PlanarPrecision`].
pub const PLANAR: Config = Config::of::<crate::config::precision::PlanarPrecision>();

/// The registry configuration named `name` (`"default"`: [`DEFAULT`]); `None` for any other
/// name. A `const fn`, so a program can pick its configuration at build time.
// The loop index stays below `CONFIGS.len()` (its condition), so the index is in range and
// `i + 1` cannot overflow.
#[allow(clippy::indexing_slicing, clippy::arithmetic_side_effects)]
pub const fn find(name: &str) -> Option<Config> {
    if eq(name.as_bytes(), b"default") {
        return Some(DEFAULT);
    }
    let mut i = 0;
    while i < CONFIGS.len() {
        if eq(name.as_bytes(), CONFIGS[i].name.as_bytes()) {
            return Some(CONFIGS[i].config);
        }
        i += 1;
    }
    None
}

/// The registry's name of `cfg` (`None` outside the registry). A `const fn`, as [`find`].
// The loop index stays below `CONFIGS.len()` (its condition): in range, `i + 1` no overflow.
#[allow(clippy::indexing_slicing, clippy::arithmetic_side_effects)]
pub const fn name_of(cfg: Config) -> Option<&'static str> {
    let mut i = 0;
    while i < CONFIGS.len() {
        if CONFIGS[i].config.same(&cfg) {
            return Some(CONFIGS[i].name);
        }
        i += 1;
    }
    None
}

/// The configurations of the precision sweep, in order.
pub fn sweep() -> impl Iterator<Item = &'static Entry> {
    CONFIGS.iter().filter(|e| e.sweep)
}

/// Byte-string equality in a constant context.
// `i < a.len() = b.len()` (the loop condition and the length check): both indexes are in range
// and `i + 1` cannot overflow.
#[allow(clippy::indexing_slicing, clippy::arithmetic_side_effects)]
const fn eq(a: &[u8], b: &[u8]) -> bool {
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

#[cfg(test)]
#[allow(clippy::arithmetic_side_effects)]
mod tests {
    extern crate std;
    use super::*;
    use std::string::ToString;

    /// Every entry's name is its configuration's `Display`, parses back to it, is found, and
    /// names one configuration only; the dispatch binds each to its own type.
    #[test]
    fn names_types_and_values_agree() {
        for (i, e) in CONFIGS.iter().enumerate() {
            assert_eq!(e.config.to_string(), e.name, "entry {i}");
            assert_eq!(Config::parse(e.name), Some(e.config), "{}", e.name);
            assert_eq!(find(e.name), Some(e.config), "{}", e.name);
            assert_eq!(name_of(e.config), Some(e.name));
            let bits = with_config!(e.config, P => Config::of::<P>());
            assert_eq!(bits, Some(e.config), "{}: dispatch", e.name);
            for f in CONFIGS.iter().skip(i + 1) {
                assert_ne!(e.config, f.config, "{} and {}", e.name, f.name);
            }
        }
        assert_eq!(find("default"), Some(DEFAULT));
        assert_eq!(name_of(DEFAULT), Some("bounded-16-16-16-20"));
        assert_eq!(
            sweep().map(|e| e.name).collect::<std::vec::Vec<_>>(),
            [
                "exact-16-16-16",
                "bounded-16-16-16-20",
                "bounded-16-16-16-22",
                "bounded-16-16-16-24",
                "bounded-12-12-12-24",
                "bounded-12-12-12-26",
                "bounded-8-8-8-28"
            ]
        );
    }

    /// Names outside the ranges or the grammar do not parse; the old tuple form is not a name.
    #[test]
    fn parse_refuses() {
        for bad in [
            "",
            "16/16/16",
            "exact-16-16",
            "exact-16-16-16-20",
            "bounded-16-16-16",
            "bounded-16-16-16-19",
            "bounded-16-16-16-33",
            "exact-1-16-16",
            "exact-17-16-16",
            "exact-16-16-17",
            "planar-16-16-16",
            "Exact-16-16-16",
        ] {
            assert_eq!(Config::parse(bad), None, "{bad:?}");
            assert_eq!(find(bad), None, "{bad:?}");
        }
        assert_eq!(
            Config::parse("planar-16-16-16-20").map(|c| c.bounded_base().to_string()),
            Some("bounded-16-16-16-20".to_string())
        );
    }
}
