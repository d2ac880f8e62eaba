#!/usr/bin/env python3
"""Build a sample-test unit with Icarus Verilog and run its cocotb test on it (cocotb's runner):
uvt_bsample.v with test_bsample.py (--unit bsample, the default) or uvt_psample.v with
test_psample.py (--unit psample).

  python run.py [--unit bsample|psample] [--rtl DIR] [--build-dir DIR] [--waves]

--rtl names the folder holding the unit and uvt_mul.v (default: vectors/rtl). The build
and results.xml go to --build-dir (default: a temporary folder, removed afterwards). UVT_FFI_LIB
(default: target/release/libuvt_ffi.so of this checkout) and the test's variables (UVT_SEED,
UVT_COCOTB_N, UVT_ARCH_ONLY, UVT_CORRUPT) are passed through. Exit status 0 when the test
passed, 1 when it failed.
"""

import argparse
import os
import shutil
import sys
import tempfile
from pathlib import Path

from cocotb_tools.check_results import get_results
from cocotb_tools.runner import get_runner

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--unit", choices=["bsample", "psample"], default="bsample")
    ap.add_argument("--rtl", type=Path, default=ROOT / "vectors" / "rtl")
    ap.add_argument("--build-dir", type=Path)
    ap.add_argument("--waves", action="store_true", help="dump waves (FST) into the build folder")
    args = ap.parse_args()

    lib = Path(os.environ.get("UVT_FFI_LIB") or ROOT / "target" / "release" / "libuvt_ffi.so")
    if not lib.is_file():
        sys.exit(f"{lib} not found: cargo build --release -p uvt-ffi (or set UVT_FFI_LIB)")
    # The simulator runs in the build folder: hand it an absolute path.
    os.environ["UVT_FFI_LIB"] = str(lib.resolve())

    build = args.build_dir or Path(tempfile.mkdtemp(prefix="uvt-cocotb-"))
    try:
        rtl = args.rtl.resolve()
        runner = get_runner("icarus")
        runner.build(
            sources=[rtl / "uvt_mul.v", rtl / f"uvt_{args.unit}.v"],
            hdl_toplevel=f"uvt_{args.unit}",
            build_dir=build,
            always=True,
            timescale=("1ns", "1ps"),
            # the RTL is Verilog-2005 (uvt_psample.v names a wire `inside`, a keyword of the
            # runner's default -g2012)
            build_args=["-g2005"],
            waves=args.waves,
        )
        results = runner.test(
            hdl_toplevel=f"uvt_{args.unit}",
            test_module=f"test_{args.unit}",
            test_dir=build,
            build_dir=build,
            results_xml=str(build / "results.xml"),
            extra_env={
                "PYTHONPATH": os.pathsep.join([str(HERE), os.environ.get("PYTHONPATH", "")]),
                "PYTHONDONTWRITEBYTECODE": "1",  # no __pycache__ in the source tree
            },
            waves=args.waves,
        )
        tests, failed = get_results(Path(results))
    finally:
        if args.build_dir is None:
            shutil.rmtree(build, ignore_errors=True)
    print(f"cocotb: {tests - failed} passed, {failed} failed")
    return 0 if tests > 0 and failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
