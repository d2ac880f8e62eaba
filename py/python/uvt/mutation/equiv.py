"""Equivalence of a surviving mutant, decided by ABC (``yosys-abc``, shipped with Yosys). The unit
with the mutations behind their select input is mapped to gates once per build and instantiated
twice, each copy in its architectural view (the unit's inputs; its valid output and the
architectural data outputs, each forced to 0 while the valid is low: what the bench compares):
gold with the select input tied to 0 (the unit itself, by ``mutate -ctrl``'s construction; the
run stage checks it on every set), gate with the select input free. Both go in a miter (``miter
-equiv``) written as AIGER with every register starting at 0. Mapping once and copying keeps the
two copies the same gates (two mappings of one multiplier can sum its partial products in
different orders, which no SAT sweep undoes in time). Per mutant the select input is tied to its
number (:func:`tie`, on the AIGER text: no second Yosys run), then:

1. register correspondence (:mod:`.corr`): the registers of the two copies paired by structure,
   the miter made combinational, one ABC ``iprove``: unsatisfiable means equivalent;
2. otherwise the unrolled region (:mod:`.unroll`): the registers the mutation reaches and the
   stages before them kept as registers over the clocks the region spans, the rest cut to free
   inputs, one ABC ``iprove`` (a proof that needs a reachable-state fact such as a divider's
   remainder below its divisor, made a few stages earlier);
3. otherwise ABC's ``dprove``: bounded model checking from the all-zero state, then sequential
   simplification (signal correspondence), induction, interpolation and property-directed
   reachability.

Both copies see the unit's inputs through the record domain of its bench (``Bench.domain``:
for the planar unit the depth exponent's reachable range, the viewport's sides, the sample
inside the viewport, σ = ±1, no zero normal; other units state none yet, so their inputs are
free). ``proven``: no input sequence of that domain from the all-zero state makes the
architectural outputs differ; no record can catch the mutant. ``differs``: ABC found inputs of
that domain that tell them apart (for a unit with no stated domain they may lie outside every
record's): the mutant stays to be killed or argued. ``undecided``: no verdict within
``timeout`` seconds.
Before any mutant, mutant 0 (the unit against itself) must prove by one of the two steps; a step
that cannot prove it is not used for the build."""

from __future__ import annotations

import hashlib
import re
import shutil
import subprocess
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Dict, Iterator, List, Sequence, Tuple

from . import corr, unroll
from .design import Mutation, _read, sel_width
from .errors import MutationError
from .units import Build


def ports(netlist: Path, top: str) -> List[Tuple[str, str, int]]:
    """(direction, name, width) of each port of ``top`` in a netlist Yosys wrote (``mutsel``
    left out)."""
    text = netlist.read_text()
    i = text.index(f"module {top}(")
    mod = text[i:text.index("endmodule", i)]
    out = []
    for d, w, n in re.findall(r"\n  (input|output) (?:\[(\d+):0\] )?(\w+);", mod):
        if n != "mutsel":
            out.append((d, n, int(w) + 1 if w else 1))
    return out


def wrapper(b: Build, pts: List[Tuple[str, str, int]], unit: str, name: str) -> str:
    """Verilog of module ``name``: ``unit`` seen through its architectural outputs, its inputs
    through the record domain of its bench (``Bench.domain``: every input value outside it
    mapped to one inside)."""
    bench = b.bench
    ins = [(n, w) for d, n, w in pts if d == "input"]
    outs = [n for n in ([bench.valid] if bench.valid else []) + list(bench.outputs)]
    width = {n: w for _, n, w in pts}
    decl = [f"    input wire [{w - 1}:0] {n}" for n, w in ins]
    decl += [f"    output wire [{width[n] - 1}:0] o_{n}" for n in outs]
    dom = dict(bench.domain)
    conns = [f".{n}({'d_' if n in dom else ''}{n})" for n, _ in ins]
    conns += [f".{n}(w_{n})" for n in outs]
    body = [f"    wire [{width[n] - 1}:0] d_{n} = {e};" for n, e in bench.domain]
    body += [f"    wire [{width[n] - 1}:0] w_{n};" for n in outs]
    body.append(f"    {unit} unit_i ({', '.join(conns)});")
    for n in outs:
        if bench.valid and n != bench.valid:
            body.append(f"    assign o_{n} = w_{bench.valid} ? w_{n} : {width[n]}'d0;")
        else:
            body.append(f"    assign o_{n} = w_{n};")
    return f"module {name} (\n" + ",\n".join(decl) + "\n);\n" + "\n".join(body) + "\nendmodule\n"


def _aigs(repo: Path, b: Build, muts: List[Mutation], count: int, netlist: Path,
          work: Path) -> Tuple[str, List[int], Dict[int, int]]:
    """The miter of the unit and every mutation of ``muts`` (of a list of ``count``) as ASCII
    AIGER, from one Yosys process (module docs): the unit with the mutations behind its select
    input (MCY's way) mapped to gates, one copy with the select input at 0 (gold) and one with
    it free (gate), each in its architectural view, in a miter (``miter -equiv``), every
    register starting at 0. Returns the file's text, the AIGER literal of each select bit
    (LSB first; :func:`tie` fixes them to one mutant) and the pairs of registers the map names
    alike in the two copies (gate's latch index -> gold's: :func:`corr.classes` starts from
    them)."""
    work.mkdir(parents=True, exist_ok=True)
    top = b.top
    pts = ports(netlist, top)
    w = sel_width(count)
    sel = f"    input wire [{w - 1}:0] mutsel,\n"
    (work / "gold.v").write_text(wrapper(b, pts, "mut_u", "gold").replace("(\n", "(\n" + sel, 1)
                                 .replace(" unit_i (", f" unit_i (.mutsel({w}'d0), ", 1))
    (work / "gate.v").write_text(wrapper(b, pts, "mut_u", "gate").replace("(\n", "(\n" + sel, 1)
                                 .replace(" unit_i (", " unit_i (.mutsel(mutsel), ", 1))
    want = [m.selected(w) for m in muts]
    apply = work / "apply.txt"
    aag, amap = work / "miter.aag", work / "miter.map"
    # The second techmap maps the miter's own compare cells; the copies are gates already.
    script = [_read(b), f"script {apply}\nopt_clean\ntechmap\nopt_clean\n"
              f"rename {top} mut_u\nread_verilog {work / 'gold.v'}\n"
              f"read_verilog {work / 'gate.v'}\nflatten gold gate\n"
              "miter -equiv gold gate miter\nhierarchy -top miter\nflatten\ntechmap\n"
              "opt_clean\nsetundef -zero -init\ndffunmap\naigmap\nopt_clean\n"
              f"write_aiger -ascii -zinit -map {amap} {aag}\n"]
    ys = work / "aig.ys"
    ys.write_text("".join(script))

    def stamp() -> str:
        # the script, the wrappers, the mutations applied and the sources
        return hashlib.sha256("".join(script).encode() + b"".join(
            f.read_bytes() for f in [work / "gold.v", work / "gate.v", apply,
                                     *(repo / s for s in b.source_paths())])).hexdigest()

    # Kept while nothing above changed (minutes of Yosys per build); a miter built for more
    # mutants serves a later run for fewer (the sets killed some since).
    st = work / "aig.stamp"
    held = set(apply.read_text().splitlines()) if apply.is_file() else set()
    if not (held.issuperset(want) and aag.is_file() and amap.is_file() and st.is_file()
            and st.read_text() == stamp()):
        st.unlink(missing_ok=True)
        apply.write_text("".join(x + "\n" for x in want))
        p = subprocess.run(["yosys", "-q", "-s", str(ys)], cwd=repo, capture_output=True,
                           text=True)
        if p.returncode != 0 or not aag.is_file():
            raise MutationError(f"{b.name}: yosys {ys} failed:\n{p.stdout[-2000:]}"
                                f"{p.stderr[-2000:]}")
        st.write_text(stamp())
    # The map names input k (the k-th input line) "input k bit name", latch j "latch j bit
    # name" (once per name it carries: "gold.unit_i.s4_gx" and "gate.unit_i.s4_gx").
    text = aag.read_text()
    lines = text.split("\n", 1 + int(text.split()[2]))
    lits = [0] * w
    named: Dict[str, Dict[Tuple[str, str], int]] = {"gold": {}, "gate": {}}
    for row in amap.read_text().splitlines():
        f = row.split()
        if f[0] == "input" and f[3] == "in_mutsel":
            lits[int(f[2])] = int(lines[1 + int(f[1])])
        elif f[0] == "latch" and f[3][:4] in named:
            named[f[3][:4]][(f[3][4:], f[2])] = int(f[1])
    if 0 in lits:
        raise MutationError(f"{b.name}: {amap} does not name every bit of in_mutsel")
    gold = named["gold"]
    pairs = {j: gold[k] for k, j in named["gate"].items() if k in gold and gold[k] != j}
    return text, lits, pairs


def tie(aag: str, lits: List[int], k: int) -> bytes:
    """The ASCII AIGER ``aag`` as binary AIGER (what ABC reads) with the input literals
    ``lits`` (LSB first) tied to the bits of ``k`` (:func:`binary`)."""
    return binary(aag, corr.select(lits, k))


def binary(aag: str, sub: Dict[int, int]) -> bytes:
    """The ASCII AIGER ``aag`` as binary AIGER, every use of a literal of ``sub`` (in a latch's
    next state, an output or an AND) replaced by its value there; the inputs stay declared.
    Yosys numbers the ASCII file as the binary format needs (inputs, latches, then ANDs in
    order), so the ANDs are written as deltas after the substitution, each pair of operands
    sorted."""
    rows = aag.split("\n")
    m, ni, nl, no, na = (int(x) for x in rows[0].split()[1:6])
    out = bytearray(f"aig {m} {ni} {nl} {no} {na}\n".encode())
    at = 1 + ni
    for row in rows[at:at + nl + no]:
        f = row.split()
        cut = 1 if len(f) >= 2 else 0        # a latch: its own literal is implicit in binary
        out += (" ".join(str(sub.get(int(x), x)) for x in f[cut:]) + "\n").encode()
    at += nl + no
    lhs_first = 2 * (ni + nl + 1)
    for n, row in enumerate(rows[at:at + na]):
        lhs, a, c = (int(x) for x in row.split())
        if lhs != lhs_first + 2 * n:
            raise MutationError(f"AIGER AND {n} defines {lhs}, not {lhs_first + 2 * n}")
        a, c = sub.get(a, a), sub.get(c, c)
        if a < c:
            a, c = c, a
        corr.and_deltas(out, lhs, a, c)
    return bytes(out)


class Unprovable(MutationError):
    """Neither step proves mutant 0 (the unit against itself) on a build in time: no verdict on
    it would mean anything."""


def verdict(text: str) -> str:
    """ABC's ``dprove`` verdict in the report's words. It ends with "Networks are equivalent"
    (or "UNSATISFIABLE" when the miter's output, once its registers are simplified away, can
    never be 1), "... not equivalent" with the frame a difference shows, or neither."""
    words = re.findall(r"[A-Za-z]+", text)
    if "Networks are equivalent" in text or "UNSATISFIABLE" in words:
        return "proven"
    if "was asserted in frame" in text or "SATISFIABLE" in words:
        return "differs"
    return "undecided"


STEPS = ("corr", "unroll", "dprove")


def prove(repo: Path, b: Build, held: List[Mutation], muts: List[Mutation], count: int,
          netlist: Path, work: Path, timeout: float, jobs: int,
          steps: Sequence[str] = STEPS) -> Iterator[Tuple[int, str]]:
    """Per mutant of ``muts`` (of a list of ``count``; ``netlist``: a netlist of the build,
    read for the port list), as each ends: the verdict on its miter (:func:`_aigs` of the
    mutants ``held``, which include ``muts``; :func:`tie`) by the ``steps`` of :data:`STEPS`
    in that order: register correspondence, the unrolled region (:mod:`.unroll`), ABC's
    ``dprove`` (module docs): ``"proven"``, ``"differs"`` (inputs found that tell them apart)
    or ``"undecided"`` (no verdict within ``timeout`` seconds per step). ``jobs`` ABC processes
    at a time."""
    if shutil.which("yosys-abc") is None:
        raise MutationError("yosys-abc not found (Debian package yosys; tests/run.sh installs it)")
    bad = [s for s in steps if s not in STEPS]
    if bad or not steps:
        raise MutationError(f"steps {','.join(steps)}: each one of {', '.join(STEPS)}")
    ids = {m.id for m in held}
    if any(m.id not in ids for m in muts):
        raise MutationError(f"{b.name}: a mutant to prove is not in the miter")
    aag, lits, pairs = _aigs(repo, b, held, count, netlist, work)
    first = max(timeout, 60.0)
    # Mutant 0 (the unit against itself) must prove by a step, or that step's verdicts mean
    # nothing on this build. The unrolled region builds on the correspondence's classes.
    need_cr = "corr" in steps or "unroll" in steps
    cr = corr.classes(corr.Aig(aag), lits, work, binary, first, pairs) if need_cr else None
    check = cr.text() if cr is not None and "corr" in steps else None
    cone = unroll.Cone(cr) if cr is not None and "unroll" in steps else None
    seq = "dprove" in steps and _dprove(work / "m0.aig", tie(aag, lits, 0), first) == "proven"
    if cr is None and not seq:
        raise Unprovable(f"{b.name}: neither register correspondence nor ABC's dprove proves "
                         f"the unit equivalent to itself (the select input at 0) in {first:.0f} "
                         f"s ({work})")

    def one(m: Mutation) -> Tuple[int, str]:
        if check is not None and corr.iprove(
                binary(check, cr.ties(m.id)), work / f"c{m.id}.aig", timeout) is True:
            return m.id, "proven"
        got = "undecided"
        if cone is not None:
            got = unroll.prove(cone, m.id, work, timeout)
            if got != "undecided":
                return m.id, got
        if not seq:
            return m.id, got
        return m.id, _dprove(work / f"m{m.id}.aig", tie(aag, lits, m.id), timeout)

    with ThreadPoolExecutor(max_workers=jobs) as ex:
        yield from ex.map(one, muts)


def _dprove(f: Path, aig: bytes, timeout: float) -> str:
    """ABC's verdict on the miter ``aig`` (written to ``f`` for the run, then removed)."""
    f.write_bytes(aig)
    try:
        p = subprocess.run(["yosys-abc", "-c", f"read_aiger {f}; strash; dprove"],
                           capture_output=True, text=True, timeout=timeout)
        got = verdict(p.stdout)
    except subprocess.TimeoutExpired:
        got = "undecided"
    f.unlink()
    return got


def prove_sat(repo: Path, b: Build, muts: List[Mutation], netlist: Path, work: Path,
               depth: int, timeout: float) -> Dict[int, str]:
    """The second engine, for a miter too large for ABC's flow (the unit against itself does not
    prove: :class:`Unprovable`): per mutant its own miter, the select input gone before the
    shared logic of unit and mutant is merged (``opt_merge -share_all``: only the mutation's
    fan-out cone stays twice), then Yosys's ``sat -tempinduct`` from the all-zero state (a unit
    without feedback proves at a depth of about its latency). Per mutant of ``muts`` of build
    ``b``: ``"proven"`` when Yosys proves it equivalent to the unit in its architectural view (``netlist``: a netlist of the build, read for the port
    list), ``"differs"`` when it finds inputs that tell them apart, ``"undecided"`` when the
    proof ran out of ``depth`` clocks or of ``timeout`` seconds of solving (``sat
    -timeout``). One Yosys process reads and elaborates the unit once for all of ``muts``."""
    work.mkdir(parents=True, exist_ok=True)
    top = b.top
    pts = ports(netlist, top)
    (work / "gold.v").write_text(wrapper(b, pts, "gold_u", "gold"))
    (work / "gate.v").write_text(wrapper(b, pts, "gate_u", "gate"))
    script = [_read(b), "design -save orig\n"]
    for m in muts:
        script.append(
            f"design -load orig\n{m.alone()}\nrename {top} gate_u\n"
            f"read_verilog {work / 'gate.v'}\ndesign -stash gate\n"
            f"design -load orig\nrename {top} gold_u\nread_verilog {work / 'gold.v'}\n"
            f"design -copy-from gate gate gate_u\n"
            f"miter -equiv -flatten -make_assert gold gate miter\nhierarchy -top miter\n"
            f"opt_clean\nopt_merge -share_all\nopt_clean\n"
            f"tee -q -o {work / f'eq{m.id}.txt'} sat -tempinduct -prove-asserts -set-init-zero "
            f"-seq 1 -maxsteps {depth} -timeout {int(timeout)} miter\n")
    ys = work / "prove.ys"
    ys.write_text("".join(script))
    p = subprocess.run(["yosys", "-q", "-s", str(ys)], cwd=repo, capture_output=True, text=True)
    out = {}
    for m in muts:
        f = work / f"eq{m.id}.txt"
        text = f.read_text() if f.is_file() else ""
        if "Induction step proven: SUCCESS!" in text:
            out[m.id] = "proven"
        elif "model found for base case" in text:
            out[m.id] = "differs"
        elif text or p.returncode == 0:
            out[m.id] = "undecided"
        else:
            raise MutationError(f"{b.name}: yosys {ys} failed before mutant {m.id}:\n"
                                f"{p.stdout[-2000:]}{p.stderr[-2000:]}")
    return out
