"""The module's lists are the Rust registries': the same as the `uvt` command and the C header."""

import re
import subprocess

import uvt
from conftest import ROOT


def cli(uvt_bin, *args):
    return subprocess.run([str(uvt_bin), *args], check=True, capture_output=True, text=True).stdout


def test_configs_match_the_cli(uvt_bin):
    rows = [line.split() for line in cli(uvt_bin, "configs").splitlines() if line.strip()]
    assert list(uvt.CONFIGS) == [r[0] for r in rows]
    assert [uvt.CONFIG_INFO[r[0]].kind for r in rows] == [r[1] for r in rows]
    assert [uvt.CONFIG_INFO[r[0]].sweep for r in rows] == [r[2] == "sweep" for r in rows]
    assert [r[0] for r in rows if "default" in r[3:]] == [uvt.DEFAULT_CONFIG]


def test_strategies_match_the_cli(uvt_bin):
    assert list(uvt.STRATEGIES) == cli(uvt_bin, "configs", "--strategies").split()


def test_kinds_match_the_c_header():
    header = (ROOT / "ffi" / "include" / "uvt.h").read_text()
    consts = dict(re.findall(r"#define (UVT_\w+) (\d+)", header))
    assert list(uvt.KINDS) == ["setup", "bounds", "select", "sample", "bsample", "psample", "resolve"]
    for name, k in uvt.KINDS.items():
        assert int(consts[f"UVT_KIND_{name.upper()}"]) == k.code
        assert int(consts[f"UVT_{name.upper()}_OUT_WORDS"]) == k.out_words
        if name == "resolve":
            assert k.in_words is None
        else:
            assert int(consts[f"UVT_{name.upper()}_IN_WORDS"]) == k.in_words
        # the layouts agree with the word counts
        spp = 16
        last = max(w + (width + 31) // 32 for _, w, _, width, _, _ in uvt.fields(f"{name}_out", spp))
        assert last == k.out_words
    assert uvt.KINDS["bsample"].architectural == ("covered", "depth")
    assert uvt.KINDS["bounds"].needs_setup and not uvt.KINDS["bsample"].needs_setup


def test_version():
    cargo = (ROOT / "Cargo.toml").read_text()
    assert re.search(r'^version = "(.*)"', cargo, re.M).group(1) == uvt.__version__
