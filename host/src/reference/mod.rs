//! The independent f64 reference: the same stages as `uvt-core` under the same module and function
//! names (its types are prefixed `Ref` — [`setup::RefSetup`], [`bounds::RefBox`] — so they are
//! not confused with the core's fixed-point ones), in glam f64 with no rounding, with a ray-cast
//! sample test instead of edge functions. It runs on the scene's own f64 values and the pattern's
//! exact samples, so differences from the core measure the core's quantization. Files: [`setup`],
//! then [`bounds`] (uses `setup`) and [`sample`]; each uses only the scene triangle
//! ([`crate::scene::tri`]) besides.

pub mod bounds;
pub mod sample;
pub mod setup;
