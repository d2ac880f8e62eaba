"""Records: gen is deterministic and shard-invariant (and is `uvt vectors gen`'s stream); run,
compare and decode reproduce the committed vectors; a flipped word is a mismatch naming the field."""

import subprocess

import numpy as np
import pytest

import uvt
from conftest import UNIT, read_hex

STREAM_KINDS = ["setup", "select", "bsample", "psample", "resolve"]


@pytest.mark.parametrize("kind", STREAM_KINDS)
def test_gen_is_deterministic_and_shard_invariant(kind):
    whole = uvt.gen(kind, None, 11, 50)
    assert whole.dtype == np.uint32 and whole.shape[0] == 50
    assert np.array_equal(whole, uvt.gen(kind, None, 11, 50))
    assert not np.array_equal(whole, uvt.gen(kind, None, 12, 50))
    for m in (1, 3, 7):
        parts = [uvt.gen(kind, None, 11, 50, shard=(k, m)) for k in range(1, m + 1)]
        assert np.array_equal(np.concatenate(parts), whole)
    assert np.array_equal(uvt.gen(kind, None, 11, 50, shard="2/3"), whole[16:33])


def test_gen_is_the_cli_stream(uvt_bin):
    for shard in ("1/1", "2/5"):
        text = subprocess.run(
            [str(uvt_bin), "vectors", "gen", "bsample", "--config", "bounded-12-12-12-24", "--seed", "5", "--count", "40", "--shard", shard],
            check=True, capture_output=True, text=True,
        ).stdout
        cli = np.array([[int(w, 16) for w in line.split()] for line in text.splitlines()], dtype=np.uint32)
        assert np.array_equal(uvt.gen("bsample", "bounded-12-12-12-24", 5, 40, shard=shard), cli)


# the committed unit vectors: bounded (vectors/unit) and exact (vectors/unit_exact, whose
# sample files hold the exact sample-test records; vectors/unit's are empty)
DIRS = {"unit": UNIT, "unit_exact": UNIT.parent / "unit_exact"}


def committed(kind, folder="unit"):
    d = DIRS[folder]
    ins, outs = read_hex(d / f"{kind}_in.hex"), read_hex(d / f"{kind}_out.hex")
    setup = None
    if uvt.KINDS[kind].needs_setup and len(ins):
        setup = read_hex(d / "setup_in.hex")[ins[:, 0]]  # field `tri`: word 0
    return ins, outs, setup


def test_every_kind_has_committed_records():
    for kind in uvt.KINDS:
        assert any(len(committed(kind, f)[0]) for f in DIRS), kind


@pytest.mark.parametrize("folder", list(DIRS))
@pytest.mark.parametrize("kind", list(uvt.KINDS))
def test_run_and_compare_reproduce_the_committed_vectors(kind, folder):
    ins, outs, setup = committed(kind, folder)
    if len(ins) == 0:
        assert len(outs) == 0
        return
    assert np.array_equal(uvt.run(kind, ins, setup=setup), outs)
    c = uvt.compare(kind, ins, outs, setup=setup)
    assert (c.pairs, c.mismatched, c.mismatches, c.ok) == (len(ins), 0, [], True)


def test_a_flipped_word_is_a_mismatch_naming_the_field():
    ins, outs, _ = committed("bsample")
    bad = outs.copy()
    bad[5, 1] ^= 1 << 3  # depth, bit 3
    bad[9, 8] ^= 1  # e0, upper word
    c = uvt.compare("bsample", ins, bad)
    assert (c.pairs, c.mismatched) == (len(ins), 2)
    m = c.mismatches[0]
    assert (m.record, m.field, m.expected ^ m.observed) == (5, "depth", 8)
    assert m.expected == int(outs[5, 1].view(np.int32)) and "field depth: expected" in m.message
    assert (c.mismatches[1].record, c.mismatches[1].field) == (9, "e0")
    # the architectural comparison sees depth, not the edge value
    a = uvt.compare("bsample", ins, bad, architectural=True)
    assert [(x.record, x.field) for x in a.mismatches] == [(5, "depth")]
    assert len(uvt.compare("bsample", ins, bad, max_mismatches=1).mismatches) == 1


def test_decode_names_every_field():
    ins, outs, setup = committed("bounds")
    d = uvt.decode("bounds", ins[0], outs[0], setup=setup[0])
    assert d["kind"] == "bounds" and d["model_error"] is None
    assert list(d["in"]) == [f[0] for f in uvt.fields("bounds_in")]
    assert d["model"] == d["out"] and d["diff"] == []
    ins, outs, _ = committed("bsample")
    flipped = outs[0].copy()
    flipped[0] ^= 1
    d = uvt.decode("bsample", ins[0], flipped)
    assert d["in"]["viewport_w"] == ins[0][30] & 0xFFFF
    assert d["out"]["covered"] != d["model"]["covered"] and d["diff"][0].startswith("field covered:")
    # a field wider than 128 bits (the exact sample test's 192-bit edge values) is exact
    ins, outs, setup = committed("sample", "unit_exact")
    d = uvt.decode("sample", ins[0], outs[0], setup=setup[0])
    wide = [f for f in uvt.fields("sample_out") if f[3] > 128]
    assert wide
    for name, word, _, width, signed, _ in wide:
        n = width // 32
        raw = int.from_bytes(b"".join(int(w).to_bytes(4, "big") for w in outs[0][word : word + n]), "big", signed=signed)
        assert d["out"][name] == raw


def test_decode_reports_the_models_refusal():
    rec = uvt.gen("bsample", None, 1, 1)[0].copy()
    rec[34] = 0x7FFFFFFF  # t far beyond 1.0
    d = uvt.decode("bsample", rec)
    assert d["model"] is None and "t" in d["model_error"]
