"""The typed sample test: the scalar call, the batch call and the C library's uvt_tri_sample agree
on random triangles and samples, and agree with the bsample records' outputs."""

import ctypes

import numpy as np
import pytest

import uvt


class CHit(ctypes.Structure):
    _fields_ = [("covered", ctypes.c_int32), ("det_sign", ctypes.c_int32), ("depth", ctypes.c_int32), ("e", ctypes.c_int64 * 3)]


@pytest.fixture(scope="module")
def clib(ffi_lib):
    lib = ctypes.CDLL(str(ffi_lib))
    lib.uvt_tri_new.argtypes = [ctypes.POINTER(ctypes.c_int32), ctypes.c_uint16, ctypes.c_uint16, ctypes.c_char_p, ctypes.POINTER(ctypes.c_void_p)]
    lib.uvt_tri_sample.argtypes = [ctypes.c_void_p, ctypes.c_uint32, ctypes.c_uint32, ctypes.c_int32, ctypes.c_int32, ctypes.c_int32, ctypes.POINTER(CHit)]
    lib.uvt_tri_class.argtypes = [ctypes.c_void_p]
    lib.uvt_tri_free.argtypes = [ctypes.c_void_p]
    lib.uvt_last_error.restype = ctypes.c_char_p
    return lib


BOUNDED = [c for c in uvt.CONFIGS if uvt.CONFIG_INFO[c].kind == "bounded"]


def triangles(config, seed, n):
    """n bsample records of the seeded stream at config: triangle words, viewport, sample."""
    return uvt.gen("bsample", config, seed, n)


def case(rec):
    verts = rec[:30].reshape(2, 3, 5)
    vp = (int(rec[30] & 0xFFFF), int(rec[30] >> 16))
    return verts, vp


@pytest.mark.parametrize("config", BOUNDED + ["planar-16-16-16-20"])
def test_scalar_batch_and_c_api_agree(config, clib):
    rng = np.random.default_rng(52)
    recs = triangles(config, 7, 40)
    checked = 0
    for rec in recs:
        verts, vp = case(rec)
        tri = uvt.Triangle(verts, vp, config)
        handle = ctypes.c_void_p()
        words = (ctypes.c_int32 * 30)(*[int(np.int32(np.uint32(w).view(np.int32))) for w in rec[:30]])
        assert clib.uvt_tri_new(words, vp[0], vp[1], config.encode(), ctypes.byref(handle)) == 0, clib.uvt_last_error()
        assert clib.uvt_tri_class(handle) == tri.cls
        # samples: t, u, v of other records (on the grid), positions random in the viewport
        n = 64
        other = recs[rng.integers(0, len(recs), n)]
        xs = rng.integers(0, vp[0] * 256, n, dtype=np.uint64).astype(np.uint32)
        ys = rng.integers(0, vp[1] * 256, n, dtype=np.uint64).astype(np.uint32)
        t, u, v = (other[:, 34 + i].view(np.int32) for i in range(3))
        batch = tri.test_batch(xs, ys, t, u, v)
        for i in range(n):
            h = tri.test(int(xs[i]), int(ys[i]), int(t[i]), int(u[i]), int(v[i]))
            c = CHit()
            assert clib.uvt_tri_sample(handle, int(xs[i]), int(ys[i]), int(t[i]), int(u[i]), int(v[i]), ctypes.byref(c)) == 0
            assert (h.covered, h.det_sign, h.depth, h.e) == (bool(c.covered), c.det_sign, c.depth, tuple(c.e))
            assert (bool(batch.covered[i]), int(batch.det_sign[i]), int(batch.depth[i])) == (h.covered, h.det_sign, h.depth)
            assert tuple(int(x) for x in batch.e[i]) == h.e
            checked += 1
        clib.uvt_tri_free(handle)
    assert checked == 40 * 64
    assert batch.covered.dtype == np.uint8 and batch.e.shape == (64, 3) and batch.e.dtype == np.int64


def test_typed_agrees_with_the_bsample_records():
    recs = triangles(None, 3, 300)
    outs = uvt.run("bsample", recs)
    covered = 0
    for rec, out in zip(recs, outs):
        verts, vp = case(rec)
        tri = uvt.Triangle(verts, vp)
        assert tri.cls == int(rec[31] & 3)
        h = tri.test(*(int(x) for x in rec[32:34]), *(int(np.uint32(x).view(np.int32)) for x in rec[34:37]))
        f = uvt.decode("bsample", rec, out)["out"]
        assert (h.covered, h.det_sign, h.depth, h.e) == (bool(f["covered"]), f["det_sign"], f["depth"], (f["e0"], f["e1"], f["e2"]))
        covered += h.covered
    assert 0 < covered < 300


def test_batch_refusal_names_the_sample():
    rec = triangles(None, 3, 1)[0]
    verts, vp = case(rec)
    tri = uvt.Triangle(verts, vp)
    xs = np.array([0, vp[0] * 256 + 256], dtype=np.uint32)
    with pytest.raises(uvt.InputError, match=r"sample 1: position xs = \d+, ys = 0 outside the viewport"):
        tri.test_batch(xs, [0, 0], [0, 0], [0, 0], [0, 0])
