// The ECP5 MULT18X18D model (vectors/rtl/ecp5/MULT18X18D.v) for Verilator builds of the units'
// MAP = 1 builds: the model is Verilog-2005 with `$fatal` (Icarus accepts it in -g2005), a
// SystemVerilog task that Verilator knows only in SystemVerilog sources, while the builds here
// parse `.v` files as Verilog-2005 (+1364-2005ext+v: uvt_psample.v names a wire `inside`).
// Included from this `.sv` file, the model is read as SystemVerilog. Build with
// -I<repository>/vectors/rtl/ecp5 (vectors/dpi/README.md); waivers in rtl.vlt.
`begin_keywords "1800-2017"
`include "MULT18X18D.v"
`end_keywords
