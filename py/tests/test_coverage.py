"""Coverage from the model: ``uvt.coverage`` counts the core's own bins, the same as ``uvt
vectors ver --coverage`` for the same records; ``gen(target=…)`` biases the stream toward the
named bins and stays seeded and shard-invariant."""

import json
import subprocess

import numpy as np
import pytest

import uvt
from conftest import UNIT, read_hex


@pytest.mark.parametrize("kind", ["bsample", "psample"])
def test_counts_equal_the_clis(kind, uvt_bin, tmp_path):
    ins = read_hex(UNIT / f"{kind}_in.hex")
    outs = read_hex(UNIT / f"{kind}_out.hex")
    got = uvt.coverage(kind, ins)
    assert set(got) == {n for n, _, _ in uvt.coverage_bins(kind)}
    assert got[f"{kind}.covered"] + got[f"{kind}.missed"] == len(ins)
    pairs = "".join(" ".join(f"{w:08x}" for w in (*i, *o)) + "\n" for i, o in zip(ins, outs))
    path = tmp_path / "cov.json"
    subprocess.run([str(uvt_bin), "vectors", "ver", kind, "--coverage", str(path)],
                   input=pairs, check=True, capture_output=True, text=True)
    cli = {r["bin"]: r["count"] for r in json.loads(path.read_text())["bins"]}
    assert cli == got


def test_unreachable_bins_name_their_reason():
    rows = uvt.coverage_bins()
    assert {k for _, k, _ in rows} == {"bsample", "psample"}
    assert any(why for _, _, why in rows)
    with pytest.raises(uvt.InputError):
        uvt.coverage("select", uvt.gen("select", None, 1, 3))


def test_target_biases_and_stays_shard_invariant():
    plain = uvt.gen("bsample", None, 3, 300)
    aimed = uvt.gen("bsample", None, 3, 300, target=["bsample.edge.zero"])
    assert uvt.coverage("bsample", aimed)["bsample.edge.zero"] > 3 * uvt.coverage("bsample", plain)["bsample.edge.zero"]
    parts = [uvt.gen("bsample", None, 3, 300, shard=(k, 4), target=["bsample.edge.zero"]) for k in range(1, 5)]
    assert np.array_equal(np.concatenate(parts), aimed)
    with pytest.raises(uvt.InputError):
        uvt.gen("bsample", None, 3, 10, target=["psample.edge.zero"])
    with pytest.raises(uvt.InputError):
        uvt.gen("bsample", None, 3, 10, target=["bsample.tie.coincident"])
