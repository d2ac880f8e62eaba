// Verilator C++ harness of uvt_bsample (vectors/rtl/uvt_bsample.v, bounded-16-16-16-20) linking
// the model's static library (libuvt_ffi.a, ffi/include/uvt.h) directly: no DPI.
// Usage: harness [seed] [rtl_samples] [model_triangles] [samples_per_triangle] [corrupt]
//   (defaults 1, 200000, 20000, 64, -1; corrupt = k flips bit 0 of sample k's expected depth,
//   which the run must report)
// 1. Model only, one core (no RTL): bounded sample tests per second, model call + compare
//    against a stored result (what a harness compares a DUT's output with), through
//    a. the typed API: uvt_tri_new once per triangle, uvt_tri_sample per sample;
//    b. the record API: uvt_bsample per 37-word record, memcmp of the 14 output words;
//    c. the record API with uvt_compare instead of memcmp.
//    The typed results are checked against the record API's (covered, det_sign, depth, E').
// 2. The RTL: record i of the seeded stream (uvt_gen), half of them with a new position, t, u,
//    v; the model's expected output (uvt_bsample); the unit driven one record per clock with
//    random bubbles; every output field compared in issue order (uvt_compare names the
//    fields of a mismatch). Samples per second of the whole loop.
// Prints "RATE <name> <samples> samples <seconds> s <rate> /s" lines, then
// "PASS <n> samples, <c> covered, <t> ties, <w> w<=0" or "FAIL …" (exit status 1).
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <vector>

#include "Vuvt_bsample.h"
#include "uvt.h"
#include "verilated.h"

static const char* CONFIG = "bounded-16-16-16-20";
static const int WI = UVT_BSAMPLE_IN_WORDS, WO = UVT_BSAMPLE_OUT_WORDS;

// SplitMix64: the harness's own stimulus generator (positions, t, u, v, bubbles).
struct Rng {
    uint64_t s;
    uint64_t next() {
        uint64_t z = (s += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    uint32_t below(uint32_t n) { return (uint32_t)(next() % n); }
};

static double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

static void rate(const char* name, uint64_t n, double s) {
    printf("RATE %s %" PRIu64 " samples %.3f s %.0f /s\n", name, n, s, n / s);
}

static void words(const char* label, const uint32_t* w, int n) {
    printf("  %s", label);
    for (int k = 0; k < n; k++) printf(" %08x", w[k]);
    printf("\n");
}

[[noreturn]] static void fail(uint64_t seed, uint64_t i, const char* what, const uint32_t* in,
                              const uint32_t* exp, const uint32_t* obs) {
    printf("MISMATCH seed %" PRIu64 " sample %" PRIu64 " (uvt_gen record %" PRIu64
           ", kind bsample, %s): %s\n",
           seed, i, i, CONFIG, what);
    words("input    (bsample_in words 0..36):", in, WI);
    if (exp) words("expected (bsample_out words 0..13):", exp, WO);
    if (obs) words("observed (bsample_out words 0..13):", obs, WO);
    printf("FAIL seed %" PRIu64 ": sample %" PRIu64 "\n", seed, i);
    exit(1);
}

// Record i of the stream, re-randomised half of the time (position inside the viewport, t, u,
// v: every raw value is on this configuration's grid).
static void stimulus(uint64_t seed, uint64_t i, Rng& rng, uint32_t* rec) {
    int rc = uvt_gen(UVT_KIND_BSAMPLE, CONFIG, seed, i, 16, rec, WI);
    if (rc != WI) fail(seed, i, uvt_last_error(), rec, nullptr, nullptr);
    if (rng.below(2)) {
        rec[32] = rng.below(256 * (rec[30] & 0xfff));
        rec[33] = rng.below(256 * ((rec[30] >> 16) & 0xfff));
        rec[34] = rng.below(65537);
        rec[35] = rng.below(131073) - 65536;
        rec[36] = rng.below(131073) - 65536;
    }
}

static void model_only(uint64_t seed, uint64_t tris, uint32_t per_tri) {
    Rng rng{seed ^ 0x6d6f64656cull};
    std::vector<uint32_t> recs;  // one record per sample: triangle words + this sample
    std::vector<UvtTri*> handles;
    recs.reserve(tris * per_tri * WI);
    uint32_t rec[WI];
    for (uint64_t i = 0; i < tris; i++) {
        stimulus(seed, i, rng, rec);
        UvtTri* h = nullptr;
        if (uvt_tri_new((const int32_t*)rec, rec[30] & 0xfff, (rec[30] >> 16) & 0xfff, CONFIG,
                        &h) != UVT_OK)
            fail(seed, i, uvt_last_error(), rec, nullptr, nullptr);
        handles.push_back(h);
        for (uint32_t j = 0; j < per_tri; j++) {
            rec[32] = rng.below(256 * (rec[30] & 0xfff));
            rec[33] = rng.below(256 * ((rec[30] >> 16) & 0xfff));
            rec[34] = rng.below(65537);
            rec[35] = rng.below(131073) - 65536;
            rec[36] = rng.below(131073) - 65536;
            recs.insert(recs.end(), rec, rec + WI);
        }
    }
    const uint64_t n = tris * per_tri;
    // The stored results a harness would compare with: the record API's, once.
    std::vector<uint32_t> outs(n * WO);
    for (uint64_t s = 0; s < n; s++)
        if (uvt_bsample(&recs[s * WI], &outs[s * WO]) != UVT_OK)
            fail(seed, s / per_tri, uvt_last_error(), &recs[s * WI], nullptr, nullptr);
    // a. typed API: model call + compare with the stored result.
    uint64_t bad = 0;
    double t0 = now();
    for (uint64_t s = 0; s < n; s++) {
        const uint32_t* r = &recs[s * WI];
        const uint32_t* o = &outs[s * WO];
        UvtHit hit;
        if (uvt_tri_sample(handles[s / per_tri], r[32], r[33], (int32_t)r[34], (int32_t)r[35],
                           (int32_t)r[36], &hit) != UVT_OK)
            fail(seed, s / per_tri, uvt_last_error(), r, o, nullptr);
        bad += (uint32_t)hit.covered != (o[0] & 1) || hit.det_sign != ((int32_t)(o[0] << 29) >> 30) ||
               (uint32_t)hit.depth != o[1] ||
               (uint64_t)hit.e[0] != ((uint64_t)o[8] << 32 | o[9]) ||
               (uint64_t)hit.e[1] != ((uint64_t)o[10] << 32 | o[11]) ||
               (uint64_t)hit.e[2] != ((uint64_t)o[12] << 32 | o[13]);
    }
    rate("model-typed", n, now() - t0);
    if (bad) {
        printf("FAIL %" PRIu64 " typed results differ from the record API's\n", bad);
        exit(1);
    }
    // b. record API + memcmp.
    uint32_t out[WO];
    t0 = now();
    for (uint64_t s = 0; s < n; s++) {
        int rc = uvt_bsample(&recs[s * WI], out);
        bad += rc != UVT_OK || memcmp(out, &outs[s * WO], sizeof out) != 0;
    }
    rate("model-record", n, now() - t0);
    // c. record API + uvt_compare (every field through the library).
    t0 = now();
    for (uint64_t s = 0; s < n; s++) {
        int rc = uvt_bsample(&recs[s * WI], out);
        bad += rc != UVT_OK || uvt_compare(UVT_KIND_BSAMPLE, &outs[s * WO], out, WO, 0) != UVT_OK;
    }
    rate("model-record-uvt_compare", n, now() - t0);
    if (bad) {
        printf("FAIL %" PRIu64 " record results differ between runs\n", bad);
        exit(1);
    }
    for (UvtTri* h : handles) uvt_tri_free(h);
}

struct Item {
    uint64_t i;
    uint32_t in[WI], exp[WO], obs[WO];
};

int main(int argc, char** argv) {
    uint64_t seed = argc > 1 ? strtoull(argv[1], nullptr, 0) : 1;
    uint64_t n = argc > 2 ? strtoull(argv[2], nullptr, 0) : 200000;
    uint64_t tris = argc > 3 ? strtoull(argv[3], nullptr, 0) : 20000;
    uint32_t per_tri = argc > 4 ? (uint32_t)strtoul(argv[4], nullptr, 0) : 64;
    // corrupt: flip bit 0 of the expected depth of that sample (the run must fail); -1: none
    int64_t corrupt = argc > 5 ? strtoll(argv[5], nullptr, 0) : -1;
    Verilated::commandArgs(argc, argv);

    model_only(seed, tris, per_tri);

    Vuvt_bsample* dut = new Vuvt_bsample;
    Rng rng{seed};
    std::deque<Item> edge_q, depth_q;  // the scoreboard, in issue order
    uint64_t issued = 0, checked = 0, n_cov = 0, n_tie = 0, n_wle0 = 0;
    auto clock = [&] {
        dut->clk = 0;
        dut->eval();
        dut->clk = 1;
        dut->eval();
    };
    dut->in_valid = 0;
    for (int c = 0; c < 60; c++) clock();
    double t0 = now();
    while (checked < n) {
        dut->in_valid = 0;
        if (issued < n && rng.below(4) != 0) {
            Item it;
            it.i = issued++;
            stimulus(seed, it.i, rng, it.in);
            if (uvt_bsample(it.in, it.exp) != UVT_OK)
                fail(seed, it.i, uvt_last_error(), it.in, nullptr, nullptr);
            if ((int64_t)it.i == corrupt) it.exp[1] ^= 1;
            n_cov += it.exp[0] & 1;
            n_tie += (it.exp[8] | it.exp[9]) == 0 || (it.exp[10] | it.exp[11]) == 0 ||
                     (it.exp[12] | it.exp[13]) == 0;
            for (int k = 3; k < 30; k += 5)
                if ((int32_t)it.in[k] <= 0) {
                    n_wle0++;
                    break;
                }
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
        }
        clock();
        if (dut->edge_valid) {
            if (edge_q.empty()) fail(seed, issued, "edge_valid with no sample in flight", nullptr, nullptr, nullptr);
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
            if (depth_q.empty()) fail(seed, issued, "out_valid with no sample in flight", nullptr, nullptr, nullptr);
            Item& it = depth_q.front();
            it.obs[1] = dut->depth;
            if (memcmp(it.exp, it.obs, sizeof it.exp) != 0) {
                int rc = uvt_compare(UVT_KIND_BSAMPLE, it.exp, it.obs, WO, 0);
                fail(seed, it.i, rc == UVT_ERR_MISMATCH ? uvt_last_error() : "words differ",
                     it.in, it.exp, it.obs);
            }
            if (dut->out_covered != (it.exp[0] & 1))
                fail(seed, it.i, "field out_covered differs", it.in, it.exp, it.obs);
            depth_q.pop_front();
            checked++;
        }
    }
    rate("rtl-harness", n, now() - t0);
    dut->final();
    delete dut;
    printf("PASS %" PRIu64 " samples, %" PRIu64 " covered, %" PRIu64 " ties, %" PRIu64 " w<=0\n",
           checked, n_cov, n_tie, n_wle0);
    return 0;
}
