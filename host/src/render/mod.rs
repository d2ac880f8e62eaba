//! `uvt render`: one scene with the core and with the f64 reference; images, heat map and
//! reports. Its files from the bottom up, each using only files listed before it (and nothing of
//! this `mod.rs`):
//!
//! - [`heatmap`]: the heat map image with its legend (and the built-in font);
//! - [`diff`]: `diff.png`, its monotone colour scale and legend, and the enlargement of small
//!   images (uses [`heatmap`]'s font);
//! - [`opts`]: what a render is asked and what it returns;
//! - [`report`]: `report.json` and `report.md`;
//! - [`scene_render`]: the render itself and the files it writes.

pub mod diff;
pub mod heatmap;
pub mod opts;
pub mod report;
pub mod scene_render;
