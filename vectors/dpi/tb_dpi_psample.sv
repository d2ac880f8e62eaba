// DPI-C scoreboard testbench of uvt_psample (vectors/rtl/uvt_psample.v, configuration
// planar-16-16-16-20, static triangles) for Verilator 5 (--binary --timing; vectors/dpi/README.md).
// Plusargs:
//   +SEED=s       stimulus seed (decimal, 64 bits; default 1)
//   +N=count      samples (default 1000)
//   +ARCH_ONLY=1  compare covered and depth only (default: every output field)
//   +CORRUPT=k    flip bit CORRUPT_BIT (default 0) of word CORRUPT_WORD (default 1, depth) of
//                 the model's expected output of sample k: the bench must FAIL on it
// Sample i is record i of the seeded planar stream (uvt_gen: static triangles of every family,
// with the planar setup's fields: normals, sigma, depth plane); for about half of the samples
// the bench then draws a new position inside the viewport ($urandom, seeded from SEED; the
// setup fields do not depend on it). The model (uvt_psample through DPI) gives the expected
// output; the unit is driven with random bubbles (in_valid low on about 1 clock in 4) and its
// outputs are compared in issue order, word by word; on a difference uvt_compare names the
// fields. The first mismatch prints the seed, the sample, every differing field
// (uvt_last_error), then the input, expected and observed words in hex, and the bench ends
// with a FAIL line. Success: "LATENCY <l> clocks", then "PASS <n> samples, <c> covered, <t>
// ties, <w> w<=0, <r> re-randomised, <b> bubbles" (ties: an expected edge value E_k = 0; w<=0:
// a triangle with a vertex at w <= 0).
// Any latency works (below SLOTS - 1 clocks): the bench measures it, clocks from a sample's
// in_valid to its out_valid, and fails if a sample's differs from the first sample's or from
// the unit's LAT (read at run time: dut.LAT).
// Parameters (Verilator -G on this top, e.g. -GPIPE=2 -GMAP=1): the unit's build, passed to it
// (uvt_psample.v; the defaults are the unit's): DSP_A, DSP_B, LUTW (the multiplier tiling),
// PIPE (0, 1, 2: the pipelining, latency only), MAP (1: hard pieces as ECP5 MULT18X18D, with
// PIPE = 2 and 18 × 18 ports; the build then needs vectors/rtl/uvt_mult18.v and the primitive's
// model through vectors/dpi/mult18x18d.sv). Every build gives the same records and so prints
// the same PASS line.
`timescale 1ns / 1ps
module tb_dpi_psample #(
    parameter int DSP_A = 25,
    parameter int DSP_B = 18,
    parameter int LUTW = 8,
    parameter int PIPE = 0,
    parameter int MAP = 0
);
    import uvt_dpi::*;
    localparam int WI = 28, WO = 8, SLOTS = 512;

    longint unsigned seed;
    int n, corrupt, corrupt_word, corrupt_bit, arch_only;
    bit failed;  // the first mismatch ends the bench: nothing is checked after it
    int issued, checked, n_cov, n_tie, n_wle0, n_rerand, n_bubble;
    int lat = -1;            // the unit's latency in clocks (the first sample's)
    longint unsigned clocks; // rising edges so far

    // Scoreboard: records by slot (issue number mod SLOTS > samples in flight), slots in issue
    // order.
    int unsigned sb_in[SLOTS][WI];
    int unsigned sb_exp[SLOTS][WO];
    int unsigned sb_obs[SLOTS][WO];
    longint unsigned sb_idx[SLOTS];
    longint unsigned sb_t[SLOTS];  // clocks when the sample was issued
    int q[$];

    bit clk = 0, in_valid = 0;
    logic [287:0] nn = 0;
    logic signed [1:0] sigma = 1;
    logic signed [7:0] f = 0;
    logic [95:0] g = 0;
    logic [11:0] vp_w = 1, vp_h = 1;
    logic [19:0] xs = 0, ys = 0;
    wire out_valid, covered;
    wire signed [31:0] depth;
    wire [191:0] e;

    uvt_psample #(
        .DSP_A(DSP_A), .DSP_B(DSP_B), .LUTW(LUTW), .PIPE(PIPE), .MAP(MAP)
    ) dut (
        .clk(clk), .in_valid(in_valid), .n(nn), .sigma(sigma), .f(f), .g(g), .vp_w(vp_w),
        .vp_h(vp_h), .xs(xs), .ys(ys), .out_valid(out_valid), .covered(covered),
        .depth(depth), .e(e)
    );

    always #5 clk = ~clk;
    always @(posedge clk) clocks++;

    function automatic void words(string label, int unsigned w[], int len);
        string s = label;
        for (int k = 0; k < len; k++) s = {s, $sformatf(" %08h", w[k])};
        $display("%s", s);
    endfunction

    function automatic void fail(string what, int slot);
        int unsigned in_w[] = new[WI];
        int unsigned ex[] = new[WO];
        int unsigned ob[] = new[WO];
        if (failed) return;
        failed = 1;
        for (int k = 0; k < WI; k++) in_w[k] = sb_in[slot][k];
        for (int k = 0; k < WO; k++) begin
            ex[k] = sb_exp[slot][k];
            ob[k] = sb_obs[slot][k];
        end
        $display("MISMATCH seed %0d sample %0d (uvt_gen record %0d, kind psample, %s): %s",
                 seed, sb_idx[slot], sb_idx[slot], UVT_PLANAR, what);
        words("  input    (psample_in words 0..27):", in_w, WI);
        words("  expected (psample_out words 0..7):", ex, WO);
        words("  observed (psample_out words 0..7):", ob, WO);
        $display("FAIL seed %0d: sample %0d mismatches, %0d samples checked before it",
                 seed, sb_idx[slot], checked);
        $finish;
    endfunction

    // Compare the slot's observed record, word by word (fast), and on a difference let
    // uvt_compare name every differing field.
    function automatic void compare(int slot);
        int unsigned ex[WO], ob[WO];
        bit same = 1;
        int rc;
        for (int k = 0; k < WO; k++) begin
            ex[k] = sb_exp[slot][k];
            ob[k] = sb_obs[slot][k];
            if (arch_only == 0 && ex[k] != ob[k]) same = 0;
        end
        if (arch_only != 0) same = ex[0][0] == ob[0][0] && ex[1] == ob[1];
        if (failed) return;
        if (!same) begin
            rc = uvt_compare_psample(UVT_KIND_PSAMPLE, ex, ob, 64'(WO), arch_only);
            if (rc == UVT_ERR_MISMATCH) fail(uvt_last_error(), slot);
            else fail($sformatf("uvt_compare returned %0d: %s", rc, uvt_last_error()), slot);
        end
        if (!failed) checked++;
    endfunction

    // The sample in slot s came out now: its latency must be the first sample's.
    function automatic void latency(int s);
        int l = int'(clocks - sb_t[s]);
        if (lat < 0) lat = l;
        if (l != lat && !failed) begin
            $display("FAIL seed %0d: sample %0d came out %0d clocks after its in_valid, the first sample %0d clocks after",
                     seed, sb_idx[s], l, lat);
            $finish;
        end
    endfunction

    // Outputs, on the falling edge, in issue order.
    always @(negedge clk) begin
        int s;
        if (out_valid === 1'b1) begin
            if (q.size() == 0) begin
                $display("FAIL seed %0d: out_valid with no sample in flight", seed);
                $finish;
            end
            s = q.pop_front();
            latency(s);
            sb_obs[s][0] = {31'b0, covered};
            sb_obs[s][1] = depth;
            for (int k = 0; k < 3; k++) begin
                sb_obs[s][2 + 2*k] = e[64*k + 32 +: 32];
                sb_obs[s][3 + 2*k] = e[64*k +: 32];
            end
            compare(s);
        end
    end

    initial begin
        int unsigned rec[WI], ex[WO];
        int rc, s;
        if (!$value$plusargs("SEED=%d", seed)) seed = 1;
        if (!$value$plusargs("N=%d", n)) n = 1000;
        if (!$value$plusargs("ARCH_ONLY=%d", arch_only)) arch_only = 0;
        if (!$value$plusargs("CORRUPT=%d", corrupt)) corrupt = -1;
        if (!$value$plusargs("CORRUPT_WORD=%d", corrupt_word)) corrupt_word = 1;
        if (!$value$plusargs("CORRUPT_BIT=%d", corrupt_bit)) corrupt_bit = 0;
        void'($urandom(seed[31:0] ^ seed[63:32]));
        // Idle clocks first: the unit must output nothing (its pipeline starts empty).
        repeat (SLOTS) @(negedge clk);
        for (longint unsigned i = 0; i < 64'(n); i++) begin
            if (failed) break;
            while ($urandom_range(3) == 0) begin
                in_valid = 0;
                n_bubble++;
                @(negedge clk);
            end
            rc = uvt_gen_psample(UVT_KIND_PSAMPLE, UVT_PLANAR, seed, i, 16, rec, 64'(WI));
            if (rc != WI) begin
                $display("FAIL seed %0d sample %0d: uvt_gen returned %0d: %s", seed, i, rc,
                         uvt_last_error());
                $finish;
            end
            if ($urandom_range(1) == 1) begin
                // A new position inside the viewport (the setup fields stay valid).
                rec[26] = $urandom_range(256 * rec[12][11:0] - 1);
                rec[27] = $urandom_range(256 * rec[12][27:16] - 1);
                n_rerand++;
            end
            rc = uvt_psample(rec, ex);
            if (q.size() >= SLOTS - 1) begin
                $display("FAIL seed %0d sample %0d: %0d samples in flight without a result, the bench holds %0d (SLOTS)",
                         seed, i, q.size(), SLOTS - 1);
                $finish;
            end
            s = issued % SLOTS;
            sb_t[s] = clocks;
            sb_idx[s] = i;
            for (int k = 0; k < WI; k++) sb_in[s][k] = rec[k];
            if (rc != UVT_OK) begin
                for (int k = 0; k < WO; k++) sb_exp[s][k] = 0;
                fail($sformatf("the model refused the input (%0d): %s", rc, uvt_last_error()), s);
            end
            if (corrupt >= 0 && i == 64'(corrupt)) ex[corrupt_word] ^= 32'd1 << corrupt_bit;
            for (int k = 0; k < WO; k++) sb_exp[s][k] = ex[k];
            // What the sample exercises.
            if (ex[0][0]) n_cov++;
            if ({ex[2], ex[3]} == 0 || {ex[4], ex[5]} == 0 || {ex[6], ex[7]} == 0) n_tie++;
            if ($signed(rec[3]) <= 0 || $signed(rec[7]) <= 0 || $signed(rec[11]) <= 0) n_wle0++;
            // Drive the unit (the record words → ports of tb_psample.v).
            vp_w = rec[12][11:0];
            vp_h = rec[12][27:16];
            for (int k = 0; k < 9; k++) nn[32*k +: 32] = rec[13 + k];
            sigma = rec[22][1:0];
            f = rec[22][9:2];
            for (int k = 0; k < 3; k++) g[32*k +: 32] = rec[23 + k];
            xs = rec[26][19:0];
            ys = rec[27][19:0];
            in_valid = 1;
            q.push_back(s);
            issued++;
            @(negedge clk);
        end
        in_valid = 0;
        if (failed) $finish;
        // Drain: every result within SLOTS clocks, then nothing more for a latency and a bit.
        for (int c = 0; c < SLOTS && q.size() > 0; c++) @(negedge clk);
        repeat (lat + 4) @(negedge clk);
        if (checked != issued) begin
            $display("FAIL seed %0d: %0d samples issued, %0d results came out", seed, issued,
                     checked);
            $finish;
        end
        if (checked > 0 && lat != dut.LAT) begin
            $display("FAIL seed %0d: results came %0d clocks after their in_valid, the unit's LAT is %0d",
                     seed, lat, dut.LAT);
            $finish;
        end
        $display("LATENCY %0d clocks", lat);
        $display("PASS %0d samples, %0d covered, %0d ties, %0d w<=0, %0d re-randomised, %0d bubbles",
                 checked, n_cov, n_tie, n_wle0, n_rerand, n_bubble);
        $finish;
    end
endmodule
