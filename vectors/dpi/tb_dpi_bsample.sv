// DPI-C scoreboard testbench of uvt_bsample (vectors/rtl/uvt_bsample.v, configuration
// bounded-16-16-16-20) for Verilator 5 (--binary --timing; vectors/dpi/README.md).
// Plusargs:
//   +SEED=s       stimulus seed (decimal, 64 bits; default 1)
//   +N=count      samples (default 1000)
//   +ARCH_ONLY=1  compare covered and depth only (default: every output field)
//   +CORRUPT=k    flip bit CORRUPT_BIT (default 0) of word CORRUPT_WORD (default 1, depth) of
//                 the model's expected output of sample k: the bench must FAIL on it
// Sample i is record i of the seeded stream (uvt_gen: every triangle class, camera-plane
// crossers, w = 0 vertices, slivers, fill-rule ties, viewport corners); for about half of the
// samples the bench then draws a new position inside the viewport and new t, u, v ($urandom,
// seeded from SEED; every raw t in [0, 2^16], u, v in [-2^16, 2^16] is on this
// configuration's grid). The model (uvt_bsample through DPI) gives the expected output; the
// unit is driven with random bubbles (in_valid low on about 1 clock in 4) and its outputs are
// checked in issue order: the edge results (edge_valid) and the depth (out_valid) of a sample
// are gathered into one bsample_out record and compared word by word; on a difference
// uvt_compare names the fields.
// The first mismatch prints the seed, the sample, every differing field (uvt_last_error),
// then the input, expected and observed words in hex, and the bench ends with a FAIL line.
// Success: "LATENCY edge <a> depth <b> clocks", then "PASS <n> samples, <c> covered, <t> ties,
// <w> w<=0, <r> re-randomised, classes <static>/<motion>/<defocus>/<both>, <b> bubbles" (ties:
// an expected edge value E'_k = 0; w<=0: a triangle with a vertex at w <= 0 in either key
// frame).
// Any latency works (below SLOTS - 1 clocks): the bench measures both, clocks from a sample's
// in_valid to its edge_valid and to its out_valid, and fails if a sample's differ from the first
// sample's or from the unit's LAT_EDGE and LAT (read at run time: dut.LAT_EDGE, dut.LAT).
// Parameters (Verilator -G on this top, e.g. -GPIPE=2 -GMAP=1 -GDSP_A=18): the unit's build,
// passed to it (uvt_bsample.v; the defaults are the unit's): DSP_A, DSP_B, LUTW (the
// multiplier tiling), PIPE (0, 1, 2: the pipelining, latency only), MAP (1: hard pieces as ECP5
// MULT18X18D, with PIPE = 2 and 18 × 18 ports; the build then needs vectors/rtl/uvt_mult18.v
// and the primitive's model through vectors/dpi/mult18x18d.sv), LUTWE and KARA (PIPE = 2: the
// edge products' LUT chunk limit, Karatsuba edge products). The configuration is the
// default one (POS = TUV = 16, OFF = 20, motion and defocus). Every build gives the same
// records and so prints the same PASS line.
`timescale 1ns / 1ps
module tb_dpi_bsample #(
    parameter int DSP_A = 25,
    parameter int DSP_B = 18,
    parameter int LUTW = 8,
    parameter int PIPE = 0,
    parameter int MAP = 0,
    parameter int LUTWE = -1,
    parameter int KARA = 0
);
    import uvt_dpi::*;
    localparam int WI = 37, WO = 14, SLOTS = 512;
    localparam string CONFIG = UVT_BOUNDED_DEFAULT;

    longint unsigned seed;
    int n, corrupt, corrupt_word, corrupt_bit, arch_only;
    bit failed;  // the first mismatch ends the bench: nothing is checked after it
    int issued, checked, n_cov, n_tie, n_wle0, n_rerand, n_bubble;
    int n_class[4];
    int lat_e = -1, lat_d = -1;  // the unit's latencies in clocks (the first sample's)
    longint unsigned clocks;     // rising edges so far

    // Scoreboard: records by slot (issue number mod SLOTS > samples in flight), slots in issue
    // order waiting for their edge results, then for their depth.
    int unsigned sb_in[SLOTS][WI];
    int unsigned sb_exp[SLOTS][WO];
    int unsigned sb_obs[SLOTS][WO];
    longint unsigned sb_idx[SLOTS];
    longint unsigned sb_t[SLOTS];  // clocks when the sample was issued
    int q_edge[$];
    int q_depth[$];

    bit clk = 0, in_valid = 0;
    logic [32*30-1:0] trin = 0;
    logic [11:0] vp_w = 1, vp_h = 1;
    logic [19:0] xs = 0, ys = 0;
    logic signed [31:0] t = 0, u = 0, v = 0;
    wire edge_valid, covered, out_valid, out_covered;
    wire [191:0] ab, e;
    wire signed [1:0] det_sign;
    wire signed [31:0] depth;

    uvt_bsample #(
        .DSP_A(DSP_A), .DSP_B(DSP_B), .LUTW(LUTW), .PIPE(PIPE), .MAP(MAP),
        .LUTWE(LUTWE), .KARA(KARA)
    ) dut (
        .clk(clk), .in_valid(in_valid), .trin(trin), .vp_w(vp_w), .vp_h(vp_h), .xs(xs), .ys(ys),
        .t(t), .u(u), .v(v), .edge_valid(edge_valid), .ab(ab), .e(e), .det_sign(det_sign),
        .covered(covered), .out_valid(out_valid), .out_covered(out_covered), .depth(depth)
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
        $display("MISMATCH seed %0d sample %0d (uvt_gen record %0d, kind bsample, %s): %s",
                 seed, sb_idx[slot], sb_idx[slot], CONFIG, what);
        words("  input    (bsample_in words 0..36):", in_w, WI);
        words("  expected (bsample_out words 0..13):", ex, WO);
        words("  observed (bsample_out words 0..13):", ob, WO);
        $display("FAIL seed %0d: sample %0d mismatches, %0d samples checked before it",
                 seed, sb_idx[slot], checked);
        $finish;
    endfunction

    // The slot's observed record is complete (edge results and depth): compare it, word by
    // word (fast), and on a difference let uvt_compare name every differing field.
    function automatic void compare(int slot, logic oc);
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
            rc = uvt_compare_bsample(UVT_KIND_BSAMPLE, ex, ob, 64'(WO), arch_only);
            if (rc == UVT_ERR_MISMATCH) fail(uvt_last_error(), slot);
            else fail($sformatf("uvt_compare returned %0d: %s", rc, uvt_last_error()), slot);
        end
        if (oc !== ex[0][0])
            fail($sformatf("field out_covered (with depth): expected %0d, observed %0d", ex[0][0], oc), slot);
        if (!failed) checked++;
    endfunction

    // The sample in slot s gave its edge results (what = "edge_valid", lat = lat_e) or its depth
    // ("out_valid", lat_d) now: the clocks since its in_valid must be the first sample's.
    function automatic void latency(int s, string what, inout int lat);
        int l = int'(clocks - sb_t[s]);
        if (lat < 0) lat = l;
        if (l != lat && !failed) begin
            $display("FAIL seed %0d: sample %0d gave %s %0d clocks after its in_valid, the first sample %0d clocks after",
                     seed, sb_idx[s], what, l, lat);
            $finish;
        end
    endfunction

    // Outputs, on the falling edge, in issue order.
    always @(negedge clk) begin
        int s;
        if (edge_valid === 1'b1) begin
            if (q_edge.size() == 0) begin
                $display("FAIL seed %0d: edge_valid with no sample in flight", seed);
                $finish;
            end
            s = q_edge.pop_front();
            latency(s, "edge_valid", lat_e);
            sb_obs[s][0] = {29'b0, det_sign, covered};
            for (int k = 0; k < 6; k++) sb_obs[s][2 + k] = ab[32*k +: 32];
            for (int k = 0; k < 3; k++) begin
                sb_obs[s][8 + 2*k] = e[64*k + 32 +: 32];
                sb_obs[s][9 + 2*k] = e[64*k +: 32];
            end
            q_depth.push_back(s);
        end
        if (out_valid === 1'b1) begin
            if (q_depth.size() == 0) begin
                $display("FAIL seed %0d: out_valid with no sample past its edge stage", seed);
                $finish;
            end
            s = q_depth.pop_front();
            latency(s, "out_valid", lat_d);
            sb_obs[s][1] = depth;
            compare(s, out_covered);
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
            rc = uvt_gen_bsample(UVT_KIND_BSAMPLE, CONFIG, seed, i, 16, rec, 64'(WI));
            if (rc != WI) begin
                $display("FAIL seed %0d sample %0d: uvt_gen returned %0d: %s", seed, i, rc,
                         uvt_last_error());
                $finish;
            end
            if ($urandom_range(1) == 1) begin
                // A new sample of the same triangle: position inside the viewport, t, u, v.
                rec[32] = $urandom_range(256 * rec[30][11:0] - 1);
                rec[33] = $urandom_range(256 * rec[30][27:16] - 1);
                rec[34] = $urandom_range(65536);
                rec[35] = $urandom_range(131072) - 65536;
                rec[36] = $urandom_range(131072) - 65536;
                n_rerand++;
            end
            rc = uvt_bsample(rec, ex);
            if (q_edge.size() + q_depth.size() >= SLOTS - 1) begin
                $display("FAIL seed %0d sample %0d: %0d samples in flight without a result, the bench holds %0d (SLOTS)",
                         seed, i, q_edge.size() + q_depth.size(), SLOTS - 1);
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
            if ({ex[8], ex[9]} == 0 || {ex[10], ex[11]} == 0 || {ex[12], ex[13]} == 0) n_tie++;
            for (int k = 3; k < 30; k += 5)
                if ($signed(rec[k]) <= 0) begin
                    n_wle0++;
                    break;
                end
            n_class[rec[31][1:0]]++;
            // Drive the unit (the record words → ports of tb_bsample.v).
            for (int k = 0; k < 30; k++) trin[32*k +: 32] = rec[k];
            vp_w = rec[30][11:0];
            vp_h = rec[30][27:16];
            xs = rec[32][19:0];
            ys = rec[33][19:0];
            t = rec[34];
            u = rec[35];
            v = rec[36];
            in_valid = 1;
            q_edge.push_back(s);
            issued++;
            @(negedge clk);
        end
        in_valid = 0;
        if (failed) $finish;
        // Drain: every result within SLOTS clocks, then nothing more for a latency and a bit.
        for (int c = 0; c < SLOTS && q_edge.size() + q_depth.size() > 0; c++) @(negedge clk);
        repeat (lat_d + 4) @(negedge clk);
        if (checked != issued) begin
            $display("FAIL seed %0d: %0d samples issued, %0d results came out", seed, issued,
                     checked);
            $finish;
        end
        if (checked > 0 && (lat_e != dut.LAT_EDGE || lat_d != dut.LAT)) begin
            $display("FAIL seed %0d: results came %0d (edge) and %0d (depth) clocks after their in_valid, the unit's LAT_EDGE is %0d, LAT %0d",
                     seed, lat_e, lat_d, dut.LAT_EDGE, dut.LAT);
            $finish;
        end
        $display("LATENCY edge %0d depth %0d clocks", lat_e, lat_d);
        $display("PASS %0d samples, %0d covered, %0d ties, %0d w<=0, %0d re-randomised, classes %0d/%0d/%0d/%0d, %0d bubbles",
                 checked, n_cov, n_tie, n_wle0, n_rerand, n_class[0], n_class[1], n_class[2],
                 n_class[3], n_bubble);
        $finish;
    end
endmodule
