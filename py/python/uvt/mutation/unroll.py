"""Proof by a bounded unrolling of the mutant's region: the second step of ABC's engine
(:mod:`.equiv`), for a mutant whose equivalence needs more than one clock of context.

Register correspondence (:mod:`.corr`) makes every register a free input, so a mutant whose
registers are equal to the unit's only in the states a pipeline can reach (a divider stage whose
remainder is below its divisor because the stages before it made it so) stays undecided. This
step keeps those stages:

1. **The mutant's cone.** With the select input at the mutant's number, the registers of the gate
   copy that the mutation can reach (forward through gates and registers from the select logic
   whose value differs from mutant 0's). Every other register keeps the class :mod:`.corr`
   proved for mutant 0: it reads nothing the mutation reaches, so its values are mutant 0's, and
   there its class holds in every reachable state.
2. **The region.** The classes of the cone and of every register within ``back`` register steps
   before it. A class outside the region is *cut*: a fresh free input at every clock (any value,
   so every real sequence of values is among them); one free input serves every register of the
   class.
3. **The unrolling.** The region has no loop (otherwise the step gives no verdict): every
   register in it is a function of the cut inputs and the unit's inputs of at most ``depth``
   clocks before. The miter's output is built at every clock 0..``depth`` from the all-zero
   start; at clock ``depth`` it no longer depends on the start, and every later clock is the same
   function of other free inputs. One ABC ``iprove`` on the OR of those outputs: unsatisfiable
   means no input sequence makes the architectural outputs differ.

A satisfiable check proves nothing while a cut class lies in the output's cone (the cut inputs
may take values the pipeline never makes); :func:`prove` then widens ``back``. With nothing cut
it is a bounded check from the all-zero start over every clock at which the outputs can differ,
exact: ``"differs"``."""

from __future__ import annotations

from pathlib import Path
from typing import Dict, Iterable, List, Optional, Set, Tuple

import numpy as np

from .corr import Corr, and_deltas, iprove, select

# The unrolled check is not built beyond this many ANDs (Python builds it).
CAP = 8_000_000


class Cone:
    """Fan-out of one build's miter (:class:`.corr.Corr` with its classes for mutant 0), built
    once and shared by every mutant."""

    def __init__(self, c: Corr):
        self.c = c
        g = c.aig
        c._compress()
        n = g.m + 1
        src = np.empty(2 * g.na + g.nl, dtype=np.int64)
        dst = np.empty_like(src)
        ands = np.array(g.ands, dtype=np.int64).reshape(-1, 3) >> 1
        src[:g.na], dst[:g.na] = ands[:, 1], ands[:, 0]
        src[g.na:2 * g.na], dst[g.na:2 * g.na] = ands[:, 2], ands[:, 0]
        src[2 * g.na:] = np.array(g.next, dtype=np.int64) >> 1
        dst[2 * g.na:] = np.arange(g.ni + 1, g.ni + 1 + g.nl)
        order = np.argsort(src, kind="stable")
        self.fo_dst = dst[order]
        self.fo_at = np.searchsorted(src[order], np.arange(n + 1))
        self.fanin: Dict[int, Tuple[int, int]] = {a >> 1: (b, cc) for a, b, cc in g.ands}
        # nodes that depend on nothing but the select input (the decode of mutsel)
        zs = {s >> 1 for s in c.sel}
        free = [False] * n
        for v in range(1, g.ni + g.nl + 1):
            free[v] = v not in zs
        for a, b, cc in g.ands:
            free[a >> 1] = free[b >> 1] or free[cc >> 1]
        self.selnodes = [(a, b, cc) for a, b, cc in g.ands if not free[a >> 1]]
        self.selvars = {a >> 1 for a, _, _ in self.selnodes} | zs

    def _selval(self, k: int) -> Dict[int, int]:
        val = {lit >> 1: b for lit, b in select(self.c.sel, k).items() if lit & 1 == 0}
        val[0] = 0
        for a, b, cc in self.selnodes:
            val[a >> 1] = (val[b >> 1] ^ (b & 1)) & (val[cc >> 1] ^ (cc & 1))
        return val

    def reach(self, k: int) -> Set[int]:
        """Latch indices the mutation ``k`` can reach (step 1 of the module docs)."""
        v0, vk = self._selval(0), self._selval(k)
        todo = [v for v in vk if v and v0.get(v) != vk[v]]
        seen = set(todo)
        g = self.c.aig
        lo, hi = g.ni + 1, g.ni + g.nl
        out = set()
        while todo:
            v = todo.pop()
            if lo <= v <= hi:
                out.add(v - lo)
            for w in self.fo_dst[self.fo_at[v]:self.fo_at[v + 1]].tolist():
                # the select logic's own values are known exactly (above)
                if w not in seen and w not in self.selvars:
                    seen.add(w)
                    todo.append(w)
        return out

    def support(self, lits: Iterable[int]) -> Tuple[Set[int], List[int]]:
        """Latch indices and AND variables (in no order) the combinational cones of ``lits``
        read, stopping at latches and inputs (each node once, however many cones share it)."""
        g = self.c.aig
        lo, hi = g.ni + 1, g.ni + g.nl
        latches, ands, seen = set(), [], set()
        todo = [x >> 1 for x in lits]
        while todo:
            v = todo.pop()
            if v in seen or v == 0:
                continue
            seen.add(v)
            if lo <= v <= hi:
                latches.add(v - lo)
            elif v in self.fanin:
                ands.append(v)
                b, cc = self.fanin[v]
                todo += [b >> 1, cc >> 1]
        return latches, ands


class _Builder:
    """A combinational AIG built node by node with structural hashing and constant folding."""

    def __init__(self) -> None:
        self.ands: List[Tuple[int, int]] = []      # node i has literal 2 * (i + 1) before renaming
        self.is_pi: List[bool] = []
        self.table: Dict[Tuple[int, int], int] = {}

    def pi(self) -> int:
        self.ands.append((0, 0))
        self.is_pi.append(True)
        return 2 * len(self.ands)

    def land(self, x: int, y: int) -> int:
        if x > y:
            x, y = y, x
        if x == 0 or x == y ^ 1:
            return 0
        if x == 1 or x == y:
            return y
        got = self.table.get((x, y))
        if got is None:
            self.ands.append((y, x))
            self.is_pi.append(False)
            got = self.table[(x, y)] = 2 * len(self.ands)
        return got

    def binary(self, out: int) -> bytes:
        """Binary AIGER: the inputs first, then the ANDs in creation order, one output."""
        ren = [0] * (len(self.ands) + 1)
        npi = 0
        for i, p in enumerate(self.is_pi):
            if p:
                npi += 1
                ren[i + 1] = npi
        nxt = npi
        for i, p in enumerate(self.is_pi):
            if not p:
                nxt += 1
                ren[i + 1] = nxt

        def r(x: int) -> int:
            return 2 * ren[x >> 1] | (x & 1)

        na = nxt - npi
        buf = bytearray(f"aig {nxt} {npi} 0 1 {na}\n{r(out)}\n".encode())
        for i, p in enumerate(self.is_pi):
            if p:
                continue
            y, x = self.ands[i]
            lhs, a, b = 2 * ren[i + 1], r(y), r(x)
            if a < b:
                a, b = b, a
            and_deltas(buf, lhs, a, b)
        return bytes(buf)


def check(cone: Cone, k: int, back: int, cap: int = CAP) -> Tuple[Optional[bytes], int]:
    """The unrolled check of mutant ``k`` with a region ``back`` register steps deep (module
    docs) as binary AIGER, and how many classes in the output's cone were cut; ``None`` when
    the region has a loop or the check would exceed ``cap`` ANDs."""
    c, g = cone.c, cone.c.aig
    hit = cone.reach(k)
    skip = set(c.selonly)
    # class heads for mutant k: a register the mutation reaches is its own class; a class whose
    # head it reaches takes its first register it does not
    head: List[int] = list(c.rep)
    moved: Dict[int, int] = {}
    for j in range(g.nl):
        if j in hit or j in skip:
            head[j] = j
        elif head[j] >= 0 and head[j] in hit:
            head[j] = moved.setdefault(c.rep[j], j)
    sup: Dict[int, Tuple[Set[int], List[int]]] = {}

    def preds(h: int) -> Set[int]:
        if h not in sup:
            sup[h] = cone.support([g.next[h]])
        return {head[x] for x in sup[h][0] if head[x] >= 0}

    # the region holds the cone and, for each register of it, the class it left (its partner
    # in the gold copy): both copies unrolled alike
    region: Set[int] = set(hit) | set(skip)
    for j in hit:
        r = c.rep[j]
        if r >= 0:
            r = moved.get(r) if r in hit else r
            if r is not None:
                region.add(r)
    frontier = set(region)
    for _ in range(back):
        frontier = {p for h in frontier for p in preds(h)} - region
        if not frontier:
            break
        region |= frontier
    # levels in the region (a loop: no verdict)
    level: Dict[int, int] = {}
    state: Dict[int, int] = {}
    for h0 in region:
        stack = [(h0, False)]
        while stack:
            h, done = stack.pop()
            if done:
                state[h] = 2
                level[h] = 1 + max((level[p] for p in preds(h) if p in region), default=-1)
                continue
            if state.get(h) == 2:
                continue
            if state.get(h) == 1:
                return None, 0
            state[h] = 1
            stack.append((h, True))
            stack += [(p, False) for p in preds(h) if p in region and state.get(p) != 2]
    depth = 1 + max(level.values(), default=0)
    # the ANDs each clock needs, in the miter's (topological) order
    # one walk for every clock's cone: the region's next values and the outputs
    read, need = cone.support([g.next[h] for h in region] + list(g.outs))
    if len(need) * (depth + 1) > cap:
        return None, 0
    order = sorted(need)
    cut = {head[x] for x in read if head[x] >= 0} - region
    sel = select(c.sel, k)
    bld = _Builder()
    cut_pi: Dict[Tuple[int, int], int] = {}
    lo = g.ni + 1
    prev: Dict[int, int] = {}                     # region head -> its literal at this clock
    trig = 0
    ins = {x >> 1 for x in g.inputs}
    for t in range(depth + 1):
        val: Dict[int, int] = {0: 0}

        def lit(x: int) -> int:
            v = x >> 1
            if v not in val:
                if v in ins:
                    val[v] = sel[2 * v] if 2 * v in sel else bld.pi()
                else:                             # a latch
                    h = head[v - lo]
                    if h < 0:
                        val[v] = 0
                    elif h in region:
                        val[v] = prev.get(h, 0) if t else 0
                    else:
                        if (h, t) not in cut_pi:
                            cut_pi[(h, t)] = bld.pi()
                        val[v] = cut_pi[(h, t)]
            return val[v] ^ (x & 1)

        for v in order:
            b, cc = cone.fanin[v]
            val[v] = bld.land(lit(b), lit(cc))
        out = lit(g.outs[0])
        for o in g.outs[1:]:
            out = bld.land(out ^ 1, lit(o) ^ 1) ^ 1
        trig = bld.land(trig ^ 1, out ^ 1) ^ 1
        prev = {h: lit(g.next[h]) for h in region}
    return bld.binary(trig), len(cut)


def prove(cone: Cone, k: int, work: Path, timeout: float,
          backs: Iterable[int] = (4, 12, 24)) -> str:
    """``"proven"``, ``"differs"`` or ``"undecided"`` for mutant ``k`` by the unrolled check
    (module docs), the region widened through ``backs`` while a cut check fails."""
    for back in backs:
        aig, cut = check(cone, k, back)
        if aig is None:
            return "undecided"
        got = iprove(aig, work / f"u{k}.aig", timeout)
        if got is True:
            return "proven"
        if got is None:
            return "undecided"
        if cut == 0:
            return "differs"
    return "undecided"
