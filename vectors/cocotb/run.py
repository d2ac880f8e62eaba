#!/usr/bin/env python3
"""Build a sample-test unit with Icarus Verilog and run its cocotb test on it (cocotb's runner):
uvt_bsample.v with test_bsample.py (--unit bsample, the default), uvt_psample.v with
test_psample.py (--unit psample), or uvt_bsample.v with the pyuvm scoreboard example
test_bsample_uvm.py (--unit bsample_uvm).

  python run.py [--unit bsample|psample|bsample_uvm] [--rtl DIR] [--build-dir DIR] [--waves]

The model is the uvt Python module (`pip install ./py`), imported by the tests in the simulator
from this Python's environment. --rtl names the folder holding the unit and uvt_mul.v (default:
vectors/rtl). The build and results.xml go to --build-dir (default: a temporary folder, removed
afterwards). The test's variables (UVT_SEED, UVT_COCOTB_N, UVT_ARCH_ONLY, UVT_CORRUPT) are passed
through. Exit status 0 when the test passed, 1 when it failed.
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
# --unit: (HDL unit, test module)
UNITS = {
    "bsample": ("uvt_bsample", "test_bsample"),
    "psample": ("uvt_psample", "test_psample"),
    "bsample_uvm": ("uvt_bsample", "test_bsample_uvm"),
}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--unit", choices=sorted(UNITS), default="bsample")
    ap.add_argument("--rtl", type=Path, default=ROOT / "vectors" / "rtl")
    ap.add_argument("--build-dir", type=Path)
    ap.add_argument("--waves", action="store_true", help="dump waves (FST) into the build folder")
    args = ap.parse_args()

    try:
        import uvt  # noqa: F401  (the tests import it in the simulator: fail early and plainly)
    except ImportError as e:
        sys.exit(f"the uvt module is not installed in {sys.prefix} ({e}): pip install ./py")
    unit, test_module = UNITS[args.unit]

    build = args.build_dir or Path(tempfile.mkdtemp(prefix="uvt-cocotb-"))
    try:
        rtl = args.rtl.resolve()
        runner = get_runner("icarus")
        runner.build(
            sources=[rtl / "uvt_mul.v", rtl / f"{unit}.v"],
            hdl_toplevel=unit,
            build_dir=build,
            always=True,
            timescale=("1ns", "1ps"),
            # the RTL is Verilog-2005 (uvt_psample.v names a wire `inside`, a keyword of the
            # runner's default -g2012)
            build_args=["-g2005"],
            waves=args.waves,
        )
        results = runner.test(
            hdl_toplevel=unit,
            test_module=test_module,
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
