//! # uvt-host
//!
//! What users run on a workstation: scenes, sample patterns, an independent f64 reference of
//! every stage, a frame driver that runs the fixed-point core and the reference side by side,
//! images, reports and the STE benchmark table. The binary is `uvt` (`src/main.rs`).
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod bench;
pub mod budget;
pub mod compare;
pub mod converge;
pub mod cost;
pub mod fit;
pub mod fit_confirm;
pub mod fit_report;
pub mod frame;
pub mod heatmap;
pub mod json;
pub mod mesh;
pub mod oracle;
pub mod pattern;
pub mod planar;
pub mod precision;
pub mod precision_cost;
pub mod reference;
pub mod render;
pub mod report;
pub mod scene;
pub mod scenes;
pub mod synth;
pub mod vectors;
