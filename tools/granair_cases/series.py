"""Time series: CSV in and out, steady windows and rates, window means, block errors.

A series is a dict {column: numpy array}, as granairFoam's and
granairContinuumFoam's postProcessing/timeSeries.csv hold them: one row per
step, `t` the end of the step.
"""
import csv

import numpy as np

from . import CaseError


def read_csv(path, min_rows=1):
    """A CSV with a header line as {column: numpy array of floats}."""
    try:
        with open(path) as fh:
            rows = [r for r in csv.reader(fh) if r]
    except OSError as e:
        raise CaseError(f"{path}: cannot read ({e.strerror})")
    if len(rows) - 1 < min_rows:
        raise CaseError(f"{path} has {len(rows) - 1} rows, expected at least {min_rows}")
    try:
        data = np.array([[float(v) for v in r] for r in rows[1:]]).reshape(-1, len(rows[0]))
    except ValueError as e:
        raise CaseError(f"{path}: not a table of numbers ({e})")
    return {h: data[:, i] for i, h in enumerate(rows[0])}


def read_table(path):
    """A CSV with a header line as a list of dicts of strings (tables of mixed columns)."""
    try:
        with open(path, newline="") as fh:
            return list(csv.DictReader(fh))
    except OSError as e:
        raise CaseError(f"{path}: cannot read ({e.strerror})")


def write_csv(path, columns, fmt="{:.8g}"):
    """columns: [(name, values)] of equal length, written with fmt (one or per column)."""
    fmts = fmt if isinstance(fmt, (list, tuple)) else [fmt] * len(columns)
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow([name for name, _ in columns])
        for i in range(len(columns[0][1])):
            w.writerow([f.format(v[i]) for f, (_, v) in zip(fmts, columns)])


def write_rows(path, rows, fmt=None):
    """A table of dicts (one per row; the columns in order of first appearance,
    missing cells empty); floats as repr, or with fmt ("{:.6g}") if given."""
    fields = []
    for r in rows:
        fields += [k for k in r if k not in fields]
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=fields, restval="")
        w.writeheader()
        for r in rows:
            w.writerow({k: fmt.format(v) if fmt and isinstance(v, float) else v for k, v in r.items()})
    return path


def step_lengths(t, t_start=0.0):
    """Length of each step: row i covers (t[i-1], t[i]], the first from t_start."""
    return np.diff(np.concatenate([[t_start], t]))


def slope(t, y, t0, t1=None):
    """Least-squares slope of y(t) over t0 <= t <= t1 (default: to the end): the
    steady rate of a cumulative quantity. NaN with fewer than 3 points."""
    sel = (t >= t0) & (t <= (t[-1] if t1 is None else t1))
    if sel.sum() < 3:
        return float("nan")
    return float(np.polyfit(t[sel], y[sel], 1)[0])


def steady_window(t, left, t_from, fraction=0.5):
    """(t0, t1): t1 the first time `left` (what is still in the silo) falls to
    `fraction` of its first value (the rate falls once the free surface reaches
    the hopper), or the end; t0 = min(t_from, t1 / 2)."""
    below = np.nonzero(left <= fraction * left[0])[0]
    t1 = float(t[below[0]]) if below.size else float(t[-1])
    return min(t_from, 0.5 * t1), t1


def time_mean(t, y, t0, t1=None, dt=None):
    """Mean of y over t0 <= t <= t1 (default the end), each row weighted by its step
    length dt (default equal weights)."""
    sel = (t >= t0) & (t <= (t[-1] if t1 is None else t1))
    if not sel.any():
        return float("nan")
    w = np.ones(sel.sum()) if dt is None else dt[sel]
    return float(np.sum(y[sel] * w) / np.sum(w))


def trailing_mean(t, y, window):
    """Mean of y over the trailing `window` [s] at every row (as the coupling's
    MassFlowRate does for the mass)."""
    out = np.empty_like(y)
    j = 0
    for i in range(len(t)):
        while t[j] < t[i] - window + 1e-12:
            j += 1
        out[i] = np.mean(y[j:i + 1])
    return out


def window_means(t, dt, columns, width, keep_last=0.0, tol=0.0):
    """Means over consecutive windows of `width` [s]: a window starts where the
    previous one ended and closes at the first row with t >= start + width - tol;
    each row's value acts over its step dt (a rate's mean is the change of its
    integral over the window length). The last, unclosed window is kept if it
    spans more than keep_last x width (None: never). Returns (window centres,
    [means per column])."""
    centres, means = [], [[] for _ in columns]
    start, i0 = float(t[0] - dt[0]), 0
    for i in range(len(t)):
        closes = t[i] >= start + width - tol
        if closes or (i == len(t) - 1 and keep_last is not None and t[i] - start > keep_last * width):
            span = float(t[i] - start)
            centres.append(0.5 * (start + float(t[i])))
            for m, c in zip(means, columns):
                m.append(float(np.sum(c[i0:i + 1] * dt[i0:i + 1]) / span))
        if closes:
            start, i0 = float(t[i]), i + 1
    return np.array(centres), [np.array(m) for m in means]


def mean_sd(values):
    """(mean, sample standard deviation (n - 1)) of the finite values (None and NaN left
    out): the spread of a result over repeated runs (seeds); NaN SD for one value."""
    x = np.array([v for v in values if v is not None and np.isfinite(v)], dtype=float)
    if not len(x):
        return float("nan"), float("nan")
    return float(x.mean()), float(x.std(ddof=1)) if len(x) > 1 else float("nan")


def mean_sd_columns(tables, keys, n=None):
    """Row by row mean and sample SD over repeated runs' tables (dicts of columns, e.g.
    read_csv, or read_table's rows turned into columns) of each of keys, as mean_sd does
    for one value (None and NaN left out, NaN SD for one run): {key: [means], key_sd:
    [SDs]}, the first n rows (default: the shortest table's)."""
    n = min(len(t[keys[0]]) for t in tables) if n is None else n
    out = {}
    for k in keys:
        pairs = [mean_sd([float(t[k][i]) for t in tables]) for i in range(n)]
        out[k], out[k + "_sd"] = np.array([m for m, _ in pairs]), np.array([s for _, s in pairs])
    return out


def block_errors(tables, fn, keys, blocks=5):
    """Standard errors of the results of fn by block averaging: the snapshots
    `tables` (dicts of arrays, in time order) in `blocks` consecutive blocks,
    each block's mean table given to fn (which returns a dict), and for each
    of `keys` the spread of the block results over sqrt(blocks) (NaN with one
    block): errors of a time average whose snapshots are correlated."""
    results = []
    for b in [b for b in np.array_split(np.arange(len(tables)), blocks) if len(b)]:
        mean = {k: (np.mean([tables[j][k] for j in b], axis=0) if isinstance(v, np.ndarray) else v)
                for k, v in tables[0].items()}
        results.append(fn(mean))
    out = {}
    for k in keys:
        x = np.array([r[k] for r in results])
        out[k] = float(np.std(x, ddof=1) / np.sqrt(len(x))) if len(x) > 1 else float("nan")
    return out


def write_keys(path, pairs, header=None):
    """`key = value` lines (floats with 6 digits), an optional # header first."""
    with open(path, "w") as fh:
        if header:
            fh.write(f"# {header}\n")
        for k, v in pairs:
            fh.write(f"{k} = {v:.6g}\n" if isinstance(v, float) else f"{k} = {v}\n")
    return path


def read_keys(path):
    """The `key = value` lines of a summary as {key: float or str}."""
    out = {}
    try:
        with open(path) as fh:
            lines = fh.readlines()
    except OSError as e:                     # e.g. a post stage before its runs (not committed) exist
        raise CaseError(f"{path}: cannot read ({e.strerror}); a finished run's summary was expected")
    for line in lines:
        k, sep, v = line.partition(" = ")
        if sep and not k.startswith("#"):
            try:
                out[k.strip()] = float(v)
            except ValueError:
                out[k.strip()] = v.strip()
    return out
