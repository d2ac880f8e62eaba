"""Run a campaign's shards on Dask and reduce their results in shard order."""

from __future__ import annotations

import time
import uuid
from dataclasses import dataclass, field
from typing import Dict, List, Optional

from ._model import CampaignError, load
from .coverage import add, table
from .spec import Campaign
from .state import StateFile
from .task import run_shard


@dataclass
class Summary:
    """A campaign's results. :meth:`verdict` is what any number of workers gives alike: totals,
    coverage and the first failure, reduced in shard order; the other fields say how this run
    went (shards it ran, skipped from the state file or cancelled; wall time and rate)."""

    campaign: Campaign
    shards: Dict[int, dict] = field(default_factory=dict)
    ran: int = 0
    resumed: int = 0
    cancelled: int = 0
    seconds: float = 0.0
    workers: int = 0

    @property
    def records(self) -> int:
        """Records checked (finished shards, resumed ones included)."""
        return sum(r["records"] for r in self.shards.values() if not r.get("error"))

    @property
    def mismatched(self) -> int:
        """Records whose output differs from the model's."""
        return sum(r["mismatched"] for r in self.shards.values())

    @property
    def failing_shards(self) -> List[int]:
        """Shards with a differing record or a simulator error, in shard order."""
        return sorted(k for k, r in self.shards.items() if r["mismatched"] or r.get("error"))

    @property
    def first_failure(self) -> Optional[dict]:
        """The first failing shard's failure (lowest shard index): its ``shard``, the
        ``failure`` of :func:`.task.run_shard` or the simulator ``error``."""
        for k in self.failing_shards:
            r = self.shards[k]
            return {"shard": k, "failure": r.get("failure"), "error": r.get("error")}
        return None

    @property
    def passed(self) -> bool:
        """Every shard ran (none cancelled or missing) and none failed."""
        return len(self.shards) == self.campaign.shards and not self.failing_shards

    @property
    def coverage(self) -> Dict[str, int]:
        """Coverage counters summed over the finished shards, in shard order."""
        tot: Dict[str, int] = {}
        for k in sorted(self.shards):
            add(tot, self.shards[k]["coverage"])
        return dict(sorted(tot.items()))

    @property
    def rate(self) -> float:
        """Records per second of the shards this run ran (wall time)."""
        n = sum(r["records"] for k, r in self.shards.items() if r.get("_ran"))
        return n / self.seconds if self.seconds > 0 else 0.0

    def verdict(self) -> dict:
        """The worker-count-independent result: campaign, shards finished, records,
        mismatched records, failing shards, coverage, first failure."""
        return {
            "campaign": self.campaign.identity(),
            "passed": self.passed,
            "shards_finished": sorted(self.shards),
            "records": self.records,
            "mismatched": self.mismatched,
            "failing_shards": self.failing_shards,
            "coverage": self.coverage,
            "first_failure": self.first_failure,
        }

    def to_dict(self) -> dict:
        """:meth:`verdict` plus how this run went (JSON-able)."""
        d = self.verdict()
        d.update({"ran": self.ran, "resumed": self.resumed, "cancelled": self.cancelled,
                  "seconds": round(self.seconds, 3), "workers": self.workers,
                  "records_per_second": round(self.rate, 1),
                  "shard_seconds": {k: round(r.get("seconds", 0.0), 4)
                                    for k, r in sorted(self.shards.items())}})
        return d

    def table(self) -> str:
        """The summary table (text): the model's coverage bins of the records (``.coverage``),
        totals, and the first failure decoded with its reproducer commands."""
        c = self.campaign
        out = [f"campaign {c.kind} at {c.stream_config or '-'}, seed {c.seed}: {c.shards} shards "
               f"× {c.per_shard} records, simulator {c.simulator}"
               + (" (architectural fields)" if c.architectural else "")
               + (f", directed at {', '.join(c.target)}" if c.target else "")]
        out.extend(table(load(), c.kind, self.coverage))
        out.append(f"shards: {len(self.shards)} of {c.shards} finished ({self.ran} run now, "
                   f"{self.resumed} from the state file, {self.cancelled} cancelled); "
                   f"{self.records} records checked, {self.mismatched} mismatched; "
                   f"{self.seconds:.2f} s on {self.workers} workers, {self.rate:,.0f} records/s")
        f = self.first_failure
        if f is None:
            out.append("PASS" if self.passed else "INCOMPLETE: not every shard ran")
            return "\n".join(out)
        if f["error"]:
            out.append(f"FAIL shard {f['shard']}/{c.shards}: {f['error']}")
            return "\n".join(out)
        x = f["failure"]
        out.append(f"FAIL shard {f['shard']}/{c.shards}, record {x['record']} (record "
                   f"{x['in_shard']} of the shard):")
        for d in x["fields"]:
            out.append(f"  field {d['field']}: expected {d['expected']}, observed {d['observed']}")
        out.append("  input:    " + " ".join(x["input"]))
        out.append("  expected: " + " ".join(x["expected"]))
        out.append("  observed: " + " ".join(x["observed"]))
        dec = x["decoded"]["input"]
        out.append("  input decoded: " + ", ".join(f"{k}={v}" for k, v in dec.items()))
        for k, v in x["reproduce"].items():
            out.append(f"  reproduce ({k}): {v}")
        return "\n".join(out)


def run(spec: Campaign, client=None, *, workers: int = 1, state: Optional[str] = None,
        stop_on_failure: bool = False, progress: bool = True) -> Summary:
    """Run campaign ``spec`` and return its :class:`Summary`.

    ``client``: a ``distributed.Client`` (of a ``LocalCluster``, a scheduler address, or a
    ``dask_jobqueue`` cluster); without one, a ``LocalCluster`` of ``workers`` single-threaded
    worker processes runs the campaign and is closed after it. ``state``: a state file (JSON
    lines, :mod:`.state`); shards it records are not run again. ``stop_on_failure``: at the
    first shard that fails, cancel the shards not yet finished. A worker lost mid-campaign loses
    no shard: the scheduler runs its shards again on the others (up to
    ``distributed.scheduler.allowed-failures`` times per shard)."""
    spec.validate()
    st = StateFile(state, spec) if state else None
    summary = Summary(spec)
    if st:
        for k, r in st.done.items():
            summary.shards[k] = r
        summary.resumed = len(st.done)
    todo = [k for k in range(1, spec.shards + 1) if k not in summary.shards]
    own = None
    if client is None:
        if not isinstance(workers, int) or workers < 1:
            raise CampaignError(f"workers = {workers!r}: at least one local worker")
        from distributed import Client, LocalCluster  # noqa: PLC0415

        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                               dashboard_address=":0")
        own = client = Client(cluster)
    try:
        summary.workers = len(client.scheduler_info(n_workers=-1)["workers"])
    except TypeError:  # older distributed: no n_workers argument
        summary.workers = len(client.scheduler_info()["workers"])
    t0 = time.perf_counter()
    try:
        if todo:
            _run_todo(spec, client, todo, summary, st, stop_on_failure, progress)
    finally:
        summary.seconds = time.perf_counter() - t0
        if own is not None:
            cluster = own.cluster
            own.close()
            cluster.close()
    return summary


def _run_todo(spec, client, todo, summary, st, stop_on_failure, progress):
    from distributed import as_completed  # noqa: PLC0415
    from tqdm import tqdm  # noqa: PLC0415

    nonce = uuid.uuid4().hex[:8]
    futures = [client.submit(run_shard, spec, k, key=f"uvt-shard-{spec.key()}-{nonce}-{k}",
                             priority=-k) for k in todo]
    by_key = {f.key: k for f, k in zip(futures, todo)}
    bar = tqdm(total=len(todo), unit="shard", disable=not progress, dynamic_ncols=True,
               desc=f"{spec.kind} campaign")
    n_rec, t0 = 0, time.perf_counter()
    stopped = False
    try:
        ac = as_completed(futures)
        for f in ac:
            k = by_key[f.key]
            if f.status == "cancelled":
                continue
            try:
                r = f.result()
            except Exception as e:  # noqa: BLE001 - a task that could not run (KilledWorker, …)
                r = {"shard": k, "records": 0, "first_record": None, "mismatched": 0,
                     "coverage": {}, "failure": None, "error": f"{type(e).__name__}: {e}"}
            r["_ran"] = True
            summary.shards[k] = r
            summary.ran += 1
            if st:
                st.record({x: v for x, v in r.items() if x != "_ran"})
            n_rec += r["records"]
            bar.update(1)
            bar.set_postfix(records_per_s=f"{n_rec / max(time.perf_counter() - t0, 1e-9):,.0f}",
                            failing=len(summary.failing_shards))
            if stop_on_failure and (r["mismatched"] or r.get("error")):
                stopped = True
                break
    finally:
        bar.close()
        if stopped:
            rest = [f for f in futures if by_key[f.key] not in summary.shards]
            client.cancel(rest)
            summary.cancelled = len(rest)
        del futures
