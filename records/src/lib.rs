//! The uvt record codec, in one place for every consumer: the host tools (`uvt vectors export`,
//! `check`, `gen`, `ver`, `decode`), the committed vector files and the C library `uvt-ffi`.
//! A record is one line of a `*_in.hex` or `*_out.hex` file: a fixed number of 32-bit words
//! whose fields [`format::layout`] defines (the manifests and `vectors/README.md` tables are
//! generated from it). Its files from the bottom up, each using only files listed before it:
//!
//! - [`format`]: the layouts, the record builder, parsing and field decoding;
//! - [`stages`]: setup, bounds, interval check, exact sample test and resolve records;
//! - [`bsample`]: the bounded sample-test records (any bounded configuration);
//! - [`psample`]: the planar sample-test records (the planar static configuration);
//! - [`kind`]: the record kinds by name and one entry point that runs any of them;
//! - [`coverage`]: the decision paths (`uvt_core::coverage` bins) that records take, counted;
//! - [`stream`]: the seeded input-record streams (`uvt vectors gen`, `uvt_gen`), shardable;
//! - [`typed`]: the typed API (a triangle set up once, its sample test) of the C library and the
//!   Python module.

#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod bsample;
pub mod coverage;
pub mod format;
pub mod kind;
pub mod psample;
pub mod stages;
pub mod stream;
pub mod typed;
