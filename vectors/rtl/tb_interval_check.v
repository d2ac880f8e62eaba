// Testbench: loads exported golden vectors with $readmemh and checks uvt_interval_check against
// every record. Plusargs: +IN=<select_in.hex> +OUT=<select_out.hex> +N=<records>.
// Prints "PASS <n> records" or "FAIL <errors> of <n> records" (first mismatches listed); a FAIL
// ends with `$fatal`: vvp exits 1 (0 on PASS).
`timescale 1ns / 1ps
module tb_interval_check;
    localparam WORDS = 9;
    localparam MAXREC = 65536;
    reg [31:0] in_mem  [0:MAXREC*WORDS-1];
    reg [31:0] out_mem [0:MAXREC-1];
    reg [8*1024-1:0] in_file, out_file;
    integer n, i, errors;
    reg signed [31:0] u_lo, u_hi, v_lo, v_hi, t_lo, t_hi, u, v, t;
    wire inside;

    uvt_interval_check dut (
        .u_lo(u_lo), .u_hi(u_hi), .v_lo(v_lo), .v_hi(v_hi), .t_lo(t_lo), .t_hi(t_hi),
        .u(u), .v(v), .t(t), .inside(inside)
    );

    initial begin
        if (!$value$plusargs("IN=%s", in_file) || !$value$plusargs("OUT=%s", out_file) ||
            !$value$plusargs("N=%d", n)) begin
            $display("FAIL usage: +IN=select_in.hex +OUT=select_out.hex +N=records");
            $fatal(1, "tb_interval_check: see the FAIL line above");
        end
        if (n > MAXREC) begin
            $display("FAIL %0d records exceed MAXREC %0d", n, MAXREC);
            $fatal(1, "tb_interval_check: see the FAIL line above");
        end
        $readmemh(in_file, in_mem, 0, n * WORDS - 1);
        $readmemh(out_file, out_mem, 0, n - 1);
        errors = 0;
        for (i = 0; i < n; i = i + 1) begin
            u_lo = in_mem[i*WORDS+0]; u_hi = in_mem[i*WORDS+1];
            v_lo = in_mem[i*WORDS+2]; v_hi = in_mem[i*WORDS+3];
            t_lo = in_mem[i*WORDS+4]; t_hi = in_mem[i*WORDS+5];
            u    = in_mem[i*WORDS+6]; v    = in_mem[i*WORDS+7];
            t    = in_mem[i*WORDS+8];
            #1;
            if (inside !== out_mem[i][0]) begin
                errors = errors + 1;
                if (errors <= 10)
                    $display("MISMATCH line %0d: u %h in [%h,%h] v %h in [%h,%h] t %h in [%h,%h]: expected %0d observed %0d",
                             i + 1, u, u_lo, u_hi, v, v_lo, v_hi, t, t_lo, t_hi, out_mem[i][0], inside);
            end
        end
        if (errors == 0) $display("PASS %0d records", n);
        else $display("FAIL %0d of %0d records", errors, n);
        // A failing bench ends with a non-zero exit status of vvp, a passing one with 0.
        if (errors != 0) $fatal(1, "tb_interval_check: %0d mismatching records", errors);
        $finish;
    end
endmodule
