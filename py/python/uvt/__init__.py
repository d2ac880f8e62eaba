"""uvt: the bit-accurate fixed-point stochastic rasterizer model in Python.

The native extension ``uvt._uvt`` (Rust, PyO3) runs the model; this package checks argument
types and shapes, converts arrays and re-exports it. Every list below is read from the Rust
registries at import, never kept here:

- ``CONFIGS`` (configuration names, registry order), ``DEFAULT_CONFIG``, ``CONFIG_INFO``;
- ``STRATEGIES`` (bounds strategies);
- ``KINDS`` (record kinds with their word counts).

The typed sample test: ``Triangle(vertices, viewport, config)`` with ``.test`` (one sample) and
``.test_batch`` (numpy arrays, without the GIL). Records: ``gen`` (seeded, shardable streams),
``run``, ``compare``, ``decode``. ``render`` runs ``uvt render``'s renderer. The model's
refusals raise ``InputError`` or ``ConfigError`` (both ``UvtError``, a ``ValueError``), naming
the field and its raw bits; a wrong type is a ``TypeError``, a wrong shape a ``ValueError``.
"""

from __future__ import annotations

import json
import os
from typing import Any, Dict, List, NamedTuple, Optional, Sequence, Tuple, Union

import numpy as np

from . import _uvt
from ._uvt import ConfigError, Hit, InputError, UvtError

__all__ = [
    "__version__",
    "FORMAT_VERSION",
    "CONFIGS",
    "CONFIG_INFO",
    "DEFAULT_CONFIG",
    "STRATEGIES",
    "KINDS",
    "ConfigInfo",
    "KindInfo",
    "Hit",
    "BatchHits",
    "Triangle",
    "Mismatch",
    "Comparison",
    "UvtError",
    "InputError",
    "ConfigError",
    "gen",
    "shard_range",
    "stream_config",
    "run",
    "coverage",
    "coverage_bins",
    "compare",
    "decode",
    "fields",
    "render",
]

#: The package's version (the Rust workspace's).
__version__: str = _uvt.__version__
#: The record format version of the vector files (the manifests' ``format_version``).
FORMAT_VERSION: int = _uvt.FORMAT_VERSION


class ConfigInfo(NamedTuple):
    """One configuration of the registry (``uvt configs``)."""

    name: str
    """registry name, e.g. ``bounded-16-16-16-20``"""
    kind: str
    """``exact``, ``bounded`` or ``planar``"""
    pos_frac: int
    """fraction bits of vertex positions"""
    tuv_frac: int
    """fraction bits of t, u, v"""
    bnd_frac: int
    """fraction bits of the bounds"""
    offset_shift: Optional[int]
    """the bounded test's offset shift (None: exact)"""
    planar: bool
    """static triangles take the planar test"""
    sweep: bool
    """in the precision sweep"""


class KindInfo(NamedTuple):
    """One record kind (a stage's ``*_in`` / ``*_out`` pair)."""

    name: str
    """the stage name, e.g. ``bsample``"""
    code: int
    """the C library's ``UVT_KIND_*`` code"""
    in_words: Optional[int]
    """words of an input record (None for resolve: one per sample, 1..=64)"""
    out_words: int
    """words of an output record"""
    needs_setup: bool
    """records name a triangle: ``run``/``compare`` need its ``setup_in`` record (``setup=``)"""
    architectural: Optional[Tuple[str, ...]]
    """the output fields a unit must produce (None: all)"""


#: Every configuration, registry name → its parameters, in registry order.
CONFIG_INFO: Dict[str, ConfigInfo] = {c[0]: ConfigInfo(*c) for c in _uvt.configs()}
#: The configuration names, in registry order.
CONFIGS: Tuple[str, ...] = tuple(CONFIG_INFO)
#: The default configuration's name.
DEFAULT_CONFIG: str = _uvt.default_config()
#: The bounds strategies, in registry order.
STRATEGIES: Tuple[str, ...] = tuple(_uvt.strategies())
#: Every record kind, name → its word counts, in code order.
KINDS: Dict[str, KindInfo] = {
    k[0]: KindInfo(k[0], k[1], k[2], k[3], k[4], None if k[5] is None else tuple(k[5]))
    for k in _uvt.kinds()
}


def _kind(kind: Any) -> KindInfo:
    if not isinstance(kind, str):
        raise TypeError(f"kind: a record kind name (one of {', '.join(KINDS)}), not {type(kind).__name__}")
    if kind not in KINDS:
        raise InputError(f"unknown record kind `{kind}` (one of {', '.join(KINDS)})")
    return KINDS[kind]


def _int_array(what: str, a: Any, ndim: int, lo: int, hi: int, dtype: Any) -> np.ndarray:
    """``a`` as a C-contiguous array of ``dtype`` with ``ndim`` dimensions, every value in lo..=hi."""
    arr = np.asarray(a)
    if arr.dtype.kind not in "iu" and not (arr.dtype.kind == "b" and lo <= 0 and hi >= 1):
        if arr.size == 0 and arr.dtype.kind == "f":
            arr = arr.astype(np.int64)
        else:
            raise TypeError(f"{what}: an integer array is needed, not dtype {arr.dtype}")
    if arr.ndim != ndim:
        raise ValueError(f"{what}: {ndim} dimension(s) needed, shape is {arr.shape}")
    if arr.size:
        mn, mx = int(arr.min()), int(arr.max())
        if mn < lo or mx > hi:
            bad = mn if mn < lo else mx
            raise ValueError(f"{what}: value {bad} outside {lo}..={hi}")
    return np.ascontiguousarray(arr, dtype=dtype)


_U32 = (0, 2**32 - 1)
_I32 = (-(2**31), 2**31 - 1)


def _words(what: str, a: Any, ndim: int) -> np.ndarray:
    """Record words as uint32 (negative int32 values taken as their bit patterns)."""
    arr = np.asarray(a)
    if arr.dtype.kind == "i" and arr.size and int(arr.min()) < 0:
        if int(arr.min()) < _I32[0]:
            raise ValueError(f"{what}: value {int(arr.min())} is not a 32-bit word")
        arr = arr.astype(np.int64) & 0xFFFFFFFF
    return _int_array(what, arr, ndim, _U32[0], _U32[1], np.uint32)


def _records(what: str, a: Any, kind: KindInfo) -> np.ndarray:
    arr = _words(what, a, 2)
    w = kind.in_words
    if w is not None and arr.shape[1] != w and arr.shape[0] > 0:
        raise ValueError(f"{what}: rows of {arr.shape[1]} words, a {kind.name}_in record has {w}")
    return arr


def _setup(setup: Any, kind: KindInfo) -> Optional[np.ndarray]:
    if setup is None:
        if kind.needs_setup:
            raise InputError(
                f"a {kind.name}_in record names its triangle in setup_in: give setup= (its setup_in record, or one per record)"
            )
        return None
    arr = _words("setup", setup, np.asarray(setup).ndim)
    if arr.ndim == 1:
        arr = arr.reshape(1, -1)
    if arr.ndim != 2 or arr.shape[1] != KINDS["setup"].in_words:
        raise ValueError(f"setup: setup_in records of {KINDS['setup'].in_words} words needed, shape is {arr.shape}")
    return arr


class BatchHits(NamedTuple):
    """The sample tests of ``Triangle.test_batch``, one entry per sample."""

    covered: np.ndarray
    """uint8, 1 when covered"""
    det_sign: np.ndarray
    """int8: the bounded test's sign of Σ E'·w, the planar test's σ"""
    depth: np.ndarray
    """int32, raw with 24 fraction bits (0 when not covered)"""
    e: np.ndarray
    """(n, 3) int64: the edge values"""


class Triangle(_uvt.Triangle):
    """A triangle set up once at one configuration: its sample test.

    ``vertices``: raw 16.16 words of shape (2, 3, 5) — key frames t0, t1 × 3 vertices × x, y, z,
    w, coc (the C library's ``uvt_tri_new`` words, a ``bsample_in`` record's words 0..29);
    negative values or their uint32 bit patterns. ``viewport``: (width, height) in pixels.
    ``config``: a name of ``CONFIGS`` (None: ``DEFAULT_CONFIG``); an exact configuration raises
    ``ConfigError`` (its 192-bit edge values: use the records). The model's refusal of the
    triangle (off the configuration's grid, the planar setup culls it, …) raises ``InputError``.

    ``test(xs, ys, t, u, v)``: one sample → ``Hit``; ``test_batch``: numpy arrays → ``BatchHits``.
    ``cls``: 0 static, 1 motion, 2 defocus, 3 both.
    """

    def __new__(cls, vertices: Any, viewport: Tuple[int, int], config: Optional[str] = None) -> "Triangle":
        arr = np.asarray(vertices)
        if arr.dtype.kind not in "iu":
            raise TypeError(f"vertices: raw 16.16 integer words are needed, not dtype {arr.dtype}")
        if arr.shape != (2, 3, 5):
            raise ValueError(f"vertices: shape (2, 3, 5) needed (t0/t1 × 3 vertices × x, y, z, w, coc), not {arr.shape}")
        if config is not None and not isinstance(config, str):
            raise TypeError(f"config: a configuration name, not {type(config).__name__}")
        try:
            vp = tuple(viewport)
        except TypeError:
            raise TypeError(f"viewport: (width, height) needed, not {viewport!r}") from None
        if len(vp) != 2 or not all(isinstance(x, (int, np.integer)) and not isinstance(x, bool) for x in vp):
            raise TypeError(f"viewport: (width, height) ints needed, not {viewport!r}")
        return super().__new__(cls, [int(x) for x in arr.reshape(-1)], (int(vp[0]), int(vp[1])), config)

    def test_batch(self, xs: Any, ys: Any, t: Any, u: Any, v: Any) -> BatchHits:
        """The sample test of every sample i at (xs[i], ys[i]) in 1/256 px and t[i], u[i], v[i]
        (raw, 16 fraction bits): integer arrays of one length (xs, ys in uint32's range; t, u, v
        in int32's). Runs without the GIL. InputError names the first sample the model refuses."""
        a = [
            _int_array("xs", xs, 1, *_U32, np.uint32),
            _int_array("ys", ys, 1, *_U32, np.uint32),
            _int_array("t", t, 1, *_I32, np.int32),
            _int_array("u", u, 1, *_I32, np.int32),
            _int_array("v", v, 1, *_I32, np.int32),
        ]
        if len({len(x) for x in a}) != 1:
            raise ValueError(f"xs, ys, t, u, v: arrays of one length needed, lengths are {[len(x) for x in a]}")
        return BatchHits(*self._test_batch(*a))


def gen(
    kind: str,
    config: Optional[str],
    seed: int,
    count: int,
    shard: Union[None, str, Tuple[int, int]] = None,
    *,
    spp: int = 16,
    target: Optional[Sequence[str]] = None,
) -> np.ndarray:
    """Input records of the seeded stream of ``kind`` at ``config`` (None: the kind's default)
    with ``seed``: ``count`` records, or with ``shard`` = "K/M" or (K, M) its part K of M
    (indices ⌊count·(K−1)/M⌋ .. ⌊count·K/M⌋). An (n, in_words) uint32 array; the same records as
    ``uvt vectors gen --shard K/M`` and ``uvt_gen``, whatever the sharding. ``spp``: samples per
    resolve record. ``target``: coverage bin names (:func:`coverage_bins`) to bias the stream
    toward, as ``uvt vectors gen --target-bins`` (still seeded and shard-invariant). Bounds and
    sample records have no self-contained stream (InputError)."""
    k = _kind(kind)
    if config is not None and not isinstance(config, str):
        raise TypeError(f"config: a configuration name or None, not {type(config).__name__}")
    for what, x in (("seed", seed), ("count", count), ("spp", spp)):
        if not isinstance(x, (int, np.integer)) or isinstance(x, bool):
            raise TypeError(f"{what}: an int, not {type(x).__name__}")
    if not 0 <= int(seed) < 2**64:
        raise ValueError(f"seed = {seed}: outside 0..2^64")
    if not 0 <= int(count) < 2**64:
        raise ValueError(f"count = {count}: outside 0..2^64")
    sh: Optional[Tuple[int, int]] = None
    if shard is not None:
        if isinstance(shard, str):
            parts = shard.split("/")
            if len(parts) != 2 or not all(p.strip().isdigit() for p in parts):
                raise ValueError(f"shard `{shard}`: expected K/M, e.g. 3/8")
            sh = (int(parts[0]), int(parts[1]))
        elif isinstance(shard, tuple) and len(shard) == 2 and all(isinstance(x, (int, np.integer)) for x in shard):
            sh = (int(shard[0]), int(shard[1]))
        else:
            raise TypeError(f"shard: \"K/M\" or (K, M), not {shard!r}")
        if sh[0] < 0 or sh[1] < 0:
            raise InputError(f"shard {sh[0]}/{sh[1]}: need 1 ≤ K ≤ M")
    tg = None if target is None else [str(t) for t in target]
    return _uvt.gen(k.name, config, int(seed), int(count), sh, int(spp), tg)


def coverage(kind: str, inputs: Any) -> Dict[str, int]:
    """The model's coverage of ``inputs`` ((n, in_words) uint32 input records of ``kind``,
    bsample or psample): {bin name: count} over every bin of the kind, zeros included — the
    bins the core's own test reports while deciding the records (``uvt_core::coverage``), the
    same counting as ``uvt vectors gen|ver --coverage`` and ``uvt_coverage``."""
    k = _kind(kind)
    return dict(_uvt.coverage(k.name, _records("inputs", inputs, k)))


def coverage_bins(kind: Optional[str] = None) -> List[Tuple[str, str, Optional[str]]]:
    """The model's coverage bins, (name, record kind, why no input reaches it or None), all or
    those of ``kind``."""
    return list(_uvt.coverage_bins(None if kind is None else _kind(kind).name))


def shard_range(count: int, k: int, m: int) -> Tuple[int, int]:
    """The record indices ``(start, end)`` of shard ``k`` of ``m`` (1 ≤ k ≤ m) of a stream of
    ``count`` records: the records ``gen(…, shard=(k, m))`` returns (InputError otherwise)."""
    return _uvt.shard_range(int(count), int(k), int(m))


def stream_config(kind: str, config: Optional[str] = None) -> Optional[str]:
    """The configuration the seeded stream of ``kind`` at ``config`` (None: the kind's default)
    is made at — None for kinds without one — or the stream's refusal (ConfigError for a
    configuration the kind is not made at, InputError for a kind without a stream)."""
    return _uvt.stream_config(_kind(kind).name, config)


def run(kind: str, inputs: Any, *, setup: Any = None) -> np.ndarray:
    """The model's output records for ``inputs`` ((n, in_words) uint32 input records of
    ``kind``): an (n, out_words) uint32 array, bit for bit the committed ``*_out.hex`` lines.
    Bounds and exact sample-test records need ``setup``: their triangle's setup_in record (one,
    or one per record). Runs without the GIL; InputError names the record and field refused."""
    k = _kind(kind)
    return _uvt.run(k.name, _records("inputs", inputs, k), _setup(setup, k))


class Mismatch(NamedTuple):
    """One field in which an observed output record differs from the model's."""

    record: int
    """index of the record in the call's arrays"""
    field: str
    """the field's name (the layout's, as in manifest.json)"""
    expected: int
    """the model's raw field value (signed per the layout)"""
    observed: int
    """the observed raw field value"""
    message: str
    """the C library's text: "field NAME: expected HEX = DECODED, observed HEX = DECODED\""""


class Comparison(NamedTuple):
    """What ``compare`` found."""

    pairs: int
    """records compared"""
    mismatched: int
    """records with at least one differing field"""
    mismatches: List[Mismatch]
    """the first differing fields (at most ``max_mismatches``), by record then layout order"""

    @property
    def ok(self) -> bool:
        """True when every record agrees."""
        return self.mismatched == 0


def compare(
    kind: str,
    inputs: Any,
    outputs: Any,
    architectural: bool = False,
    *,
    setup: Any = None,
    max_mismatches: int = 100,
) -> Comparison:
    """Run the model on ``inputs`` and compare its output records with ``outputs`` (observed,
    (n, out_words) uint32), every field or with ``architectural`` only the architectural ones
    (``KINDS[kind].architectural``; as ``uvt_compare``'s ``arch_only``). Runs without the GIL."""
    k = _kind(kind)
    ins = _records("inputs", inputs, k)
    outs = _words("outputs", outputs, 2)
    if outs.shape[0] != ins.shape[0]:
        raise ValueError(f"{ins.shape[0]} input records, {outs.shape[0]} output records")
    if outs.shape[0] and outs.shape[1] != k.out_words:
        raise ValueError(f"outputs: rows of {outs.shape[1]} words, a {k.name}_out record has {k.out_words}")
    if not isinstance(max_mismatches, int) or max_mismatches < 0:
        raise ValueError(f"max_mismatches = {max_mismatches!r}: a count ≥ 0 is needed")
    pairs, bad, ms = _uvt.compare(k.name, ins, outs, bool(architectural), _setup(setup, k), max_mismatches)
    return Comparison(pairs, bad, [Mismatch(*m) for m in ms])


def decode(kind: str, in_words: Any, out_words: Any = None, *, setup: Any = None) -> Dict[str, Any]:
    """One record decoded: ``{"kind", "in": {field: raw int}, "model": {field: raw int} or None,
    "model_error": the model's refusal or None}``, and with ``out_words``: ``"out"`` (its fields)
    and ``"diff"`` (the fields it differs from the model's in, as ``uvt vectors decode``)."""
    k = _kind(kind)
    i = _words("in_words", in_words, 1)
    o = None if out_words is None else _words("out_words", out_words, 1)
    s = None
    if setup is not None:
        s = _words("setup", setup, 1)
    return _uvt.decode(k.name, i, o, s)


def fields(file: str, spp: int = 16) -> List[Tuple[str, int, int, int, bool, int]]:
    """The layout of record file ``file`` (e.g. ``bsample_out``): (name, word, bit, width,
    signed, frac) per field, as manifest.json lists them."""
    if not isinstance(file, str):
        raise TypeError(f"file: a record file name such as bsample_out, not {type(file).__name__}")
    return _uvt.fields(file, spp)


def render(
    scene: Union[None, str, "os.PathLike[str]"] = None,
    config: Optional[str] = None,
    bounds: Optional[str] = None,
    spp: Optional[int] = None,
    viewport: Optional[Tuple[int, int]] = None,
) -> Tuple[np.ndarray, Dict[str, Any]]:
    """Render ``scene`` (a scene file's path, its JSON text, or None: the built-in default scene)
    as ``uvt render`` does: the core at ``config`` with bounds strategy ``bounds`` (default
    laine2011), ``spp`` and ``viewport`` (width, height) overriding the scene's. Returns the
    core's image, an (H, W, 3) uint8 array (``uvt render``'s fixed.png), and report.json's
    counters as a dict (samples tested and covered, tiles, …). Runs without the GIL."""
    if isinstance(scene, os.PathLike):
        scene = os.fspath(scene)
    if scene is not None and not isinstance(scene, str):
        raise TypeError(f"scene: a path, a JSON text or None, not {type(scene).__name__}")
    for what, x in (("config", config), ("bounds", bounds)):
        if x is not None and not isinstance(x, str):
            raise TypeError(f"{what}: a name or None, not {type(x).__name__}")
    if spp is not None and (not isinstance(spp, (int, np.integer)) or isinstance(spp, bool)):
        raise TypeError(f"spp: an int or None, not {type(spp).__name__}")
    vp = None
    if viewport is not None:
        vp = tuple(viewport)
        if len(vp) != 2 or not all(isinstance(x, (int, np.integer)) for x in vp):
            raise TypeError(f"viewport: (width, height) ints, not {viewport!r}")
    image, report = _uvt.render(scene, config, bounds, None if spp is None else int(spp), vp)
    return image, json.loads(report)
