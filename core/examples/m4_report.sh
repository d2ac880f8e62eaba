#!/usr/bin/env bash
# Size, stack and per-stage cost of the core on both emulated thumbv7 profiles — Cortex-M4F
# (thumbv7em-none-eabihf, QEMU mps2-an386) and Cortex-M3 without FPU (thumbv7m-none-eabi, QEMU
# mps2-an385) — beside the same stages on the host. Prints Markdown tables (the README's Cortex-M
# section). Needs: rustup targets thumbv7em-none-eabihf and thumbv7m-none-eabi, qemu-system-arm,
# readelf (binutils). Honours CARGO_TARGET_DIR.
set -euo pipefail
cd "$(dirname "$0")/../.."
tdir=${CARGO_TARGET_DIR:-target}
# profile: name target machine cpu
profiles=("M4F thumbv7em-none-eabihf mps2-an386 cortex-m4" "M3 thumbv7m-none-eabi mps2-an385 cortex-m3")
host=$(cargo run -q --release -p uvt-core --example m4_render)
declare -A out elf
for p in "${profiles[@]}"; do
  read -r name target machine cpu <<<"$p"
  cargo build -q --release -p uvt-core --example m4_render --target "$target"
  elf[$name]=$tdir/$target/release/examples/m4_render
  out[$name]=$(timeout 120 qemu-system-arm -machine "$machine" -cpu "$cpu" -nographic -monitor none \
      -semihosting-config enable=on,target=native -icount shift=0 -kernel "${elf[$name]}")
done
sec() { printf '%d' "0x$(readelf -S -W "$1" | awk -v s="$2" '{for (i = 1; i <= NF; i++) if ($i == s) print $(i + 4)}')"; }
field() { echo "$1" | awk -v k="$2" '$1 == k {print $2}'; }
echo "checksum: M4F $(field "${out[M4F]}" checksum), M3 $(field "${out[M3]}" checksum), host $(field "$host" checksum)"
echo "calibration (8000002 expected): M4F $(echo "${out[M4F]}" | awk -F= '/^calibration/ {print $2}'), M3 $(echo "${out[M3]}" | awk -F= '/^calibration/ {print $2}')"
echo
echo "| program (m4_render, release) | Cortex-M4F bytes | Cortex-M3 bytes |"
echo "|---|---|---|"
row() { # label, then a command printing the figure for one elf/output
  local a b; a=$("$2" M4F); b=$("$2" M3); echo "| $1 | $a | $b |"; }
flash() { local e=${elf[$1]}; local t; t=$(sec "$e" .text); echo "$(( $(sec "$e" .vector_table) + t + $(sec "$e" .rodata) )) (.text $t)"; }
ram() { local e=${elf[$1]}; echo "$(( $(sec "$e" .data) + $(sec "$e" .bss) ))"; }
stack() { field "${out[$1]}" stack_peak_bytes; }
row "flash: .vector_table + .text + .rodata" flash
row "RAM: .data + .bss" ram
row "RAM: peak stack (painted)" stack
echo
echo "| stage | Cortex-M4F instructions per call | Cortex-M3 instructions per call | host ns per call |"
echo "|---|---|---|---|"
per() { echo "$1" | awk -v s="$2" '$1=="cost" && $2==s {split($3,a,"="); split($4,b,"="); printf "%.'"$3"'f", b[2]/a[2]}'; }
# *_bounded: the same stages at BoundedPrecision (the bounded sample test, ε-widened setup).
for st in setup bounds sample setup_bounded bounds_bounded sample_bounded; do
  echo "| $st | $(per "${out[M4F]}" $st 0) | $(per "${out[M3]}" $st 0) | $(per "$host" $st 1) |"
done
