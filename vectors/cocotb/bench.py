"""What the cocotb tests share: environment integers, reading an output, printing words, the
bounded unit's rare-path test, and naming the fields in which observed records differ."""

import os

import numpy as np

import uvt


def env_int(name, default):
    raw = os.environ.get(name, "")
    return int(raw, 0) if raw.strip() else default


def word(handle):
    """An output as an unsigned int, or None when a bit is X or Z. (int(str, 2) rejects those
    and is ~10x faster than LogicArray.is_resolvable + to_unsigned in cocotb 2.1.)"""
    try:
        return int(str(handle.value), 2)
    except ValueError:
        return None


def hexwords(ws):
    return " ".join(f"{int(w):08x}" for w in ws)


def lerp(f0, f1, t):
    """Step 1's lerp of the bounded sample test (core/src/sample/bounded/datapath.rs: nearest,
    ties up)."""
    return f0 + ((t * (f1 - f0) + (1 << 15)) >> 16)


def s32(x):
    return x - (1 << 32) if x & 0x80000000 else x


def rare_path(rec):
    """bsample_in record `rec`: some vertex has w <= 0 at the sample's t (the orientation takes
    sign(sum E'w))."""
    t = s32(rec[34])
    ws = [lerp(s32(rec[5 * k + 3]), s32(rec[15 + 5 * k + 3]), t) for k in range(3)]
    return min(ws) <= 0


def _show(v):
    return f"{v:#010x}" if isinstance(v, (int, np.integer)) else str(v)


def _field(m, name, idx):
    """A mismatch's attribute, whether the module gives an object or a tuple."""
    return getattr(m, name) if hasattr(m, name) else m[idx]


def mismatch_report(kind, inputs, expected, observed, architectural=False):
    """{record: [field lines]} for the records whose `observed` outputs differ from `expected`
    (every field, or the architectural ones: covered, depth).

    The fields are named by uvt.compare (observed against the model run on `inputs`). Where the
    bench's `expected` is not the model's own output (UVT_CORRUPT altered it), the words that
    differ from `observed` are reported by name as well (covered: word 0 bit 0, depth: word 1 in
    both sample-test kinds), so a corrupted expectation fails the check too."""
    inputs = np.asarray(inputs, dtype=np.uint32)
    expected = np.asarray(expected, dtype=np.uint32)
    observed = np.asarray(observed, dtype=np.uint32)
    out = {}
    if architectural:
        differ = ((expected[:, 0] ^ observed[:, 0]) & 1) | (expected[:, 1] ^ observed[:, 1])
        rows = np.nonzero(differ)[0]
    else:
        rows = np.nonzero((expected != observed).any(axis=1))[0]
    if len(rows) == 0:
        return out
    res = uvt.compare(kind, inputs[rows], observed[rows], architectural=architectural)
    for m in res.mismatches:
        r = int(rows[int(_field(m, "record", 0))])
        f, e, o = _field(m, "field", 1), _field(m, "expected", 2), _field(m, "observed", 3)
        out.setdefault(r, []).append(f"field {f}: expected {_show(e)}, observed {_show(o)}")
    model = uvt.run(kind, inputs[rows])
    for j, r in enumerate(rows.tolist()):
        if (model[j] == expected[r]).all():
            continue
        exp, obs = expected[r].tolist(), observed[r].tolist()
        named = [("covered", exp[0] & 1, obs[0] & 1), ("depth", exp[1], obs[1])]
        if not architectural:
            named.append(("word 0 bits 31..1", exp[0] >> 1, obs[0] >> 1))
            named += [(f"word {k}", exp[k], obs[k]) for k in range(2, len(exp))]
        for name, e, o in named:
            if e != o:
                out.setdefault(r, []).append(
                    f"field {name} (expected record altered, not the model's): expected "
                    f"{e:#010x}, observed {o:#010x}"
                )
    return out
