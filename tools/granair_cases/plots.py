"""Plots of the case layer (matplotlib, Agg: no display needed).

    plt = pyplot()
    field_panels(path, title, cells, rows, xlim, ylim)   cell fields (polygons) at several times
    case_fields(path, title, case, times, rows, ...)     the same from a plane OpenFOAM case
    cell_map(ax, cells, values, cmap, lim)               one panel of cell polygons coloured by a field
    grid_map(ax, x, z, values, cmap, lim)                one panel of a grid field [i_z, i_x] (CG fields)
    save(fig, path)
"""
import os

import numpy as np

from . import foam


def pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def save(fig, path, dpi=120):
    fig.savefig(path, dpi=dpi)
    pyplot().close(fig)
    return path


def cell_map(ax, cells, values, cmap, lim):
    """Cell polygons [(x, z) corners] coloured by values on ax; returns the collection (for a colour bar)."""
    from matplotlib.collections import PolyCollection
    pc = PolyCollection(cells, array=values, cmap=cmap, edgecolors="face", linewidths=0.2)
    pc.set_clim(*lim)
    ax.add_collection(pc)
    return pc


def grid_map(ax, x, z, values, cmap, lim, scale=1e3):
    """A field on a regular grid (values [i_z, i_x] at the points x, z; gc.cg.read(csv,
    order=("z", "x"))) on ax, each point a pixel, lengths times scale (mm); returns the image."""
    ext = [x[0] * scale, x[-1] * scale, z[0] * scale, z[-1] * scale]
    return ax.imshow(values, origin="lower", extent=ext, cmap=cmap, vmin=lim[0], vmax=lim[1], interpolation="nearest")


def field_panels(path, title, cells, rows, xlim, ylim, notes=None):
    """One row of panels per field, one panel per time, each cell drawn as its
    polygon (cells: [(x, z) corners] in the unit of xlim/ylim). rows: [(label,
    cmap, (vmin, vmax) or None, {t: values})]; None limits give a symmetric
    range (a pressure). notes: {t: text} added under a panel's time (e.g. the fill level)."""
    plt = pyplot()
    times = sorted({t for _, _, _, by_t in rows for t in by_t})
    aspect = (ylim[1] - ylim[0]) / (xlim[1] - xlim[0])
    fig, axes = plt.subplots(len(rows), len(times), squeeze=False,
                             figsize=(1.9 * len(times) + 2.0, 1.9 * aspect * len(rows) + 0.8))
    fig.suptitle(title, fontsize=10)
    for i, (label, cmap, lim, by_t) in enumerate(rows):
        if lim is None:
            m = max([float(np.max(np.abs(v))) for v in by_t.values()] + [1e-6])
            lim = (-m, m)
        for j, t in enumerate(times):
            ax = axes[i][j]
            ax.set(xlim=xlim, ylim=ylim, aspect="equal", xlabel="x [mm]")
            ax.set_title(f"t = {t:g} s" + (f"\n{notes[t]}" if notes and t in notes else ""), fontsize=9)
            ax.tick_params(labelsize=7)
            if t in by_t:
                pc = cell_map(ax, cells, by_t[t], cmap, lim)
        axes[i][0].set_ylabel("z [mm]", fontsize=8)
        fig.colorbar(pc, ax=list(axes[i]), fraction=0.04, pad=0.02, label=label)
    return save(fig, path, dpi=110)


def case_fields(path, title, case, times, rows, xlim, ylim, notes=None):
    """field_panels of a plane OpenFOAM case (foam.plane_cells: an ASCII mesh, one
    cell thick): rows [(field, label, cmap, limits)] at the times given that have
    the field, lengths in mm. Returns the picture's path, or None without any field."""
    cells = [c * 1e3 for c in foam.plane_cells(case)]
    by_t = [(label, cmap, lim, {t: foam.read_field(p, len(cells)) for t in times for d in [foam.time_dir(case, t)]
                                for p in [d and os.path.join(d, field)] if p and os.path.exists(p)})
            for field, label, cmap, lim in rows]
    by_t = [r for r in by_t if r[3]]
    return field_panels(path, title, cells, by_t, xlim, ylim, notes) if by_t else None


def mesh_study(ax, n, w, g, label, across):
    """W against 1/N of a mesh study on ax: the runs (N = n, W = w, labelled), and for a
    monotonic gc.gci result g (its finest mesh first in g's inputs: n_fine = max(n)) the
    Richardson extrapolation at 1/N = 0 and the GCI_fine bar; across: what N counts."""
    ax.plot([1 / x for x in n], w, "o-", label=label)
    if g["convergence"] == "monotonic":
        fine = max(range(len(n)), key=lambda i: n[i])
        ax.plot([0], [g["extrapolated"]], "k*", ms=10, label="Richardson extrapolation (order %.2f)" % g["order"])
        ax.errorbar([1 / n[fine]], [w[fine]], yerr=[g["gci_fine"] * w[fine]], fmt="none", ecolor="k", capsize=4,
                    label="GCI_fine %.2f %%" % (100 * g["gci_fine"]))
    for x, y in zip(n, w):
        ax.annotate("N = %d" % x, (1 / x, y), textcoords="offset points", xytext=(5, 5), fontsize=8)
    ax.set(xlabel=f"1/N (N cells across {across})", ylabel="steady mass flow W [kg/s]")
    ax.set_xlim(left=-0.005)
    ax.grid(alpha=0.3)
