"""The mutated design of one build, MCY's way: Yosys's ``mutate`` lists ``count`` mutations
(seeded, every mode: inv, const0, const1, cnot0, cnot1) of the flattened, word-level (``prep``)
unit and applies every one behind a select input, ``mutate -ctrl mutsel W K``: mutant K acts
when ``mutsel == K``, 0 is the unit itself. The written netlist keeps the unit's ports and name;
``mutsel`` becomes a register the simulation sets from the plusarg ``+MUTSEL=K``, so the bench
that checks the unit checks the mutants unchanged, and the simulator is built once.

The sources are read by paths relative to the checkout, so the list (its ``-src`` attributes
included) is the same in every checkout for the same seed.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path
from typing import List, Optional

from .errors import MutationError
from .units import Build


@dataclass(frozen=True)
class Mutation:
    """One line of ``mutate -list``: its number (the ``mutsel`` value), mode, cell, port and bit,
    the wire bit it drives and the source lines it comes from."""

    id: int
    mode: str
    cell: str
    port: str
    portbit: int
    wire: str
    wirebit: int
    src: str
    line: str

    def alone(self) -> str:
        """The Yosys command applying this mutation unconditionally (no select input)."""
        return re.sub(r"-ctrl mutsel \d+ \d+ ", "", self.line)

    def selected(self, width: int) -> str:
        """The Yosys command applying this mutation behind a ``width``-bit select input
        ``mutsel`` (active when it holds the mutant's number), as ``mutate -list -ctrl``
        lists it."""
        return self.alone().replace("mutate ", f"mutate -ctrl mutsel {width} {self.id} ", 1)


def _opt(words: List[str], key: str, default: str = "") -> str:
    vals = [words[i + 1] for i, w in enumerate(words[:-1]) if w == key]
    return " ".join(vals) if vals else default


def parse_list(text: str) -> List[Mutation]:
    """The mutations of a ``mutate -list … -ctrl mutsel W 1`` listing, numbered as listed."""
    out = []
    for line in text.splitlines():
        if not line.startswith("mutate "):
            continue
        w = line.split()
        out.append(Mutation(
            id=int(w[w.index("-ctrl") + 3]), mode=_opt(w, "-mode"), cell=_opt(w, "-cell"),
            port=_opt(w, "-port"), portbit=int(_opt(w, "-portbit", "0")),
            wire=_opt(w, "-wire"), wirebit=int(_opt(w, "-wirebit", "0")),
            src=_opt(w, "-src").replace("vectors/rtl/", ""), line=line))
    return out


def from_row(row: dict) -> Mutation:
    """The mutation of a report line (its ``mutate`` command, without a select input)."""
    return Mutation(row["id"], row["mode"], row["cell"], row["port"], row["portbit"],
                    row["wire"], row["wirebit"], row["src"], row["mutate"])


def sel_width(count: int) -> int:
    """Bits of ``mutsel`` for mutants 1..count."""
    return max(1, count.bit_length())


def _read(b: Build) -> str:
    """Yosys commands reading, parametrising, elaborating and flattening the build."""
    srcs = " ".join(b.source_paths())
    sets = " ".join(f"-set {k} {v}" for k, v in b.params)
    return (f"read_verilog -I vectors/rtl {srcs}\n" + (f"chparam {sets} {b.top}\n" if sets else "")
            + f"prep -top {b.top}\nflatten\nopt_clean\nrename -top {b.top}\n")


def _yosys(repo: Path, script: str, where: Path, name: str) -> None:
    if shutil.which("yosys") is None:
        raise MutationError("yosys not found (Debian package yosys; tests/run.sh installs it)")
    ys = where / f"{name}.ys"
    ys.write_text(script)
    p = subprocess.run(["yosys", "-q", "-s", str(ys)], cwd=repo, capture_output=True, text=True)
    if p.returncode != 0:
        raise MutationError(f"yosys {ys} failed:\n{p.stdout[-3000:]}{p.stderr[-3000:]}")


def _select_from_plusarg(text: str, top: str, width: int) -> str:
    """The netlist with ``mutsel`` no longer a port of ``top`` but a register set from
    ``+MUTSEL=K`` (0 when absent)."""
    i = text.index(f"module {top}(")
    j = text.index("endmodule", i)
    mod = text[i:j]
    mod, n = re.subn(r", mutsel\);", ");", mod, count=1)
    mod, m = re.subn(r"\n\s*input (\[\d+:0\] )?mutsel;",
                     f"\n  reg [{width - 1}:0] mutsel;\n"
                     "  initial if (!$value$plusargs(\"MUTSEL=%d\", mutsel)) mutsel = 0;", mod, count=1)
    mod, k = re.subn(r"\n\s*wire (\[\d+:0\] )?mutsel;", "", mod, count=1)
    if (n, m, k) != (1, 1, 1):
        raise MutationError(f"the mutated netlist of {top} has no mutsel port to replace")
    return text[:i] + mod + text[j:]


def make(repo: Path, b: Build, count: int, seed: int, out: Path) -> List[Mutation]:
    """List ``count`` mutations of build ``b`` with ``seed`` into ``out/list.txt``; the
    mutations."""
    out.mkdir(parents=True, exist_ok=True)
    lst = out / "list.txt"
    script = (_read(b) + f"mutate -list {count} -seed {seed} -ctrl mutsel {sel_width(count)} 1 "
              f"-o {lst}\n")
    _yosys(repo, script, out, "list")
    muts = parse_list(lst.read_text())
    if len(muts) != count:
        raise MutationError(f"{b.name}: mutate listed {len(muts)} mutations, not {count}")
    return muts


def netlist(repo: Path, b: Build, muts: List[Mutation], count: int, out: Path) -> Path:
    """The netlist of build ``b`` holding the mutations ``muts`` (of a list of ``count``) behind
    the select input, as ``out/mutants.v``."""
    out.mkdir(parents=True, exist_ok=True)
    apply = out / "apply.txt"
    apply.write_text("".join(m.line + "\n" for m in muts))
    # The same read and elaboration in a new process names every cell as the listing did.
    raw = out / "raw.v"
    _yosys(repo, _read(b) + f"script {apply}\nopt_clean\nwrite_verilog -noattr {raw}\n",
           out, "mutants")
    v = out / "mutants.v"
    v.write_text(_select_from_plusarg(raw.read_text(), b.top, sel_width(count)))
    raw.unlink()
    return v


def single(repo: Path, b: Build, m: Optional[Mutation], out: Path) -> Path:
    """The netlist of build ``b`` with the one mutation ``m`` applied unconditionally (``None``:
    the unmutated flattened unit): the slow path, one simulator build per mutant, that checks
    the select-input design's verdicts through another simulator."""
    out.mkdir(parents=True, exist_ok=True)
    name = f"single{m.id if m else 0}"
    v = out / f"{name}.v"
    _yosys(repo, _read(b) + (m.alone() + "\n" if m else "") + f"opt_clean\nwrite_verilog -noattr {v}\n",
           out, name)
    return v
