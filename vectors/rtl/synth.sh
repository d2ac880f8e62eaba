#!/usr/bin/env bash
# Synthesize the bounded sample-test unit (uvt_bsample.v, its multipliers uvt_mul.v), the
# planar static sample-test unit (uvt_psample.v) and the per-tile bounds unit (uvt_bounds.v) with Yosys for Xilinx 7-series (synth_xilinx:
# DSP48E1, LUT1..6, flip-flops, SRLs) and Lattice ECP5 (synth_ecp5: MULT18X18D, LUT4,
# flip-flops) per configuration and unit variant, and write the counts to host/report/synth.json:
#   {"yosys": …, "configs": [{"name", "xilinx": {…}, "ecp5": {…}}],     full unit per configuration
#    "units": [{"unit", "name", "xilinx": {…}, "ecp5": {…}}]}           each unit at the default,
#                                                                      static-only at planar,
#                                                                      the bounds unit ("bounds")
#
#   bash vectors/rtl/synth.sh [-j JOBS] [-o OUT.json] [-r WORKDIR] [-k] [RUN …]
#
# RUN = CONFIG (the full unit) or UNIT@CONFIG, UNIT one of full, motion-only, defocus-only,
# static-only (uvt_bsample's MOTION, DEFOCUS) or bounds (uvt_bounds.v: BND = B, TUV = T); CONFIG = bounded-P-T-B-O (B, the bounds'
# precision, does not enter the sample test). The planar static configuration has one run,
# static-only@planar-16-16-16-20: uvt_psample.v (its other units would carry the bounded unit
# beside it; they are not built). Default: bounded-16-16-16-20 bounded-16-16-16-24
# bounded-12-12-12-24 bounded-8-8-8-28, motion-only@, defocus-only@, static-only@ the default
# bounded-16-16-16-20, static-only@planar-16-16-16-20 and bounds@bounded-16-16-16-20. "configs"
# lists the full-unit runs; "units" the four units at the default configuration (full = the run
# bounded-16-16-16-20), the static-only unit at planar-16-16-16-20 and the bounds unit at the
# default, those that were synthesized.
# -k: keep the entries of the existing OUT that this run does not synthesize (needs jq); each
# entry's "seconds" are its own run's, total_seconds this run's.
# -r WORKDIR: no synthesis; rebuild the JSON from the stat files and times of an earlier run's
# folder (the one it printed); total_seconds is then the sum of the runs' times.
# JOBS yosys runs at once (default 1). Logs and per-run stat files go to a temporary folder that
# is printed.
set -euo pipefail
cd "$(dirname "$0")/../.."
jobs=1
reuse=
keep=
out=host/report/synth.json
default=bounded-16-16-16-20
planar=planar-16-16-16-20
while [ $# -gt 0 ]; do
  case "$1" in
    -j) jobs="$2"; shift 2 ;;
    -o) out="$2"; shift 2 ;;
    -r) reuse="$2"; shift 2 ;;
    -k) keep=1; shift ;;
    -*) echo "synth.sh: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
runs=("$@")
[ ${#runs[@]} -gt 0 ] || runs=(bounded-16-16-16-20 bounded-16-16-16-24 bounded-12-12-12-24 bounded-8-8-8-28
  "motion-only@$default" "defocus-only@$default" "static-only@$default" "static-only@$planar"
  "bounds@$default")
units=(full motion-only defocus-only static-only)
# unit → MOTION DEFOCUS of uvt_bsample.v
terms() {
  case "$1" in
    full) echo "1 1" ;; motion-only) echo "1 0" ;; defocus-only) echo "0 1" ;; static-only) echo "0 0" ;;
    bounds) echo "- -" ;;                # not a sample-test unit: uvt_bounds.v
    *) return 1 ;;
  esac
}
# A run's unit and configuration ("full@C" is the run "C": one name per synthesis).
unit_of() { case "$1" in *@*) echo "${1%%@*}" ;; *) echo full ;; esac; }
config_of() { echo "${1#*@}"; }
for r in "${runs[@]}"; do
  u=$(unit_of "$r"); c=$(config_of "$r")
  terms "$u" >/dev/null || { echo "synth.sh: run '$r': unit '$u' is not one of ${units[*]} bounds" >&2; exit 2; }
  [ "$u" != full ] || [ "$r" = "$c" ] || { echo "synth.sh: run '$r': write the full unit's run as '$c'" >&2; exit 2; }
  if [ "$c" = "$planar" ]; then
    [ "$u" = static-only ] ||
      { echo "synth.sh: run '$r': at $planar only the static-only unit is built (static-only@$planar)" >&2; exit 2; }
    continue
  fi
  IFS=- read -r kind _pos _tuv _bnd off <<<"$c"
  if [ "$kind" != bounded ] || [ -z "$off" ]; then
    echo "synth.sh: run '$r': configuration '$c' is neither bounded-P-T-B-O nor $planar" >&2; exit 2
  fi
done
if [ -n "$keep" ]; then
  command -v jq >/dev/null || { echo "synth.sh: -k needs jq (Debian package jq)" >&2; exit 1; }
  [ -s "$out" ] || { echo "synth.sh: -k: no $out to keep entries of" >&2; exit 1; }
  jq -e '.configs | type == "array"' "$out" >/dev/null 2>&1 ||
    { echo "synth.sh: -k: $out has no \"configs\" array" >&2; exit 1; }
fi
rtl="vectors/rtl/uvt_mul.v vectors/rtl/uvt_bsample.v"
rtl_planar="vectors/rtl/uvt_mul.v vectors/rtl/uvt_psample.v"
rtl_bounds="vectors/rtl/uvt_mul.v vectors/rtl/uvt_bounds.v"
if [ -n "$reuse" ]; then
  work=$reuse
else
  command -v yosys >/dev/null || { echo "synth.sh: yosys not found (Debian package yosys)" >&2; exit 1; }
  work=$(mktemp -d /tmp/uvt-synth.XXXXXX)
  echo "synth.sh: logs in $work" >&2
fi

run() { # run family
  local name=$1 fam=$2
  local unit cfg mot dof
  unit=$(unit_of "$name"); cfg=$(config_of "$name")
  IFS=- read -r _kind pos tuv bnd off <<<"$cfg"
  # The multiplier tiling follows the family's hard multiplier (uvt_mul.v): 25 × 18 signed for
  # the DSP48E1, 18 × 18 for the MULT18X18D. The full unit keeps MOTION = DEFOCUS = 1 (the
  # defaults, not set: the same command as before the unit parameters).
  # The planar static unit (uvt_psample.v) has only the tiling parameters; the bounds unit
  # (uvt_bounds.v) takes the configuration's BND and TUV.
  local cmd ports top=uvt_bsample src=$rtl cfgp
  if [ "$cfg" = "$planar" ]; then
    top=uvt_psample; src=$rtl_planar; cfgp=""
  elif [ "$unit" = bounds ]; then
    top=uvt_bounds; src=$rtl_bounds; cfgp="-set BND $bnd -set TUV $tuv"
  else
    cfgp="-set POS $pos -set TUV $tuv -set OFF $off"
  fi
  if [ "$fam" = xilinx ]; then
    cmd="synth_xilinx -top $top -family xc7"; ports="-set DSP_A 25 -set DSP_B 18"
  else
    cmd="synth_ecp5 -top $top"; ports="-set DSP_A 18 -set DSP_B 18"
  fi
  if [ "$unit" != full ] && [ "$top" = uvt_bsample ]; then
    read -r mot dof <<<"$(terms "$unit")"
    ports="$ports -set MOTION $mot -set DEFOCUS $dof"
  fi
  local t0=$SECONDS
  if ! yosys -q -l "$work/$name.$fam.log" -p "read_verilog -defer $src; chparam $cfgp $ports $top; $cmd; tee -q -o $work/$name.$fam.stat stat" >/dev/null 2>&1; then
    echo "synth.sh: yosys failed for $name ($fam); see $work/$name.$fam.log" >&2; return 1
  fi
  echo "$((SECONDS - t0))" > "$work/$name.$fam.secs"
  echo "synth.sh: $name $fam done in $((SECONDS - t0)) s" >&2
}

t_start=$SECONDS
pids=()
[ -n "$reuse" ] || for c in "${runs[@]}"; do
  for fam in xilinx ecp5; do
    run "$c" "$fam" &
    pids+=($!)
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  done
done
fail=0
for p in "${pids[@]}"; do wait "$p" || fail=1; done
[ $fail -eq 0 ] || { echo "synth.sh: a run failed; nothing written" >&2; exit 1; }
for c in "${runs[@]}"; do
  for fam in xilinx ecp5; do
    [ -s "$work/$c.$fam.stat" ] || { echo "synth.sh: no $work/$c.$fam.stat; nothing written" >&2; exit 1; }
  done
done
total=$((SECONDS - t_start))
[ -z "$reuse" ] || total=$(for c in "${runs[@]}"; do cat "$work/$c".*.secs; done | awk '{ s += $1 } END { print s + 0 }')

# Sum of the cells of the listed types in a stat file (0 if none). synth_xilinx keeps the
# uvt_mul instances as modules: stat then lists every module once and the whole design under
# "design hierarchy", which alone is counted (synth_ecp5 flattens: one module, counted whole).
count() { # file regex
  awk -v re="$2" '/^=== design hierarchy ===/ { s = 0 }
    $1 ~ re && $2 ~ /^[0-9]+$/ { s += $2 } END { print s + 0 }' "$1"
}
# The "xilinx": {…}, "ecp5": {…} fields of run $1.
fields() {
  local x="$work/$1.xilinx.stat" e="$work/$1.ecp5.stat"
  printf '"xilinx": {"dsp48e1": %d, "lut": %d, "ff": %d, "srl": %d, "carry4": %d, "seconds": %d},\n     "ecp5": {"mult18x18d": %d, "lut4": %d, "ff": %d, "seconds": %d}' \
    "$(count "$x" '^DSP48E1$')" "$(count "$x" '^LUT[1-6]$')" "$(count "$x" '^FD[CPRS]E$')" \
    "$(count "$x" '^SRL')" "$(count "$x" '^CARRY4$')" "$(cat "$work/$1.xilinx.secs")" \
    "$(count "$e" '^MULT18X18D$')" "$(count "$e" '^LUT4$')" "$(count "$e" '^TRELLIS_FF$')" \
    "$(cat "$work/$1.ecp5.secs")"
}
ran() { local r; for r in "${runs[@]}"; do [ "$r" = "$1" ] && return 0; done; return 1; }
ver=$(yosys -V | sed 's/"/\\"/g')
{
  printf '{\n  "yosys": "%s",\n  "script": "bash vectors/rtl/synth.sh",\n  "total_seconds": %d,\n  "configs": [' "$ver" "$total"
  sep=""
  for c in "${runs[@]}"; do
    [ "$(unit_of "$c")" = full ] || continue
    printf '%s\n    {"name": "%s",\n     %s}' "$sep" "$c" "$(fields "$c")"
    sep=","
  done
  if [ -n "$keep" ]; then
    while IFS= read -r e; do
      ran "$(jq -r .name <<<"$e")" && continue
      printf '%s\n    %s' "$sep" "$e"
      sep=","
    done < <(jq -c '.configs[]' "$out")
  fi
  printf '\n  ],\n  "units": ['
  sep=""
  for u in "${units[@]}"; do
    r="$u@$default"; [ "$u" != full ] || r=$default
    if ran "$r"; then
      printf '%s\n    {"unit": "%s", "name": "%s",\n     %s}' "$sep" "$u" "$default" "$(fields "$r")"
      sep=","
    elif [ -n "$keep" ]; then
      e=$(jq -c --arg u "$u" --arg n "$default" '(.units // [])[] | select(.unit == $u and .name == $n)' "$out")
      if [ -z "$e" ] && [ "$u" = full ]; then
        e=$(jq -c --arg n "$default" '.configs[] | select(.name == $n) | {unit: "full"} + .' "$out")
      fi
      [ -z "$e" ] || { printf '%s\n    %s' "$sep" "$e"; sep=","; }
    fi
  done
  # The planar static unit (one run; its entry kept with -k when not re-run).
  r="static-only@$planar"
  if ran "$r"; then
    printf '%s\n    {"unit": "static-only", "name": "%s",\n     %s}' "$sep" "$planar" "$(fields "$r")"
    sep=","
  elif [ -n "$keep" ]; then
    e=$(jq -c --arg n "$planar" '(.units // [])[] | select(.unit == "static-only" and .name == $n)' "$out")
    [ -z "$e" ] || { printf '%s\n    %s' "$sep" "$e"; sep=","; }
  fi
  # The bounds unit at the default configuration (kept with -k likewise).
  r="bounds@$default"
  if ran "$r"; then
    printf '%s\n    {"unit": "bounds", "name": "%s",\n     %s}' "$sep" "$default" "$(fields "$r")"
    sep=","
  elif [ -n "$keep" ]; then
    e=$(jq -c --arg n "$default" '(.units // [])[] | select(.unit == "bounds" and .name == $n)' "$out")
    [ -z "$e" ] || { printf '%s\n    %s' "$sep" "$e"; sep=","; }
  fi
  printf '\n  ]\n}\n'
} > "$out.tmp"
jq -e . "$out.tmp" >/dev/null 2>&1 || ! command -v jq >/dev/null || { echo "synth.sh: wrote invalid JSON to $out.tmp" >&2; exit 1; }
mv "$out.tmp" "$out"
echo "synth.sh: wrote $out ($total s of synthesis)" >&2
cat "$out"
