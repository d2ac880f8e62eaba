//! Tighter bounds strategies, each a separate [`crate::BoundsStrategy`] and composable:
//! - [`hull::HullCull`]: tile culling by the swept cone of the triangle over the shutter and lens
//!   (in front of any strategy);
//! - [`lens_time::LensTime`]: Laine 2011's bounds plus one t interval per lens slab (Wu 2014
//!   stage II), checked per sample;
//! - [`best()`] combines both.
//!
//! The conservativeness proof of each is at the top of its file.

pub mod hull;
pub mod lens_time;

use crate::bounds::Laine2011;
pub use hull::HullCull;
pub use lens_time::LensTime;

/// Lens slabs of the combined strategy.
pub const BEST_SLABS: usize = 4;

/// Swept-hull tile culling in front of Laine 2011 ("hull").
pub const fn hull() -> HullCull<Laine2011> {
    HullCull::new(Laine2011, "hull")
}

/// Swept-hull tile culling in front of lens-dependent time bounds ("best").
pub const fn best() -> HullCull<LensTime<BEST_SLABS>> {
    HullCull::new(LensTime, "best")
}
