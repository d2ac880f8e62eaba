"""One build's mutation run: the mutated design, its simulator, the unmutated design checked
on every set (a flow whose reference fails proves nothing), then every mutant against the
committed sets in order, each stopping at its first mismatch."""

from __future__ import annotations

import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Dict, List, Optional, Tuple

from . import bench, design
from .errors import MutationError
from .units import Build


@dataclass
class Result:
    """A mutant's fate: ``killed`` by set ``set`` at ``record`` on ``field``, or ``survived``
    every set; how many records the sets ahead of the killing one held (records to kill =
    those + record + 1)."""

    mutation: design.Mutation
    set: Optional[str] = None
    record: int = -1
    field: str = ""
    records_before: int = 0

    @property
    def killed(self) -> bool:
        """Whether a committed set kills the mutant."""
        return self.set is not None

    def to_json(self) -> Dict:
        m = self.mutation
        d = {"id": m.id, "mode": m.mode, "cell": m.cell, "port": m.port, "portbit": m.portbit,
             "wire": m.wire, "wirebit": m.wirebit, "src": m.src, "mutate": m.alone()}
        if self.killed:
            d.update({"killed_by": self.set, "record": self.record, "field": self.field,
                      "records_to_kill": self.records_before + max(self.record, 0) + 1})
        else:
            d["killed_by"] = None
        return d


def set_sizes(repo: Path, b: Build, names: List[str]) -> Dict[str, int]:
    """Records per set (tb_mul: its corner and random pairs)."""
    out = {}
    for s in names:
        if s == "pairs":
            out[s] = 36 + bench.MUL_PAIRS
        else:
            stem = b.bench.stem
            out[s] = sum(1 for _ in open(repo / "vectors" / s / f"{stem}_out.hex"))
    return out


@dataclass
class Run:
    """A build's mutants, their results and the run's own figures."""

    build: Build
    seed: int
    sets: List[str]
    sizes: Dict[str, int]
    results: List[Result] = field(default_factory=list)
    seconds: float = 0.0
    #: verdicts judged again by Icarus on single-mutant netlists, all agreeing
    confirmed: int = 0


#: Mutants per simulator build. Verilator 5.006 mis-simulates some large select-input designs
#: (bsample-pipe2 with all 1000 mutants fails its own vectors at mutsel = 0, where Icarus passes
#: the same netlist and either half of it passes under Verilator), so a build holds at most this
#: many, and a group whose mutant 0 fails is split in two until each part passes.
CHUNK = 250


def run_build(repo: Path, b: Build, count: int, seed: int, work: Path, jobs: int = 2,
              upto: Optional[int] = None, cross: Tuple[int, int] = (0, 0), log=print) -> Run:
    """Mutate build ``b`` (``count`` mutants, ``seed``), build its simulators in ``work`` and
    judge every mutant (``upto``: mutants 1..upto of the list alone) against the committed sets;
    ``cross``: that many killed mutants and that many survivors judged again by Icarus on their
    own single-mutant netlists, which must agree (a survivor under Icarus runs every set:
    minutes for the bounds unit)."""
    t0 = time.time()
    muts = design.make(repo, b, count, seed, work)
    todo = [m for m in muts if upto is None or m.id <= upto]
    names = bench.sets(repo, b)
    sizes = set_sizes(repo, b, names)
    args = {s: bench.set_args(repo, b, s) for s in names}
    groups = [todo[k:k + CHUNK] for k in range(0, len(todo), CHUNK)]
    results: Dict[int, Result] = {}
    built = 0
    while groups:
        g = groups.pop(0)
        d = work / f"g{g[0].id}-{g[-1].id}"
        exe = bench.verilate(repo, b, design.netlist(repo, b, g, count, d), d, jobs)
        built += 1
        bad = next(((s, v) for s in names
                    for v in [bench.run([str(exe)], 0, args[s])] if v is not None), None)
        if bad is not None:
            if len(g) == 1:
                raise MutationError(
                    f"{b.name}: the select-input design of mutant {g[0].id} alone fails set "
                    f"{bad[0]} at record {bad[1][0]} field {bad[1][1]} at mutsel = 0 under "
                    "Verilator: no verdict of this flow holds for it")
            log(f"{b.name}: mutants {g[0].id}..{g[-1].id}: mutsel = 0 fails {bad[0]} under "
                "Verilator; split in two")
            groups[:0] = [g[:len(g) // 2], g[len(g) // 2:]]
            continue

        def judge(m: design.Mutation, exe=exe) -> Result:
            before = 0
            for s in names:
                v = bench.run([str(exe)], m.id, args[s])
                if v is not None:
                    return Result(m, s, v[0], v[1], before)
                before += sizes[s]
            return Result(m)

        with ThreadPoolExecutor(max_workers=jobs) as ex:
            for r in ex.map(judge, g):
                results[r.mutation.id] = r
    out = [results[m.id] for m in todo]
    checked = _cross(repo, b, out, names, args, work, cross)
    r = Run(b, seed, names, sizes, out, time.time() - t0, checked)
    k = sum(x.killed for x in out)
    log(f"{b.name}: {k} of {len(out)} killed by the committed sets ({built} simulator builds, "
        f"{checked} verdicts confirmed by Icarus, {r.seconds:.0f} s)")
    return r


def _cross(repo: Path, b: Build, out: List[Result], names: List[str], args: Dict, work: Path,
           n: Tuple[int, int]) -> int:
    """Judge the first ``n[0]`` killed mutants and the first ``n[1]`` survivors of ``out`` again
    under Icarus, each on its own single-mutant netlist (no select input); a verdict that
    differs is an error. The number confirmed."""
    pick = [x for x in out if x.killed][:n[0]] + [x for x in out if not x.killed][:n[1]]
    for x in pick:
        d = work / "icarus"
        cmd = bench.icarus(repo, b, design.single(repo, b, x.mutation, d), d)
        got = None
        for s in names:
            v = bench.run(cmd, 0, args[s], timeout=1800)
            if v is not None:
                got = (s, v[0], v[1])
                break
        want = (x.set, x.record, x.field) if x.killed else None
        if got != want:
            raise MutationError(f"{b.name} mutant {x.mutation.id}: Verilator (select input) says "
                                f"{want}, Icarus (single mutant) says {got}")
    return len(pick)
