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


def test_the_planar_proof_domain_keeps_records_and_maps_the_rest_inside(tmp_path):
    """``Bench.domain`` of the planar unit, simulated by Icarus: an input of the record domain
    passes unchanged (f at −62 and 68, the viewport's sides at 1 and 2048, the sample at its
    last position, σ = ±1, a nonzero normal), one outside it is mapped inside (f 69 and −63 to
    the ends, a side of 0 or 4095, a sample past the viewport, σ = 0 or −2, a zero normal)."""
    import shutil
    import subprocess

    if shutil.which("iverilog") is None:
        pytest.skip("iverilog not installed (tests/run.sh installs it)")
    dom = units.BENCHES["uvt_psample"].domain
    width = {"f": 8, "vp_w": 12, "vp_h": 12, "xs": 20, "ys": 20, "sigma": 2, "n": 288}
    assert [n for n, _ in dom] == list(width)
    decl = "".join(f"    reg [{w - 1}:0] {n};\n" for n, w in width.items())
    decl += "".join(f"    wire [{width[n] - 1}:0] d_{n} = {e};\n" for n, e in dom)
    cases = [  # inputs, then the expected d_ values (f as 8-bit two's complement)
        ({"f": 68, "vp_w": 1, "vp_h": 2048, "xs": 255, "ys": 2048 * 256 - 1, "sigma": 1,
          "n": 5 | 5 << 160 | 1 << 287}, {"f": 68, "vp_w": 1, "vp_h": 2048, "xs": 255,
                                         "ys": 2048 * 256 - 1, "sigma": 1,
                                         "n": 5 | 5 << 160 | 1 << 287}),
        ({"f": 0xc2, "vp_w": 7, "vp_h": 9, "xs": 0, "ys": 0, "sigma": 3, "n": (1 << 288) - 1},
         {"f": 0xc2, "vp_w": 7, "vp_h": 9, "xs": 0, "ys": 0, "sigma": 3, "n": (1 << 288) - 1}),
        ({"f": 69, "vp_w": 0, "vp_h": 4095, "xs": 300, "ys": (1 << 20) - 1, "sigma": 0, "n": 0},
         {"f": 68, "vp_w": 1, "vp_h": 2048, "xs": 255, "ys": 2048 * 256 - 1, "sigma": 1,
          "n": 1 | 1 << 96 | 1 << 192}),
        ({"f": 0xc1, "vp_w": 2, "vp_h": 2, "xs": 512, "ys": 600, "sigma": 2, "n": 7 << 200},
         {"f": 0xc2, "vp_w": 2, "vp_h": 2, "xs": 511, "ys": 511, "sigma": 1,
          "n": 7 << 200 | 1 | 1 << 96}),
    ]
    body = ""
    for ins, want in cases:
        body += "".join(f"        {n} = {width[n]}'h{v:x};\n" for n, v in ins.items())
        body += "        #1;\n"
        body += "".join(f"        if (d_{n} !== {width[n]}'h{v:x}) begin $display(\"BAD {n} %h\", "
                        f"d_{n}); end\n" for n, v in want.items())
    src = tmp_path / "dom.v"
    src.write_text(f"module t;\n{decl}    initial begin\n{body}        $display(\"DONE\");\n"
                   "    end\nendmodule\n")
    exe = tmp_path / "dom.vvp"
    subprocess.run(["iverilog", "-g2005", "-o", str(exe), str(src)], check=True)
    out = subprocess.run(["vvp", "-n", str(exe)], capture_output=True, text=True).stdout
    assert "DONE" in out and "BAD" not in out, out


def test_a_miter_built_for_more_mutants_serves_fewer(tmp_path):
    """``equiv._aigs`` (the prover's miter, minutes of Yosys on a datapath unit) is kept for a
    later proof of fewer mutants (the sets killed some since) and built again for a mutant it
    does not hold; the select literals and the register pairs are the same either way."""
    import shutil

    from uvt.mutation import design, equiv

    if shutil.which("yosys") is None:
        pytest.skip("yosys not installed (tests/run.sh installs it)")
    b = units.build(ROOT, "mul31")
    muts = design.make(ROOT, b, 1000, 1, tmp_path / "list")[:4]
    net = design.single(ROOT, b, None, tmp_path / "p")
    aag = tmp_path / "p" / "miter.aag"
    first = equiv._aigs(ROOT, b, muts[:3], 1000, net, tmp_path / "p")
    built = aag.stat().st_mtime_ns
    again = equiv._aigs(ROOT, b, muts[1:3], 1000, net, tmp_path / "p")
    assert aag.stat().st_mtime_ns == built, "a miter holding every mutant asked for was rebuilt"
    assert again[1:] == first[1:] and again[2], "select literals or register pairs differ"
    equiv._aigs(ROOT, b, muts[2:4], 1000, net, tmp_path / "p")
    assert aag.stat().st_mtime_ns != built, "a miter without mutant 4 was kept"
    held = (tmp_path / "p" / "apply.txt").read_text().splitlines()
    assert held == [m.selected(design.sel_width(1000)) for m in muts[2:4]]
