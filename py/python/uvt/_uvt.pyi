"""Type stubs of the native extension ``uvt._uvt`` (Rust, PyO3); the package ``uvt`` wraps it."""

from typing import Any, Dict, List, Optional, Tuple

import numpy as np
import numpy.typing as npt

__version__: str
FORMAT_VERSION: int
TRI_WORDS: int

class UvtError(ValueError):
    """A call the uvt model refuses: the base of InputError and ConfigError."""

class InputError(UvtError):
    """An input the model refuses; the message names the field and its raw bits."""

class ConfigError(UvtError):
    """An unknown configuration or strategy, or one the operation is not made at."""

class Hit:
    """The result of one sample test."""

    @property
    def covered(self) -> bool:
        """True when the sample is covered."""
    @property
    def det_sign(self) -> int:
        """The bounded test's sign of Σ E'·w, the planar test's σ (−1, 0, 1)."""
    @property
    def depth(self) -> int:
        """Depth, raw with 24 fraction bits; 0 when not covered."""
    @property
    def e(self) -> Tuple[int, int, int]:
        """The three edge values, raw."""

class Triangle:
    """A triangle set up once at one configuration (the package's uvt.Triangle subclasses it)."""

    def __new__(cls, vertices: List[int], viewport: Tuple[int, int], config: Optional[str] = None) -> "Triangle": ...
    @property
    def cls(self) -> int:
        """0 static, 1 motion, 2 defocus, 3 both."""
    @property
    def config(self) -> str:
        """The configuration's registry name."""
    @property
    def viewport(self) -> Tuple[int, int]:
        """(width, height)."""
    @property
    def planar(self) -> bool:
        """True when the planar test runs."""
    def test(self, xs: int, ys: int, t: int, u: int, v: int) -> Hit:
        """The sample test of one sample."""
    def _test_batch(
        self,
        xs: npt.NDArray[np.uint32],
        ys: npt.NDArray[np.uint32],
        t: npt.NDArray[np.int32],
        u: npt.NDArray[np.int32],
        v: npt.NDArray[np.int32],
    ) -> Tuple[npt.NDArray[np.uint8], npt.NDArray[np.int8], npt.NDArray[np.int32], npt.NDArray[np.int64]]:
        """The batch sample test on contiguous arrays, without the GIL."""

def configs() -> List[Tuple[str, str, int, int, int, Optional[int], bool, bool]]:
    """The registry's configurations: (name, kind, pos, tuv, bnd, offset shift, planar, sweep)."""

def default_config() -> str:
    """The default configuration's name."""

def strategies() -> List[str]:
    """The bounds strategies."""

def kinds() -> List[Tuple[str, int, Optional[int], int, bool, Optional[List[str]]]]:
    """The record kinds: (name, code, in words, out words, needs setup, architectural fields)."""

def fields(file: str, spp: int = 16) -> List[Tuple[str, int, int, int, bool, int]]:
    """The layout of a record file: (name, word, bit, width, signed, frac) per field."""

def gen(
    kind: str,
    config: Optional[str],
    seed: int,
    count: int,
    shard: Optional[Tuple[int, int]] = None,
    spp: int = 16,
    target: Optional[List[str]] = None,
) -> npt.NDArray[np.uint32]:
    """Input records of a seeded stream (or one shard of it); ``target``: bin names to bias it toward."""

def coverage(kind: str, inputs: npt.NDArray[np.uint32]) -> Dict[str, int]:
    """The model's coverage bins of the records: {bin name: count} over every bin of the kind."""

def coverage_bins(kind: Optional[str] = None) -> List[Tuple[str, str, Optional[str]]]:
    """The model's coverage bins: (name, record kind, why unreachable or None)."""

def shard_range(count: int, k: int, m: int) -> Tuple[int, int]:
    """The record indices (start, end) of shard K of M of a stream of ``count`` records."""

def stream_config(kind: str, config: Optional[str] = None) -> Optional[str]:
    """The configuration the stream of ``kind`` at ``config`` is made at (None: none)."""

def run(kind: str, inputs: npt.NDArray[np.uint32], setup: Optional[npt.NDArray[np.uint32]] = None) -> npt.NDArray[np.uint32]:
    """The model's output records."""

def compare(
    kind: str,
    inputs: npt.NDArray[np.uint32],
    outputs: npt.NDArray[np.uint32],
    architectural: bool = False,
    setup: Optional[npt.NDArray[np.uint32]] = None,
    max_mismatches: int = 100,
) -> Tuple[int, int, List[Tuple[int, str, int, int, str]]]:
    """(pairs, records that differ, first mismatches as (record, field, expected, observed, message))."""

def decode(
    kind: str,
    in_words: npt.NDArray[np.uint32],
    out_words: Optional[npt.NDArray[np.uint32]] = None,
    setup: Optional[npt.NDArray[np.uint32]] = None,
) -> Dict[str, Any]:
    """One record decoded (fields of the input, the model's output, the given output)."""

def render(
    scene: Optional[str] = None,
    config: Optional[str] = None,
    bounds: Optional[str] = None,
    spp: Optional[int] = None,
    viewport: Optional[Tuple[int, int]] = None,
) -> Tuple[npt.NDArray[np.uint8], str]:
    """(the core's image (H, W, 3), report.json's text)."""
