"""Equivalence of a surviving mutant, proven by Yosys. Gold is the unit, gate the unit with the
one mutation; each is wrapped in its architectural view (the unit's inputs; its valid output and
the architectural data outputs, each forced to 0 while the valid is low: what the bench
compares), both go in a miter (``miter -equiv``) whose shared logic is merged
(``opt_merge -share_all``: only the mutation's fan-out cone stays twice), then
``sat -tempinduct``: outputs equal for k clocks from any state imply equal outputs the next
clock, and from the all-zero state they are equal for k clocks. A unit without feedback (each
reference unit: its registers carry records down the pipeline) proves at a k of its latency
when the mutant is equivalent. The inputs are free (no record domain is assumed), so a
counterexample may lie outside the records' domains: ``differs`` means "not proven", and the
mutant stays to be killed or argued. A run that does not end within ``timeout`` seconds proves
nothing either."""

from __future__ import annotations

import re
import subprocess
from pathlib import Path
from typing import Dict, List, Tuple

from .design import Mutation, _read
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
    """Verilog of module ``name``: ``unit`` seen through its architectural outputs."""
    bench = b.bench
    ins = [(n, w) for d, n, w in pts if d == "input"]
    outs = [n for n in ([bench.valid] if bench.valid else []) + list(bench.outputs)]
    width = {n: w for _, n, w in pts}
    decl = [f"    input wire [{w - 1}:0] {n}" for n, w in ins]
    decl += [f"    output wire [{width[n] - 1}:0] o_{n}" for n in outs]
    conns = [f".{n}({n})" for n, _ in ins] + [f".{n}(w_{n})" for n in outs]
    body = [f"    wire [{width[n] - 1}:0] w_{n};" for n in outs]
    body.append(f"    {unit} unit_i ({', '.join(conns)});")
    for n in outs:
        if bench.valid and n != bench.valid:
            body.append(f"    assign o_{n} = w_{bench.valid} ? w_{n} : {width[n]}'d0;")
        else:
            body.append(f"    assign o_{n} = w_{n};")
    return f"module {name} (\n" + ",\n".join(decl) + "\n);\n" + "\n".join(body) + "\nendmodule\n"


def prove_many(repo: Path, b: Build, muts: List[Mutation], netlist: Path, work: Path,
               depth: int, timeout: float) -> Dict[int, str]:
    """Per mutant of ``muts`` of build ``b``: ``"proven"`` when Yosys proves it equivalent to the
    unit in its architectural view (``netlist``: a netlist of the build, read for the port
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
