#!/usr/bin/env bash
# LIGGGHTS' processor grid follows system/decomposeParDict (issue 13, item 9):
#   packed column, simple n (2 1 1), 2 ranks, no `processors` in the script:
#     LIGGGHTS uses 2 by 1 by 1 (its log says so) and granairFoam reports it;
#   the same with `processors 1 1 2` in the script: the script wins, and
#     granairFoam warns that the grids differ;
#   one 200 um particle in the 0.3 m column without `neigh_modify binsize`
#     (1 rank): the warning about ~4e7 neighbour bins.
# Usage: dem_processor_grid.sh WORKDIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$1
. "$here/../../tools/case-lib.sh"
rm -rf "$work"; mkdir -p "$work"
fails=0
expect() {   # file regex what
  if grep -Eq -- "$2" "$1"; then echo "  ok: $3"; else echo "  FAILED: $3 (/$2/ not in $1)"; fails=$((fails+1)); fi
}
one_step() { sed -i 's/endTime 0.001;/endTime 0.0005;/; s/endTime 0.1;/endTime 0.001;/' "$1/system/controlDict"; }

d=$work/matched; cp -r "$here/../data/packed-column" "$d"; one_step "$d"
granair_mesh "$d"; granair_decompose "$d" 2; granair_run "$d" 2 granairFoam
expect "$d/log/log.liggghts" "2 by 1 by 1 MPI processor grid" "LIGGGHTS splits 2 x 1 x 1 as decomposeParDict"
expect "$d/log/granairFoam.log" "DEM processor grid 2 x 1 x 1 \(decomposeParDict: simple n \(2 1 1\)\)" "the grid is reported"
if grep -q "WARNING" "$d/log/granairFoam.log"; then echo "  FAILED: a warning in the matched run"; fails=$((fails+1)); fi

d=$work/script_grid; cp -r "$here/../data/packed-column" "$d"; one_step "$d"
sed -i 's/^units           si/processors      1 1 2\nunits           si/' "$d/dem/in.liggghts"
granair_mesh "$d"; granair_decompose "$d" 2; granair_run "$d" 2 granairFoam
expect "$d/log/log.liggghts" "1 by 1 by 2 MPI processor grid" "the script's processors command wins"
expect "$d/log/granairFoam.log" "WARNING: LIGGGHTS splits its box 1 x 1 x 2 .* the CFD decomposition is 2 x 1 x 1" \
  "granairFoam warns that the grids differ"

d=$work/fine_bins; cp -r "$here/../data/particle-in-stream" "$d"; one_step "$d"
sed -i 's/ binsize 0.01 .*//' "$d/dem/in.liggghts"
granair_mesh "$d"; granair_run "$d" 1 granairFoam
expect "$d/log/granairFoam.log" "WARNING: LIGGGHTS' neighbour binning makes about [34]\.[0-9]e\+07 bins .* for 1 particle\(s\).*neigh_modify binsize" \
  "the absurd bin count is reported"

[ $fails -eq 0 ] && echo "dem_processor_grid: all checks passed" || { echo "dem_processor_grid: $fails check(s) failed"; exit 1; }
