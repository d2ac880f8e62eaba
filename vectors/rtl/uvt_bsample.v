// uvt_bsample — the bounded sample test of uvt-core (core/src/sample/bounded/, steps 1–8) as a fully
// pipelined unit: one sample per clock, bit-exact against the golden vectors bsample_in.hex /
// bsample_out.hex. Synthesizable Verilog-2005 (Icarus Verilog and Yosys).
//
// Parameters (the configuration `bounded-POS-TUV-POS-OFF` of the precision sweep):
//   POS  fraction bits of clip x, y, z, w and CoC (2..16); the inputs' low 16−POS bits are zero
//   TUV  fraction bits of t, u, v (2..16); the inputs' low 16−TUV bits are zero
//   OFF  offset-grid shift S (20..32): a' = round(A / 2^OFF)
//   DSP_A, DSP_B, LUTW  the multiplier tiling of every product (uvt_mul.v): hard-multiplier
//        ports 25 × 18 (DSP48E1, default) or 18 × 18 (ECP5), top chunks <= LUTW bits in LUTs
//   MOTION, DEFOCUS  the unit variant (1, 1: full; 1, 0: motion-only; 0, 1: defocus-only;
//        0, 0: static-only). A narrow unit has no register or multiplier for what it cannot
//        use: no key frame 1, t and lerp without MOTION, no CoC, u, v and lens without DEFOCUS.
// The unit ignores the low zero bits (narrower multipliers for narrower configurations). It
// needs no class input: for a static triangle the lerp returns the t = 0 value exactly and for
// a triangle without CoC the lens term is 0, so the general path equals every class's path.
// A narrow unit gives the full unit's outputs on the classes it accepts (bit 0 of the class
// index = motion, bit 1 = defocus, vectors/README.md); the caller routes no other class to it.
//
// Ports = record fields (vectors/README.md "RTL integration"):
//   trin[32*k +: 32]  bsample_in word k, k = 0..29 (t0 v0 x y z w coc, t0 v1 …, t1 v2 coc);
//                     without MOTION words 0..14 only (trin is 480 bits); CoC words, t, u, v
//                     are unconnected in a unit without their terms
//   vp_w, vp_h        viewport (word 30, ≤ 2048), xs, ys (words 32, 33; < 256·vp), t, u, v
//   ab[32*i +: 32]    a0 b0 a1 b1 a2 b2 (bsample_out words 2..7), sign-extended
//   e[64*k +: 64]     E'_k (words 8..13)
//   det_sign, covered (word 0), with edge_valid, LAT_EDGE = 11 clocks after in_valid
//   depth (word 1; 0 when not covered) with out_valid and out_covered, LAT = 46 clocks after
// Latency: LAT_EDGE = 11, LAT = 46 (13 stages to num/den, 1 prepare, 31 divider, 1 select);
// PIPE = 1: 23, 63; PIPE = 2: from the products' tiling (localparams below; pnr.sh's
// bsample-pipe2 build, ECP5 18 × 18 ports, LUTW = 8: 39, 85; with KARA = 1: 40, 86).
// The depth divider is a pipelined restoring (radix-2) divider: one quotient bit per stage,
// 31 stages, plus an overflow compare for saturation.
`timescale 1ns / 1ps
module uvt_bsample #(
    parameter POS = 16,
    parameter TUV = 16,
    parameter OFF = 20,
    // the unit variant (core/src/config/unit.rs): MOTION = 0 leaves out key frame 1, t and the lerp
    // multipliers; DEFOCUS = 0 the CoC, u, v, the CoC lerp and the lens multipliers. Full: 1, 1;
    // motion-only: 1, 0; defocus-only: 0, 1; static-only: 0, 0.
    parameter MOTION = 1,
    parameter DEFOCUS = 1,
    // hard-multiplier ports and LUT chunk limit of every product (uvt_mul.v): 25 × 18 for
    // Xilinx DSP48E1 (the default), 18 × 18 for Lattice ECP5 MULT18X18D
    parameter DSP_A = 25,
    parameter DSP_B = 18,
    parameter LUTW = 8,
    // PIPE = 1: registers inside every multiplier (uvt_mul REG = 2: the partial products, LUT
    // chunks as sums of four rows, and the sums of four) and in the wide adder stages, for a
    // faster clock: LAT_EDGE = 23, LAT = 63 instead of 11, 46 (same results).
    // PIPE = 2: every product uvt_mul REG = 3 (registered hard pieces and LUT rows, a registered
    // two-input adder tree: LAT = 3 + clog2(terms) clocks, the same for the products of one
    // stage) and at most one wide carry chain between registers everywhere else (same results;
    // LAT_EDGE and LAT below).
    parameter PIPE = 0,
    // MAP = 1 (PIPE = 2, 18 × 18 ports): every hard piece an instantiated ECP5 MULT18X18D with
    // its three register stages on (uvt_mul MAP); same bits and latency as MAP = 0.
    parameter MAP = 0,
    // PIPE = 2 only: the LUT chunk limit of the edge products a'·b' and of E'·w (LUTW: the rest),
    // -1: LUTW for these too
    parameter LUTWE = -1,
    // PIPE = 2 only: 1 = each edge product a'·b' on three hard multipliers (Karatsuba) instead
    // of four
    parameter KARA = 0
) (
    input  wire               clk,
    input  wire               in_valid,
    input  wire [32*(MOTION ? 30 : 15)-1:0] trin,
    input  wire [11:0]        vp_w,
    input  wire [11:0]        vp_h,
    input  wire [19:0]        xs,
    input  wire [19:0]        ys,
    input  wire signed [31:0] t,
    input  wire signed [31:0] u,
    input  wire signed [31:0] v,
    output wire               edge_valid,
    output wire [191:0]       ab,
    output wire [191:0]       e,
    output wire signed [1:0]  det_sign,
    output wire               covered,
    output wire               out_valid,
    output wire               out_covered,
    output wire signed [31:0] depth
);
    localparam FW = POS + 15;          // |f'| <= 2^(13+POS): input coordinate, signed
    localparam DW = POS + 16;          // f1' - f0'
    localparam TW = TUV + 2;           // t', u', v' signed (|.| <= 2^TUV)
    localparam LS = 32 - TUV - POS;    // T·d = T'·d'·2^LS (32 fraction bits)
    localparam US = 16 - TUV;          // U·c = U'·c·2^US
    localparam AW = 51 - OFF;          // |a'| < 2^(50-OFF)
    localparam EW = 2 * AW;            // |E'| < 2^(2·AW-1)
    localparam RW = EW + 32;           // E'·w, sums of three
    localparam P2 = PIPE == 2 ? 1 : 0; // PIPE = 2: one more register where a sum is split
    localparam MR = PIPE ? 2 : 0;      // clocks inside each multiplier (uvt_mul REG), PIPE <= 1
    localparam RG = P2 ? 3 : MR;       // uvt_mul REG
    localparam P1 = PIPE ? 1 : 0;      // one more register where a wide stage is split
    localparam LWE = (P2 && LUTWE >= 0) ? LUTWE : LUTW;  // LUT chunk limit, edge and E'·w
    // Clocks inside the products of each stage: MR, or with PIPE = 2 the most any product of
    // the stage needs (uvt_mul REG = 3: 3 + clog2(terms)).
    localparam M1 = P2 ? mlat(TW, DW, LUTW) : MR;                                // lerp
    localparam M2 = P2 ? mlat(TW, 31, LUTW) : MR;                                // lens
    localparam M3 = P2 ? max2(mlat(13, 32, LUTW), mlat(22, 31, LUTW)) : MR;      // A, B
    // KARA (PIPE = 2, AW <= 33): E' = a'·b' − a'·b' on three 18 × 18 hard multipliers per
    // product instead of four (uvt_bsample_kdet: 7 clocks = M4 + 1)
    localparam KE = P2 && KARA && AW <= 33 && AW > 16;
    localparam M4 = KE ? 6 : P2 ? mlat(AW, AW, LWE) : MR;                        // E'
    // KARA (PIPE = 2, 17 <= EW − 31 <= 33): E'·w = E'_H·w·2^31 + E'_L·w, each on three 18 × 18
    // hard multipliers (uvt_bsample_kprod: 6 clocks), then their sum: 7 clocks, 6 multipliers
    // instead of 8.
    localparam KK = P2 && KARA && EW - 31 >= 17 && EW - 31 <= 33;
    localparam M5 = KK ? 7 : P2 ? mlat(EW, 31, LWE) : MR;                        // E'·w
    localparam M6 = P2 ? mlat(25, 31, LUTW) : MR;                                // depth
    localparam LAT_EDGE = 11 + 2 * P1 + P2 + M1 + M2 + M3 + M4 + M5;
    localparam LAT = LAT_EDGE + 35 + M6 + 3 * P1 + P2;

    // The tiling of uvt_mul.v (its functions, for the latency of REG = 3): unsigned low chunks
    // and the signed top chunk of an n-bit operand on a p-bit port, and the chosen layout's
    // hard pieces and LUT rows.
    function integer max2(input integer x, input integer y);
        max2 = x > y ? x : y;
    endfunction
    function integer nlow(input integer n, input integer pw);
        nlow = (n <= pw) ? 0 : (n - pw + pw - 2) / (pw - 1);
    endfunction
    function integer top(input integer n, input integer pw);
        top = n - nlow(n, pw) * (pw - 1);
    endfunction
    function integer lutable(input integer n, input integer pw, input integer lw);
        lutable = (nlow(n, pw) > 0 && top(n, pw) <= lw) ? 1 : 0;
    endfunction
    // Terms (hard pieces + LUT rows) of x on port px, y on port py, option o (as uvt_mul's
    // score: 0 none, 1 x's top in LUTs, 2 y's), and its score (a large one when not allowed).
    function integer terms(input integer x, input integer y, input integer px, input integer py,
                           input integer o);
        integer kx, ky;
        begin
            kx = nlow(x, px);
            ky = nlow(y, py);
            if (o == 0) terms = (kx + 1) * (ky + 1);
            else if (o == 1) terms = kx * (ky + 1) + top(x, px);
            else terms = (kx + 1) * ky + top(y, py);
        end
    endfunction
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
    // 3 + clog2(terms) of uvt_mul's chosen layout of an aw × bw product (DSP_A × DSP_B ports).
    function integer mlat(input integer aw, input integer bw, input integer lw);
        integer sw, o, best, c, n, v;
        begin
            best = 32'h7fffffff;
            n = 1;
            for (sw = 0; sw < 2; sw = sw + 1)
                for (o = 0; o < 3; o = o + 1) begin
                    c = sw ? score(bw, aw, DSP_A, DSP_B, lw, o)
                           : score(aw, bw, DSP_A, DSP_B, lw, o);
                    if (c < best) begin
                        best = c;
                        n = sw ? terms(bw, aw, DSP_A, DSP_B, o) : terms(aw, bw, DSP_A, DSP_B, o);
                    end
                end
            mlat = 3;
            for (v = 1; v < n; v = v * 2)
                mlat = mlat + 1;
        end
    endfunction

    reg [LAT:1] vld;
    always @(posedge clk) vld <= {vld[LAT-1:1], in_valid};
    assign edge_valid = vld[LAT_EDGE];
    assign out_valid  = vld[LAT];

    // ---- stage 1: inputs at their significant widths; g = sample-relative scale --------------
    // Registered only where the unit uses them: key frame 1 and t with MOTION, the CoC words
    // and u, v with DEFOCUS (the other bits of s1_f0 / s1_f1 / s3_f stay undriven and unread).
    reg [15*FW-1:0] s1_f0, s1_f1;
    reg signed [TW-1:0] s1_t, s1_u, s1_v;
    reg signed [12:0] s1_w, s1_h;      // W, H (sw = 256·W)
    reg signed [21:0] s1_gx, s1_gy;    // gx = 2xs − 256W, gy = 256H − 2ys, |.| <= 2^19
    genvar i;
    generate
        for (i = 0; i < 15; i = i + 1) begin : g_in
            if (DEFOCUS || i % 5 != 4) begin : g_f0
                always @(posedge clk) s1_f0[FW*i +: FW] <= trin[32*i + 16 - POS +: FW];
            end
            if (MOTION && (DEFOCUS || i % 5 != 4)) begin : g_f1
                always @(posedge clk) s1_f1[FW*i +: FW] <= trin[32*(15+i) + 16 - POS +: FW];
            end
        end
        if (MOTION) begin : g_in_t
            always @(posedge clk) s1_t <= t[16-TUV +: TW];
        end
        if (DEFOCUS) begin : g_in_uv
            always @(posedge clk) begin
                s1_u <= u[16-TUV +: TW];
                s1_v <= v[16-TUV +: TW];
            end
        end
    endgenerate
    always @(posedge clk) begin
        s1_w <= {1'b0, vp_w};
        s1_h <= {1'b0, vp_h};
        s1_gx <= $signed({1'b0, xs, 1'b0}) - $signed({2'b0, vp_w, 8'b0});
        s1_gy <= $signed({2'b0, vp_h, 8'b0}) - $signed({1'b0, ys, 1'b0});
    end

    // ---- stages 2–3: step 1, lerp f_t = rnd16(f0·2^16 + T·(f1 − f0)) -----------------------
    // Without MOTION every field is its t = 0 value (the lerp of f1 = f0 returns f0 exactly):
    // f_t = f0·2^(16−POS), no multiplier. Without DEFOCUS the CoC is not read.
    reg [15*FW-1:0] s2_f0;
    reg [15*(TW+DW)-1:0] s2_p;
    reg [15*31-1:0] s3_f;              // x y z w c per vertex, raw 2^-16, |.| <= 2^29
    wire signed [TW-1:0] s1_td;        // t at the multipliers (after d's register with PIPE)
    uvt_dly #(.W(TW), .N(P1)) dl_t (clk, s1_t, s1_td);
    generate
        for (i = 0; i < 15; i = i + 1) begin : g_lerp
            if (MOTION && (DEFOCUS || i % 5 != 4)) begin : g_mul
                wire signed [FW-1:0] f0 = s1_f0[FW*i +: FW];
                wire signed [FW-1:0] f1 = s1_f1[FW*i +: FW];
                wire signed [DW-1:0] d = f1 - f0;
                wire signed [DW-1:0] dd;
                wire [FW-1:0] f0d;
                uvt_dly #(.W(DW), .N(P1)) dl_d (clk, d, dd);
                uvt_dly #(.W(FW), .N(P1 + M1)) dl_f0 (clk, f0, f0d);
                wire signed [TW+DW-1:0] p;
                uvt_mul #(.AW(TW), .BW(DW), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(RG), .LAT(M1),
                          .MAP(MAP)) m_t (s1_td, dd, p, clk);
                always @(posedge clk) begin
                    s2_f0[FW*i +: FW] <= f0d;
                    s2_p[(TW+DW)*i +: TW+DW] <= p;
                end
                wire signed [FW-1:0] g0 = s2_f0[FW*i +: FW];
                wire signed [TW+DW-1:0] gp = s2_p[(TW+DW)*i +: TW+DW];
                // PIPE = 2: the rounding constant 2^15 ORed into f0's zero low bits (32 − POS >=
                // 16 of them), one adder.
                wire signed [47:0] g0s = g0 <<< (32 - POS);
                wire signed [47:0] sum = P2 ? (g0s | 48'sd32768) + (gp <<< LS)
                                            : (g0 <<< (32 - POS)) + (gp <<< LS) + 48'sd32768;
                wire signed [47:0] rnd = sum >>> 16;
                always @(posedge clk) s3_f[31*i +: 31] <= rnd[30:0];
            end else if (DEFOCUS || i % 5 != 4) begin : g_t0
                wire [FW-1:0] f0d;
                uvt_dly #(.W(FW), .N(P1 + M1)) dl_f0 (clk, s1_f0[FW*i +: FW], f0d);
                always @(posedge clk) s2_f0[FW*i +: FW] <= f0d;
                wire signed [FW-1:0] g0 = s2_f0[FW*i +: FW];
                wire signed [30:0] ft = g0 <<< (16 - POS);   // FW + 16 − POS = 31 bits
                always @(posedge clk) s3_f[31*i +: 31] <= ft;
            end
        end
    endgenerate
    reg signed [TW-1:0] s2_u, s2_v, s3_u, s3_v;
    reg signed [12:0] s2_w, s2_h, s3_w, s3_h, s4_w, s4_h, s5_w, s5_h;
    reg signed [21:0] s2_gx, s2_gy, s3_gx, s3_gy, s4_gx, s4_gy, s5_gx, s5_gy;
    generate
        if (DEFOCUS) begin : g_uv
            wire [2*TW-1:0] uvd;
            uvt_dly #(.W(2*TW), .N(P1 + M1)) dl_uv (clk, {s1_u, s1_v}, uvd);
            always @(posedge clk) {s2_u, s2_v, s3_u, s3_v} <= {uvd, s2_u, s2_v};
        end
    endgenerate
    wire [69:0] vp1d, vp4d;            // {w, h, gx, gy} through the multipliers of stages 2, 4
    uvt_dly #(.W(70), .N(P1 + M1)) dl_vp1 (clk, {s1_w, s1_h, s1_gx, s1_gy}, vp1d);
    uvt_dly #(.W(70), .N(M2)) dl_vp4 (clk, {s4_w, s4_h, s4_gx, s4_gy}, vp4d);
    always @(posedge clk) begin
        {s2_w, s2_h, s2_gx, s2_gy} <= vp1d;
        {s3_w, s3_h, s3_gx, s3_gy} <= {s2_w, s2_h, s2_gx, s2_gy};
        {s4_w, s4_h, s4_gx, s4_gy} <= {s3_w, s3_h, s3_gx, s3_gy};
        {s5_w, s5_h, s5_gx, s5_gy} <= vp4d;
    end

    // ---- stages 4–5: step 2, lens x = x_t + rnd16(U·c_t), y = y_t + rnd16(V·c_t) -------------
    // Without DEFOCUS the lens term is 0 (no CoC): x = x_t, y = y_t, no multiplier.
    reg [3*32-1:0] s5_x, s5_y;         // |.| <= 2^30
    reg [3*31-1:0] s5_wt, s5_zt, s6_wt, s6_zt, s7_wt, s7_zt;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_lens
            reg signed [30:0] xt, yt, wt, zt;
            wire signed [31:0] x, y;
            if (DEFOCUS) begin : g_uv
                wire signed [30:0] c = s3_f[31*(5*i+4) +: 31];
                reg signed [TW+30:0] pu, pv;
                wire signed [TW+30:0] mu, mv;
                uvt_mul #(.AW(TW), .BW(31), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(RG), .LAT(M2),
                          .MAP(MAP)) m_u (s3_u, c, mu, clk);
                uvt_mul #(.AW(TW), .BW(31), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(RG), .LAT(M2),
                          .MAP(MAP)) m_v (s3_v, c, mv, clk);
                always @(posedge clk) begin
                    pu <= mu;
                    pv <= mv;
                end
                wire signed [47:0] lu = ((pu <<< US) + 48'sd32768) >>> 16;
                wire signed [47:0] lv = ((pv <<< US) + 48'sd32768) >>> 16;
                // PIPE = 2: x = floor((x_t·2^16 + U·c + 2^15) / 2^16), one adder (2^15 ORed
                // into x_t·2^16's zero low bits); the same value modulo 2^32.
                wire signed [49:0] xs2 = ($signed({xt, 16'd0}) | 50'sd32768) + (pu <<< US);
                wire signed [49:0] ys2 = ($signed({yt, 16'd0}) | 50'sd32768) + (pv <<< US);
                assign x = P2 ? $signed(xs2[47:16]) : xt + $signed(lu[31:0]);
                assign y = P2 ? $signed(ys2[47:16]) : yt + $signed(lv[31:0]);
            end else begin : g_pin
                assign x = xt;
                assign y = yt;
            end
            wire [4*31-1:0] fd;
            uvt_dly #(.W(4*31), .N(M2)) dl_f (clk, {s3_f[31*(5*i) +: 31],
                s3_f[31*(5*i+1) +: 31], s3_f[31*(5*i+2) +: 31], s3_f[31*(5*i+3) +: 31]}, fd);
            always @(posedge clk) begin
                {xt, yt, zt, wt} <= fd;
                s5_x[32*i +: 32] <= x;
                s5_y[32*i +: 32] <= y;
                s5_wt[31*i +: 31] <= wt;
                s5_zt[31*i +: 31] <= zt;
            end
        end
    endgenerate

    // ---- stages 6–7: steps 3–4, A = 256W·x − gx·w, B = 256H·y − gy·w; a' = rnd_OFF(A) ------
    reg [3*AW-1:0] s7_a, s7_b;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_off
            wire signed [31:0] x = s5_x[32*i +: 32];
            wire signed [31:0] y = s5_y[32*i +: 32];
            wire signed [30:0] w = s5_wt[31*i +: 31];
            reg signed [44:0] mx, my;      // W·x, H·y: |.| <= 2^41
            reg signed [52:0] mw, mh;      // gx·w, gy·w: |.| <= 2^48
            wire signed [44:0] px, py;
            wire signed [52:0] pw, ph;
            uvt_mul #(.AW(13), .BW(32), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(RG), .LAT(M3),
                      .MAP(MAP)) m_x (s5_w, x, px, clk);
            uvt_mul #(.AW(13), .BW(32), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(RG), .LAT(M3),
                      .MAP(MAP)) m_y (s5_h, y, py, clk);
            uvt_mul #(.AW(22), .BW(31), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(RG), .LAT(M3),
                      .MAP(MAP)) m_w (s5_gx, w, pw, clk);
            uvt_mul #(.AW(22), .BW(31), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(RG), .LAT(M3),
                      .MAP(MAP)) m_h (s5_gy, w, ph, clk);
            // PIPE = 2: the rounding constant 2^(OFF−1) = 2^(OFF−9)·2^8 added to W·x, H·y in
            // their own register (an adder each), so that A, B are one subtraction.
            localparam signed [44:0] RC = P2 ? 45'sd1 <<< (OFF - 9) : 45'sd0;
            always @(posedge clk) begin
                mx <= px + RC;
                my <= py + RC;
                mw <= pw;
                mh <= ph;
            end
            wire signed [55:0] A = P2 ? (mx <<< 8) - mw : (mx <<< 8) - mw + (56'sd1 <<< (OFF - 1));
            wire signed [55:0] B = P2 ? (my <<< 8) - mh : (my <<< 8) - mh + (56'sd1 <<< (OFF - 1));
            wire signed [55:0] ra = A >>> OFF;
            wire signed [55:0] rb = B >>> OFF;
            always @(posedge clk) begin
                s7_a[AW*i +: AW] <= ra[AW-1:0];
                s7_b[AW*i +: AW] <= rb[AW-1:0];
            end
        end
    endgenerate
    wire [6*31-1:0] wz5d;
    uvt_dly #(.W(6*31), .N(M3)) dl_wz5 (clk, {s5_wt, s5_zt}, wz5d);
    always @(posedge clk) begin
        {s6_wt, s6_zt} <= wz5d;
        {s7_wt, s7_zt} <= {s6_wt, s6_zt};
    end

    // ---- stages 8–9: step 5, E'_k = a'_{k+1}·b'_{k+2} − a'_{k+2}·b'_{k+1} --------------------
    reg [3*AW-1:0] s8_a, s8_b, s9_a, s9_b, s10_a, s10_b;
    reg [3*31-1:0] s8_wt, s8_zt, s9_wt, s9_zt, s10_wt, s10_zt, s11_zt;
    reg [3*EW-1:0] s9_e;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_edge
            wire signed [AW-1:0] ai = s7_a[AW*((i+1)%3) +: AW];
            wire signed [AW-1:0] bi = s7_b[AW*((i+1)%3) +: AW];
            wire signed [AW-1:0] aj = s7_a[AW*((i+2)%3) +: AW];
            wire signed [AW-1:0] bj = s7_b[AW*((i+2)%3) +: AW];
            if (KE) begin : g_kara
                wire signed [EW-1:0] ek;
                uvt_bsample_kdet #(.AW(AW), .PA(DSP_A), .PB(DSP_B), .MAP(MAP)) m_k (
                    .clk(clk), .ai(ai), .bj(bj), .aj(aj), .bi(bi), .e(ek));
                always @(posedge clk) s9_e[EW*i +: EW] <= ek;
            end else begin : g_mul
                reg signed [EW-1:0] p1, p2;
                wire signed [EW-1:0] q1, q2;
                uvt_mul #(.AW(AW), .BW(AW), .PA(DSP_A), .PB(DSP_B), .LW(LWE), .REG(RG),
                          .LAT(M4), .MAP(MAP)) m_1 (ai, bj, q1, clk);
                uvt_mul #(.AW(AW), .BW(AW), .PA(DSP_A), .PB(DSP_B), .LW(LWE), .REG(RG),
                          .LAT(M4), .MAP(MAP)) m_2 (aj, bi, q2, clk);
                always @(posedge clk) begin
                    p1 <= q1;
                    p2 <= q2;
                end
                always @(posedge clk) s9_e[EW*i +: EW] <= p1 - p2;
            end
        end
    endgenerate
    wire [6*AW+6*31-1:0] ab7d, ab9d;
    wire [3*31-1:0] zt10d;
    uvt_dly #(.W(6*AW+6*31), .N(M4)) dl_ab7 (clk, {s7_a, s7_b, s7_wt, s7_zt}, ab7d);
    uvt_dly #(.W(6*AW+6*31), .N(M5)) dl_ab9 (clk, {s9_a, s9_b, s9_wt, s9_zt}, ab9d);
    uvt_dly #(.W(3*31), .N(P1 + P2)) dl_zt10 (clk, s10_zt, zt10d);
    always @(posedge clk) begin
        {s8_a, s8_b, s8_wt, s8_zt} <= ab7d;
        {s9_a, s9_b, s9_wt, s9_zt} <= {s8_a, s8_b, s8_wt, s8_zt};
        {s10_a, s10_b, s10_wt, s10_zt} <= ab9d;
        s11_zt <= zt10d;
    end

    // ---- stage 10: rare-path products E'·w, tie keys, |E'| bit length ----------------------
    // With PIPE the product takes MR more clocks; the other results wait for it in delay
    // registers, and |E'|'s OR is registered before its bit length (P1 of the MR clocks).
    reg [3*RW-1:0] s10_q;
    reg [3*EW-1:0] s10_e;
    reg [2:0] s10_pos, s10_neg, s10_gt, s10_lt;
    reg s10_wpos;
    reg [5:0] s10_sh;
    wire [3*EW-1:0] e_mag;
    wire [EW-1:0] e_or = e_mag[0 +: EW] | e_mag[EW +: EW] | e_mag[2*EW +: EW];
    wire [11:0] key_n;                 // {pos, neg, gt, lt}, each of the three edges
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_key
            wire signed [EW-1:0] ek = s9_e[EW*i +: EW];
            wire signed [30:0] wk = s9_wt[31*i +: 31];
            wire signed [EW+30:0] qk;
            if (KK) begin : g_kara
                wire signed [EW-1:0] ph;       // E'_H·w, E'_H = E' >> 31 (signed)
                wire signed [62:0] pl;         // E'_L·w, E'_L = E' mod 2^31 (unsigned)
                uvt_bsample_kprod #(.XW(EW - 31), .XU(0), .PA(DSP_A), .PB(DSP_B), .MAP(MAP))
                    m_h (.clk(clk), .x(ek[EW-1:31]), .y(wk), .p(ph));
                uvt_bsample_kprod #(.XW(31), .XU(1), .PA(DSP_A), .PB(DSP_B), .MAP(MAP))
                    m_l (.clk(clk), .x(ek[30:0]), .y(wk), .p(pl));
                reg signed [EW+30:0] q7;
                always @(posedge clk) q7 <= (ph <<< 31) + pl;   // clock 7
                assign qk = q7;
            end else begin : g_mul
                uvt_mul #(.AW(EW), .BW(31), .PA(DSP_A), .PB(DSP_B), .LW(LWE), .REG(RG),
                          .LAT(M5), .MAP(MAP)) m_q (ek, wk, qk, clk);
            end
            assign e_mag[EW*i +: EW] = ek[EW-1] ? -ek : ek;
            // tie key κ = cmp((b', a', w)_{k+1}, (b', a', w)_{k+2}), lexicographic, signed
            wire signed [AW-1:0] ai = s9_a[AW*((i+1)%3) +: AW];
            wire signed [AW-1:0] bi = s9_b[AW*((i+1)%3) +: AW];
            wire signed [30:0]   wi = s9_wt[31*((i+1)%3) +: 31];
            wire signed [AW-1:0] aj = s9_a[AW*((i+2)%3) +: AW];
            wire signed [AW-1:0] bj = s9_b[AW*((i+2)%3) +: AW];
            wire signed [30:0]   wj = s9_wt[31*((i+2)%3) +: 31];
            // PIPE = 2: the sign tests as the sign bit and an OR (no subtraction)
            assign key_n[9+i] = P2 ? !ek[EW-1] && (|ek) : (ek > 0);
            assign key_n[6+i] = P2 ? ek[EW-1] : (ek < 0);
            assign key_n[3+i] = (bi > bj) || (bi == bj && ((ai > aj) || (ai == aj && wi > wj)));
            assign key_n[i] = (bi < bj) || (bi == bj && ((ai < aj) || (ai == aj && wi < wj)));
            always @(posedge clk) s10_q[RW*i +: RW] <= {qk[EW+30], qk};
        end
    endgenerate
    wire wpos_n = P2 ? !s9_wt[30] && (|s9_wt[29:0]) && !s9_wt[61] && (|s9_wt[60:31]) &&
                       !s9_wt[92] && (|s9_wt[91:62])
                     : ($signed(s9_wt[30:0]) > 0) && ($signed(s9_wt[61:31]) > 0) &&
                       ($signed(s9_wt[92:62]) > 0);
    wire [3*EW+12:0] key_d;
    uvt_dly #(.W(3*EW+13), .N(M5)) dl_key (clk, {s9_e, key_n, wpos_n}, key_d);
    // sh = max(bit length of max|E'| − 24, 0); bit length of the max = that of the OR.
    wire [EW-1:0] e_or_d;
    uvt_dly #(.W(EW), .N(P1)) dl_or (clk, e_or, e_or_d);
    reg [6:0] blen;
    integer k;
    always @(*) begin
        blen = 0;
        for (k = 0; k < EW; k = k + 1)
            if (e_or_d[k]) blen = k + 1;
    end
    wire [5:0] sh_n;
    generate
        if (P2) begin : g_lz
            // PIPE = 2: sh = 0 if bits EW−1..24 of the OR are 0, else 1 + the index of the
            // highest set one among them: a two-level leading-one tree over groups of four bits
            // (each group's OR and top index registered, then the top group and its index).
            wire [63:0] v = {{(88-EW){1'b0}}, e_or_d[EW-1:24]};
            wire [15:0] ga;                // group g has a set bit
            wire [31:0] gp;                // the index of its top set bit
            for (i = 0; i < 16; i = i + 1) begin : g_grp
                wire [3:0] q = v[4*i +: 4];
                assign ga[i] = |q;
                assign gp[2*i +: 2] = q[3] ? 2'd3 : q[2] ? 2'd2 : q[1] ? 2'd1 : 2'd0;
            end
            reg [15:0] ra;
            reg [31:0] rp;
            always @(posedge clk) begin
                ra <= ga;
                rp <= gp;
            end
            wire [3:0] ha;                 // some group of the quad set
            wire [7:0] hg;                 // the top such group of the quad
            for (i = 0; i < 4; i = i + 1) begin : g_quad
                wire [3:0] q = ra[4*i +: 4];
                assign ha[i] = |q;
                assign hg[2*i +: 2] = q[3] ? 2'd3 : q[2] ? 2'd2 : q[1] ? 2'd1 : 2'd0;
            end
            wire [1:0] h = ha[3] ? 2'd3 : ha[2] ? 2'd2 : ha[1] ? 2'd1 : 2'd0;
            wire [3:0] g = {h, hg[2*h +: 2]};
            wire [5:0] idx = {g, rp[2*g +: 2]};
            assign sh_n = (|ha) ? idx + 6'd1 : 6'd0;
        end else begin : g_blen
            assign sh_n = (blen > 24) ? blen - 7'd24 : 6'd0;
        end
    endgenerate
    wire [5:0] sh_d;
    uvt_dly #(.W(6), .N(M5 - P1 - P2)) dl_sh (clk, sh_n, sh_d);
    always @(posedge clk) begin
        {s10_e, s10_pos, s10_neg, s10_gt, s10_lt, s10_wpos} <= key_d;
        s10_sh <= sh_d;
    end

    // ---- stage 11: steps 6–7, orientation and coverage; E'' = floor(E' / 2^sh) --------------
    // With PIPE the sum det is registered (P1) before the sign tests; the rest waits for it.
    // PIPE = 2: q0 + q1 registered first (and q2 beside it), then det = that + q2, one adder a
    // clock; the sign tests are the sign bit and an OR.
    wire signed [RW+1:0] det_n;
    generate
        if (P2) begin : g_det2
            reg signed [RW:0] q01;
            reg signed [RW-1:0] q2;
            always @(posedge clk) begin
                q01 <= $signed(s10_q[0 +: RW]) + $signed(s10_q[RW +: RW]);
                q2 <= s10_q[2*RW +: RW];
            end
            assign det_n = q01 + q2;
        end else begin : g_det1
            assign det_n = $signed(s10_q[0 +: RW]) + $signed(s10_q[RW +: RW]) +
                           $signed(s10_q[2*RW +: RW]);
        end
    endgenerate
    wire [3*25-1:0] e2_n;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_shift
            wire signed [EW-1:0] ek = s10_e[EW*i +: EW];
            wire signed [EW-1:0] es = ek >>> s10_sh;
            assign e2_n[25*i +: 25] = es[24:0];
        end
    endgenerate
    wire signed [RW+1:0] det;
    wire [12:0] key11;
    wire [3*25-1:0] e2_d;
    wire [6*AW+3*EW+3*31-1:0] abe_d;
    uvt_dly #(.W(RW+2), .N(P1)) dl_det (clk, det_n, det);
    uvt_dly #(.W(13), .N(P1 + P2)) dl_key11 (clk, {s10_pos, s10_neg, s10_gt, s10_lt, s10_wpos}, key11);
    uvt_dly #(.W(75), .N(P1 + P2)) dl_e2 (clk, e2_n, e2_d);
    uvt_dly #(.W(6*AW+3*EW+3*31), .N(P1 + P2)) dl_abe (clk, {s10_a, s10_b, s10_e, s10_wt}, abe_d);
    wire [2:0] k_pos = key11[12:10], k_neg = key11[9:7], k_gt = key11[6:4], k_lt = key11[3:1];
    wire k_wpos = key11[0];
    wire any_pos = |k_pos, any_neg = |k_neg;
    wire det_pos = P2 ? !det[RW+1] && (|det) : (det > 0);
    wire det_neg = P2 ? det[RW+1] : (det < 0);
    wire sp = k_wpos ? (any_pos && !any_neg) : det_pos;
    wire sn = k_wpos ? (any_neg && !any_pos) : det_neg;
    wire [2:0] in_k = sp ? (k_pos | (~k_pos & ~k_neg & k_gt))
                         : (k_neg | (~k_pos & ~k_neg & k_lt));
    reg s11_sp, s11_sn, s11_cov;
    reg [3*AW-1:0] s11_a, s11_b;
    reg [3*EW-1:0] s11_e;
    reg [3*31-1:0] s11_wt;
    reg [3*25-1:0] s11_e2;
    always @(posedge clk) begin
        s11_sp <= sp;
        s11_sn <= sn;
        s11_cov <= (sp || sn) && (&in_k);
        {s11_a, s11_b, s11_e, s11_wt} <= abe_d;
        s11_e2 <= e2_d;
    end
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_out
            assign ab[64*i +: 32] = {{(32-AW){s11_a[AW*i+AW-1]}}, s11_a[AW*i +: AW]};
            assign ab[64*i+32 +: 32] = {{(32-AW){s11_b[AW*i+AW-1]}}, s11_b[AW*i +: AW]};
            assign e[64*i +: 64] = {{(64-EW){s11_e[EW*i+EW-1]}}, s11_e[EW*i +: EW]};
        end
    endgenerate
    assign det_sign = s11_sp ? 2'sb01 : (s11_sn ? 2'sb11 : 2'sb00);
    assign covered = s11_cov;

    // ---- stages 12–13: step 8, num = Σ E''·z, den = Σ E''·w (times the orientation sign) -----
    // With PIPE the products take MR more clocks and the sums are registered (P1) before
    // the sign is applied.
    reg [3*56-1:0] s12_nz, s12_nw;
    reg s12_neg, s12_cov;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_depth
            wire signed [24:0] e2 = s11_e2[25*i +: 25];
            wire signed [30:0] zk = s11_zt[31*i +: 31];
            wire signed [30:0] wk = s11_wt[31*i +: 31];
            wire signed [55:0] pz, pw;
            uvt_mul #(.AW(25), .BW(31), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(RG), .LAT(M6),
                      .MAP(MAP)) m_z (e2, zk, pz, clk);
            uvt_mul #(.AW(25), .BW(31), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(RG), .LAT(M6),
                      .MAP(MAP)) m_w (e2, wk, pw, clk);
            always @(posedge clk) begin
                s12_nz[56*i +: 56] <= pz;
                s12_nw[56*i +: 56] <= pw;
            end
        end
    endgenerate
    wire [1:0] nc11d;
    uvt_dly #(.W(2), .N(M6)) dl_nc11 (clk, {s11_sn, s11_cov}, nc11d);
    always @(posedge clk) {s12_neg, s12_cov} <= nc11d;
    // PIPE = 2: the first two terms of each sum registered first (the third and the flags
    // beside them), then the third added: one adder a clock.
    wire signed [55:0] nsum_n, dsum_n;
    wire [1:0] nc12;
    generate
        if (P2) begin : g_sum2
            reg signed [55:0] n01, n2, d01, d2;
            reg [1:0] f;
            always @(posedge clk) begin
                n01 <= $signed(s12_nz[0 +: 56]) + $signed(s12_nz[56 +: 56]);
                d01 <= $signed(s12_nw[0 +: 56]) + $signed(s12_nw[56 +: 56]);
                n2 <= s12_nz[112 +: 56];
                d2 <= s12_nw[112 +: 56];
                f <= {s12_neg, s12_cov};
            end
            assign nsum_n = n01 + n2;
            assign dsum_n = d01 + d2;
            assign nc12 = f;
        end else begin : g_sum1
            assign nsum_n = $signed(s12_nz[0 +: 56]) + $signed(s12_nz[56 +: 56]) +
                            $signed(s12_nz[112 +: 56]);
            assign dsum_n = $signed(s12_nw[0 +: 56]) + $signed(s12_nw[56 +: 56]) +
                            $signed(s12_nw[112 +: 56]);
            assign nc12 = {s12_neg, s12_cov};
        end
    endgenerate
    wire [113:0] sums_d;
    uvt_dly #(.W(114), .N(P1)) dl_sums (clk, {nsum_n, dsum_n, nc12}, sums_d);
    wire signed [55:0] nsum = sums_d[113:58], dsum = sums_d[57:2];
    wire s12_negd = sums_d[1], s12_covd = sums_d[0];
    reg signed [55:0] s13_num, s13_den;
    reg s13_cov;
    always @(posedge clk) begin
        s13_num <= s12_negd ? -nsum : nsum;
        s13_den <= s12_negd ? -dsum : dsum;
        s13_cov <= s12_covd;
    end

    // ---- stage 14: divider set-up. q = floor(num·2^24 / den) saturated to [−2^31, 2^31−2];
    // den <= 0 gives the far end. Unsigned M / D with M = |num|·2^24 (+ D − 1 when num < 0,
    // so that floor of the negative quotient = −floor(M / D)); Q >= 2^31 saturates.
    // With PIPE two more registers: after |num| and D − 1 (P1), and after M (P1).
    wire        dneg_n = s13_num[55];
    wire [55:0] nmag_n = dneg_n ? -s13_num : s13_num;
    wire [79:0] dm1_n = {24'd0, s13_den} - 80'd1;
    wire [193:0] st_a;
    uvt_dly #(.W(194), .N(P1)) dl_sta (clk, {dneg_n, nmag_n, dm1_n, s13_den, s13_cov}, st_a);
    wire        dneg = st_a[193];
    wire [55:0] nmag = st_a[192:137];
    wire [79:0] dm1 = st_a[136:57];
    wire [79:0] mm_n = {nmag[54:0], 24'd0} + (dneg ? dm1 : 80'd0);
    wire [137:0] st_b;
    uvt_dly #(.W(138), .N(P1)) dl_stb (clk, {dneg, mm_n, st_a[56:0]}, st_b);
    wire        mneg = st_b[137];
    wire [79:0] mm = st_b[136:57];
    wire signed [55:0] mden = st_b[56:1];
    wire        mcov = st_b[0];
    // Stage j of the divider in slice j of each vector (j = 0: set-up, 31: quotient done).
    reg  [31:0] dv_bad;                // den <= 0: the far end
    reg  [31:0] dv_sat;                // Q >= 2^31: saturate
    reg  [31:0] dv_neg, dv_cov;
    reg  [32*57-1:0] dv_r;             // partial remainder, < D
    reg  [32*55-1:0] dv_d;             // divisor D = den < 2^55
    reg  [32*31-1:0] dv_m;             // dividend bits still to shift in (MSB first)
    reg  [32*31-1:0] dv_q;             // quotient bits so far
    always @(posedge clk) begin
        dv_r[0 +: 57] <= {8'd0, mm[79:31]};
        dv_d[0 +: 55] <= mden[54:0];
        dv_m[0 +: 31] <= mm[30:0];
        dv_q[0 +: 31] <= 31'd0;
        dv_neg[0] <= mneg;
        dv_cov[0] <= mcov;
        dv_bad[0] <= (mden <= 0);
        dv_sat[0] <= {8'd0, mm[79:31]} >= {2'd0, mden[54:0]};
    end
    // ---- stages 15–45: restoring division, quotient bit 30 − j at stage j -------------------
    generate
        for (i = 0; i < 31; i = i + 1) begin : g_div
            wire [54:0] d  = dv_d[55*i +: 55];
            wire [30:0] m  = dv_m[31*i +: 31];
            wire [57:0] r2 = {dv_r[57*i +: 57], m[30]};
            wire        ge = r2 >= {3'd0, d};
            wire [57:0] rs = r2 - {3'd0, d};
            always @(posedge clk) begin
                dv_r[57*(i+1) +: 57] <= ge ? rs[56:0] : r2[56:0];
                dv_d[55*(i+1) +: 55] <= d;
                dv_m[31*(i+1) +: 31] <= {m[29:0], 1'b0};
                dv_q[31*(i+1) +: 31] <= {dv_q[31*i +: 30], ge};
                dv_neg[i+1] <= dv_neg[i];
                dv_cov[i+1] <= dv_cov[i];
                dv_sat[i+1] <= dv_sat[i];
                dv_bad[i+1] <= dv_bad[i];
            end
        end
    endgenerate
    // ---- stage 46: sign, saturation, far end for den <= 0, 0 when not covered -------------
    wire [30:0] qq = dv_q[31*31 +: 31];
    reg  signed [31:0] r_depth;
    reg         r_cov;
    always @(posedge clk) begin
        r_cov <= dv_cov[31];
        if (!dv_cov[31])
            r_depth <= 32'sd0;
        else if (dv_bad[31])
            r_depth <= 32'sh7ffffffe;
        else if (dv_sat[31])
            r_depth <= dv_neg[31] ? 32'sh80000000 : 32'sh7ffffffe;
        else if (dv_neg[31])
            r_depth <= -$signed({1'b0, qq});
        else
            r_depth <= (qq == 31'h7fffffff) ? 32'sh7ffffffe : $signed({1'b0, qq});
    end
    assign depth = r_depth;
    assign out_covered = r_cov;
endmodule

// uvt_bsample_kdet — e = ai·bj − aj·bi (AW-bit signed operands, 16 < AW <= 33) on six 18 × 18
// products instead of eight: with x = xH·2^16 + xL (xL = x mod 2^16, xH = x >> 16 signed),
// x·y = xH·yH·2^32 + ((xH + xL)(yH + yL) − xH·yH − xL·yL)·2^16 + xL·yL (Karatsuba), and
// xH + xL lies in [−2^(AW−17), 2^16 + 2^(AW−17)), 18 bits signed. Each product is uvt_mul
// REG = 3 (3 clocks; the operand sums are formed before its input registers), then the three
// differences (clock 4), DM − DH and DH·2^32 + DL (clock 5), minus DL (clock 6), the sum
// (clock 7): one adder a clock, e seven clocks after the inputs. Arithmetic modulo 2^(2·AW),
// exact as |e| < 2^(2·AW−1).
module uvt_bsample_kdet #(
    parameter AW = 31,
    parameter PA = 18,
    parameter PB = 18,
    parameter MAP = 0
) (
    input  wire                   clk,
    input  wire signed [AW-1:0]   ai,
    input  wire signed [AW-1:0]   bj,
    input  wire signed [AW-1:0]   aj,
    input  wire signed [AW-1:0]   bi,
    output wire signed [2*AW-1:0] e
);
    localparam EW = 2 * AW;
    wire signed [17:0] aiH = ai >>> 16, bjH = bj >>> 16, ajH = aj >>> 16, biH = bi >>> 16;
    wire signed [17:0] aiL = {2'b0, ai[15:0]}, bjL = {2'b0, bj[15:0]};
    wire signed [17:0] ajL = {2'b0, aj[15:0]}, biL = {2'b0, bi[15:0]};
    wire signed [17:0] aiS = aiH + aiL, bjS = bjH + bjL, ajS = ajH + ajL, biS = biH + biL;
    wire signed [35:0] hh1, ll1, mm1, hh2, ll2, mm2;
    uvt_mul #(.AW(18), .BW(18), .PA(PA), .PB(PB), .LW(0), .REG(3), .LAT(3), .MAP(MAP))
        m_hh1 (aiH, bjH, hh1, clk), m_ll1 (aiL, bjL, ll1, clk), m_mm1 (aiS, bjS, mm1, clk),
        m_hh2 (ajH, biH, hh2, clk), m_ll2 (ajL, biL, ll2, clk), m_mm2 (ajS, biS, mm2, clk);
    reg signed [36:0] dh, dl, dm;
    reg signed [EW-1:0] m1, a1, dl5, mp, a6, s7;
    always @(posedge clk) begin
        dh <= hh1 - hh2;                                   // clock 4
        dl <= ll1 - ll2;
        dm <= mm1 - mm2;
        m1 <= dm - dh;                                     // clock 5
        a1 <= (dh <<< 32) + dl;
        dl5 <= dl;
        mp <= m1 - dl5;                                    // clock 6
        a6 <= a1;
        s7 <= a6 + (mp <<< 16);                            // clock 7
    end
    assign e = s7;
endmodule

// uvt_bsample_kprod — p = x·y, x XW bits (17 <= XW <= 33; unsigned if XU, else signed), y 31
// bits signed, on three 18 × 18 products (Karatsuba, as uvt_bsample_kdet: x = xH·2^16 + xL,
// x·y = xH·yH·2^32 + ((xH + xL)(yH + yL) − xH·yH − xL·yL)·2^16 + xL·yL, each operand sum 18
// bits signed). uvt_mul REG = 3 (3 clocks), then MM − HH and HH·2^32 + LL (clock 4), minus LL
// (clock 5), the sum (clock 6): p six clocks after x and y, exact (modulo 2^(XW+31+XU), which
// holds the product).
module uvt_bsample_kprod #(
    parameter XW = 31,
    parameter XU = 0,
    parameter PA = 18,
    parameter PB = 18,
    parameter MAP = 0
) (
    input  wire                      clk,
    input  wire [XW-1:0]             x,
    input  wire signed [30:0]        y,
    output wire signed [XW+XU+30:0]  p
);
    localparam QW = XW + XU + 31;
    wire signed [XW+XU-1:0] xs;        // x as a signed value
    generate
        if (XU) begin : g_u
            assign xs = {1'b0, x};
        end else begin : g_s
            assign xs = x;
        end
    endgenerate
    wire signed [17:0] xH = xs >>> 16, yH = y >>> 16;
    wire signed [17:0] xL = {2'b0, x[15:0]}, yL = {2'b0, y[15:0]};
    wire signed [17:0] xS = xH + xL, yS = yH + yL;
    wire signed [35:0] hh, ll, mm;
    uvt_mul #(.AW(18), .BW(18), .PA(PA), .PB(PB), .LW(0), .REG(3), .LAT(3), .MAP(MAP))
        m_hh (xH, yH, hh, clk), m_ll (xL, yL, ll, clk), m_mm (xS, yS, mm, clk);
    reg signed [QW-1:0] m1, a1, ll4, mp, a5, s6;
    always @(posedge clk) begin
        m1 <= mm - hh;                                     // clock 4
        a1 <= (hh <<< 32) + ll;
        ll4 <= ll;
        mp <= m1 - ll4;                                    // clock 5
        a5 <= a1;
        s6 <= a5 + (mp <<< 16);                            // clock 6
    end
    assign p = s6;
endmodule
