"""The strain of the particles in a control volume, from their own motion (the
convex-hull method of Rivera, Avila & Avila 2023, reference case D) and from a
CG velocity field (granairCG), so the two can be set side by side.

    eps, V, m = hull_strain(x0, u)       the hull's strain of particles at x0 displaced by u
    i1, i2, j2 = invariants(eps)         I1 = tr eps, I2 (principal 2 x 2 minors), J2 = I2 - I1^2/3
    rows = series(snapshots, r, h)       the hull strain of every interval between snapshots, a cylinder
    i1, j2 = mean_invariants(rows, t0, dt)   of the time-mean strain of those intervals from t0
    i1, j2, eps, n = cg_mean(f, inside, interval)   of the mean CG strain rate over the points inside x interval
    i1, j2, eps, n = cg_cylinder(case, dumps, ...)  granairCG on a chunked run's dumps, cg_mean over a cylinder

The hull method: the particles inside the volume at t_k; the triangles of their
convex hull (a Delaunay triangulation's boundary); over one interval each
triangle n moves by u_n, the mean displacement of its three particles, and

    eps = sym[ (1/V) sum_n u_n (x) n_n A_n ]

(n_n the outward unit normal, A_n the area, V the hull's volume): the divergence
theorem applied to the displacement field, exact for a homogeneous one (unit
test unit/strain). J2 = I2 - I1^2/3 is the reference's definition (= -(1/2) s:s
<= 0, s the deviator). scipy.spatial.Delaunay: Debian's python3-scipy.
"""
import math

import numpy as np

from . import CaseError, cg, dem
from .series import read_csv

COMPONENTS = ("xx", "yy", "zz", "xy", "yz", "xz")
# the columns of series(): interval, particles, hull volume, invariants, the strain's components
COLUMNS = ("step0", "step1", "grains", "grains_lost", "hull_volume_m3", "I1", "J2") + tuple(f"eps_{c}" for c in COMPONENTS)


def hull_strain(x0, u):
    """(eps 3 x 3, hull volume [m3], number of hull triangles) of particles at x0 (n, 3)
    displaced by u (n, 3)."""
    from scipy.spatial import Delaunay
    x0, u = np.asarray(x0, dtype=float), np.asarray(u, dtype=float)
    facets = Delaunay(x0).convex_hull                      # (m, 3) indices of the boundary triangles
    p = x0[facets]
    area = 0.5 * np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])       # n_n A_n, orientation still open
    centre = p.mean(axis=1)
    inside = x0.mean(axis=0)                               # a point inside a convex hull
    area *= np.sign(np.einsum("ij,ij->i", area, centre - inside))[:, None]   # outward
    volume = float(np.einsum("ij,ij->i", centre, area).sum() / 3.0)       # divergence theorem on x
    grad = np.einsum("ni,nj->ij", u[facets].mean(axis=1), area) / volume
    return 0.5 * (grad + grad.T), volume, len(facets)


def invariants(eps):
    """(I1, I2, J2) of a symmetric strain, J2 = I2 - I1^2/3."""
    i1 = float(np.trace(eps))
    i2 = float(eps[0, 0] * eps[1, 1] + eps[1, 1] * eps[2, 2] + eps[0, 0] * eps[2, 2]
               - eps[0, 1] ** 2 - eps[1, 2] ** 2 - eps[0, 2] ** 2)
    return i1, i2, i2 - i1 * i1 / 3.0


def tensor(xx, yy, zz, xy, yz, xz):
    """The symmetric 3 x 3 tensor of six components (the order of COMPONENTS)."""
    return np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])


def in_cylinder(x, radius, height):
    """Mask of points inside the cylinder r < radius, 0 < z < height (its axis the z axis)."""
    return (np.hypot(x[:, 0], x[:, 1]) < radius) & (x[:, 2] > 0.0) & (x[:, 2] < height)


def series(snapshots, radius, height, min_grains=20):
    """The hull strain of every interval between consecutive snapshots [(step, columns)]
    (columns id, x, y, z) of the particles in the cylinder in_cylinder(radius, height)
    at the interval's start: rows of COLUMNS. Particles of the volume at step0 missing at
    step1 (they left the dumped region) are counted and left out; an interval with
    fewer than min_grains left is skipped."""
    rows = []
    for (s0, a), (s1, b) in zip(snapshots[:-1], snapshots[1:]):
        if not len(a["id"]):
            continue
        x0 = np.column_stack([a["x"], a["y"], a["z"]])
        sel = in_cylinder(x0, radius, height)
        where = {int(i): k for k, i in enumerate(b["id"])}
        ids = a["id"][sel].astype(int)
        keep = np.array([i in where for i in ids], dtype=bool)
        if keep.sum() < min_grains:
            continue
        j = np.array([where[i] for i in ids[keep]])
        x1 = np.column_stack([b["x"][j], b["y"][j], b["z"][j]])
        eps, vol, _ = hull_strain(x0[sel][keep], x1 - x0[sel][keep])
        i1, _, j2 = invariants(eps)
        rows.append((s0, s1, int(keep.sum()), int((~keep).sum()), vol, i1, j2, eps[0, 0], eps[1, 1], eps[2, 2],
                     eps[0, 1], eps[1, 2], eps[0, 2]))
    return rows


def mean_invariants(rows, t0, dt):
    """(I1, J2) of the time mean of the interval strains of series() that start at t0 or
    later (dt: the time of one step); NaN without one."""
    st = np.array(rows).reshape(-1, len(COLUMNS))
    st = st[st[:, 0] * dt >= t0 - 1e-9]
    if not len(st):
        return math.nan, math.nan
    xx, yy, zz, xy, yz, xz = st[:, 7:13].mean(axis=0)
    i1, _, j2 = invariants(tensor(xx, yy, zz, xy, yz, xz))
    return i1, j2


def cg_mean(f, inside, interval, where="the CG fields"):
    """(I1, J2, eps 3 x 3, points used) of the strain over one interval from a CG field:
    the mean of granairCG's strain_rate_<c> columns of f (a dict of arrays) over the
    points of the mask `inside` where all six are finite, times the interval [s]. It is
    the Eulerian rate at fixed points; the hull's the Lagrangian strain of the particles
    that were inside: set beside mean_invariants they compare the invariants of a mean
    strain with those of a mean strain."""
    d = np.array([f[f"strain_rate_{c}"] for c in COMPONENTS])
    ok = inside & np.all(np.isfinite(d), axis=0)
    if not ok.any():
        raise CaseError(f"{where}: no grid point inside the control volume with a strain rate")
    m = d[:, ok].mean(axis=1) * interval
    eps = tensor(*m)
    i1, _, j2 = invariants(eps)
    return i1, j2, eps, int(ok.sum())


def cg_cylinder(case, dumps, stem, dt, radius, height, width, spacing, t0, t1, interval):
    """cg_mean over the cylinder in_cylinder(radius, height) of granairCG's fields of the
    particle dumps `dumps` (the chunks of a run: merged into <stem>_particles.dump, each
    step once) on an XYZ grid of `spacing` over the cylinder's bounding box, Gaussian
    kernel of `width`, time-averaged over [t0, t1] (dt: the time of one step). The
    dumps hold id, position, velocity, radius and mass of the particles within the
    kernel's reach of the cylinder."""
    merged, _ = dem.merge_dumps(dumps, stem + "_particles.dump")
    r, h = radius, height
    cg.run(case, stem, {"particles": merged, "dt": dt, "coordinates": "XYZ", "kernel": "gauss", "width": width,
                        "spacing": spacing, "min": [-r, -r, "0"], "max": [r, r, h], "from": t0, "to": t1,
                        "format": "csv"}, log="granairCG")
    f = read_csv(stem + ".csv")
    return cg_mean(f, np.hypot(f["x"], f["y"]) < r, interval, f"{stem}.csv")


def steady(rows, dt, t0, csv=None):
    """A run's series() rows summed up over its steady window (intervals from t0 on):
    strain_intervals, the time mean and SD of I1 and J2 of the interval strains, the
    mean count of particles in the volume, those lost over all intervals, and I1, J2 of
    the time-mean strain (mean_invariants); the rows written to `csv` (times in s) if
    given. NaN means without an interval."""
    st = np.array(rows).reshape(-1, len(COLUMNS))
    if csv:
        from .series import write_csv
        write_csv(csv, [("t0", st[:, 0] * dt), ("t1", st[:, 1] * dt)] +
                  [(c, st[:, i]) for i, c in enumerate(COLUMNS[2:], 2)], fmt="{:.6g}")
    ss = st[st[:, 0] * dt >= t0 - 1e-9]
    stat = lambda col, f: float(f(ss[:, col])) if len(ss) else math.nan          # noqa: E731
    i1, j2 = mean_invariants(rows, t0, dt)
    return dict(strain_intervals=len(ss), I1_mean=stat(5, np.mean), J2_mean=stat(6, np.mean),
                I1_sd_time=stat(5, np.std), J2_sd_time=stat(6, np.std), cv_grains_mean=stat(2, np.mean),
                cv_grains_lost=int(st[:, 3].sum()) if len(st) else 0, I1_of_mean=i1, J2_of_mean=j2)


def check_hull(c, radius, seed=7):
    """A study's check of the hull method (gc.checks.Checks c): 300 points in a cube of
    half-width radius under a homogeneous deformation (and a translation), for which the
    surface integral is exact."""
    rng = np.random.default_rng(seed)
    x = rng.uniform(-radius, radius, (300, 3))
    grad = np.array([[0.010, 0.020, 0.0], [0.0, -0.030, 0.005], [0.001, 0.0, 0.020]])
    eps = hull_strain(x, x @ grad.T + 0.003)[0]
    c.near("convex-hull strain of a homogeneous deformation: largest error of a component", float(
        np.abs(eps - 0.5 * (grad + grad.T)).max()), 0.0, 1e-12, "the surface integral is exact for a linear "
        "displacement field (any translation drops out)")
