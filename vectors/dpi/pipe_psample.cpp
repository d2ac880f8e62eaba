// A stream runner of uvt_psample (vectors/rtl/uvt_psample.v; any build, any latency), the planar
// unit's twin of pipe.cpp: for `uvt vectors gen psample | runner | uvt vectors ver psample`, the
// campaigns of the Python package (uvt.campaign) and the mutation flow's stream stage
// (uvt.mutation). No model linked: the RTL alone.
// Usage: pipe_psample [seed] [+MUTSEL=k]   (seed of the bubble pattern, default 1; +MUTSEL picks
// a mutant of a netlist the mutation flow wrote)
// Reads psample_in records from standard input, one per line (28 words of 8 hex digits, as
// `uvt vectors gen psample` writes them), drives the unit one record per clock with random
// bubbles (in_valid low on about 1 clock in 4) and writes, per record and in issue order, the
// input record's words followed by the 8 psample_out words the unit produced (covered, depth,
// e_k as high and low words). A malformed line is an error naming the line (exit status 2); so
// is an output without a record in flight.
// Build (from the repository root; B is any build folder):
//   verilator --cc --exe --build -j 2 --top-module uvt_psample --Mdir $B/p -o pipe_psample \
//     vectors/dpi/rtl.vlt vectors/rtl/uvt_mul.v vectors/rtl/uvt_psample.v \
//     $PWD/vectors/dpi/pipe_psample.cpp
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>

#include "Vuvt_psample.h"
#include "verilated.h"

static const int WI = 28, WO = 8;

struct Rng {  // SplitMix64: the bubble pattern (as pipe.cpp)
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
    fprintf(stderr, "pipe_psample: stdin line %" PRIu64 ": %s\n", line, what);
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
        if (end == p) die(line, "fewer than 28 hex words (a psample_in record has 28)");
        rec[k] = (uint32_t)v;
        p = end;
    }
    while (*p == ' ' || *p == '\r' || *p == '\n') p++;
    if (*p) die(line, "more than 28 words (a psample_in record has 28)");
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
    uint64_t seed = argc > 1 && argv[1][0] != '+' ? strtoull(argv[1], nullptr, 0) : 1;
    Verilated::commandArgs(argc, argv);
    Vuvt_psample* dut = new Vuvt_psample;
    Rng rng{seed};
    std::deque<Item> q;  // records in flight, in issue order
    uint64_t read = 0;
    bool eof = false;
    auto clock = [&] {
        dut->clk = 0;
        dut->eval();
        dut->clk = 1;
        dut->eval();
    };
    dut->in_valid = 0;
    for (int c = 0; c < 60; c++) clock();  // no reset: idle clocks flush the pipeline
    while (!eof || !q.empty()) {
        dut->in_valid = 0;
        if (!eof && rng.next() % 4 != 0) {
            Item it;
            if (read_record(read + 1, it.in)) {
                read++;
                // words 12: viewport; 13..21: n; 22: sigma (bits 1..0), f (bits 9..2);
                // 23..25: g; 26, 27: sample position (tb_psample.v reads the same words)
                dut->vp_w = it.in[12] & 0xfff;
                dut->vp_h = (it.in[12] >> 16) & 0xfff;
                for (int k = 0; k < 9; k++) dut->n[k] = it.in[13 + k];
                dut->sigma = it.in[22] & 3;
                dut->f = (it.in[22] >> 2) & 0xff;
                for (int k = 0; k < 3; k++) dut->g[k] = it.in[23 + k];
                dut->xs = it.in[26] & 0xfffff;
                dut->ys = it.in[27] & 0xfffff;
                dut->in_valid = 1;
                q.push_back(it);
            } else {
                eof = true;
            }
        }
        clock();
        if (dut->out_valid) {
            if (q.empty()) die(read, "out_valid with no record in flight");
            Item it = q.front();
            q.pop_front();
            it.obs[0] = dut->covered;
            it.obs[1] = dut->depth;
            for (int k = 0; k < 3; k++) {
                it.obs[2 + 2 * k] = dut->e[2 * k + 1];
                it.obs[3 + 2 * k] = dut->e[2 * k];
            }
            write_pair(it);
        }
    }
    fflush(stdout);
    dut->final();
    delete dut;
    return 0;
}
