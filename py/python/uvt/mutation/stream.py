"""The second stage: a mutant the committed sets leave alive meets the seeded stream, through
the campaign's simulator interface on Dask (:mod:`uvt.campaign`): the stream runner of
``vectors/dpi/pipe.cpp`` (``pipe_psample.cpp`` for the planar unit) built once per build on the
mutated netlist (``+MUTSEL=K`` picks the
mutant), each survivor one campaign of ``shards`` × ``per_shard`` records of the kind's seeded
stream (record *i* is ``uvt vectors gen``'s record *i*), architectural fields only, stopped at
the first failing shard. Kinds with a stream runner: ``bsample`` (``uvt_bsample``) and
``psample`` (``uvt_psample``); the bounds unit's records name a triangle of a setup file, so
it has no stream."""

from __future__ import annotations

from pathlib import Path
from typing import Dict, List, Optional, Tuple

from .bench import verilator_build
from .errors import MutationError
from .units import Build

#: The units whose mutants meet a stream, with the record kind and the runner's source.
RUNNERS = {"uvt_bsample": ("bsample", "pipe.cpp"), "uvt_psample": ("psample", "pipe_psample.cpp")}


#: Seconds a shard's runner may take: a mutant that never gives a record's result (its valid
#: logic broken by the stream's bubbles) hangs the runner, and the campaign reports the shard's
#: runner as failed (10^4 records take under a second).
HANG = 120.0


def has_stream(b: Build) -> bool:
    """Whether build ``b``'s unit has a stream runner (a team's unit: that of the reference unit
    it stands for, whose ports it has)."""
    return (b.like or b.top) in RUNNERS


def build_runner(repo: Path, b: Build, netlist: Path, out: Path, jobs: int = 2) -> Path:
    """Verilate ``vectors/dpi/<runner>`` with the mutated ``netlist`` into ``out`` (kept when the
    sources are unchanged); the executable."""
    src = repo / "vectors" / "dpi" / RUNNERS[b.like or b.top][1]
    args = ["verilator", "--cc", "--exe", "--build", "-j", str(jobs), "-Wno-fatal", "-Wno-lint",
            "-Wno-style", "--top-module", b.top, "--prefix", f"V{b.like or b.top}",
            "--Mdir", str(out / "obj"), "-o", "pipe", str(netlist), str(src)]
    return verilator_build(args, [src, netlist], out / "obj" / "pipe", out)


def _first(spec, client, s) -> Optional[dict]:
    """The stream's first failure: the lowest failing shard's, after running the lower shards
    that stopping at the first failing shard to finish cancelled (so the record is the first
    failing one of the stream, whichever shard finished first)."""
    from ..campaign import run_shard  # noqa: PLC0415

    f = s.first_failure
    if f is None:
        return None
    lower = [j for j in range(1, f["shard"]) if j not in s.shards]
    for j, r in zip(lower, client.gather([client.submit(run_shard, spec, j, pure=False)
                                          for j in lower])):
        if r["mismatched"] or r.get("error"):
            return {"shard": j, "failure": r.get("failure"), "error": r.get("error")}
    return f


def kill(b: Build, exe: Path, ids: List[int], seed: int, shards: int, per_shard: int,
         workers: int = 2, log=print, target: Tuple[str, ...] = ()) -> Dict[int, Optional[dict]]:
    """Run each mutant of ``ids`` (0: the unmutated unit, which must pass) through a campaign of
    ``shards`` × ``per_shard`` records (the stream directed at the coverage bins ``target``,
    if any); per id ``None`` (alive after them all) or ``{"record", "field"}`` of the first
    failure."""
    from distributed import Client, LocalCluster  # noqa: PLC0415

    from ..campaign import Campaign, run  # noqa: PLC0415

    kind = RUNNERS[b.like or b.top][0]
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                           dashboard_address=":0")
    client = Client(cluster)
    out: Dict[int, Optional[dict]] = {}
    try:
        for k in [0, *ids]:
            spec = Campaign(kind=kind, seed=seed, shards=shards, per_shard=per_shard,
                            simulator=f"{exe} 1 +MUTSEL={k}", architectural=True,
                            timeout=HANG, target=target)
            s = run(spec, client, stop_on_failure=True, progress=False)
            f = _first(spec, client, s)
            if f is None:
                if not s.passed:
                    raise MutationError(f"{b.name} mutant {k}: the campaign did not finish")
                out[k] = None
            elif f.get("failure"):
                fl = f["failure"]
                out[k] = {"record": fl["record"],
                          "field": ",".join(x["field"] for x in fl["fields"]) or "?"}
            else:
                out[k] = {"record": -1, "field": "runner: " + str(f.get("error"))[:200]}
            if k == 0 and out[0] is not None:
                raise MutationError(f"{b.name}: the unmutated unit fails the stream: {out[0]}")
            log(f"{b.name} mutant {k}: {'alive' if out[k] is None else out[k]} "
                f"({s.seconds:.1f} s)")
    finally:
        client.close()
        cluster.close()
    out.pop(0, None)
    return out
