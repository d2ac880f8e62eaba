//! The C library: the C boundary (codes, never a panic; the committed vectors through the C
//! functions; the typed API) and the committed header. One test binary: `cargo test -p uvt-ffi
//! --test c_api`; one module: `cargo test -p uvt-ffi --test c_api header::`.

mod boundary;
mod coverage;
mod header;
