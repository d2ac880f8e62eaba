//! The record codec: the record lengths, the setup records at a configuration and the seeded
//! streams. One test binary: `cargo test -p uvt-records --test codec`; one module: `cargo test
//! -p uvt-records --test codec stream::`.

mod coverage;
mod layout;
mod setup;
mod stream;
