//! The specialised units: the static-only unit at a planar precision ([`static_only`]) and the
//! motion-only unit at a bounded precision ([`motion_only`]).

pub mod motion_only;
pub mod static_only;
