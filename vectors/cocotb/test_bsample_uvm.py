"""pyuvm scoreboard example: vectors/rtl/uvt_bsample.v on its architectural ports against the uvt
Python module.

A UVM environment in pyuvm (on cocotb), the shape a verification team would give it:

  BsampleTest ── BsampleEnv ─┬─ sequencer ◄── BsampleSeq (seeded records of uvt.gen)
                             ├─ BsampleDriver ──── ports: in_valid, trin, vp_w, vp_h, xs, ys, t, u, v
                             │        └─ ap (each sample as it is driven) ─┐
                             ├─ BsampleMonitor ─── ports: out_valid, out_covered, depth
                             │        └─ ap (each result) ─────────────────┤
                             ├─ BsampleScoreboard ◄────────────────────────┘ (two analysis fifos)
                             │        uvt.run + uvt.compare(..., architectural=True) in one batch
                             └─ BsampleCoverage ◄── driver's ap: classes, covered, ties, rare path

Only the architectural ports are touched (docs/rtl.md, "Wiring your own unit"), so any unit with
those ports runs (`run.py --unit bsample_uvm --rtl DIR`). Results pair with samples in issue
order (any latency); the driver inserts random bubbles (in_valid low, junk on the data ports).
The scoreboard fails the test on a mismatching field, a result with no sample, a sample with no
result, or an X on out_valid after the initial flush.

Environment (as test_bsample.py):
  UVT_SEED        seed of the record stream and of the bubbles (default 1)
  UVT_COCOTB_N    samples (default 300)
  UVT_CORRUPT     k: flip bit 7 of sample k's expected depth (the scoreboard must fail)

A mismatch is reported as "MISMATCH seed S sample I: ..." with the differing fields (expected and
observed, decoded by the module) and the 37 input words; the coverage as one line
"UVT_COCOTB_COVERAGE key=value ...".
"""

import collections
import random

import cocotb
import numpy as np
import pyuvm
from cocotb.clock import Clock
from cocotb.triggers import FallingEdge
from pyuvm import (
    ConfigDB,
    uvm_analysis_port,
    uvm_component,
    uvm_driver,
    uvm_env,
    uvm_monitor,
    uvm_sequence,
    uvm_sequence_item,
    uvm_sequencer,
    uvm_subscriber,
    uvm_test,
    uvm_tlm_analysis_fifo,
)

import uvt
from bench import env_int, hexwords, mismatch_report, rare_path, word

KIND = "bsample"
FLUSH = 60  # idle clocks before the first sample (the valid pipeline starts unknown) and after
DRAIN = 200  # clocks the last result may take after the last sample
MAX_REPORTED = 10


class Sample(uvm_sequence_item):
    """One bsample_in record (37 words) and its number in the stream."""

    def __init__(self, name="sample", index=0, words=None):
        super().__init__(name)
        self.index = index
        self.words = words

    def __str__(self):
        return f"sample {self.index}: {hexwords(self.words)}"


class Result(uvm_sequence_item):
    """What the unit put out on one out_valid clock (None: X or Z)."""

    def __init__(self, name="result", covered=None, depth=None, cycle=0):
        super().__init__(name)
        self.covered = covered
        self.depth = depth
        self.cycle = cycle


class BsampleSeq(uvm_sequence):
    """The first N records of the model's seeded stimulus stream (uvt.gen): triangles of every
    class, camera-plane crossers, w = 0 vertices, slivers, fill-rule ties, viewport corners."""

    async def body(self):
        records = ConfigDB().get(None, "", "RECORDS")
        for i, rec in enumerate(records):
            item = Sample(f"sample{i}", i, [int(w) for w in rec])
            await self.start_item(item)
            await self.finish_item(item)


class BsampleDriver(uvm_driver):
    """Drives one sample per clock on the architectural input ports, with random bubbles, and
    publishes every sample as it drives it (ap), in issue order."""

    def build_phase(self):
        self.ap = uvm_analysis_port("ap", self)

    def start_of_simulation_phase(self):
        self.dut = cocotb.top
        self.rng = random.Random(ConfigDB().get(self, "", "SEED") * 7919 + 1)
        self.bubbles = 0

    def drive(self, rec):
        d = self.dut
        trin = 0
        for k in range(30):
            trin |= rec[k] << (32 * k)
        d.trin.value = trin
        d.vp_w.value = rec[30] & 0xFFF
        d.vp_h.value = (rec[30] >> 16) & 0xFFF
        d.xs.value = rec[32] & 0xFFFFF
        d.ys.value = rec[33] & 0xFFFFF
        d.t.value = rec[34]
        d.u.value = rec[35]
        d.v.value = rec[36]
        d.in_valid.value = 1

    async def run_phase(self):
        d = self.dut
        d.in_valid.value = 0
        for _ in range(FLUSH):
            await FallingEdge(d.clk)
        while True:
            item = await self.seq_item_port.get_next_item()
            while self.rng.random() < 0.2:  # a bubble: in_valid low, junk on the data ports
                d.in_valid.value = 0
                d.xs.value = self.rng.getrandbits(20)
                d.t.value = self.rng.getrandbits(32)
                self.bubbles += 1
                await FallingEdge(d.clk)
            self.drive(item.words)
            self.ap.write(item)
            await FallingEdge(d.clk)  # the rising edge in between took it
            d.in_valid.value = 0  # overridden at once when the sequence has another sample
            self.seq_item_port.item_done()


class BsampleMonitor(uvm_monitor):
    """Samples out_valid, out_covered and depth at every falling edge after the flush and
    publishes each result (ap)."""

    def build_phase(self):
        self.ap = uvm_analysis_port("ap", self)

    def start_of_simulation_phase(self):
        self.dut = cocotb.top
        self.results = 0

    async def run_phase(self):
        d = self.dut
        for _ in range(FLUSH):
            await FallingEdge(d.clk)
        cycle = FLUSH
        while True:
            await FallingEdge(d.clk)
            cycle += 1
            ov = word(d.out_valid)
            if ov == 0:
                continue
            # ov is 1, or None (X/Z: published as a result with unknown values, which the
            # scoreboard reports)
            cv = word(d.out_covered) if ov else None
            dp = word(d.depth) if ov else None
            self.results += 1
            self.ap.write(Result("result", cv, dp, cycle))


class BsampleCoverage(uvm_subscriber):
    """Counts what the driven samples exercise, from their records and the model's outputs."""

    def start_of_simulation_phase(self):
        self.samples = []

    def write(self, item):
        self.samples.append(item.words)

    def report_phase(self):
        cov = collections.Counter()
        if self.samples:
            recs = np.array(self.samples, dtype=np.uint32)
            exp = uvt.run(KIND, recs)
            for rec, out in zip(self.samples, exp.tolist()):
                cov["samples"] += 1
                cov[f"class{rec[31] & 3}"] += 1
                cov["covered"] += out[0] & 1
                cov["ties"] += any(out[8 + 2 * k] == 0 and out[9 + 2 * k] == 0 for k in range(3))
                rare = rare_path(rec)
                cov["rare_path"] += rare
                cov["rare_path_covered"] += rare and (out[0] & 1)
                cov["depth_saturated"] += (out[0] & 1) and out[1] in (0x7FFFFFFE, 0x80000000)
        self.counts = cov


class BsampleScoreboard(uvm_component):
    """Pairs samples and results in issue order and checks them against the model in one batch:
    uvt.run gives the expected records (UVT_CORRUPT alters one), uvt.compare names the
    differing architectural fields (covered, depth)."""

    def build_phase(self):
        self.issued = uvm_tlm_analysis_fifo("issued", self)
        self.results = uvm_tlm_analysis_fifo("results", self)
        self.issued_export = self.issued.analysis_export
        self.results_export = self.results.analysis_export

    def drain(self, fifo):
        items = []
        while True:
            ok, item = fifo.try_get()
            if not ok:
                return items
            items.append(item)

    def check_phase(self):
        seed = ConfigDB().get(self, "", "SEED")
        n = ConfigDB().get(self, "", "N")
        corrupt = ConfigDB().get(self, "", "CORRUPT")
        samples = self.drain(self.issued)
        results = self.drain(self.results)
        self.failures = []
        for r in results:
            if r.covered is None or r.depth is None:
                self.failures.append(
                    f"seed {seed} cycle {r.cycle}: out_valid, out_covered or depth is X/Z"
                )
                break
        if len(results) > len(samples):
            self.failures.append(
                f"seed {seed}: {len(results) - len(samples)} result(s) with no sample "
                f"({len(results)} results for {len(samples)} samples)"
            )
        elif len(results) < len(samples):
            self.failures.append(
                f"seed {seed}: {len(samples) - len(results)} sample(s) with no result "
                f"({DRAIN} clocks after the last)"
            )
        m = min(len(samples), len(results))
        self.pairs = m
        if m and not self.failures:
            inputs = np.array([s.words for s in samples[:m]], dtype=np.uint32)
            expected = uvt.run(KIND, inputs)
            if 0 <= corrupt < m:
                expected[corrupt, 1] ^= 1 << 7
            observed = np.zeros_like(expected)
            observed[:, 0] = [r.covered for r in results[:m]]
            observed[:, 1] = [r.depth for r in results[:m]]
            by_record = mismatch_report(KIND, inputs, expected, observed, architectural=True)
            for i in sorted(by_record)[:MAX_REPORTED]:
                s = samples[i]
                self.failures.append(
                    f"MISMATCH seed {seed} sample {s.index}: {len(by_record[i])} field(s) differ "
                    f"(rerun: UVT_SEED={seed} UVT_COCOTB_N={n})\n"
                    + "".join(f"  {f}\n" for f in by_record[i])
                    + f"  inputs (bsample_in words 0..36): {hexwords(s.words)}\n"
                    + f"  expected (covered, depth): {int(expected[i, 0]) & 1} "
                    + f"{int(expected[i, 1]):08x}, observed {results[i].covered} "
                    + f"{results[i].depth:08x}"
                )
            if len(by_record) > MAX_REPORTED:
                self.failures.append(f"... {len(by_record)} mismatching samples in all")
        for f in self.failures:
            self.logger.error("%s", f)


class BsampleEnv(uvm_env):
    def build_phase(self):
        self.seqr = uvm_sequencer("seqr", self)
        ConfigDB().set(None, "*", "SEQR", self.seqr)
        self.driver = BsampleDriver("driver", self)
        self.monitor = BsampleMonitor("monitor", self)
        self.scoreboard = BsampleScoreboard("scoreboard", self)
        self.coverage = BsampleCoverage("coverage", self)

    def connect_phase(self):
        self.driver.seq_item_port.connect(self.seqr.seq_item_export)
        self.driver.ap.connect(self.scoreboard.issued_export)
        self.driver.ap.connect(self.coverage.analysis_export)
        self.monitor.ap.connect(self.scoreboard.results_export)


@pyuvm.test()
class BsampleTest(uvm_test):
    """The seeded stream through the unit, checked by the scoreboard."""

    def build_phase(self):
        self.seed = env_int("UVT_SEED", 1)
        self.n = env_int("UVT_COCOTB_N", 300)
        corrupt = env_int("UVT_CORRUPT", -1)
        assert corrupt < self.n, f"UVT_CORRUPT={corrupt} is not a sample of this run (N = {self.n})"
        ConfigDB().set(None, "*", "SEED", self.seed)
        ConfigDB().set(None, "*", "N", self.n)
        ConfigDB().set(None, "*", "CORRUPT", corrupt)
        ConfigDB().set(None, "*", "RECORDS", uvt.gen(KIND, uvt.DEFAULT_CONFIG, self.seed, self.n))
        self.env = BsampleEnv("env", self)

    def start_of_simulation_phase(self):
        dut = cocotb.top
        Clock(dut.clk, 10, unit="ns").start()
        self.logger.info(
            "UVT_SEED=%d UVT_COCOTB_N=%d, uvt %s", self.seed, self.n,
            getattr(uvt, "__version__", "?"),
        )

    async def run_phase(self):
        self.raise_objection()
        dut = cocotb.top
        seq = BsampleSeq("seq")
        await seq.start(self.env.seqr)
        # The last sample is in; wait for its result (or DRAIN clocks), then FLUSH quiet clocks
        # in which any spurious result would be counted.
        for _ in range(DRAIN):
            if self.env.monitor.results >= self.n:
                break
            await FallingEdge(dut.clk)
        for _ in range(FLUSH):
            await FallingEdge(dut.clk)
        self.drop_objection()

    def report_phase(self):
        cov = self.env.coverage.counts
        cov["bubbles"] = self.env.driver.bubbles
        cov["results"] = self.env.monitor.results
        self.logger.info("UVT_COCOTB_COVERAGE %s", " ".join(f"{k}={cov[k]}" for k in sorted(cov)))
        failures = self.env.scoreboard.failures
        assert not failures, (
            f"UVT_SEED={self.seed}: {len(failures)} failure(s); the first:\n{failures[0]}"
        )
        self.logger.info("PASS %d samples, seed %d (pyuvm, architectural)", self.n, self.seed)
