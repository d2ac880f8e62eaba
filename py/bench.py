"""Rates of the uvt module (benchmarks, not tests): the batch sample test in samples/s on one
thread, the scalar call's time per call and its overhead over the batch's per-sample time, and the
record calls (gen, run, compare) in records/s. Measure a release wheel (`pip install ./py`):

    python py/bench.py [--n 2000000] [--repeat 5]

Prints one line per figure; each is the best of --repeat runs."""

import argparse
import time

import numpy as np

import uvt


def best(f, repeat):
    """The shortest wall time of `repeat` calls of f."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return min(times)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=2_000_000, help="samples of the batch call")
    ap.add_argument("--scalar", type=int, default=200_000, help="scalar calls")
    ap.add_argument("--records", type=int, default=200_000, help="records of gen/run/compare")
    ap.add_argument("--repeat", type=int, default=5)
    a = ap.parse_args()
    print(f"uvt {uvt.__version__}, configuration {uvt.DEFAULT_CONFIG}")

    # triangles and samples of the seeded bsample stream: every class, positions in the viewport
    recs = uvt.gen("bsample", None, 1, 64)
    rng = np.random.default_rng(1)
    tris, samples = [], []
    for rec in recs:
        vp = (int(rec[30] & 0xFFFF), int(rec[30] >> 16))
        tris.append(uvt.Triangle(rec[:30].reshape(2, 3, 5), vp))
        m = a.n // len(recs)
        other = recs[rng.integers(0, len(recs), m)]
        # as the bsample stream draws them: half near the triangle (within 4 px of the record's
        # own sample position), half anywhere in the viewport
        near = rng.random(m) < 0.5
        jx = int(rec[32]) + rng.integers(-1024, 1025, m)
        jy = int(rec[33]) + rng.integers(-1024, 1025, m)
        xs = np.where(near, jx, rng.integers(0, vp[0] * 256, m, dtype=np.int64))
        ys = np.where(near, jy, rng.integers(0, vp[1] * 256, m, dtype=np.int64))
        xs = np.clip(xs, 0, vp[0] * 256 - 1).astype(np.uint32)
        ys = np.clip(ys, 0, vp[1] * 256 - 1).astype(np.uint32)
        samples.append((xs, ys, *(np.ascontiguousarray(other[:, 34 + i]).view(np.int32) for i in range(3))))
    n = sum(len(s[0]) for s in samples)

    def batch():
        for tri, s in zip(tris, samples):
            tri.test_batch(*s)

    def native():
        for tri, s in zip(tris, samples):
            tri._test_batch(*s)

    covered = sum(int(tri.test_batch(*s).covered.sum()) for tri, s in zip(tris, samples))
    print(f"samples covered: {covered / n:.1%}")
    tb = best(batch, a.repeat)
    tn = best(native, a.repeat)
    print(f"test_batch: {n / tb / 1e6:.2f} M samples/s ({n} samples, {len(tris)} triangles, argument checks included)")
    print(f"test_batch without the argument checks (_test_batch): {n / tn / 1e6:.2f} M samples/s")

    tri = tris[0]
    xs, ys, t, u, v = (x[: a.scalar].tolist() for x in samples[0])
    k = len(xs)

    def scalar():
        test = tri.test
        for i in range(k):
            test(xs[i], ys[i], t[i], u[i], v[i])

    ts = best(scalar, a.repeat)
    per_sample = tn / n
    print(f"test (scalar): {ts / k * 1e9:.0f} ns per call ({k / ts / 1e6:.2f} M calls/s); "
          f"overhead over the batch's {per_sample * 1e9:.0f} ns per sample: {(ts / k - per_sample) * 1e9:.0f} ns")

    r = a.records
    tg = best(lambda: uvt.gen("bsample", None, 1, r), a.repeat)
    ins = uvt.gen("bsample", None, 1, r)
    tr = best(lambda: uvt.run("bsample", ins), a.repeat)
    outs = uvt.run("bsample", ins)
    tc = best(lambda: uvt.compare("bsample", ins, outs), a.repeat)
    print(f"gen bsample: {r / tg / 1e6:.2f} M records/s; run: {r / tr / 1e6:.2f} M records/s; "
          f"compare (run + field check): {r / tc / 1e6:.2f} M records/s ({r} records)")


if __name__ == "__main__":
    main()
