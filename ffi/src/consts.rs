//! The interface version, the kind codes and the record lengths of the header (held equal to
//! the layouts by `ffi/tests/c_api/boundary.rs`).

/// Version of this C interface: bumped when a function's signature or meaning changes.
pub const UVT_FFI_VERSION: u32 = 1;

/// Kind code of setup records (`setup_in` → `setup_out`).
pub const UVT_KIND_SETUP: u32 = 0;
/// Kind code of bounds records (`bounds_in` with its `setup_in` → `bounds_out`).
pub const UVT_KIND_BOUNDS: u32 = 1;
/// Kind code of interval-check records.
pub const UVT_KIND_SELECT: u32 = 2;
/// Kind code of exact sample-test records (`sample_in` with its `setup_in`).
pub const UVT_KIND_SAMPLE: u32 = 3;
/// Kind code of bounded sample-test records.
pub const UVT_KIND_BSAMPLE: u32 = 4;
/// Kind code of planar sample-test records.
pub const UVT_KIND_PSAMPLE: u32 = 5;
/// Kind code of resolve records.
pub const UVT_KIND_RESOLVE: u32 = 6;

/// Words of a `setup_in` record.
pub const UVT_SETUP_IN_WORDS: usize = 32;
/// Words of a `setup_out` record.
pub const UVT_SETUP_OUT_WORDS: usize = 108;
/// Words of a `bounds_in` record.
pub const UVT_BOUNDS_IN_WORDS: usize = 3;
/// Words of a `bounds_out` record.
pub const UVT_BOUNDS_OUT_WORDS: usize = 7;
/// Words of a `select_in` record.
pub const UVT_SELECT_IN_WORDS: usize = 9;
/// Words of a `select_out` record.
pub const UVT_SELECT_OUT_WORDS: usize = 1;
/// Words of a `sample_in` record.
pub const UVT_SAMPLE_IN_WORDS: usize = 6;
/// Words of a `sample_out` record.
pub const UVT_SAMPLE_OUT_WORDS: usize = 26;
/// Words of a `bsample_in` record.
pub const UVT_BSAMPLE_IN_WORDS: usize = 37;
/// Words of a `bsample_out` record.
pub const UVT_BSAMPLE_OUT_WORDS: usize = 14;
/// Words of a `psample_in` record.
pub const UVT_PSAMPLE_IN_WORDS: usize = 28;
/// Words of a `psample_out` record.
pub const UVT_PSAMPLE_OUT_WORDS: usize = 8;
/// Words of a `resolve_out` record (a `resolve_in` record has one word per sample).
pub const UVT_RESOLVE_OUT_WORDS: usize = 1;
/// Largest samples per pixel of a resolve record.
pub const UVT_MAX_SPP: u32 = 64;
/// Longest record of any kind, in words (a buffer of this size takes any output record).
pub const UVT_MAX_WORDS: usize = 108;
