"""Which unit builds the mutation flow mutates, and the bench and vector sets that judge them.

A build is named as in ``vectors/rtl/pnr.sh``'s unit table (``bsample``, ``bsample-pipe2``, …),
the one definition of each build's parameters: this module reads the table, never a copy. The
mutated design is the build's behavioural form (``MAP = 0``: ``MAP = 1`` only swaps each hard
product for the vendor primitive's instance, whose model is not uvt's logic), flattened, so a
mutant may sit anywhere in the unit, its multipliers included.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Dict, List, Tuple

from .errors import MutationError

#: The builds of the report, in its order: every reference unit at its default build (the
#: placed-and-routed one) and at ``PIPE = 2``.
BUILDS = ("bsample", "bsample-pipe2", "psample", "psample-pipe2", "bounds", "bounds-pipe2",
          "mul31", "mul31-pipe2")

#: The committed vector sets, in the order a mutant meets them (the first that kills it is named).
SETS = ("unit", "frame_a", "frame_b", "unit_exact")


@dataclass(frozen=True)
class Bench:
    """How one unit is judged: its testbench (``vectors/rtl``), the record stem of its vector
    files (``None``: the bench makes its own operands), the macros that select the
    architectural mode (every port a team's unit must have, no parameter passed), and the
    bench parameters taken from the build's."""

    tb: str
    stem: object
    defines: Tuple[str, ...]
    tb_params: Tuple[str, ...]
    #: the architectural outputs the bench checks in that mode (the report names them)
    checked: str
    #: the output that marks a result valid (``None``: every clock's output counts) and the
    #: architectural data outputs it qualifies: the equivalence proofs compare these alone
    valid: object = None
    outputs: Tuple[str, ...] = ()
    #: the record domain the equivalence proofs assume: per input, a Verilog expression over the
    #: raw inputs (and the other inputs' ``d_NAME``) that is the input itself inside the domain
    #: and a value inside it elsewhere; the unit sees ``d_NAME`` (docs/mutation.md)
    domain: Tuple[Tuple[str, str], ...] = ()


#: The planar unit's record domain (vectors/README.md, `psample_in` fields): the depth
#: exponent f of a reachable triangle in [−62, 68] (`core/src/setup/planar.rs`,
#: tests/tests/model/planar_exponent.rs), the viewport 1..2048 a side, the sample inside it
#: (xs < 256·W, ys < 256·H), σ = ±1, and no edge normal 0 (a degenerate triangle, culled).
PSAMPLE_DOMAIN = (
    ("f", "($signed(f) > 8'sd68) ? 8'sd68 : ($signed(f) < -8'sd62) ? -8'sd62 : f"),
    ("vp_w", "(vp_w == 12'd0) ? 12'd1 : (vp_w > 12'd2048) ? 12'd2048 : vp_w"),
    ("vp_h", "(vp_h == 12'd0) ? 12'd1 : (vp_h > 12'd2048) ? 12'd2048 : vp_h"),
    ("xs", "(xs >= {d_vp_w, 8'd0}) ? {d_vp_w, 8'd0} - 20'd1 : xs"),
    ("ys", "(ys >= {d_vp_h, 8'd0}) ? {d_vp_h, 8'd0} - 20'd1 : ys"),
    ("sigma", "(sigma == 2'b01 || sigma == 2'b11) ? sigma : 2'b01"),
    ("n", "{" + ", ".join(f"(n[{96 * k} +: 96] == 96'd0) ? 96'd1 : n[{96 * k} +: 96]"
                          for k in (2, 1, 0)) + "}"),
)

BENCHES: Dict[str, Bench] = {
    "uvt_bsample": Bench("tb_bsample", "bsample", ("UVT_ARCH_ONLY",),
                         ("POS", "TUV", "OFF", "MOTION", "DEFOCUS"), "out_covered, depth",
                         "out_valid", ("out_covered", "depth")),
    "uvt_psample": Bench("tb_psample", "psample", ("UVT_ARCH_ONLY",), (), "covered, depth",
                         "out_valid", ("covered", "depth"), PSAMPLE_DOMAIN),
    "uvt_bounds": Bench("tb_bounds", "bounds", ("UVT_DUT=uvt_bounds",), ("BND", "TUV"),
                        "nonempty, u, v, t intervals", "out_valid",
                        ("nonempty", "u_lo", "u_hi", "v_lo", "v_hi", "t_lo", "t_hi")),
    "uvt_mul": Bench("tb_mul", None, ("UVT_ARCH_ONLY",), ("AW", "BW", "REG", "LAT"), "p",
                     None, ("p",)),
}


@dataclass(frozen=True)
class Build:
    """One build of ``pnr.sh``'s table: its name, top module, sources (file names in
    ``vectors/rtl``) and parameters, as mutated (``MAP`` forced to 0)."""

    name: str
    top: str
    sources: Tuple[str, ...]
    params: Tuple[Tuple[str, int], ...]
    #: a team's own unit: the reference unit whose bench judges it (``None``: ``top`` is one)
    like: object = None

    @property
    def bench(self) -> Bench:
        """The bench that judges this build's unit (a team's unit: the bench of the reference
        unit it stands for, instantiating ``top`` in the architectural mode)."""
        if self.like is None:
            return BENCHES[self.top]
        ref = BENCHES[self.like]
        defines = tuple(d for d in ref.defines if not d.startswith("UVT_DUT="))
        return Bench(ref.tb, ref.stem, (*defines, f"UVT_DUT={self.top}"), ref.tb_params,
                     ref.checked, ref.valid, ref.outputs, ref.domain)

    def source_paths(self) -> List[str]:
        """The sources as Yosys reads them: ``vectors/rtl/…`` for a reference unit (relative, so
        a mutation list is the same in every checkout), as given for a team's unit."""
        return list(self.sources) if self.like else [f"vectors/rtl/{s}" for s in self.sources]

    def param(self, key: str, default: int) -> int:
        """The build's parameter ``key`` (``default`` when the table leaves it at the unit's)."""
        return dict(self.params).get(key, default)


def rtl_dir(repo: Path) -> Path:
    """``vectors/rtl`` of the checkout ``repo``."""
    return repo / "vectors" / "rtl"


def build(repo: Path, name: str) -> Build:
    """The build ``name`` of ``vectors/rtl/pnr.sh``'s unit table (the line
    ``    NAME) echo "top|sources|P=V …|…"``), with ``MAP = 0`` and without ``uvt_mult18.v``."""
    script = rtl_dir(repo) / "pnr.sh"
    head = f'    {name}) echo "'
    for line in script.read_text().splitlines():
        if line.startswith(head):
            fields = line[len(head):].split("|")
            if len(fields) < 3:
                break
            top = fields[0]
            if top not in BENCHES:
                raise MutationError(f"build {name}: unit {top} has no bench in the mutation flow")
            sources = tuple(s for s in fields[1].split() if s != "uvt_mult18.v")
            params: List[Tuple[str, int]] = []
            for p in fields[2].split():
                k, v = p.split("=", 1)
                params.append((k, 0 if k == "MAP" else int(v)))
            return Build(name, top, sources, tuple(params))
    raise MutationError(f"{script}: no build {name!r} (the builds: {', '.join(BUILDS)})")


def own(spec: str) -> Build:
    """A team's unit from ``--own LIKE:TOP:FILE[,FILE…]``: judged by the bench of the reference
    unit ``LIKE`` (``bsample``, ``psample``, ``bounds``, ``mul``), top module ``TOP``, read from
    the files (absolute or relative to the checkout)."""
    parts = spec.split(":", 2)
    if len(parts) != 3 or not all(parts):
        raise MutationError(f"--own {spec!r}: LIKE:TOP:FILE[,FILE…]")
    like, top, files = parts
    ref = f"uvt_{like}"
    if ref not in BENCHES:
        raise MutationError(f"--own {spec!r}: LIKE is one of "
                            f"{', '.join(b[4:] for b in BENCHES)}")
    srcs = tuple(str(Path(f).resolve()) for f in files.split(","))
    for s in srcs:
        if not Path(s).is_file():
            raise MutationError(f"--own: {s}: no such file")
    return Build(f"own-{top}", top, srcs, (), ref)
