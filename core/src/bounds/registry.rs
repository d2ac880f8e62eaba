//! Every named bounds strategy, defined once: [`STRATEGIES`], the names every command, table and
//! report takes (the composed strategies, swept-hull tile culling in front of the others, are
//! built in [`crate::bounds::composed`] and re-exported here), with
//! [`with_strategy!`](crate::with_strategy) binding a name to its strategy value.
//!
//! | name | strategy |
//! |---|---|
//! | `bbox` | [`BboxScan`]: every sample of the footprint |
//! | `laine2011` | [`Laine2011`] |
//! | `hull` | [`hull()`]: swept-hull tile culling in front of Laine 2011 |
//! | `lens-t` | [`LensTime`] with [`BEST_SLABS`] lens slabs |
//! | `hyper` | [`Hyper`] |
//! | `hull+lens-t` | [`hull_lens()`] |
//! | `hull+edge-t` | [`hull_edge()`] |
//! | `best` | [`best()`] |
//! | `auto` | [`Auto`]: Laine 2011, hull or hull+edge-t per triangle |
//!
//! [`BboxScan`]: crate::bounds::bbox::BboxScan
//! [`Laine2011`]: crate::bounds::laine::Laine2011
//! [`LensTime`]: crate::bounds::lens_time::LensTime
//! [`Hyper`]: crate::bounds::hyper::Hyper
//! [`Auto`]: crate::bounds::auto::Auto

pub use crate::bounds::composed::{best, hull, hull_edge, hull_lens, BEST_SLABS};

/// The registry's one list: `$callback!` receives every strategy as
/// `name => Variant: Type = value;`, in the order of the tables (module docs): its name, its
/// variant in [`AnyStrategy`](crate::bounds::any::AnyStrategy), its type and its value.
/// Internal: use [`STRATEGIES`], [`with_strategy!`](crate::with_strategy) and
/// [`AnyStrategy`](crate::bounds::any::AnyStrategy).
#[doc(hidden)]
#[macro_export]
macro_rules! __uvt_strategies {
    ($callback:ident!($($pre:tt)*)) => {
        $crate::$callback! {$($pre)*
            "bbox" => Bbox: $crate::bounds::bbox::BboxScan = $crate::bounds::bbox::BboxScan;
            "laine2011" => Laine2011: $crate::bounds::laine::Laine2011 = $crate::bounds::laine::Laine2011;
            "hull" => Hull: $crate::bounds::hull::HullCull<$crate::bounds::laine::Laine2011> = $crate::bounds::composed::hull();
            "lens-t" => LensTime: $crate::bounds::lens_time::LensTime<{ $crate::bounds::composed::BEST_SLABS }> = $crate::bounds::lens_time::LensTime::<{ $crate::bounds::composed::BEST_SLABS }>;
            "hyper" => Hyper: $crate::bounds::hyper::Hyper = $crate::bounds::hyper::Hyper;
            "hull+lens-t" => HullLens: $crate::bounds::hull::HullCull<$crate::bounds::lens_time::LensTime<{ $crate::bounds::composed::BEST_SLABS }>> = $crate::bounds::composed::hull_lens();
            "hull+edge-t" => HullEdge: $crate::bounds::hull::HullCull<$crate::bounds::edge_time::EdgeTime<$crate::bounds::laine::Laine2011>> = $crate::bounds::composed::hull_edge();
            "best" => Best: $crate::bounds::hull::HullCull<$crate::bounds::edge_time::EdgeTime<$crate::bounds::hyper::Hyper>> = $crate::bounds::composed::best();
            "auto" => Auto: $crate::bounds::auto::Auto = $crate::bounds::auto::Auto::new();
        }
    };
}

/// The names of [`__uvt_strategies`] as an array.
#[doc(hidden)]
#[macro_export]
macro_rules! __uvt_strategy_array {
    ($($name:literal => $variant:ident: $ty:ty = $value:expr;)*) => {
        [$($name,)*]
    };
}

/// The dispatch of [`with_strategy!`](crate::with_strategy) over the entries.
#[doc(hidden)]
#[macro_export]
macro_rules! __uvt_strategy_dispatch {
    ($n:ident, $s:ident, $body:expr; $($name:literal => $variant:ident: $ty:ty = $value:expr;)*) => {
        match $n {
            $($name => {
                let $s: $ty = $value;
                ::core::option::Option::Some($body)
            })*
            _ => ::core::option::Option::None,
        }
    };
}

/// The name of every strategy of the registry, in the order of the tables (module docs).
pub const STRATEGIES: [&str; 9] = __uvt_strategies!(__uvt_strategy_array!());

/// `with_strategy!(name, s => body)`: `Some(body)` with `s` bound to the strategy named `name`
/// (one of [`STRATEGIES`]), `None` for any other name. The only place a strategy's name meets
/// its value:
///
/// ```
/// use uvt_core::{with_strategy, BoundsStrategy};
/// assert_eq!(with_strategy!("hull+edge-t", s => s.name()), Some("hull+edge-t"));
/// assert_eq!(with_strategy!("laine", s => s.name()), None);
/// ```
#[macro_export]
macro_rules! with_strategy {
    ($name:expr, $s:ident => $body:expr) => {{
        let name: &str = $name;
        $crate::__uvt_strategies!(__uvt_strategy_dispatch!(name, $s, $body;))
    }};
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bounds::strategy::BoundsStrategy;

    /// Every listed name dispatches to a strategy of that name; no other name does.
    #[test]
    fn every_name_is_its_strategy() {
        for name in STRATEGIES {
            assert_eq!(
                crate::with_strategy!(name, s => s.name()),
                Some(name),
                "{name}"
            );
        }
        for bad in ["", "laine", "Laine2011", "hull+hyper", "edge-t"] {
            assert_eq!(crate::with_strategy!(bad, s => s.name()), None, "{bad:?}");
            assert!(
                crate::bounds::any::AnyStrategy::named(bad).is_none(),
                "{bad:?}"
            );
        }
        for name in STRATEGIES {
            let any = crate::bounds::any::AnyStrategy::named(name).map(|s| s.name());
            assert_eq!(any, Some(name), "{name}");
        }
    }
}
