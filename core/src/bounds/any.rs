//! Every registry strategy behind one type, [`AnyStrategy`], generated from the registry's one
//! list ([`crate::bounds::registry`]): a strategy picked by name at run time, for code that
//! would otherwise be compiled once per strategy (a tool's checks, a test over every
//! strategy). It dispatches once per call to the named strategy's own code — `prepare` once per
//! triangle, and the walk to the strategy's own walk, so every tile step and the per-sample loop
//! run on the strategy's own tile type, with no dispatch per tile or per sample — and its
//! decisions are that strategy's, bit for bit. A user's renderer names the strategy's own type
//! (`Renderer<B, N, P, U>`); this wrapper is for run-time choice.
//!
//! The coefficients and tiles of one strategy are kept in the variant of the same name
//! ([`AnyCoeffs`], [`AnyTile`]); a call with the coefficients of another strategy (only possible
//! by mixing two `AnyStrategy` values) culls the tile and walks nothing.

use crate::bounds::strategy::{BoundsStrategy, CellVisitor, RowSpan, TileBounds, UvtBox};
use crate::config::unit::Unit;
use crate::input::PixelRect;
use crate::setup::Setup;
use crate::stats::Ops;

/// The types of [`AnyStrategy`] and their impls, from the registry's entries. Internal.
#[doc(hidden)]
#[macro_export]
macro_rules! __uvt_any_strategy {
    ($($name:literal => $variant:ident: $ty:ty = $value:expr;)*) => {
        /// Any strategy of the registry (module docs).
        #[derive(Clone, Copy, Debug)]
        #[allow(clippy::large_enum_variant)]
        pub enum AnyStrategy {
            $(
                #[doc = concat!("`", $name, "`")]
                $variant($ty),
            )*
        }

        /// The per-triangle coefficients of an [`AnyStrategy`]: its strategy's own, inline (no
        /// heap: every variant is as large as the largest).
        #[derive(Clone, Copy, Debug)]
        #[allow(clippy::large_enum_variant)]
        pub enum AnyCoeffs {
            $(
                #[doc = concat!("of `", $name, "`")]
                $variant(<$ty as BoundsStrategy>::Coeffs),
            )*
        }

        /// A tile of an [`AnyStrategy`]: its strategy's own.
        #[derive(Clone, Copy, Debug)]
        #[allow(clippy::large_enum_variant)]
        pub enum AnyTile {
            $(
                #[doc = concat!("of `", $name, "`")]
                $variant(<$ty as BoundsStrategy>::Tile),
            )*
        }

        impl AnyStrategy {
            /// The strategy named `name` (one of
            /// [`STRATEGIES`](crate::bounds::registry::STRATEGIES)); `None` for any other name.
            pub fn named(name: &str) -> Option<AnyStrategy> {
                match name {
                    $($name => Some(AnyStrategy::$variant($value)),)*
                    _ => None,
                }
            }
        }

        impl TileBounds for AnyTile {
            #[inline]
            fn uvt_box(&self) -> &UvtBox {
                match self {
                    $(AnyTile::$variant(t) => t.uvt_box(),)*
                }
            }
            #[inline]
            fn predicate(&self, u: i32, v: i32, t: i32, ops: &mut Ops) -> bool {
                match self {
                    $(AnyTile::$variant(x) => x.predicate(u, v, t, ops),)*
                }
            }
        }

        impl BoundsStrategy for AnyStrategy {
            type Coeffs = AnyCoeffs;
            type Tile = AnyTile;

            fn name(&self) -> &'static str {
                match self {
                    $(AnyStrategy::$variant(s) => s.name(),)*
                }
            }

            #[inline(always)]
            fn prepare<U: Unit>(&self, setup: &Setup, ops: &mut Ops) -> AnyCoeffs {
                match self {
                    $(AnyStrategy::$variant(s) => AnyCoeffs::$variant(s.prepare::<U>(setup, ops)),)*
                }
            }

            fn tile<U: Unit>(
                &self,
                setup: &Setup,
                c: &AnyCoeffs,
                tile: PixelRect,
                ops: &mut Ops,
            ) -> Option<AnyTile> {
                match (self, c) {
                    $((AnyStrategy::$variant(s), AnyCoeffs::$variant(c)) => {
                        s.tile::<U>(setup, c, tile, ops).map(AnyTile::$variant)
                    })*
                    #[allow(unreachable_patterns)]
                    _ => None,
                }
            }

            fn row_span(
                &self,
                setup: &Setup,
                c: &AnyCoeffs,
                row: PixelRect,
                bt: u16,
                ops: &mut Ops,
            ) -> RowSpan {
                match (self, c) {
                    $((AnyStrategy::$variant(s), AnyCoeffs::$variant(c)) => {
                        s.row_span(setup, c, row, bt, ops)
                    })*
                    #[allow(unreachable_patterns)]
                    _ => RowSpan::pruned(row, row.x0, row.x0),
                }
            }

            fn span_tile<U: Unit>(
                &self,
                setup: &Setup,
                c: &AnyCoeffs,
                span: &RowSpan,
                tile: PixelRect,
                ops: &mut Ops,
            ) -> Option<AnyTile> {
                match (self, c) {
                    $((AnyStrategy::$variant(s), AnyCoeffs::$variant(c)) => {
                        s.span_tile::<U>(setup, c, span, tile, ops).map(AnyTile::$variant)
                    })*
                    #[allow(unreachable_patterns)]
                    _ => None,
                }
            }

            /// The named strategy's own walk (its own tile type reaches `v`).
            #[inline(always)]
            fn walk<U: Unit, V: CellVisitor>(
                &self,
                setup: &Setup,
                c: &AnyCoeffs,
                region: PixelRect,
                bt: u16,
                ops: &mut Ops,
                v: &mut V,
            ) {
                match (self, c) {
                    $((AnyStrategy::$variant(s), AnyCoeffs::$variant(c)) => {
                        s.walk::<U, V>(setup, c, region, bt, ops, v)
                    })*
                    #[allow(unreachable_patterns)]
                    _ => {}
                }
            }
        }
    };
}

__uvt_strategies!(__uvt_any_strategy!());
