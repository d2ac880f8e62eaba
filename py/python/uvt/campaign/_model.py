"""The model operations a campaign needs — gen, run, compare, decode — from the ``uvt`` module
(its native ``uvt._uvt``, built by maturin). Kinds, configurations and shards are the module's
(read from the Rust registries and ``uvt_records::stream``), never a list of this package's.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional, Sequence, Tuple

import numpy as np

import uvt


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


def stream_kinds() -> Tuple[str, ...]:
    """The kinds whose input records form a self-contained seeded stream (``uvt vectors gen``):
    those that need no ``setup_in`` record (``uvt.KINDS``)."""
    return tuple(k for k, i in uvt.KINDS.items() if not i.needs_setup)


def shard_range(count: int, k: int, m: int) -> range:
    """The record indices of shard ``k`` of ``m`` (1-based) of a stream of ``count`` records
    (``uvt.shard_range``: exactly what ``uvt vectors gen --shard K/M`` gives)."""
    try:
        a, b = uvt.shard_range(count, k, m)
    except uvt.UvtError as e:
        raise CampaignError(str(e)) from e
    return range(a, b)


def config_for(kind: str, config: Optional[str]) -> Optional[str]:
    """The configuration a stream of ``kind`` at ``config`` (None: the kind's default) is made
    at, None for kinds without one (``uvt.stream_config``); a refusal is a CampaignError."""
    try:
        return uvt.stream_config(kind, config)
    except uvt.UvtError as e:
        raise CampaignError(f"kind {kind!r}, configuration {config!r}: {e}") from e


def _plain(v):
    """A decoded value as JSON can hold it."""
    if isinstance(v, np.integer):
        return int(v)
    if isinstance(v, np.floating):
        return float(v)
    if isinstance(v, dict):
        return {str(k): _plain(x) for k, x in v.items()}
    if isinstance(v, (list, tuple, np.ndarray)):
        return [_plain(x) for x in v]
    return v


class Model:
    """The ``uvt`` module's batch calls (numpy in, numpy out)."""

    name = "uvt module"

    def __init__(self):
        self.configs = uvt.CONFIGS
        self.kinds = tuple(uvt.KINDS)

    def gen(self, kind, config, seed, count, shard, target=()):
        return uvt.gen(kind, config, seed, count, shard=shard, target=list(target) or None)

    def coverage(self, kind, inputs):
        return uvt.coverage(kind, inputs)

    def coverage_bins(self, kind=None):
        return uvt.coverage_bins(kind)

    def run(self, kind, inputs):
        return uvt.run(kind, inputs)

    def compare(self, kind, inputs, outputs, architectural=False):
        r = uvt.compare(kind, inputs, outputs, architectural=architectural)
        return int(r.pairs), [
            Mismatch(int(m.record), str(m.field), m.expected, m.observed) for m in r.mismatches
        ]

    def decode(self, kind, in_words, out_words=None):
        d = uvt.decode(kind, np.asarray(in_words, dtype=np.uint32),
                       None if out_words is None else np.asarray(out_words, dtype=np.uint32))
        return {str(k): _plain(v) for k, v in dict(d).items()}


_MODEL = Model()


def load() -> Model:
    """The model operations (the ``uvt`` module's)."""
    return _MODEL


def words(model: Model, kind: str) -> Sequence[int]:
    """(input words, output words) of a record of ``kind`` (``uvt.KINDS``)."""
    i = uvt.KINDS[kind]
    return i.in_words, i.out_words
