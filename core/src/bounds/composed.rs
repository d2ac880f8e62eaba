//! The composed strategies: swept-hull tile culling ([`HullCull`]) in front of another
//! strategy, each built once here under its registry name ([`crate::bounds::registry`] lists
//! them; `auto` picks among them without depending on the registry).

use crate::bounds::edge_time::EdgeTime;
use crate::bounds::hull::HullCull;
use crate::bounds::hyper::Hyper;
use crate::bounds::laine::Laine2011;
use crate::bounds::lens_time::LensTime;

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
