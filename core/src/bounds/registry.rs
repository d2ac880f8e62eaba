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

/// The name of every strategy of the registry, in the order of the tables (module docs).
pub const STRATEGIES: [&str; 9] = [
    "bbox",
    "laine2011",
    "hull",
    "lens-t",
    "hyper",
    "hull+lens-t",
    "hull+edge-t",
    "best",
    "auto",
];

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
    ($name:expr, $s:ident => $body:expr) => {
        match $name {
            "bbox" => {
                let $s = $crate::bounds::bbox::BboxScan;
                ::core::option::Option::Some($body)
            }
            "laine2011" => {
                let $s = $crate::bounds::laine::Laine2011;
                ::core::option::Option::Some($body)
            }
            "hull" => {
                let $s = $crate::bounds::composed::hull();
                ::core::option::Option::Some($body)
            }
            "lens-t" => {
                let $s =
                    $crate::bounds::lens_time::LensTime::<{ $crate::bounds::composed::BEST_SLABS }>;
                ::core::option::Option::Some($body)
            }
            "hyper" => {
                let $s = $crate::bounds::hyper::Hyper;
                ::core::option::Option::Some($body)
            }
            "hull+lens-t" => {
                let $s = $crate::bounds::composed::hull_lens();
                ::core::option::Option::Some($body)
            }
            "hull+edge-t" => {
                let $s = $crate::bounds::composed::hull_edge();
                ::core::option::Option::Some($body)
            }
            "best" => {
                let $s = $crate::bounds::composed::best();
                ::core::option::Option::Some($body)
            }
            "auto" => {
                let $s = $crate::bounds::auto::Auto::new();
                ::core::option::Option::Some($body)
            }
            _ => ::core::option::Option::None,
        }
    };
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
        }
    }
}
