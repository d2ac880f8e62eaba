// Testbench of uvt_psample: streams psample_in.hex records into the unit, one per clock, and
// compares every output field with psample_out.hex. Plusargs:
//   +IN=<psample_in.hex> +OUT=<psample_out.hex> +N=<records>
//   +STOP=1      end at the first mismatching field: "STOP record <r> field <name>", exit 1
// The unit reads only the setup fields (n, σ, G, f), the viewport and the position of a record;
// the raw vertices (words 0..11) are for the checker (`uvt vectors check`).
// Prints "LATENCY <clocks> clocks" (the first sample's), then "PASS <n> records" or "FAIL <errors>
// mismatching fields in <n> records"; each of the
// first 10 mismatches as "MISMATCH record <r> (line <r+1>) field <name>: expected <hex>
// observed <hex>" followed by the record's input words in hex. A FAIL ends with `$fatal`: vvp
// exits 1 (0 on PASS).
// Your own unit: `-DUVT_DUT=my_unit` instantiates my_unit instead of uvt_psample;
// `-DUVT_ARCH_ONLY` connects and checks only the architectural ports (their one table, with
// widths, and the command: docs/rtl.md "Wiring your own unit"), and passes no parameter. Any latency works (results are
// matched in issue order by out_valid; +DRAIN=<clocks>, default 200, waits for the last).
`ifndef UVT_DUT
`define UVT_DUT uvt_psample
`endif
`timescale 1ns / 1ps
module tb_psample;
    parameter DSP_A = 25;              // the unit's multiplier tiling (uvt_mul.v)
    parameter DSP_B = 18;
    parameter LUTW = 8;
    parameter PIPE = 0;                // the unit's pipelining (uvt_psample.v; latency only)
    parameter MAP = 0;                 // PIPE = 2: hard pieces as ECP5 MULT18X18D (uvt_mul.v)
    localparam WI = 28, WO = 8, MAXREC = 16384, LAT = 24;  // at least the unit's (PIPE = 2: 16-19)
    reg [31:0] in_mem  [0:MAXREC*WI-1];
    reg [31:0] out_mem [0:MAXREC*WO-1];
    reg [8*1024-1:0] in_file, out_file;
    integer n, drain, issued, got, errors, r, w, k, j, ro, wo, ko;

    reg clk = 0, in_valid = 0;
    reg [287:0] nn = 0;
    reg signed [1:0] sigma = 1;
    reg signed [7:0] f = 0;
    reg [95:0] g = 0;
    reg [11:0] vp_w = 1, vp_h = 1;
    reg [19:0] xs = 0, ys = 0;
    wire out_valid, covered;
    wire signed [31:0] depth;
    wire [191:0] e;

`ifdef UVT_ARCH_ONLY
    `UVT_DUT dut (
        .clk(clk), .in_valid(in_valid), .n(nn), .sigma(sigma), .f(f), .g(g), .vp_w(vp_w),
        .vp_h(vp_h), .xs(xs), .ys(ys), .out_valid(out_valid), .covered(covered), .depth(depth)
    );
    assign e = 0;                      // the internal edge values are not checked
`else
    `UVT_DUT #(.DSP_A(DSP_A), .DSP_B(DSP_B), .LUTW(LUTW), .PIPE(PIPE), .MAP(MAP)) dut (
        .clk(clk), .in_valid(in_valid), .n(nn), .sigma(sigma), .f(f), .g(g), .vp_w(vp_w),
        .vp_h(vp_h), .xs(xs), .ys(ys), .out_valid(out_valid), .covered(covered),
        .depth(depth), .e(e)
    );
`endif

    always #5 clk = ~clk;

    // Latency: clocks from the first sample's in_valid to its result.
    integer clocks = 0, t_in = -1, lat = -1;
    always @(posedge clk) begin
        if (in_valid === 1'b1 && t_in < 0) t_in = clocks;
        if (out_valid === 1'b1 && lat < 0 && t_in >= 0) lat = clocks - t_in;
        clocks = clocks + 1;
    end

    task show_inputs(input integer rec);
        begin
            $write("  inputs (psample_in words 0..27):");
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

    // Outputs: compared on the falling edge, in issue order (records are issued in file order).
    always @(negedge clk) begin
        if (out_valid === 1'b1) begin
            ro = got;
            wo = ro * WO;
            check(ro, "covered", out_mem[wo][0], covered);
            check(ro, "depth", out_mem[wo+1], depth[31:0]);
`ifndef UVT_ARCH_ONLY
            for (ko = 0; ko < 3; ko = ko + 1)
                check(ro, ko == 0 ? "e0" : ko == 1 ? "e1" : "e2",
                      {out_mem[wo+2+2*ko], out_mem[wo+3+2*ko]}, e[64*ko +: 64]);
`endif
            got = got + 1;
        end
    end

    initial begin
        if (!$value$plusargs("IN=%s", in_file) || !$value$plusargs("OUT=%s", out_file) ||
            !$value$plusargs("N=%d", n)) begin
            $display("FAIL usage: +IN=psample_in.hex +OUT=psample_out.hex +N=records");
            $fatal(1, "tb_psample: see the FAIL line above");
        end
        if (!$value$plusargs("DRAIN=%d", drain) || drain < 1) drain = 200;
        if (!$value$plusargs("STOP=%d", stop_first)) stop_first = 0;
        if (n > MAXREC) begin
            $display("FAIL %0d records exceed MAXREC %0d", n, MAXREC);
            $fatal(1, "tb_psample: see the FAIL line above");
        end
        if (n > 0) begin
            $readmemh(in_file, in_mem, 0, n * WI - 1);
            $readmemh(out_file, out_mem, 0, n * WO - 1);
        end
        errors = 0; issued = 0; got = 0;
        // Flush the unit's pipeline (unknown valid bits after power-up).
        repeat (2 * LAT) @(negedge clk);
        for (r = 0; r < n; r = r + 1) begin
            w = r * WI;
            vp_w = in_mem[w+12][11:0];
            vp_h = in_mem[w+12][27:16];
            for (k = 0; k < 9; k = k + 1) nn[32*k +: 32] = in_mem[w+13+k];
            sigma = in_mem[w+22][1:0];
            f = in_mem[w+22][9:2];
            for (k = 0; k < 3; k = k + 1) g[32*k +: 32] = in_mem[w+23+k];
            xs = in_mem[w+26][19:0];
            ys = in_mem[w+27][19:0];
            in_valid = 1;
            issued = issued + 1;
            @(negedge clk);
        end
        in_valid = 0;
        repeat (drain) @(negedge clk);
        if (got != issued) begin
            errors = errors + 1;
            $display("MISMATCH %0d records issued, %0d results came out", issued, got);
        end
        $display("LATENCY %0d clocks", lat);
        if (errors == 0) $write("PASS %0d records", issued);
        else $write("FAIL %0d mismatching fields in %0d records", errors, issued);
`ifdef UVT_ARCH_ONLY
        $write(" (architectural: covered, depth)");
`endif
        $write("\n");
        // A failing bench ends with a non-zero exit status of vvp, a passing one with 0.
        if (errors != 0) $fatal(1, "tb_psample: %0d mismatching fields", errors);
        $finish;
    end
endmodule
