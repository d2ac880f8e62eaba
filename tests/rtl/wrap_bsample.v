// A user's unit that wraps the reference unit (tests of the own-unit command in docs/rtl.md,
// tests/tests/external/bsample.rs): the architectural ports only, uvt_bsample.v inside (which
// needs uvt_mul.v), its internal edge outputs left unconnected.
`timescale 1ns / 1ps
module wrap_bsample (
    input  wire               clk,
    input  wire               in_valid,
    input  wire [959:0]       trin,
    input  wire [11:0]        vp_w,
    input  wire [11:0]        vp_h,
    input  wire [19:0]        xs,
    input  wire [19:0]        ys,
    input  wire signed [31:0] t,
    input  wire signed [31:0] u,
    input  wire signed [31:0] v,
    output wire               out_valid,
    output wire               out_covered,
    output wire signed [31:0] depth
);
    uvt_bsample unit (
        .clk(clk), .in_valid(in_valid), .trin(trin), .vp_w(vp_w), .vp_h(vp_h), .xs(xs), .ys(ys),
        .t(t), .u(u), .v(v), .edge_valid(), .covered(), .det_sign(), .ab(), .e(),
        .out_valid(out_valid), .out_covered(out_covered), .depth(depth)
    );
endmodule
