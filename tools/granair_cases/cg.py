"""CG fields in a case: granairCG (coupling/cg, docs/cg-fields.md) run on a run's
dumps and its CSV read back as grids.

    cpu = run(case, "results/cg_rz", {"coordinates": "RZ", "width": 0.03, ...})   (or [(option, value), ...])
    f = read("results/cg_rz.csv")          f["axes"] = ("r", "z"), f["r"], f["z"] (grid values),
                                           f["density"][i_r, i_z], ... (NaN where granairCG masks)
    f = read(csv, order=("z", "x"))         the same with the fields as [i_z, i_x]
    p, tau = invariants(f, "contact_stress")   tr(sigma)/3 and sqrt(J2) of a tensor field's components
    bilinear(f["z"], f["x"], f["density"], z, x)   a grid field at points (NaN outside)
    kernel_share_below(u, cut)              the share of a cut 2-D Gaussian kernel below a line
"""
import math
import os

import numpy as np

from . import CaseError, runner

COORDINATES = ("x", "y", "z", "r")      # the coordinate columns granairCG writes, in its order


def run(case, stem, options, log=None):
    """granairCG in `case` with `options` ({option without --: value or list of values}, True
    for a flag; a list of (option, value) pairs to repeat an option, e.g. plane-wall) writing
    `stem`.* (relative to case); log/<log>.log (default the stem's name). Returns the CPU seconds."""
    cmd = ["granairCG"]
    for key, value in (options.items() if isinstance(options, dict) else options):
        if value is False or value is None:
            continue
        cmd.append("--" + key)
        if value is not True:
            cmd += [str(v) for v in (value if isinstance(value, (list, tuple)) else [value])]
    cmd += ["--out", stem]
    os.makedirs(os.path.dirname(os.path.join(case, stem)) or case, exist_ok=True)
    return runner.run(cmd, case, log or os.path.basename(stem))


def read(path, order=None):
    """granairCG's CSV as grids: {"axes": resolved coordinate names in file order (or in
    `order`, which must name the same axes), each axis' sorted values, every field shaped
    (n_axis0, n_axis1, ...)}; a file with no coordinate column (a window average) gives scalars."""
    try:
        with open(path) as fh:
            head = fh.readline().strip().split(",")
    except OSError as e:
        raise CaseError(f"{path}: cannot read ({e.strerror})")
    data = np.genfromtxt(path, delimiter=",", skip_header=1, ndmin=2)
    if data.shape[1] != len(head):
        raise CaseError(f"{path}: {data.shape[1]} values per row but {len(head)} column names")
    axes = tuple(c for c in head if c in COORDINATES)
    out = {"axes": axes}
    if not axes:
        return dict(out, **{h: float(data[0, i]) for i, h in enumerate(head)})
    values = [np.unique(data[:, head.index(a)]) for a in axes]
    shape = tuple(len(v) for v in values)
    if int(np.prod(shape)) != data.shape[0]:
        raise CaseError(f"{path}: {data.shape[0]} rows are not a grid of {' x '.join(map(str, shape))} points")
    idx = [np.searchsorted(v, data[:, head.index(a)]) for a, v in zip(axes, values)]
    for a, v in zip(axes, values):
        out[a] = v
    for i, h in enumerate(head):
        if h in axes:
            continue
        grid = np.full(shape, np.nan)
        grid[tuple(idx)] = data[:, i]
        out[h] = grid
    if order and tuple(order) != axes:
        if sorted(order) != sorted(axes):
            raise CaseError(f"{path}: expected a grid over {', '.join(order)}, found coordinates {', '.join(axes)}")
        perm = [axes.index(a) for a in order]
        out = dict({k: (np.transpose(v, perm) if isinstance(v, np.ndarray) and v.ndim == len(axes) else v)
                    for k, v in out.items()}, axes=tuple(order))
    return out


def bilinear(a0, a1, grid, p0, p1):
    """grid [i0, i1] (on the axis values a0, a1) at the points (p0, p1), bilinear; NaN outside."""
    i = np.clip(np.searchsorted(a0, p0) - 1, 0, len(a0) - 2)
    k = np.clip(np.searchsorted(a1, p1) - 1, 0, len(a1) - 2)
    f0, f1 = (p0 - a0[i]) / (a0[i + 1] - a0[i]), (p1 - a1[k]) / (a1[k + 1] - a1[k])
    out = (grid[i, k] * (1 - f1) * (1 - f0) + grid[i, k + 1] * f1 * (1 - f0) + grid[i + 1, k] * (1 - f1) * f0
           + grid[i + 1, k + 1] * f1 * f0)
    inside = (p0 >= a0[0]) & (p0 <= a0[-1]) & (p1 >= a1[0]) & (p1 <= a1[-1])
    return np.where(inside, out, np.nan)


def kernel_share_below(u, cut=3.0):
    """Share of the 2-D Gaussian kernel (cut at `cut` widths, normalised over its disc, as
    granairCG's) whose points lie below a line u widths above its centre (numerical, 1e-9):
    what of a particle's kernel falls inside a window's edge."""
    t = np.linspace(-cut, cut, 20001)
    m = np.exp(-t ** 2 / 2) * np.array([math.erf(math.sqrt(max(cut ** 2 - x ** 2, 0.0) / 2)) for x in t])
    cdf = np.concatenate([[0.0], np.cumsum(0.5 * (m[1:] + m[:-1]) * np.diff(t))])
    return np.interp(u, t, cdf / cdf[-1], left=0.0, right=1.0)


def invariants(f, name):
    """(P, tau) of the tensor field `name` of a read() result: P = tr(sigma)/3 and
    tau = sqrt(J2), J2 = s:s/2 of the deviator s = sym(sigma) - P I (the components
    name_ab, a, b in x y z or, for RZ files, r t z)."""
    comps = ("r", "t", "z") if "r" in f["axes"] else ("x", "y", "z")
    try:
        s = [[f[f"{name}_{a}{b}"] for b in comps] for a in comps]
    except KeyError as e:
        raise CaseError(f"the CG fields have no component {e.args[0]} (tensor {name!r})")
    p = (s[0][0] + s[1][1] + s[2][2]) / 3.0
    j2 = 0.0
    for i in range(3):
        for j in range(3):
            dev = 0.5 * (s[i][j] + s[j][i]) - (p if i == j else 0.0)
            j2 = j2 + 0.5 * dev * dev
    return p, np.sqrt(j2)
