// MULT18X18D — a simulation model of the Lattice ECP5 sysDSP 18 × 18 multiplier, for the
// benches of the units' MAP = 1 builds (uvt_mult18.v). Yosys 0.23 (and 0.70) ship only a black
// box of the primitive (share/ecp5/cells_bb.v), so this model is uvt's own, written from the
// ECP5 sysDSP usage guide (FPGA-TN-02205, the MULT18X18D's register stages) and the port and
// parameter list of Yosys's black box. It models the subset uvt uses and stops the simulation
// (`$fatal`) on any other setting, so it cannot silently mis-model a mode it does not implement:
// - P = A · B (36 bits), A signed when SIGNEDA is high, B when SIGNEDB is (each sign control
//   travels with its operand through the input register);
// - the input registers of A and B, the pipeline register and the output register, each on
//   CLK0 ("CLK0") or absent ("NONE"), enabled by CE0 and reset synchronously by RST0;
// - SOURCEA = SOURCEB = 0 (parallel inputs), MULT_BYPASS "DISABLED", HIGHSPEED_CLK "NONE".
// The C input, the shift chains (SRO*) and the cascade outputs (RO*) are not modelled: the outputs
// are X, so a design that used them would fail its bench. The inputs CLK1-3, CE1-3, RST1-3 and
// the shift inputs SRIA/SRIB are left out of the port list (uvt_mult18.v leaves them unconnected,
// as Yosys's mapping does: nextpnr cannot route a constant to the shift inputs); an instance
// that connects them does not elaborate with this model. SIGNEDP = SIGNEDA | SIGNEDB
// of the product. GSR and the *_DIV clock dividers have no effect in this model.
`timescale 1ns / 1ps
module MULT18X18D (
    input A0, A1, A2, A3, A4, A5, A6, A7, A8, A9, A10, A11, A12, A13, A14, A15, A16, A17,
    input B0, B1, B2, B3, B4, B5, B6, B7, B8, B9, B10, B11, B12, B13, B14, B15, B16, B17,
    input C0, C1, C2, C3, C4, C5, C6, C7, C8, C9, C10, C11, C12, C13, C14, C15, C16, C17,
    input SIGNEDA, SIGNEDB, SOURCEA, SOURCEB,
    input CLK0, CE0, RST0,
    output SROA0, SROA1, SROA2, SROA3, SROA4, SROA5, SROA6, SROA7, SROA8, SROA9, SROA10, SROA11,
    SROA12, SROA13, SROA14, SROA15, SROA16, SROA17,
    output SROB0, SROB1, SROB2, SROB3, SROB4, SROB5, SROB6, SROB7, SROB8, SROB9, SROB10, SROB11,
    SROB12, SROB13, SROB14, SROB15, SROB16, SROB17,
    output ROA0, ROA1, ROA2, ROA3, ROA4, ROA5, ROA6, ROA7, ROA8, ROA9, ROA10, ROA11, ROA12,
    ROA13, ROA14, ROA15, ROA16, ROA17,
    output ROB0, ROB1, ROB2, ROB3, ROB4, ROB5, ROB6, ROB7, ROB8, ROB9, ROB10, ROB11, ROB12,
    ROB13, ROB14, ROB15, ROB16, ROB17,
    output ROC0, ROC1, ROC2, ROC3, ROC4, ROC5, ROC6, ROC7, ROC8, ROC9, ROC10, ROC11, ROC12,
    ROC13, ROC14, ROC15, ROC16, ROC17,
    output P0, P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, P12, P13, P14, P15, P16, P17, P18,
    P19, P20, P21, P22, P23, P24, P25, P26, P27, P28, P29, P30, P31, P32, P33, P34, P35,
    output SIGNEDP
);
    parameter REG_INPUTA_CLK = "NONE";
    parameter REG_INPUTA_CE = "CE0";
    parameter REG_INPUTA_RST = "RST0";
    parameter REG_INPUTB_CLK = "NONE";
    parameter REG_INPUTB_CE = "CE0";
    parameter REG_INPUTB_RST = "RST0";
    parameter REG_INPUTC_CLK = "NONE";
    parameter REG_INPUTC_CE = "CE0";
    parameter REG_INPUTC_RST = "RST0";
    parameter REG_PIPELINE_CLK = "NONE";
    parameter REG_PIPELINE_CE = "CE0";
    parameter REG_PIPELINE_RST = "RST0";
    parameter REG_OUTPUT_CLK = "NONE";
    parameter REG_OUTPUT_CE = "CE0";
    parameter REG_OUTPUT_RST = "RST0";
    parameter CLK0_DIV = "ENABLED";
    parameter CLK1_DIV = "ENABLED";
    parameter CLK2_DIV = "ENABLED";
    parameter CLK3_DIV = "ENABLED";
    parameter HIGHSPEED_CLK = "NONE";
    parameter GSR = "ENABLED";
    parameter CAS_MATCH_REG = "FALSE";
    parameter SOURCEB_MODE = "B_SHIFT";
    parameter MULT_BYPASS = "DISABLED";
    parameter RESETMODE = "SYNC";

    // One register stage's setting: 1 registered on CLK0, 0 absent; anything else stops the run.
    function integer on(input [8*8-1:0] clk_, input [8*8-1:0] ce, input [8*8-1:0] rst);
        begin
            on = -1;
            if (ce == "CE0" && rst == "RST0") begin
                if (clk_ == "CLK0") on = 1;
                else if (clk_ == "NONE") on = 0;
            end
        end
    endfunction
    localparam RA = on(REG_INPUTA_CLK, REG_INPUTA_CE, REG_INPUTA_RST);
    localparam RB = on(REG_INPUTB_CLK, REG_INPUTB_CE, REG_INPUTB_RST);
    localparam RP = on(REG_PIPELINE_CLK, REG_PIPELINE_CE, REG_PIPELINE_RST);
    localparam RO = on(REG_OUTPUT_CLK, REG_OUTPUT_CE, REG_OUTPUT_RST);
    initial begin
        if (RA < 0 || RB < 0 || RP < 0 || RO < 0)
            $fatal(1, "MULT18X18D model: a register stage other than NONE or CLK0/CE0/RST0 (%m)");
        if (MULT_BYPASS != "DISABLED" || HIGHSPEED_CLK != "NONE" || RESETMODE != "SYNC")
            $fatal(1, "MULT18X18D model: MULT_BYPASS, HIGHSPEED_CLK or RESETMODE not modelled (%m)");
    end
    always @(SOURCEA or SOURCEB)
        if (SOURCEA !== 1'b0 || SOURCEB !== 1'b0)
            $fatal(1, "MULT18X18D model: SOURCEA/SOURCEB must be 0 (the shift inputs are not modelled, %m)");

    wire [17:0] a = {A17, A16, A15, A14, A13, A12, A11, A10, A9, A8, A7, A6, A5, A4, A3, A2, A1,
        A0};
    wire [17:0] b = {B17, B16, B15, B14, B13, B12, B11, B10, B9, B8, B7, B6, B5, B4, B3, B2, B1,
        B0};
    // Input stage: operand and its sign control.
    reg  [18:0] ar, br;
    always @(posedge CLK0)
        if (RST0) begin
            ar <= 19'd0;
            br <= 19'd0;
        end else if (CE0) begin
            ar <= {SIGNEDA, a};
            br <= {SIGNEDB, b};
        end
    wire [18:0] ai = RA ? ar : {SIGNEDA, a};
    wire [18:0] bi = RB ? br : {SIGNEDB, b};
    // Each operand extended by its sign control to 19 bits signed; the product's low 36 bits
    // (every product of two 18-bit operands, signed or unsigned, fits in 36 bits).
    wire signed [18:0] as = {ai[18] & ai[17], ai[17:0]};
    wire signed [18:0] bs = {bi[18] & bi[17], bi[17:0]};
    wire signed [37:0] full = as * bs;
    wire [36:0] m = {ai[18] | bi[18], full[35:0]};   // SIGNEDP, P
    // Pipeline and output stages.
    reg  [36:0] pr, orr;
    always @(posedge CLK0)
        if (RST0) begin
            pr <= 37'd0;
            orr <= 37'd0;
        end else if (CE0) begin
            pr <= m;
            orr <= RP ? pr : m;
        end
    wire [36:0] q = RO ? orr : (RP ? pr : m);
    assign {SIGNEDP, P35, P34, P33, P32, P31, P30, P29, P28, P27, P26, P25, P24, P23, P22, P21,
        P20, P19, P18, P17, P16, P15, P14, P13, P12, P11, P10, P9, P8, P7, P6, P5, P4, P3, P2, P1,
        P0} = q;
    assign {SROA17, SROA16, SROA15, SROA14, SROA13, SROA12, SROA11, SROA10, SROA9, SROA8, SROA7,
        SROA6, SROA5, SROA4, SROA3, SROA2, SROA1, SROA0} = 18'bx;
    assign {SROB17, SROB16, SROB15, SROB14, SROB13, SROB12, SROB11, SROB10, SROB9, SROB8, SROB7,
        SROB6, SROB5, SROB4, SROB3, SROB2, SROB1, SROB0} = 18'bx;
    assign {ROA17, ROA16, ROA15, ROA14, ROA13, ROA12, ROA11, ROA10, ROA9, ROA8, ROA7, ROA6,
        ROA5, ROA4, ROA3, ROA2, ROA1, ROA0} = 18'bx;
    assign {ROB17, ROB16, ROB15, ROB14, ROB13, ROB12, ROB11, ROB10, ROB9, ROB8, ROB7, ROB6,
        ROB5, ROB4, ROB3, ROB2, ROB1, ROB0} = 18'bx;
    assign {ROC17, ROC16, ROC15, ROC14, ROC13, ROC12, ROC11, ROC10, ROC9, ROC8, ROC7, ROC6,
        ROC5, ROC4, ROC3, ROC2, ROC1, ROC0} = 18'bx;
endmodule
