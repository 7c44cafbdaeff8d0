"""Panels of a discharge study's rates and 2-D CG fields (RZ or XZ grids [i_axis, i_z]),
drawn on axes the caller made, so a case keeps only its layout and its words
(cases/orifice-arch).

    rates(ax, curves, t0)                    rates against time, each with its closed-form band
    at_heights(axes, grids, axis, comps, zs, scale, first)   each field along the axis at heights z
    profiles_figure(path, grids, axis, comps, ylabels, zs, scale, first, ...)   the same as a figure, a panel per field
    maps(fig, axes, a, z, grid_of, panels, mark)           one pcolormesh per field, each its colour bar
    paraboloid(ax, r, z, R, alpha, label, marker)          points z/R against r/R and alpha (1 - (r/R)^2)
"""
import numpy as np

from . import plots


def rates(ax, curves, t0, window_label=" averaging window"):
    """curves: [(label, t, rate, (band_lo, band_hi))] in the units to show; colour Ci for the
    i-th, its band in the same colour; a dotted line and a label where the average starts."""
    for i, (label, t, rate, band) in enumerate(curves):
        col = f"C{i}"
        ax.plot(t, rate, color=col, lw=1.2, label=label)
        ax.axhspan(band[0], band[1], color=col, alpha=0.15)
    ax.axvline(t0, color="0.4", ls=":", lw=1)
    ax.text(t0, ax.get_ylim()[1] * 0.97, window_label, fontsize=7, va="top", color="0.3")


def at_heights(axes, grids, axis, comps, zs, scale, first, styles=None, d=1.0):
    """For each height zs[i] [units of d] and each grid of `grids` ({key: grid dict}), the
    grid row nearest it, field comps[k] (divided by scale) along the axis / d on axes[k];
    colour Ci per height (cycling over ten), line style styles[key] per grid; only the
    `first` grid's lines are labelled (one legend entry per height)."""
    styles = styles or {}
    for i, zd in enumerate(zs):
        for key, red in grids.items():
            j = int(np.argmin(abs(red["z"] - zd * d)))
            for ax, comp in zip(axes, comps):
                ax.plot(red[axis] / d, red[comp][:, j] / scale, color=f"C{i % 10}", ls=styles.get(key, "-"),
                        lw=1.1, label=f"z = {zd:g} d" if key == first else None)


def profiles_figure(path, grids, axis, comps, ylabels, zs, scale, first, styles=None, d=1.0, mark=None, title="",
                    figsize=(7.5, 4.8), suptitle=False, ncol=1):
    """at_heights() as a figure of one panel per field of comps (x: axis / d, y: ylabels[k]),
    a grey line at `mark` (the outlet's edge), the legend on the first panel (ncol columns),
    the title over the figure (suptitle) or over the first panel. Returns the path."""
    plt = plots.pyplot()
    fig, axes = plt.subplots(1, len(comps), figsize=figsize, squeeze=False)
    axes = axes[0]
    at_heights(axes, grids, axis, comps, zs, scale, first, styles, d)
    for ax, ylabel in zip(axes, ylabels):
        if mark is not None:
            ax.axvline(mark, color="0.5", lw=0.8)
        ax.set(xlabel=f"{axis} / d", ylabel=ylabel)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7, ncol=ncol)
    if suptitle:
        fig.suptitle(title, fontsize=9)
    else:
        axes[0].set_title(title, fontsize=9)
    fig.tight_layout()
    return plots.save(fig, path)


def maps(fig, axes, a, z, grid_of, panels, mark=None, scale=1e3, cmap="viridis"):
    """panels: [(field, title)]; axes[k] shows grid_of[field].T / scale over (a, z) with its
    own colour bar, equal aspect; mark: a vertical dotted white line there (an outlet's edge)."""
    for ax, (k, label) in zip(axes, panels):
        m = ax.pcolormesh(a, z, grid_of[k].T / scale, shading="nearest", cmap=cmap)
        ax.set(title=label, aspect="equal")
        ax.title.set_fontsize(8)
        if mark is not None:
            ax.axvline(mark, color="w", lw=0.6, ls=":")
        fig.colorbar(m, ax=ax, fraction=0.05, pad=0.02)


def paraboloid(ax, r, z, R, alpha, label, marker="o", color=None, **kw):
    """The points (r / R, z / R) and the fitted z / R = alpha (1 - (r / R)^2) over 0..1 in
    the same colour (color, or the next of the cycle). Returns the colour."""
    line = ax.plot(r / R, z / R, marker, ms=4, label=label, **(dict(color=color) if color else {}), **kw)[0]
    x = np.linspace(0, 1, 50)
    ax.plot(x, alpha * (1 - x ** 2), color=line.get_color(), lw=1)
    return line.get_color()
