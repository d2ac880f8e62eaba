// uvt_psample — the planar static sample test of uvt-core (core/src/sample/planar.rs, configuration
// planar-16-16-16-20) as a fully pipelined unit: one sample per clock, bit-exact against the
// golden vectors psample_in.hex / psample_out.hex. Synthesizable Verilog-2005 (Icarus Verilog
// and Yosys).
//
// The unit receives what the planar setup hands the per-sample test (like a real pipeline, it
// never sees the vertices): the edge normals n_k = (a, b, c) = P'_{k+1} × P'_{k+2} of the rounded
// vertices (|.| <= 2·(2^15 − 1)^2 < 2^31), the orientation σ = ±1 and the depth plane G, f; plus
// the viewport and the sample position. Widths are those of the frozen contract
// (core/src/verify/planar_frozen.rs): the rounded vertices have 15 bits, so n, G and the direction d have
// 32 and every product is 32 × 32 → 64 bits; the only parameters are the multiplier tiling's.
//
// Per sample (planar.rs "Per sample", "Depth"):
//   d = ((2xs − 256W)·H, (256H − 2ys)·W, 256·W·H)          |d_i| <= 2^30
//   E_k = n_k · d                                          |E| < 3·2^61, exact in 64 bits
//   covered iff for every k: σ·E_k > 0, or E_k = 0 and the fill rule accepts
//     (σ·a_k > 0, or a_k = 0 and σ·b_k > 0)
//   acc = G · d                                            |acc| < 3·2^61
//   depth = clamp(floor(acc / 2^f)) for f >= 0 (shift by min(f, 63)), clamp(acc·2^(−f)) for
//           f < 0, clamped to [−2^31, 2^31 − 2] (DEPTH_NEAR, DEPTH_FAR); 0 when not covered.
//
// Pipeline (LAT = 6 clocks from in_valid to out_valid; every stage registered):
//   1  inputs; gx = 2xs − 256W, gy = 256H − 2ys, 256W (21 bits signed each)
//   2  direction: 3 products 21 × 13 (gx·H, gy·W, 256W·H), each truncated to 32 bits (exact)
//   3  12 products 32 × 32 → 64: n_k,i · d_i (9) and G_i · d_i (3)
//   4  sums E_k = Σ_i n_k,i·d_i and acc = Σ_i G_i·d_i (64 bits, exact); the depth shift
//      amount clamp(f + 33, 0, 96), which depends on f alone
//   5  coverage (sign tests, fill rule); depth shift: acc·2^33 arithmetically shifted right by
//      that amount (= the floor for f >= −33), saturation flag for f < −33, acc ≠ 0
//   6  clamp to the depth range, 0 when not covered; outputs registered
// With PIPE = 1 the products of stage 2 take one more clock and those of stage 3 two more
// (uvt_mul REG; a LUT chunk's rows summed four at a time): LAT = 9.
// Every product goes through uvt_mul.v, which tiles it into hard multipliers as the cost model
// (host/src/config/multipliers.rs, host/src/config/planar_static.rs PRODUCTS) counts:
// 3·1 + 12·2 = 27 DSP48E1 (25 × 18), 3·1 + 12·4 = 51 MULT18X18D (18 × 18).
//
// Ports = record fields (vectors/README.md "RTL integration: the planar sample-test unit"):
//   n[32*(3k+i) +: 32]  psample_in word 13 + 3k + i (n0_a n0_b n0_c n1_a … n2_c)
//   sigma               word 22 bits 1..0 (±1), f word 22 bits 9..2 (signed)
//   g[32*i +: 32]       words 23..25
//   vp_w, vp_h          word 12 (≤ 2048); xs, ys words 26, 27 (xs < 256·W, ys < 256·H: the core
//                       has no result outside the viewport, and the unit's 21-bit gx, gy assume it)
//   covered             psample_out word 0 bit 0, depth word 1, e[64*k +: 64] = E_k words 2..7,
//                       all with out_valid
`timescale 1ns / 1ps
module uvt_psample #(
    // hard-multiplier ports and LUT chunk limit of every product (uvt_mul.v): 25 × 18 for
    // Xilinx DSP48E1 (the default), 18 × 18 for Lattice ECP5 MULT18X18D
    parameter DSP_A = 25,
    parameter DSP_B = 18,
    parameter LUTW = 8,
    // PIPE = 1: registers inside the products (uvt_mul REG: 1 in stage 2, 2 in stage 3), for
    // a faster clock: LAT = 9 instead of 6 (same results)
    parameter PIPE = 0
) (
    input  wire               clk,
    input  wire               in_valid,
    input  wire [287:0]       n,
    input  wire signed [1:0]  sigma,
    input  wire signed [7:0]  f,
    input  wire [95:0]        g,
    input  wire [11:0]        vp_w,
    input  wire [11:0]        vp_h,
    input  wire [19:0]        xs,
    input  wire [19:0]        ys,
    output wire               out_valid,
    output wire               covered,
    output wire signed [31:0] depth,
    output wire [191:0]       e
);
    localparam R2 = PIPE ? 1 : 0;      // clocks inside the stage-2 products (uvt_mul REG)
    localparam R3 = PIPE ? 2 : 0;      // and inside the stage-3 products
    localparam LAT = 6 + R2 + R3;

    reg [LAT:1] vld;
    always @(posedge clk) vld <= {vld[LAT-1:1], in_valid};
    assign out_valid = vld[LAT];

    // ---- stage 1: inputs; direction factors ------------------------------------------------
    reg [287:0] s1_n;
    reg [95:0]  s1_g;
    reg         s1_neg;                // σ = −1
    reg signed [7:0]  s1_f;
    reg signed [12:0] s1_w, s1_h;      // W, H <= 2048
    reg signed [20:0] s1_gx, s1_gy;    // |.| <= 2^19 inside the viewport
    reg signed [20:0] s1_w8;           // 256·W <= 2^19
    always @(posedge clk) begin
        s1_n <= n;
        s1_g <= g;
        s1_neg <= sigma[1];
        s1_f <= f;
        s1_w <= {1'b0, vp_w};
        s1_h <= {1'b0, vp_h};
        s1_gx <= $signed({1'b0, xs[18:0], 1'b0}) - $signed({1'b0, vp_w, 8'b0});
        s1_gy <= $signed({1'b0, vp_h, 8'b0}) - $signed({1'b0, ys[18:0], 1'b0});
        s1_w8 <= {1'b0, vp_w, 8'b0};
    end

    // ---- stage 2: d = (gx·H, gy·W, 256W·H) ---------------------------------------------------
    wire signed [33:0] px, py, pw;
    uvt_mul #(.AW(21), .BW(13), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(R2)) m_dx (s1_gx, s1_h, px, clk);
    uvt_mul #(.AW(21), .BW(13), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(R2)) m_dy (s1_gy, s1_w, py, clk);
    uvt_mul #(.AW(21), .BW(13), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(R2)) m_dw (s1_w8, s1_h, pw, clk);
    wire [392:0] s1d;                  // {n, g, neg, f} beside the products
    uvt_dly #(.W(393), .N(R2)) dl_s1 (clk, {s1_n, s1_g, s1_neg, s1_f}, s1d);
    reg [95:0]  s2_d;                  // |d_i| <= 2^30: the low 32 bits are exact
    reg [287:0] s2_n;
    reg [95:0]  s2_g;
    reg         s2_neg;
    reg signed [7:0] s2_f;
    always @(posedge clk) begin
        s2_d <= {pw[31:0], py[31:0], px[31:0]};
        {s2_n, s2_g, s2_neg, s2_f} <= s1d;
    end

    // ---- stage 3: n_k,i·d_i and G_i·d_i -----------------------------------------------------
    reg [9*64-1:0] s3_pn;
    reg [3*64-1:0] s3_pg;
    reg [287:0] s3_n;
    reg         s3_neg;
    reg signed [7:0] s3_f;
    genvar k, i;
    generate
        for (k = 0; k < 3; k = k + 1) begin : g_edge
            for (i = 0; i < 3; i = i + 1) begin : g_term
                wire signed [31:0] a = s2_n[32*(3*k+i) +: 32];
                wire signed [31:0] b = s2_d[32*i +: 32];
                wire signed [63:0] p;
                uvt_mul #(.AW(32), .BW(32), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(R3)) m_e (a, b, p, clk);
                always @(posedge clk) s3_pn[64*(3*k+i) +: 64] <= p;
            end
        end
        for (i = 0; i < 3; i = i + 1) begin : g_plane
            wire signed [31:0] a = s2_g[32*i +: 32];
            wire signed [31:0] b = s2_d[32*i +: 32];
            wire signed [63:0] p;
            uvt_mul #(.AW(32), .BW(32), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(R3)) m_g (a, b, p, clk);
            always @(posedge clk) s3_pg[64*i +: 64] <= p;
        end
    endgenerate
    wire [296:0] s2d;                  // {n, neg, f} beside the products
    uvt_dly #(.W(297), .N(R3)) dl_s2 (clk, {s2_n, s2_neg, s2_f}, s2d);
    always @(posedge clk) {s3_n, s3_neg, s3_f} <= s2d;

    // ---- stage 4: E_k and acc (each |.| < 3·2^61: no overflow in 64 bits) ------------------
    reg [3*64-1:0] s4_e;
    reg signed [63:0] s4_acc;
    wire signed [8:0] amt9 = s3_f + 9'sd33;
    reg [287:0] s4_n;
    reg         s4_neg;
    reg signed [8:0] s4_amt9;          // f + 33 (below)
    reg [6:0]   s4_amt;                // its clamp: the depth shift, ready before stage 5
    generate
        for (k = 0; k < 3; k = k + 1) begin : g_sum
            always @(posedge clk)
                s4_e[64*k +: 64] <= $signed(s3_pn[64*(3*k) +: 64]) +
                                    $signed(s3_pn[64*(3*k+1) +: 64]) +
                                    $signed(s3_pn[64*(3*k+2) +: 64]);
        end
    endgenerate
    always @(posedge clk) begin
        s4_acc <= $signed(s3_pg[0 +: 64]) + $signed(s3_pg[64 +: 64]) + $signed(s3_pg[128 +: 64]);
        s4_n <= s3_n;
        s4_neg <= s3_neg;
        s4_amt9 <= amt9;
        s4_amt <= (amt9 < 0) ? 7'd0 : (amt9 > 96) ? 7'd96 : amt9[6:0];
    end

    // ---- stage 5: coverage; depth shift -----------------------------------------------------
    wire [2:0] inside;
    generate
        for (k = 0; k < 3; k = k + 1) begin : g_cov
            wire signed [63:0] ek = s4_e[64*k +: 64];
            wire signed [31:0] ak = s4_n[32*(3*k) +: 32];
            wire signed [31:0] bk = s4_n[32*(3*k+1) +: 32];
            wire zero = (ek == 64'sd0);
            // σ·E > 0; on E = 0 the fill rule: σ·a > 0, or a = 0 and σ·b > 0
            wire side = s4_neg ? (ek < 0) : (ek > 0);
            wire fill = s4_neg ? (ak < 0 || (ak == 0 && bk < 0))
                               : (ak > 0 || (ak == 0 && bk > 0));
            assign inside[k] = zero ? fill : side;
        end
    endgenerate
    // acc·2^33 >>> clamp(f + 33, 0, 96): floor(acc / 2^min(f, 63)) for f >= 0, the exact
    // acc·2^(−f) for −33 <= f < 0; below −33 any acc ≠ 0 leaves the depth range (|.| >= 2^34).
    // The shift (s4_amt) depends on f alone: computed in stage 4, beside the sums.
    wire [6:0]         amt = s4_amt;
    wire signed [96:0] x97 = {s4_acc, 33'd0};
    reg  signed [96:0] s5_sv;
    reg                s5_big, s5_neg_acc, s5_cov;
    reg [3*64-1:0]     s5_e;
    always @(posedge clk) begin
        s5_sv <= x97 >>> amt;
        s5_big <= (s4_amt9 < 0) && (s4_acc != 0);
        s5_neg_acc <= s4_acc[63];
        s5_cov <= &inside;
        s5_e <= s4_e;
    end

    // ---- stage 6: clamp to [DEPTH_NEAR, DEPTH_FAR]; 0 when not covered ---------------------
    localparam signed [96:0] FAR = 97'sh7ffffffe;
    localparam signed [96:0] NEAR = -97'sh80000000;
    reg signed [31:0] r_depth;
    reg               r_cov;
    reg [3*64-1:0]    r_e;
    always @(posedge clk) begin
        r_cov <= s5_cov;
        r_e <= s5_e;
        if (!s5_cov)
            r_depth <= 32'sd0;
        else if (s5_big)
            r_depth <= s5_neg_acc ? 32'sh80000000 : 32'sh7ffffffe;
        else if (s5_sv > FAR)
            r_depth <= 32'sh7ffffffe;
        else if (s5_sv < NEAR)
            r_depth <= 32'sh80000000;
        else
            r_depth <= s5_sv[31:0];
    end
    assign covered = r_cov;
    assign depth = r_depth;
    assign e = r_e;
endmodule
