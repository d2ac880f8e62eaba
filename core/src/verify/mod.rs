//! Test-only verification of the core, apart from the product code: domain-corner drives of
//! every stage against wide shadow computations (`*_corners`), the frozen contracts of the
//! bounded and planar datapaths with their committed hashes (`*_frozen`), the direct references
//! the optimised hull and surface strategies are compared with (`*_reference`). The seeded random
//! numbers (`UVT_SEED`, `UVT_EXTENSIVE`) are `uvt-testkit`'s, shared with the integration tests.

mod bounded_corners;
pub(crate) mod bounded_frozen;
mod corners;
mod edge_time_corners;
mod eps_corners;
mod fast_corners;
pub(crate) mod hull_reference;
pub(crate) mod hyper_reference;
mod interval_corners;
mod planar_corners;
pub(crate) mod planar_frozen;
mod width_corners;
mod wrap_reference;
