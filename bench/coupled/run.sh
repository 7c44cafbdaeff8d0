#!/usr/bin/env bash
# bench/coupled/run.sh: coupled vs DEM-only throughput, mapping + exchange
# share, and cost per particle-step across sizes (a benchmark, not a test).
#
#   bench/coupled/run.sh [--sizes "1000 10000 100000"] [--steps 20] [--np 2]
#                        [--repeat 1] [--work DIR] [--results DIR] [--name coupled]
#                        [--configs "off forces-off on"] [--bed lattice|random]
#
# For every size: writes the packed-column case (make_case.py), meshes and
# decomposes it, runs granairFoam with `air off;` (DEM only), with the air on
# but its forces off (the fair reference) and with `air on;` for
# --steps coupling steps (50 DEM steps each) on --np ranks, --repeat times
# each, then report.py writes <results>/<name>.{md,csv} (default coupled). Needs a build with
# OpenFOAM and LIGGGHTS (build/bin/granairFoam; GRANAIR_BUILD overrides).
# Work folders default to build/bench-coupled-np<np> (one per rank count: a
# 2-rank run would otherwise replace the 1-rank run's folders); the run
# folders of an earlier call there are removed first, as report.py reads
# every run folder it finds. Results go to bench/results.
# --bed random: the bed of every size is poured and settled once by LIGGGHTS
# (make_case.py --settle, on --np ranks; kept in <work>/../bench-coupled-beds/<size>/bed.data
# and reused by later calls, any rank count) and every run reads it; the
# default is the simple cubic lattice (make_case.py tells the difference).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=../../tools/case-lib.sh
. "$here/../../tools/case-lib.sh"

sizes="1000 10000 100000" steps=20 np=2 repeat=1 name=coupled configs="off forces-off on" bed=lattice
work="" results="$here/../results"
while [ $# -gt 0 ]; do
  case $1 in
    --sizes) sizes=$2; shift 2 ;;
    --steps) steps=$2; shift 2 ;;
    --np) np=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --results) results=$2; shift 2 ;;
    --name) name=$2; shift 2 ;;
    --configs) configs=$2; shift 2 ;;
    --bed) bed=$2; shift 2 ;;
    *) echo "usage: $0 [--sizes \"N ...\"] [--steps S] [--np P] [--repeat R] [--work DIR] [--results DIR] [--name NAME] [--configs \"off forces-off on\"] [--bed lattice|random]" >&2
       exit 2 ;;
  esac
done
command -v granairFoam >/dev/null || { echo "bench/coupled: granairFoam not found in $GRANAIR_BUILD/bin" >&2; exit 1; }

work=${work:-$GRANAIR_BUILD/bench-coupled-np$np}
mkdir -p "$work"
rm -rf "$work"/[0-9]*_*_[0-9]*
case $bed in lattice|random) ;; *) echo "bench/coupled: --bed $bed: expected lattice or random" >&2; exit 2 ;; esac

# The random beds, settled once per size (not timed: they are the set-up).
beds=$(dirname "$work")/bench-coupled-beds
bed_args() { [ "$bed" = lattice ] && echo "--bed lattice" || echo "--bed random --bed-data $beds/$1/bed.data"; }
if [ "$bed" = random ]; then
  for n in $sizes; do
    if [ ! -f "$beds/$n/bed.data" ]; then
      rm -rf "$beds/$n"
      "$GRANAIR_PYTHON" "$here/make_case.py" --settle "$beds/$n" --particles "$n" --np "$np" > "$beds.$n.json"
      echo "bench/coupled: settling the random bed of $n particles on $np rank(s): $(cat "$beds.$n.json")"
      granair_liggghts "$beds/$n" "$np" -in in.settle -log log.liggghts -screen none
      mv "$beds.$n.json" "$beds/$n/settle.json"
    fi
  done
fi

echo "$(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, $bed bed, load average at start $(cut -d' ' -f1-3 /proc/loadavg)" \
  > "$work/machine.txt"
# Repeats outermost and the configurations of a size back to back, so they see the same load.
for r in $(seq 1 "$repeat"); do
  for n in $sizes; do
    for air in $configs; do
      dir="$work/${n}_${air}_${r}"
      rm -rf "$dir"
      "$GRANAIR_PYTHON" "$here/make_case.py" --out "$dir" --particles "$n" --air "$air" --steps "$steps" --np "$np" \
        $(bed_args "$n") > /dev/null
      touch "$dir/bench.foam"   # ParaView opens the case through this empty file
      granair_mesh "$dir"
      granair_decompose "$dir" "$np"
      granair_run "$dir" "$np" granairFoam
      echo "bench/coupled: $n particles, air $air, repeat $r: $(grep -h 'Coupling loop' "$dir/log/granairFoam.log")"
    done
  done
done
echo "load average at end $(cut -d' ' -f1-3 /proc/loadavg)" >> "$work/machine.txt"
"$GRANAIR_PYTHON" "$here/report.py" "$work" "$results" "$name"
