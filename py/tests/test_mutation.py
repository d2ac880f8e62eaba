"""The mutation report's parts agree (docs/mutation.md): the summary host/report/mutation.json
is what the per-build files make, the table host/report/mutation.md is what the summary makes,
and every mutant line is whole. The flow itself runs in tests/tests/external/mutation.rs."""

import json

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
