//! Tighter bounds strategies, each a separate [`crate::BoundsStrategy`] and composable:
//! - [`hull::HullCull`]: tile culling by the swept cone of the triangle over the shutter and lens
//!   (in front of any strategy);
//! - [`lens_time::LensTime`]: Laine 2011's bounds plus one t interval per lens slab (Wu 2014
//!   stage II), checked per sample;
//! - [`hyper::Hyper`]: Laine 2011's box plus bilinear (u, t) / (v, t) bounding surfaces
//!   (after Munkberg & Akenine-Möller 2012), checked per sample;
//! - [`hull_lens()`] and [`best()`] put hull culling in front of lens slabs and of the surfaces.
//!
//! The conservativeness proof of each is at the top of its file.

pub mod hull;
pub mod hyper;
pub mod lens_time;

#[cfg(test)]
mod eps_corners;

use crate::bounds::Laine2011;
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

/// The combined strategy, swept-hull tile culling in front of the bilinear (u, t) / (v, t)
/// surfaces ("best": the highest STE of the bench-ste rows at a per-tile cost below
/// "hull+lens-t").
pub const fn best() -> HullCull<Hyper> {
    HullCull::new(Hyper, "best")
}
