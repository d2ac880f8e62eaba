#!/usr/bin/env bash
# Size, stack and per-stage cost of the core on both emulated thumbv7 profiles — Cortex-M4F
# (thumbv7em-none-eabihf, QEMU mps2-an386) and Cortex-M3 without FPU (thumbv7m-none-eabi, QEMU
# mps2-an385) — beside the same stages on the host. Prints Markdown tables (the README's Cortex-M
# section). Needs: rustup targets thumbv7em-none-eabihf and thumbv7m-none-eabi, qemu-system-arm,
# readelf (binutils). Honours CARGO_TARGET_DIR.
#
# `m4_report.sh --sweep [OUT.json]` instead builds m4_render once per configuration of the
# precision sweep (UVT_M4_PREC=NAME; the names from the registry, `uvt configs --sweep`), runs
# each on the Cortex-M4F under QEMU and on the host, and writes instructions (and host ns) per
# setup / tile bounds / sample test to OUT.json (default host/report/m4.json), which `uvt
# precision` reads.
#
# `m4_report.sh --units [OUT.json]` builds m4_render once per unit variant (UVT_M4_UNIT=NAME:
# the default configuration and the demo prims the unit accepts only), runs each on the
# Cortex-M4F under QEMU and writes flash (.vector_table + .text + .rodata), .text, RAM (.data +
# .bss), peak stack, instructions per setup / tile bounds / sample test and the image checksum
# to OUT.json (default host/report/m4_units.json); then the full unit on each narrower unit's
# prims (UVT_M4_PRIMS; its checksum must equal that unit's), so the cost per call can be
# compared on the same work ("full_on_unit_prims"). Beside them: the harness (the unit program
# with no unit code linked, UVT_M4_HARNESS: "harness", and "unit_flash" = flash − its flash) and
# the measuring loop's own cost per sample-test call (a second build with UVT_M4_EMPTY:
# "sample_empty"; "sample_net" = "sample_raw" − "sample_empty"; "bounds_empty" the same for the
# tile-bounds loop).
# `m4_report.sh --units OUT.json PREC` does the same at configuration PREC (UVT_M4_PREC; the
# default configuration or planar-16-16-16-20), e.g. `--units /tmp/m4_units_planar.json
# planar-16-16-16-20`; without PREC the output is the default configuration's, as before.
# `m4_report.sh --strategies [OUT.json]` measures every bounds strategy of the bench on the bench
# rows' own triangles at both sizes (`uvt m4-workload`: every 2nd triangle of a quick game row,
# every 16th of a quick dense row, every 26th and 256th at the full size, which has 13 and 16
# times the triangles: about as many per row at either size; the whole sample table, bounds
# tile 1): m4_stages built once per row with
# the row linked in (UVT_M4_WORKLOAD), run on the Cortex-M4F under QEMU, and the same program on
# the host, whose counts must equal the Cortex-M's line for line. Writes per row, strategy and
# triangle class the counts (triangles, visible, tiles, admits, tested, covered, core ops) and the
# instructions of setup, tile walk, predicate and sample test to OUT.json (default
# host/report/m4_strategies.json), which `uvt bench-ste` reads for its whole-cost column.
set -euo pipefail
cd "$(dirname "$0")/.."
tdir=${CARGO_TARGET_DIR:-target}
# The rows of a JSON array, comma-separated (one per line, as given).
json_items() { local n=$#; local i=0; for r in "$@"; do i=$((i + 1)); if [[ $i -lt $n ]]; then echo "$r,"; else echo "$r"; fi; done; }
# Move a finished temporary file into place (nothing half-written), print it and stop.
publish() { mv "$1" "$2"; cat "$2"; exit 0; }
sec() { printf '%d' "0x$(readelf -S -W "$1" | awk -v s="$2" '{for (i = 1; i <= NF; i++) if ($i == s) print $(i + 4)}')"; }
# `m4_report.sh --zmax [OUT.json]` does the same on the occlusion rows (`uvt bench-zmax`: the game
# street behind a near fence, static, motion, defocus, both; at both sizes, every 2nd triangle of
# a quick row and every 26th of a full one) and adds per row
# Zmax culling's own instructions (`uvt_demo::zmax_cost`: the depth floor per visible triangle,
# the tile check per kept bounds tile, the register refresh per written sample at 16 spp) — the
# "zmax" line of m4_stages, which `--strategies` records too. Writes OUT.json (default
# host/report/m4_zmax.json), which `uvt bench-zmax` reads for its Cortex-M4F column.
if [[ "${1:-}" == "--strategies" || "${1:-}" == "--zmax" ]]; then
  if [[ "$1" == "--zmax" ]]; then
    json=${2:-host/report/m4_zmax.json}
    plan=("quick occluded static motion defocus both" "full occluded static motion defocus both")
  else
    json=${2:-host/report/m4_strategies.json}
    plan=()
    for size in quick full; do
      plan+=("$size game static motion motion2 defocus defocus2 both both2" "$size dense static motion motion2 defocus defocus2 both both2")
    done
  fi
  elf=$tdir/thumbv7em-none-eabihf/release/examples/m4_stages
  cargo build -q --release -p uvt-host --bin uvt
  cargo build -q --release -p uvt-demo --example m4_stages
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  rows=()
  for line in "${plan[@]}"; do
    read -r size scene row_names <<<"$line"
    # Every N-th triangle: the full size has 13 (game, occluded) and 16 (dense) times the
    # quick size's triangles, so about as many per row are measured at either size.
    every=2
    [[ $scene == dense ]] && every=16
    quick=(--quick)
    if [[ $size == full ]]; then
      every=26
      [[ $scene == dense ]] && every=256
      quick=()
    fi
    for row in $row_names; do
      echo "m4_report $1: $scene $row, $size size (every $every)" >&2
      w=$work/$size-$scene-$row.bin
      "$tdir/release/uvt" m4-workload --scene "$scene" --row "$row" "${quick[@]}" --every "$every" --out "$w" >/dev/null
      host=$("$tdir/release/examples/m4_stages" "$w")
      UVT_M4_WORKLOAD=$w cargo build -q --release -p uvt-demo --example m4_stages --target thumbv7em-none-eabihf
      m4=$(timeout 1200 qemu-system-arm -machine mps2-an386 -cpu cortex-m4 -nographic -monitor none \
          -semihosting-config enable=on,target=native -icount shift=0 -kernel "$elf")
      cal=$(echo "$m4" | awk -F= '/^calibration/ {print $2}')
      [[ $cal -ge 7999922 && $cal -le 8000082 ]] || { echo "calibration $cal, expected 8000002 +- 80" >&2; exit 1; }
      # The same work with the same bits: every count of every line equal (insn aside).
      strip() { echo "$1" | grep -E '^(workload|stage|zmax) ' | sed 's/ insn=.*//'; }
      if [[ "$(strip "$host")" != "$(strip "$m4")" ]]; then
        diff <(strip "$host") <(strip "$m4") >&2 || true
        echo "m4_stages: the Cortex-M4F's counts differ from the host's ($scene $row)" >&2
        exit 1
      fi
      [[ $(echo "$m4" | grep -c '^stage ') -ge 7 ]] || { echo "m4_stages: no stage lines ($scene $row)" >&2; exit 1; }
      lines=$(echo "$m4" | awk '$1 == "stage" {
        n = split($0, f, " "); out = "{\"strategy\": \"" $2 "\", \"class\": \"" $3 "\"";
        for (i = 4; i <= n; i++) { split(f[i], kv, "="); v = kv[2];
          if (kv[1] == "ops" || kv[1] == "insn") v = "[" v "]";
          out = out ", \"" kv[1] "\": " v }
        print out "}" }' | paste -sd, -)
      zline=$(echo "$m4" | awk '$1 == "zmax" {
        out = "{"; for (i = 2; i <= NF; i++) { split($i, kv, "="); v = kv[2];
          if (kv[1] == "insn") v = "[" v "]";
          out = out (i > 2 ? ", " : "") "\"" kv[1] "\": " v }
        print out "}" }')
      [[ -n "$zline" ]] || { echo "m4_stages: no zmax line ($scene $row)" >&2; exit 1; }
      rows+=("{\"scene\": \"$scene\", \"row\": \"$row\", \"size\": \"$size\", \"every\": $every, \"stages\": [$lines], \"zmax\": $zline}")
    done
  done
  {
    echo "{"
    echo "  \"target\": \"Cortex-M4F (thumbv7em-none-eabihf, QEMU mps2-an386, -icount shift=0): m4_stages on each bench row's own triangles at its size (every 'every'-th), default configuration, bounds tile 1; per strategy and triangle class: counts, core ops [setup, bounds, rows, predicate, sample] and instructions [setup, tile walk, predicate, sample test]; zmax: Zmax culling's calls [depth floor per visible triangle, tile check, register refresh at spp 16] and their instructions (SysTick laps, 40 instructions per tick)\","
    echo "  \"rows\": ["
    json_items "${rows[@]}"
    echo "  ]"
    echo "}"
  } >"$json.tmp"
  publish "$json.tmp" "$json"
fi
if [[ "${1:-}" == "--units" ]]; then
  json=${2:-host/report/m4_units.json}
  uprec=${3:-}
  if [[ -n "$uprec" ]]; then export UVT_M4_PREC=$uprec; fi
  per() { echo "$1" | awk -v s="$2" '$1=="cost" && $2==s {split($3,a,"="); split($4,b,"="); printf "%.0f", b[2]/a[2]}'; }
  per1() { echo "$1" | awk -v s="$2" '$1=="cost" && $2==s {split($3,a,"="); split($4,b,"="); printf "%.1f", b[2]/a[2]}'; }
  field() { echo "$1" | awk -v k="$2" '$1 == k {print $2}'; }
  elf=$tdir/thumbv7em-none-eabihf/release/examples/m4_render
  # Build m4_render with the given environment assignments and run it under QEMU (stdout).
  m4run() {
    env "$@" cargo build -q --release -p uvt-demo --example m4_render --target thumbv7em-none-eabihf
    local out
    out=$(timeout 120 qemu-system-arm -machine mps2-an386 -cpu cortex-m4 -nographic -monitor none \
        -semihosting-config enable=on,target=native -icount shift=0 -kernel "$elf")
    local cal
    cal=$(echo "$out" | awk -F= '/^calibration/ {print $2}')
    [[ $cal -ge 7999922 && $cal -le 8000082 ]] || { echo "calibration $cal, expected 8000002 +- 80" >&2; exit 1; }
    echo "$out"
  }
  # The measuring loop's own cost per sample-test call: the same program built with
  # UVT_M4_EMPTY (the loop with the test replaced by black_box), one decimal.
  empty_of() {
    local out
    out=$(m4run "$@" UVT_M4_EMPTY=1)
    echo "$(per1 "$out" sample_empty) $(per1 "$out" bounds_empty)"
  }
  # The harness: the unit program with no unit code linked (UVT_M4_HARNESS).
  echo "m4_report --units: harness" >&2
  m4=$(m4run UVT_M4_UNIT=static-only UVT_M4_HARNESS=1)
  [[ "$(echo "$m4" | awk '$1 == "harness"')" == "harness" ]] || { echo "m4_render not built as the harness" >&2; exit 1; }
  htext=$(sec "$elf" .text)
  hflash=$(( $(sec "$elf" .vector_table) + htext + $(sec "$elf" .rodata) ))
  hram=$(( $(sec "$elf" .data) + $(sec "$elf" .bss) ))
  harness="{\"flash\": $hflash, \"text\": $htext, \"ram\": $hram, \"stack\": $(field "$m4" stack_peak_bytes)}"
  rows=()
  same=()
  declare -A sums
  for u in full motion-only defocus-only static-only; do
    echo "m4_report --units: $u" >&2
    m4=$(m4run UVT_M4_UNIT=$u)
    got=$(field "$m4" unit)
    [[ "$got" == "$u" ]] || { echo "m4_render built for unit '$got', expected '$u'" >&2; exit 1; }
    [[ -z "$uprec" || "$(field "$m4" unit_prec)" == "$uprec" ]] || { echo "m4_render not built at $uprec" >&2; exit 1; }
    text=$(sec "$elf" .text)
    flash=$(( $(sec "$elf" .vector_table) + text + $(sec "$elf" .rodata) ))
    ram=$(( $(sec "$elf" .data) + $(sec "$elf" .bss) ))
    sums[$u]=$(field "$m4" checksum)
    sample=$(per1 "$m4" sample_unit)
    echo "m4_report --units: $u, harness loop" >&2
    read -r empty bempty <<<"$(empty_of UVT_M4_UNIT=$u)"
    net=$(awk -v a="$sample" -v b="$empty" 'BEGIN {printf "%.1f", a - b}')
    rows+=("    {\"unit\": \"$u\", \"flash\": $flash, \"text\": $text, \"ram\": $ram, \"stack\": $(field "$m4" stack_peak_bytes), \"setup\": $(per "$m4" setup_unit), \"bounds\": $(per "$m4" bounds_unit), \"sample\": $(per "$m4" sample_unit), \"checksum\": \"$(field "$m4" checksum)\", \"unit_flash\": $((flash - hflash)), \"sample_raw\": $sample, \"sample_empty\": $empty, \"sample_net\": $net, \"bounds_raw\": $(per1 "$m4" bounds_unit), \"bounds_empty\": $bempty}")
  done
  # The full unit on each narrower unit's prims: the same work as that unit's row (its image
  # must be the same, bit for bit).
  for u in motion-only defocus-only static-only; do
    echo "m4_report --units: full on the $u prims" >&2
    m4=$(m4run UVT_M4_UNIT=full UVT_M4_PRIMS=$u)
    [[ "$(field "$m4" prims)" == "$u" ]] || { echo "m4_render not built for the $u prims" >&2; exit 1; }
    [[ "$(field "$m4" checksum)" == "${sums[$u]}" ]] || { echo "full on the $u prims: checksum $(field "$m4" checksum), the $u unit ${sums[$u]}" >&2; exit 1; }
    sample=$(per1 "$m4" sample_unit)
    read -r empty bempty <<<"$(empty_of UVT_M4_UNIT=full UVT_M4_PRIMS=$u)"
    net=$(awk -v a="$sample" -v b="$empty" 'BEGIN {printf "%.1f", a - b}')
    same+=("    {\"prims\": \"$u\", \"setup\": $(per "$m4" setup_unit), \"bounds\": $(per "$m4" bounds_unit), \"sample\": $(per "$m4" sample_unit), \"checksum\": \"$(field "$m4" checksum)\", \"sample_raw\": $sample, \"sample_empty\": $empty, \"sample_net\": $net, \"bounds_raw\": $(per1 "$m4" bounds_unit), \"bounds_empty\": $bempty}")
  done
  tmp=$(mktemp "$json.XXXX")
  {
    echo "{"
    echo "  \"command\": \"bash demo/m4_report.sh --units${uprec:+ $json $uprec}\","
    if [[ -n "$uprec" ]]; then
      echo "  \"prec\": \"$uprec\","
    fi
    echo "  \"target\": \"Cortex-M4F (thumbv7em-none-eabihf, QEMU mps2-an386, -icount shift=0): m4_render built with UVT_M4_UNIT; ${uprec:-default} configuration only; the demo prims the unit accepts; flash = .vector_table + .text + .rodata bytes, ram = .data + .bss bytes, stack = painted peak bytes; setup/bounds/sample = instructions per call; harness = the same program with no unit code linked (UVT_M4_HARNESS), unit_flash = flash - harness flash; sample_raw = sample with one decimal, sample_empty = the measuring loop alone per call (UVT_M4_EMPTY build: the test replaced by black_box), sample_net = sample_raw - sample_empty; bounds_raw, bounds_empty = the same for the tile bounds\","
    echo "  \"harness\": $harness,"
    echo "  \"units\": ["
    json_items "${rows[@]}"
    echo "  ],"
    echo "  \"full_on_unit_prims\": ["
    json_items "${same[@]}"
    echo "  ]"
    echo "}"
  } > "$tmp"
  publish "$tmp" "$json"
fi
if [[ "${1:-}" == "--sweep" ]]; then
  json=${2:-host/report/m4.json}
  # The sweep's names, one per line, from the configuration registry (uvt_core::config::registry).
  sweep=$(cargo run -q --release -p uvt-host -- configs --sweep)
  mapfile -t names <<<"$sweep"
  [[ ${#names[@]} -gt 0 && -n "${names[0]}" ]] || { echo "uvt configs --sweep printed no names" >&2; exit 1; }
  per() { echo "$1" | awk -v s="$2" '$1=="cost" && $2==s {split($3,a,"="); split($4,b,"="); printf "%.'"$3"'f", b[2]/a[2]}'; }
  rows=()
  for n in "${names[@]}"; do
    echo "m4_report --sweep: $n" >&2
    UVT_M4_PREC=$n cargo build -q --release -p uvt-demo --example m4_render --target thumbv7em-none-eabihf
    m4=$(timeout 120 qemu-system-arm -machine mps2-an386 -cpu cortex-m4 -nographic -monitor none \
        -semihosting-config enable=on,target=native -icount shift=0 \
        -kernel "$tdir/thumbv7em-none-eabihf/release/examples/m4_render")
    host=$(UVT_M4_PREC=$n cargo run -q --release -p uvt-demo --example m4_render)
    got=$(echo "$m4" | awk '$1 == "prec" {print $2}')
    [[ "$got" == "$n" ]] || { echo "m4_render built for '$got', expected '$n'" >&2; exit 1; }
    cal=$(echo "$m4" | awk -F= '/^calibration/ {print $2}')
    rows+=("    {\"name\": \"$n\", \"setup\": $(per "$m4" setup_sel 0), \"bounds\": $(per "$m4" bounds_sel 0), \"sample\": $(per "$m4" sample_sel 0), \"host_ns\": [$(per "$host" setup_sel 1), $(per "$host" bounds_sel 1), $(per "$host" sample_sel 1)], \"calibration\": $cal}")
  done
  tmp=$(mktemp "$json.XXXX")
  {
    echo "{"
    echo "  \"command\": \"bash demo/m4_report.sh --sweep\","
    echo "  \"target\": \"Cortex-M4F (thumbv7em-none-eabihf, QEMU mps2-an386, -icount shift=0; instructions per call on the demo scene; calibration 8000002 expected)\","
    echo "  \"configs\": ["
    json_items "${rows[@]}"
    echo "  ]"
    echo "}"
  } > "$tmp"
  publish "$tmp" "$json"
fi
# profile: name target machine cpu
profiles=("M4F thumbv7em-none-eabihf mps2-an386 cortex-m4" "M3 thumbv7m-none-eabi mps2-an385 cortex-m3")
host=$(cargo run -q --release -p uvt-demo --example m4_render)
declare -A out elf
for p in "${profiles[@]}"; do
  read -r name target machine cpu <<<"$p"
  cargo build -q --release -p uvt-demo --example m4_render --target "$target"
  elf[$name]=$tdir/$target/release/examples/m4_render
  out[$name]=$(timeout 120 qemu-system-arm -machine "$machine" -cpu "$cpu" -nographic -monitor none \
      -semihosting-config enable=on,target=native -icount shift=0 -kernel "${elf[$name]}")
done
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
