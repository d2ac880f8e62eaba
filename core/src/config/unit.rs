//! Unit variants chosen at build time: which effects the rasterizer unit has hardware for.
//!
//! A [`Unit`] is a type parameter of the renderer (`Renderer`, default [`Full`]). Its constants
//! `MOTION` and `DEFOCUS` gate, at compile time, the setup terms, the bounds coefficients and the
//! sample-test terms of the classes it lacks (`if U::MOTION && …`): a variant's program does not
//! contain them. A triangle whose class (`Triangle::class`) the unit does not accept is
//! refused by the renderer with `Error::ClassNotInUnit`, never rendered with
//! the terms left out. For every triangle a variant accepts, its output is bit-identical to
//! [`Full`]'s at the same precision (`tests/tests/model/variants.rs`): the gated terms are exactly the
//! ones the class does not use.
//!
//! Input fields each variant reads (`Triangle::class` decides acceptance from the whole triangle;
//! after that the unit's stages read only these):
//!
//! | unit | accepts classes | reads |
//! |---|---|---|
//! | [`Full`] | static, motion, defocus, motion + defocus | x, y, z, w, CoC at both shutter ends |
//! | [`MotionOnly`] | static, motion | x, y, z, w at both ends; refuses any CoC ≠ 0 |
//! | [`DefocusOnly`] | static, defocus | x, y, z, w, CoC at t0; refuses any field of t1 differing from t0 |
//! | [`StaticOnly`] | static | x, y, z, w at t0; refuses a differing t1 field or any CoC ≠ 0 |
//!
//! (`Triangle::class`: motion iff x, y, z or w differ between the ends, or the CoC differs on a
//! triangle with some CoC ≠ 0; defocus iff some CoC ≠ 0. A triangle with CoC = 0 everywhere is
//! in focus whatever else; the CoC of an in-focus triangle is never read.)

use crate::config::class::Class;

mod sealed {
    /// Only this module's four units implement [`super::Unit`].
    pub trait Sealed {}
    impl Sealed for super::Full {}
    impl Sealed for super::MotionOnly {}
    impl Sealed for super::DefocusOnly {}
    impl Sealed for super::StaticOnly {}
}

/// The effects a rasterizer unit has hardware for (sealed: the four units below).
pub trait Unit: sealed::Sealed + Copy + Default + core::fmt::Debug + 'static {
    /// The unit has the motion-blur terms (t lerps, t bounds).
    const MOTION: bool;
    /// The unit has the defocus terms (lens offsets, u/v bounds).
    const DEFOCUS: bool;
    /// Name for reports and errors: "full", "motion-only", "defocus-only", "static-only".
    const NAME: &'static str;
    /// Whether the unit can render a triangle of `class`: its motion ⊆ `MOTION` and its
    /// defocus ⊆ `DEFOCUS`.
    fn accepts(class: Class) -> bool {
        (Self::MOTION || !class.motion()) && (Self::DEFOCUS || !class.defocus())
    }
}

/// Every effect: motion and defocus.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Full;
/// Motion blur only (in-focus triangles).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MotionOnly;
/// Defocus blur only (triangles that do not move).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DefocusOnly;
/// Static, in-focus triangles only.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StaticOnly;

impl Unit for Full {
    const MOTION: bool = true;
    const DEFOCUS: bool = true;
    const NAME: &'static str = "full";
}
impl Unit for MotionOnly {
    const MOTION: bool = true;
    const DEFOCUS: bool = false;
    const NAME: &'static str = "motion-only";
}
impl Unit for DefocusOnly {
    const MOTION: bool = false;
    const DEFOCUS: bool = true;
    const NAME: &'static str = "defocus-only";
}
impl Unit for StaticOnly {
    const MOTION: bool = false;
    const DEFOCUS: bool = false;
    const NAME: &'static str = "static-only";
}

/// The names of the four units, widest first (the order reports list them in).
pub const UNIT_NAMES: [&str; 4] = [
    Full::NAME,
    MotionOnly::NAME,
    DefocusOnly::NAME,
    StaticOnly::NAME,
];

#[cfg(test)]
mod tests {
    use super::*;

    const CLASSES: [Class; 4] = [
        Class::Static,
        Class::Motion,
        Class::Defocus,
        Class::MotionDefocus,
    ];

    /// The acceptance table, written out by hand (rows: units; columns: static, motion,
    /// defocus, both).
    #[test]
    fn acceptance_table() {
        let table: [(&str, [bool; 4], [bool; 4]); 4] = [
            (Full::NAME, CLASSES.map(Full::accepts), [true; 4]),
            (
                MotionOnly::NAME,
                CLASSES.map(MotionOnly::accepts),
                [true, true, false, false],
            ),
            (
                DefocusOnly::NAME,
                CLASSES.map(DefocusOnly::accepts),
                [true, false, true, false],
            ),
            (
                StaticOnly::NAME,
                CLASSES.map(StaticOnly::accepts),
                [true, false, false, false],
            ),
        ];
        for (name, got, want) in table {
            assert_eq!(
                got, want,
                "unit {name}: accepts(static, motion, defocus, both)"
            );
        }
        assert_eq!(
            UNIT_NAMES,
            ["full", "motion-only", "defocus-only", "static-only"]
        );
    }
}
