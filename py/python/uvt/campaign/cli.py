"""The command line: ``python -m uvt.campaign`` and the console script ``uvt-campaign``.

::

    uvt-campaign run [--kind bsample] [--config NAME] [--seed S] --shards M --per-shard R
                     [--sim model|COMMAND] [--arch-only] [--corrupt I]
                     [--workers N | --scheduler ADDRESS | --jobqueue slurm|lsf|pbs|sge --jobs N …]
                     [--state FILE] [--stop-on-failure] [--json FILE] [--no-progress]
                     [--only-shard K]
    uvt-campaign build-sim --out DIR [--repo PATH] [--mutant tie-key]

Exit status: 0 when every shard passed, 1 when a record differs, a simulator failed or the
campaign was stopped before every shard ran, 2 on bad arguments (the message says which).
"""

from __future__ import annotations

import argparse
import json
import sys
from typing import List, Optional

from ._model import CampaignError
from .spec import Campaign

JOBQUEUE = {"slurm": "SLURMCluster", "lsf": "LSFCluster", "pbs": "PBSCluster",
            "sge": "SGECluster"}


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="uvt-campaign", description=__doc__.split("\n\n")[0])
    sub = p.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run", help="run a campaign")
    r.add_argument("--kind", default="bsample", help="record kind (default bsample)")
    r.add_argument("--config", default=None, help="configuration (default: the default one)")
    r.add_argument("--seed", type=int, default=1)
    r.add_argument("--shards", type=int, required=True, help="shard count M")
    r.add_argument("--per-shard", type=int, required=True, help="records per shard")
    r.add_argument("--sim", default="model",
                   help="'model' or a simulator command (reads input records, writes pairs)")
    r.add_argument("--arch-only", action="store_true", help="compare architectural fields only")
    r.add_argument("--corrupt", type=int, default=None,
                   help="model simulator: flip bit 0 of word 1 of this record's output")
    r.add_argument("--timeout", type=float, default=None, help="seconds per shard's simulator")
    r.add_argument("--target-bins", default="",
                   help="coverage bins to bias the stream toward (comma-separated names)")
    g = r.add_mutually_exclusive_group()
    g.add_argument("--workers", type=int, default=1, help="LocalCluster worker processes")
    g.add_argument("--scheduler", default=None, help="address of a running Dask scheduler")
    g.add_argument("--jobqueue", choices=sorted(JOBQUEUE), default=None,
                   help="a dask-jobqueue cluster of this batch system")
    r.add_argument("--jobs", type=int, default=1, help="--jobqueue: batch jobs to start")
    r.add_argument("--queue", default=None, help="--jobqueue: queue / partition")
    r.add_argument("--account", default=None, help="--jobqueue: account / project")
    r.add_argument("--walltime", default="04:00:00", help="--jobqueue: job wall time")
    r.add_argument("--cores", type=int, default=1, help="--jobqueue: cores (workers) per job")
    r.add_argument("--memory", default="2GB", help="--jobqueue: memory per job")
    r.add_argument("--state", default=None, help="state file (JSON lines): resume from it")
    r.add_argument("--stop-on-failure", action="store_true",
                   help="cancel the remaining shards at the first failing one")
    r.add_argument("--json", default=None, help="write the summary as JSON to this file")
    r.add_argument("--no-progress", action="store_true", help="no progress bar")
    r.add_argument("--only-shard", type=int, default=None,
                   help="run shard K alone in this process (no Dask) and print its result")
    b = sub.add_parser("build-sim", help="build the Verilator stream runner of uvt_bsample.v")
    b.add_argument("--out", required=True, help="build folder (kept; rebuilt when sources change)")
    b.add_argument("--repo", default=None, help="uvt checkout (default: UVT_REPO or the cwd)")
    b.add_argument("--mutant", default=None, help="a mutated unit: tie-key")
    return p


def _client(a):
    """The Dask client the arguments ask for (None: a LocalCluster of --workers)."""
    if a.scheduler:
        from distributed import Client  # noqa: PLC0415

        return Client(a.scheduler)
    if a.jobqueue:
        import dask_jobqueue  # noqa: PLC0415
        from distributed import Client  # noqa: PLC0415

        cls = getattr(dask_jobqueue, JOBQUEUE[a.jobqueue])
        kw = {"cores": a.cores, "processes": a.cores, "memory": a.memory,
              "walltime": a.walltime}
        if a.queue:
            kw["queue"] = a.queue
        if a.account:
            kw["account"] = a.account
        cluster = cls(**kw)
        cluster.scale(jobs=a.jobs)
        return Client(cluster)
    return None


def main(argv: Optional[List[str]] = None) -> int:
    """Run the command line ``argv`` (default ``sys.argv[1:]``); the exit status."""
    a = _parser().parse_args(argv)
    try:
        if a.cmd == "build-sim":
            from .verilator import build_pipe  # noqa: PLC0415

            exe = build_pipe(a.out, a.repo, a.mutant)
            print(exe)
            return 0
        spec = Campaign(kind=a.kind, config=a.config, seed=a.seed, shards=a.shards,
                        per_shard=a.per_shard, simulator=a.sim, architectural=a.arch_only,
                        corrupt=a.corrupt, timeout=a.timeout,
                        target=tuple(t for t in a.target_bins.split(",") if t)).validate()
        if a.only_shard is not None:
            from .task import only_shard  # noqa: PLC0415

            r = only_shard(spec, a.only_shard)
            print(json.dumps(r, indent=1, sort_keys=True))
            return 1 if r["mismatched"] or r["error"] else 0
        from .runner import run  # noqa: PLC0415

        client = _client(a)
        try:
            s = run(spec, client, workers=a.workers, state=a.state,
                    stop_on_failure=a.stop_on_failure, progress=not a.no_progress)
        finally:
            if client is not None:
                client.close()
        print(s.table())
        if a.json:
            with open(a.json, "w") as f:
                json.dump(s.to_dict(), f, indent=1, sort_keys=True)
        return 0 if s.passed else 1
    except CampaignError as e:
        print(f"uvt-campaign: {e}", file=sys.stderr)
        return 2
