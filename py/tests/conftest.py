"""Shared fixtures of the uvt module's tests: the repository root, the `uvt` binary and the C
library the module is compared with (built by the test command's cargo steps before pytest;
UVT_BIN and UVT_FFI_LIB override the paths)."""

import os
import pathlib

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
UNIT = ROOT / "vectors" / "unit"


def target_file(env: str, name: str) -> pathlib.Path:
    """A file of the Cargo target folder (CARGO_TARGET_DIR or target/) or the path in `env`."""
    if os.environ.get(env):
        return pathlib.Path(os.environ[env])
    target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    if not target.is_absolute():
        target = ROOT / target
    return target / "debug" / name


def read_hex(path: pathlib.Path) -> np.ndarray:
    """A committed *.hex file as an (n, words) uint32 array."""
    rows = [[int(w, 16) for w in line.split()] for line in path.read_text().splitlines() if line.strip()]
    if not rows:
        return np.zeros((0, 0), dtype=np.uint32)
    return np.array(rows, dtype=np.uint32)


@pytest.fixture(scope="session")
def uvt_bin() -> pathlib.Path:
    """The `uvt` binary (`cargo build -p uvt-host` makes it)."""
    p = target_file("UVT_BIN", "uvt")
    assert p.is_file(), f"{p}: no uvt binary (cargo build -p uvt-host, or set UVT_BIN)"
    return p


@pytest.fixture(scope="session")
def ffi_lib() -> pathlib.Path:
    """The C library libuvt_ffi.so (`cargo build -p uvt-ffi` makes it)."""
    p = target_file("UVT_FFI_LIB", "libuvt_ffi.so")
    assert p.is_file(), f"{p}: no C library (cargo build -p uvt-ffi, or set UVT_FFI_LIB)"
    return p
