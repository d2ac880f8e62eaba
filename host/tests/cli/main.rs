//! The host tools end to end, one module per subject: the `uvt` binary's commands (render, fit,
//! units, precision, cost, diff images, vector streams, frame vectors of a scene) and the host library's scene files,
//! focus range and error statements; a closed pipe. One test binary: `cargo test -p uvt-host --test cli`; one
//! module: `cargo test -p uvt-host --test cli streams::`.

mod cli;
mod cost_text;
mod diff_image;
mod export_scene;
mod fit_cli;
mod focus_range;
mod m4_units_tables;
mod pipes;
mod planar_fit;
mod precision_cli;
mod scene_files;
mod statements;
mod streams;
