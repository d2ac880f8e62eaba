//! Tighter bounds strategies, each a separate [`crate::BoundsStrategy`] and composable:
//! - [`hull::HullCull`]: tile culling by the swept cone of the triangle over the shutter and lens
//!   (in front of any strategy);
//! - [`lens_time::LensTime`]: Laine 2011's bounds plus one t interval per lens slab (Wu 2014
//!   stage II), checked per sample;
//! - [`hyper::Hyper`]: Laine 2011's box plus bilinear (u, t) / (v, t) bounding surfaces
//!   (after Munkberg & Akenine-Möller 2012), checked per sample;
//! - [`edge_time::EdgeTime`]: the inner strategy's box with t narrowed by Laine's dual-space
//!   bound along the normal of the triangle's most oblique edge (motion-only triangles);
//! - [`hull_lens()`], [`hull_edge()`] and [`best()`] put hull culling in front of lens slabs, of
//!   the edge bound and of the surfaces.
//!
//! The conservativeness proof of each is at the top of its file.

pub mod edge_time;
pub mod hull;
pub mod hyper;
pub mod lens_time;

#[cfg(test)]
mod eps_corners;

use crate::bounds::Laine2011;
pub use edge_time::EdgeTime;
pub use hull::HullCull;
pub use hyper::Hyper;
pub use lens_time::LensTime;

/// Lens slabs of "lens-t" and "hull+lens-t".
pub const BEST_SLABS: usize = 4;

/// Swept-hull tile culling in front of Laine 2011 ("hull").
pub const fn hull() -> HullCull<Laine2011> {
    HullCull::new(Laine2011, "hull")
}

/// Swept-hull tile culling in front of lens-dependent time bounds ("hull+lens-t").
pub const fn hull_lens() -> HullCull<LensTime<BEST_SLABS>> {
    HullCull::new(LensTime, "hull+lens-t")
}

/// Swept-hull tile culling in front of edge-direction time bounds on Laine 2011
/// ("hull+edge-t").
pub const fn hull_edge() -> HullCull<EdgeTime<Laine2011>> {
    HullCull::new(EdgeTime::new(Laine2011, "edge-t"), "hull+edge-t")
}

/// The combined strategy: swept-hull tile culling in front of the edge-direction time bound
/// (motion-only triangles) on the bilinear (u, t) / (v, t) surfaces ("best": the highest STE of
/// the bench-ste rows; the edge bound adds 34 ops per tile on motion-only triangles only).
pub const fn best() -> HullCull<EdgeTime<Hyper>> {
    HullCull::new(EdgeTime::new(Hyper, "edge-t+hyper"), "best")
}
