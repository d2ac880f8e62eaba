//! The class of a triangle: which effects it has (motion, defocus). Setup decides it
//! (`Triangle::class`); a unit accepts the classes it has hardware for.

/// Which effects a triangle has; the class decides which work is skipped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Class {
    /// no motion, in focus: plain 2D test, no bounds
    Static,
    /// motion only: t bounds, no lens terms
    Motion,
    /// defocus only: u/v bounds, no t terms
    Defocus,
    /// both: everything
    MotionDefocus,
}

impl Class {
    /// Index 0..4 for counters.
    pub fn index(self) -> usize {
        match self {
            Class::Static => 0,
            Class::Motion => 1,
            Class::Defocus => 2,
            Class::MotionDefocus => 3,
        }
    }
    /// Every class, in [`Class::index`] order.
    pub const ALL: [Class; 4] = [
        Class::Static,
        Class::Motion,
        Class::Defocus,
        Class::MotionDefocus,
    ];
    /// Name for reports and errors: "static", "motion", "defocus", "motion+defocus".
    pub fn name(self) -> &'static str {
        match self {
            Class::Static => "static",
            Class::Motion => "motion",
            Class::Defocus => "defocus",
            Class::MotionDefocus => "motion+defocus",
        }
    }
    /// Whether the triangle moves (any of x, y, z, w, or the CoC of a defocused triangle).
    pub fn motion(self) -> bool {
        matches!(self, Class::Motion | Class::MotionDefocus)
    }
    /// Whether any CoC is non-zero.
    pub fn defocus(self) -> bool {
        matches!(self, Class::Defocus | Class::MotionDefocus)
    }
}
