"""Coverage of a shard: what its records exercised, classified from the records themselves.

Per kind, counters keyed ``"<class>/<what>"`` (class ``static``, ``motion``, ``defocus``,
``both`` of the triangle; ``all`` for kinds without one):

- ``records``: records of that class;
- ``covered``: the model's ``covered`` bit set (sample tests);
- ``ties``: an expected edge value of exactly 0 (a fill-rule tie: the bounded test's rounded
  E'_k, the planar test's E_k);
- ``ties_covered``: a tie that is covered (decided by the fill rule's key);
- ``w<=0``: a vertex with w ≤ 0 at either key frame (the rare orientation path);
- ``corner``: the sample at a viewport corner (xs or ys at 0 or at the last sub-pixel).

The record words are read as vectors/README.md lays them out (``uvt vectors layout``).
"""

from __future__ import annotations

from typing import Dict

import numpy as np

CLASSES = ("static", "motion", "defocus", "both")  # class index: bit 0 motion, bit 1 defocus


def _e_zero(out: np.ndarray, first: int) -> np.ndarray:
    """Whether any of the three 64-bit edge values at words ``first``.. is 0."""
    z = np.zeros(len(out), dtype=bool)
    for k in range(3):
        z |= (out[:, first + 2 * k] | out[:, first + 2 * k + 1]) == 0
    return z


def _corner(xs, ys, vp):
    w = (vp & 0xFFFF).astype(np.int64) * 256 - 1
    h = (vp >> 16).astype(np.int64) * 256 - 1
    x, y = xs.astype(np.int64), ys.astype(np.int64)
    return ((x == 0) | (x == w)) & ((y == 0) | (y == h))


def classify(kind: str, inputs: np.ndarray, expected: np.ndarray) -> Dict[str, int]:
    """Counters of the records ``inputs`` of ``kind`` with the model's outputs ``expected``
    (the keys above; only non-zero counters)."""
    n = len(inputs)
    if n == 0:
        return {}
    if kind == "bsample":
        cls = inputs[:, 31] & 3
        w = inputs[:, [3, 8, 13, 18, 23, 28]].view(np.int32)
        flags = {
            "covered": (expected[:, 0] & 1) == 1,
            "ties": _e_zero(expected, 8),
            "w<=0": (w <= 0).any(axis=1),
            "corner": _corner(inputs[:, 32], inputs[:, 33], inputs[:, 30]),
        }
    elif kind == "psample":
        cls = np.zeros(n, dtype=np.uint32)
        w = inputs[:, [3, 7, 11]].view(np.int32)
        flags = {
            "covered": (expected[:, 0] & 1) == 1,
            "ties": _e_zero(expected, 2),
            "w<=0": (w <= 0).any(axis=1),
            "corner": _corner(inputs[:, 26], inputs[:, 27], inputs[:, 12]),
        }
    elif kind == "setup":
        cls = (expected[:, 0] >> 3) & 3  # setup_out word 0: visible, cull (2), class (2)
        w = inputs[:, [3, 8, 13, 18, 23, 28]].view(np.int32)
        flags = {"visible": (expected[:, 0] & 1) == 1, "w<=0": (w <= 0).any(axis=1)}
    else:
        return {"all/records": int(n)}
    if "covered" in flags:
        flags["ties_covered"] = flags["ties"] & flags["covered"]
    out: Dict[str, int] = {}
    for c, name in enumerate(CLASSES):
        sel = cls == c
        if not sel.any():
            continue
        out[f"{name}/records"] = int(sel.sum())
        for what, f in flags.items():
            v = int((f & sel).sum())
            if v:
                out[f"{name}/{what}"] = v
    return out


def add(total: Dict[str, int], part: Dict[str, int]) -> Dict[str, int]:
    """``total`` plus ``part``, counter by counter (in place; returns ``total``)."""
    for k, v in part.items():
        total[k] = total.get(k, 0) + v
    return total
