#!/usr/bin/env bash
# Synthesize the bounded sample-test unit (uvt_bsample.v, its multipliers uvt_mul.v) with Yosys
# for Xilinx 7-series (synth_xilinx: DSP48E1, LUT1..6, flip-flops, SRLs) and Lattice ECP5
# (synth_ecp5: MULT18X18D, LUT4, flip-flops) per configuration, and write the counts to host/report/synth.json (the
# format of the precision report: {"yosys": …, "configs": [{"name", "xilinx": {…}, "ecp5": {…}}]}).
#
#   bash vectors/rtl/synth.sh [-j JOBS] [-o OUT.json] [-r WORKDIR] [CONFIG …]
#
# -r WORKDIR: no synthesis; rebuild the JSON from the stat files and times of an earlier run's
# folder (the one it printed); total_seconds is then the sum of the runs' times.
# CONFIG = bounded-P-T-B-O (B, the bounds' precision, does not enter the sample test). Default:
# bounded-16-16-16-20 bounded-16-16-16-24 bounded-12-12-12-24 bounded-8-8-8-28. JOBS yosys runs
# at once (default 1). Logs and per-run stat files go to a temporary folder that is printed.
set -euo pipefail
cd "$(dirname "$0")/../.."
jobs=1
reuse=
out=host/report/synth.json
while [ $# -gt 0 ]; do
  case "$1" in
    -j) jobs="$2"; shift 2 ;;
    -o) out="$2"; shift 2 ;;
    -r) reuse="$2"; shift 2 ;;
    -*) echo "synth.sh: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
configs=("$@")
[ ${#configs[@]} -gt 0 ] || configs=(bounded-16-16-16-20 bounded-16-16-16-24 bounded-12-12-12-24 bounded-8-8-8-28)
rtl="vectors/rtl/uvt_mul.v vectors/rtl/uvt_bsample.v"
if [ -n "$reuse" ]; then
  work=$reuse
else
  command -v yosys >/dev/null || { echo "synth.sh: yosys not found (Debian package yosys)" >&2; exit 1; }
  work=$(mktemp -d /tmp/uvt-synth.XXXXXX)
  echo "synth.sh: logs in $work" >&2
fi

run() { # config family
  local name=$1 fam=$2
  IFS=- read -r kind pos tuv _bnd off <<<"$name"
  if [ "$kind" != bounded ] || [ -z "$off" ]; then
    echo "synth.sh: configuration '$name' is not bounded-P-T-B-O" >&2; return 1
  fi
  # The multiplier tiling follows the family's hard multiplier (uvt_mul.v): 25 × 18 signed for
  # the DSP48E1, 18 × 18 for the MULT18X18D.
  local cmd ports
  if [ "$fam" = xilinx ]; then
    cmd="synth_xilinx -top uvt_bsample -family xc7"; ports="-set DSP_A 25 -set DSP_B 18"
  else
    cmd="synth_ecp5 -top uvt_bsample"; ports="-set DSP_A 18 -set DSP_B 18"
  fi
  local t0=$SECONDS
  if ! yosys -q -l "$work/$name.$fam.log" -p "read_verilog -defer $rtl; chparam -set POS $pos -set TUV $tuv -set OFF $off $ports uvt_bsample; $cmd; tee -q -o $work/$name.$fam.stat stat" >/dev/null 2>&1; then
    echo "synth.sh: yosys failed for $name ($fam); see $work/$name.$fam.log" >&2; return 1
  fi
  echo "$((SECONDS - t0))" > "$work/$name.$fam.secs"
  echo "synth.sh: $name $fam done in $((SECONDS - t0)) s" >&2
}

t_start=$SECONDS
pids=()
[ -n "$reuse" ] || for c in "${configs[@]}"; do
  for fam in xilinx ecp5; do
    run "$c" "$fam" &
    pids+=($!)
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  done
done
fail=0
for p in "${pids[@]}"; do wait "$p" || fail=1; done
[ $fail -eq 0 ] || { echo "synth.sh: a run failed; nothing written" >&2; exit 1; }
for c in "${configs[@]}"; do
  for fam in xilinx ecp5; do
    [ -s "$work/$c.$fam.stat" ] || { echo "synth.sh: no $work/$c.$fam.stat; nothing written" >&2; exit 1; }
  done
done
total=$((SECONDS - t_start))
[ -z "$reuse" ] || total=$(cat "$work"/*.secs | awk '{ s += $1 } END { print s + 0 }')

# Sum of the cells of the listed types in a stat file (0 if none). synth_xilinx keeps the
# uvt_mul instances as modules: stat then lists every module once and the whole design under
# "design hierarchy", which alone is counted (synth_ecp5 flattens: one module, counted whole).
count() { # file regex
  awk -v re="$2" '/^=== design hierarchy ===/ { s = 0 }
    $1 ~ re && $2 ~ /^[0-9]+$/ { s += $2 } END { print s + 0 }' "$1"
}
ver=$(yosys -V | sed 's/"/\\"/g')
{
  printf '{\n  "yosys": "%s",\n  "script": "bash vectors/rtl/synth.sh",\n  "total_seconds": %d,\n  "configs": [' "$ver" "$total"
  sep=""
  for c in "${configs[@]}"; do
    x="$work/$c.xilinx.stat"; e="$work/$c.ecp5.stat"
    printf '%s\n    {"name": "%s",\n     "xilinx": {"dsp48e1": %d, "lut": %d, "ff": %d, "srl": %d, "carry4": %d, "seconds": %d},\n     "ecp5": {"mult18x18d": %d, "lut4": %d, "ff": %d, "seconds": %d}}' \
      "$sep" "$c" \
      "$(count "$x" '^DSP48E1$')" "$(count "$x" '^LUT[1-6]$')" "$(count "$x" '^FD[CPRS]E$')" \
      "$(count "$x" '^SRL')" "$(count "$x" '^CARRY4$')" "$(cat "$work/$c.xilinx.secs")" \
      "$(count "$e" '^MULT18X18D$')" "$(count "$e" '^LUT4$')" "$(count "$e" '^TRELLIS_FF$')" \
      "$(cat "$work/$c.ecp5.secs")"
    sep=","
  done
  printf '\n  ]\n}\n'
} > "$out.tmp"
mv "$out.tmp" "$out"
echo "synth.sh: wrote $out ($total s of synthesis)" >&2
cat "$out"
