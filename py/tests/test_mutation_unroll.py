"""The unrolled region (uvt.mutation.unroll), the prover's second step, on miters small enough
to read: two copies of a two-stage pipeline whose first stage loads p = x AND y and q = x, so
p implies q in every reachable state; the gate copy's second register loads ``s ? t : p``."""

from pathlib import Path

import pytest

from uvt.mutation import corr, equiv, unroll

# Inputs x = 2, y = 4, select s = 6; latches gold p, q, r = 8, 10, 12 and gate p, q, r =
# 14, 16, 18; the one output is r(gold) XOR r(gate).
HEAD = ("aag 17 3 6 1 8\n2\n4\n6\n8 20\n10 2\n12 8\n14 20\n16 2\n18 29\n35\n20 4 2\n")
TAIL = "24 22 6\n26 14 7\n28 27 25\n30 19 12\n32 18 13\n34 33 31\n"
# t = p AND q: equal to p wherever p implies q, which only the stage before makes so
IMPLIED = HEAD + "22 16 14\n" + TAIL
# t = p AND NOT q: 0 in every reachable state, so it differs from p whenever x = y = 1
NEVER = HEAD + "22 17 14\n" + TAIL
PAIRS = {3: 0, 4: 1, 5: 2}                       # gate latch -> gold latch named alike


def _cone(text: str, tmp_path: Path) -> unroll.Cone:
    c = corr.classes(corr.Aig(text), [6], tmp_path, equiv.binary, 30.0, PAIRS)
    assert c is not None, "mutant 0 (the unit against itself) must prove"
    assert c.rep[3:] == [0, 1, 2], c.rep
    return unroll.Cone(c)


def test_correspondence_alone_cannot_prove_a_fact_of_the_stage_before(tmp_path):
    c = _cone(IMPLIED, tmp_path).c
    got = corr.iprove(equiv.binary(c.text(), c.ties(1)), tmp_path / "k.aig", 30.0)
    assert got is False, "with p and q free, p = 1 and q = 0 tells the copies apart"


def test_the_mutation_reaches_the_gate_copy_s_second_register_only(tmp_path):
    assert _cone(IMPLIED, tmp_path).reach(1) == {5}
    assert _cone(IMPLIED, tmp_path).reach(0) == set()


def test_the_unrolled_region_proves_it(tmp_path):
    cone = _cone(IMPLIED, tmp_path)
    # no stage before kept: p and q cut to free inputs, so the check fails and proves nothing
    aig, cut = unroll.check(cone, 1, 0)
    assert aig is not None and cut == 2
    assert corr.iprove(aig, tmp_path / "u.aig", 30.0) is False
    # one stage before kept: nothing is cut, and the check holds
    aig, cut = unroll.check(cone, 1, 1)
    assert aig is not None and cut == 0
    assert corr.iprove(aig, tmp_path / "u.aig", 30.0) is True
    assert unroll.prove(cone, 1, tmp_path, 30.0, backs=(0, 1)) == "proven"


def test_a_mutant_that_differs_from_the_all_zero_start_is_found(tmp_path):
    cone = _cone(NEVER, tmp_path)
    assert unroll.prove(cone, 1, tmp_path, 30.0, backs=(0, 1)) == "differs"


def test_a_loop_in_the_region_gives_no_verdict(tmp_path):
    # gold and gate q hold their value (next = q): the region has a loop, so no clock is
    # free of the start state
    loop = IMPLIED.replace("\n10 2\n", "\n10 10\n").replace("\n16 2\n", "\n16 16\n")
    cone = _cone(loop, tmp_path)
    assert unroll.check(cone, 1, 1) == (None, 0)
    assert unroll.prove(cone, 1, tmp_path, 30.0, backs=(1,)) == "undecided"


@pytest.mark.parametrize("k", [0, 2])
def test_a_select_value_that_picks_no_mutation_is_the_unit_itself(tmp_path, k):
    # the select input is one bit here: 0 and 2 both leave the mutation off
    cone = _cone(NEVER, tmp_path)
    assert cone.reach(k) == set()
    assert unroll.prove(cone, k, tmp_path, 30.0, backs=(1,)) == "proven"
