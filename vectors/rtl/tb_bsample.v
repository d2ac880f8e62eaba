// Testbench of uvt_bsample: streams bsample_in.hex records into the unit, one per clock, and
// compares every output field with bsample_out.hex. Plusargs:
//   +IN=<bsample_in.hex> +OUT=<bsample_out.hex> +N=<records>
//   +STRIDE=<k>  test records 0, k, 2k, … (default 1: every record)
//   +STOP=1      end at the first mismatching field: "STOP record <r> field <name>", exit 1
// Parameters (iverilog -P tb_bsample.OFF=24 …) set the unit's configuration; a record of
// another configuration is a failure (its off_shift / pos_frac / tuv_frac fields name it).
// MOTION, DEFOCUS select the unit variant: a record whose class (word 31 bits 1..0; bit 0
// motion, bit 1 defocus) the unit lacks is skipped and counted, not fed to the unit.
// Prints "PASS <n> records" (a narrow unit that skipped m > 0 records: "PASS <n> records,
// <m> skipped (class not in the unit)") or "FAIL <errors> mismatching fields in <n> records"
// (", <m> skipped …" likewise); each of the first 10 mismatches
// as "MISMATCH record <r> (line <r+1>) field <name>: expected <hex> observed <hex>" followed by
// the record's input words in hex. A FAIL ends with `$fatal`: vvp exits 1 (0 on PASS).
// Your own unit (docs/rtl.md "Wiring your own unit"): `-DUVT_DUT=my_unit` instantiates my_unit
// instead of uvt_bsample; `-DUVT_ARCH_ONLY` connects and checks only the architectural ports
// (their one table, with widths, and the command: docs/rtl.md "Wiring your own unit") and
// passes the unit no parameter. Any latency works: outputs are matched in issue order by
// out_valid (+DRAIN=<clocks> waits that long for the last results, default 200). Before the
// verdict: "LATENCY edge <a> depth <b> clocks", the first sample's (−1: no such result).
`ifndef UVT_DUT
`define UVT_DUT uvt_bsample
`endif
`timescale 1ns / 1ps
module tb_bsample;
    parameter POS = 16;
    parameter TUV = 16;
    parameter OFF = 20;
    parameter DSP_A = 25;              // the unit's multiplier tiling (uvt_mul.v)
    parameter DSP_B = 18;
    parameter LUTW = 8;
    parameter MOTION = 1;              // the unit variant (uvt_bsample.v)
    parameter DEFOCUS = 1;
    parameter PIPE = 0;                // the unit's pipelining (uvt_bsample.v; latency only)
    parameter MAP = 0;                 // PIPE = 2: MULT18X18D instances (needs their model)
    parameter LUTWE = -1;              // PIPE = 2: LUT chunk limit of a'·b' and E'·w
    parameter KARA = 0;                // PIPE = 2: a'·b' on three hard multipliers (Karatsuba)
    localparam NT = MOTION ? 30 : 15;  // trin words: key frame 1 only with MOTION
    localparam WI = 37, WO = 14, MAXREC = 16384;
    reg [31:0] in_mem  [0:MAXREC*WI-1];
    reg [31:0] out_mem [0:MAXREC*WO-1];
    reg [8*1024-1:0] in_file, out_file;
    integer n, stride, drain, issued, got_e, got_d, errors, tested, skipped, r, w, k, j, ro, wo, ko;
    integer order [0:MAXREC-1];

    reg clk = 0, in_valid = 0;
    reg [32*NT-1:0] trin = 0;
    reg [11:0] vp_w = 1, vp_h = 1;
    reg [19:0] xs = 0, ys = 0;
    reg signed [31:0] t = 0, u = 0, v = 0;
    wire edge_valid, covered, out_valid, out_covered;
    wire [191:0] ab, e;
    wire signed [1:0] det_sign;
    wire signed [31:0] depth;

`ifdef UVT_ARCH_ONLY
    `UVT_DUT dut (
        .clk(clk), .in_valid(in_valid), .trin(trin), .vp_w(vp_w), .vp_h(vp_h), .xs(xs), .ys(ys),
        .t(t), .u(u), .v(v), .out_valid(out_valid), .out_covered(out_covered), .depth(depth)
    );
    assign edge_valid = 1'b0;          // the internal edge values are not checked
    assign {ab, e, det_sign, covered} = 0;
`else
    `UVT_DUT #(.POS(POS), .TUV(TUV), .OFF(OFF), .DSP_A(DSP_A), .DSP_B(DSP_B),
               .MOTION(MOTION), .DEFOCUS(DEFOCUS), .PIPE(PIPE), .LUTW(LUTW), .MAP(MAP),
               .LUTWE(LUTWE), .KARA(KARA)) dut (
        .clk(clk), .in_valid(in_valid), .trin(trin), .vp_w(vp_w), .vp_h(vp_h), .xs(xs), .ys(ys),
        .t(t), .u(u), .v(v), .edge_valid(edge_valid), .ab(ab), .e(e), .det_sign(det_sign),
        .covered(covered), .out_valid(out_valid), .out_covered(out_covered), .depth(depth)
    );
`endif

    always #5 clk = ~clk;

    task show_inputs(input integer rec);
        begin
            $write("  inputs (bsample_in words 0..36):");
            for (j = 0; j < WI; j = j + 1) $write(" %h", in_mem[rec*WI+j]);
            $write("\n");
        end
    endtask

    integer stop_first = 0;          // +STOP=1: end at the first mismatching field

    task check(input integer rec, input [8*8-1:0] name, input [63:0] exp, input [63:0] obs);
        begin
            if (exp !== obs) begin
                errors = errors + 1;
                if (errors <= 10) begin
                    $display("MISMATCH record %0d (line %0d) field %0s: expected %h observed %h",
                             rec, rec + 1, name, exp, obs);
                    show_inputs(rec);
                end
                if (stop_first == 1) begin
                    $display("STOP record %0d field %0s", rec, name);
                    $fatal(1, "%m: the first mismatch (+STOP=1)");
                end
            end
        end
    endtask

    // Outputs: compared on the falling edge, in issue order.
    // Latency: clocks from the first sample's in_valid to its first edge / depth result.
    integer clocks = 0, t_in = -1, lat_e = -1, lat_d = -1;
    always @(posedge clk) begin
        if (in_valid === 1'b1 && t_in < 0) t_in = clocks;
        if (edge_valid === 1'b1 && lat_e < 0 && t_in >= 0) lat_e = clocks - t_in;
        if (out_valid === 1'b1 && lat_d < 0 && t_in >= 0) lat_d = clocks - t_in;
        clocks = clocks + 1;
    end

    always @(negedge clk) begin
        if (edge_valid === 1'b1) begin
            ro = order[got_e];
            wo = ro * WO;
            check(ro, "covered", out_mem[wo][0], covered);
            check(ro, "det_sign", {{62{out_mem[wo][2]}}, out_mem[wo][2:1]}, {{62{det_sign[1]}}, det_sign});
            for (ko = 0; ko < 3; ko = ko + 1) begin
                check(ro, ko == 0 ? "a0" : ko == 1 ? "a1" : "a2", out_mem[wo+2+2*ko], ab[64*ko +: 32]);
                check(ro, ko == 0 ? "b0" : ko == 1 ? "b1" : "b2", out_mem[wo+3+2*ko], ab[64*ko+32 +: 32]);
                check(ro, ko == 0 ? "e0" : ko == 1 ? "e1" : "e2",
                      {out_mem[wo+8+2*ko], out_mem[wo+9+2*ko]}, e[64*ko +: 64]);
            end
            got_e = got_e + 1;
        end
        if (out_valid === 1'b1) begin
            ro = order[got_d];
            wo = ro * WO;
            check(ro, "covered", out_mem[wo][0], out_covered);
            check(ro, "depth", out_mem[wo+1], depth[31:0]);
            got_d = got_d + 1;
        end
    end

    initial begin
        if (!$value$plusargs("IN=%s", in_file) || !$value$plusargs("OUT=%s", out_file) ||
            !$value$plusargs("N=%d", n)) begin
            $display("FAIL usage: +IN=bsample_in.hex +OUT=bsample_out.hex +N=records [+STRIDE=k]");
            $fatal(1, "tb_bsample: see the FAIL line above");
        end
        if (!$value$plusargs("STRIDE=%d", stride) || stride < 1) stride = 1;
        if (!$value$plusargs("DRAIN=%d", drain) || drain < 1) drain = 200;
        if (!$value$plusargs("STOP=%d", stop_first)) stop_first = 0;
        if (n > MAXREC) begin
            $display("FAIL %0d records exceed MAXREC %0d", n, MAXREC);
            $fatal(1, "tb_bsample: see the FAIL line above");
        end
        $readmemh(in_file, in_mem, 0, n * WI - 1);
        $readmemh(out_file, out_mem, 0, n * WO - 1);
        errors = 0; issued = 0; got_e = 0; got_d = 0; tested = 0; skipped = 0;
        // Flush the unit's pipeline (unknown valid bits after power-up; PIPE = 1 has 63 stages).
        repeat (80) @(negedge clk);
        for (r = 0; r < n; r = r + stride) begin
            w = r * WI;
            if (in_mem[w+31][7:2] != OFF || in_mem[w+31][12:8] != POS || in_mem[w+31][17:13] != TUV) begin
                errors = errors + 1;
                if (errors <= 10)
                    $display("MISMATCH record %0d (line %0d): configuration off_shift %0d pos_frac %0d tuv_frac %0d, the unit is OFF %0d POS %0d TUV %0d",
                             r, r + 1, in_mem[w+31][7:2], in_mem[w+31][12:8], in_mem[w+31][17:13], OFF, POS, TUV);
            end else if ((in_mem[w+31][0] && !MOTION) || (in_mem[w+31][1] && !DEFOCUS)) begin
                skipped = skipped + 1;
            end else begin
                for (k = 0; k < NT; k = k + 1) trin[32*k +: 32] = in_mem[w+k];
                vp_w = in_mem[w+30][11:0];
                vp_h = in_mem[w+30][27:16];
                xs = in_mem[w+32][19:0];
                ys = in_mem[w+33][19:0];
                t = in_mem[w+34];
                u = in_mem[w+35];
                v = in_mem[w+36];
                in_valid = 1;
                order[issued] = r;
                issued = issued + 1;
                tested = tested + 1;
                @(negedge clk);
            end
        end
        in_valid = 0;
        repeat (drain) @(negedge clk);
`ifdef UVT_ARCH_ONLY
        got_e = got_d;                 // no edge results in architectural mode
`endif
        if (got_e != issued || got_d != issued) begin
            errors = errors + 1;
            $display("MISMATCH %0d records issued, %0d edge and %0d depth results came out",
                     issued, got_e, got_d);
        end
        $display("LATENCY edge %0d depth %0d clocks", lat_e, lat_d);
        if (errors == 0) $write("PASS %0d records", tested);
        else $write("FAIL %0d mismatching fields in %0d records", errors, tested);
`ifdef UVT_ARCH_ONLY
        $write(" (architectural: covered, depth)");
`endif
        if (skipped > 0) $write(", %0d skipped (class not in the unit)", skipped);
        $write("\n");
        // A failing bench ends with a non-zero exit status of vvp, a passing one with 0.
        if (errors != 0) $fatal(1, "tb_bsample: %0d mismatching fields", errors);
        $finish;
    end
endmodule
