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
use crate::sample::exact::{exact_test, sample_eval_unit};
use crate::sample::pos::{Hit, ScreenPos};
use crate::setup::Setup;
use crate::stats::Ops;

/// The sample test for one sample of a visible triangle: the depth on a hit. A setup of a
/// [`crate::config::precision::Bounded`] precision runs the bounded test ([`crate::sample::bounded`]); every other
/// runs the exact test above.
pub fn sample_test(setup: &Setup, pos: ScreenPos, s: &Sample, ops: &mut Ops) -> Option<Hit> {
    if setup.prec.planar() && setup.class == Class::Static {
        return crate::sample::planar::planar_test(setup, pos, ops);
    }
    if setup.prec.offset_shift().is_some() {
        return crate::sample::bounded::bounded_test(setup, pos, s, ops);
    }
    exact_test(setup, pos, s, ops)
}

/// The sample test of precision `P` on unit `U`, chosen at compile time: `P`'s bounded test
/// ([`crate::sample::bounded::bounded_test_unit`]) or the exact one, with only the classes `U`
/// accepts instantiated. For a setup of precision `P` whose class `U` accepts, the same hit as
/// [`sample_test`]; a class `U` does not accept is never covered (the renderer refuses it
/// before setup).
pub fn sample_test_unit<P: Precision, U: Unit>(
    setup: &Setup,
    pos: ScreenPos,
    s: &Sample,
    ops: &mut Ops,
) -> Option<Hit> {
    if !U::accepts(setup.class) {
        return None;
    }
    // A `Planar` precision's static class (gated as in setup: a constant on the static-only
    // unit, whose program then has no bounded datapath).
    if P::PLANAR && !(U::MOTION && setup.class.motion()) && !(U::DEFOCUS && setup.class.defocus()) {
        return crate::sample::planar::planar_test(setup, pos, ops);
    }
    if P::OFFSET_SHIFT.is_some() {
        return crate::sample::bounded::bounded_test_unit::<P, U>(setup, pos, s, ops);
    }
    sample_eval_unit::<U>(setup, pos, s, ops).hit
}
