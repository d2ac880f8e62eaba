//! What a configuration is: every signal's number format ([`formats`]), the precision types
//! ([`precision`]) and every named configuration ([`registry`]), the unit variants ([`unit`])
//! and the class of a triangle ([`class`]).

pub mod class;
pub mod formats;
pub mod precision;
pub mod registry;
pub mod unit;
