// uvt_dpi: the uvt golden model (libuvt_ffi.a, header ffi/include/uvt.h) for SystemVerilog
// testbenches through DPI-C. Every import binds straight to a library function: no C shim.
// The C types are the header's: a fixed-size unpacked `int unsigned a[N]` argument is a
// `const uint32_t *` (input) or `uint32_t *` (output), `longint unsigned` a `uint64_t` (also the
// `size_t` lengths, on LP64 hosts), `string` a `const char *`. Return codes: 0 (UVT_OK) or a
// count on success, negative UVT_ERR_* on failure, then uvt_last_error() names the field.
//
// Configurations are passed by name: the library reads a null `config` as the kind's default,
// but a DPI `string` cannot be null and "" is not a registry name, so pass UVT_BOUNDED_DEFAULT
// or UVT_PLANAR (or another name of `uvt configs`).
//
// Build (Verilator 5.006): verilator --binary --timing uvt_dpi.sv <tb>.sv <rtl> libuvt_ffi.a
//   -LDFLAGS "-lpthread -ldl -lm"   (vectors/dpi/README.md)
`timescale 1ns / 1ps
package uvt_dpi;
    // Kind codes and record sizes (uvt.h UVT_KIND_*, UVT_*_WORDS).
    localparam int unsigned UVT_KIND_BSAMPLE = 4;
    localparam int unsigned UVT_KIND_PSAMPLE = 5;
    localparam int unsigned UVT_BSAMPLE_IN_WORDS = 37;
    localparam int unsigned UVT_BSAMPLE_OUT_WORDS = 14;
    localparam int unsigned UVT_PSAMPLE_IN_WORDS = 28;
    localparam int unsigned UVT_PSAMPLE_OUT_WORDS = 8;
    // Return codes (uvt.h UVT_OK, UVT_ERR_*).
    localparam int UVT_OK = 0;
    localparam int UVT_ERR_INPUT = -4;
    localparam int UVT_ERR_CONFIG = -5;
    localparam int UVT_ERR_MISMATCH = -6;
    // The configurations of the two sample-test units.
    localparam string UVT_BOUNDED_DEFAULT = "bounded-16-16-16-20";
    localparam string UVT_PLANAR = "planar-16-16-16-20";

    // Interface and record format versions.
    import "DPI-C" function int unsigned uvt_version();
    import "DPI-C" function int unsigned uvt_format_version();
    // Message of the last failed call on this thread ("" after a success).
    import "DPI-C" function string uvt_last_error();
    // Fixed description of a return code.
    import "DPI-C" function string uvt_strerror(input int code);

    // The model on one record: bounded (37 → 14 words) and planar (28 → 8 words).
    import "DPI-C" function int uvt_bsample(input int unsigned in_w[37],
                                            output int unsigned out_w[14]);
    import "DPI-C" function int uvt_psample(input int unsigned in_w[28],
                                            output int unsigned out_w[8]);

    // Record `index` of the seeded stream of `kind` at configuration `cfg` (`spp`: pass 16).
    // Returns the words written. One import per record size, both binding uvt_gen.
    import "DPI-C" uvt_gen = function int uvt_gen_bsample(
        input int unsigned kind, input string cfg, input longint unsigned seed,
        input longint unsigned index, input int unsigned spp,
        output int unsigned out_w[37], input longint unsigned out_len);
    import "DPI-C" uvt_gen = function int uvt_gen_psample(
        input int unsigned kind, input string cfg, input longint unsigned seed,
        input longint unsigned index, input int unsigned spp,
        output int unsigned out_w[28], input longint unsigned out_len);

    // Fill the derived input fields in place (bounded: class; planar: the setup fields).
    import "DPI-C" uvt_complete = function int uvt_complete_bsample(
        input int unsigned kind, inout int unsigned in_w[37], input longint unsigned len);
    import "DPI-C" uvt_complete = function int uvt_complete_psample(
        input int unsigned kind, inout int unsigned in_w[28], input longint unsigned len);

    // Compare two output records: 0, or UVT_ERR_MISMATCH with uvt_last_error() listing every
    // differing field (expected and observed, hex and decoded). arch_only != 0: covered and
    // depth only.
    import "DPI-C" uvt_compare = function int uvt_compare_bsample(
        input int unsigned kind, input int unsigned expected[14],
        input int unsigned observed[14], input longint unsigned len,
        input int unsigned arch_only);
    import "DPI-C" uvt_compare = function int uvt_compare_psample(
        input int unsigned kind, input int unsigned expected[8],
        input int unsigned observed[8], input longint unsigned len,
        input int unsigned arch_only);
endpackage
