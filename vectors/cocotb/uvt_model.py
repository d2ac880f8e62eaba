"""The uvt model through ctypes: a thin wrapper of libuvt_ffi.so (ffi/include/uvt.h).

The library is loaded by path from the environment variable UVT_FFI_LIB (after
`cargo build --release -p uvt-ffi`: target/release/libuvt_ffi.so). Records are lists of
unsigned 32-bit words, laid out as in vectors/README.md.
"""

import ctypes
import os

KIND_BSAMPLE = 4
KIND_PSAMPLE = 5
BSAMPLE_IN_WORDS = 37
BSAMPLE_OUT_WORDS = 14
PSAMPLE_IN_WORDS = 28
PSAMPLE_OUT_WORDS = 8
PLANAR_CONFIG = "planar-16-16-16-20"
OK = 0
ERR_MISMATCH = -6
DEFAULT_CONFIG = "bounded-16-16-16-20"


class UvtError(RuntimeError):
    """A negative return code of the library, with uvt_last_error()'s message."""


class Model:
    """One loaded libuvt_ffi.so."""

    def __init__(self, path=None):
        path = path or os.environ.get("UVT_FFI_LIB")
        if not path:
            raise UvtError(
                "set UVT_FFI_LIB to the path of libuvt_ffi.so "
                "(cargo build --release -p uvt-ffi: target/release/libuvt_ffi.so)"
            )
        lib = ctypes.CDLL(os.path.abspath(path))
        u32p = ctypes.POINTER(ctypes.c_uint32)
        lib.uvt_version.restype = ctypes.c_uint32
        lib.uvt_version.argtypes = []
        lib.uvt_last_error.restype = ctypes.c_char_p
        lib.uvt_last_error.argtypes = []
        lib.uvt_gen.restype = ctypes.c_int32
        lib.uvt_gen.argtypes = [
            ctypes.c_uint32, ctypes.c_char_p, ctypes.c_uint64, ctypes.c_uint64,
            ctypes.c_uint32, u32p, ctypes.c_size_t,
        ]
        lib.uvt_bsample.restype = ctypes.c_int32
        lib.uvt_bsample.argtypes = [u32p, u32p]
        lib.uvt_psample.restype = ctypes.c_int32
        lib.uvt_psample.argtypes = [u32p, u32p]
        lib.uvt_compare.restype = ctypes.c_int32
        lib.uvt_compare.argtypes = [ctypes.c_uint32, u32p, u32p, ctypes.c_size_t, ctypes.c_uint32]
        self.lib = lib
        self.path = path
        # Buffers reused by every call (one model per thread, as the library's last error).
        self._in = (ctypes.c_uint32 * BSAMPLE_IN_WORDS)()
        self._out = (ctypes.c_uint32 * BSAMPLE_OUT_WORDS)()
        self._obs = (ctypes.c_uint32 * BSAMPLE_OUT_WORDS)()
        self._pin = (ctypes.c_uint32 * PSAMPLE_IN_WORDS)()
        self._pout = (ctypes.c_uint32 * PSAMPLE_OUT_WORDS)()

    def version(self):
        return self.lib.uvt_version()

    def last_error(self):
        return self.lib.uvt_last_error().decode("utf-8", "replace")

    def _check(self, rc, what):
        if rc < 0:
            raise UvtError(f"{what}: code {rc}: {self.last_error()}")
        return rc

    def gen(self, index, seed, kind=KIND_BSAMPLE, config=DEFAULT_CONFIG, words=BSAMPLE_IN_WORDS):
        """Input record `index` of the seeded stimulus stream of `kind` at `config`."""
        buf = (ctypes.c_uint32 * words)()
        cfg = config.encode() if config is not None else None
        n = self._check(self.lib.uvt_gen(kind, cfg, seed, index, 16, buf, words), "uvt_gen")
        return list(buf[:n])

    def bsample(self, words):
        """The model's bsample_out record (14 words) for bsample_in record `words` (37)."""
        if len(words) != BSAMPLE_IN_WORDS:
            raise UvtError(f"bsample: {len(words)} words, expected {BSAMPLE_IN_WORDS}")
        self._in[:] = words
        self._check(self.lib.uvt_bsample(self._in, self._out), "uvt_bsample")
        return list(self._out)

    def psample(self, words):
        """The model's psample_out record (8 words) for psample_in record `words` (28; its setup
        fields the core's, as uvt_gen gives them)."""
        if len(words) != PSAMPLE_IN_WORDS:
            raise UvtError(f"psample: {len(words)} words, expected {PSAMPLE_IN_WORDS}")
        self._pin[:] = words
        self._check(self.lib.uvt_psample(self._pin, self._pout), "uvt_psample")
        return list(self._pout)

    def compare(self, expected, observed, kind=KIND_BSAMPLE, arch_only=False):
        """[] when the records agree, else the differing fields as uvt_last_error() lists them
        (one string per field: name, expected and observed in hex and decoded)."""
        n = len(expected)
        if list(expected) == list(observed):
            return []  # identical records agree in every mode (no call needed)
        if len(observed) != n:
            raise UvtError(f"compare: {n} expected words, {len(observed)} observed")
        exp = (ctypes.c_uint32 * n)(*expected)
        obs = (ctypes.c_uint32 * n)(*observed)
        rc = self.lib.uvt_compare(kind, exp, obs, n, 1 if arch_only else 0)
        if rc == OK:
            return []
        if rc != ERR_MISMATCH:
            self._check(rc, "uvt_compare")
        return [f for f in (s.strip() for s in self.last_error().split(";")) if f]
