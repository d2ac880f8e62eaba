"""``python -m uvt.mutation``: mutate the reference units and judge the mutants.

- ``run``: list ``--mutants`` mutations (default 1000, ``--seed`` 1) of every build of
  :data:`.units.BUILDS` (or ``--builds``) and judge them with the committed vector sets; each
  build's mutants go to ``host/report/mutation/<build>.jsonl`` as soon as it is done (a mutant
  that survives again keeps the ``prove`` and ``stream`` verdicts of the file it replaces).
- ``prove``: try to prove each survivor equivalent (``--engine abc``: on one miter per build
  Yosys maps, register correspondence by ABC's ``iprove``, the unrolled region, then ABC's
  ``dprove`` (``--steps``); ``sat``:
  Yosys's ``sat -tempinduct`` on one miter per mutant; ``--timeout`` seconds each).
- ``stream``: run each survivor still unproven through the seeded stream on Dask
  (``--records``; units with a stream runner).
- ``report``: the summary ``host/report/mutation.json`` from the per-build files (every stage
  writes it too).
- ``check``: mutants 1..``--sample`` of each default build judged again and compared with the
  committed per-build files: a mutant the report says a set kills must still be killed by it, at
  the same record and field.

Exit status 0 on success, 1 when ``check`` finds a difference, 2 on bad input or a failed tool.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import time
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import List, Optional

from . import design, equiv, flow, report, stream, units
from .errors import MutationError

DEFAULT_BUILDS = ("bsample", "psample", "bounds", "mul31")


def _repo(given: Optional[str]) -> Path:
    for c in ([given] if given else [".", ".."]):
        p = Path(c).resolve()
        if (p / "vectors" / "rtl" / "pnr.sh").is_file():
            return p
    raise MutationError("no uvt checkout (vectors/rtl/pnr.sh) here: give --repo")


def _tool(cmd: List[str]) -> str:
    try:
        out = subprocess.run(cmd, capture_output=True, text=True).stdout
    except FileNotFoundError as e:
        raise MutationError(f"{cmd[0]} not found (tests/run.sh installs it)") from e
    return (out.strip().splitlines() or ["?"])[0]


def _parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(prog="python -m uvt.mutation",
                                 description=__doc__.split("\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    for name in ("run", "prove", "stream", "report", "check"):
        p = sub.add_parser(name)
        p.add_argument("--repo", default=None, help="uvt checkout (default: here)")
        p.add_argument("--builds", default=None,
                       help=f"comma-separated builds of pnr.sh's table (default: "
                            f"{','.join(DEFAULT_BUILDS if name == 'check' else units.BUILDS)})")
        p.add_argument("--mutants", type=int, default=1000, help="mutants listed per build")
        p.add_argument("--seed", type=int, default=1, help="mutate -seed")
        p.add_argument("--jobs", type=int, default=2, help="simulations or proofs at once")
        p.add_argument("--work", default="target/mutation", help="build folder")
        p.add_argument("--json", default="host/report/mutation.json", help="the report")
    sub.choices["report"].add_argument("--markdown", default=None,
                                       help="also write the docs table to this file")
    for name in ("run", "prove", "stream", "report"):
        sub.choices[name].add_argument(
            "--own", default=None, metavar="LIKE:TOP:FILE[,FILE…]",
            help="your unit instead (judged by the bench of the reference unit LIKE: "
                 "bsample, psample, bounds, mul; give --json a report of your own)")
    sub.choices["check"].add_argument("--sample", type=int, default=50,
                                      help="mutants 1..N of each build's list")
    for name, n in (("run", "2,0"), ("check", "1,0")):
        sub.choices[name].add_argument(
            "--cross", default=n, metavar="K,S",
            help=f"the first K killed mutants and S survivors judged again by Icarus, each on "
                 f"its own netlist (default {n})")
    sub.choices["prove"].add_argument("--timeout", type=float, default=12.0,
                                      help="seconds per proof (one ABC dprove; sat: per SAT call)")
    sub.choices["prove"].add_argument("--engine", choices=("abc", "sat"), default="abc",
                                      help="abc: one miter per build; per mutant register "
                                           "correspondence (ABC's iprove), then ABC's dprove; "
                                           "sat: one miter per mutant, Yosys's sat -tempinduct")
    sub.choices["prove"].add_argument(
        "--steps", default=",".join(equiv.STEPS), metavar="STEP,STEP",
        help="--engine abc: the steps tried per mutant, in their order (corr: register "
             "correspondence; unroll: the unrolled region; dprove: ABC's dprove)")
    sub.choices["prove"].add_argument("--depth", type=int, default=120,
                                      help="largest induction length (--engine sat)")
    sub.choices["prove"].add_argument("--retry", action="store_true",
                                      help="prove the undecided again (e.g. with a longer "
                                           "--timeout)")
    sub.choices["stream"].add_argument("--records", type=int, default=10**6,
                                       help="stream records per survivor")
    sub.choices["stream"].add_argument("--per-shard", type=int, default=20000)
    sub.choices["stream"].add_argument("--stream-seed", type=int, default=1)
    sub.choices["stream"].add_argument(
        "--target-bins", default="", metavar="BIN,BIN",
        help="the stream directed at these coverage bins (uvt.coverage_bins; docs/coverage.md): "
             "a survivor alive after the plain stream meets the directed one")
    return ap


def main(argv: Optional[List[str]] = None) -> int:
    a = _parser().parse_args(argv)
    try:
        repo = _repo(a.repo)
        names = a.builds.split(",") if a.builds else list(
            DEFAULT_BUILDS if a.cmd == "check" else units.BUILDS)
        if a.mutants < 1 or (a.cmd == "check" and not 1 <= a.sample <= a.mutants):
            raise MutationError(f"--mutants {a.mutants}, --sample: need 1 ≤ sample ≤ mutants")
        blds = [units.build(repo, n) for n in names]
        if a.cmd != "check" and a.own:
            blds = [units.own(a.own)]
        work = (repo / a.work).resolve()
        js = repo / a.json
        per = js.parent / js.stem
        if a.cmd == "check":
            return _check(repo, blds, a, work, per)
        meta = {"version": 1, "seed": a.seed, "mutants_per_build": a.mutants,
                "command": "bash host/report/regen.sh --only mutation",
                "yosys": _tool(["yosys", "-V"]), "verilator": _tool(["verilator", "--version"]),
                "mode": "architectural: each bench's -DUVT_ARCH_ONLY / -DUVT_DUT form",
                "runs": {}}
        every = blds if a.cmd != "check" and a.own else [units.build(repo, n) for n in units.BUILDS]
        for b in blds:
            if a.cmd == "run":
                r = flow.run_build(repo, b, a.mutants, a.seed, work / b.name, a.jobs,
                                   cross=_pair(a.cross))
                rows = [x.to_json() for x in r.results]
                try:
                    kept = report.carry(report.load(per, b.name), rows)
                except ValueError as e:
                    raise MutationError(f"{b.name}: {e}") from e
                print(f"{b.name}: later verdicts kept for {kept} survivors")
                report.save(per, b.name, rows)
                meta["runs"][b.name] = {"sets": r.sizes, "seconds": round(r.seconds, 1),
                                        "icarus_confirmed": r.confirmed}
            elif a.cmd == "prove":
                _prove(repo, b, a, work, per)
            elif a.cmd == "stream":
                _stream(repo, b, a, work, per)
            report.write(repo, every, js, per, meta)
        rep = report.write(repo, every, js, per, meta)
        if a.cmd == "report" and a.markdown:
            report.write_atomic(Path(a.markdown), report.markdown(rep))
        for row in rep["builds"]:
            print(f"{row['build']:14} {row['mutants']:5} mutants  vectors {row['killed_by_vectors']:5}"
                  f"  equivalent {row['equivalent']:4}  stream {row['killed_by_stream']:4}"
                  f"  survivors {row['survivors']:4}")
        return 0
    except MutationError as e:
        print(f"uvt.mutation: {e}", file=sys.stderr)
        return 2


def _pair(s: str):
    try:
        k, v = (int(x) for x in s.split(","))
    except ValueError as e:
        raise MutationError(f"--cross {s!r}: K,S (two counts)") from e
    return (k, v)


def _prove(repo: Path, b, a, work: Path, per: Path) -> None:
    rows = report.load(per, b.name)
    done = ("proven", "differs") if a.retry else ("proven", "differs", "undecided")
    todo = [r for r in rows if report.fate(r) == "survivor" and r.get("equivalent") not in done]
    if not todo:
        return
    d = work / f"prove-{b.name}"
    net = design.single(repo, b, None, d)
    t0 = time.time()
    byid = {r["id"]: r for r in todo}
    muts = [design.from_row(r) for r in todo]
    if a.engine == "sat":
        # One Yosys process per part of 25 mutants (each reads the unit once), ``jobs`` at a
        # time; the file is saved after each part.
        parts = [muts[k:k + 25] for k in range(0, len(muts), 25)]
        with ThreadPoolExecutor(max_workers=a.jobs) as ex:
            for got in ex.map(lambda p: equiv.prove_sat(repo, b, p, net, d / f"p{p[0].id}",
                                                        a.depth, a.timeout), parts):
                for k, v in got.items():
                    byid[k]["equivalent"] = v
                report.save(per, b.name, rows)
    else:
        # The miter holds every mutant the sets leave alive (not only those proven now), so a
        # later run (--retry, a longer --timeout) finds it built.
        alive = [design.from_row(r) for r in rows if not r.get("killed_by")]
        try:
            # The file is saved every 20 verdicts, so an interrupted run keeps what it decided.
            for n, (k, v) in enumerate(equiv.prove(repo, b, alive, muts, a.mutants, net, d,
                                                   a.timeout, a.jobs,
                                                   a.steps.split(","))):
                byid[k]["equivalent"] = v
                if n % 20 == 19:
                    report.save(per, b.name, rows)
        except equiv.Unprovable as e:
            print(f"{e}: its survivors are left as they were (--engine sat proves one miter "
                  "per mutant)")
            return
    report.save(per, b.name, rows)
    c = Counter(r["equivalent"] for r in todo)
    print(f"{b.name}: of {len(todo)} survivors {c['proven']} proven equivalent, {c['differs']} "
          f"differ on the domain's inputs, {c['undecided']} undecided ({time.time() - t0:.0f} s)")


def _stream(repo: Path, b, a, work: Path, per: Path) -> None:
    if not stream.has_stream(b):
        return
    rows = report.load(per, b.name)
    shards = max(1, a.records // a.per_shard)
    target = tuple(t for t in a.target_bins.split(",") if t)
    # Survivors not yet streamed this far (a survivor alive after as many records is not run
    # again: a longer stream runs the survivors alive after a shorter one); a directed stream
    # is kept apart (``stream_directed``), after the plain one, for survivors not proven
    # equivalent.
    key, n = ("stream_directed", "stream_directed_records") if target else ("stream",
                                                                           "stream_records")
    todo = [r for r in rows if report.fate(r) == "survivor"
            and r.get(n, 0) < shards * a.per_shard
            and not (target and r.get("equivalent") == "proven")]
    if not todo:
        return
    d = work / f"stream-{b.name}"
    ids = {r["id"] for r in todo}
    muts = [m for m in design.make(repo, b, a.mutants, a.seed, d) if m.id in ids]
    exe = stream.build_runner(repo, b, design.netlist(repo, b, muts, a.mutants, d), d, a.jobs)
    got = stream.kill(b, exe, [r["id"] for r in todo], a.stream_seed, shards, a.per_shard,
                      a.jobs, target=target)
    for r in todo:
        v = got.get(r["id"])
        r[key] = v if v is not None else "alive"
        r[n] = shards * a.per_shard
        if target:
            r["stream_target"] = list(target)
    report.save(per, b.name, rows)


def _check(repo: Path, blds, a, work: Path, per: Path) -> int:
    bad = 0
    for b in blds:
        want = {d["id"]: d for d in report.load(per, b.name)}
        if not want:
            raise MutationError(f"{per}/{b.name}.jsonl: no committed results of {b.name} "
                                "(bash host/report/regen.sh --only mutation)")
        r = flow.run_build(repo, b, a.mutants, a.seed, work / f"check-{b.name}", a.jobs, a.sample,
                           _pair(a.cross))
        for x in r.results:
            got, exp = x.to_json(), want.get(x.mutation.id)
            if exp is None or got["mutate"] != exp.get("mutate"):
                print(f"{b.name} mutant {x.mutation.id}: the list is not the committed one "
                      f"(the RTL or yosys changed): bash host/report/regen.sh --only mutation")
                bad += 1
                continue
            keys = ("killed_by", "record", "field")
            if any(got.get(k) != exp.get(k) for k in keys):
                print(f"{b.name} mutant {x.mutation.id} ({x.mutation.alone()}): committed "
                      f"{ {k: exp.get(k) for k in keys} }, now { {k: got.get(k) for k in keys} }")
                bad += 1
        print(f"{b.name}: mutants 1..{a.sample}, {sum(x.killed for x in r.results)} killed, "
              f"{len(r.results)} compared with {b.name}.jsonl")
    print(f"{'PASS' if bad == 0 else 'FAIL'}: {bad} differences from the committed report")
    return 0 if bad == 0 else 1
