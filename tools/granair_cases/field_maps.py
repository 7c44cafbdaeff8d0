"""Maps of 2-D fields (CG fields over an outlet, x-z or r-z), one row per run and one
column per field, each field on one colour scale across the rows so runs compare.

    draw(path, title, rows, panels)
      rows:   [(name, xs, zs, {field: grid[len(zs), len(xs)]}, decorate(ax) or None)]
      panels: [(field, label, cmap)]
"""
import numpy as np

from . import plots


def draw(path, title, rows, panels, percentile=99, row_height=1.9, dpi=100):
    """Each field from 0 to the largest of its `percentile`-th percentiles over the rows (1
    where that is not positive); a grid of the wrong size is left blank; decorate(ax) draws over each panel (the
    openings, a surface). Returns the path, or None without rows."""
    if not rows:
        return None
    plt = plots.pyplot()
    fig, axs = plt.subplots(len(rows), len(panels), figsize=(4 * len(panels), row_height * len(rows) + 0.6),
                            squeeze=False)
    lim = {k: max([0.0] + [float(np.nanpercentile(fields[k], percentile)) for _, _, _, fields, _ in rows])
           for k, _, _ in panels}
    for axrow, (name, xs, zs, fields, decorate) in zip(axs, rows):
        for ax, (k, label, cmap) in zip(axrow, panels):
            grid = fields[k]
            if grid.size != len(xs) * len(zs):
                continue
            im = ax.pcolormesh(xs, zs, grid.reshape(len(zs), len(xs)), cmap=cmap, vmin=0, vmax=lim[k] or 1,
                               shading="auto")
            if decorate:
                decorate(ax)
            ax.set_aspect("equal")
            ax.set_title(f"{name}: {label}", fontsize=8)
            fig.colorbar(im, ax=ax, shrink=0.8)
    fig.suptitle(title, fontsize=9)
    fig.tight_layout()
    return plots.save(fig, path, dpi=dpi)
