//! The one place that picks the pipeline of a (precision, unit): [`Select`]. A unit's program
//! contains exactly the pipeline picked here, so what a user instantiates as
//! `Renderer<B, N, P, U>` (`crate::raster::renderer`) is what the Cortex-M programs and the
//! reports measure.
//!
//! | precision | full | motion-only | defocus-only | static-only |
//! |---|---|---|---|---|
//! | exact ([`Prec`]) | general | general | general | general |
//! | bounded ([`Bounded`]) | general | [`MotionPipeline`] | general | general |
//! | planar ([`Planar`]) | general | [`MotionPipeline`] | general | [`StaticPipeline`] |
//!
//! (general = [`General`]: setup, the bounds strategy's (u, v, t) bounds and the precision's
//! sample test with the unit's missing effects compiled out.) Generic code over a precision `P`
//! and a unit `U` names the pipeline as [`PipelineOf<B, P, U>`] with the bound
//! `(P, U): Select<B>`, which every sealed precision and unit satisfy.

use crate::bounds::strategy::BoundsStrategy;
use crate::config::precision::{Bounded, Planar, Prec};
use crate::config::unit::{DefocusOnly, Full, MotionOnly, StaticOnly};
use crate::units::general::General;
use crate::units::motion_only::MotionPipeline;
use crate::units::pipeline::Pipeline;
use crate::units::static_only::StaticPipeline;

/// The pipeline of precision `P` on unit `U` with bounds strategy `B`, implemented for every
/// pair `(P, U)` of a sealed precision and a unit (module docs).
pub trait Select<B: BoundsStrategy> {
    /// The pipeline.
    type Pipeline: Pipeline<Bounds = B>;
}

/// The pipeline [`Select`] picks for `(P, U)` with bounds strategy `B`.
pub type PipelineOf<B, P, U> = <(P, U) as Select<B>>::Pipeline;

impl<B: BoundsStrategy, U: crate::config::unit::Unit, const A: u32, const T: u32, const D: u32>
    Select<B> for (Prec<A, T, D>, U)
{
    type Pipeline = General<B, Prec<A, T, D>, U>;
}

/// One `impl Select` per (precision kind, unit) with the pipeline it gets.
macro_rules! select {
    ($($kind:ident, $unit:ty => $pipe:ty;)*) => {$(
        impl<B: BoundsStrategy, const A: u32, const T: u32, const D: u32, const O: u32> Select<B>
            for ($kind<A, T, D, O>, $unit)
        {
            type Pipeline = $pipe;
        }
    )*};
}

select! {
    Bounded, Full => General<B, Bounded<A, T, D, O>, Full>;
    Bounded, DefocusOnly => General<B, Bounded<A, T, D, O>, DefocusOnly>;
    Bounded, StaticOnly => General<B, Bounded<A, T, D, O>, StaticOnly>;
    Bounded, MotionOnly => MotionPipeline<B, Bounded<A, T, D, O>>;
    Planar, Full => General<B, Planar<A, T, D, O>, Full>;
    Planar, DefocusOnly => General<B, Planar<A, T, D, O>, DefocusOnly>;
    Planar, StaticOnly => StaticPipeline<B>;
    Planar, MotionOnly => MotionPipeline<B, Planar<A, T, D, O>>;
}
