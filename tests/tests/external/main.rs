//! The tests that run outside tools, one module per subject: Icarus Verilog (the vector, bounds
//! and sample-test RTL benches), Verilator (DPI-C), cocotb, a C and C++ compiler (the C
//! library), QEMU (the Cortex-M programs and their reports), Yosys and nextpnr. One test binary:
//! `cargo test -p uvt-tests --test external`; one module: `cargo test -p uvt-tests --test
//! external dpi::`.

mod bounds_rtl;
mod bsample;
mod cocotb;
mod dpi;
mod ffi_c;
mod m4_qemu;
mod mul;
mod mutation;
mod pnr;
mod psample;
mod reports;
mod vectors;
