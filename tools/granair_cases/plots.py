"""Plots of the case layer (matplotlib, Agg: no display needed).

    plt = pyplot()
    field_panels(path, title, x, z, size, rows, xlim, ylim)   cell fields at several times
    save(fig, path)
"""
import numpy as np


def pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def save(fig, path, dpi=120):
    fig.savefig(path, dpi=dpi)
    pyplot().close(fig)
    return path


def field_panels(path, title, x, z, size, rows, xlim, ylim):
    """One row of panels per field, one panel per time, cells drawn as squares of
    their own size at their centres (x, z, size: numpy arrays, the same length
    unit as xlim/ylim). rows: [(label, cmap, (vmin, vmax) or None, {t: values})];
    a row with None limits gets a symmetric range (a pressure)."""
    plt = pyplot()
    times = sorted({t for _, _, _, by_t in rows for t in by_t})
    aspect = (ylim[1] - ylim[0]) / (xlim[1] - xlim[0])
    fig, axes = plt.subplots(len(rows), len(times), squeeze=False,
                             figsize=(1.9 * len(times) + 1.4, 1.9 * aspect * len(rows) + 0.8))
    fig.suptitle(title, fontsize=10)
    for i, (label, cmap, lim, by_t) in enumerate(rows):
        if lim is None:
            m = max([float(np.max(np.abs(v))) for v in by_t.values()] + [1e-6])
            lim = (-m, m)
        for j, t in enumerate(times):
            ax = axes[i][j]
            ax.set_xlim(*xlim)
            ax.set_ylim(*ylim)
            ax.set_aspect("equal")
            ax.set_title(f"t = {t:g} s", fontsize=9)
            ax.set_xlabel("x [mm]", fontsize=8)
            ax.tick_params(labelsize=7)
            if t not in by_t:
                continue
            # marker edge in points from the data scale of this panel
            fig.canvas.draw()
            pts = ax.get_window_extent().width * 72 / fig.dpi / (xlim[1] - xlim[0])
            sc = ax.scatter(x, z, c=by_t[t], s=(size * pts) ** 2, marker="s", cmap=cmap,
                            vmin=lim[0], vmax=lim[1], linewidths=0)
        axes[i][0].set_ylabel("z [mm]", fontsize=8)
        fig.colorbar(sc, ax=list(axes[i]), fraction=0.04, pad=0.02, label=label)
    return save(fig, path, dpi=110)
