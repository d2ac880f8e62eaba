//! The model's properties, one module per subject: pure Rust, no outside tool (conservativeness,
//! watertightness, depth, every bounds strategy and unit variant against the reference, the
//! quantization bound, the paths named in the documentation and in comments, the
//! documentation's copies of committed reports, and the crates' import graph). One test binary: `cargo test -p uvt-tests --test model`; one module:
//! `cargo test -p uvt-tests --test model zmax::`.

mod auto;
mod bounded;
mod conservative;
mod depth;
mod docs;
mod domain;
mod edge_time;
mod hindsight;
mod host_reference;
mod hull;
mod imports;
mod limit;
mod motion_unit;
mod planar;
mod planar_exponent;
mod precision;
mod quant_check;
mod report_copies;
mod row_span;
mod stages;
mod static_unit;
mod ste;
mod strategy_ops;
mod variants;
mod watertight;
mod zmax;
