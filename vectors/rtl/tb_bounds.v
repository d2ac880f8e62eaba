// Testbench of uvt_bounds: streams the tiles of bounds_in.hex into the unit, one per clock with
// random bubbles, with each tile's triangle
// coefficients taken from its setup_out.hex record, and compares every field of every result
// with bounds_out.hex. Plusargs:
//   +SET=<dir>     the vector set (setup_out.hex, bounds_in.hex, bounds_out.hex; counted here)
//   +SEED=<n>      the bubble pattern's seed (default 1); +BUBBLES=<percent> (default 25)
//   +DRAIN=<k>     clocks to wait for the last results (default 200)
//   +STOP=1      end at the first mismatching field: "STOP record <r> field <name>", exit 1
//   +JUNK=1        unknowns (x) on every data port during bubbles (slower: ~5x under Icarus)
// Parameters (iverilog -P tb_bounds.X=…): BND, TUV, DSP_A, DSP_B, PIPE, MAP the unit's
// (uvt_bounds.v; MAP = 1 needs uvt_mult18.v and the primitive's model ecp5/MULT18X18D.v);
// SW, LENS_AT, DUAL_AT the setup_out format: words per record and first word of the lens and
// dual coefficient blocks (format version 4, the default: 108, 24, 72; version 3, without
// eps_x, eps_y, eps_w at words 21..23: 105, 21, 69). A setup_out.hex whose lines are not SW
// words is refused.
// Prints "PASS <n> records (<k> nonempty)" or "FAIL <errors> mismatching fields in <n> records";
// each of the first 10 mismatches as "MISMATCH record <r> (line <r+1>) field <name>: expected
// <hex> (<decimal>) observed <hex> (<decimal>)" followed by the record's inputs. A FAIL ends
// with `$fatal`: vvp exits 1 (0 on PASS).
// Your own unit: `-DUVT_DUT=my_unit` instantiates my_unit (no parameters passed) with the ports
// of uvt_bounds.v; results are matched in issue order by out_valid, so any latency works.
`ifndef UVT_DUT
`define UVT_DUT uvt_bounds
`define UVT_DUT_IS_REFERENCE
`endif
`timescale 1ns / 1ps
module tb_bounds;
    parameter BND = 16;
    parameter TUV = 16;
    parameter DSP_A = 25;
    parameter DSP_B = 18;
    parameter PIPE = 0;
    parameter MAP = 0;
    parameter SW = 108;
    parameter LENS_AT = 24;
    parameter DUAL_AT = 72;
    localparam WI = 3, WO = 7, MAXREC = 16384, MAXSET = 4096;
    reg [31:0] setup_mem [0:MAXSET*SW-1];
    reg [31:0] in_mem  [0:MAXREC*WI-1];
    reg [31:0] out_mem [0:MAXREC*WO-1];
    reg [8*1024-1:0] dir, fname;
    reg [8*4096-1:0] line;
    reg [31:0] word;
    integer n, ns, seed, bubbles, drain, issued, got, errors, nonempties, r, w, s, k, j, ro, fd, c;
    integer lines, words, junk_on;
    integer order [0:MAXREC-1];

    reg clk = 0, in_valid = 0;
    reg [15:0] x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    reg signed [31:0] span_lo = 0, span_hi = 0;
    reg [3:0] lens_on = 0;
    reg [1:0] dual_on = 0;
    reg [4*64-1:0] lens_base = 0, lens_d = 0;
    reg [4*128-1:0] lens_rup = 0, lens_rdn = 0;
    reg [4*32-1:0] dual_xi = 0;
    reg [16*64-1:0] dual_delta = 0;
    wire out_valid, nonempty;
    wire signed [31:0] u_lo, u_hi, v_lo, v_hi, t_lo, t_hi;

`ifdef UVT_DUT_IS_REFERENCE
    `UVT_DUT #(.BND(BND), .TUV(TUV), .DSP_A(DSP_A), .DSP_B(DSP_B), .PIPE(PIPE), .MAP(MAP)) dut (
`else
    `UVT_DUT dut (
`endif
        .clk(clk), .in_valid(in_valid), .x0(x0), .y0(y0), .x1(x1), .y1(y1),
        .span_lo(span_lo), .span_hi(span_hi), .lens_on(lens_on), .lens_base(lens_base),
        .lens_d(lens_d), .lens_rup(lens_rup), .lens_rdn(lens_rdn), .dual_on(dual_on),
        .dual_xi(dual_xi), .dual_delta(dual_delta), .out_valid(out_valid), .nonempty(nonempty),
        .u_lo(u_lo), .u_hi(u_hi), .v_lo(v_lo), .v_hi(v_hi), .t_lo(t_lo), .t_hi(t_hi)
    );

    always #5 clk = ~clk;

    // Count a file's lines and hex words (the sets are one record per line).
    task count_file(input [8*1024-1:0] path);
        begin
            lines = 0;
            words = 0;
            fd = $fopen(path, "r");
            if (fd == 0) begin
                $display("FAIL cannot open %0s", path);
                $fatal(1, "tb_bounds: see the FAIL line above");
            end
            while (!$feof(fd)) begin
                c = $fgets(line, fd);
                if (c > 1) lines = lines + 1;
            end
            $fclose(fd);
            fd = $fopen(path, "r");
            while ($fscanf(fd, "%h", word) == 1) words = words + 1;
            $fclose(fd);
        end
    endtask

    task show_inputs(input integer rec);
        begin
            $display("  inputs: bounds_in %h %h %h (triangle %0d, tile x %0d..%0d, y %0d..%0d)",
                     in_mem[rec*WI], in_mem[rec*WI+1], in_mem[rec*WI+2], in_mem[rec*WI],
                     in_mem[rec*WI+1][15:0], in_mem[rec*WI+2][15:0],
                     in_mem[rec*WI+1][31:16], in_mem[rec*WI+2][31:16]);
            s = in_mem[rec*WI] * SW;
            $display("          setup_out flags %h span %h %h", setup_mem[s], setup_mem[s+3],
                     setup_mem[s+4]);
        end
    endtask

    integer stop_first = 0;          // +STOP=1: end at the first mismatching field

    task check(input integer rec, input [8*8-1:0] name, input [31:0] exp, input [31:0] obs);
        begin
            if (exp !== obs) begin
                errors = errors + 1;
                if (errors <= 10) begin
                    $display("MISMATCH record %0d (line %0d) field %0s: expected %h (%0d) observed %h (%0d)",
                             rec, rec + 1, name, exp, $signed(exp), obs, $signed(obs));
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
    always @(negedge clk) begin
        if (out_valid === 1'b1) begin
            ro = order[got];
            w = ro * WO;
            check(ro, "nonempty", out_mem[w], {31'b0, nonempty});
            check(ro, "u_lo", out_mem[w+1], u_lo);
            check(ro, "u_hi", out_mem[w+2], u_hi);
            check(ro, "v_lo", out_mem[w+3], v_lo);
            check(ro, "v_hi", out_mem[w+4], v_hi);
            check(ro, "t_lo", out_mem[w+5], t_lo);
            check(ro, "t_hi", out_mem[w+6], t_hi);
            got = got + 1;
        end
    end

    // Drive the triangle and tile of record rec (setup_out fields: vectors/README.md).
    task drive(input integer rec);
        reg [31:0] flags;
        begin
            s = in_mem[rec*WI] * SW;
            flags = setup_mem[s];
            x0 = in_mem[rec*WI+1][15:0];
            y0 = in_mem[rec*WI+1][31:16];
            x1 = in_mem[rec*WI+2][15:0];
            y1 = in_mem[rec*WI+2][31:16];
            span_lo = setup_mem[s+3];
            span_hi = setup_mem[s+4];
            // lens side 2a+side exists: box_{a}_{side} (bits 5..8) and lens_{a} (bits 9, 10)
            lens_on = flags[8:5] & {flags[10], flags[10], flags[9], flags[9]};
            dual_on = flags[12:11];
            for (k = 0; k < 4; k = k + 1) begin
                j = s + LENS_AT + 12 * k;       // base i64, d i64, rup i128, rdn i128
                lens_base[64*k +: 64] = {setup_mem[j], setup_mem[j+1]};
                lens_d[64*k +: 64] = {setup_mem[j+2], setup_mem[j+3]};
                lens_rup[128*k +: 128] = {setup_mem[j+4], setup_mem[j+5], setup_mem[j+6], setup_mem[j+7]};
                lens_rdn[128*k +: 128] = {setup_mem[j+8], setup_mem[j+9], setup_mem[j+10], setup_mem[j+11]};
            end
            for (k = 0; k < 2; k = k + 1) begin
                j = s + DUAL_AT + 18 * k;       // ξa, ξb i32, then δ[m][t][e] i64
                dual_xi[64*k +: 64] = {setup_mem[j+1], setup_mem[j]};
                for (c = 0; c < 8; c = c + 1)
                    dual_delta[64*(8*k+c) +: 64] = {setup_mem[j+2+2*c], setup_mem[j+3+2*c]};
            end
        end
    endtask

    // With +JUNK=1 the data ports carry unknowns (x) between tiles: a result that depended on
    // a bubble's inputs would come out unknown and mismatch. (Otherwise they hold the last tile.)
    task junk;
        if (junk_on) begin
            {x0, y0, x1, y1, span_lo, span_hi, lens_on, dual_on} = {134{1'bx}};
            {lens_base, lens_d, lens_rup, lens_rdn, dual_xi, dual_delta} = {2688{1'bx}};
        end
    endtask

    initial begin
        if (!$value$plusargs("SET=%s", dir)) begin
            $display("FAIL usage: +SET=<vector set directory> [+SEED=n] [+BUBBLES=percent] [+DRAIN=clocks] [+JUNK=1]");
            $fatal(1, "tb_bounds: see the FAIL line above");
        end
        if (!$value$plusargs("SEED=%d", seed)) seed = 1;
        if (!$value$plusargs("BUBBLES=%d", bubbles)) bubbles = 25;
        if (!$value$plusargs("DRAIN=%d", drain) || drain < 1) drain = 200;
        if (!$value$plusargs("STOP=%d", stop_first)) stop_first = 0;
        if (!$value$plusargs("JUNK=%d", junk_on)) junk_on = 0;
        $sformat(fname, "%0s/setup_out.hex", dir);
        count_file(fname);
        ns = lines;
        if (words != ns * SW) begin
            $display("FAIL %0s: %0d words in %0d lines, not %0d per line (setup_out format: set SW, LENS_AT, DUAL_AT)",
                     fname, words, ns, SW);
            $fatal(1, "tb_bounds: see the FAIL line above");
        end
        if (ns > MAXSET) begin
            $display("FAIL %0d setup records exceed MAXSET %0d", ns, MAXSET);
            $fatal(1, "tb_bounds: see the FAIL line above");
        end
        $readmemh(fname, setup_mem, 0, ns * SW - 1);
        $sformat(fname, "%0s/bounds_out.hex", dir);
        count_file(fname);
        n = lines;
        if (words != n * WO || n > MAXREC) begin
            $display("FAIL %0s: %0d words in %0d lines (%0d per line, at most %0d lines)", fname,
                     words, n, WO, MAXREC);
            $fatal(1, "tb_bounds: see the FAIL line above");
        end
        $readmemh(fname, out_mem, 0, n * WO - 1);
        $sformat(fname, "%0s/bounds_in.hex", dir);
        count_file(fname);
        if (words != n * WI || lines != n) begin
            $display("FAIL %0s: %0d words in %0d lines, bounds_out.hex has %0d records", fname,
                     words, lines, n);
            $fatal(1, "tb_bounds: see the FAIL line above");
        end
        $readmemh(fname, in_mem, 0, n * WI - 1);
        errors = 0; issued = 0; got = 0; nonempties = 0;
        // Flush the unit's pipeline (unknown valid bits after power-up).
        repeat (40) @(negedge clk);
        for (r = 0; r < n; r = r + 1) begin
            if (in_mem[r*WI] >= ns || setup_mem[in_mem[r*WI] * SW][0] !== 1'b1) begin
                errors = errors + 1;
                $display("MISMATCH record %0d (line %0d): triangle %0d is not a visible setup record (of %0d)",
                         r, r + 1, in_mem[r*WI], ns);
            end else begin
                while (($random(seed) & 32'h7fffffff) % 100 < bubbles) begin
                    in_valid = 0;
                    junk;
                    @(negedge clk);
                end
                drive(r);
                in_valid = 1;
                order[issued] = r;
                issued = issued + 1;
                nonempties = nonempties + out_mem[r*WO][0];
                @(negedge clk);
            end
        end
        in_valid = 0;
        junk;
        repeat (drain) @(negedge clk);
        if (got != issued) begin
            errors = errors + 1;
            $display("MISMATCH %0d records issued, %0d results came out", issued, got);
        end
        if (errors == 0) $display("PASS %0d records (%0d nonempty)", n, nonempties);
        else $display("FAIL %0d mismatching fields in %0d records", errors, n);
        // A failing bench ends with a non-zero exit status of vvp, a passing one with 0.
        if (errors != 0) $fatal(1, "tb_bounds: %0d mismatching fields", errors);
        $finish;
    end
endmodule
