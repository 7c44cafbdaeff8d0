#!/usr/bin/env bash
# More ranks (issue 22): the restart column (tests/data/restart-column: 972
# spheres, air up through the bed, a sink deleting the bottom layer, 8
# coupling steps) on NP ranks with DEM and CFD decompositions that differ
# equals the serial run to round-off: time series, air pressure (reconstructed),
# particles, accounting (restart_check.py --label). Both runs solve p and U to
# 1e-14 instead of the case's 1e-8: a decomposition changes the linear
# solvers' path (DIC preconditioning per subdomain), so at 1e-8 the runs
# differ by the tolerance (measured 2e-5 relative on the near-zero outlet
# dp/dz at the open top, 8e-9 of max|p|), not by round-off.
#   NP = 3: CFD simple (3 1 1)  DEM processors 1 1 3
#   NP = 4: CFD simple (2 2 1)  DEM processors 1 1 4
#   NP = 8: CFD simple (2 2 2)  DEM processors 1 1 8 (slabs thinner than two diameters)
# Usage: ranks.sh WORKDIR NP [TOL]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$1 np=$2 tol=${3:-1e-9}
. "$here/../../tools/case-lib.sh"
src=$here/../data/restart-column
case $np in
  3) cfd="3 1 1" ;;
  4) cfd="2 2 1" ;;
  8) cfd="2 2 2" ;;
  *) echo "ranks.sh: NP must be 3, 4 or 8" >&2; exit 2 ;;
esac
rm -rf "$work"; mkdir -p "$work"
serial=$work/np1 par=$work/np$np
cp -r "$src" "$serial"; cp -r "$src" "$par"
for d in "$serial" "$par"; do sed -i 's/tolerance 1e-8;/tolerance 1e-14;/g' "$d/system/fvSolution"; done
grep -q "tolerance 1e-14;" "$serial/system/fvSolution" || { echo "ranks.sh: could not tighten the solver tolerance" >&2; exit 1; }
sed -i "s/numberOfSubdomains 2;/numberOfSubdomains $np;/; s/n (2 1 1);/n ($cfd);/" "$par/system/decomposeParDict"
sed -i "s/^units           si$/units           si\nprocessors      1 1 $np/" "$par/dem/in.liggghts"
grep -q "^processors      1 1 $np" "$par/dem/in.liggghts" || { echo "ranks.sh: could not set the DEM grid" >&2; exit 1; }
for d in "$serial" "$par"; do granair_mesh "$d"; done
granair_decompose "$par" "$np"
granair_run "$serial" 1 granairFoam
granair_run "$par" "$np" granairFoam
grep -q "DEM processor grid 1 x 1 x $np" "$par/log/granairFoam.log" \
  || { echo "ranks.sh: the DEM did not run on the 1 x 1 x $np grid:"; grep -i "processor grid" "$par/log/granairFoam.log"; exit 1; }
( cd "$par" && reconstructPar -latestTime > log/reconstructPar.log 2>&1 ) \
  || { tail -20 "$par/log/reconstructPar.log"; exit 1; }
mkdir "$par/decomposed" && mv "$par"/processor* "$par/decomposed/"
"$GRANAIR_PYTHON" "$here/restart_check.py" "$serial" "$par" --tol "$tol" --label "$np ranks (CFD ($cfd), DEM 1 x 1 x $np) vs 1 rank"
