"""The mutation report. Each build's mutants are kept one per line in
``host/report/mutation/<build>.jsonl`` (what the mutation changes; ``killed_by``: the committed
set that kills it, with ``record`` and ``field``; ``equivalent``: ``proven`` when ABC proves it
equivalent, ``differs`` when ABC finds inputs of the unit's record domain (free inputs where it
states none) that tell it apart, ``undecided`` when it gives no verdict in the time allowed;
``stream``: the seeded
stream's record and field that kill it, or ``alive`` after ``stream_records``;
``stream_directed``: the same for the stream directed at the bins ``stream_target``), and the
summary
``host/report/mutation.json`` is made from those files alone. Every file is written whole or not
at all."""

from __future__ import annotations

import json
import os
import statistics
from collections import Counter
from pathlib import Path
from typing import Dict, List

from .units import SETS, Build


def write_atomic(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` through a temporary file and a rename."""
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(path.suffix + ".tmp")
    tmp.write_text(text)
    os.replace(tmp, path)


def load(per: Path, name: str) -> List[Dict]:
    """The mutants of build ``name`` in ``per`` (``[]`` when it has none yet)."""
    f = per / f"{name}.jsonl"
    return [json.loads(x) for x in f.read_text().splitlines()] if f.is_file() else []


def save(per: Path, name: str, rows: List[Dict]) -> None:
    """Write build ``name``'s mutants to ``per``."""
    write_atomic(per / f"{name}.jsonl",
                 "".join(json.dumps(r, sort_keys=True) + "\n" for r in rows))


#: The keys the later stages (``prove``, ``stream``) add to a mutant's line.
LATER = ("equivalent", "stream", "stream_records", "stream_directed", "stream_directed_records",
         "stream_target")


def carry(old: List[Dict], new: List[Dict]) -> int:
    """Keep the later stages' verdicts of ``old`` for the mutants of ``new`` that survive the
    committed sets again with the same mutation (a new run after the vectors changed: a proof or
    a stream verdict does not depend on them); a mutant the sets now kill drops them. How many
    mutants kept verdicts. A mutant proven equivalent that the sets now kill is an error: the
    proof or the bench is wrong."""
    by = {r["id"]: r for r in old}
    kept = 0
    for r in new:
        o = by.get(r["id"])
        if o is None or o.get("mutate") != r.get("mutate"):
            continue
        if r.get("killed_by") and o.get("equivalent") == "proven":
            raise ValueError(f"mutant {r['id']} was proven equivalent, and set "
                             f"{r['killed_by']} kills it at record {r['record']}")
        if not r.get("killed_by"):
            got = {k: o[k] for k in LATER if k in o}
            r.update(got)
            kept += bool(got)
    return kept


def fate(r: Dict) -> str:
    """A mutant's place in the report: ``vectors``, ``equivalent``, ``stream`` or ``survivor``."""
    if r.get("killed_by"):
        return "vectors"
    if r.get("equivalent") == "proven":
        return "equivalent"
    if isinstance(r.get("stream"), dict) or isinstance(r.get("stream_directed"), dict):
        return "stream"
    return "survivor"


def summary(b: Build, rows: List[Dict], meta: Dict) -> Dict:
    """The report's row of build ``b`` from its mutants ``rows``."""
    by = Counter(fate(r) for r in rows)
    killed = [r for r in rows if r.get("killed_by")]
    rtk = [r["records_to_kill"] for r in killed]
    left = [r for r in rows if fate(r) == "survivor"]
    streamed = [r for r in rows if r.get("stream") is not None]
    nonequiv = len(rows) - by["equivalent"]
    return {
        "build": b.name,
        "unit": b.top,
        "params": dict(b.params),
        "checked": b.bench.checked,
        "sets": meta.get("sets", {}),
        "mutants": len(rows),
        "modes": dict(sorted(Counter(r["mode"] for r in rows).items())),
        "killed_by_vectors": by["vectors"],
        "killed_by_set": {s: n for s in (*SETS, "pairs")
                          for n in [sum(r["killed_by"] == s for r in killed)] if n},
        "equivalent": by["equivalent"],
        "killed_by_stream": sum(isinstance(r.get("stream"), dict) for r in rows
                                if fate(r) == "stream"),
        "killed_by_directed_stream": sum(not isinstance(r.get("stream"), dict) for r in rows
                                         if fate(r) == "stream"),
        "directed_stream_records": max((r.get("stream_directed_records", 0) for r in rows),
                                       default=0),
        "stream_records": max((r.get("stream_records", 0) for r in streamed), default=0),
        "survivors": by["survivor"],
        "survivors_not_proven": {
            "differs_on_domain_inputs": sum(r.get("equivalent") == "differs" for r in left),
            "undecided": sum(r.get("equivalent") == "undecided" for r in left),
            "not_tried": sum(r.get("equivalent") is None for r in left),
        },
        "score_vectors": round(by["vectors"] / nonequiv, 4) if nonequiv else None,
        "records_to_kill": {"median": statistics.median(rtk) if rtk else None,
                            "largest": max(rtk) if rtk else None},
        "seconds": meta.get("seconds"),
        "icarus_confirmed": meta.get("icarus_confirmed"),
    }


def write(repo: Path, builds: List[Build], out_json: Path, per: Path, meta: Dict) -> Dict:
    """The summary of every build of ``builds`` that has mutants in ``per``, written to
    ``out_json``; the summary."""
    rep = dict(meta)
    old = {}
    if out_json.is_file():
        old = {r["build"]: r for r in json.loads(out_json.read_text()).get("builds", [])}
    runs = meta.get("runs", {})
    rep.pop("runs", None)
    rep["builds"] = []
    for b in builds:
        rows = load(per, b.name)
        if rows:
            m = runs.get(b.name) or {k: old.get(b.name, {}).get(k)
                                     for k in ("sets", "seconds", "icarus_confirmed")}
            rep["builds"].append(summary(b, rows, m))
    write_atomic(out_json, json.dumps(rep, indent=1) + "\n")
    return rep


def markdown(rep: Dict) -> str:
    """The report as the table of docs/mutation.md."""
    head = ("| build | unit outputs checked | mutants | killed by the committed sets | "
            "proven equivalent | killed by the stream | survivors: differ on the domain's inputs, "
            "undecided, not tried | score (killed ÷ not equivalent) | records to kill: median, "
            "largest |\n"
            "|---|---|---|---|---|---|---|---|---|\n")
    rows = []
    for r in rep["builds"]:
        sets = ", ".join(f"{k} {v}" for k, v in r["killed_by_set"].items())
        stream = (f"{r['killed_by_stream']} (of {r['stream_records']:,} records each)"
                  if r["stream_records"] else "no stream run")
        if r["directed_stream_records"]:
            stream += (f"; directed: {r['killed_by_directed_stream']} (of "
                       f"{r['directed_stream_records']:,})")
        score = f"{100 * r['score_vectors']:.1f}%" if r["score_vectors"] is not None else "–"
        rtk = {k: (f"{v:g}" if v is not None else "–") for k, v in r["records_to_kill"].items()}
        left = r["survivors_not_proven"]
        rows.append(f"| {r['build']} | {r['checked']} | {r['mutants']} | "
                    f"{r['killed_by_vectors']} ({sets}) | {r['equivalent']} | {stream} | "
                    f"{r['survivors']}: {left['differs_on_domain_inputs']}, {left['undecided']}, "
                    f"{left['not_tried']} | {score} | {rtk['median']}, {rtk['largest']} |")
    return head + "\n".join(rows) + "\n"
