"""Coverage of a shard: the bins the model's own tests take deciding its records.

The bins are the core's (``uvt_core::coverage``, read through ``uvt.coverage_bins`` and counted
by ``uvt.coverage``: the same counting as ``uvt vectors gen|ver --coverage`` and the C
library's ``uvt_coverage``); this package keeps no definition of its own. Counters are keyed by
bin name (``bsample.edge.zero``, …) plus ``<kind>.records``, the records counted; kinds
without bins (setup, select, resolve) have the records counter only.
"""

from __future__ import annotations

from typing import Dict, List, Optional, Tuple

import numpy as np


def bins(model, kind: str) -> List[Tuple[str, Optional[str]]]:
    """The bins of ``kind``: (name, why no input reaches it or None), the model's order."""
    return [(name, why) for name, _, why in model.coverage_bins(kind)]


def classify(model, kind: str, inputs: np.ndarray) -> Dict[str, int]:
    """Counters of the input records ``inputs`` of ``kind``: ``<kind>.records`` and, for kinds
    with bins, every bin of the kind (zeros included)."""
    out = {f"{kind}.records": int(len(inputs))}
    if len(inputs) and bins(model, kind):
        out.update({str(k): int(v) for k, v in model.coverage(kind, inputs).items()})
    return out


def add(total: Dict[str, int], part: Dict[str, int]) -> Dict[str, int]:
    """``total`` plus ``part``, counter by counter (in place; returns ``total``)."""
    for k, v in part.items():
        total[k] = total.get(k, 0) + v
    return total


def table(model, kind: str, cov: Dict[str, int]) -> List[str]:
    """The coverage table's lines: per reachable bin its count, the bins not hit, and the
    unreachable bins apart with their reasons."""
    rows = bins(model, kind)
    if not rows:
        return [f"{cov.get(f'{kind}.records', 0)} {kind} records (no coverage bins)"]
    w = max(len(n) for n, _ in rows)
    out = [f"| {'bin'.ljust(w)} | {'hits':>10} |", f"|{'-' * (w + 2)}|{'-' * 12}|"]
    unhit = []
    for name, why in rows:
        if why is None:
            out.append(f"| {name.ljust(w)} | {cov.get(name, 0):>10} |")
            if not cov.get(name, 0):
                unhit.append(name)
    if unhit:
        out.append("not hit: " + ", ".join(unhit))
    for name, why in rows:
        if why is not None:
            out.append(f"unreachable {name}: {why}")
    return out
