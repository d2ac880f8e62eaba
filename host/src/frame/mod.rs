//! Frames: the core's render loop over a whole frame on the host, and the f64 reference's own
//! (`crate::compare` holds the two against each other sample by sample). Its files from the bottom up, each using only
//! files listed before it (and nothing of this `mod.rs`):
//!
//! - [`opts`]: what a frame run is asked ([`opts::RunOpts`]);
//! - [`counters`]: the counters of a frame and the rendered frame;
//! - [`oracle`]: the in-band oracle box of `uvt render`'s report, an observer of the core's loop;
//! - [`core_frame`]: the core's frame — the core's own loop ([`uvt_core::Engine`]) in bands on
//!   threads, every triangle set up once ([`core_frame::run_core`]);
//! - [`reference`]: the f64 reference's frame, its own loop ([`reference::run_reference`]).

pub mod core_frame;
pub mod counters;
pub mod opts;
pub mod oracle;
pub mod reference;
