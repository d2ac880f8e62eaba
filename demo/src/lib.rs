//! # uvt-demo
//!
//! The built-in demo scene of uvt ([`scene`]: 32×32 pixels, 4 samples per pixel, seven
//! triangles with motion, defocus, a camera-plane crossing and one wholly behind the camera) and
//! the per-stage cost workloads the Cortex-M programs measure ([`cost`]). `no_std`, no heap:
//! `examples/m4_render/` (`main.rs`, `target.rs`) runs both on a Cortex-M4F and a Cortex-M3 under QEMU
//! (`m4_report.sh` prints the size, stack and instruction tables), and the tests run them on the
//! host and compare checksums.
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]
#![warn(
    clippy::arithmetic_side_effects,
    clippy::indexing_slicing,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    clippy::cast_possible_wrap
)]

pub mod cost;
pub mod scene;
pub mod workload;
pub mod zmax_cost;

pub use scene::{prims, render, unit_prims, viewport, DemoResult, BOUNDS_TILE, SAMPLES, SIZE, SPP};
