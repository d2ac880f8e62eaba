// A stream runner of uvt_bsample (vectors/rtl/uvt_bsample.v at its default parameters,
// bounded-16-16-16-20) for `uvt vectors gen | runner | uvt vectors ver` and for the campaigns
// of the Python package (uvt.campaign): no model linked, the RTL alone.
// Usage: pipe [seed]   (seed of the bubble pattern, default 1)
// Reads bsample_in records from standard input, one per line (37 words of 8 hex digits, as
// `uvt vectors gen bsample` writes them), drives the unit one record per clock with random
// bubbles (in_valid low on about 1 clock in 4) and writes, per record and in issue order, the
// input record's words followed by the 14 bsample_out words the unit produced (covered,
// det_sign, depth, a_k, b_k, e_k): the pair `uvt vectors ver bsample` reads. A malformed line
// is an error naming the line (exit status 2); so is an output without a record in flight, and
// an out_covered that differs from the edge stage's covered (both are the unit's outputs).
// Build (from the repository root; B is any build folder):
//   verilator --cc --exe --build -j 2 +1364-2005ext+v --top-module uvt_bsample --Mdir $B/p \
//     -o pipe vectors/dpi/rtl.vlt vectors/rtl/uvt_mul.v vectors/rtl/uvt_bsample.v \
//     $PWD/vectors/dpi/pipe.cpp
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <string>

#include "Vuvt_bsample.h"
#include "verilated.h"

static const int WI = 37, WO = 14;

struct Rng {  // SplitMix64: the bubble pattern
    uint64_t s;
    uint64_t next() {
        uint64_t z = (s += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
};

struct Item {
    uint32_t in[WI], obs[WO];
};

[[noreturn]] static void die(uint64_t line, const char* what) {
    fprintf(stderr, "pipe: stdin line %" PRIu64 ": %s\n", line, what);
    exit(2);
}

// Parse one line of WI hex words into rec; false at end of input.
static bool read_record(uint64_t line, uint32_t* rec) {
    static char buf[1024];
    if (!fgets(buf, sizeof buf, stdin)) return false;
    char* p = buf;
    for (int k = 0; k < WI; k++) {
        char* end;
        while (*p == ' ') p++;
        unsigned long v = strtoul(p, &end, 16);
        if (end == p) die(line, "fewer than 37 hex words (a bsample_in record has 37)");
        rec[k] = (uint32_t)v;
        p = end;
    }
    while (*p == ' ' || *p == '\r' || *p == '\n') p++;
    if (*p) die(line, "more than 37 words (a bsample_in record has 37)");
    return true;
}

static void write_pair(const Item& it) {
    char buf[(WI + WO) * 9 + 2];
    char* p = buf;
    for (int k = 0; k < WI; k++) p += sprintf(p, k ? " %08x" : "%08x", it.in[k]);
    for (int k = 0; k < WO; k++) p += sprintf(p, " %08x", it.obs[k]);
    *p++ = '\n';
    fwrite(buf, 1, p - buf, stdout);
}

int main(int argc, char** argv) {
    uint64_t seed = argc > 1 ? strtoull(argv[1], nullptr, 0) : 1;
    Verilated::commandArgs(argc, argv);
    Vuvt_bsample* dut = new Vuvt_bsample;
    Rng rng{seed};
    std::deque<Item> edge_q, depth_q;  // records in flight, in issue order
    uint64_t read = 0;
    bool eof = false;
    auto clock = [&] {
        dut->clk = 0;
        dut->eval();
        dut->clk = 1;
        dut->eval();
    };
    dut->in_valid = 0;
    for (int c = 0; c < 60; c++) clock();  // no reset: >= 46 idle clocks before the first sample
    while (!eof || !edge_q.empty() || !depth_q.empty()) {
        dut->in_valid = 0;
        if (!eof && rng.next() % 4 != 0) {
            Item it;
            if (read_record(read + 1, it.in)) {
                read++;
                for (int k = 0; k < 30; k++) dut->trin[k] = it.in[k];
                dut->vp_w = it.in[30] & 0xfff;
                dut->vp_h = (it.in[30] >> 16) & 0xfff;
                dut->xs = it.in[32] & 0xfffff;
                dut->ys = it.in[33] & 0xfffff;
                dut->t = it.in[34];
                dut->u = it.in[35];
                dut->v = it.in[36];
                dut->in_valid = 1;
                edge_q.push_back(it);
            } else {
                eof = true;
            }
        }
        clock();
        if (dut->edge_valid) {
            if (edge_q.empty()) die(read, "edge_valid with no record in flight");
            Item it = edge_q.front();
            edge_q.pop_front();
            it.obs[0] = dut->covered | (dut->det_sign & 3) << 1;
            for (int k = 0; k < 6; k++) it.obs[2 + k] = dut->ab[k];
            for (int k = 0; k < 3; k++) {
                it.obs[8 + 2 * k] = dut->e[2 * k + 1];
                it.obs[9 + 2 * k] = dut->e[2 * k];
            }
            depth_q.push_back(it);
        }
        if (dut->out_valid) {
            if (depth_q.empty()) die(read, "out_valid with no record in flight");
            Item& it = depth_q.front();
            it.obs[1] = dut->depth;
            if (dut->out_covered != (it.obs[0] & 1)) {
                char msg[96];
                snprintf(msg, sizeof msg, "record %" PRIu64 ": out_covered differs from covered",
                         read - edge_q.size() - depth_q.size());
                die(read, msg);
            }
            write_pair(it);
            depth_q.pop_front();
        }
    }
    fflush(stdout);
    dut->final();
    delete dut;
    return 0;
}
