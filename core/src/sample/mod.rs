//! Stage 3 — the sample test: does the triangle at the sample's (t, u, v) cover the sample's
//! screen position, and at what depth? Three datapaths, chosen by the precision: the exact test
//! ([`exact`]), the hardware-width bounded test ([`bounded`]) and the planar static test
//! ([`planar`]); this module is the one dispatch between them.

pub mod bounded;
pub mod exact;
pub mod planar;
pub mod pos;

use crate::config::class::Class;
use crate::config::precision::Precision;
use crate::config::unit::Unit;
use crate::input::Sample;
use crate::sample::pos::{Hit, ScreenPos};
use crate::setup::Setup;
use crate::stats::Ops;

/// Whether a triangle of `class` takes the planar test at precision `P` on unit `U`: a
/// `Planar` precision's static class — static as the unit sees it (gated as in setup: a
/// constant on the static-only unit, whose program then has no bounded datapath).
#[inline(always)]
pub fn takes_planar<P: Precision, U: Unit>(class: Class) -> bool {
    P::PLANAR && !(U::MOTION && class.motion()) && !(U::DEFOCUS && class.defocus())
}

/// The sample test of precision `P` on unit `U` for a setup made at `P` ([`crate::setup::setup`]
/// or [`Setup::unculled`] with the same `P`), chosen at compile time: the planar test for a
/// static triangle of a [`crate::config::precision::Planar`] precision, the bounded test of
/// any other bounded precision, else the exact test — with only the classes `U` accepts
/// instantiated. The depth on a hit; a class `U` does not accept is never covered (the
/// renderer refuses it before setup). This is the one dispatch between the three tests.
pub fn test<P: Precision, U: Unit>(
    setup: &Setup,
    pos: ScreenPos,
    s: &Sample,
    ops: &mut Ops,
) -> Option<Hit> {
    if !U::accepts(setup.class) {
        return None;
    }
    if takes_planar::<P, U>(setup.class) {
        return planar::test(setup, pos, ops);
    }
    if P::OFFSET_SHIFT.is_some() {
        return bounded::test::<P, U>(setup, pos, s, ops);
    }
    exact::eval::<U>(setup, pos, s, ops).hit
}
