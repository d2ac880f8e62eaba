//! The independent f64 reference: the same stages as `uvt-core` under the same names, in glam
//! f64 with no rounding, with a ray-cast sample test instead of edge functions. It runs on the
//! scene's own f64 values and the pattern's exact samples, so differences from the core measure
//! the core's quantization.

pub mod bounds;
pub mod sample;
pub mod setup;
