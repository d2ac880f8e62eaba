"""Register correspondence (uvt.mutation.corr), the first step of the mutation flow's ABC
prover, on miters small enough to read: two copies of a two-register pipeline, the gate copy's
first register loading a mutated value when the select input is 1."""

from pathlib import Path

from uvt.mutation import corr, equiv

# Inputs x = 2, y = 4, select s = 6; latches gold r1 = 8, gold r2 = 10, gate r1 = 12, gate
# r2 = 14; the one output is r2(gold) XOR r2(gate). The gate's r1 loads m = s ? t : x.
HEAD = "aag 15 3 4 1 8\n2\n4\n6\n8 2\n10 8\n12 25\n14 12\n31\n"
MUX = "20 6 19\n22 7 2\n24 21 23\n26 10 15\n28 11 14\n30 27 29\n"
# t = x OR (x AND y) = x: equivalent, but only SAT (not structure) shows it
ABSORB = HEAD + "16 4 2\n18 3 17\n" + MUX
# t = NOT x: mutant 1 loads the inverse
INVERT = HEAD + "16 2 2\n18 2 2\n" + MUX


def _check(text: str, tmp_path: Path, k: int):
    c = corr.classes(corr.Aig(text), [6], tmp_path, equiv.binary, 30.0)
    assert c is not None, "mutant 0 (the unit against itself) must prove"
    # gate r1 and r2 (latches 2, 3) join gold's (0, 1): the select input at 0 makes them load
    # the same functions
    assert c.rep == [0, 1, 0, 1], c.rep
    return corr.iprove(equiv.binary(c.text(), c.ties(k)), tmp_path / "k.aig", 30.0)


def test_an_equivalent_mutant_proves(tmp_path):
    assert _check(ABSORB, tmp_path, 1) is True


def test_a_mutant_that_changes_a_register_does_not_prove(tmp_path):
    assert _check(INVERT, tmp_path, 1) is False


def test_a_wrong_class_is_split_by_the_counterexample(tmp_path):
    # gold r2 put in the class of gold r1: ABC's counterexample (r1 = x = 0 ... ) splits it
    c = corr.Corr(corr.Aig(INVERT), [6])
    c.rep = [0, 0, 0, 0]
    cex = tmp_path / "c.cex"
    got = corr.iprove(equiv.binary(c.text(), c.ties(0)), tmp_path / "c.aig", 30.0, cex)
    assert got is False and cex.is_file()
    assert c.refine(corr._cex(cex)) > 0
    assert c.rep != [0, 0, 0, 0]


def test_registers_named_alike_start_in_one_class(tmp_path):
    # the map's pairs (gate latch -> gold latch) seed the classes before any structural round
    c = corr.Corr(corr.Aig(ABSORB), [6], {2: 0, 3: 1})
    assert c.rep == [0, 1, 0, 1], c.rep
    got = corr.iprove(equiv.binary(c.text(), c.ties(1)), tmp_path / "k.aig", 30.0)
    assert got is True


def test_a_wrong_pair_is_split_before_any_verdict(tmp_path):
    # gate r1 paired with gold r2 and gate r2 with gold r1: the check of mutant 0 fails, the
    # counterexample splits the pairs, and the verdicts are those of the right classes
    c = corr.classes(corr.Aig(INVERT), [6], tmp_path, equiv.binary, 30.0, {2: 1, 3: 0})
    assert c is not None, "mutant 0 (the unit against itself) must prove"
    assert c.rep[2] != 1 and c.rep[3] != 0, c.rep
    assert corr.iprove(equiv.binary(c.text(), c.ties(1)), tmp_path / "k.aig", 30.0) is False
