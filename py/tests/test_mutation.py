"""The mutation report's parts agree (docs/mutation.md): the summary host/report/mutation.json
is what the per-build files make, the table host/report/mutation.md is what the summary makes,
and every mutant line is whole. The flow itself runs in tests/tests/external/mutation.rs."""

import json

import pytest

from uvt.mutation import report, units
from uvt.mutation.errors import MutationError

from conftest import ROOT

REPORT = ROOT / "host" / "report"


def test_summary_and_table_are_made_from_the_per_build_files():
    rep = json.loads((REPORT / "mutation.json").read_text())
    per = REPORT / "mutation"
    names = [r["build"] for r in rep["builds"]]
    assert names == [n for n in units.BUILDS if (per / f"{n}.jsonl").is_file()]
    for row in rep["builds"]:
        b = units.build(ROOT, row["build"])
        rows = report.load(per, b.name)
        again = report.summary(b, rows, {k: row[k] for k in ("sets", "seconds",
                                                               "icarus_confirmed")})
        assert again == row, b.name
        assert row["mutants"] == rep["mutants_per_build"] == len({r["id"] for r in rows})
        for r in rows:
            assert r["mutate"].startswith("mutate -mode "), r
            assert report.fate(r) in ("vectors", "equivalent", "stream", "survivor")
            if r["killed_by"]:
                assert r["killed_by"] in (*units.SETS, "pairs") and r["field"], r
    assert (REPORT / "mutation.md").read_text() == report.markdown(rep)


def test_a_build_outside_the_table_is_refused_by_name():
    try:
        units.build(ROOT, "bsample-nonesuch")
    except MutationError as e:
        assert "bsample-nonesuch" in str(e)
    else:
        raise AssertionError("no error")


def test_a_new_run_keeps_later_verdicts_of_mutants_that_survive_again():
    """``report.carry``: a survivor keeps its proof and stream verdicts when the same mutation
    survives the new vectors; a mutant they now kill drops them; another mutation under the
    same id keeps nothing; a proven mutant that the vectors kill is an error."""
    old = [{"id": 1, "mutate": "m1", "killed_by": None, "equivalent": "undecided",
            "stream": "alive", "stream_records": 20000},
           {"id": 2, "mutate": "m2", "killed_by": None, "equivalent": "differs"},
           {"id": 3, "mutate": "m3", "killed_by": None, "equivalent": "undecided"}]
    new = [{"id": 1, "mutate": "m1", "killed_by": None},
           {"id": 2, "mutate": "m2", "killed_by": "unit", "record": 9},
           {"id": 3, "mutate": "other", "killed_by": None}]
    assert report.carry(old, new) == 1
    assert new[0]["equivalent"] == "undecided" and new[0]["stream_records"] == 20000
    assert "equivalent" not in new[1] and "equivalent" not in new[2]
    proven = [{"id": 4, "mutate": "m4", "killed_by": None, "equivalent": "proven"}]
    with pytest.raises(ValueError, match="mutant 4 was proven equivalent"):
        report.carry(proven, [{"id": 4, "mutate": "m4", "killed_by": "unit", "record": 0}])
