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
// With PIPE = 2 (the placed-and-routed build, `pnr.sh psample-pipe2`) every hard multiplier has
// its input, pipeline and output registers (uvt_mul REG = 3; MAP = 1 instantiates the ECP5
// MULT18X18D) and no register-to-register path holds more than one wide carry chain: the sums
// in two clocks, coverage from registered zero and sign flags, the fill rule from n and σ
// early, and the depth clamp without compares (the shift in three clocks, the range test as
// masked ORs of acc's bits): LAT = 8 + L2 + L3 (g_p2 below), 17 for 18 × 18 with LUTW = 0
// (3·2 + 12·4 = 54 MULT18X18D), 18 for the DSP48E1 tiling.
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
    // a faster clock: LAT = 9 instead of 6 (same results). PIPE = 2: registered hard multipliers
    // (uvt_mul REG = 3) and one wide carry chain per clock (below): LAT = 8 + L2 + L3
    parameter PIPE = 0,
    // MAP = 1 (with PIPE = 2): every hard piece an instantiated ECP5 MULT18X18D (uvt_mul MAP)
    parameter MAP = 0
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
    // The number of terms of a uvt_mul product with REG = 3 (its hard pieces plus its LUT
    // chunk's rows), by uvt_mul.v's tiling rule (the same functions, condensed), and clog2:
    // the product's least LAT is 3 + clog2(terms).
    function integer nlow(input integer nb, input integer pw);
        nlow = (nb <= pw) ? 0 : (nb - pw + pw - 2) / (pw - 1);
    endfunction
    function integer top(input integer nb, input integer pw);
        top = nb - nlow(nb, pw) * (pw - 1);
    endfunction
    function integer lutable(input integer nb, input integer pw, input integer lw);
        lutable = (nlow(nb, pw) > 0 && top(nb, pw) <= lw) ? 1 : 0;
    endfunction
    // Score (hard multipliers · 2^20 + LUT bits) and terms of x on port px, y on port py,
    // option o (0 none, 1 x's top in LUTs, 2 y's top in LUTs).
    function integer score(input integer x, input integer y, input integer px, input integer py,
                           input integer lw, input integer o);
        integer kx, ky;
        begin
            kx = nlow(x, px);
            ky = nlow(y, py);
            if (o == 0)
                score = (kx + 1) * (ky + 1) * 1048576;
            else if (o == 1)
                score = lutable(x, px, lw) ? kx * (ky + 1) * 1048576 + top(x, px) * y
                                           : 32'h7fffffff;
            else
                score = lutable(y, py, lw) ? (kx + 1) * ky * 1048576 + top(y, py) * x
                                           : 32'h7fffffff;
        end
    endfunction
    function integer terms(input integer x, input integer y, input integer px, input integer py,
                           input integer o);
        integer kx, ky;
        begin
            kx = nlow(x, px);
            ky = nlow(y, py);
            if (o == 0)
                terms = (kx + 1) * (ky + 1);
            else if (o == 1)
                terms = kx * (ky + 1) + top(x, px);
            else
                terms = (kx + 1) * ky + top(y, py);
        end
    endfunction
    function integer mterms(input integer aw, input integer bw, input integer pa,
                            input integer pb, input integer lw);
        integer s, o, best, c;
        begin
            best = 32'h7fffffff;
            mterms = 0;
            for (s = 0; s < 2; s = s + 1)
                for (o = 0; o < 3; o = o + 1) begin
                    c = s ? score(bw, aw, pa, pb, lw, o) : score(aw, bw, pa, pb, lw, o);
                    if (c < best) begin
                        best = c;
                        mterms = s ? terms(bw, aw, pa, pb, o) : terms(aw, bw, pa, pb, o);
                    end
                end
        end
    endfunction
    function integer clog2(input integer v);
        integer t;
        begin
            clog2 = 0;
            for (t = 1; t < v; t = t * 2)
                clog2 = clog2 + 1;
        end
    endfunction

    localparam R2 = PIPE ? 1 : 0;      // clocks inside the stage-2 products (uvt_mul REG)
    localparam R3 = PIPE ? 2 : 0;      // and inside the stage-3 products
    // PIPE = 2: the clocks of the stage-2 and stage-3 products (uvt_mul REG = 3, LAT): the
    // multiplier's three registers and one per level of the adder tree over its terms
    localparam L2 = 3 + clog2(mterms(21, 13, DSP_A, DSP_B, LUTW));
    localparam L3 = 3 + clog2(mterms(32, 32, DSP_A, DSP_B, LUTW));
    localparam LAT = PIPE == 2 ? 8 + L2 + L3 : 6 + R2 + R3;

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

    genvar k, i;
    generate
        if (PIPE == 2) begin : g_p2
            // PIPE = 2: every product registered in and out of its hard multipliers (uvt_mul
            // REG = 3; L2, L3 clocks), every wide carry chain alone between two registers and
            // the depth clamp without compares. Clocks (register stages after in_valid):
            //   1          inputs, gx, gy, 256W (stage 1 above)
            //   2, 3       fill rule per edge from n and σ; the depth shift amount from f
            //   1 + L2     d (the direction products' registered output)
            //   T3 = 1 + L2 + L3   the 12 products n_k,i·d_i, G_i·d_i
            //   T3 + 1     the first two terms of each sum added, the third registered
            //   T5 = T3 + 2        E_k, acc; the mask of acc's bits the depth range needs
            //   T5 + 1     E_k = 0, sign; acc·2^33 shifted right by 32·amt[6:5]; acc's bits
            //              above the range (masked)
            //   T5 + 2     coverage; the shift by 8·amt[4:3]; ORs of 16 of those bits
            //   T5 + 3     the shift by amt[2:0]: the depth's 32 bits; whether it is in 32 bits
            //   T5 + 4     in range (neither above 2^31 − 2 nor below −2^31)
            //   T5 + 5     outputs: LAT = T5 + 5 = 8 + L2 + L3
            localparam T5 = 3 + L2 + L3;
            wire signed [33:0] px, py, pw;
            uvt_mul #(.AW(21), .BW(13), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(3), .LAT(L2),
                      .MAP(MAP)) m_dx (s1_gx, s1_h, px, clk);
            uvt_mul #(.AW(21), .BW(13), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(3), .LAT(L2),
                      .MAP(MAP)) m_dy (s1_gy, s1_w, py, clk);
            uvt_mul #(.AW(21), .BW(13), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(3), .LAT(L2),
                      .MAP(MAP)) m_dw (s1_w8, s1_h, pw, clk);
            wire [95:0] d = {pw[31:0], py[31:0], px[31:0]};   // |d_i| <= 2^30: exact
            wire [383:0] ng;                                   // {g, n} beside d
            uvt_dly #(.W(384), .N(L2)) dl_ng (clk, {s1_g, s1_n}, ng);

            // The fill rule per edge (n and σ alone): σ·a > 0, or a = 0 and σ·b > 0.
            reg [2:0] f2_az, f2_an, f2_bz, f2_bn;   // a = 0, a < 0, b = 0, b < 0
            reg       f2_neg, f3_neg;
            reg [2:0] f3_fill;
            reg signed [8:0] f2_amt9;               // f + 33
            reg [6:0] f3_amt;                       // clamp(f + 33, 0, 96): the depth shift
            for (k = 0; k < 3; k = k + 1) begin : g_fill
                always @(posedge clk) begin
                    f2_az[k] <= s1_n[32*(3*k) +: 32] == 32'd0;
                    f2_an[k] <= s1_n[32*(3*k) + 31];
                    f2_bz[k] <= s1_n[32*(3*k+1) +: 32] == 32'd0;
                    f2_bn[k] <= s1_n[32*(3*k+1) + 31];
                    f3_fill[k] <= f2_neg ? (f2_an[k] || (f2_az[k] && f2_bn[k]))
                                         : ((!f2_an[k] && !f2_az[k]) ||
                                            (f2_az[k] && !f2_bn[k] && !f2_bz[k]));
                end
            end
            // f + 33 in [0, 96] (f2_in), above 96 (f2_over)
            wire f2_over = !f2_amt9[8] &&
                           (f2_amt9[7] || (f2_amt9[6] && f2_amt9[5] && |f2_amt9[4:0]));
            wire f2_in = !f2_amt9[8] && !f2_over;
            always @(posedge clk) begin
                f2_neg <= s1_neg;
                f3_neg <= f2_neg;
                f2_amt9 <= s1_f + 9'sd33;
                // no compare (a carry chain): f + 33 < 0 by its sign, > 96 = 0b1100000 by bits;
                // AND/OR, not a multiplexer to a constant (no sync-reset flip-flops, whose
                // LSR net was the critical route of a run)
                f3_amt <= (f2_amt9[6:0] & {7{f2_in}}) | ({7{f2_over}} & 7'd96);
            end
            wire [6:0] sd_amt;                      // at clock T5 − 1
            wire [2:0] sd_fill;
            wire       sd_neg;
            uvt_dly #(.W(11), .N(T5 - 4)) dl_f (clk, {f3_amt, f3_fill, f3_neg},
                                                {sd_amt, sd_fill, sd_neg});

            // The 12 products, registered at T3; the sums in two clocks.
            wire [12*64-1:0] pr;                    // n_k,i·d_i at 3k + i, G_i·d_i at 9 + i
            for (k = 0; k < 4; k = k + 1) begin : g_row
                for (i = 0; i < 3; i = i + 1) begin : g_term
                    wire signed [31:0] a = ng[32*(3*k+i) +: 32];
                    wire signed [31:0] b = d[32*i +: 32];
                    uvt_mul #(.AW(32), .BW(32), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(3),
                              .LAT(L3), .MAP(MAP)) m_p (a, b, pr[64*(3*k+i) +: 64], clk);
                end
            end
            reg [4*64-1:0] q_ab, q_c;               // T3 + 1: p0 + p1, p2
            reg [4*64-1:0] t5_s;                    // T5: E_0, E_1, E_2, acc
            for (k = 0; k < 4; k = k + 1) begin : g_sum
                always @(posedge clk) begin
                    q_ab[64*k +: 64] <= pr[64*(3*k) +: 64] + pr[64*(3*k+1) +: 64];
                    q_c[64*k +: 64] <= pr[64*(3*k+2) +: 64];
                    t5_s[64*k +: 64] <= q_ab[64*k +: 64] + q_c[64*k +: 64];
                end
            end
            // acc·2^33 >>> amt lies in [−2^31, 2^31) iff acc lies in [−2^(amt−2), 2^(amt−2)),
            // that is (amt >= 2) acc's bits amt − 2 … 63 all equal its sign, (amt < 2) acc = 0:
            // the bits j < 63 with j + 2 >= amt (mask t5_m, all of them for amt < 2) equal the
            // sign, and acc is not negative for amt < 2.
            reg [62:0] t5_m;
            reg        t5_low, t5_neg;
            reg [6:0]  t5_amt;
            reg [2:0]  t5_fill;
            wire [64:0] ones_sh = {65{1'b1}} << sd_amt;   // bit j: j >= amt (no compares)
            always @(posedge clk) begin
                t5_m <= ones_sh[64:2];
                t5_low <= sd_amt[6:1] == 6'd0;
                t5_amt <= sd_amt;
                t5_fill <= sd_fill;
                t5_neg <= sd_neg;
            end
            wire signed [63:0] acc = t5_s[192 +: 64];
            wire signed [96:0] x97 = {acc, 33'd0};
            wire signed [96:0] sh1 = x97 >>> {t5_amt[6:5], 5'd0};

            // T5 + 1
            reg signed [62:0] u1_y;                 // the bits the next shifts reach
            reg [62:0] u1_dm;                       // acc's masked bits unequal to its sign
            reg        u1_lowneg, u1_sgn, u1_neg;
            reg [4:0]  u1_amt;
            reg [2:0]  u1_ez, u1_es, u1_fill;
            always @(posedge clk) begin
                u1_y <= sh1[62:0];
                u1_dm <= (acc[62:0] ^ {63{acc[63]}}) & t5_m;
                u1_lowneg <= t5_low & acc[63];
                u1_sgn <= acc[63];
                u1_amt <= t5_amt[4:0];
                u1_neg <= t5_neg;
                u1_fill <= t5_fill;
            end
            for (k = 0; k < 3; k = k + 1) begin : g_ez
                always @(posedge clk) begin
                    u1_ez[k] <= t5_s[64*k +: 64] == 64'd0;
                    u1_es[k] <= t5_s[64*k + 63];
                end
            end

            // T5 + 2: coverage (σ·E > 0, or E = 0 and the fill rule)
            wire [2:0] inside = (u1_ez & u1_fill) | (~u1_ez & (u1_neg ? u1_es : ~u1_es));
            wire signed [62:0] sh2 = u1_y >>> {u1_amt[4:3], 3'd0};
            reg signed [38:0] u2_y;
            reg [3:0]  u2_po;
            reg        u2_lowneg, u2_sgn, u2_cov;
            reg [2:0]  u2_amt;
            always @(posedge clk) begin
                u2_y <= sh2[38:0];
                u2_po <= {|u1_dm[62:48], |u1_dm[47:32], |u1_dm[31:16], |u1_dm[15:0]};
                u2_lowneg <= u1_lowneg;
                u2_sgn <= u1_sgn;
                u2_cov <= &inside;
                u2_amt <= u1_amt[2:0];
            end

            // T5 + 3, T5 + 4: the depth's bits; in range; T5 + 5 the outputs
            wire signed [38:0] sh3 = u2_y >>> u2_amt;
            reg [31:0] u3_v, u4_v;
            reg        u3_fits, u3_sgn, u3_cov, u4_ok, u4_sgn, u4_cov;
            always @(posedge clk) begin
                u3_v <= sh3[31:0];
                u3_fits <= !(|u2_po) && !u2_lowneg;
                u3_sgn <= u2_sgn;
                u3_cov <= u2_cov;
                u4_v <= u3_v;
                u4_ok <= u3_fits && (u3_v != 32'h7fffffff);   // 2^31 − 1 is above DEPTH_FAR
                u4_sgn <= u3_sgn;
                u4_cov <= u3_cov;
            end
            wire [191:0] u4_e;
            uvt_dly #(.W(192), .N(4)) dl_e (clk, t5_s[0 +: 192], u4_e);
            reg signed [31:0] r_depth;
            reg               r_cov;
            reg [191:0]       r_e;
            always @(posedge clk) begin
                r_cov <= u4_cov;
                r_e <= u4_e;
                if (!u4_cov)
                    r_depth <= 32'sd0;
                else if (u4_ok)
                    r_depth <= u4_v;
                else
                    r_depth <= u4_sgn ? 32'sh80000000 : 32'sh7ffffffe;
            end
            assign covered = r_cov;
            assign depth = r_depth;
            assign e = r_e;
        end else begin : g_p01
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
                for (k = 0; k < 3; k = k + 1) begin : g_sum
                    always @(posedge clk)
                        s4_e[64*k +: 64] <= $signed(s3_pn[64*(3*k) +: 64]) +
                                            $signed(s3_pn[64*(3*k+1) +: 64]) +
                                            $signed(s3_pn[64*(3*k+2) +: 64]);
                end
            always @(posedge clk) begin
                s4_acc <= $signed(s3_pg[0 +: 64]) + $signed(s3_pg[64 +: 64]) + $signed(s3_pg[128 +: 64]);
                s4_n <= s3_n;
                s4_neg <= s3_neg;
                s4_amt9 <= amt9;
                s4_amt <= (amt9 < 0) ? 7'd0 : (amt9 > 96) ? 7'd96 : amt9[6:0];
            end

            // ---- stage 5: coverage; depth shift -----------------------------------------------------
            wire [2:0] inside;
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
        end
    endgenerate
endmodule
