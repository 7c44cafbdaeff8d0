"""Plots of the case layer (matplotlib, Agg: no display needed).

    plt = pyplot()
    field_panels(path, title, cells, rows, xlim, ylim)   cell fields (polygons) at several times
    case_fields(path, title, case, times, rows, ...)     the same from a plane OpenFOAM case
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


def field_panels(path, title, cells, rows, xlim, ylim, notes=None):
    """One row of panels per field, one panel per time, each cell drawn as its
    polygon (cells: [(x, z) corners] in the unit of xlim/ylim). rows: [(label,
    cmap, (vmin, vmax) or None, {t: values})]; None limits give a symmetric
    range (a pressure). notes: {t: text} added under a panel's time (e.g. the fill level)."""
    from matplotlib.collections import PolyCollection
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
                pc = PolyCollection(cells, array=by_t[t], cmap=cmap, edgecolors="face", linewidths=0.2)
                pc.set_clim(*lim)
                ax.add_collection(pc)
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
