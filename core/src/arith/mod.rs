//! The shared arithmetic of every stage: the 192-bit accumulator ([`wide`]), closed t/u/v
//! intervals and the outward-rounding solvers ([`interval`]), and the divisions ([`div`]).

pub mod div;
pub mod interval;
pub mod wide;
