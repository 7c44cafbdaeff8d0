#!/usr/bin/env python3
"""plot_cg.py: PNG maps and profiles of granairCG's CSV output.

    plot_cg.py cg.csv [--fields F ...] [--slice AXIS=VALUE] [--out cg.png]
    ./granair cg plot cg.csv ...        (the same)

The kind of plot follows from the file:
  - two coordinate columns (XY, XZ, YZ, RZ): one map per field;
  - one (X, Y, Z profiles): one profile per field;
  - three (XYZ): a map of the plane --slice picks (e.g. y=0.01, the nearest
    grid plane; default: the middle plane of the last axis);
  - a series file (cg_series.csv: time, step, fields): fields against time.
A field is a column name (velocity_z, stress_xz) or a vector/tensor name:
"velocity" plots the magnitude of velocity_x/_y/_z (or _r/_t/_z).
Default fields: volume_fraction, velocity, pressure. NaN (no particles) is
left blank. Uses Debian's python3-matplotlib and numpy only.
"""
import argparse
import os
import sys

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COORDS = ("x", "y", "z", "r")


def read_csv(path):
    try:
        with open(path) as f:
            head = f.readline().strip().split(",")
    except OSError as e:
        sys.exit(f"plot_cg: cannot read '{path}': {e.strerror}")
    data = np.genfromtxt(path, delimiter=",", skip_header=1, ndmin=2)
    if data.shape[1] != len(head):
        sys.exit(f"plot_cg: '{path}': {data.shape[1]} values per row but {len(head)} column names")
    return {h: data[:, i] for i, h in enumerate(head)}


def field(cols, name, path):
    if name in cols:
        return cols[name], name
    comps = [c for c in cols if c.startswith(name + "_") and len(c) == len(name) + 2]
    if len(comps) == 3:
        return np.sqrt(sum(cols[c] ** 2 for c in comps)), f"|{name}|"
    names = sorted(c for c in cols if c not in COORDS)
    sys.exit(f"plot_cg: '{path}' has no field '{name}'. Fields: {' '.join(names)}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("csv")
    ap.add_argument("--fields", nargs="+", default=["volume_fraction", "velocity", "pressure"])
    ap.add_argument("--slice", help="AXIS=VALUE: the plane of a 3-D (XYZ) file to map")
    ap.add_argument("--out", help="PNG file (default: the CSV's name with .png)")
    a = ap.parse_args()
    cols = read_csv(a.csv)
    out = a.out or os.path.splitext(a.csv)[0] + ".png"
    coords = [c for c in COORDS if c in cols]
    n = len(a.fields)

    if "time" in cols:  # a window-average series
        fig, axes = plt.subplots(n, 1, figsize=(6, 2.2 * n), sharex=True, squeeze=False)
        for ax, name in zip(axes[:, 0], a.fields):
            v, label = field(cols, name, a.csv)
            ax.plot(cols["time"], v, ".-")
            ax.set_ylabel(label)
        axes[-1, 0].set_xlabel("time")
    elif len(coords) == 1:
        (x,) = coords
        fig, axes = plt.subplots(1, n, figsize=(3.2 * n, 4.5), sharey=True, squeeze=False)
        for ax, name in zip(axes[0], a.fields):
            v, label = field(cols, name, a.csv)
            ax.plot(v, cols[x])
            ax.set_xlabel(label)
        axes[0, 0].set_ylabel(f"{x} [m]")
    else:
        if len(coords) == 3:
            axis, value = (a.slice.split("=") if a.slice else ("z", None))
            if axis not in coords:
                sys.exit(f"plot_cg: --slice axis '{axis}' is not one of {' '.join(coords)}")
            levels = np.unique(cols[axis])
            pick = levels[len(levels) // 2] if value is None else levels[np.argmin(abs(levels - float(value)))]
            keep = cols[axis] == pick
            cols = {k: v[keep] for k, v in cols.items()}
            coords = [c for c in coords if c != axis]
            title = f" ({axis} = {pick:.4g} m)"
        else:
            title = ""
        u, w = coords
        uu, ww = np.unique(cols[u]), np.unique(cols[w])
        aspect = ww.ptp() / max(uu.ptp(), 1e-30)
        panel_h = min(8.0, max(3.0, 3.6 * aspect))
        panel_w = min(8.0, max(2.6, panel_h / aspect + 1.4))  # the map and its colour bar
        fig, axes = plt.subplots(1, n, figsize=(panel_w * n, panel_h + 0.8), squeeze=False)
        for ax, name in zip(axes[0], a.fields):
            v, label = field(cols, name, a.csv)
            grid = np.full((len(ww), len(uu)), np.nan)
            grid[np.searchsorted(ww, cols[w]), np.searchsorted(uu, cols[u])] = v
            m = ax.pcolormesh(uu, ww, np.ma.masked_invalid(grid), shading="nearest")
            ax.set_aspect("equal")
            ax.set_xlabel(f"{u} [m]")
            ax.set_title(label + title, fontsize=9)
            fig.colorbar(m, ax=ax, shrink=0.8)
        axes[0, 0].set_ylabel(f"{w} [m]")
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    print(f"plot_cg: wrote {out}")


if __name__ == "__main__":
    main()
