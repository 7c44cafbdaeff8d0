"""Plots of the case layer (matplotlib, Agg: no display needed).

    plt = pyplot()
    field_panels(path, title, cells, rows, xlim, ylim)   cell fields (polygons) at several times
    case_fields(path, title, case, times, rows, ...)     the same from a plane OpenFOAM case
    cell_map(ax, cells, values, cmap, lim)               one panel of cell polygons coloured by a field
    grid_map(ax, x, z, values, cmap, lim)                one panel of a grid field [i_z, i_x] (CG fields)
    errorbars(ax, x, rows, key, label)                   mean +- SD of rows[key], rows[key + "_sd"] against x
    grains(fig, ax, x, z, d, colours)                    particles of a slice as discs of their own size
    lc, mean = force_chains(ax, pairs, half_width)       the contacts stronger than the mean in a slice
    save(fig, path, tight=False)                         tight: the saved area grows to hold a legend outside the axes
"""
import os

import numpy as np

from . import foam


def pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def save(fig, path, dpi=120, tight=False):
    # tight: a legend placed below the axes (many levels in one plot) would
    # otherwise be cut at the figure's edge
    fig.savefig(path, dpi=dpi, **({"bbox_inches": "tight"} if tight else {}))
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


def errorbars(ax, x, rows, key, label, **kw):
    """Points rows[i][key] against x with error bars rows[i][key + "_sd"] (none where NaN: one run)."""
    y = np.array([m[key] for m in rows])
    e = np.array([m[key + "_sd"] for m in rows])
    ax.errorbar(x, y, yerr=np.where(np.isfinite(e), e, 0.0), capsize=3, marker="o", label=label, **kw)


def grains(fig, ax, x, z, diameter, colours, scale=0.9):
    """Particles at (x, z) drawn as discs `scale` x their diameter [m] on the axes' own
    scale (set the limits and the aspect first)."""
    fig.canvas.draw()
    xlim = ax.get_xlim()
    per_m = ax.get_window_extent().width * 72 / fig.dpi / (xlim[1] - xlim[0])      # points per metre
    ax.scatter(x, z, s=(scale * diameter * per_m) ** 2, c=colours, linewidths=0)


def force_chains(ax, pairs, half_width, vmax=6.0):
    """The contact network of one `compute pair/gran/local` snapshot (columns
    c_pairs[1..3] and [4..6] the two centres, [10..12] the force) in the slice
    |y| < half_width of the contact midpoints: a line from centre to centre (x, z)
    for every contact stronger than the mean, its width and colour the force over
    the mean (colours 1..vmax). Returns (the LineCollection, the mean force [N])."""
    from matplotlib.collections import LineCollection
    c = pairs
    xi = np.column_stack([c[f"c_pairs[{k}]"] for k in (1, 2, 3)])
    xj = np.column_stack([c[f"c_pairs[{k}]"] for k in (4, 5, 6)])
    f = np.linalg.norm(np.column_stack([c[f"c_pairs[{k}]"] for k in (10, 11, 12)]), axis=1)
    mean = float(f.mean()) if len(f) else 1.0
    sel = (np.abs(0.5 * (xi[:, 1] + xj[:, 1])) < half_width) & (f > mean)
    order = np.argsort(f[sel])
    segs = np.stack([xi[sel][:, [0, 2]], xj[sel][:, [0, 2]]], axis=1)[order]
    lc = LineCollection(segs, linewidths=0.4 * f[sel][order] / mean, cmap="inferno_r",
                        norm=pyplot().Normalize(1, vmax))
    lc.set_array(f[sel][order] / mean)
    ax.add_collection(lc)
    return lc, mean


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
