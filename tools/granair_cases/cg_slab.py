"""CG fields of a thin slab silo (a box between four plane walls, x across, y through
the depth, z up), depth averaged on an XZ grid by granairCG, and the fields Fullard et
al. (2019) derive from them (cases/two-slot-silo). Why here: the granairCG command of
such a silo, the derived shear rate, inertial number and viscosity, the averages over
boxes of the grid and the mass check do not depend on the openings in its floor.

    cpu, steps = run(case, stem, box, lo, hi, dt, width, cutoff, spacing, log, last_only=False)
    gd, i_num, eta = fullard(f, d, rho_p)      from a read_csv of granairCG's XZ output
    means = box_mean(arrays, sel)              {name: nanmean over the points sel}
    cg_kg, dump_kg, cpu = mass_check(case, box, z_range, dt, width, cutoff, spacing, steps[-1])

box = (xlo, xhi, depth): the side walls at x = xlo, xhi, the front and back at y = 0, depth.
The dumps are granairCG's three inputs, post/cg/particles_<step>.dump, pairs_*, walls_*.
"""
import os

import numpy as np

from . import CaseError, cg, cg_grids, dem

DUMPS = "post/cg"


def run(case, stem, box, lo, hi, dt, width, cutoff, spacing, log, last_only=False):
    """granairCG over the case's CG dumps into <case>/cg/<stem>.csv on the window lo..hi
    (XZ, Gaussian of `width`, `cutoff` widths, grid `spacing`), the four walls as planes
    and the walls' own contacts; last_only: the last snapshot alone. Returns (CPU seconds,
    the snapshots' steps)."""
    xlo, xhi, depth = box
    steps = [s for s, _ in dem.numbered(os.path.join(case, DUMPS, "particles_*.dump"))]
    if not steps:
        raise CaseError(f"{os.path.join(case, DUMPS)}: no CG snapshots (particles_*.dump)")
    opts = [("particles", f"{DUMPS}/particles_*.dump"), ("pairs", f"{DUMPS}/pairs_*.dump"),
            ("walls", f"{DUMPS}/walls_*.dump"), ("plane-wall", ["wxlo", "x", xlo]),
            ("plane-wall", ["wxhi", "x", xhi]), ("plane-wall", ["wfront", "y", 0]),
            ("plane-wall", ["wback", "y", depth]), ("dt", dt), ("coordinates", "XZ"),
            ("kernel", "gauss"), ("width", width), ("cutoff", cutoff),
            ("spacing", spacing), ("min", list(lo)), ("max", list(hi)), ("threads", 1), ("format", "csv")]
    if last_only:
        t = steps[-1] * dt
        opts += [("from", t * (1 - 1e-9)), ("to", t * (1 + 1e-9))]
    return cg.run(case, os.path.join("cg", stem), opts, log), steps


def fullard(f, d, rho_p):
    """(shear rate, inertial number, apparent viscosity) as Fullard et al. define them
    from an XZ field f (gc.series.read_csv of granairCG's CSV): gamma_dot =
    sqrt((dx vz + dz vx)^2 + (dx vx - dz vz)^2), I = d gamma_dot sqrt(rho_p / P),
    eta = tau / gamma_dot (tau granairCG's shear_stress); NaN where gamma_dot or P is not
    positive."""
    gd = np.sqrt((f["velocity_gradient_xz"] + f["velocity_gradient_zx"]) ** 2
                 + (f["velocity_gradient_xx"] - f["velocity_gradient_zz"]) ** 2)
    p = f["pressure"]
    eta = np.where(gd > 0, f["shear_stress"] / np.where(gd > 0, gd, 1), np.nan)
    i_num = np.where(p > 0, d * gd * np.sqrt(rho_p / np.where(p > 0, p, 1)), np.nan)
    return gd, i_num, eta


def box_mean(arrays, sel):
    """{name: the mean of the finite values at the points sel} of [(name, array)]."""
    return {k: float(np.nanmean(a[sel])) for k, a in arrays}


def mass_check(case, box, z_range, dt, width, cutoff, spacing, step, log="granairCG_mass"):
    """The last snapshot's CG density integrated over a grid that holds every kernel
    (the box and z_range widened by cutoff widths on each side: cg/mass.csv) against the
    mass of that snapshot's particles between the front and back walls: (CG kg, dump kg,
    CPU s)."""
    xlo, xhi, depth = box
    m = 3 * cutoff * width
    lo, hi = (xlo - m, 0.0, z_range[0] - m), (xhi + m, depth, z_range[1] + m)
    cpu = run(case, "mass", box, lo, hi, dt, width, cutoff, spacing, log, last_only=True)[0]
    grid, _ = cg_grids.mass(cg.read(os.path.join(case, "cg", "mass.csv")), depth=depth)
    snap = dem.read_dump(os.path.join(case, DUMPS, f"particles_{step}.dump"))
    return grid, float(snap["mass"][(snap["y"] >= 0) & (snap["y"] <= depth)].sum()), cpu
