"""cocotb testbench of vectors/rtl/uvt_psample.v (the planar static sample test) against the uvt
model (the uvt Python module): the planar counterpart of test_bsample.py.

Every sample is a psample_in record of the model's seeded stream (uvt.gen, planar-16-16-16-20:
static triangles of every family — crossers, w = 0 vertices, slivers, fill-rule ties, depths
beyond both clamps — with the planar setup's output the unit reads); half of them get a new
random position in Python (the setup fields stay valid). The DUT is driven one record per clock
with random bubbles; a scoreboard in issue order compares covered, depth and E_k with the model's
output (uvt.run; fields named by uvt.compare: every field, or with UVT_ARCH_ONLY=1 covered and
depth only).

Environment: UVT_SEED, UVT_COCOTB_N (default 600), UVT_ARCH_ONLY, UVT_CORRUPT (as
test_bsample.py). At the end it logs "UVT_COCOTB_COVERAGE key=value ...".
"""

import collections
import random

import cocotb
import numpy as np
from cocotb.clock import Clock
from cocotb.triggers import FallingEdge

import uvt
from bench import env_int, hexwords, mismatch_report, word

KIND = "psample"
CONFIG = "planar-16-16-16-20"

MAX_REPORTED = 10
FLUSH = 20  # idle clocks before the first sample and after the last result
DRAIN = 200





def drive(dut, rec):
    """psample_in words → ports, as vectors/rtl/tb_psample.v wires them."""
    dut.vp_w.value = rec[12] & 0xFFF
    dut.vp_h.value = (rec[12] >> 16) & 0xFFF
    n = 0
    for k in range(9):
        n |= rec[13 + k] << (32 * k)
    dut.n.value = n
    dut.sigma.value = rec[22] & 3
    dut.f.value = (rec[22] >> 2) & 0xFF
    g = 0
    for k in range(3):
        g |= rec[23 + k] << (32 * k)
    dut.g.value = g
    dut.xs.value = rec[26] & 0xFFFFF
    dut.ys.value = rec[27] & 0xFFFFF
    dut.in_valid.value = 1


@cocotb.test()
async def psample_vs_model(dut):
    seed = env_int("UVT_SEED", 1)
    n = env_int("UVT_COCOTB_N", 600)
    arch_only = env_int("UVT_ARCH_ONLY", 0) != 0
    corrupt = env_int("UVT_CORRUPT", -1)
    rng = random.Random(seed)
    log = dut._log
    assert corrupt < n, f"UVT_CORRUPT={corrupt} is not a sample of this run (N = {n})"

    recs = uvt.gen(KIND, CONFIG, seed, n).tolist()
    rnds = []
    for rec in recs:
        rnds.append(rng.random() < 0.5)
        if rnds[-1]:
            rec[26] = rng.randrange(256 * (rec[12] & 0xFFFF))
            rec[27] = rng.randrange(256 * (rec[12] >> 16))
    exps = uvt.run(KIND, np.array(recs, dtype=np.uint32).reshape(n, -1)).tolist()
    samples = []
    cov = collections.Counter()
    for i, (rec, exp, rnd) in enumerate(zip(recs, exps, rnds)):
        if i == corrupt:
            exp[1] ^= 1 << 7
        samples.append((rec, exp, rnd))
        cov["samples"] += 1
        cov["randomised"] += rnd
        cov["covered"] += exp[0] & 1
        cov["ties"] += any(exp[2 + 2 * k] == 0 and exp[3 + 2 * k] == 0 for k in range(3))
        cov["clockwise"] += (rec[22] & 3) == 3
        cov["depth_saturated"] += (exp[0] & 1) and exp[1] in (0x7FFFFFFE, 0x80000000)

    Clock(dut.clk, 10, unit="ns").start()
    dut.in_valid.value = 0
    for _ in range(FLUSH):
        await FallingEdge(dut.clk)

    queue = collections.deque()
    failures = []
    nxt = cycle = bubbles = quiet = idle_after = 0
    while len(failures) < MAX_REPORTED:
        await FallingEdge(dut.clk)
        cycle += 1
        ov = word(dut.out_valid)
        if ov is None:
            failures.append(f"seed {seed} cycle {cycle}: out_valid unknown")
            break
        if ov:
            if not queue:
                failures.append(f"seed {seed} cycle {cycle}: out_valid with no sample outstanding")
                break
            i = queue.popleft()
            rec, exp, rnd = samples[i]
            # Architectural mode reads only the architectural ports: no edge values.
            cv, d = word(dut.covered), word(dut.depth)
            e = 0 if arch_only else word(dut.e)
            if None in (cv, d, e):
                failures.append(f"seed {seed} sample {i}: outputs unknown")
                break
            obs = [cv, d]
            for k in range(3):
                ek = (e >> (64 * k)) & 0xFFFFFFFFFFFFFFFF
                obs += [ek >> 32, ek & 0xFFFFFFFF]
            if arch_only:
                same = (exp[0] & 1) == (obs[0] & 1) and exp[1] == obs[1]
            else:
                same = exp == obs
            fields = [] if same else mismatch_report(KIND, [rec], [exp], [obs], arch_only).get(0, [])
            if not same and not fields:
                fields.append("records differ, but no field is named (uvt.compare)")
            if fields:
                msg = (
                    f"MISMATCH seed {seed} sample {i}{' (randomised)' if rnd else ''}: "
                    f"{len(fields)} field(s) differ (rerun: UVT_SEED={seed} UVT_COCOTB_N={n})\n"
                    + "".join(f"  {f}\n" for f in fields)
                    + f"  inputs (psample_in words 0..27): {hexwords(rec)}\n"
                    + f"  expected (psample_out words 0..7): {hexwords(exp)}\n"
                    + f"  observed (psample_out words 0..7): {hexwords(obs)}"
                )
                failures.append(msg)
                log.error("%s", msg)
        if nxt < n and rng.random() >= 0.2:
            drive(dut, samples[nxt][0])
            queue.append(nxt)
            nxt += 1
        else:
            dut.in_valid.value = 0
            if nxt < n:
                bubbles += 1
                dut.xs.value = rng.getrandbits(20)
            elif not queue:
                quiet += 1
                if quiet >= FLUSH:
                    break
            elif idle_after > DRAIN:
                failures.append(f"seed {seed}: {len(queue)} results missing {DRAIN} clocks "
                                f"after the last sample")
                break
            else:
                idle_after += 1

    cov["bubbles"] = bubbles
    cov["cycles"] = cycle
    log.info("UVT_COCOTB_COVERAGE %s", " ".join(f"{k}={cov[k]}" for k in sorted(cov)))
    if failures:
        raise AssertionError(
            f"UVT_SEED={seed}: {len(failures)} failure(s) (a run stops at {MAX_REPORTED}); "
            f"the first:\n{failures[0]}"
        )
    assert nxt == n, f"seed {seed}: only {nxt} of {n} samples issued"
    log.info("PASS %d samples, seed %d%s", n, seed, " (arch only)" if arch_only else "")
