#!/usr/bin/env bash
# The one command that runs every uvt test on a fresh machine (README.md names it; .ci/run calls it).
# Installs what the tests need, then: thumbv7em and thumbv7m builds of the core, clippy and tests
# with warnings as errors. UVT_SEED and UVT_EXTENSIVE=1 are passed through to the tests.
set -euo pipefail
cd "$(dirname "$0")/.."
export RUSTFLAGS="${RUSTFLAGS:-} -D warnings"
export CARGO_TERM_COLOR=never

echo "== installing test prerequisites"
# The pinned toolchain of rust-toolchain.toml with its components and targets (a no-op when
# present); the Cortex-M figures are compared with the committed ones made with it.
rustup toolchain install >/dev/null 2>&1 || rustup toolchain install "$(sed -n 's/^channel = "\(.*\)"/\1/p' rust-toolchain.toml)" --profile minimal
rustup target add thumbv7em-none-eabihf thumbv7m-none-eabi >/dev/null
rustup component add clippy rustfmt >/dev/null 2>&1 || true
rustc --version
# Debian packages: qemu-system-arm (the Cortex-M4F and Cortex-M3 runs), iverilog (the RTL testbench),
# verilator (the DPI-C testbenches and the C++ harness of vectors/dpi), python3-venv (`python3 -m
# venv` for the cocotb test's venv, tests/tests/external/cocotb.rs; its pip needs PyPI), yosys (the
# mutation sample, tests/tests/external/mutation.rs: Yosys `mutate`).
missing=()
for pkg in qemu-system-arm iverilog verilator python3-venv yosys; do
  dpkg -s "$pkg" >/dev/null 2>&1 || missing+=("$pkg")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

echo "== core for Cortex-M4F (thumbv7em-none-eabihf) and Cortex-M3 (thumbv7m-none-eabi, no FPU)"
# The bare-metal program (the core and demo libraries inside it) into the target folder the QEMU
# tests build in (tests/tests/external/m4_qemu.rs: target/m4-test), so that they reuse it rather
# than build the core for each target a second time.
CARGO_TARGET_DIR=target/m4-test cargo build --locked -p uvt-demo --example m4_render --target thumbv7em-none-eabihf --release
CARGO_TARGET_DIR=target/m4-test cargo build --locked -p uvt-demo --example m4_render --target thumbv7m-none-eabi --release

echo "== rustfmt"
rustup component add rustfmt >/dev/null 2>&1 || true
cargo fmt --all --check

echo "== clippy (warnings are errors), host and the bare-metal programs"
cargo clippy --locked --workspace --all-targets -- -D warnings
cargo clippy --locked -p uvt-demo --example m4_render --target thumbv7em-none-eabihf -- -D warnings
cargo clippy --locked -p uvt-demo --example m4_stages --target thumbv7em-none-eabihf -- -D warnings
cargo clippy --locked -p uvt-demo --example m4_render --target thumbv7m-none-eabi -- -D warnings

echo "== Python module (py/): wheel built by maturin, installed in target/py-venv, pytest"
# Before the cargo tests: the cocotb and pyuvm tests (tests/tests/external/cocotb.rs) run in this
# venv with the module installed. The venv: made anew when a requirements file (exact versions:
# the module's, its campaigns', the cocotb benches') changes; pip needs PyPI. The wheel
# is built with the dev profile (target/debug; debug assertions and overflow checks on): a seventh
# of the time of the release build `pip install ./py` makes (maturin's `--profile test` would build
# the test harness). The tests compare the module with the `uvt` binary and libuvt_ffi.so of the
# test profile (target/debug; the line below builds them, and `cargo test` reuses them).
# (two commands: `--bin uvt` beside `-p uvt-ffi` would build no library of uvt-ffi)
cargo build --locked --profile test -p uvt-ffi
cargo build --locked --profile test -p uvt-host --bin uvt
venv=target/py-venv
reqs=(py/requirements.txt py/requirements-campaign.txt vectors/cocotb/requirements.txt)
if ! cat "${reqs[@]}" | cmp -s - "$venv/uvt-requirements.txt"; then
  rm -rf "$venv"
  python3 -m venv "$venv"
  "$venv/bin/pip" install -q --disable-pip-version-check -r py/requirements.txt -r vectors/cocotb/requirements.txt
  cat "${reqs[@]}" >"$venv/uvt-requirements.txt"
fi
rm -rf target/py-wheel
"$venv/bin/maturin" build --locked --profile dev -m py/Cargo.toml -o target/py-wheel
"$venv/bin/pip" install -q --disable-pip-version-check --force-reinstall --no-deps target/py-wheel/uvt-*.whl
"$venv/bin/python" -m pytest py/tests -q -p no:cacheprovider

echo "== tests"
cargo test --locked --workspace

