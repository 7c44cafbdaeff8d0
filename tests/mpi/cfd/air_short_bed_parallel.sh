#!/usr/bin/env bash
# The air solver's face fluxes and face pressure on processor faces: the
# 4-cell short bed (cases/ergun-packed-bed/study.py --short-bed, d = 225 um, Re 1 and
# 100) with both bed edges on processor faces (manual decomposition: the bed
# on rank 1, plenum and freeboard on rank 0) gives the serial p and U. Every
# written time is compared (every 25 steps, from the start-up transient to
# steady state), to 1e-8 relative: the fields are written with 10 significant
# digits and the linear solvers converge to 1e-12 absolute.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
work=$1
. "$here/../../../tools/foam-env.sh"
"$here/../../../cases/ergun-packed-bed/Allrun" --short-bed --out "$work/generate" \
    --diameters 225e-6 --bed-cells 4 --reynolds 1 100
for src in "$work"/generate/runs-short/*/; do
  name=$(basename "$src")
  for mode in serial parallel; do
    c="$work/$mode/$name"
    rm -rf "$c"; mkdir -p "$c"
    cp -r "$src/0" "$src/constant" "$src/system" "$c/"
    sed -i 's/writeInterval [0-9]*;/writeInterval 25;/' "$c/system/controlDict"
  done
  c="$work/parallel/$name"
  # 6 plenum, 4 bed, 6 freeboard cells (ergun-packed-bed/parameters.py)
  { echo 'FoamFile { version 2.0; format ascii; class labelList; object cellDecomposition; }'
    echo '16 ( 0 0 0 0 0 0 1 1 1 1 0 0 0 0 0 0 )'; } > "$c/constant/cellDecomposition"
  { echo 'FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }'
    echo 'numberOfSubdomains 2; method manual; coeffs { dataFile "cellDecomposition"; }'; } \
    > "$c/system/decomposeParDict"
  (cd "$work/serial/$name" && granairAirFoam > log.granairAirFoam 2>&1)
  (cd "$c" && decomposePar > log.decomposePar 2>&1 \
     && mpirun -np 2 granairAirFoam -parallel > log.granairAirFoam 2>&1 \
     && reconstructPar > log.reconstructPar 2>&1)
done
"$GRANAIR_PYTHON" - "$work" <<'PY'
import os, sys
from granair_cases.foam import read_field
work = sys.argv[1]
worst, ok = 0.0, True
for name in sorted(os.listdir(os.path.join(work, "serial"))):
    a, b = os.path.join(work, "serial", name), os.path.join(work, "parallel", name)
    times = sorted((t for t in os.listdir(a) if t not in ("0",) and t[0].isdigit()), key=float)
    if not times or sorted(t for t in os.listdir(b) if t[0].isdigit() and t != "0") != sorted(times):
        print(f"{name}: serial and parallel runs wrote different times"); ok = False; continue
    # 2 processor faces expected: the bed must sit on its own rank
    with open(os.path.join(b, "log.decomposePar")) as fh:
        if "Number of processor faces = 2" not in fh.read():
            print(f"{name}: the decomposition does not put both bed edges on processor faces"); ok = False
    for t in times:
        for f in ("p", "U"):
            x = read_field(os.path.join(a, t, f), 16)
            y = read_field(os.path.join(b, t, f), 16)
            if f == "U":
                x, y = [v[2] for v in x], [v[2] for v in y]
            scale = max(abs(v) for v in x)
            diff = max(abs(u - v) for u, v in zip(x, y)) / scale
            worst = max(worst, diff)
    print(f"{name}: {len(times)} times compared")
print(f"largest relative difference of p or U, serial vs 2 ranks: {worst:.2e} (tolerance 1e-8)")
sys.exit(0 if ok and worst <= 1e-8 else 1)
PY
