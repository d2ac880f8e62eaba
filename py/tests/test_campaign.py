"""Campaigns on Dask (uvt.campaign): a small campaign on a 2-worker LocalCluster passes, its
verdict is the same on 1 and 2 workers, a killed worker and a restart from a state file lose no
shard, a mutated unit (the bounded unit's fill-rule tie key reversed, in Verilator) and a
corrupted model output are found with shard, record and decoded fields, and bad input to every
entry point is a clear error.

The Verilator tests build ``vectors/dpi/pipe.cpp`` with the committed and the mutated unit
(about 30 s each, once: the builds are kept in ``UVT_CAMPAIGN_BUILD``, default
``$TMPDIR/uvt-campaign-build``); they need ``verilator`` (tests/run.sh installs it) and fail,
not skip, without it.
"""

from __future__ import annotations

import json
import os
import signal
import sys
import tempfile
import threading
import time
from pathlib import Path

import pytest

from uvt.campaign import Campaign, CampaignError, run, run_shard, shard_range
from uvt.campaign.cli import main
from uvt.campaign.state import StateFile
from uvt.campaign.verilator import build_pipe

REPO = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get("UVT_CAMPAIGN_BUILD",
                            Path(tempfile.gettempdir()) / "uvt-campaign-build"))


@pytest.fixture(scope="module")
def cluster():
    """One 2-worker LocalCluster (single-threaded worker processes) for the module."""
    from distributed import Client, LocalCluster

    c = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0")
    client = Client(c)
    yield client
    client.close()
    c.close()


def test_small_campaign_passes_on_two_workers(cluster):
    s = run(Campaign(shards=6, per_shard=500, seed=3), cluster, progress=False)
    assert s.passed and s.records == 3000 and s.mismatched == 0 and s.workers == 2
    cov = s.coverage
    assert cov["bsample.records"] == 3000
    # the model's bins: one class bin per record, a covered or missed bin per record
    assert sum(cov[f"bsample.class.{c}"] for c in ("static", "motion", "defocus", "both")) == 3000
    assert cov["bsample.covered"] + cov["bsample.missed"] == 3000
    for what in ("bsample.covered", "bsample.edge.zero", "bsample.decide.w_le_0"):
        assert cov[what] > 0, what
    assert "PASS" in s.table() and "| bsample.class.both" in s.table()
    # two workers did the work
    assert len({r["worker"] for r in s.shards.values()}) == 2


def test_same_verdict_on_one_and_two_workers(cluster):
    spec = Campaign(shards=5, per_shard=400, seed=11, corrupt=1234)
    two = run(spec, cluster, progress=False)
    one = run(spec, workers=1, progress=False)
    assert one.workers == 1 and two.workers == 2
    assert one.verdict() == two.verdict()
    assert not two.passed and two.failing_shards == [4]


def test_shards_are_the_stream():
    """The records of shard K/M are records range(K/M) of the stream, whatever M."""
    from uvt.campaign._model import load

    m = load()
    whole = m.gen("bsample", "bounded-16-16-16-20", 5, 12, (1, 1))
    parts = [m.gen("bsample", "bounded-16-16-16-20", 5, 12, (k, 5)) for k in range(1, 6)]
    assert [len(p) for p in parts] == [len(shard_range(12, k, 5)) for k in range(1, 6)]
    assert (whole == __import__("numpy").concatenate(parts)).all()


def test_corrupted_output_is_found_and_decoded(cluster):
    spec = Campaign(shards=4, per_shard=300, corrupt=777)
    s = run(spec, cluster, progress=False)
    f = s.first_failure
    assert f["shard"] == 3 and s.mismatched == 1 and s.failing_shards == [3]
    x = f["failure"]
    assert x["record"] == 777 and x["in_shard"] == 777 - 600
    assert [d["field"] for d in x["fields"]] == ["depth"]
    assert x["decoded"]["input"], "the failing input is decoded"
    assert "--shard 3/4" in x["reproduce"]["record"] and "sed -n 178p" in x["reproduce"]["record"]
    assert x["reproduce"]["decode"].startswith("uvt vectors decode bsample ")
    assert "FAIL shard 3/4, record 777" in s.table()


def test_resume_from_state_file_runs_only_missing_shards(cluster, tmp_path):
    spec = Campaign(shards=6, per_shard=300, seed=2)
    full = run(spec, cluster, progress=False)
    state = tmp_path / "state.jsonl"
    first = run(spec, cluster, state=str(state), progress=False)
    assert first.ran == 6
    lines = state.read_text().splitlines()
    assert len(lines) == 7
    # a campaign stopped after 2 shards, the third half written
    state.write_text("\n".join(lines[:3]) + "\n" + lines[3][:40])
    again = run(spec, cluster, state=str(state), progress=False)
    assert again.resumed == 2 and again.ran == 4
    assert again.verdict() == full.verdict()
    assert len(state.read_text().splitlines()) == 7
    # a state file of another campaign is refused
    with pytest.raises(CampaignError, match="another campaign"):
        run(Campaign(shards=6, per_shard=300, seed=9), cluster, state=str(state), progress=False)


def test_killed_worker_loses_no_shard(tmp_path):
    """A worker process killed while it runs a shard: the shard runs again on the restarted
    worker; the verdict is the uninterrupted campaign's."""
    from distributed import Client, LocalCluster

    spec = Campaign(shards=10, per_shard=20000, seed=4)
    c = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0")
    client = Client(c)
    try:
        out = {}
        t = threading.Thread(target=lambda: out.setdefault(
            "s", run(spec, client, state=str(tmp_path / "s.jsonl"), progress=False)))
        t.start()
        killed, in_flight = None, []
        deadline = time.time() + 30
        while killed is None and time.time() < deadline:
            busy = {w: ts for w, ts in client.processing().items() if ts}
            done = len((tmp_path / "s.jsonl").read_text().splitlines()) - 1 \
                if (tmp_path / "s.jsonl").exists() else 0
            if busy and done >= 1:
                w = sorted(busy)[0]
                pid = client.run(os.getpid, workers=[w])[w]
                in_flight = [int(str(key).rsplit("-", 1)[1]) for key in busy[w]]
                os.kill(pid, signal.SIGKILL)
                killed = pid
            time.sleep(0.05)
        t.join(120)
        assert killed is not None, "no worker was busy to kill"
        s = out["s"]
        assert s.passed and sorted(s.shards) == list(range(1, 11))
        # a shard the killed worker held ran again in another process
        assert any(s.shards[k]["worker"].rsplit(":", 1)[1] != str(killed) for k in in_flight)
        assert s.verdict() == run(spec, client, progress=False).verdict()
    finally:
        client.close()
        c.close()


def test_stop_on_failure_cancels_and_decodes(cluster):
    spec = Campaign(shards=40, per_shard=200, corrupt=250)
    s = run(spec, cluster, stop_on_failure=True, progress=False)
    assert s.first_failure["shard"] == 2
    assert s.first_failure["failure"]["record"] == 250
    assert s.cancelled > 0 and len(s.shards) < 40 and not s.passed


@pytest.fixture(scope="module")
def pipes():
    """The Verilator stream runner of the committed unit and of the tie-key mutant."""
    good = build_pipe(str(BUILD / "good"), str(REPO))
    bad = build_pipe(str(BUILD / "tie-key"), str(REPO), mutant="tie-key")
    return good, bad


def test_verilator_unit_passes(cluster, pipes):
    good, _ = pipes
    s = run(Campaign(shards=4, per_shard=1500, simulator=str(good)), cluster, progress=False)
    assert s.passed, s.table()
    assert s.coverage["bsample.edge.zero"] > 0


def test_verilator_reversed_tie_key_is_found(cluster, pipes):
    _, bad = pipes
    spec = Campaign(shards=4, per_shard=1500, simulator=str(bad))
    s = run(spec, cluster, progress=False)
    assert not s.passed and s.mismatched > 0
    f = s.first_failure
    x = f["failure"]
    k = f["shard"]
    assert x["record"] in shard_range(spec.count, k, spec.shards)
    assert "covered" in [d["field"] for d in x["fields"]]
    # the failing sample is a fill-rule tie: an expected edge value of 0
    e = x["expected"][8:14]
    assert any(e[i] == e[i + 1] == "00000000" for i in (0, 2, 4)), x
    assert x["decoded"]["input"]
    assert f"--shard {k}/4 | {bad} | uvt vectors ver bsample" in x["reproduce"]["shard"]
    # the same shard alone, in this process, reports the same record
    assert run_shard(spec, k)["failure"]["record"] == x["record"]


@pytest.mark.parametrize("kw, match", [
    (dict(kind="bounds"), "stream-less kind"),
    (dict(kind="nope"), "unknown or stream-less kind"),
    (dict(config="bounded-99-1-1-1"), "bounded-99-1-1-1"),
    (dict(kind="select", config="bounded-16-16-16-20"), "no configuration"),
    (dict(kind="psample", config="bounded-16-16-16-20"), "planar"),
    (dict(shards=0), "at least one shard"),
    (dict(per_shard=0), "at least one record"),
    (dict(shards=2.5), "integer"),
    (dict(seed=-1), "seed"),
    (dict(simulator="/no/such/sim"), "not found"),
    (dict(simulator="no-such-simulator-uvt"), "not found"),
    (dict(simulator=""), "empty"),
    (dict(corrupt=10**9), "corrupt"),
    (dict(simulator="cat", corrupt=1), "self-test"),
])
def test_bad_campaigns_are_refused(kw, match):
    with pytest.raises(CampaignError, match=match):
        Campaign(**{"shards": 2, "per_shard": 10, **kw}).validate()
    with pytest.raises(CampaignError, match=match):
        run(Campaign(**{"shards": 2, "per_shard": 10, **kw}), progress=False)


def test_bad_entry_points(cluster, tmp_path, capsys):
    with pytest.raises(CampaignError, match="local worker"):
        run(Campaign(shards=1, per_shard=1), workers=0)
    with pytest.raises(CampaignError, match="1 ≤ K"):
        from uvt.campaign.task import only_shard
        only_shard(Campaign(shards=2, per_shard=1), 3)
    with pytest.raises(CampaignError, match="mutant"):
        build_pipe(str(tmp_path), str(REPO), mutant="nope")
    with pytest.raises(CampaignError, match="no uvt checkout"):
        build_pipe(str(tmp_path), str(tmp_path))
    (tmp_path / "st").write_text("not json\n")
    with pytest.raises(CampaignError, match="line 1 is not JSON"):
        StateFile(str(tmp_path / "st"), Campaign())
    assert main(["run", "--shards", "0", "--per-shard", "5", "--no-progress"]) == 2
    assert "at least one shard" in capsys.readouterr().err
    assert main(["run", "--kind", "nope", "--shards", "1", "--per-shard", "5"]) == 2
    assert main(["run", "--config", "x", "--shards", "1", "--per-shard", "5"]) == 2
    assert main(["run", "--sim", "/no/sim", "--shards", "1", "--per-shard", "5"]) == 2
    assert "not found" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        main(["run", "--per-shard", "5"])  # --shards missing: argparse's usage error


def test_simulator_that_loses_records_is_a_shard_error(cluster, tmp_path):
    """An external simulator that drops a record, or exits non-zero, fails its shard with the
    reason (and the state file does not record it, so a restart runs it again)."""
    lossy = tmp_path / "lossy.py"
    lossy.write_text("import sys\nlines = sys.stdin.read().splitlines()\n"
                     "print('\\n'.join(lines[1:]))\n")
    spec = Campaign(shards=2, per_shard=5, simulator=f"{sys.executable} {lossy}")
    s = run(spec, cluster, state=str(tmp_path / "st"), progress=False)
    assert not s.passed and "lost or added records" in s.first_failure["error"]
    assert len((tmp_path / "st").read_text().splitlines()) == 1
    crash = Campaign(shards=1, per_shard=5, simulator=f"{sys.executable} -c 'raise SystemExit(3)'")
    s = run(crash, cluster, progress=False)
    assert "exited with status 3" in s.first_failure["error"]


def test_cli_runs_and_writes_json(tmp_path, capsys):
    out = tmp_path / "s.json"
    rc = main(["run", "--shards", "3", "--per-shard", "200", "--workers", "1",
               "--no-progress", "--json", str(out)])
    assert rc == 0
    d = json.loads(out.read_text())
    assert d["passed"] and d["records"] == 600
    assert "PASS" in capsys.readouterr().out
    rc = main(["run", "--shards", "3", "--per-shard", "200", "--corrupt", "450",
               "--only-shard", "3"])
    assert rc == 1 and json.loads(capsys.readouterr().out)["failure"]["record"] == 450
