"""Two-dimensional CG fields (granairCG `--coordinates RZ` or `XZ`) kept on their grid:
written as a flat CSV a study commits, read back as grids, and the density's
integral over the grid (the mass check of every CG study).

    write(path, fields, axis)          fields: {axis: a, "z": z, name: grid[len(a), len(z)], ...}
    fields = read(path, axis)          the same dict back
    m = mass(f, depth=None)            int rho dV of a gc.cg.read() result: RZ 2 pi r dr dz, XZ dx dz depth
    grid_kg, particles_kg = logged_mass(log)   what granairCG's log says of the same window
"""
import math
import re

import numpy as np

from . import CaseError, series


def write(path, fields, axis):
    """A flat CSV of 2-D fields: columns axis, z, then every other field, one row per grid
    point (axis outer, z inner), 6 significant digits."""
    A, Z = np.meshgrid(fields[axis], fields["z"], indexing="ij")
    cols = [(axis, A.ravel()), ("z", Z.ravel())] + [(k, fields[k].ravel()) for k in fields if k not in (axis, "z")]
    series.write_csv(path, cols, fmt="{:.6g}")
    return path


def read(path, axis):
    """write()'s CSV back: {axis: sorted values, "z": sorted values, name: grid}."""
    t = series.read_csv(path)
    a, z = np.unique(t[axis]), np.unique(t["z"])
    return dict({axis: a, "z": z}, **{k: v.reshape(len(a), len(z)) for k, v in t.items() if k not in (axis, "z")})


def mass(f, depth=None):
    """(int rho dV, the plain midpoint sum) of the density of a gc.cg.read() result on its
    grid. RZ: sum of rho 2 pi r dr dz less the midpoint rule's end term at the axis: the
    integrand 2 pi r rho(r) has the slope 2 pi rho(0) there, so the rule exceeds the
    integral by (dr^2 / 24) 2 pi rho(0) (Euler-Maclaurin; rho(0) ~ the first ring's
    density, the next term ~3 % of this one): 0.2 % for dr = d in a silo of radius 6 d.
    XZ: sum of rho dx dz x depth (the window's extent in y)."""
    z = f["z"]
    dz = z[1] - z[0]
    if "r" in f["axes"]:
        r = f["r"]
        dr = r[1] - r[0]
        raw = float(np.sum(f["density"] * (2 * math.pi * r * dr)[:, None]) * dz)
        return raw - float(dr * dr / 24 * 2 * math.pi * np.sum(f["density"][0, :]) * dz), raw
    if depth is None:
        raise CaseError("cg_grids.mass: an XZ grid needs the window's depth in y")
    x = f["x"]
    raw = float(np.sum(f["density"]) * (x[1] - x[0]) * dz * depth)
    return raw, raw


def logged_mass(log):
    """(mass on the grid, particle mass in the window) [kg] from a granairCG log."""
    try:
        with open(log) as fh:
            m = re.search(r"mass on the grid (\S+) kg, particle mass in the window (\S+) kg", fh.read())
    except OSError as e:
        raise CaseError(f"{log}: cannot read ({e.strerror})")
    if not m:
        raise CaseError(f"{log}: no 'mass on the grid' line (did granairCG finish?)")
    return float(m.group(1)), float(m.group(2))
