// uvt_interval_check — the per-sample interval test of the stochastic rasterizer (Laine et al.
// 2011 §3): a sample is sent to the sample test only if its lens point (u, v) and time t lie
// inside the closed intervals computed for its bounds tile. Combinational, synthesizable.
//
// All inputs are uvt-core's t/u/v format: 32-bit two's complement, 16 fraction bits
// (1.0 = 32'h0001_0000). Golden vectors: select_in.hex (9 words per record, in port order
// u_lo u_hi v_lo v_hi t_lo t_hi u v t) and select_out.hex (bit 0 = inside).
`timescale 1ns / 1ps
module uvt_interval_check (
    input  wire signed [31:0] u_lo,
    input  wire signed [31:0] u_hi,
    input  wire signed [31:0] v_lo,
    input  wire signed [31:0] v_hi,
    input  wire signed [31:0] t_lo,
    input  wire signed [31:0] t_hi,
    input  wire signed [31:0] u,
    input  wire signed [31:0] v,
    input  wire signed [31:0] t,
    output wire               inside
);
    assign inside = (u_lo <= u) && (u <= u_hi) &&
                    (v_lo <= v) && (v <= v_hi) &&
                    (t_lo <= t) && (t <= t_hi);
endmodule
