"""The particle counts of a steady (re-fed) discharge run in LIGGGHTS segments
(gc.chunks.liggghts) and the flow rate they give: the counts of every segment in one
table with the strays each segment deleted at its start counted as removed, the rate
as means over windows of whole counts, its steady value over an averaging window, and
Beverloo's k at a fixed C (cases/orifice-arch).

    st = steps(dt, unit, every, snapshot, segment, transient, average)   step counts on one count grid
    segments = plan(total, seg, snap, avg_from, cg_on)   gc.chunks.liggghts' segments: nsteps, cg_every
    c = read(case, n_segments, columns)     {column: int array} of post/counts_<k>.txt, "removed" + strays
    acc = accounting(c, packed)             the balance at every count and the end's totals
    check_accounting(checks, name, acc)     exact at every count and at the end; fed and drained
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


def steps(dt, unit, every, snapshot, segment, transient, average):
    """The step counts of a segmented run with times in units of `unit` [s] (t_d): between
    counts (`every`), CG snapshots, segments, the start of the averaging window (after
    `transient`) and the run's end (`average` later). Each is a whole multiple of the one
    before (snapshots of counts, segments and the window of snapshots), so every snapshot
    and every segment's end is a count: {print, snap, seg, avg_from, total}."""
    n_print = max(1, round(every * unit / dt))
    n_snap = n_print * max(1, round(snapshot / every))
    n_seg = n_snap * max(1, round(segment / snapshot))
    n_from = n_snap * round(transient / snapshot)
    return dict(print=n_print, snap=n_snap, seg=n_seg, avg_from=n_from, total=n_from + n_snap * round(average / snapshot))


def plan(total, seg, snap, avg_from, cg_on=True):
    """The segments of a run of `total` steps in pieces of `seg` (the last shorter):
    [{nsteps, cg_every}], CG snapshots every `snap` steps in the segments that end after
    `avg_from` (the averaging window; none with cg_on false), 0 in the others."""
    out, s0 = [], 0
    while s0 < total:
        s1 = min(s0 + seg, total)
        out.append(dict(nsteps=s1 - s0, cg_every=snap if cg_on and s1 > avg_from else 0))
        s0 = s1
    return out


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


def accounting(c, packed):
    """A re-fed run's particle accounting from read()'s counts (columns atoms, fed, removed,
    below, stray) and the particles packed at its start: balance = packed + fed - atoms -
    removed at every count (0: no particle made or lost), and of the last count: last
    (each column), inserted = packed + fed, in_silo = atoms - below, discharged = removed
    + below."""
    last = {k: int(x[-1]) for k, x in c.items()}
    return dict(balance=packed + c["fed"] - c["atoms"] - c["removed"], last=last, packed=packed,
                inserted=packed + last["fed"], in_silo=last["atoms"] - last["below"],
                discharged=last["removed"] + last["below"])


def check_accounting(checks, name, acc):
    """The accounting checks of one run (a gc.checks.Checks): balanced exactly at every
    count and at the end (inserted = in the silo + below the floor + removed), and
    particles both re-inserted and removed (the flow ran and was fed)."""
    last = acc["last"]
    checks.exact(f"{name}: packed + re-inserted - present - removed at every count ({len(acc['balance'])} counts)",
                 int(np.max(np.abs(acc["balance"]))), 0, "integer counts: no particle made or lost")
    checks.exact(f"{name}: inserted = in silo + below the floor + removed at the end",
                 acc["inserted"], acc["in_silo"] + last["below"] + last["removed"], "integer counts")
    checks.true(f"{name}: particles re-inserted and removed", last["fed"] > 0 and last["removed"] > 0,
                f"{last['fed']} re-inserted, {last['removed']} removed", "the flow ran and was fed")
