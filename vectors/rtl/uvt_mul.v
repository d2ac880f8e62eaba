// uvt_mul — a signed AW × BW product decomposed explicitly into hard-multiplier-sized partial
// products, so that synthesis maps each `*` to exactly one hard multiplier (vectors/README.md
// "Multiplier decomposition"; host/src/config/multipliers.rs models the same rule). Combinational;
// synthesizable Verilog-2005 (Icarus Verilog and Yosys).
//
// Tiling rule (ports PA × PB, signed only, as the DSP48E1's 25 × 18; ECP5 builds use 18 × 18):
// - An n-bit operand on a p-bit port is one signed piece if n <= p; otherwise k = ceil((n−p)/(p−1))
//   unsigned low chunks of p−1 bits (zero-extended to p bits signed) and a signed top chunk of
//   h = n − k·(p−1) bits. Every chunk pair is one hard multiplier.
// - A top chunk of at most LW bits may instead be multiplied by the whole other operand in LUTs
//   (a shift-and-add of h rows; no `*`, so synthesis cannot put it on a DSP), removing that
//   chunk's row of hard multipliers. At most one operand's top chunk goes to LUTs.
// - Among both orientations (A on port PA or on port PB) and the options {no LUT chunk, A's top
//   in LUTs, B's top in LUTs}, the one with the fewest hard multipliers is taken, ties broken by
//   fewer LUT partial-product bits (h × other operand's width), then A on port PA.
// The partial products are summed in the fabric (or the DSP cascade, as synthesis packs them);
// the sum is the exact AW+BW-bit product.
// REG = 0 (default): combinational, the terms summed one after the other and the LUT product's
// rows a serial chain of adders; `clk` is unused.
// REG = 1: the terms are registered, then summed as a balanced tree; the LUT product enters as
// ceil(h/4) terms, each the sum of four of its rows as a two-level tree (no serial chain before
// the register); p follows the inputs by 1 clock. REG = 2: the sums of groups of four terms
// (a two-level tree) are registered too; p follows the inputs by 2 clocks. The value is the
// same; only the timing differs (the units' PIPE uses REG = 2 for a faster clock).
// REG = 3 (the units' PIPE = 2, the builds that close timing): at most one multiplier or one
// carry chain between registers. Each hard piece has registered inputs, a pipeline register on
// its product and a registered output (the three register stages of an ECP5 MULT18X18D); a LUT
// chunk's rows are separate terms (the inputs registered, each row formed and registered, then
// registered again); then a binary tree of two-input adders with a register after every level,
// each adder only as wide as its operands' nonzero bits (below the larger of their shifts one
// operand is zero, so those bits are wired, not added). p follows the inputs by LAT clocks: 3 +
// clog2(terms) for the tree, the rest delay registers on p; a LAT too small fails elaboration.
// MAP = 1 (REG = 3 and 18 × 18 ports only): each hard piece is an instantiated MULT18X18D with
// its input, pipeline and output registers on CLK0 (synthesis leaves those registers unused
// when it infers a `*`); MAP = 0 is the same in behavioural Verilog. Same bits and latency;
// MAP = 1 needs uvt_mult18.v (the instance) and, to simulate, a model of the primitive
// (vectors/rtl/ecp5/MULT18X18D.v).
`timescale 1ns / 1ps
module uvt_mul #(
    parameter AW = 18,
    parameter BW = 32,
    parameter PA = 25,
    parameter PB = 18,
    parameter LW = 8,
    parameter REG = 0,
    parameter LAT = 0,
    parameter MAP = 0
) (
    input  wire signed [AW-1:0]    a,
    input  wire signed [BW-1:0]    b,
    output wire signed [AW+BW-1:0] p,
    input  wire                    clk
);
    // Unsigned low chunks of an n-bit operand on a p-bit signed port.
    function integer nlow(input integer n, input integer pw);
        nlow = (n <= pw) ? 0 : (n - pw + pw - 2) / (pw - 1);
    endfunction
    // Width of the signed top chunk.
    function integer top(input integer n, input integer pw);
        top = n - nlow(n, pw) * (pw - 1);
    endfunction
    // Whether the top chunk may go to LUTs.
    function integer lutable(input integer n, input integer pw, input integer lw);
        lutable = (nlow(n, pw) > 0 && top(n, pw) <= lw) ? 1 : 0;
    endfunction
    // Score (hard multipliers · 2^20 + LUT bits) of x on port px, y on port py, option o:
    // 0 none, 1 x's top in LUTs, 2 y's top in LUTs (a large score when not allowed).
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
    // The chosen layout: swap · 4 + option (0, 1: X's top in LUTs, 2: Y's top in LUTs).
    function integer choose(input integer aw, input integer bw, input integer pa,
                            input integer pb, input integer lw);
        integer s, o, best, c;
        begin
            best = 32'h7fffffff;
            choose = 0;
            for (s = 0; s < 2; s = s + 1)
                for (o = 0; o < 3; o = o + 1) begin
                    c = s ? score(bw, aw, pa, pb, lw, o) : score(aw, bw, pa, pb, lw, o);
                    if (c < best) begin
                        best = c;
                        choose = s * 4 + o;
                    end
                end
        end
    endfunction

    // REG = 3: ceil(log2(n)) (0 for n = 1), the tree's levels over n terms.
    function integer clog2(input integer n);
        integer v;
        begin
            clog2 = 0;
            for (v = 1; v < n; v = v * 2)
                clog2 = clog2 + 1;
        end
    endfunction
    // REG = 3: nodes on level k of the tree over n terms, ceil(n / 2^k).
    function integer cnt(input integer n, input integer k);
        cnt = (n + (1 << k) - 1) >> k;
    endfunction
    // REG = 3: the zero low bits of node m on level k (n terms, nh of them hard pieces on yn
    // columns, LUT rows from shift sh): the smallest shift among the terms it sums.
    function integer zlow(input integer n, input integer nh, input integer yn, input integer pa,
                          input integer pb, input integer sh, input integer k, input integer m);
        integer q, z, zq;
        begin
            z = 1 << 30;
            for (q = m << k; q < ((m + 1) << k) && q < n; q = q + 1) begin
                zq = (q < nh) ? (q / yn) * (pa - 1) + (q % yn) * (pb - 1) : sh + (q - nh);
                if (zq < z) z = zq;
            end
            zlow = z;
        end
    endfunction

    localparam C = choose(AW, BW, PA, PB, LW);
    // Clocks from a and b to p (vectors/rtl/pnr.sh reports it).
    localparam LATENCY = REG == 3 ? LAT : REG;
    localparam SWAP = C / 4;
    localparam LX = (C % 4) == 1;
    localparam LY = (C % 4) == 2;
    localparam XW = SWAP ? BW : AW;    // operand X on port PA
    localparam YW = SWAP ? AW : BW;    // operand Y on port PB
    localparam PW = AW + BW;
    localparam XK = nlow(XW, PA), XH = top(XW, PA);
    localparam YK = nlow(YW, PB), YH = top(YW, PB);
    localparam XN = XK + (LX ? 0 : 1);  // hard-multiplier pieces of X
    localparam YN = YK + (LY ? 0 : 1);
    localparam LH = LX ? XH : (LY ? YH : 0);  // rows of the LUT product (0: none)
    // Terms (REG <= 2): hard products, then the LUT product (one term, or 0, with REG = 0; with
    // REG = 1, 2 one term per group of four rows). REG = 3 counts its own (N3 below).
    localparam NL = (REG == 0 || LH == 0) ? 1 : (LH + 3) / 4;
    localparam NT = XN * YN + NL;

    wire signed [XW-1:0] x;
    wire signed [YW-1:0] y;
    generate
        if (SWAP) begin : g_swap
            assign x = b;
            assign y = a;
        end else begin : g_keep
            assign x = a;
            assign y = b;
        end
    endgenerate

    genvar i, j, k, m;
    generate
        if (REG <= 2) begin : g_r012
        // The terms, each shifted to its place: hard products, then the LUT product's terms (or 0);
        // with REG = 0 their running sum acc[t+1] = acc[t] + term t.
        wire [PW*NT-1:0] term;
        wire [PW*(NT+1)-1:0] acc;
        assign acc[0 +: PW] = {PW{1'b0}};
            for (i = 0; i < XN; i = i + 1) begin : g_x
                wire signed [PA-1:0] xp;
                if (i < XK) begin : g_lo
                    assign xp = $signed({1'b0, x[i*(PA-1) +: PA-1]});
                end else begin : g_hi
                    wire signed [XH-1:0] xt = x[XW-1 -: XH];
                    assign xp = xt;
                end
                for (j = 0; j < YN; j = j + 1) begin : g_y
                    wire signed [PB-1:0] yp;
                    if (j < YK) begin : g_lo
                        assign yp = $signed({1'b0, y[j*(PB-1) +: PB-1]});
                    end else begin : g_hi
                        wire signed [YH-1:0] yt = y[YW-1 -: YH];
                        assign yp = yt;
                    end
                    wire signed [PA+PB-1:0] pp = xp * yp;   // one hard multiplier
                    wire signed [PW-1:0] pe = pp;
                    assign term[PW*(i*YN+j) +: PW] = pe <<< (i*(PA-1) + j*(PB-1));
                    assign acc[PW*(i*YN+j+1) +: PW] =
                        $signed(acc[PW*(i*YN+j) +: PW]) + $signed(term[PW*(i*YN+j) +: PW]);
                end
            end
            // The LUT product: a signed top chunk t (TH bits) times the signed operand o (OW bits)
            // as a shift-and-add of TH rows (row q: t[q]·o·2^q, the top row subtracted), shifted
            // to the chunk's position.
            if (LX || LY) begin : g_lut
                localparam TH = LH;
                localparam OW = LX ? YW : XW;
                localparam SH = LX ? XK * (PA - 1) : YK * (PB - 1);
                wire signed [TH-1:0] t;
                wire signed [OW-1:0] o;
                if (LX) begin : g_lx
                    assign t = x[XW-1 -: XH];
                    assign o = y;
                end else begin : g_ly
                    assign t = y[YW-1 -: YH];
                    assign o = x;
                end
                if (REG == 0) begin : g_chain
                    // The rows one after the other: the partial sum after row q is OW+q+1 bits
                    // signed, and each row is one (OW+1)-bit adder above the q bits that are final
                    // already (no sign extension to the full width).
                    wire [(TH+1)*(OW+TH)-1:0] r;
                    assign r[0 +: OW+TH] = {(OW+TH){1'b0}};
                    for (j = 0; j < TH; j = j + 1) begin : g_row
                        wire signed [OW-1:0] pr = {OW{t[j]}} & o;
                        wire signed [OW+j-1:0] prev = r[(OW+TH)*j +: OW+j];  // previous sum >> 0
                        wire signed [OW:0] hi = (j == TH - 1)
                            ? $signed(prev[OW+j-1:j]) - pr
                            : $signed(prev[OW+j-1:j]) + pr;
                        if (j == 0) begin : g_first
                            assign r[(OW+TH)*(j+1) +: OW+TH] = $signed(hi);
                        end else begin : g_next
                            wire signed [OW+j:0] nx = {hi, prev[j-1:0]};
                            assign r[(OW+TH)*(j+1) +: OW+TH] = $signed(nx);
                        end
                    end
                    wire signed [OW+TH-1:0] s = r[(OW+TH)*TH +: OW+TH];
                    wire signed [PW-1:0] se = s;
                    assign term[PW*(NT-1) +: PW] = se <<< SH;
                    assign acc[PW*NT +: PW] =
                        $signed(acc[PW*(NT-1) +: PW]) + $signed(term[PW*(NT-1) +: PW]);
                end else begin : g_tree
                    // Rows in groups of four, each group (r0 + r1) + (r2 + r3) one term. Range: |o|
                    // <= 2^(OW−1) and a row is 0 or ±o·2^q (q <= TH−1), so |row| <= 2^(OW+TH−2);
                    // a group below the top one (q + 4 <= TH − 1) sums to less than |o|·2^(q+4)
                    // <= 2^(OW+TH−2), the top group (positive rows below one negative row) to at
                    // most |o|·2^(TH−1) in magnitude, and so does every partial sum: OW+TH bits
                    // signed hold each value exactly, and the terms sum to t·o.
                    for (i = 0; i < NL; i = i + 1) begin : g_grp
                        wire [4*(OW+TH)-1:0] rw;
                        for (j = 0; j < 4; j = j + 1) begin : g_row
                            if (4 * i + j < TH) begin : g_on
                                wire signed [OW-1:0] pm = {OW{t[4*i+j]}} & o;
                                wire signed [OW+TH-1:0] pr = pm;          // sign-extended
                                wire signed [OW+TH-1:0] sh = pr <<< (4 * i + j);
                                assign rw[(OW+TH)*j +: OW+TH] = (4 * i + j == TH - 1) ? -sh : sh;
                            end else begin : g_off
                                assign rw[(OW+TH)*j +: OW+TH] = {(OW+TH){1'b0}};
                            end
                        end
                        wire signed [OW+TH-1:0] gsum =
                            ($signed(rw[0 +: OW+TH]) + $signed(rw[OW+TH +: OW+TH])) +
                            ($signed(rw[2*(OW+TH) +: OW+TH]) + $signed(rw[3*(OW+TH) +: OW+TH]));
                        wire signed [PW-1:0] ge = gsum;
                        assign term[PW*(XN*YN+i) +: PW] = ge <<< SH;
                    end
                    assign acc[PW*NT +: PW] = {PW{1'b0}};   // unused: REG >= 1 sums the terms as a tree
                end
            end else begin : g_nolut
                assign term[PW*(NT-1) +: PW] = {PW{1'b0}};
                assign acc[PW*NT +: PW] = acc[PW*(NT-1) +: PW];
            end
            if (REG == 0) begin : g_comb
                assign p = acc[PW*NT +: PW];
            end else begin : g_reg
                // Registered terms, padded with zeros to NG groups of four.
                localparam NG = (NT + 3) / 4;
                reg  [PW*NT-1:0] tr;
                always @(posedge clk) tr <= term;
                wire [PW*4*NG-1:0] tp;
                if (4 * NG > NT) begin : g_pad
                    assign tp = {{(PW*(4*NG-NT)){1'b0}}, tr};
                end else begin : g_nopad
                    assign tp = tr;
                end
                // Group sums (t0 + t1) + (t2 + t3), registered with REG >= 2.
                wire [PW*NG-1:0] gs;
                reg  [PW*NG-1:0] gr;
                for (i = 0; i < NG; i = i + 1) begin : g_grp
                    wire [PW-1:0] t0 = tp[PW*(4*i) +: PW], t1 = tp[PW*(4*i+1) +: PW];
                    wire [PW-1:0] t2 = tp[PW*(4*i+2) +: PW], t3 = tp[PW*(4*i+3) +: PW];
                    assign gs[PW*i +: PW] = (t0 + t1) + (t2 + t3);
                end
                if (REG >= 2) begin : g_reg2
                    always @(posedge clk) gr <= gs;
                end else begin : g_reg1
                    always @(*) gr = gs;
                end
                // Sum of the groups, a tree again: two levels for up to 4 groups (16 terms), three
                // for up to 8 (32 terms; the bounds unit's 59 × 82 product with its LUT rows).
                localparam NG4 = NG <= 4 ? 4 : 8;
                wire [PW*NG4-1:0] gp;
                if (NG < NG4) begin : g_gpad
                    assign gp = {{(PW*(NG4-NG)){1'b0}}, gr};
                end else begin : g_gnopad
                    assign gp = gr;
                end
                wire [PW-1:0] lo4 = (gp[0 +: PW] + gp[PW +: PW]) + (gp[2*PW +: PW] + gp[3*PW +: PW]);
                if (NG4 == 4) begin : g_sum4
                    assign p = lo4;
                end else begin : g_sum8
                    assign p = lo4 + ((gp[4*PW +: PW] + gp[5*PW +: PW]) +
                                      (gp[6*PW +: PW] + gp[7*PW +: PW]));
                end
                if (NG > 8) begin : g_too_many
                    uvt_mul_REG_supports_at_most_32_terms error ();   // elaboration error
                end
            end
        end else begin : g_r3
            // REG = 3. Terms: the hard pieces (term i·YN + j, shift i·(PA−1) + j·(PB−1)), then
            // the LUT chunk's rows (term NH + q, shift SH + q); every term's bits below its
            // shift are zero. Each reaches t3 three clocks after the inputs.
            localparam NH = XN * YN;
            localparam N3 = NH + LH;
            localparam LV = clog2(N3);         // adder-tree levels, one clock each
            localparam SH = LX ? XK * (PA - 1) : YK * (PB - 1);
            if (LAT < 3 + LV) begin : g_lat_too_small
                uvt_mul_LAT_below_3_plus_tree_levels error ();   // elaboration error
            end
            if (MAP > 1 || (MAP == 1 && (PA != 18 || PB != 18))) begin : g_bad_map
                uvt_mul_MAP_1_needs_18x18_ports error ();        // elaboration error
            end
            wire [PW*N3-1:0] t3;
            for (i = 0; i < XN; i = i + 1) begin : g_x
                wire signed [PA-1:0] xp;
                if (i < XK) begin : g_lo
                    assign xp = $signed({1'b0, x[i*(PA-1) +: PA-1]});
                end else begin : g_hi
                    wire signed [XH-1:0] xt = x[XW-1 -: XH];
                    assign xp = xt;
                end
                for (j = 0; j < YN; j = j + 1) begin : g_y
                    wire signed [PB-1:0] yp;
                    if (j < YK) begin : g_lo
                        assign yp = $signed({1'b0, y[j*(PB-1) +: PB-1]});
                    end else begin : g_hi
                        wire signed [YH-1:0] yt = y[YW-1 -: YH];
                        assign yp = yt;
                    end
                    wire signed [PA+PB-1:0] pr;   // xp · yp, three clocks later
                    if (MAP == 1) begin : g_prim
                        uvt_mult18 m (.clk(clk), .a(xp), .b(yp), .p(pr));
                    end else begin : g_beh
                        reg signed [PA-1:0] ar;
                        reg signed [PB-1:0] br;
                        reg signed [PA+PB-1:0] p1, p2;
                        always @(posedge clk) begin
                            ar <= xp;              // input registers
                            br <= yp;
                            p1 <= ar * br;         // pipeline register: one multiplier
                            p2 <= p1;              // output register
                        end
                        assign pr = p2;
                    end
                    wire signed [PW-1:0] pe = pr;
                    assign t3[PW*(i*YN+j) +: PW] = pe <<< (i*(PA-1) + j*(PB-1));
                end
            end
            if (LH > 0) begin : g_rows
                // Row q: t[q]·o·2^(SH+q), the top row negated (t is the signed top chunk). The
                // inputs registered (clock 1), each row formed and registered (clock 2: the top
                // row's negation, an OW+1-bit carry chain; |o| <= 2^(OW−1), so −o fits), then
                // registered again (clock 3).
                localparam OW = LX ? YW : XW;
                wire signed [LH-1:0] t;
                wire signed [OW-1:0] o;
                if (LX) begin : g_lx
                    assign t = x[XW-1 -: XH];
                    assign o = y;
                end else begin : g_ly
                    assign t = y[YW-1 -: YH];
                    assign o = x;
                end
                reg [LH-1:0] tr;
                reg signed [OW-1:0] orr;
                always @(posedge clk) begin
                    tr <= t;
                    orr <= o;
                end
                for (j = 0; j < LH; j = j + 1) begin : g_row
                    wire signed [OW-1:0] pm0 = {OW{tr[j]}} & orr;
                    wire signed [OW:0] pm = pm0;              // sign-extended
                    wire signed [OW:0] pv = (j == LH - 1) ? -pm : pm;
                    wire signed [PW-1:0] pe = pv;
                    reg [PW-1:0] r1, r2;
                    always @(posedge clk) begin
                        r1 <= pe <<< (SH + j);
                        r2 <= r1;
                    end
                    assign t3[PW*(NH+j) +: PW] = r2;
                end
            end
            // The tree: level k holds cnt(N3, k) nodes at lv[N3·k + m]; node m of level k
            // is the sum of nodes 2m and 2m+1 of level k−1 (or node 2m alone, registered). Its
            // bits below zb = the larger of the two nodes' zero counts come from one node only.
            wire [PW-1:0] lv [0:N3*(LV+1)-1];
            for (m = 0; m < N3; m = m + 1) begin : g_leaf
                assign lv[m] = t3[PW*m +: PW];
            end
            for (k = 1; k <= LV; k = k + 1) begin : g_lv
                for (m = 0; m < N3; m = m + 1) begin : g_n
                    if (m >= cnt(N3, k)) begin : g_off
                        assign lv[N3*k+m] = {PW{1'b0}};
                    end else begin : g_on
                        wire [PW-1:0] ua = lv[N3*(k-1)+2*m];
                        reg  [PW-1:0] s;
                        if (2 * m + 1 >= cnt(N3, k - 1)) begin : g_pass
                            always @(posedge clk) s <= ua;
                        end else begin : g_add
                            localparam ZA = zlow(N3, NH, YN, PA, PB, SH, k - 1, 2 * m);
                            localparam ZB = zlow(N3, NH, YN, PA, PB, SH, k - 1, 2 * m + 1);
                            localparam ZB2 = ZA > ZB ? ZA : ZB;
                            localparam Z = ZB2 < PW ? ZB2 : PW - 1;
                            wire [PW-1:0] ub = lv[N3*(k-1)+2*m+1];
                            if (Z == 0) begin : g_full
                                always @(posedge clk) s <= ua + ub;
                            end else begin : g_part
                                always @(posedge clk)
                                    s <= {ua[PW-1:Z] + ub[PW-1:Z], ua[Z-1:0] | ub[Z-1:0]};
                            end
                        end
                        assign lv[N3*k+m] = s;
                    end
                end
            end
            uvt_dly #(.W(PW), .N(LAT - 3 - LV)) dl_p (clk, lv[N3*LV], p);
        end
    endgenerate
endmodule


// uvt_dly — N clocks of delay of a W-bit value (N = 0: the value itself; clk unused): the
// registers beside a pipelined product (uvt_bsample.v, uvt_psample.v with PIPE = 1).
module uvt_dly #(
    parameter W = 1,
    parameter N = 0
) (
    input  wire         clk,
    input  wire [W-1:0] d,
    output wire [W-1:0] q
);
    generate
        if (N == 0) begin : g_wire
            assign q = d;
        end else if (N == 1) begin : g_one
            reg [W-1:0] r;
            always @(posedge clk) r <= d;
            assign q = r;
        end else begin : g_many
            reg [W*N-1:0] r;
            always @(posedge clk) r <= {r[W*(N-1)-1:0], d};
            assign q = r[W*N-1 -: W];
        end
    endgenerate
endmodule
