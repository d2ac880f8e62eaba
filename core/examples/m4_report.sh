#!/usr/bin/env bash
# Size, stack and per-stage cost of the core on an emulated Cortex-M4F (QEMU mps2-an386) beside
# the same stages on the host. Prints a Markdown table (the README's "Cortex-M4F" section).
# Needs: rustup target thumbv7em-none-eabihf, qemu-system-arm, readelf (binutils).
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build -q --release -p uvt-core --example m4_render --target thumbv7em-none-eabihf
elf=target/thumbv7em-none-eabihf/release/examples/m4_render
m4=$(timeout 120 qemu-system-arm -machine mps2-an386 -cpu cortex-m4 -nographic -monitor none \
      -semihosting-config enable=on,target=native -icount shift=0 -kernel "$elf")
host=$(cargo run -q --release -p uvt-core --example m4_render)
sec() { printf '%d' "0x$(readelf -S -W "$elf" | awk -v s="$1" '{for (i = 1; i <= NF; i++) if ($i == s) print $(i + 4)}')"; }
text=$(sec .text); rodata=$(sec .rodata); vt=$(sec .vector_table); data=$(sec .data); bss=$(sec .bss)
stack=$(echo "$m4" | awk '/^stack_peak_bytes/ {print $2}')
echo "checksum: target $(echo "$m4" | awk '/^checksum/ {print $2}'), host $(echo "$host" | awk '/^checksum/ {print $2}')"
echo
echo "| program (m4_render, release) | bytes |"
echo "|---|---|"
echo "| flash: .vector_table + .text + .rodata | $((vt + text + rodata)) (.text $text) |"
echo "| RAM: .data + .bss | $((data + bss)) |"
echo "| RAM: peak stack (painted) | $stack |"
echo
echo "| stage | Cortex-M4F instructions per call | host ns per call |"
echo "|---|---|---|"
for st in setup bounds sample; do
  mi=$(echo "$m4" | awk -v s="$st" '$1=="cost" && $2==s {split($3,a,"="); split($4,b,"="); printf "%.0f", b[2]/a[2]}')
  hn=$(echo "$host" | awk -v s="$st" '$1=="cost" && $2==s {split($3,a,"="); split($4,b,"="); printf "%.1f", b[2]/a[2]}')
  echo "| $st | $mi | $hn |"
done
