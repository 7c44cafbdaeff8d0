#!/usr/bin/env bash
# bench/memory/run.sh: bytes per particle and per cell that the coupling
# layer adds (a benchmark, not a test).
#
#   bench/memory/run.sh [--beds "39 78"] [--width 36] [--box-height 99]
#                       [--steps 5] [--np 2] [--work DIR] [--results DIR]
#
# One mesh (the packed column of bench/coupled, --width x --width x
# --box-height particle diameters, cells of 3 diameters) holding beds of
# different heights (--beds, in layers of width^2 particles), each run with
# `air on;` and `air off;`. Two measures, reported by report.py in
# <results>/memory.{md,csv}:
#   1. the coupling layer's own buffers, counted by granairFoam (vector
#      capacities of CoupledRun, ParticleExchange, CouplingStep);
#   2. peak resident memory (VmHWM summed over ranks), air on minus air off,
#      split into a per-particle slope (between the two beds, same mesh) and
#      a per-cell rest.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=../../tools/case-lib.sh
. "$here/../../tools/case-lib.sh"

beds="39 78" width=36 box=99 steps=5 np=2
work="$GRANAIR_BUILD/bench-memory" results="$here/../results"
while [ $# -gt 0 ]; do
  case $1 in
    --beds) beds=$2; shift 2 ;;
    --width) width=$2; shift 2 ;;
    --box-height) box=$2; shift 2 ;;
    --steps) steps=$2; shift 2 ;;
    --np) np=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --results) results=$2; shift 2 ;;
    *) echo "usage: $0 [--beds \"H ...\"] [--width W] [--box-height B] [--steps S] [--np P] [--work DIR] [--results DIR]" >&2
       exit 2 ;;
  esac
done
command -v granairFoam >/dev/null || { echo "bench/memory: granairFoam not found in $GRANAIR_BUILD/bin" >&2; exit 1; }

mkdir -p "$work"
for h in $beds; do
  for air in off on; do
    dir="$work/bed${h}_${air}"
    rm -rf "$dir"
    "$GRANAIR_PYTHON" "$here/../coupled/make_case.py" --out "$dir" --width "$width" --bed-height "$h" --box-height "$box" --air "$air" --steps "$steps" --np "$np" > /dev/null
    granair_mesh "$dir"
    granair_decompose "$dir" "$np"
    granair_run "$dir" "$np" granairFoam
    echo "bench/memory: bed $h, air $air: $(grep -h 'Peak memory' "$dir/log/granairFoam.log")"
  done
done
"$GRANAIR_PYTHON" "$here/report.py" "$work" "$results"
