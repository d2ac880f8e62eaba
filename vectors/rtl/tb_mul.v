// tb_mul — uvt_mul against the plain `*` for one operand-width pair: every corner pair
// (−2^(n−1), −2^(n−1)+1, −1, 0, 1, 2^(n−1)−1 of each operand) and NR seeded random pairs.
// REG = 1, 2 (the pipelined forms): each pair is held for REG clocks before p is compared.
// REG = 3 (LAT clocks, MAP 0 or 1): streamed, a new pair on every clock, p compared with the
// product of the pair LAT clocks earlier (so the registers are checked as a pipeline).
// Prints "PASS n products AWxBW: h hard multipliers, l LUT bits (layout)" or each mismatch with operands, expected and observed,
// and a FAIL line that ends with `$fatal`: vvp exits 1 (0 on PASS).
//   iverilog -g2005 -Ptb_mul.AW=18 -Ptb_mul.BW=32 [-Ptb_mul.PA=25 -Ptb_mul.PB=18 -Ptb_mul.LW=8
//     -Ptb_mul.REG=0] uvt_mul.v tb_mul.v
//   REG = 3: -Ptb_mul.REG=3 -Ptb_mul.LAT=n [-Ptb_mul.MAP=1 uvt_mult18.v ecp5/MULT18X18D.v]
//   vvp -n a.out [+SEED=n] [+NR=n] [+STOP=1: end at the first wrong product, "STOP record <n> field p"]
//   -DUVT_ARCH_ONLY: instantiate uvt_mul without parameters (a unit built elsewhere: a netlist)
`timescale 1ns / 1ps
module tb_mul;
    parameter AW = 18;
    parameter BW = 32;
    parameter PA = 25;
    parameter PB = 18;
    parameter LW = 8;
    parameter REG = 0;
    parameter LAT = 0;
    parameter MAP = 0;
    localparam H = 64;                 // history of the streamed pairs (LAT < H)
    reg clk = 1'b0;
    reg  signed [AW-1:0] a;
    reg  signed [BW-1:0] b;
    wire signed [AW+BW-1:0] p;
`ifdef UVT_ARCH_ONLY
    uvt_mul dut (.a(a), .b(b), .p(p), .clk(clk));  // a unit built elsewhere (no parameter passed)
`else
    uvt_mul #(.AW(AW), .BW(BW), .PA(PA), .PB(PB), .LW(LW), .REG(REG), .LAT(LAT), .MAP(MAP)) dut (.a(a), .b(b), .p(p), .clk(clk));
`endif
    integer stop_first = 0;            // +STOP=1: end at the first wrong product
    reg signed [AW+BW-1:0] want;
    reg signed [AW-1:0] ca [0:5];
    reg signed [BW-1:0] cb [0:5];
    integer seed, nr, i, j, k, n, bad, fed;
    reg signed [AW-1:0] ha [0:H-1];
    reg signed [BW-1:0] hb [0:H-1];
    task check;
        if (REG == 3) stream;
        else begin
            #1;
            repeat (REG) begin
                clk = 1'b1;
                #1 clk = 1'b0;
                #1;
            end
            want = a * b;
            n = n + 1;
            if (p !== want) begin
                bad = bad + 1;
                if (bad <= 10)
                    $display("MISMATCH %0d×%0d a=%0d (%h) b=%0d (%h): expected %0d (%h) observed %0d (%h)",
                             AW, BW, a, a, b, b, want, want, p, p);
                if (stop_first == 1) begin
                    $display("STOP record %0d field p", n - 1);
                    $fatal(1, "tb_mul: the first wrong product (+STOP=1)");
                end
            end
        end
    endtask
    // REG = 3: one clock per pair; p after the clock is the product of the pair fed LAT clocks
    // before it (pair fed − LAT, counting from 0).
    task stream;
        begin
            ha[fed % H] = a;
            hb[fed % H] = b;
            #1 clk = 1'b1;
            #1 clk = 1'b0;
            fed = fed + 1;
            if (fed >= LAT) begin
                #1;
                want = ha[(fed - LAT) % H] * hb[(fed - LAT) % H];
                n = n + 1;
                if (p !== want) begin
                    bad = bad + 1;
                    if (bad <= 10)
                        $display("MISMATCH %0d×%0d a=%0d (%h) b=%0d (%h): expected %0d (%h) observed %0d (%h)",
                                 AW, BW, ha[(fed - LAT) % H], ha[(fed - LAT) % H],
                                 hb[(fed - LAT) % H], hb[(fed - LAT) % H], want, want, p, p);
                    if (stop_first == 1) begin
                        $display("STOP record %0d field p", n - 1);
                        $fatal(1, "tb_mul: the first wrong product (+STOP=1)");
                    end
                end
            end
        end
    endtask
    initial begin
        if (!$value$plusargs("SEED=%d", seed)) seed = 7;
        if (!$value$plusargs("NR=%d", nr)) nr = 2000;
        if (!$value$plusargs("STOP=%d", stop_first)) stop_first = 0;
        n = 0;
        bad = 0;
        fed = 0;
        if (REG == 3 && LAT >= H) $fatal(1, "tb_mul: LAT = %0d, at most %0d", LAT, H - 1);
        ca[0] = {1'b1, {(AW-1){1'b0}}}; ca[1] = ca[0] + 1; ca[2] = -1; ca[3] = 0; ca[4] = 1; ca[5] = ~ca[0];
        cb[0] = {1'b1, {(BW-1){1'b0}}}; cb[1] = cb[0] + 1; cb[2] = -1; cb[3] = 0; cb[4] = 1; cb[5] = ~cb[0];
        for (i = 0; i < 6; i = i + 1)
            for (j = 0; j < 6; j = j + 1) begin
                a = ca[i];
                b = cb[j];
                check;
            end
        for (k = 0; k < nr; k = k + 1) begin
            a = {$random(seed), $random(seed), $random(seed), $random(seed)};
            b = {$random(seed), $random(seed), $random(seed), $random(seed)};
            check;
        end
        // REG = 3: LAT − 1 more clocks (the last pair fed again) bring out the last products.
        if (REG == 3) repeat (LAT - 1) check;
`ifdef UVT_ARCH_ONLY
        if (bad == 0) $display("PASS %0d products %0dx%0d", n, AW, BW);
`else
        if (bad == 0)
            $display("PASS %0d products %0dx%0d: %0d hard multipliers, %0d LUT bits (swap %0d, lut-x %0d, lut-y %0d)",
                     n, AW, BW, dut.XN * dut.YN,
                     dut.LX ? dut.XH * dut.YW : (dut.LY ? dut.YH * dut.XW : 0),
                     dut.SWAP, dut.LX, dut.LY);
`endif
        else
            $display("FAIL %0d of %0d products %0dx%0d (SEED=%0d)", bad, n, AW, BW, seed);
        // A failing bench ends with a non-zero exit status of vvp, a passing one with 0.
        if (bad != 0) $fatal(1, "tb_mul: %0d wrong products", bad);
        $finish;
    end
endmodule
