// uvt_bounds — the per-tile bounds of uvt-core (core/src/bounds/laine.rs, `Laine2011::tile`:
// Laine et al. 2011's lens bounds and dual-space time bounds) as a fully pipelined unit: one
// tile per clock, bit-exact against the golden vectors bounds_in.hex / bounds_out.hex with the
// triangle's coefficients from setup_out.hex. Synthesizable Verilog-2005 (Icarus, Yosys).
//
// Parameters:
//   BND  fraction bits of the bounds' pixel grid (`prec.bnd()`, 0..16): tile edges are x·2^BND
//   TUV  fraction bits of t, u, v (`prec.tuv()`, 2..16): every interval is rounded outward to
//        that grid (`Interval::round_out`; a no-op at 16)
//   DSP_A, DSP_B, LUTW  the multiplier tiling of every product (uvt_mul.v): 25 × 18 for DSP48E1
//        (default), 18 × 18 for ECP5
//   PIPE 0 (default): LAT = 26; 1: LAT = 27, the same results one clock later: the lens
//        products registered inside uvt_mul (REG = 2: the lens path then ends at stage 9, still
//        ahead of the dual path) and stage 26 split in two (docs/rtl.md "Placed and routed
//        speed" for what each gives); 2: LAT = 34, at most one wide carry chain or one
//        multiplier between registers: every product REG = 3 inside uvt_mul (the lens products
//        8 clocks, the dual line products 5, in place of the stage-4 register), the lens
//        clamp (5), the lens u = 2s − 1 (7) and the dual meet (25) each before a register of
//        their own, |n| > |d| of negative n, d compared as n < d (no negation before it), and
//        stage 26 four clocks (span ∩ t_x, ∩ t_y, the test tl ≤ th, the outputs)
//   MAP  0 (default): behavioural products; 1 (PIPE = 2, 18 × 18 ports only): every hard piece
//        an instantiated ECP5 MULT18X18D (uvt_mul.v); the same bits and latency
// The default configuration bounded-16-16-16-20 (and the exact one) is BND = TUV = 16, the only
// values the committed records exercise (tests/tests/external/bounds_rtl.rs); others are untested.
//
// Ports (setup_out / bounds_in record fields, vectors/README.md; i64 / i128 two's complement):
//   x0, y0, x1, y1      the tile (bounds_in words 1, 2), inside the triangle's footprint
//   span_lo, span_hi    setup's frustum time span (setup_out words 3, 4), raw 2^-16
//   lens_on[2a+s]       lens side s (0: box minimum, 1: maximum) of axis a (0: x → u, 1: y → v)
//                       exists: flag box_{x,y}_{lo,hi} and flag lens_{x,y} of setup_out word 0
//   lens_base[64k +: 64], lens_d[64k +: 64], lens_rup[128k +: 128], lens_rdn[128k +: 128]
//                       side k = 2a+s: box value at lens −1, slope d and its reciprocals
//                       ceil/floor(2^80/|d|) (`LensSide`, `RecipConstraint`)
//   dual_on[a]          dual-space lines of axis a exist (flag dual_{x,y})
//   dual_xi[32(2a+e) +: 32]   footprint start ξa (e = 0) and end ξb (e = 1) of axis a
//   dual_delta[64(8a+4m+2t+e) +: 64]  δmin (m = 0) / δmax (m = 1) at time t, footprint end e
//   nonempty, u_lo, u_hi, v_lo, v_hi, t_lo, t_hi   bounds_out words 0..6 (the box; all zero
//                       when the tile is empty), with out_valid, LAT = 26 + PIPE clocks after
//                       in_valid (PIPE = 2: 34)
// The unit reads the bits the model's ranges allow (core/src/bounds/laine.rs and the width table,
// `uvt widths`, core/README.md): |base| < 2^58, |d| ≤ 3·2^56 (so |n| < 2^58 where it is
// multiplied, and n·r < 2^81), r ≤ 2^80 (81 bits), |δ| < 2^44 (45 bits), ξ < 2^16; every line
// value and solve operand is then exact in its register.
//
// Pipeline (stage k = the registers loaded k clocks after in_valid):
//   1      inputs registered
//   lens (per side): 2  n = x1·2^BND − base (side lo) or base − x0·2^BND (side hi)
//          3  the cases of `RecipConstraint::solve`: d > 0: n < 0 empty, n ≥ d all of [0, 1];
//             d < 0: n ≥ 0 all, |n| > |d| empty; d = 0: n ≥ 0 all, else empty; otherwise the
//             product |n| · (d > 0 ? r_up : r_dn)
//          4  the product, exact in 82 bits (uvt_mul; `mul_shr64`'s n·r); with PIPE = 1 it
//             is registered inside uvt_mul and stages 4–7 below become 6–9
//          5  q = product >> 64, plus 1 when d > 0 and the low 64 bits are nonzero (ceil);
//             clamped to 1: d > 0 gives s ∈ [0, q], d < 0 gives s ∈ [q, 1]
//          6  `meet` of [0, 1] with the present sides (empty when one is empty or lo > hi)
//          7  `s_to_lens` (u = 2s − 1) and `round_out(TUV)`; then delayed to stage 26
//   dual (per axis): 2  footprint span D = ξb − ξa, tile ends xl = min, xh = max, slopes v1 − v0
//          3  per line the tile end the slope's sign picks (`dual_t`'s `line`), x − ξa
//          4  products v0·D and (v1 − v0)·(x − ξa) (uvt_mul)
//          5  line values lo0, lo1, hi0, hi1 (their sums)
//          6  the two solves' operands: (d, n) = (lo1 − lo0, −lo0) and (hi0 − hi1, hi0)
//          7  the cases of `solve_le64` (d > 0: n < 0 empty, n ≥ d all; d < 0: n ≥ 0 all,
//             |n| > |d| empty, |n| = |d| gives [1, 1]; d = 0: n ≥ 0 all, else empty) and the
//             divider's operands (n, d) or (|n|, |d|)
//          8–23  `frac_div`: floor(num·2^16 / den) by a pipelined restoring (radix-2) divider,
//             one quotient bit per stage, 16 stages; the remainder's nonzero bit is the ceil
//          24  the intervals [0, q + (rem ≠ 0)] (d > 0) and [q, 1] (d < 0)
//          25  their `meet`, then `round_out(TUV)`
//   26     t = span ∩ the present axes' t intervals; nonempty unless a present lens axis or
//          dual axis is empty or t is; the outputs registered (zero when empty). With PIPE = 1
//          the meet is registered in 26 and the emptiness test and the outputs are stage 27.
// PIPE = 2 (the stage numbers above move): lens 4–11 the product (8 clocks), 12 its register,
//   13 q, 14 the clamp and the side's interval, 15 the meet of the sides, 16 2s − 1 and the
//   axis's emptiness, 17 round_out; dual 4–8 the products (5 clocks), 9 the line values, 10 the
//   operands, 11 the cases, 12–27 the divider, 28 the intervals, 29 their meet, 30 round_out and
//   the emptiness; 31 span ∩ t_x, 32 ∩ t_y, 33 the test tl ≤ th, 34 the outputs.
// No reset: hold in_valid low for LAT clocks after power-up (the valid pipeline fills with 0).
`timescale 1ns / 1ps
module uvt_bounds #(
    parameter BND = 16,
    parameter TUV = 16,
    parameter DSP_A = 25,
    parameter DSP_B = 18,
    parameter LUTW = 8,
    parameter PIPE = 0,
    parameter MAP = 0
) (
    input  wire               clk,
    input  wire               in_valid,
    input  wire [15:0]        x0,
    input  wire [15:0]        y0,
    input  wire [15:0]        x1,
    input  wire [15:0]        y1,
    input  wire signed [31:0] span_lo,
    input  wire signed [31:0] span_hi,
    input  wire [3:0]         lens_on,
    input  wire [4*64-1:0]    lens_base,
    input  wire [4*64-1:0]    lens_d,
    input  wire [4*128-1:0]   lens_rup,
    input  wire [4*128-1:0]   lens_rdn,
    input  wire [1:0]         dual_on,
    input  wire [4*32-1:0]    dual_xi,
    input  wire [16*64-1:0]   dual_delta,
    output wire               out_valid,
    output reg                nonempty,
    output reg signed [31:0]  u_lo,
    output reg signed [31:0]  u_hi,
    output reg signed [31:0]  v_lo,
    output reg signed [31:0]  v_hi,
    output reg signed [31:0]  t_lo,
    output reg signed [31:0]  t_hi
);
    localparam P2 = PIPE == 2 ? 1 : 0;
    localparam LL = 8;         // PIPE = 2: clocks of the lens products (uvt_mul REG = 3: 3 +
                               // clog2(terms), 23 terms at 18 × 18, 20 at 25 × 18)
    localparam LD = 5;         // PIPE = 2: clocks of the dual line products (3 or 2 terms)
    localparam MR = P2 ? LL : 2 * PIPE;  // clocks inside the lens products (uvt_mul REG)
    localparam DS = P2 ? LD - 1 : 0;     // the dual path's stages 5–25 move by DS
    localparam S25 = 25 + DS + P2;       // the stage of the time intervals (s25_*)
    localparam LAT = S25 + (P2 ? 4 : 1 + PIPE);
    localparam UD = S25 - (7 + MR + 2 * P2);   // the lens results' delay to stage S25
    localparam XD = S25 - 1;                   // span and flags: stage 1 → S25
    localparam signed [17:0] ONE = 18'sd65536;     // 1.0 in t/u/v raw units
    localparam signed [17:0] STEP = 18'sd1 <<< (16 - TUV);   // the TUV grid's step
    localparam NW = 66;        // n = ±(x·2^BND − base), signed
    localparam MW = 58;        // |n| at the multiplier (< |d| ≤ 3·2^56)
    localparam RW = 81;        // r_up, r_dn ≤ 2^80
    localparam PW = 82;        // n·r < 2^81: its low 82 bits are the product
    localparam DW = 45;        // |δ| < 2^44
    localparam LW = 64;        // line values < 2^62; solve operands < 2^63 (65 bits held)
    localparam QW = 16;        // quotient bits (`frac_div`'s k = 16)

    reg [LAT:1] vld;
    always @(posedge clk) vld <= {vld[LAT-1:1], in_valid};
    assign out_valid = vld[LAT];

    // round_out: the low end down, the high end up (then ≤ 1) to the TUV grid.
    function signed [17:0] rnd_lo(input signed [17:0] x);
        rnd_lo = x & ~(STEP - 18'sd1);
    endfunction
    function signed [17:0] rnd_hi(input signed [17:0] x);
        reg signed [17:0] y;
        begin
            y = (x + STEP - 18'sd1) & ~(STEP - 18'sd1);
            rnd_hi = y > ONE ? ONE : y;
        end
    endfunction

    // ---- stage 1: inputs --------------------------------------------------------------------
    reg [15:0] s1_x0, s1_y0, s1_x1, s1_y1;
    reg [3:0] s1_lon;
    reg [1:0] s1_don;
    reg signed [31:0] s1_slo, s1_shi;
    reg [4*64-1:0] s1_base, s1_d;
    reg [4*RW-1:0] s1_rup, s1_rdn;
    reg [4*16-1:0] s1_xi;
    reg [16*DW-1:0] s1_dl;
    genvar i, k, st;
    generate
        for (i = 0; i < 4; i = i + 1) begin : g_in4
            always @(posedge clk) begin
                s1_rup[RW*i +: RW] <= lens_rup[128*i +: RW];
                s1_rdn[RW*i +: RW] <= lens_rdn[128*i +: RW];
                s1_xi[16*i +: 16] <= dual_xi[32*i +: 16];
            end
        end
        for (i = 0; i < 16; i = i + 1) begin : g_in16
            always @(posedge clk) s1_dl[DW*i +: DW] <= dual_delta[64*i +: DW];
        end
    endgenerate
    always @(posedge clk) begin
        {s1_x0, s1_y0, s1_x1, s1_y1} <= {x0, y0, x1, y1};
        {s1_lon, s1_don, s1_slo, s1_shi} <= {lens_on, dual_on, span_lo, span_hi};
        s1_base <= lens_base;
        s1_d <= lens_d;
    end

    // ---- lens: stages 2–7 per side k = 2a + s -----------------------------------------------
    reg [4*18-1:0] s5_lo, s5_hi;       // s interval per side, [0, 1]
    reg [3:0] s5_e;                    // side empty
    generate
        for (i = 0; i < 4; i = i + 1) begin : g_side
            wire [15:0] edge_px = (i % 2 == 0) ? (i < 2 ? s1_x1 : s1_y1) : (i < 2 ? s1_x0 : s1_y0);
            wire signed [NW-1:0] scaled = $signed({{NW-16-BND{1'b0}}, edge_px, {BND{1'b0}}});
            wire signed [NW-1:0] base = $signed(s1_base[64*i +: 64]);
            wire signed [NW-1:0] d1 = $signed(s1_d[64*i +: 64]);
            reg signed [NW-1:0] s2_n, s2_d;
            reg [RW-1:0] s2_r;
            reg s2_on, s2_up;
            always @(posedge clk) begin
                s2_n <= (i % 2 == 0) ? scaled - base : base - scaled;
                s2_d <= d1;
                s2_up <= !d1[NW-1] && d1 != 0;
                s2_r <= (!d1[NW-1] && d1 != 0) ? s1_rup[RW*i +: RW] : s1_rdn[RW*i +: RW];
                s2_on <= s1_lon[i];
            end
            // stage 3: the cases; code 0 all of [0, 1], 1 empty, 2 the product decides
            wire nneg = s2_n[NW-1];
            wire dneg = s2_d[NW-1];
            wire signed [NW:0] an = nneg ? -s2_n : s2_n;
            wire signed [NW:0] ad = dneg ? -s2_d : s2_d;
            // |n| > |d| where both are negative; PIPE = 2: as n < d (one carry chain, not a
            // negation followed by a compare)
            wire nbig = P2 ? s2_n < s2_d : an > ad;
            wire [1:0] code = !s2_on ? 2'd0
                            : s2_up ? (nneg ? 2'd1 : s2_n >= s2_d ? 2'd0 : 2'd2)
                            : dneg  ? (!nneg ? 2'd0 : nbig ? 2'd1 : 2'd2)
                            :         (nneg ? 2'd1 : 2'd0);
            reg [1:0] s3_code;
            reg s3_up;
            reg [MW-1:0] s3_m;
            reg [RW-1:0] s3_r;
            always @(posedge clk) begin
                s3_code <= code;
                s3_up <= s2_up;
                s3_m <= an[MW-1:0];
                s3_r <= s2_r;
            end
            // stage 4: n·r (exact: < 2^81)
            wire signed [MW+RW+1:0] p;
            // With PIPE the product takes MR more clocks; its case code and d's sign wait for it.
            uvt_mul #(.AW(MW+1), .BW(RW+1), .PA(DSP_A), .PB(DSP_B), .LW(LUTW),
                      .REG(P2 ? 3 : MR), .LAT(P2 ? LL : 0), .MAP(MAP)) m_nr (
                $signed({1'b0, s3_m}), $signed({1'b0, s3_r}), p, clk);
            wire [1:0] s3_code_d;
            wire s3_up_d;
            uvt_dly #(.W(3), .N(MR)) dl_code (clk, {s3_code, s3_up}, {s3_code_d, s3_up_d});
            reg [PW-1:0] s4_p;
            reg [1:0] s4_code;
            reg s4_up;
            always @(posedge clk) begin
                s4_p <= p[PW-1:0];
                s4_code <= s3_code_d;
                s4_up <= s3_up_d;
            end
            // stage 5: ÷2^64, ceil for d > 0, clamp to 1 (PIPE = 2: the sum registered before
            // the clamp)
            wire [PW-64:0] q = s4_p[PW-1:64] + (s4_up && s4_p[63:0] != 64'd0);
            wire [PW-64:0] q5;
            wire [1:0] c5;
            wire up5;
            uvt_dly #(.W(PW-64+4), .N(P2)) dl_q (clk, {q, s4_code, s4_up}, {q5, c5, up5});
            wire signed [17:0] qc = q5 > ONE ? ONE : $signed({1'b0, q5[16:0]});
            always @(posedge clk) begin
                s5_e[i] <= c5 == 2'd1;
                s5_lo[18*i +: 18] <= (c5 == 2'd2 && !up5) ? qc : 18'sd0;
                s5_hi[18*i +: 18] <= (c5 == 2'd2 && up5) ? qc : ONE;
            end
        end
    endgenerate
    // stages 6, 7 per axis: meet of the sides, then u = 2s − 1 (s ≥ 0 here, so the model's
    // clamp at −1 never acts) rounded outward (PIPE = 2: 2s − 1 and the emptiness registered
    // before the rounding).
    reg [2*18-1:0] s7_lo, s7_hi;
    reg [1:0] s7_e;
    generate
        for (i = 0; i < 2; i = i + 1) begin : g_lens
            wire signed [17:0] la = s5_lo[18*(2*i) +: 18], lb = s5_lo[18*(2*i+1) +: 18];
            wire signed [17:0] ha = s5_hi[18*(2*i) +: 18], hb = s5_hi[18*(2*i+1) +: 18];
            reg signed [17:0] s6_lo, s6_hi;
            reg s6_e;
            always @(posedge clk) begin
                s6_lo <= la > lb ? la : lb;
                s6_hi <= ha < hb ? ha : hb;
                s6_e <= s5_e[2*i] | s5_e[2*i+1];
            end
            wire signed [17:0] ul = 2 * s6_lo - ONE, uh = 2 * s6_hi - ONE;
            wire signed [17:0] ul7, uh7;
            wire ue7;
            uvt_dly #(.W(37), .N(P2)) dl_u (clk, {ul, uh, s6_e | (s6_lo > s6_hi)}, {ul7, uh7, ue7});
            always @(posedge clk) begin
                s7_lo[18*i +: 18] <= rnd_lo(ul7);
                s7_hi[18*i +: 18] <= rnd_hi(uh7);
                s7_e[i] <= ue7;
            end
        end
    endgenerate

    // ---- dual: stages 2–25 per axis a, lines j = 2m + t (lo0, lo1, hi0, hi1) -----------------
    reg [8*LW-1:0] s5_line;            // per axis a, line k: slice 4a + k
    reg [4*18-1:0] s24_lo, s24_hi;     // per solve j = 2a + (0: lo line solve, 1: hi line solve)
    reg [3:0] s24_e;
    generate
        for (i = 0; i < 2; i = i + 1) begin : g_axis
            wire [15:0] t0 = i == 0 ? s1_x0 : s1_y0, t1 = i == 0 ? s1_x1 : s1_y1;
            wire [15:0] xa = s1_xi[16*(2*i) +: 16], xb = s1_xi[16*(2*i+1) +: 16];
            reg [15:0] s2_xl, s2_xh, s2_xa;
            reg signed [16:0] s2_span;
            always @(posedge clk) begin
                s2_xl <= t0 < t1 ? t0 : t1;
                s2_xh <= t0 < t1 ? t1 : t0;
                s2_xa <= xa;
                s2_span <= $signed({1'b0, xb}) - $signed({1'b0, xa});
            end
            reg signed [16:0] s3_span;
            always @(posedge clk) s3_span <= s2_span;
            for (k = 0; k < 4; k = k + 1) begin : g_line
                wire signed [DW-1:0] v0 = s1_dl[DW*(8*i+2*k) +: DW];
                wire signed [DW-1:0] v1 = s1_dl[DW*(8*i+2*k+1) +: DW];
                reg signed [DW-1:0] s2_v0, s3_v0;
                reg signed [DW:0] s2_sl, s3_sl;
                reg signed [16:0] s3_dx;
                always @(posedge clk) begin
                    s2_v0 <= v0;
                    s2_sl <= v1 - v0;
                end
                // the line's minimum (k < 2: δmin lines) or maximum over the tile's two ends
                wire pick_lo = (!s2_sl[DW]) == (k < 2);
                always @(posedge clk) begin
                    s3_v0 <= s2_v0;
                    s3_sl <= s2_sl;
                    s3_dx <= $signed({1'b0, pick_lo ? s2_xl : s2_xh}) - $signed({1'b0, s2_xa});
                end
                wire signed [DW+16:0] p0;
                wire signed [DW+17:0] p1;
                // PIPE = 2: products of LD clocks (uvt_mul REG = 3) in place of the stage-4
                // register; the line value one clock after them (stage 5 + DS)
                uvt_mul #(.AW(DW), .BW(17), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(3 * P2),
                          .LAT(P2 ? LD : 0), .MAP(MAP)) m_v0 (s3_v0, s3_span, p0, clk);
                uvt_mul #(.AW(DW+1), .BW(17), .PA(DSP_A), .PB(DSP_B), .LW(LUTW), .REG(3 * P2),
                          .LAT(P2 ? LD : 0), .MAP(MAP)) m_sl (s3_sl, s3_dx, p1, clk);
                if (P2) begin : g_p2
                    always @(posedge clk) s5_line[LW*(4*i+k) +: LW] <= p0 + p1;
                end else begin : g_p01
                    reg signed [DW+16:0] s4_p0;
                    reg signed [DW+17:0] s4_p1;
                    always @(posedge clk) begin
                        s4_p0 <= p0;
                        s4_p1 <= p1;
                        s5_line[LW*(4*i+k) +: LW] <= s4_p0 + s4_p1;
                    end
                end
            end
            // stage 6: (d, n) of (1−t)·lo0 + t·lo1 ≤ 0 and (1−t)·hi0 + t·hi1 ≥ 0
            wire signed [LW-1:0] lo0 = s5_line[LW*(4*i) +: LW], lo1 = s5_line[LW*(4*i+1) +: LW];
            wire signed [LW-1:0] hi0 = s5_line[LW*(4*i+2) +: LW], hi1 = s5_line[LW*(4*i+3) +: LW];
            reg [2*(LW+1)-1:0] s6_d, s6_n;
            always @(posedge clk) begin
                s6_d[0 +: LW+1] <= lo1 - lo0;
                s6_n[0 +: LW+1] <= -lo0;
                s6_d[LW+1 +: LW+1] <= hi0 - hi1;
                s6_n[LW+1 +: LW+1] <= hi0;
            end
            for (k = 0; k < 2; k = k + 1) begin : g_solve
                // stage 7: solve_le64's cases; code 0 all, 1 empty, 2 [1, 1], 3 divide
                wire signed [LW:0] d = s6_d[(LW+1)*k +: LW+1], n = s6_n[(LW+1)*k +: LW+1];
                wire dpos = !d[LW] && d != 0, dneg = d[LW], nneg = n[LW];
                wire [LW:0] ad = dneg ? -d : d, an = nneg ? -n : n;
                // |n| > |d|, |n| = |d| where both are negative; PIPE = 2: n < d, n = d (no
                // negation before the compare)
                wire nbig = P2 ? n < d : an > ad, neq = P2 ? n == d : an == ad;
                wire [1:0] code = dpos ? (nneg ? 2'd1 : n >= d ? 2'd0 : 2'd3)
                                : dneg ? (!nneg ? 2'd0 : nbig ? 2'd1 : neq ? 2'd2 : 2'd3)
                                :        (nneg ? 2'd1 : 2'd0);
                // stages 7–23: the divider; per stage st the slice st − 7 of each vector
                // (rem < den: num < den ≤ 2^63)
                reg [17*LW-1:0] den, rem;
                reg [17*QW-1:0] quo;
                reg [17*2-1:0] code_p;
                reg [16:0] up_p;
                always @(posedge clk) begin
                    den[0 +: LW] <= ad[LW-1:0];
                    rem[0 +: LW] <= an[LW-1:0];
                    quo[0 +: QW] <= {QW{1'b0}};
                    code_p[0 +: 2] <= code;
                    up_p[0] <= dpos;
                end
                for (st = 1; st <= 16; st = st + 1) begin : g_div
                    wire [LW-1:0] dn = den[LW*(st-1) +: LW];
                    wire [LW:0] r2 = {rem[LW*(st-1) +: LW], 1'b0};
                    wire ge = r2 >= {1'b0, dn};
                    wire [LW:0] rn = ge ? r2 - {1'b0, dn} : r2;
                    always @(posedge clk) begin
                        den[LW*st +: LW] <= dn;
                        rem[LW*st +: LW] <= rn[LW-1:0];
                        quo[QW*st +: QW] <= {quo[QW*(st-1) +: QW-1], ge};
                        code_p[2*st +: 2] <= code_p[2*(st-1) +: 2];
                        up_p[st] <= up_p[st-1];
                    end
                end
                // stage 24: the solve's interval (q < 2^16, so q + 1 ≤ 1 needs no clamp)
                wire [1:0] c = code_p[2*16 +: 2];
                wire up = up_p[16];
                wire signed [17:0] q = $signed({2'b0, quo[QW*16 +: QW]});
                wire signed [17:0] qup = q + (rem[LW*16 +: LW] != 0);
                always @(posedge clk) begin
                    s24_e[2*i+k] <= c == 2'd1;
                    s24_lo[18*(2*i+k) +: 18] <= c == 2'd2 ? ONE : (c == 2'd3 && !up) ? q : 18'sd0;
                    s24_hi[18*(2*i+k) +: 18] <= (c == 2'd3 && up) ? qup : ONE;
                end
            end
        end
    endgenerate
    // stage 25 per axis: meet of the two solves, then round_out (PIPE = 2: the meet registered
    // before the rounding and the emptiness test, stage S25 = 30)
    reg [2*18-1:0] s25_lo, s25_hi;
    reg [1:0] s25_e;
    generate
        for (i = 0; i < 2; i = i + 1) begin : g_t
            wire signed [17:0] la = s24_lo[18*(2*i) +: 18], lb = s24_lo[18*(2*i+1) +: 18];
            wire signed [17:0] ha = s24_hi[18*(2*i) +: 18], hb = s24_hi[18*(2*i+1) +: 18];
            wire signed [17:0] lo = la > lb ? la : lb, hi = ha < hb ? ha : hb;
            wire signed [17:0] lo_m, hi_m;
            wire e_m;
            uvt_dly #(.W(37), .N(P2)) dl_m (clk, {lo, hi, s24_e[2*i] | s24_e[2*i+1]},
                                            {lo_m, hi_m, e_m});
            always @(posedge clk) begin
                s25_lo[18*i +: 18] <= rnd_lo(lo_m);
                s25_hi[18*i +: 18] <= rnd_hi(hi_m);
                s25_e[i] <= e_m | (lo_m > hi_m);
            end
        end
    endgenerate

    // ---- delays to stage 25 (S25): the lens results (from 7 + MR + 2·P2), span and flags
    // (from 1) -----------------------------------------------------------------------------------
    localparam UW = 2 * 18 * 2 + 2;    // u, v: lo, hi, empty (UD registers: 18 − MR; PIPE = 2: 13)
    localparam XW = 64 + 2;            // span, dual_on (XD registers: 24; PIPE = 2: 29)
    reg [UD*UW-1:0] u_d;
    reg [XD*XW-1:0] x_d;
    always @(posedge clk) begin
        u_d <= {u_d[(UD-1)*UW-1:0], s7_lo, s7_hi, s7_e};
        x_d <= {x_d[(XD-1)*XW-1:0], s1_slo, s1_shi, s1_don};
    end

    // ---- stage 26: t = span ∩ t_x ∩ t_y, emptiness, outputs ----------------------------------
    wire [2*18-1:0] ul, uh;
    wire [1:0] ue, don;
    wire signed [31:0] slo, shi;
    assign {ul, uh, ue} = u_d[(UD-1)*UW +: UW];
    assign {slo, shi, don} = x_d[(XD-1)*XW +: XW];
    wire signed [31:0] txl = don[0] ? $signed(s25_lo[0 +: 18]) : -32'sd65536;
    wire signed [31:0] txh = don[0] ? $signed(s25_hi[0 +: 18]) : 32'sd65536;
    wire signed [31:0] tyl = don[1] ? $signed(s25_lo[18 +: 18]) : -32'sd65536;
    wire signed [31:0] tyh = don[1] ? $signed(s25_hi[18 +: 18]) : 32'sd65536;
    wire signed [31:0] m1 = slo > txl ? slo : txl, tl = m1 > tyl ? m1 : tyl;
    wire signed [31:0] m2 = shi < txh ? shi : txh, th = m2 < tyh ? m2 : tyh;
    wire bad = ue[0] | ue[1] | (don[0] & s25_e[0]) | (don[1] & s25_e[1]);
    // PIPE = 1: the meet, the flags and the lens results registered here (stage 26), the test
    // tl ≤ th and the outputs one clock later.
    wire signed [31:0] tl_p, th_p;
    wire bad_p;
    wire [2*18-1:0] ul_p, uh_p;
    uvt_dly #(.W(2 * 32 + 1 + 4 * 18), .N(P2 ? 0 : PIPE)) dl_meet (clk, {tl, th, bad, ul, uh},
                                                        {tl_p, th_p, bad_p, ul_p, uh_p});
    wire ok = !bad_p && tl_p <= th_p;
    // The output stage's operands: the emptiness test and the values it selects.
    wire ok_o;
    wire signed [31:0] tl_o, th_o;
    wire [2*18-1:0] ul_o, uh_o;
    generate
        if (P2) begin : g_tail2
            // PIPE = 2: each compare-and-select level of the meet in a clock of its own (stages
            // S25 + 1: span ∩ t_x, S25 + 2: ∩ t_y), then the test tl ≤ th (S25 + 3), then the
            // outputs (S25 + 4 = LAT).
            reg signed [31:0] a_l, a_h, a_yl, a_yh, b_l, b_h, c_l, c_h;
            reg a_bad, b_bad, c_ok;
            reg [2*18-1:0] a_ul, a_uh, b_ul, b_uh, c_ul, c_uh;
            always @(posedge clk) begin
                {a_l, a_h, a_yl, a_yh, a_bad, a_ul, a_uh} <= {m1, m2, tyl, tyh, bad, ul, uh};
                b_l <= a_l > a_yl ? a_l : a_yl;
                b_h <= a_h < a_yh ? a_h : a_yh;
                {b_bad, b_ul, b_uh} <= {a_bad, a_ul, a_uh};
                c_ok <= !b_bad && b_l <= b_h;
                {c_l, c_h, c_ul, c_uh} <= {b_l, b_h, b_ul, b_uh};
            end
            assign {ok_o, tl_o, th_o, ul_o, uh_o} = {c_ok, c_l, c_h, c_ul, c_uh};
        end else begin : g_tail
            assign {ok_o, tl_o, th_o, ul_o, uh_o} = {ok, tl_p, th_p, ul_p, uh_p};
        end
    endgenerate
    always @(posedge clk) begin
        nonempty <= ok_o;
        u_lo <= ok_o ? $signed(ul_o[0 +: 18]) : 32'sd0;
        u_hi <= ok_o ? $signed(uh_o[0 +: 18]) : 32'sd0;
        v_lo <= ok_o ? $signed(ul_o[18 +: 18]) : 32'sd0;
        v_hi <= ok_o ? $signed(uh_o[18 +: 18]) : 32'sd0;
        t_lo <= ok_o ? tl_o : 32'sd0;
        t_hi <= ok_o ? th_o : 32'sd0;
    end
endmodule
