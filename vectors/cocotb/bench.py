"""What the cocotb tests share: environment integers, reading an output, printing words."""

import os


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
    return " ".join(f"{w:08x}" for w in ws)
