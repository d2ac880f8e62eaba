//! # uvt-host
//!
//! What users run on a workstation: scenes, sample patterns, an independent f64 reference of
//! every stage, the core's own render loop over whole frames in parallel, the comparison of the
//! core with the reference, images, reports and the STE benchmark table. The binary is `uvt` (`src/bin/uvt/`: `main.rs` runs a command, `cli.rs` declares them).
//!
//! Modules by what they do, from the bottom up; a file uses only files of the modules listed
//! before its own (or earlier files of its own folder, as that folder's `mod.rs` lists them),
//! never a `mod.rs` nor this root, so there is no import circle (`tests/tests/model/imports.rs`
//! checks it):
//!
//! - [`log`]: lines on the standard error (progress, warnings) that a closed pipe does not turn
//!   into a panic;
//! - [`scene`]: scene input — scene files, meshes, built-in scenes, memory budget, sample
//!   patterns;
//! - [`reference`](mod@reference): the independent f64 reference of every stage;
//! - [`frame`]: whole frames — the core's own loop in bands on threads, the reference's own loop;
//! - [`config`]: configurations and their costs — the core's configuration and strategy
//!   registries on the command line, the multiplier model, the unit variants' sample-test
//!   cost, the inputs' rounding, the error statements (d_q), the planar static configuration;
//! - [`compare`]: the one sample-by-sample comparison of the core with the reference;
//! - [`oracle`]: the axis-aligned limit of `bench-ste`;
//! - [`bench`](mod@bench): `uvt bench-ste`, and one bounds strategy over a frame by name;
//! - [`converge`]: `uvt converge`;
//! - [`fit`]: `uvt fit` and `uvt units`;
//! - [`precision`]: `uvt precision`;
//! - [`render`]: `uvt render`;
//! - [`vectors`]: `uvt vectors`, the golden test vectors for RTL;
//! - [`splice`]: `uvt splice`, the documentation's copies of reports and command outputs.
#![forbid(unsafe_code)]
#![deny(missing_docs)]
// Lines on stderr go through `log::line`: a closed pipe must not panic.
#![deny(clippy::print_stderr)]

pub mod bench;
pub mod compare;
pub mod config;
pub mod converge;
pub mod fit;
pub mod frame;
pub mod log;
pub mod oracle;
pub mod precision;
pub mod reference;
pub mod render;
pub mod scene;
pub mod splice;
pub mod vectors;
