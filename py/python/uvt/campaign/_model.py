"""The model operations a campaign needs: gen, run, compare, decode.

The campaign calls the ``uvt`` module's batch functions (``uvt.gen``, ``uvt.run``,
``uvt.compare``, ``uvt.decode``: the native ``uvt._uvt`` built by maturin). Where that module is
not importable — a checkout without the wheel installed — the same operations run through the C
library ``libuvt_ffi.so`` with ``ctypes`` (``UVT_FFI_LIB`` names it; ``cargo build --release -p
uvt-ffi`` makes ``target/release/libuvt_ffi.so``), record by record and so slower; the results
are the same records. :func:`load` picks one, and :class:`Mismatch` is what both report.
"""

from __future__ import annotations

import ctypes
import os
from dataclasses import dataclass
from typing import Any, Optional, Sequence

import numpy as np

#: The kinds whose input records form a self-contained seeded stream (``uvt vectors gen``):
#: the only kinds a campaign can run (bounds and exact sample-test records name a triangle of a
#: ``setup_in`` file).
STREAM_KINDS = ("bsample", "psample", "setup", "select", "resolve")

_KIND_CODES = {"setup": 0, "bounds": 1, "select": 2, "sample": 3, "bsample": 4, "psample": 5,
               "resolve": 6}
_KINDS_WITHOUT_CONFIG = ("select", "resolve")
PLANAR_CONFIG = "planar-16-16-16-20"
DEFAULT_CONFIG = "bounded-16-16-16-20"


class CampaignError(ValueError):
    """A campaign that cannot run as asked: bad arguments, a missing simulator, a simulator that
    failed or lost records. The message names what and why."""


@dataclass(frozen=True)
class Mismatch:
    """One differing field of one output record: ``record`` is the index within the batch
    compared, ``expected`` and ``observed`` the field's values as the model reports them."""

    record: int
    field: str
    expected: Any
    observed: Any


def shard_range(count: int, k: int, m: int) -> range:
    """The record indices of shard ``k`` of ``m`` (1-based, contiguous) of a stream of ``count``
    records: exactly ``uvt vectors gen --count COUNT --shard K/M`` (records/src/stream.rs)."""
    return range(count * (k - 1) // m, count * k // m)


def config_for(kind: str, config: Optional[str]) -> Optional[str]:
    """The configuration a stream of ``kind`` is made at: ``None`` for kinds without one,
    the planar configuration for ``psample``, ``config`` (default: the default configuration)
    otherwise."""
    if kind in _KINDS_WITHOUT_CONFIG:
        return None
    if kind == "psample":
        return PLANAR_CONFIG
    return config or DEFAULT_CONFIG


class NativeModel:
    """The ``uvt`` module's batch calls (numpy in, numpy out)."""

    name = "uvt module"

    def __init__(self, mod):
        self.mod = mod
        self.configs = tuple(getattr(mod, "CONFIGS", ()))
        self.kinds = tuple(getattr(mod, "KINDS", STREAM_KINDS))

    def gen(self, kind, config, seed, count, shard):
        return np.ascontiguousarray(self.mod.gen(kind, config, seed, count, shard=shard),
                                    dtype=np.uint32)

    def run(self, kind, inputs):
        return np.ascontiguousarray(self.mod.run(kind, inputs), dtype=np.uint32)

    def compare(self, kind, inputs, outputs, architectural=False):
        r = self.mod.compare(kind, inputs, outputs, architectural=architectural)
        out = []
        for m in r.mismatches:
            if isinstance(m, (tuple, list)):
                out.append(Mismatch(int(m[0]), str(m[1]), m[2], m[3]))
            else:
                out.append(Mismatch(int(m.record), str(m.field), m.expected, m.observed))
        return int(r.pairs), out

    def decode(self, kind, in_words, out_words=None):
        d = self.mod.decode(kind, np.asarray(in_words, dtype=np.uint32),
                            None if out_words is None else np.asarray(out_words, dtype=np.uint32))
        return {str(k): _plain(v) for k, v in dict(d).items()}


def _plain(v):
    """A decoded value as JSON can hold it."""
    if isinstance(v, (np.integer,)):
        return int(v)
    if isinstance(v, (np.floating,)):
        return float(v)
    if isinstance(v, dict):
        return {str(k): _plain(x) for k, x in v.items()}
    if isinstance(v, (list, tuple, np.ndarray)):
        return [_plain(x) for x in v]
    return v


class FfiModel:
    """The C library through ``ctypes``: the same operations, one record per call."""

    name = "libuvt_ffi (ctypes)"

    def __init__(self, path: str):
        if not os.path.isfile(path):
            raise CampaignError(f"UVT_FFI_LIB={path}: no such file (cargo build --release -p "
                                "uvt-ffi makes target/release/libuvt_ffi.so)")
        lib = ctypes.CDLL(os.path.abspath(path))
        u32p = ctypes.POINTER(ctypes.c_uint32)
        lib.uvt_last_error.restype = ctypes.c_char_p
        lib.uvt_gen.restype = ctypes.c_int32
        vp = ctypes.c_void_p  # raw addresses into numpy arrays: cheaper than a pointer object
        lib.uvt_gen.argtypes = [ctypes.c_uint32, ctypes.c_char_p, ctypes.c_uint64,
                                ctypes.c_uint64, ctypes.c_uint32, vp, ctypes.c_size_t]
        lib.uvt_run.restype = ctypes.c_int32
        lib.uvt_run.argtypes = [ctypes.c_uint32, vp, ctypes.c_size_t, vp, ctypes.c_size_t,
                                vp, ctypes.c_size_t]
        lib.uvt_compare.restype = ctypes.c_int32
        lib.uvt_compare.argtypes = [ctypes.c_uint32, u32p, u32p, ctypes.c_size_t,
                                    ctypes.c_uint32]
        lib.uvt_words.restype = ctypes.c_int32
        lib.uvt_words.argtypes = [ctypes.c_uint32, ctypes.c_uint32, u32p, u32p]
        self.lib = lib
        self.configs = ()
        self.kinds = tuple(_KIND_CODES)

    def _err(self, what):
        return CampaignError(f"{what}: {self.lib.uvt_last_error().decode('utf-8', 'replace')}")

    def _code(self, kind):
        if kind not in _KIND_CODES:
            raise CampaignError(f"unknown kind {kind!r}: one of {', '.join(_KIND_CODES)}")
        return _KIND_CODES[kind]

    def words(self, kind):
        wi, wo = ctypes.c_uint32(), ctypes.c_uint32()
        if self.lib.uvt_words(self._code(kind), 16, ctypes.byref(wi), ctypes.byref(wo)) != 0:
            raise self._err(f"uvt_words({kind})")
        return wi.value, wo.value

    def gen(self, kind, config, seed, count, shard):
        code = self._code(kind)
        wi, _ = self.words(kind)
        k, m = shard
        r = shard_range(count, k, m)
        out = np.zeros((len(r), wi), dtype=np.uint32)
        cfg = None if config is None else config.encode()
        base, step, gen = out.ctypes.data, 4 * wi, self.lib.uvt_gen
        for j, i in enumerate(r):
            if gen(code, cfg, seed, i, 16, base + j * step, wi) < 0:
                raise self._err(f"uvt_gen({kind}, {config}, seed {seed}, record {i})")
        return out

    def run(self, kind, inputs):
        code = self._code(kind)
        wi, wo = self.words(kind)
        inputs = np.ascontiguousarray(inputs, dtype=np.uint32)
        out = np.zeros((len(inputs), wo), dtype=np.uint32)
        bi, bo, run = inputs.ctypes.data, out.ctypes.data, self.lib.uvt_run
        for j in range(len(inputs)):
            if run(code, bi + 4 * wi * j, wi, None, 0, bo + 4 * wo * j, wo) < 0:
                raise self._err(f"uvt_run({kind}, record {j})")
        return out

    def compare(self, kind, inputs, outputs, architectural=False):
        code = self._code(kind)
        exp = self.run(kind, inputs)
        obs = np.ascontiguousarray(outputs, dtype=np.uint32)
        u32p = ctypes.POINTER(ctypes.c_uint32)
        out = []
        for j in np.nonzero((exp != obs).any(axis=1))[0]:
            rc = self.lib.uvt_compare(code, exp[j].ctypes.data_as(u32p),
                                      obs[j].ctypes.data_as(u32p), exp.shape[1],
                                      1 if architectural else 0)
            if rc == 0:
                continue
            msg = self.lib.uvt_last_error().decode("utf-8", "replace")
            # "field NAME: expected X = …, observed Y = …", one line per field
            for line in msg.splitlines() or [msg]:
                line = line.strip()
                name = line.split(":")[0].replace("field ", "").strip() or "?"
                exp_s = line.split("expected ", 1)[1].split(", observed")[0] if "expected " in line else ""
                obs_s = line.split("observed ", 1)[1] if "observed " in line else ""
                out.append(Mismatch(int(j), name, exp_s, obs_s))
        return len(obs), out

    def decode(self, kind, in_words, out_words=None):
        return {"in": [f"{int(w):08x}" for w in in_words],
                **({} if out_words is None else {"out": [f"{int(w):08x}" for w in out_words]})}


_LOADED = None


def load():
    """The model operations of this process: the ``uvt`` module's, or the C library's through
    ``ctypes`` when the module's batch calls are missing and ``UVT_FFI_LIB`` is set. A
    :class:`CampaignError` says how to get either."""
    global _LOADED
    if _LOADED is not None:
        return _LOADED
    try:
        import uvt  # noqa: PLC0415

        if all(hasattr(uvt, f) for f in ("gen", "run", "compare", "decode")):
            _LOADED = NativeModel(uvt)
            return _LOADED
    except ImportError:
        pass
    path = os.environ.get("UVT_FFI_LIB")
    if path:
        _LOADED = FfiModel(path)
        return _LOADED
    raise CampaignError("the uvt module's batch calls (uvt.gen, uvt.run, uvt.compare, "
                        "uvt.decode) are missing: install the wheel (pip install ./py), or set "
                        "UVT_FFI_LIB to libuvt_ffi.so (cargo build --release -p uvt-ffi)")


def words(model, kind: str) -> Sequence[int]:
    """(input words, output words) of a record of ``kind``, from one generated record."""
    if isinstance(model, FfiModel):
        return model.words(kind)
    rec = model.gen(kind, config_for(kind, None), 0, 1, (1, 1))
    return rec.shape[1], model.run(kind, rec).shape[1]
