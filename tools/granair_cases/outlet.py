"""What leaves a silo through its outlet, for the DEM-only studies that count
particles (two-slot-silo, orifice-arch): the per-particle records of a LIGGGHTS
counter, the flow rate in fixed windows, the settled fill's bulk density and a
Beverloo fit over several outlets.

    cols = read_records(paths, ncols)            rows of `massflow/mesh ... file` records, all files in turn
    rates = window_rates(t, m, t0, t_end, width) sum of m in each whole window from t0, over its width
    mean, sd = mean_sd(rates)
    rho_b, top = bulk_density(z, mass, area, d)  between 2 d and 2 d below the settled top
    ratio, stagnant, h = flow_pattern(fill, final, d, R, floor, surface, gone_z)   mass or funnel flow
    C, k = beverloo_fit(D, W, rho_b, d, ...)     Beverloo's C and k (in d) from outlets of widths D
"""
import math

import numpy as np

from . import CaseError


def read_records(paths, ncols):
    """The first `ncols` numbers of every record line (not blank, not #) of the files in
    `paths`, in order, as an (n, ncols) float array (LIGGGHTS massflow/mesh `file`
    output: id, time, diameter, position ...)."""
    rows = []
    for p in paths:
        try:
            with open(p) as fh:
                rows += [line.split()[:ncols] for line in fh if line.strip() and not line.startswith("#")]
        except OSError as e:
            raise CaseError(f"{p}: cannot read the particle records ({e.strerror})")
    try:
        return np.array(rows, dtype=float).reshape(-1, ncols)
    except ValueError:
        raise CaseError(f"{', '.join(paths)}: a record line with fewer than {ncols} numbers")


def window_rates(t, m, t0, t_end, width):
    """The rate in each whole window [t0 + k width, t0 + (k + 1) width) before t_end:
    the sum of m (mass or 1 per particle) of the records in it over the width."""
    n = int((t_end - t0) / width + 1e-9)
    return np.array([m[(t >= t0 + k * width) & (t < t0 + (k + 1) * width)].sum() / width for k in range(n)])


def mean_sd(rates):
    """(mean, sample standard deviation) of window rates; NaN where undefined."""
    return (float(rates.mean()) if rates.size else math.nan,
            float(rates.std(ddof=1)) if rates.size > 1 else math.nan)


def bulk_density(z, mass, area, d, k_top=200, floor=0.0, radius=0.0, min_height=None):
    """(bulk density [kg/m3], top [m]) of a settled fill: top is the mean height of the
    k_top highest centres (plus `radius`: the free surface over them); the density is
    the mass of the particles between 2 d above the floor and 2 d below that top over
    area x that height (clear of the floor's and the surface's loose layers). A fill
    too low for it stops, or gives NaN if min_height is given and the height is not
    above it."""
    top = float(np.mean(np.sort(z)[::-1][:k_top])) + radius
    z0, z1 = floor + 2 * d, top - 2 * d
    if min_height is not None and not z1 - z0 > min_height:
        return math.nan, top
    if z1 <= z0:
        raise CaseError(f"the settled fill is {top / d:.3g} d high: too low for a bulk density between 2 d and "
                        "2 d below its top")
    sel = (z > z0) & (z < z1)
    return float(mass[sel].sum() / (area * (z1 - z0))), top


def beverloo_fit(D, W, rho_b, d, n_exp=2.5, length=1.0, g=9.81):
    """C and k of Beverloo W = C rho_b sqrt(g) L (D - k d)^n (circular orifice: n = 5/2,
    L = 1; slit: n = 3/2, L its length) from outlets of widths D [m] with mass flows W
    [kg/s]: W^(1/n) is linear in D. rho_b: their mean bulk density. (NaN, NaN) with fewer
    than two outlets."""
    if len(D) < 2:
        return math.nan, math.nan
    y = np.asarray(W, float) ** (1 / n_exp)
    slope, icpt = np.polyfit(np.asarray(D, float), y, 1)
    return float(slope ** n_exp / (rho_b * math.sqrt(g) * length)), float(-icpt / slope / d)


def flow_pattern(fill, final, d, R, floor, surface, gone_z):
    """Flow-pattern measures of an axisymmetric silo from its particles at rest (`fill`)
    and at the end (`final`, dumps with id x y z mass): (the mean descent of the wall
    zone over the core's in the lowest third of the fill above `floor` (the hopper's
    top) and below `surface`, the mass fraction that moved less than d/2 (stagnant:
    dead zones; Jenike's mass flow moves every particle), the height of the highest
    stagnant particle at the wall). Wall zone: r > R - 2 d; core: r < 2 d; a particle
    that has left counts as descended to gone_z (the sink)."""
    where = {int(i): k for k, i in enumerate(final["id"])}
    idx = np.array([where.get(int(i), -1) for i in fill["id"]])
    gone = idx < 0
    zf = np.where(gone, gone_z, final["z"][np.maximum(idx, 0)])
    xf = np.where(gone, 0.0, final["x"][np.maximum(idx, 0)])
    yf = np.where(gone, 0.0, final["y"][np.maximum(idx, 0)])
    descent = fill["z"] - zf
    r0 = np.hypot(fill["x"], fill["y"])
    low = (fill["z"] > floor + d) & (fill["z"] < floor + (surface - floor) / 3)
    wall, core = low & (r0 > R - 2 * d), low & (r0 < 2 * d)
    ratio = float(descent[wall].mean() / descent[core].mean()) if wall.any() and core.any() and \
        descent[core].mean() > 0 else math.nan
    moved = np.sqrt((xf - fill["x"]) ** 2 + (yf - fill["y"]) ** 2 + descent ** 2)
    stagnant = ~gone & (moved < d / 2)
    at_wall = stagnant & (r0 > R - 2 * d)
    return (ratio, float(fill["mass"][stagnant].sum() / fill["mass"].sum()),
            float(fill["z"][at_wall].max()) if at_wall.any() else 0.0)
