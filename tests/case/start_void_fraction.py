"""start_void_fraction.py CASE...: the start-time void fraction written by
granairFoam (0/voidfraction, or processor*/0/voidfraction) in the packed
column (tests/data/packed-column): 36 bed cells of 3 mm holding 27 spheres
of 1 mm each, eps = 1 - pi/6 (to 1e-12: sums of 27 volumes, written with 17
digits), and 9 empty cells above, eps = 1 exactly."""

import glob
import math
import os
import re
import sys


def internal_field(path):
    """Values of an ascii volScalarField's internalField (uniform or nonuniform)."""
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(([^)]*)\)", text)
    if m:
        return [float(v) for v in m.group(2).split()][: int(m.group(1))]
    m = re.search(r"internalField\s+uniform\s+(\S+);", text)
    owner = os.path.join(os.path.dirname(path), "..", "constant", "polyMesh", "owner")
    n = int(re.search(r"nCells:\s*(\d+)", open(owner, errors="replace").read()).group(1))
    return [float(m.group(1))] * n


def check(case):
    files = sorted(glob.glob(os.path.join(case, "processor*", "0", "voidfraction"))) or \
        [os.path.join(case, "0", "voidfraction")]
    eps = [e for f in files if os.path.exists(f) for e in internal_field(f)]
    bed = 1 - math.pi / 6
    n_bed = sum(abs(e - bed) <= 1e-12 for e in eps)
    n_free = sum(e == 1.0 for e in eps)
    print(f"start_void_fraction: {case}: {len(files)} file(s), {len(eps)} cells: "
          f"{n_bed} at 1 - pi/6, {n_free} at 1")
    return len(eps) == 45 and n_bed == 36 and n_free == 9


def main():
    ok = all([check(c) for c in sys.argv[1:]])
    if not ok:
        print("start_void_fraction: FAILED: expected 45 cells, 36 at 1 - pi/6 and 9 at 1")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
