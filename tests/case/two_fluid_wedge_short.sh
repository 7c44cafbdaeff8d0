#!/usr/bin/env bash
# The two-fluid wedge silo (cases/wedge-silo/twofluid.py, b = 10 mm, b/4 mesh, with
# air) for 10 ms in two chunks, the second by --resume. Guards two defects found in
# its mesh study (docs/two-fluid-model.md): the staircase wall faces subsetMesh
# exposes must start from defined coulombWallSlip values (they came out 1e5 on some
# faces, and the run remembered it), so the wall's valueFraction must be a fraction
# in [0, 1] on every face at every written time, 0 included; and a resumed chunk must reach its
# end time (one looped, never writing it). The driver must also run at all: a
# continuum option it did not set once stopped it before the mesh.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../../tools/case-lib.sh"
work=$1
rm -rf "$work"; mkdir -p "$work"
tf=$here/../../cases/wedge-silo/twofluid.py
"$GRANAIR_PYTHON" "$tf" --b 10 --air on --end 0.005 --chunk 0.005 --out "$work"
"$GRANAIR_PYTHON" "$tf" --b 10 --air on --end 0.01 --chunk 0.005 --resume --out "$work"
"$GRANAIR_PYTHON" - "$work/runs/b10_air" <<'PY'
import os, re, sys
run = sys.argv[1]
times = sorted((float(t), t) for t in os.listdir(run) if re.fullmatch(r"[0-9.e+-]+", t))
fails = []
if not times or abs(times[-1][0] - 0.01) > 1e-9:
    fails.append(f"written times {[t for _, t in times]}: expected the resumed chunk's end, 0.01")
for _, t in times:
    text = open(os.path.join(run, t, "U.particles")).read()
    walls = text[text.index("\n    walls"):]
    m = re.search(r"valueFraction\s+(uniform\s+(\S+);|nonuniform\s+List<scalar>\s*(\d+)\s*\(([^)]*)\))", walls)
    values = [float(m.group(2))] if m.group(2) else [float(x) for x in m.group(4).split()]
    bad = [f for f in values if not 0.0 <= f <= 1.0]
    print(f"t = {t}: walls valueFraction over {len(values)} faces in [{min(values):.3g}, {max(values):.3g}]")
    if bad:
        fails.append(f"t = {t}: {len(bad)} wall faces with valueFraction outside [0, 1] (e.g. {bad[0]:g})")
print("\n".join(fails) if fails else "two_fluid_wedge_short: all checks passed")
sys.exit(1 if fails else 0)
PY
# --shear-pressure-phi-max alphaMax: p_I's phiMax is the contact law's alphaMax, its span kept
"$GRANAIR_PYTHON" "$tf" --b 10 --air off --shear-pressure-phi-max alphaMax --setup-only --out "$work/phimax"
"$GRANAIR_PYTHON" - "$work/phimax/runs/b10_noair/constant/turbulenceProperties.particles" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
get = lambda k: float(re.search(r"^\s*" + k + r"\s+([0-9.eE+-]+);", text, re.M).group(1))
amax, pmax, pmin = get("alphaMax"), get("phiMax"), get("phiMin")
print(f"alphaMax {amax:g}, rheology phiMax {pmax:g}, phiMin {pmin:g}")
ok = abs(pmax - amax) < 1e-5 and abs(pmax - pmin - 0.189) < 1e-5
print("two_fluid_wedge_short: --shear-pressure-phi-max " + ("checks passed" if ok else "FAILED"))
sys.exit(0 if ok else 1)
PY
