"""Proof by register correspondence: the first, fast step of ABC's engine (:mod:`.equiv`).

The miter of a build holds two copies of one gate-level netlist, the unit with every mutant
behind its select input: gold with the select input tied to 0 (the unit itself, by ``mutate
-ctrl``'s construction), gate with it free. Registers are grouped in classes: the registers of
a class hold the same value in every reachable state, or all hold 0 (the constant class). Under
that hypothesis each class is one free input (its head), and the check asks, for every state and
input: the architectural outputs of the two copies equal, and every register's next value equal
to its head's (0 for the constant class). When no assignment breaks it (ABC's ``iprove`` finds
the check unsatisfiable) the hypothesis is inductive: it holds in the all-zero start and every
clock keeps it, so the outputs agree on every input sequence and the mutant is equivalent.
Nothing here assumes a record domain; a check that fails proves nothing (the mutant goes on to
``dprove``).

The classes come from the copies' names and structure with the select input at 0: each gate
register starts in the class of the gold register the AIGER map names alike (the copies are one
netlist, so the pair is equal in every reachable state of mutant 0; a miter of two million ANDs
would otherwise take one structural round per pipeline stage to pair them), then registers
whose next values are the same AND node once every register is replaced by its class's head
(constants folded) join one class, until nothing more joins. Registers that start at 0 and load the same
function of equal values are equal in every reachable state, so these classes hold by
construction for mutant 0; a counterexample ABC still finds splits the classes it tells apart
(van Eijk's refinement). The same classes then serve every mutant: only the select input, and
the registers it alone drives, change per mutant, so one mutant costs one ABC call on a check in
which the copies share everything the mutation does not reach."""

from __future__ import annotations

import re
import subprocess
from pathlib import Path
from typing import Callable, Dict, List, Optional, Sequence, Tuple

from .errors import MutationError

# Refinements of the classes before the check with the select input at 0 is given up.
_ROUNDS = 50


def select(lits: Sequence[int], k: int) -> Dict[int, int]:
    """Literal substitutions tying the select input's literals ``lits`` (LSB first) to the bits
    of ``k``."""
    sub: Dict[int, int] = {}
    for i, lit in enumerate(lits):
        bit = (k >> i) & 1
        sub[lit], sub[lit ^ 1] = bit, bit ^ 1
    return sub


class Aig:
    """An ASCII AIGER miter as Yosys writes it (inputs, latches, then ANDs in order)."""

    def __init__(self, text: str):
        rows = text.split("\n")
        head = rows[0].split()
        if len(head) < 6 or head[0] != "aag":
            raise MutationError("not an ASCII AIGER file")
        self.m, self.ni, self.nl, self.no, self.na = (int(x) for x in head[1:6])
        at = 1 + self.ni
        self.inputs = [int(r) for r in rows[1:at]]
        self.next = [int(r.split()[1]) for r in rows[at:at + self.nl]]
        at += self.nl
        self.outs = [int(r.split()[0]) for r in rows[at:at + self.no]]
        at += self.no
        self.ands = [(int(a), int(b), int(c)) for a, b, c in
                     (r.split() for r in rows[at:at + self.na])]

    def latch(self, j: int) -> int:
        """The literal of latch ``j``."""
        return 2 * (self.ni + 1 + j)

    def eval(self, val: List[int]) -> None:
        """Every AND of ``val`` (0 or 1 per variable) from the values of its inputs."""
        for a, b, c in self.ands:
            val[a >> 1] = (val[b >> 1] ^ (b & 1)) & (val[c >> 1] ^ (c & 1))


def and_deltas(out: bytearray, lhs: int, a: int, b: int) -> None:
    """Append binary AIGER's encoding of the AND ``lhs = a & b`` (``lhs > a >= b``): the two
    deltas ``lhs - a`` and ``a - b``, seven bits a byte, low first."""
    for d in (lhs - a, a - b):
        while d >= 0x80:
            out.append((d & 0x7F) | 0x80)
            d >>= 7
        out.append(d)


def _lit(val: List[int], x: int) -> int:
    return val[x >> 1] ^ (x & 1)


class Corr:
    """Register classes of one build's miter and the combinational check built from them."""

    def __init__(self, aig: Aig, sel: Sequence[int], pairs: Optional[Dict[int, int]] = None):
        self.aig = aig
        self.sel = list(sel)                 # the select input's literals, LSB first
        zs = {s >> 1 for s in sel}
        free = [False] * (aig.m + 1)         # depends on more than the select input
        for v in range(1, aig.ni + aig.nl + 1):
            free[v] = v not in zs
        for a, b, c in aig.ands:
            free[a >> 1] = free[b >> 1] or free[c >> 1]
        # Registers whose next value is a function of the select input alone (a constant
        # included): per mutant 0 when that function is 0 there, otherwise left free (0 at the
        # start, then 1). They join no class.
        self.selonly = [j for j in range(aig.nl) if not free[aig.next[j] >> 1]]
        self._skip = set(self.selonly)
        self.rep: List[int] = list(range(aig.nl))   # a register's class head, or -1 (0)
        for j, g in (pairs or {}).items():           # gate's latch -> gold's (module docs)
            if j not in self._skip and g not in self._skip and self.rep[g] == g:
                self.rep[j] = g
        self.structural()

    def _compress(self) -> None:
        for j, r in enumerate(self.rep):
            while r >= 0 and self.rep[r] != r:
                r = self.rep[r]
            self.rep[j] = r

    def structural(self) -> None:
        """Join registers whose next values are the same AND node (module docs), until none
        joins."""
        g = self.aig
        zs = {s >> 1 for s in self.sel}
        while True:
            self._compress()
            canon = list(range(0, 2 * (g.m + 1), 2))
            for v in zs:
                canon[v] = 0
            for j, r in enumerate(self.rep):
                canon[g.ni + 1 + j] = 0 if r < 0 or j in self._skip else g.latch(r)
            table: Dict[Tuple[int, int], int] = {}
            for a, b, c in g.ands:
                x, y = canon[b >> 1] ^ (b & 1), canon[c >> 1] ^ (c & 1)
                if x > y:
                    x, y = y, x
                if x == 0 or x == y ^ 1:
                    canon[a >> 1] = 0
                elif x == 1 or x == y:
                    canon[a >> 1] = y
                else:
                    canon[a >> 1] = table.setdefault((x, y), a)
            first: Dict[int, int] = {}
            joined = 0
            for j in range(g.nl):
                if j in self._skip or self.rep[j] != j:
                    continue
                n = canon[g.next[j] >> 1] ^ (g.next[j] & 1)
                h = -1 if n == 0 else first.setdefault(n, j)
                if h != j:
                    self.rep[j] = h
                    joined += 1
            if not joined:
                return

    def text(self) -> str:
        """The check as ASCII AIGER: the registers become inputs (a class member replaced by
        its head, or by 0), and the one output is 1 where an architectural output of the two
        copies differs or a register's next value differs from its head's."""
        g = self.aig
        self._compress()
        sub: Dict[int, int] = {}
        for j, r in enumerate(self.rep):
            if r != j:
                to = 0 if r < 0 else g.latch(r)
                sub[g.latch(j)], sub[g.latch(j) + 1] = to, to ^ 1
        top, extra = g.m, []

        def s(x: int) -> int:
            return sub.get(x, x)

        def land(a: int, b: int) -> int:
            nonlocal top
            top += 1
            extra.append((2 * top, a, b))
            return 2 * top

        def lor(a: int, b: int) -> int:
            return land(a ^ 1, b ^ 1) ^ 1

        acc = s(g.outs[0])
        for o in g.outs[1:]:
            acc = lor(acc, s(o))
        for j, r in enumerate(self.rep):
            if r != j:
                a, b = s(g.next[j]), 0 if r < 0 else s(g.next[r])
                acc = lor(acc, lor(land(a, b ^ 1), land(a ^ 1, b)))
        rows = [f"aag {top} {g.ni + g.nl} 0 1 {g.na + len(extra)}"]
        rows += [str(x) for x in g.inputs]
        rows += [str(g.latch(j)) for j in range(g.nl)]
        rows.append(str(acc))
        rows += [f"{a} {s(b)} {s(c)}" for a, b, c in g.ands]
        rows += [f"{a} {b} {c}" for a, b, c in extra]
        return "\n".join(rows) + "\n"

    def ties(self, k: int) -> Dict[int, int]:
        """Literal substitutions for mutant ``k``: the select input's bits, and 0 for every
        register the select input alone drives whose next value is 0 for ``k``."""
        g = self.aig
        sub = select(self.sel, k)
        val = [0] * (g.m + 1)
        for lit in self.sel:
            val[lit >> 1] = sub[lit]
        if self.selonly:
            g.eval(val)
            for j in self.selonly:
                if _lit(val, g.next[j]) == 0:
                    sub[g.latch(j)], sub[g.latch(j) + 1] = 0, 1
        return sub

    def refine(self, cex: Dict[int, int]) -> int:
        """Split the classes a counterexample of the check (input index of :meth:`text` ->
        value) tells apart; returns how many registers left their class."""
        g = self.aig
        val = [0] * (g.m + 1)
        for i in range(g.ni):
            val[i + 1] = cex.get(i, 0)
        for lit in self.sel:
            val[lit >> 1] = 0
        tied = self.ties(0)
        for j, r in enumerate(self.rep):
            if g.latch(j) in tied or r < 0:
                val[g.ni + 1 + j] = 0
            else:
                val[g.ni + 1 + j] = cex.get(g.ni + r, 0)
        g.eval(val)
        nxt = [_lit(val, n) for n in g.next]
        moved, fresh = 0, {}
        for j, r in enumerate(self.rep):
            if r != j and nxt[j] != (0 if r < 0 else nxt[r]):
                self.rep[j] = fresh.setdefault((r, nxt[j]), j)
                moved += 1
        return moved


def iprove(aig: bytes, f: Path, timeout: float, cex: Optional[Path] = None) -> Optional[bool]:
    """ABC's ``iprove`` on the binary AIGER ``aig`` (written to ``f`` for the run): True when
    its output can never be 1, False when ABC finds an assignment that sets it (written to
    ``cex`` when given), None without a verdict in ``timeout`` seconds."""
    f.write_bytes(aig)
    cmd = f"read_aiger {f}; strash; iprove" + (f"; write_cex -n {cex}" if cex else "")
    try:
        p = subprocess.run(["yosys-abc", "-c", cmd], capture_output=True, text=True,
                           timeout=timeout)
    except subprocess.TimeoutExpired:
        return None
    finally:
        f.unlink(missing_ok=True)
    words = re.findall(r"[A-Za-z]+", p.stdout)
    if "UNSATISFIABLE" in words:
        return True
    if "SATISFIABLE" in words:
        return False
    return None


def _cex(path: Path) -> Dict[int, int]:
    out = {}
    for row in path.read_text().splitlines():
        m = re.match(r"pi(\d+)@0=([01])", row)
        if m:
            out[int(m.group(1))] = int(m.group(2))
    return out


Binary = Callable[[str, Dict[int, int]], bytes]


def classes(aig: Aig, sel: Sequence[int], work: Path, binary: Binary,
            timeout: float, pairs: Optional[Dict[int, int]] = None) -> Optional[Corr]:
    """The classes of ``aig`` (select literals ``sel``; ``pairs``: registers named alike in the
    two copies, gate's latch index -> gold's) under which the check of mutant 0 holds, or None
    when refinement does not reach them in ``_ROUNDS`` rounds of at most ``timeout`` seconds.
    ``binary(text, ties)`` writes the binary AIGER ABC reads."""
    c = Corr(aig, sel, pairs)
    f, cx = work / "corr0.aig", work / "corr0.cex"
    for _ in range(_ROUNDS):
        cx.unlink(missing_ok=True)
        got = iprove(binary(c.text(), c.ties(0)), f, timeout, cx)
        if got is True:
            return c
        if got is None or not cx.is_file() or c.refine(_cex(cx)) == 0:
            return None
        # registers split from a wrong class join the one their next values now share
        c.structural()
    return None
