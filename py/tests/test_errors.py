"""Bad input to every call raises the right exception with a message naming what is wrong."""

import numpy as np
import pytest

import uvt


def tri_words():
    rec = uvt.gen("bsample", None, 1, 1)[0]
    return rec[:30].reshape(2, 3, 5), (int(rec[30] & 0xFFFF), int(rec[30] >> 16))


def test_hierarchy():
    assert issubclass(uvt.InputError, uvt.UvtError) and issubclass(uvt.ConfigError, uvt.UvtError)
    assert issubclass(uvt.UvtError, ValueError)


def test_triangle_errors():
    v, vp = tri_words()
    with pytest.raises(uvt.ConfigError, match="unknown configuration `nope`"):
        uvt.Triangle(v, vp, "nope")
    with pytest.raises(uvt.ConfigError, match="exact"):
        uvt.Triangle(v, vp, "exact-16-16-16")
    with pytest.raises(ValueError, match=r"shape \(2, 3, 5\)"):
        uvt.Triangle(v.reshape(-1), vp)
    with pytest.raises(TypeError, match="float64"):
        uvt.Triangle(v.astype(np.float64), vp)
    with pytest.raises(TypeError, match="config"):
        uvt.Triangle(v, vp, 3)
    with pytest.raises(TypeError, match="viewport"):
        uvt.Triangle(v, (1.5, 2))
    with pytest.raises(TypeError, match="viewport"):
        uvt.Triangle(v, 7)
    with pytest.raises(uvt.InputError, match="viewport refused: viewport 4000x10"):
        uvt.Triangle(v, (4000, 10))
    off = v.astype(np.int64).copy()
    off[0, 0, 0] += 1  # x one LSB off the 12-bit grid
    with pytest.raises(uvt.InputError, match=r"not on the 12-fraction-bit position grid of bounded-12-12-12-24: t0_v0_x = 0x[0-9a-f]{8} has bits below 2\^-12"):
        uvt.Triangle(off, vp, "bounded-12-12-12-24")
    big = v.astype(np.int64).copy()
    big[0, 1, 3] = 0  # w = 0 at every key frame of one vertex is accepted; a coc out of range is not
    big[0, 1, 4] = 0x7FFFFFFF
    with pytest.raises(uvt.InputError, match="coc|CoC"):
        uvt.Triangle(big, vp)


def test_sample_errors():
    v, vp = tri_words()
    tri = uvt.Triangle(v, vp)
    with pytest.raises(uvt.InputError, match=r"position xs = 999999, ys = 0 outside the viewport"):
        tri.test(999999, 0, 0, 0, 0)
    with pytest.raises(uvt.InputError, match=r"xs = -1: outside"):
        tri.test(-1, 0, 0, 0, 0)
    with pytest.raises(uvt.InputError, match=r"t = 4294967296: outside"):
        tri.test(0, 0, 2**32, 0, 0)
    with pytest.raises(uvt.InputError, match="sample refused by the core"):
        tri.test(0, 0, 0x7FFFFFFF, 0, 0)
    with pytest.raises(TypeError, match="float64"):
        tri.test_batch(np.zeros(3), np.zeros(3, int), np.zeros(3, int), np.zeros(3, int), np.zeros(3, int))
    with pytest.raises(ValueError, match="one length"):
        tri.test_batch([0, 0], [0], [0], [0], [0])
    with pytest.raises(ValueError, match="1 dimension"):
        tri.test_batch([[0]], [[0]], [[0]], [[0]], [[0]])
    with pytest.raises(ValueError, match=r"xs: value -1 outside 0..=4294967295"):
        tri.test_batch([-1], [0], [0], [0], [0])
    with pytest.raises(TypeError):
        tri.test(0.5, 0, 0, 0, 0)
    # On a 12-bit t/u/v grid a t one LSB off it is refused, naming t and its raw bits.
    coarse = uvt.Triangle((v.astype(np.int64) & ~0xF).astype(np.int64), vp, "bounded-12-12-12-24")
    with pytest.raises(uvt.InputError, match=r"not on the 12-fraction-bit grid: t = 0x00000001 has bits below 2\^-12"):
        coarse.test(0, 0, 1, 0, 0)


def test_gen_errors():
    with pytest.raises(uvt.InputError, match="unknown record kind `nope`"):
        uvt.gen("nope", None, 1, 4)
    with pytest.raises(TypeError, match="kind"):
        uvt.gen(4, None, 1, 4)
    with pytest.raises(uvt.ConfigError, match="nope"):
        uvt.gen("bsample", "nope", 1, 4)
    with pytest.raises(uvt.InputError, match="setup_in|self-contained|triangle"):
        uvt.gen("bounds", None, 1, 4)
    with pytest.raises(uvt.InputError, match=r"shard 4/3: need 1 ≤ K ≤ M"):
        uvt.gen("bsample", None, 1, 4, shard=(4, 3))
    with pytest.raises(ValueError, match="K/M"):
        uvt.gen("bsample", None, 1, 4, shard="4")
    with pytest.raises(TypeError, match="seed"):
        uvt.gen("bsample", None, "1", 4)
    with pytest.raises(ValueError, match="seed = -1"):
        uvt.gen("bsample", None, -1, 4)
    with pytest.raises(uvt.InputError, match="1..=64"):
        uvt.gen("resolve", None, 1, 4, spp=65)


def test_run_compare_decode_errors():
    recs = uvt.gen("bsample", None, 1, 4)
    with pytest.raises(ValueError, match="rows of 36 words, a bsample_in record has 37"):
        uvt.run("bsample", recs[:, :36])
    with pytest.raises(ValueError, match="2 dimension"):
        uvt.run("bsample", recs[0])
    with pytest.raises(TypeError, match="float"):
        uvt.run("bsample", recs.astype(np.float32))
    bad = recs.copy()
    bad[2, 34] = 0x7FFFFFFF
    with pytest.raises(uvt.InputError, match=r"record 2: .*\bt\b"):
        uvt.run("bsample", bad)
    with pytest.raises(uvt.InputError, match="setup="):
        uvt.run("bounds", np.zeros((1, 3), np.uint32))
    with pytest.raises(ValueError, match="setup_in records of 32 words"):
        uvt.run("bounds", np.zeros((1, 3), np.uint32), setup=np.zeros(5, np.uint32))
    outs = uvt.run("bsample", recs)
    with pytest.raises(ValueError, match="4 input records, 3 output records"):
        uvt.compare("bsample", recs, outs[:3])
    with pytest.raises(ValueError, match="rows of 13 words, a bsample_out record has 14"):
        uvt.compare("bsample", recs, outs[:, :13])
    with pytest.raises(uvt.InputError, match="in_words: 36 words, a bsample_in record has 37"):
        uvt.decode("bsample", recs[0, :36])
    with pytest.raises(uvt.InputError, match="out_words: 13 words"):
        uvt.decode("bsample", recs[0], outs[0, :13])
    with pytest.raises(uvt.InputError, match="unknown record file"):
        uvt.fields("nope_out")


def test_render_errors(tmp_path):
    with pytest.raises(uvt.ConfigError, match="nope"):
        uvt.render(config="nope")
    with pytest.raises(uvt.ConfigError, match="nope"):
        uvt.render(bounds="nope")
    with pytest.raises(uvt.InputError, match="spp = 65: outside 1..=64"):
        uvt.render(spp=65)
    with pytest.raises(uvt.InputError, match="viewport width = 0"):
        uvt.render(viewport=(0, 10))
    with pytest.raises(uvt.InputError, match="missing.json"):
        uvt.render(str(tmp_path / "missing.json"))
    with pytest.raises(uvt.InputError, match="JSON|json|expected"):
        uvt.render("{not json")
    with pytest.raises(TypeError, match="scene"):
        uvt.render(3)
