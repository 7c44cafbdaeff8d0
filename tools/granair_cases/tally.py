"""The exact particle count of a LIGGGHTS discharge run in restart chunks with a feed,
an outlet counter and a sink (cases/two-slot-silo): the `granair ...` lines each
chunk's input prints into its log, and the balance over the chunks. Why here: the
balance is what every counted discharge checks, whatever its silo, and it is only
worth anything when it is exact (integer counts, no tolerance).

    found = log_values(path, prefix)        {label: {key: value}} of the lines `prefix label: key value ...`
    start, end = chunk_states(log, k)        the `granair chunk k start|end:` counts
    n = lost_atoms(screen)                   LIGGGHTS' "Lost atoms" warnings on a chunk's screen
    acc = balance(n_fill, n_requested, states, crossing_ids, removed_ids, pending_ids, lost)
    check(c, name, acc, n_chunks)            the six checks of the balance (gc.checks)
    q, (tc, series) = crossing_flow(t, m, t0, t_end, width, groups, bin_width)   the outlet's flow from its records

The balance: inserted (fill + fed) = in the silo + below the outlet + removed at the
sink; crossed the outlet = below the outlet + removed; one record per crossing and
per removal; each chunk starts with the atoms the one before ended with and ends
with start + fed - removed; the particles a chunk deleted at its end (counted by
the sink, not yet deleted by LIGGGHTS) are all among the sink's records.
"""
import re

import numpy as np

from . import CaseError, outlet

COUNTS = ("atoms", "in_silo", "outlet", "sink", "feed")


def _number(s):
    try:
        return float(s)
    except ValueError:
        return s


def log_values(path, prefix):
    """{label: {key: value}} of every line `<prefix> <label>: key value key value ...` of
    a log (values as floats where they are numbers; the last line of a label wins)."""
    try:
        with open(path, errors="replace") as fh:
            text = fh.read()
    except OSError as e:
        raise CaseError(f"{path}: cannot read ({e.strerror})")
    out = {}
    for m in re.finditer(rf"^{re.escape(prefix)} (\S+): (.*)$", text, re.M):
        tok = m.group(2).split()
        out[m.group(1)] = {k: _number(v) for k, v in zip(tok[::2], tok[1::2])}
    return out


def chunk_states(path, k):
    """(start, end) of chunk k from its log: dicts of t (time) and the integer COUNTS of
    the lines `granair chunk <k> start|end: time T atoms N in_silo N outlet N sink N feed N`."""
    found = log_values(path, f"granair chunk {k}")
    if not {"start", "end"} <= set(found) or any(c not in found[s] for s in ("start", "end")
                                                for c in ("time",) + COUNTS):
        raise CaseError(f"{path}: no 'granair chunk {k} start/end' lines (did the chunk finish?)")
    return tuple(dict(t=float(found[s]["time"]), **{c: int(found[s][c]) for c in COUNTS}) for s in ("start", "end"))


def lost_atoms(path):
    """LIGGGHTS' "WARNING: Lost atoms" lines on a screen log (3.8 warns with equal counts
    after a restart: the chunks run with `thermo_modify lost warn` and count for themselves)."""
    with open(path, errors="replace") as fh:
        return fh.read().count("WARNING: Lost atoms")


def balance(n_fill, n_requested, states, crossing_ids, removed_ids, pending_ids=(), lost=0):
    """The balance of a run from its fill (n_fill placed of n_requested), its chunks'
    (start, end) states in order, the ids of the outlet's and the sink's records and
    the ids the chunks deleted at their ends: a dict of the counts and `closes`."""
    feed = outlet = sink = 0
    chunk_ok, atoms_prev = True, n_fill
    for s, e in states:
        df, do, ds = e["feed"] - s["feed"], e["outlet"] - s["outlet"], e["sink"] - s["sink"]
        chunk_ok &= s["atoms"] == atoms_prev and e["atoms"] == s["atoms"] + df - ds
        feed, outlet, sink, atoms_prev = feed + df, outlet + do, sink + ds, e["atoms"]
    in_silo = e["in_silo"]
    below = e["atoms"] - in_silo
    ids, rid, pend = np.asarray(crossing_ids), np.asarray(removed_ids), list(pending_ids)
    pend_ok = bool(set(pend) <= set(rid.tolist()))
    return dict(fill=n_fill, fill_requested=n_requested, fed=feed, inserted=n_fill + feed, in_silo=in_silo,
                below_outlet=below, removed=sink, discharged=outlet, crossing_records=int(ids.size),
                crossing_ids_unique=int(np.unique(ids).size), removed_records=int(rid.size),
                chunks_consistent=bool(chunk_ok), pending_deleted=len(pend), pending_all_removed=pend_ok,
                lost_atom_warnings=lost, t_end=e["t"],
                closes=bool(n_fill + feed == in_silo + below + sink and outlet == below + sink and chunk_ok
                            and ids.size == outlet and rid.size == sink and pend_ok))


def check(c, name, acc, n_chunks):
    """The balance's checks on gc.checks.Checks c, each line named `name: ...`."""
    c.exact(f"{name}: particles poured = requested", acc["fill"], acc["fill_requested"],
            "the packing places every sphere; LIGGGHTS reads them all")
    c.exact(f"{name}: inserted (fill + fed) = in silo + below the outlet + removed",
            acc["inserted"], acc["in_silo"] + acc["below_outlet"] + acc["removed"], "integer counts")
    c.exact(f"{name}: crossed the outlet = below the outlet + removed", acc["discharged"],
            acc["below_outlet"] + acc["removed"], "integer counts: nothing passes the outlet plane uncounted")
    c.exact(f"{name}: crossing records = crossings, removal records = removals",
            (acc["crossing_records"], acc["removed_records"]), (acc["discharged"], acc["removed"]), "one line each")
    c.true(f"{name}: every chunk's atom count = start + fed - removed", acc["chunks_consistent"],
           f"{n_chunks} chunks, {acc['lost_atom_warnings']} LIGGGHTS 'Lost atoms' warnings",
           "integer counts (LIGGGHTS 3.8 warns with equal counts after a restart: template/dem/in.chunk)")
    c.true(f"{name}: the particles deleted at chunk ends (counted by the sink, not yet deleted) are all "
           f"among the sink's records", acc["pending_all_removed"], f"{acc['pending_deleted']} particles",
           "massflow/mesh deletes at the next neighbour-list build")


def crossing_flow(t, m, t0, t_end, width, groups=None, bin_width=0.02):
    """The mass flow through an outlet from its crossing records (times t, masses m): the
    rate in each whole window `width` long from t0 (gc.outlet.window_rates), their mean
    and SD, the same per group of records (masks: the openings of a floor; default one
    group of all), the mass that crossed, and a series in bins of bin_width from 0 to
    t_end ((centres, rates): the figures' line). Returns (dict, series)."""
    rates = outlet.window_rates(t, m, t0, t_end, width)
    mean, sd = outlet.mean_sd(rates)
    groups = [np.ones_like(t, bool)] if groups is None else groups
    per = [outlet.mean_sd(outlet.window_rates(t[s], m[s], t0, t_end, width)) for s in groups]
    edges = np.arange(0.0, t_end + 1e-9, bin_width)
    series = np.histogram(t, edges, weights=m)[0] / bin_width
    return dict(windows=rates.tolist(), window_start=t0, mean=mean, sd=sd, n_windows=int(rates.size),
                per_opening_mean=[p[0] for p in per], per_opening_sd=[p[1] for p in per],
                discharged_kg=float(m.sum())), (0.5 * (edges[1:] + edges[:-1]), series)
