"""What leaves a silo through its outlet, for the DEM-only studies that count
particles (two-slot-silo, orifice-arch): the per-particle records of a LIGGGHTS
counter, the flow rate in fixed windows, the settled fill's bulk density and a
Beverloo fit over several outlets.

    cols = read_records(paths, ncols)            rows of `massflow/mesh ... file` records, all files in turn
    rates = window_rates(t, m, t0, t_end, width) sum of m in each whole window from t0, over its width
    mean, sd = mean_sd(rates)
    rho_b, top = bulk_density(z, mass, area, d)  between 2 d and 2 d below the settled top
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


def bulk_density(z, mass, area, d, k_top=200):
    """(bulk density [kg/m3], top [m]) of a settled fill: top is the mean height of the
    k_top highest centres; the density is the mass of the particles between 2 d above
    the floor and 2 d below that top over area x that height (clear of the floor's
    and the surface's loose layers)."""
    top = float(np.mean(np.sort(z)[::-1][:k_top]))
    z0, z1 = 2 * d, top - 2 * d
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
