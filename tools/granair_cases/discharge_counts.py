"""The particle counts of a steady (re-fed) discharge run in LIGGGHTS segments
(gc.chunks.liggghts) and the flow rate they give: the counts of every segment in one
table with the strays each segment deleted at its start counted as removed, the rate
as means over windows of whole counts, its steady value over an averaging window, and
Beverloo's k at a fixed C (cases/orifice-arch).

    c = read(case, n_segments, columns)     {column: int array} of post/counts_<k>.txt, "removed" + strays
    tw, rate = window_rates(t, n, per)     dN/dt: the change of a cumulative count over every `per` counts
    steady, se = steady_rate(t, n, tw, rate, t0)   slope from t0 on; standard error of the window means
    k = beverloo_k(W, D, d, rho_b, C, n_exp, length, g)   k of W = C rho_b sqrt(g) L (D - k d)^n

Why strays: a particle can cross the sink plane in a segment's last steps, after the
sink's last check; LIGGGHTS' restart keeps it, and the next segment deletes it at its
start and prints `granair stray <k>: <n> particles ...`; without it the accounting
(packed + re-inserted = present + removed) is short by those particles.
"""
import math
import os

import numpy as np

from . import CaseError, dem, series


def strays(case, k, tag="granair stray"):
    """The particles segment k deleted below the sink plane at its start: the last
    `<tag> <k>: <n> ...` line of log/segment_<k>.liggghts (0 without one)."""
    path = os.path.join(case, "log", f"segment_{k}.liggghts")
    try:
        with open(path) as fh:
            found = [ln for ln in fh if ln.startswith(f"{tag} {k}:")]
    except OSError:
        raise CaseError(f"{path}: missing (segment {k} did not run)")
    return int(found[-1].split(":")[1].split()[0]) if found else 0


def segment_starts(case, n_segments, columns):
    """The first step of each segment: the step of its restart (the previous one's last count)."""
    return [0] + [int(dem.read_print([os.path.join(case, "post", f"counts_{k}.txt")], columns)["step"][-1])
                  for k in range(1, n_segments)]


def read(case, n_segments, columns, tag="granair stray"):
    """The counts of a run's segments in order (post/counts_<k>.txt, `fix print` rows whose
    first column is "step") as ints, with "stray" (the strays deleted so far) added and
    added to "removed": segment k's counts carry the strays of segments 1..k."""
    paths = [os.path.join(case, "post", f"counts_{k}.txt") for k in range(1, n_segments + 1)]
    for k, path in enumerate(paths, 1):
        if not os.path.exists(path):
            raise CaseError(f"{path}: missing (segment {k} did not run)")
    out = {k: np.rint(x).astype(int) for k, x in dem.read_print(paths, columns).items()}
    stray = np.zeros(len(out["step"]), dtype=int)
    for k, s0 in enumerate(segment_starts(case, n_segments, columns), 1):
        stray[out["step"] > s0] += strays(case, k, tag)
    out["stray"] = stray
    out["removed"] = out["removed"] + stray
    return out


def window_rates(t, n, per):
    """(window midpoints, rates): the change of the cumulative count n(t) over windows of
    `per` counts from the first, divided by their length; a last partial window is left out."""
    edges = np.arange(0, len(t), per)
    return 0.5 * (t[edges[:-1]] + t[edges[1:]]), np.diff(n[edges]) / np.diff(t[edges])


def steady_rate(t, n, tw, rate, t0):
    """(the least-squares slope of n(t) from t0, the standard error of the window means
    whose midpoints are at t0 or later: sd / sqrt(m), NaN with fewer than two)."""
    steady = series.slope(t, n.astype(float), t0)
    sel = tw >= t0
    se = float(np.std(rate[sel], ddof=1) / math.sqrt(sel.sum())) if sel.sum() > 1 else math.nan
    return steady, se


def beverloo_k(W, D, d, rho_b, C=0.58, n_exp=2.5, length=1.0, g=9.81):
    """k of Beverloo W = C rho_b sqrt(g) L (D - k d)^n with C fixed, from one mass flow W
    [kg/s] through an outlet of width D: (D - (W / (C rho_b sqrt(g) L))^(1/n)) / d
    (circular: n = 5/2, L = 1; a slit: n = 3/2, L its length). How far a measured rate
    is from the usual k = 1..3 at the chosen C."""
    return (D - (W / (C * rho_b * math.sqrt(g) * length)) ** (1 / n_exp)) / d
