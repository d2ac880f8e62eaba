"""Build the Verilator stream runner of the bounded sample-test unit (``vectors/dpi/pipe.cpp``
with ``vectors/rtl/uvt_bsample.v``), optionally of a mutated unit, for a campaign's
``simulator``: ``python -m uvt.campaign build-sim --out DIR`` prints the command to give."""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
from pathlib import Path
from typing import Optional

from ._model import CampaignError

#: Mutations of ``uvt_bsample.v`` a campaign must find (the same edits as
#: ``tests/tests/external/dpi.rs``): name → (text, replacement).
MUTANTS = {
    "tie-key": ("(~k_pos & ~k_neg & k_gt))", "(~k_pos & ~k_neg & k_lt))"),
}


def find_repo(start: Optional[str] = None) -> Path:
    """The uvt checkout holding ``vectors/rtl/uvt_bsample.v``: ``start``, else ``UVT_REPO``,
    else the current folder or one above it."""
    cands = [start] if start else ([os.environ["UVT_REPO"]] if os.environ.get("UVT_REPO") else [])
    if not cands:
        here = Path.cwd().resolve()
        cands = [str(p) for p in (here, *here.parents)]
    for c in cands:
        p = Path(c)
        if (p / "vectors" / "rtl" / "uvt_bsample.v").is_file():
            return p.resolve()
    raise CampaignError(f"no uvt checkout (vectors/rtl/uvt_bsample.v) at {', '.join(cands)}: "
                        "give --repo or set UVT_REPO")


def build_pipe(out: str, repo: Optional[str] = None, mutant: Optional[str] = None,
               jobs: int = 2) -> Path:
    """Verilate and build the stream runner into folder ``out`` (kept: a second call with the
    same sources returns the executable without building); ``mutant`` names an entry of
    :data:`MUTANTS` applied to a copy of the unit. Returns the executable's path."""
    if shutil.which("verilator") is None:
        raise CampaignError("verilator not found (Debian package verilator; tests/run.sh "
                            "installs it)")
    if mutant is not None and mutant not in MUTANTS:
        raise CampaignError(f"unknown mutant {mutant!r}: one of {', '.join(MUTANTS)}")
    root = find_repo(repo)
    dpi, rtl = root / "vectors" / "dpi", root / "vectors" / "rtl"
    outp = Path(out).resolve()
    outp.mkdir(parents=True, exist_ok=True)
    unit = (rtl / "uvt_bsample.v").read_text()
    if mutant:
        a, b = MUTANTS[mutant]
        if unit.count(a) != 1:
            raise CampaignError(f"mutant {mutant}: `{a}` is not in uvt_bsample.v exactly once")
        unit = unit.replace(a, b)
    (outp / "uvt_bsample.v").write_text(unit)
    srcs = [dpi / "rtl.vlt", rtl / "uvt_mul.v", outp / "uvt_bsample.v", dpi / "pipe.cpp"]
    # The stamp covers the sources' paths and contents: Verilator's makefiles name the sources
    # by path, so a build from another checkout (or of other sources) is not reused, and a
    # rebuild starts from an empty folder rather than from another build's objects.
    stamp = hashlib.sha256(b"".join(str(p).encode() + b"\0" + p.read_bytes()
                                    for p in srcs)).hexdigest()
    exe = outp / "obj" / "pipe"
    if exe.is_file() and (outp / "stamp").is_file() and (outp / "stamp").read_text() == stamp:
        return exe
    (outp / "stamp").unlink(missing_ok=True)
    shutil.rmtree(outp / "obj", ignore_errors=True)
    args = ["verilator", "--cc", "--exe", "--build", "-j", str(jobs), "+1364-2005ext+v",
            "--top-module", "uvt_bsample", "--Mdir", str(outp / "obj"), "-o", "pipe",
            *map(str, srcs)]
    p = subprocess.run(args, capture_output=True, text=True)
    if p.returncode != 0:
        raise CampaignError(f"verilator failed ({' '.join(args)}):\n{p.stdout[-3000:]}"
                            f"{p.stderr[-3000:]}")
    (outp / "stamp").write_text(stamp)
    return exe
