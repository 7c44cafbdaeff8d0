#!/usr/bin/env bash
# The air solver gives the same answer on 2 ranks as on 1: the Ergun bed at
# two velocities, decomposed along the column, pressure drop equal to 1e-9
# relative (linear solvers converge to 1e-12 absolute; the only difference is
# summation order across ranks).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$1
. "$here/../../../tools/foam-env.sh"
allrun=$here/../../../cases/ergun-packed-bed/Allrun
sel=(--laws ErgunGidaspow DiFelice --diameters 225e-6 --reynolds 1 100)
"$allrun" --out "$work/np1" "${sel[@]}" --np 1
"$allrun" --out "$work/np2" "${sel[@]}" --np 2
"$GRANAIR_PYTHON" - "$work/np1/ergun.csv" "$work/np2/ergun.csv" <<'PY'
import csv, sys
a = list(csv.DictReader(open(sys.argv[1])))
b = list(csv.DictReader(open(sys.argv[2])))
assert len(a) == len(b) == 4, (len(a), len(b))
worst = 0.0
for ra, rb in zip(a, b):
    x, y = float(ra["dpL_sim_Pa_m"]), float(rb["dpL_sim_Pa_m"])
    worst = max(worst, abs(x - y) / abs(x))
    print(f"{ra['law']:14s} Re={ra['Re']:>4s}: dp/L serial {x:.12e}  2 ranks {y:.12e}")
print(f"largest relative difference {worst:.2e} (tolerance 1e-9)")
sys.exit(0 if worst <= 1e-9 else 1)
PY
