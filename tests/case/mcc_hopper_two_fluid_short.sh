#!/usr/bin/env bash
# The two-fluid MCC hopper (cases/mcc-hopper/twofluid.py, with air, the default
# staircase wedge R_o/5) for 20 ms: the axisymmetric staircase meshes with the
# wedge silo's template (constraint patches wedge and empty), the cone is cut to
# a staircase, the fill holds 1000 g within a row, and the powder starts to
# leave: every row of its series finite, the outflow positive, the mass out
# equal to the rate's time integral the summary reports; the wedge patches are
# planar to OpenFOAM (no "not planar" warning in any log: the mesh's points are
# written at 15 digits, gc.two_fluid.run).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../tools/case-lib.sh"
work=$1
rm -rf "$work"; mkdir -p "$work"
"$GRANAIR_PYTHON" "$here/../../cases/mcc-hopper/twofluid.py" --air on --end 0.02 --chunk 0.01 --steady-from 0.01 \
  --out "$work"
"$GRANAIR_PYTHON" - "$work" <<'PY'
import os, sys
import numpy as np
import granair_cases as gc
out = sys.argv[1]
s = gc.series.read_keys(os.path.join(out, "air", "summary.txt"))
ts = gc.series.read_csv(os.path.join(out, "air", "timeseries.csv"))
fails = []
# the staircase's fill: the row boundary nearest to 1000 g (a row of the cylinder holds ~29 g)
if not abs(s["fill_g"] - 1000.0) <= 29.0 / 2:
    fails.append(f"fill {s['fill_g']:g} g: expected 1000 g within half a row (14.5 g)")
# 1181 cells: the free fall 5 x 5, the orifice column 5 x 52 and the annulus 20 x 52 less its 144 cells
# outside the cone (twofluid.py staircase(), R_o/5)
if int(s["cells"]) != 1181:
    fails.append(f"{int(s['cells'])} cells: expected 1181 (twofluid.py staircase(), R_o/5)")
for k, v in ts.items():
    if not np.all(np.isfinite(v)):
        fails.append(f"timeseries.csv column {k}: not all finite")
if not ts["t"][-1] >= 0.02 - 1e-9:
    fails.append(f"the series ends at t = {ts['t'][-1]:g} s: expected 0.02 s")
logs = os.path.join(out, "runs", "air", "log")
for name in sorted(os.listdir(logs)):
    with open(os.path.join(logs, name), errors="replace") as fh:
        n = fh.read().count("is not planar")
    if n:
        fails.append(f"log/{name}: {n} 'wedge patch is not planar' warnings: expected none")
if not s["W_kg_s"] > 0:
    fails.append(f"W = {s['W_kg_s']:g} kg/s over [0.01, 0.02] s: expected the powder leaving (> 0)")
print("\n".join(fails) if fails else f"mcc_hopper_two_fluid_short: W {s['W_kg_s']:.4g} kg/s, fill {s['fill_g']:.1f} g, "
      f"{int(s['cells'])} cells: all checks passed")
sys.exit(1 if fails else 0)
PY
