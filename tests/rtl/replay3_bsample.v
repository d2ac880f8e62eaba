// A stand-in for a user's own bounded sample-test unit, for the test of the bench's wiring
// options (tests/tests/external/bsample.rs): the architectural ports only, 3 clocks of latency, and no
// arithmetic — it replays the expected outputs of the +OUT file in issue order. +REPLAY_FLIP=r
// flips bit 0 of record r's depth, which the bench must report.
`timescale 1ns / 1ps
module replay3_bsample (
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
    localparam WO = 14, MAXREC = 16384;
    reg [31:0] mem [0:MAXREC*WO-1];
    reg [8*1024-1:0] file;
    integer k, flip, n;
    initial begin
        k = 0;
        if (!$value$plusargs("REPLAY_FLIP=%d", flip)) flip = -1;
        if ($value$plusargs("OUT=%s", file) && $value$plusargs("N=%d", n) && n > 0)
            $readmemh(file, mem, 0, n * WO - 1);
    end
    reg [2:0] vld = 0;
    reg [2:0] cov = 0;
    reg [31:0] d1 = 0, d2 = 0, d3 = 0;
    always @(posedge clk) begin
        vld <= {vld[1:0], in_valid};
        cov <= {cov[1:0], in_valid ? mem[k*WO][0] : 1'b0};
        d1 <= in_valid ? mem[k*WO+1] ^ {31'b0, k == flip} : 32'b0;
        d2 <= d1;
        d3 <= d2;
        if (in_valid) k <= k + 1;
    end
    assign out_valid = vld[2];
    assign out_covered = cov[2];
    assign depth = d3;
endmodule
