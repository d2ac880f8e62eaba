"""cocotb testbench of vectors/rtl/uvt_bsample.v against the uvt model (the uvt Python module).

Every sample is a bsample_in record of the model's seeded stimulus stream (uvt.gen: triangles
of every class, camera-plane crossers, w = 0 vertices, slivers, fill-rule ties, viewport
corners); half of them get a new random position and t, u, v in Python. The model's output
record (uvt.run, all samples in one call) is the expected one; the DUT is driven one record per
clock with random bubbles, and a scoreboard in issue order compares what comes out (fields named
by uvt.compare: every field, or with UVT_ARCH_ONLY=1 only covered and depth).

Environment:
  UVT_SEED        seed of the stream and of the randomisation (default 1)
  UVT_COCOTB_N    samples (default 800)
  UVT_ARCH_ONLY   1: compare covered and depth only, touching only the architectural ports
                  (docs/rtl.md, "Wiring your own unit"): a unit without edge ports runs
  UVT_CORRUPT     k: flip bit 7 of the expected depth of sample k (the check must fail)

On a mismatch it prints the seed, the sample number, the 37 input words and every differing
field expected/observed in hex, and fails. At the end it logs one line
"UVT_COCOTB_COVERAGE key=value ..." with the counts of what the run exercised.
"""

import collections
import random
import time

import cocotb
import numpy as np
from cocotb.clock import Clock
from cocotb.triggers import FallingEdge

import uvt
from bench import env_int, hexwords, mismatch_report, rare_path, word

KIND = "bsample"

MAX_REPORTED = 10  # mismatching samples printed before the run stops
FLUSH = 60  # idle clocks before the first sample (the valid pipeline starts unknown) and after
DRAIN = 200  # clocks the last results may take after the last sample


def randomise(rec, rng):
    """A new position in the viewport and new t, u, v (all on the default config's grid)."""
    vp_w, vp_h = rec[30] & 0xFFFF, rec[30] >> 16
    rec[32] = rng.randrange(256 * vp_w)
    rec[33] = rng.randrange(256 * vp_h)
    rec[34] = rng.randint(0, 65536)
    rec[35] = rng.randint(-65536, 65536) & 0xFFFFFFFF
    rec[36] = rng.randint(-65536, 65536) & 0xFFFFFFFF


def drive(dut, rec):
    trin = 0
    for k in range(30):
        trin |= rec[k] << (32 * k)
    dut.trin.value = trin
    dut.vp_w.value = rec[30] & 0xFFF
    dut.vp_h.value = (rec[30] >> 16) & 0xFFF
    dut.xs.value = rec[32] & 0xFFFFF
    dut.ys.value = rec[33] & 0xFFFFF
    dut.t.value = rec[34]
    dut.u.value = rec[35]
    dut.v.value = rec[36]
    dut.in_valid.value = 1



bit = word



@cocotb.test()
async def bsample_vs_model(dut):
    seed = env_int("UVT_SEED", 1)
    n = env_int("UVT_COCOTB_N", 800)
    arch_only = env_int("UVT_ARCH_ONLY", 0) != 0
    corrupt = env_int("UVT_CORRUPT", -1)
    rng = random.Random(seed)
    log = dut._log
    log.info(
        "UVT_SEED=%d UVT_COCOTB_N=%d%s%s, uvt module %s",
        seed, n, " UVT_ARCH_ONLY=1" if arch_only else "",
        f" UVT_CORRUPT={corrupt}" if corrupt >= 0 else "", getattr(uvt, "__file__", "?"),
    )
    assert corrupt < n, f"UVT_CORRUPT={corrupt} is not a sample of this run (N = {n})"

    # Stimulus and expected results, all up front (the simulation loop then only drives).
    t_start = time.perf_counter()
    recs = uvt.gen(KIND, uvt.DEFAULT_CONFIG, seed, n).tolist()
    rnds = []
    for rec in recs:
        rnds.append(rng.random() < 0.5)
        if rnds[-1]:
            randomise(rec, rng)
    inputs = np.array(recs, dtype=np.uint32).reshape(n, -1)
    try:
        exps = uvt.run(KIND, inputs).tolist()
    except uvt.UvtError:
        for i in range(n):  # name the record the model refused
            try:
                uvt.run(KIND, inputs[i : i + 1])
            except uvt.UvtError as e:
                raise AssertionError(
                    f"seed {seed} sample {i}: the model refused the record: {e}\n"
                    f"  inputs (bsample_in words 0..36): {hexwords(recs[i])}"
                ) from None
        raise
    samples = []
    cov = collections.Counter()
    for i, (rec, exp, rnd) in enumerate(zip(recs, exps, rnds)):
        if i == corrupt:
            exp[1] ^= 1 << 7
        samples.append((rec, exp, rnd))
        rare = rare_path(rec)
        cov["samples"] += 1
        cov["randomised"] += rnd
        cov["covered"] += exp[0] & 1
        cov["ties"] += any(exp[8 + 2 * k] == 0 and exp[9 + 2 * k] == 0 for k in range(3))
        cov["rare_path"] += rare
        cov["rare_path_covered"] += rare and (exp[0] & 1)
        cov["depth_saturated"] += (exp[0] & 1) and exp[1] in (0x7FFFFFFE, 0x80000000)
        cov[f"class{rec[31] & 3}"] += 1

    t_model = time.perf_counter() - t_start
    Clock(dut.clk, 10, unit="ns").start()
    dut.in_valid.value = 0
    for _ in range(FLUSH):
        await FallingEdge(dut.clk)

    edge_q = collections.deque()  # sample numbers awaiting edge results, in issue order
    depth_q = collections.deque()  # … awaiting depth
    partial = {}  # sample number -> observed words 0, 2..13 (edge stage)
    issued_at = {}
    latency = {}
    failures = []
    cycle = 0
    nxt = 0
    bubbles = 0
    idle_after = 0
    quiet = 0

    def fail(msg):
        failures.append(msg)
        log.error("%s", msg)

    def on_depth(i, out_covered, depth):
        rec, exp, rnd = samples[i]
        obs = partial.pop(i)
        obs[1] = depth
        if arch_only:
            obs[0] = out_covered
        if arch_only:
            same = (exp[0] & 1) == (obs[0] & 1) and exp[1] == obs[1]
        else:
            same = exp == obs
        fields = [] if same else mismatch_report(KIND, [rec], [exp], [obs], arch_only).get(0, [])
        if not same and not fields:
            fields.append("records differ, but no field is named (uvt.compare)")
        if out_covered != (exp[0] & 1):
            fields.append(
                f"field out_covered (with depth): expected {exp[0] & 1:#010x}, "
                f"observed {out_covered:#010x}"
            )
        if fields:
            fail(
                f"MISMATCH seed {seed} sample {i}{' (randomised)' if rnd else ''}: "
                f"{len(fields)} field(s) differ (rerun: UVT_SEED={seed} UVT_COCOTB_N={n})\n"
                + "".join(f"  {f}\n" for f in fields)
                + f"  inputs (bsample_in words 0..36): {hexwords(rec)}\n"
                + f"  expected (bsample_out words 0..13): {hexwords(exp)}\n"
                + f"  observed (bsample_out words 0..13): {hexwords(obs)}"
            )

    t_py = 0.0  # time in this coroutine's own code (reading, comparing, driving)
    t_sim0 = time.perf_counter()
    while len(failures) < MAX_REPORTED:
        await FallingEdge(dut.clk)
        t0 = time.perf_counter()
        cycle += 1
        # Outputs of the previous rising edge. Architectural mode touches only the
        # architectural ports (docs/rtl.md, "Wiring your own unit"): no edge port is read.
        ev = 0 if arch_only else bit(dut.edge_valid)
        ov = bit(dut.out_valid)
        if ev is None or ov is None:
            fail(f"seed {seed} cycle {cycle}: edge_valid {ev} "
                 f"out_valid {dut.out_valid.value} unknown")
            break
        if ev:
            if not edge_q:
                fail(f"seed {seed} cycle {cycle}: edge_valid with no sample outstanding")
                break
            i = edge_q.popleft()
            latency.setdefault("edge", cycle - issued_at[i])
            cv, ds = bit(dut.covered), word(dut.det_sign)
            ab, e = word(dut.ab), word(dut.e)
            if None in (cv, ds, ab, e):
                fail(f"seed {seed} sample {i}: edge outputs unknown (covered {dut.covered.value} "
                     f"det_sign {dut.det_sign.value} ab {dut.ab.value} e {dut.e.value})")
                break
            obs = [cv | (ds << 1), 0]
            obs += [(ab >> (32 * k)) & 0xFFFFFFFF for k in range(6)]
            for k in range(3):
                ek = (e >> (64 * k)) & 0xFFFFFFFFFFFFFFFF
                obs += [ek >> 32, ek & 0xFFFFFFFF]
            partial[i] = obs
        if ov:
            if not depth_q:
                fail(f"seed {seed} cycle {cycle}: out_valid with no sample outstanding")
                break
            i = depth_q.popleft()
            latency.setdefault("depth", cycle - issued_at[i])
            if arch_only:
                partial[i] = [0] * 14  # covered comes from out_covered (on_depth)
            if i not in partial:
                fail(f"seed {seed} sample {i}: depth came out before its edge results")
                break
            oc, d = bit(dut.out_covered), word(dut.depth)
            if oc is None or d is None:
                fail(f"seed {seed} sample {i}: depth outputs unknown (out_covered "
                     f"{dut.out_covered.value} depth {dut.depth.value})")
                break
            on_depth(i, oc, d)
        # Inputs for the next rising edge: a sample, or a bubble with junk on the data ports.
        if nxt < n and rng.random() >= 0.2:
            drive(dut, samples[nxt][0])
            if not arch_only:
                edge_q.append(nxt)
            depth_q.append(nxt)
            issued_at[nxt] = cycle
            nxt += 1
        else:
            dut.in_valid.value = 0
            if nxt < n:
                bubbles += 1
                dut.xs.value = rng.getrandbits(20)
                dut.t.value = rng.getrandbits(32)
            elif not edge_q and not depth_q:
                quiet += 1  # no spurious results after the last one
                if quiet >= FLUSH:
                    break
            elif idle_after > DRAIN:
                fail(f"seed {seed}: {len(edge_q)} edge and {len(depth_q)} depth results "
                     f"missing {DRAIN} clocks after the last sample")
                break
            else:
                idle_after += 1
        t_py += time.perf_counter() - t0

    t_sim = time.perf_counter() - t_sim0
    cov["bubbles"] = bubbles
    cov["cycles"] = cycle
    counts = " ".join(f"{k}={cov[k]}" for k in sorted(cov))
    log.info("UVT_COCOTB_COVERAGE %s", counts)
    log.info("latency: edge %s, depth %s clocks", latency.get("edge"), latency.get("depth"))
    log.info(
        "UVT_COCOTB_TIME samples=%d cycles=%d model_s=%.3f loop_s=%.3f python_in_loop_s=%.3f "
        "per_sample_us: model %.1f, python %.1f; per_clock_ms: simulator+cocotb %.2f",
        n, cycle, t_model, t_sim, t_py, 1e6 * t_model / max(n, 1), 1e6 * t_py / max(n, 1),
        1e3 * (t_sim - t_py) / max(cycle, 1),
    )
    if failures:
        raise AssertionError(
            f"UVT_SEED={seed}: {len(failures)} failure(s) (a run stops at {MAX_REPORTED}); "
            f"the first:\n{failures[0]}"
        )
    assert nxt == n, f"seed {seed}: only {nxt} of {n} samples issued"
    log.info("PASS %d samples, seed %d%s", n, seed, " (arch only)" if arch_only else "")
