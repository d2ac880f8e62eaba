"""Run a build's bench on its unit's netlist: the Verilator build of the bench with the
mutated design (built once), the run of one mutant on one vector set, and the same run under
Icarus for a single-mutant netlist (the cross-check of the select-input design).

A run's verdict: ``None`` when the bench passes, else ``(record, field)`` of the first
mismatching field (``+STOP=1``): ``record`` is the record's index in the set's file (the
product's index for ``tb_mul``), ``field`` the bench's field name, ``count`` when results were
lost or added, ``timeout`` when the bench did not end.
"""

from __future__ import annotations

import hashlib
import json
import re
import shutil
import subprocess
from pathlib import Path
from typing import List, Optional, Tuple

from .errors import MutationError
from .units import Build, rtl_dir

Verdict = Optional[Tuple[int, str]]

#: tb_mul's seeded operand pairs after its 36 corner pairs (the unit's "vector set").
MUL_PAIRS = 2000
#: Seconds one run may take before it counts as a hang.
TIMEOUT = 120.0


def _defines(b: Build) -> List[str]:
    return [f"+define+{d}" for d in b.bench.defines]


def _params(b: Build) -> List[str]:
    out = []
    for k in b.bench.tb_params:
        v = dict(b.params).get(k)
        if v is not None:
            out.append(f"-G{k}={v}")
    return out


def sets(repo: Path, b: Build) -> List[str]:
    """The committed sets that hold records of the build's unit, in :data:`units.SETS` order
    (``["pairs"]`` for the multiplier: its bench's own seeded operands)."""
    from .units import SETS
    stem = b.bench.stem
    if stem is None:
        return ["pairs"]
    vec = repo / "vectors"
    return [s for s in SETS if (vec / s / f"{stem}_out.hex").is_file()
            and (vec / s / f"{stem}_out.hex").stat().st_size > 0]


def verilator_build(args: List[str], sources: List[Path], exe: Path, out: Path) -> Path:
    """Run the Verilator command ``args`` that builds ``exe`` under ``out/obj``, unless a build
    from the same command and the same ``sources`` (their contents) is there already; the
    executable."""
    if shutil.which("verilator") is None:
        raise MutationError("verilator not found (Debian package verilator; tests/run.sh "
                            "installs it)")
    out.mkdir(parents=True, exist_ok=True)
    stamp = hashlib.sha256(json.dumps(args).encode()
                           + b"".join(s.read_bytes() for s in sources)).hexdigest()
    if exe.is_file() and (out / "stamp").is_file() and (out / "stamp").read_text() == stamp:
        return exe
    shutil.rmtree(out / "obj", ignore_errors=True)
    p = subprocess.run(args, capture_output=True, text=True)
    if p.returncode != 0 or not exe.is_file():
        raise MutationError(f"verilator failed ({' '.join(args)}):\n{p.stdout[-3000:]}"
                            f"{p.stderr[-3000:]}")
    (out / "stamp").write_text(stamp)
    return exe


def verilate(repo: Path, b: Build, netlist: Path, out: Path, jobs: int = 2) -> Path:
    """Build the bench with ``netlist`` under Verilator (``--binary --timing``) into ``out``
    (kept: rebuilt only when the bench, the netlist or the options change); the executable."""
    tb = rtl_dir(repo) / f"{b.bench.tb}.v"
    args = ["verilator", "--binary", "--timing", "-j", str(jobs), "-Wno-fatal", "-Wno-lint",
            "-Wno-style", *_defines(b), *_params(b), "--top-module", b.bench.tb,
            "--Mdir", str(out / "obj"), "-o", "sim", str(tb), str(netlist)]
    return verilator_build(args, [tb, netlist], out / "obj" / "sim", out)


def icarus(repo: Path, b: Build, netlist: Path, out: Path) -> List[str]:
    """Compile the bench with ``netlist`` under Icarus into ``out``; the command prefix that
    runs it (``vvp -n …``)."""
    tb = rtl_dir(repo) / f"{b.bench.tb}.v"
    exe = out / f"{netlist.stem}.vvp"
    args = ["iverilog", "-g2005", *[f"-D{d}" for d in b.bench.defines],
            *[f"-P{b.bench.tb}.{a[2:]}" for a in _params(b)], "-o", str(exe), str(tb),
            str(netlist)]
    p = subprocess.run(args, capture_output=True, text=True)
    if p.returncode != 0:
        raise MutationError(f"iverilog failed ({' '.join(args)}):\n{p.stderr[-3000:]}")
    return ["vvp", "-n", str(exe)]


def set_args(repo: Path, b: Build, name: str, seed: int = 7, pairs: int = MUL_PAIRS) -> List[str]:
    """The plusargs that run the bench on set ``name`` (``pairs``: tb_mul's ``seed`` and
    ``pairs`` random operand pairs)."""
    if name == "pairs":
        return [f"+SEED={seed}", f"+NR={pairs}"]
    d = repo / "vectors" / name
    if b.bench.tb == "tb_bounds":
        return [f"+SET={d}/"]
    stem = b.bench.stem
    n = sum(1 for _ in open(d / f"{stem}_out.hex"))
    return [f"+IN={d / f'{stem}_in.hex'}", f"+OUT={d / f'{stem}_out.hex'}", f"+N={n}"]


_STOP = re.compile(r"^STOP record (\d+) field (\S+)", re.M)


def run(cmd: List[str], mutant: int, args: List[str], timeout: float = TIMEOUT) -> Verdict:
    """Run the bench command ``cmd`` with mutant ``mutant`` (``+MUTSEL``; a single-mutant
    netlist ignores it) on ``args``, stopping at the first mismatch; its verdict."""
    try:
        p = subprocess.run([*cmd, f"+MUTSEL={mutant}", "+STOP=1", *args], capture_output=True,
                           text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return (-1, "timeout")
    text = p.stdout + p.stderr
    m = _STOP.search(text)
    if m:
        return (int(m.group(1)), m.group(2))
    if re.search(r"^PASS ", text, re.M) and p.returncode == 0:
        return None
    if "results came out" in text or "came out" in text:
        return (-1, "count")
    raise MutationError(f"mutant {mutant}: the bench neither passed nor named a mismatch "
                        f"(exit {p.returncode}): {' '.join(cmd + args)}\n{text[-2000:]}")
