"""One shard of a campaign: :func:`run_shard`, the function each Dask task runs."""

from __future__ import annotations

import os
import socket
import subprocess
import tempfile
import time
import numpy as np

from ._model import CampaignError, load, shard_range
from .coverage import classify
from .spec import MODEL, Campaign


_HEX = np.frombuffer(b"0123456789abcdef", dtype=np.uint8)


def to_text(records: np.ndarray) -> str:
    """Records as the vector files write them: per line, words of 8 lower-case hex digits
    separated by one space (vectorised: no Python loop per word)."""
    n = len(records)
    if n == 0:
        return ""
    w = records.shape[1]
    buf = np.empty((n, w, 9), dtype=np.uint8)
    r = np.ascontiguousarray(records, dtype=np.uint32)
    for d in range(8):
        buf[:, :, d] = _HEX[(r >> np.uint32(28 - 4 * d)) & np.uint32(15)]
    buf[:, :, 8] = ord(" ")
    buf[:, -1, 8] = ord("\n")
    return buf.tobytes().decode("ascii")


def _fixed_width(text: str, n: int, words: int):
    """The words of ``n`` lines of exactly ``words`` hex words each (as :func:`to_text` writes
    them), or ``None`` when the text is not in that exact shape."""
    b = np.frombuffer(text.encode("ascii", "replace"), dtype=np.uint8)
    if b.size != n * words * 9:
        return None
    b = b.reshape(n, words, 9)
    if not ((b[:, :-1, 8] == 32).all() and (b[:, -1, 8] == 10).all()):
        return None
    d = b[:, :, :8].astype(np.int16)
    v = np.where((d >= 48) & (d <= 57), d - 48, np.where((d >= 97) & (d <= 102), d - 87, -1))
    if (v < 0).any():
        return None
    out = np.zeros((n, words), dtype=np.uint32)
    for k in range(8):
        out = (out << np.uint32(4)) | v[:, :, k].astype(np.uint32)
    return out


def parse_output(text: str, inputs: np.ndarray, wo: int, where: str) -> np.ndarray:
    """The output records of a simulator's text: per line ``wi + wo`` words (the input record
    echoed, then the output) or ``wo`` words. One line per input record, in order; a lost,
    added or reordered record is a :class:`CampaignError`."""
    wi = inputs.shape[1]
    for width in (wi + wo, wo):
        a = _fixed_width(text, len(inputs), width)
        if a is not None:
            return _check_echo(a, inputs, wo, where)
    lines = [l for l in text.splitlines() if l.strip()]
    if len(lines) != len(inputs):
        raise CampaignError(f"{where}: {len(lines)} output lines for {len(inputs)} input records "
                            "(the simulator lost or added records)")
    try:
        words = [[int(h, 16) for h in l.split()] for l in lines]
    except ValueError as e:
        raise CampaignError(f"{where}: a line that is not hex words: {e}") from e
    widths = {len(w) for w in words}
    if widths in ({wi + wo}, {wo}):
        return _check_echo(np.array(words, dtype=np.uint32), inputs, wo, where)
    bad = next(i for i, w in enumerate(words) if len(w) not in (wo, wi + wo))
    raise CampaignError(f"{where}: output line {bad + 1} has {len(words[bad])} words; a line "
                        f"holds {wi} input + {wo} output words or {wo} output words")


def _check_echo(a: np.ndarray, inputs: np.ndarray, wo: int, where: str) -> np.ndarray:
    """The output words of lines ``a``; where the lines echo the input records, each must be
    the record fed on that line."""
    wi = inputs.shape[1]
    if a.shape[1] == wo:
        return a
    moved = np.nonzero((a[:, :wi] != inputs).any(axis=1))[0]
    if len(moved):
        raise CampaignError(f"{where}: output line {moved[0] + 1} carries another input "
                            "record than was fed on that line (records reordered or changed)")
    return np.ascontiguousarray(a[:, wi:])


def simulate(spec: Campaign, k: int, inputs: np.ndarray, expected: np.ndarray) -> np.ndarray:
    """The simulator's outputs of shard ``k``'s ``inputs`` (``expected``: the model's, which
    the ``model`` simulator returns, with its corruption)."""
    if spec.simulator == MODEL:
        obs = expected.copy()
        if spec.corrupt is not None:
            r = shard_range(spec.count, k, spec.shards)
            if spec.corrupt in r:
                obs[spec.corrupt - r.start, spec.corrupt_word] ^= np.uint32(1 << spec.corrupt_bit)
        return obs
    where = f"shard {k}/{spec.shards}: simulator {spec.simulator!r}"
    with tempfile.TemporaryDirectory(prefix="uvt-shard-") as d:
        fin, fout = os.path.join(d, "in.hex"), os.path.join(d, "out.hex")
        text = to_text(inputs)
        subst = {"in": fin, "out": fout, "seed": str(spec.seed), "shard": str(k),
                 "shards": str(spec.shards)}
        args = [a.format(**subst) for a in spec.command()]
        use_in = any("{in}" in a for a in spec.command())
        use_out = any("{out}" in a for a in spec.command())
        if use_in:
            with open(fin, "w") as f:
                f.write(text)
        try:
            p = subprocess.run(args, input=None if use_in else text, capture_output=True,
                               text=True, timeout=spec.timeout,
                               stdin=subprocess.DEVNULL if use_in else None)
        except FileNotFoundError as e:
            raise CampaignError(f"{where}: {e}") from e
        except subprocess.TimeoutExpired as e:
            raise CampaignError(f"{where}: no result after {spec.timeout} s") from e
        if p.returncode != 0:
            raise CampaignError(f"{where} exited with status {p.returncode}: "
                                f"{p.stderr.strip()[-2000:]}")
        if use_out:
            with open(fout) as f:
                out = f.read()
        else:
            out = p.stdout
    wo = expected.shape[1]
    return parse_output(out, inputs, wo, where)


def gen_command(spec: Campaign, k: int) -> str:
    """The ``uvt vectors gen`` command of shard ``k``'s input records."""
    cfg = spec.stream_config
    c = f"uvt vectors gen {spec.kind}"
    if cfg is not None and spec.kind != "psample":
        c += f" --config {cfg}"
    if spec.target:
        c += " --target-bins " + ",".join(spec.target)
    return c + f" --seed {spec.seed} --count {spec.count} --shard {k}/{spec.shards}"


def reproducer(spec: Campaign, k: int, j: int, in_words, out_words) -> dict:
    """Commands that give shard ``k``'s failing record ``j`` (index within the shard) again:
    the shard through the simulator into ``uvt vectors ver``, the record alone, and its decode
    against the model."""
    gen = gen_command(spec, k)
    n = len(shard_range(spec.count, k, spec.shards))
    arch = " --arch-only" if spec.architectural else ""
    if spec.simulator == MODEL:
        shard = (f"python -m uvt.campaign run --kind {spec.kind}"
                 + (f" --config {spec.stream_config}" if spec.config else "")
                 + f" --seed {spec.seed} --shards {spec.shards} --per-shard {spec.per_shard}"
                 + (f" --corrupt {spec.corrupt}" if spec.corrupt is not None else "")
                 + f" --only-shard {k}")
    else:
        shard = f"{gen} | {spec.simulator} | uvt vectors ver {spec.kind}{arch} --count {n}"
    words = " ".join(f"{int(w):08x}" for w in list(in_words) + list(out_words))
    return {
        "shard": shard,
        "record": f"{gen} | sed -n {j + 1}p",
        "decode": f"uvt vectors decode {spec.kind} {words}",
    }


def run_shard(spec: Campaign, k: int) -> dict:
    """Run shard ``k`` (1-based) of ``spec``: generate its records, run the simulator, compare
    with the model. Returns a dict (JSON-able): ``shard``, ``records``, ``first_record`` (the
    global index of its first record), ``mismatched`` (records that differ), ``coverage``
    (:mod:`.coverage`), ``failure`` (the first differing record: global and in-shard index,
    the differing fields, the record decoded, its words and reproducer commands; ``None`` when
    none differs), ``error`` (a simulator that failed or lost records; ``None`` otherwise),
    ``seconds`` and ``worker``."""
    t0 = time.perf_counter()
    model = load()
    r = shard_range(spec.count, k, spec.shards)
    res = {"shard": k, "records": len(r), "first_record": r.start, "mismatched": 0,
           "coverage": {}, "failure": None, "error": None}
    inputs = model.gen(spec.kind, spec.stream_config, spec.seed, spec.count, (k, spec.shards),
                       spec.target)
    expected = model.run(spec.kind, inputs)
    res["coverage"] = classify(model, spec.kind, inputs)
    try:
        observed = simulate(spec, k, inputs, expected)
    except CampaignError as e:
        res["error"] = str(e)
    else:
        rows = np.nonzero((expected != observed).any(axis=1))[0]
        if len(rows):
            _, mism = model.compare(spec.kind, inputs[rows], observed[rows], spec.architectural)
            bad = sorted({int(rows[m.record]) for m in mism})
            res["mismatched"] = len(bad)
            if bad:
                j = bad[0]
                fields = [{"field": m.field, "expected": _s(m.expected), "observed": _s(m.observed)}
                          for m in mism if int(rows[m.record]) == j]
                res["failure"] = {
                    "record": r.start + j,
                    "in_shard": j,
                    "fields": fields,
                    "input": [f"{int(w):08x}" for w in inputs[j]],
                    "expected": [f"{int(w):08x}" for w in expected[j]],
                    "observed": [f"{int(w):08x}" for w in observed[j]],
                    "decoded": {"input": model.decode(spec.kind, inputs[j]),
                                "observed": _decode_out(model, spec.kind, inputs[j], observed[j])},
                    "reproduce": reproducer(spec, k, j, inputs[j], observed[j]),
                }
    res["seconds"] = time.perf_counter() - t0
    res["worker"] = f"{socket.gethostname()}:{os.getpid()}"
    return res


def _s(v):
    return v if isinstance(v, (int, float, str)) or v is None else str(v)


def _decode_out(model, kind, in_words, out_words):
    try:
        return model.decode(kind, in_words, out_words)
    except Exception as e:  # noqa: BLE001 - the decode is a help, not the verdict
        return {"error": str(e)}


def only_shard(spec: Campaign, k: int) -> dict:
    """:func:`run_shard` in this process, after checking ``k`` (the CLI's ``--only-shard``)."""
    if not 1 <= k <= spec.shards:
        raise CampaignError(f"shard {k}: need 1 ≤ K ≤ {spec.shards}")
    return run_shard(spec, k)


__all__ = ["run_shard", "simulate", "parse_output", "to_text", "reproducer", "gen_command",
           "only_shard"]
