"""The strain over the outlet from the CG velocity field (granairCG,
docs/cg-fields.md), beside the convex-hull strain of strain.py.

The grains around the control volume (post/cv_*.dump: id x y z vx vy vz
radius mass every CV_EVERY) are coarse-grained on a Cartesian grid over the
control volume's bounding box with a Gaussian kernel, time-averaged over the
steady window; the strain rate D = sym(grad V) (granairCG's central
differences of momentum and density) is averaged over the grid points inside
the cylinder, and eps = <D> CV_EVERY is the strain of one interval, the
interval of the hull method. Its invariants are set beside the hull's of the
time-mean strain (the mean of the hull's interval strains): both are
invariants of a mean strain, so they compare like with like."""
import glob
import math
import os
import shutil

import numpy as np

import granair_cases as gc
import parameters as P
import strain

COMPONENTS = ("xx", "yy", "zz", "xy", "yz", "xz")


def run(run_dir, v, t0, t1):
    """(I1, J2, eps 3 x 3, grid points used) of the CG strain per CV_EVERY over
    [t0, t1]; None (with a message) when granairCG is not built."""
    exe = shutil.which("granairCG")
    if exe is None:
        print(f"corn-silo: granairCG not found (./granair build): no CG strain for {run_dir}", flush=True)
        return None
    post = os.path.join(run_dir, "post")
    merged, n = gc.dem.merge_dumps(sorted(glob.glob(os.path.join(post, "cv_*.dump"))), os.path.join(post, "cv_all.dump"))
    r, h = P.CV_RADIUS, P.CV_HEIGHT
    stem = os.path.join(post, "cg_cv")
    gc.cg.run(run_dir, stem, {"particles": merged, "dt": v["DT"], "coordinates": "XYZ", "kernel": "gauss",
                              "width": P.CG_WIDTH, "spacing": P.CG_SPACING, "min": [-r, -r, "0"], "max": [r, r, h],
                              "from": t0, "to": t1, "format": "csv"}, log="granairCG")
    f = gc.series.read_csv(stem + ".csv")
    inside = np.hypot(f["x"], f["y"]) < r
    d = np.array([f[f"strain_rate_{c}"] for c in COMPONENTS])
    ok = inside & np.all(np.isfinite(d), axis=0)
    if not ok.any():
        raise gc.CaseError(f"{stem}.csv: no grid point inside the control volume with a strain rate")
    m = d[:, ok].mean(axis=1) * P.CV_EVERY
    eps = np.array([[m[0], m[3], m[5]], [m[3], m[1], m[4]], [m[5], m[4], m[2]]])
    i1, _, j2 = strain.invariants(eps)
    return i1, j2, eps, int(ok.sum())


def hull_mean(rows, t0, dt):
    """(I1, J2) of the time mean of the hull's interval strains from t0 on (rows of strain.series)."""
    st = np.array(rows).reshape(-1, 13)
    st = st[st[:, 0] * dt >= t0 - 1e-9]
    if not len(st):
        return math.nan, math.nan
    xx, yy, zz, xy, yz, xz = st[:, 7:13].mean(axis=0)
    i1, _, j2 = strain.invariants(np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]]))
    return i1, j2
