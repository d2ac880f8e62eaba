"""Batch calls release the GIL: another Python thread keeps running during a long test_batch."""

import threading
import time

import numpy as np

import uvt


def test_test_batch_releases_the_gil():
    rec = uvt.gen("bsample", None, 1, 1)[0]
    vp = (int(rec[30] & 0xFFFF), int(rec[30] >> 16))
    tri = uvt.Triangle(rec[:30].reshape(2, 3, 5), vp)
    rng = np.random.default_rng(1)
    n = 2_000_000
    xs = rng.integers(0, vp[0] * 256, n).astype(np.uint32)
    ys = rng.integers(0, vp[1] * 256, n).astype(np.uint32)
    z = np.zeros(n, np.int32)
    span = []

    def batch():
        t0 = time.perf_counter()
        tri._test_batch(xs, ys, z, z, z)
        span.append((t0, time.perf_counter()))

    ticks = []
    th = threading.Thread(target=batch)
    th.start()
    while th.is_alive():
        ticks.append(time.perf_counter())
    th.join()
    (t0, t1), = span
    # the main thread kept running during the call: no gap in its ticks as long as half the call
    # (with the GIL held through the call, one gap would be the whole call)
    inside = [t0] + [t for t in ticks if t0 < t < t1] + [t1]
    gap = max(b - a for a, b in zip(inside, inside[1:]))
    assert gap < 0.5 * (t1 - t0), f"the main thread stopped for {gap:.3f} s of a {t1 - t0:.3f} s call"
