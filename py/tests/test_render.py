"""render is `uvt render`: the same image as its fixed.png and the same counters as its report.json."""

import json
import struct
import subprocess
import zlib

import numpy as np
import pytest

import uvt
from conftest import ROOT


def read_png(path):
    """An 8-bit RGB, non-interlaced PNG (what `uvt render` writes) as an (H, W, 3) uint8 array."""
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, w, h = 8, b"", 0, 0
    while pos < len(data):
        n, tag = struct.unpack(">I4s", data[pos : pos + 8])
        body = data[pos + 8 : pos + 8 + n]
        if tag == b"IHDR":
            w, h, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert (depth, color, interlace) == (8, 2, 0)
        elif tag == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    stride = w * 3
    out = np.zeros((h, stride), dtype=np.int32)
    prev = np.zeros(stride, dtype=np.int32)
    for y in range(h):
        f = raw[y * (stride + 1)]
        line = np.frombuffer(raw, dtype=np.uint8, count=stride, offset=y * (stride + 1) + 1).astype(np.int32)
        cur = np.zeros(stride, dtype=np.int32)
        for x in range(stride):
            a = cur[x - 3] if x >= 3 else 0
            b = prev[x]
            c = prev[x - 3] if x >= 3 else 0
            if f == 0:
                p = 0
            elif f == 1:
                p = a
            elif f == 2:
                p = b
            elif f == 3:
                p = (a + b) // 2
            else:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            cur[x] = (line[x] + p) & 0xFF
        out[y] = cur
        prev = cur
    return out.astype(np.uint8).reshape(h, w, 3)


def without_times(v):
    if isinstance(v, dict):
        return {k: without_times(x) for k, x in v.items() if k != "wall_ms"}
    if isinstance(v, list):
        return [without_times(x) for x in v]
    return v


SCENE = ROOT / "host" / "scenes" / "motion_triangles.json"


@pytest.mark.parametrize("scene", [None, SCENE])
def test_render_is_uvt_render(scene, uvt_bin, tmp_path):
    args = ["--viewport", "48x27", "--spp", "4", "--bounds", "hull", "--precision", "bounded-12-12-12-24"]
    cmd = [str(uvt_bin), "render", *([str(scene)] if scene else []), "--out", str(tmp_path), *args]
    subprocess.run(cmd, check=True, capture_output=True)
    image, report = uvt.render(scene, config="bounded-12-12-12-24", bounds="hull", spp=4, viewport=(48, 27))
    assert image.dtype == np.uint8 and image.shape == (27, 48, 3)
    assert np.array_equal(image, read_png(tmp_path / "fixed.png"))
    cli = json.loads((tmp_path / "report.json").read_text())
    assert without_times(report) == without_times(cli)
    assert report["fixed"]["samples_tested"] > 0 and report["fixed"]["samples_covered"] > 0
    assert image.any()


def test_render_of_a_json_text_is_the_file(tmp_path):
    a, ra = uvt.render(SCENE, spp=2, viewport=(32, 18))
    b, rb = uvt.render(SCENE.read_text(), spp=2, viewport=(32, 18))
    assert np.array_equal(a, b)
    assert without_times(ra)["fixed"] == without_times(rb)["fixed"]
