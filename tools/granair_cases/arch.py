"""The free-fall arch above an outlet from 2-D CG fields (RZ about the outlet's axis or XZ
across a slit), three ways, each a surface z(r) over |r| <= fit_r R fitted with the
paraboloid z / R = alpha (1 - (r / R)^2) (cases/orifice-arch, README "The free-fall arch").

    r, zc = kinetic_max(f, axis, R)          where P_kinetic peaks along z at each r (the reference's arch)
    r, zf = free_fall(f, axis, R, g)         v_z(r, 0)^2 / (2 g): the classical free-fall height
    r, zs = contact_vanish(f, axis, R, level)  coming down, where P_contact falls to `level`
    alpha, se = paraboloid(r, z, R)          least squares through the origin in 1 - (r/R)^2
    se = block_se(alphas)                    the standard error of alpha over blocks of snapshots

f: a dict of grids [i_axis, i_z] with the axis values (f[axis], f["z"], z ascending on a
uniform grid) and the fields p_kinetic, p_contact, velocity_z (gc.cg_runs.reduce). The
monolayer's x is folded: every point is at |x|. Columns with no answer are left out.
"""
import math

import numpy as np

from . import fits


def kinetic_max(f, axis, R, z_range=(-1.0, 2.0), fit_r=0.9):
    """z_c(r): the maximum of f["p_kinetic"] along z within z_range x R at each |r| <= fit_r R,
    refined by the parabola through it and its neighbours. The range stops 3 grid spacings
    below the window's top (a "maximum" there is the window's edge); a column whose maximum
    is the range's first or last point, or with a non-finite value, has no arch point."""
    z, pk = f["z"], f["p_kinetic"]
    top = min(z_range[1] * R, z[-1] - 3 * (z[1] - z[0]))
    sel_z = np.nonzero((z >= z_range[0] * R - 1e-9) & (z <= top + 1e-9))[0]
    rs, zc = [], []
    for i, r in enumerate(f[axis]):
        if abs(r) > fit_r * R:
            continue
        col = pk[i, sel_z]
        if not np.all(np.isfinite(col)):
            continue
        j = int(np.argmax(col))
        if j == 0 or j == len(col) - 1:
            continue
        p0, p1, p2 = col[j - 1], col[j], col[j + 1]
        den = p0 - 2 * p1 + p2
        dz = z[sel_z[1]] - z[sel_z[0]]
        shift = 0.5 * dz * (p0 - p2) / den if den < 0 else 0.0
        rs.append(abs(r))
        zc.append(z[sel_z[j]] + shift)
    return np.array(rs), np.array(zc)


def free_fall(f, axis, R, g=9.81, fit_r=0.9):
    """z_ff(r) = v_z(r, 0)^2 / (2 g) at each |r| <= fit_r R (v_z on the grid row nearest
    z = 0): the height from which a particle released at rest crosses the orifice plane
    as fast as measured."""
    j = int(np.argmin(abs(f["z"])))
    sel = (abs(f[axis]) <= fit_r * R) & np.isfinite(f["velocity_z"][:, j])
    return abs(f[axis][sel]), f["velocity_z"][sel, j] ** 2 / (2 * g)


def contact_vanish(f, axis, R, level, z_range=(-1.0, 2.0), fit_r=0.9):
    """Where the contact stress 'vanishes' at each |r| <= fit_r R: coming down from
    z_range[1] R, the first z where f["p_contact"] falls below `level` (linear between grid
    points; the contact stress does not vanish above an outlet, so any level is a choice);
    columns that stay above it to the range's bottom are left out."""
    z, pc = f["z"], f["p_contact"]
    js = [j for j in np.argsort(z)[::-1] if z_range[0] * R - 1e-9 <= z[j] <= z_range[1] * R + 1e-9]
    rs, zs = [], []
    for i, r in enumerate(f[axis]):
        if abs(r) > fit_r * R:
            continue
        for j0, j1 in zip(js, js[1:]):
            if pc[i, j0] >= level > pc[i, j1]:
                rs.append(abs(r))
                zs.append(z[j0] + (z[j1] - z[j0]) * (pc[i, j0] - level) / (pc[i, j0] - pc[i, j1]))
                break
    return np.array(rs), np.array(zs)


def paraboloid(r, z, R):
    """alpha of z / R = alpha (1 - (r / R)^2) (least squares) and its standard error;
    (NaN, NaN) with fewer than two points."""
    return fits.through_origin(1 - (r / R) ** 2, z / R)


def block_se(values):
    """The standard error of the mean of per-block values (sd / sqrt(n)): what the scatter
    between consecutive blocks of a time window says of the whole window's value. NaN with
    fewer than two blocks or a non-finite one."""
    v = np.array(values)
    return float(np.std(v, ddof=1) / math.sqrt(len(v))) if len(v) >= 2 and np.all(np.isfinite(v)) else math.nan
