"""restart_check.py A B [--tol REL] [--label TEXT]: run A (0 -> 2T in one go) and run B
(0 -> T, then a restart from T -> 2T) of tests/data/restart-column must agree
to round-off (issue 13, item 4):

  - time series (postProcessing/timeSeries.csv): the same rows, no row lost or
    repeated (same count, the same t in every row), every value within
    REL * max(|a|, |b|) + 1e-30 (REL default 1e-9);
  - air pressure at 2T (every processor*/<2T>/p or <2T>/p, ascii): the same
    within REL relative to the largest |p|;
  - particles at 2T (the last particle output, postProcessing/particles):
    the same ids, positions within REL times the box size (9 mm), velocities
    within REL relative to the largest |v|;
  - the HDF5 copy of the time series (timeSeries.h5, if h5py is there) has
    the same rows as the CSV, in both runs;
  - the particle accounting at the end of B's log equals A's.

Round-off: a restart changes the order of LIGGGHTS' atoms and neighbour lists
(and so of the contact-force sums) and of OpenFOAM's nothing; the runs are 8
coupling steps of 50 DEM steps, so differences stay near 1e-16 of the
values, far below REL.

tests/case/ranks.sh uses the same comparison for a serial run A and a run B
on more ranks (reconstructed, --label says so).
"""

import glob
import os
import re
import sys

from first_step_force import read_vtp


def series(case):
    rows = open(os.path.join(case, "postProcessing", "timeSeries.csv")).read().strip().split("\n")
    return rows[0], [[float(v) for v in r.split(",")] for r in rows[1:]]


def last_time_dir(case):
    base = os.path.join(case, "processor0") if os.path.isdir(os.path.join(case, "processor0")) else case
    times = []
    for name in os.listdir(base):
        try:
            times.append((float(name), name))
        except ValueError:
            pass
    return max(times)[1]


def pressure(case, tname):
    files = sorted(glob.glob(os.path.join(case, "processor*", tname, "p"))) or [os.path.join(case, tname, "p")]
    values = []
    for f in files:
        text = open(f).read()
        m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*\d+\s*\((.*?)\)", text, re.S)
        values += [float(v) for v in m.group(1).split()] if m else \
            [float(re.search(r"internalField\s+uniform\s+(\S+);", text).group(1))]
    return values


def particles(case):
    pvd = open(os.path.join(case, "postProcessing", "particles", "particles.pvd")).read()
    last = re.findall(r'file="(particles_\d+)\.pvtp"', pvd)[-1]
    t = float(re.findall(r'timestep="([^"]+)"', pvd)[-1])
    out = {}
    for piece in glob.glob(os.path.join(case, "postProcessing", "particles", last, "rank*.vtp")):
        a = read_vtp(piece)
        for i, x, v in zip(a["id"].ravel(), a["Points"], a["velocity"]):
            out[int(i)] = (tuple(x), tuple(v))
    return t, out


def balance(case):
    log = open(os.path.join(case, "log", "granairFoam.log")).read()
    block = log[log.rindex("DEM discharge balance"):]
    return [l.split()[-3] for l in block.split("\n")[1:6]]


def main():
    a, b = sys.argv[1], sys.argv[2]
    rel = float(sys.argv[sys.argv.index("--tol") + 1]) if "--tol" in sys.argv else 1e-9
    # --label: what B is (tests/case/ranks.sh compares NP ranks with 1 rank the same way)
    label = sys.argv[sys.argv.index("--label") + 1] if "--label" in sys.argv else "T + restart + T vs 2T"
    ok = True
    ha, ra = series(a)
    hb, rb = series(b)
    worst = 0.0
    if ha != hb or len(ra) != len(rb) or any(x[0] != y[0] for x, y in zip(ra, rb)):
        print(f"FAILED: time series differ in columns, rows ({len(ra)} vs {len(rb)}) or times")
        ok = False
    else:
        for x, y in zip(ra, rb):
            for u, w in zip(x, y):
                worst = max(worst, abs(u - w) / (max(abs(u), abs(w)) + 1e-30))
    print(f"restart_check ({label}): time series {len(ra)} rows each, same t; largest relative difference {worst:.2e}")
    ok &= worst <= rel

    tname = last_time_dir(a)
    pa, pb = pressure(a, tname), pressure(b, tname)
    scale = max(abs(v) for v in pa) or 1.0
    dp = max(abs(u - w) for u, w in zip(pa, pb)) / scale if len(pa) == len(pb) else float("inf")
    print(f"  air pressure at t = {tname}: {len(pa)} cells, largest difference {dp:.2e} of max|p| = {scale:.4g} Pa")
    ok &= dp <= rel

    ta, xa = particles(a)
    tb, xb = particles(b)
    dx = dv = float("inf")
    if ta == tb and set(xa) == set(xb):
        vmax = max(max(abs(c) for c in v) for _, v in xa.values()) or 1.0
        dx = max(max(abs(p - q) for p, q in zip(xa[i][0], xb[i][0])) for i in xa) / 9e-3
        dv = max(max(abs(p - q) for p, q in zip(xa[i][1], xb[i][1])) for i in xa) / vmax
    print(f"  particles at t = {ta} ({len(xa)} vs {len(xb)}, t = {tb}): largest position difference "
          f"{dx:.2e} of the box, velocity {dv:.2e} of max|v|")
    ok &= dx <= rel and dv <= rel

    try:
        import h5py
    except ImportError:
        h5py = None
    if h5py:
        for case, rows in ((a, ra), (b, rb)):
            with h5py.File(os.path.join(case, "postProcessing", "timeSeries.h5"), "r") as f:
                cols = f.attrs["columns"].decode().split(",") if isinstance(f.attrs["columns"], bytes) \
                    else str(f.attrs["columns"]).split(",")
                same = all(list(f[c][()]) == [r[k] for r in rows] for k, c in enumerate(cols))
                n = len(f[cols[0]])
            print(f"  {os.path.basename(case)}/postProcessing/timeSeries.h5: {n} rows, "
                  f"{'the same as' if same else 'DIFFERENT from'} the CSV")
            ok &= same

    ba, bb = balance(a), balance(b)
    print(f"  accounting (inserted, present, removed, lost, discharged): {ba} vs {bb}")
    ok &= ba == bb
    if not ok:
        print(f"FAILED: {label}: differences above {rel:g}")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
