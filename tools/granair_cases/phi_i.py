"""The solid fraction against the inertial number, phi = a1 / (1 + a2 I) (Fullard et
al. 2019; the fit is gc.fits.phi_of_I), as a figure and a text file of the fits, one
set of CG points per friction set or material (cases/two-slot-silo). Why here: the law
and its picture are the same whatever silo the points come from.

    fits = plot(png, txt, sets, i_min, title, header)
      sets: [(name, colour, [(I, phi), ...])]; fits: [(name, a1, a2, points)]
"""
import numpy as np

from . import fits as fitting, plots


def plot(png, txt, sets, i_min, title, header):
    """The points of each set (sets without points are left out), its fit drawn from
    i_min to its largest I, the fits in txt (`# header`, then `name: a1 = .., a2 = ..,
    points = n`)."""
    plt = plots.pyplot()
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    lines = []
    for name, colour, pts in sets:
        if not pts:
            continue
        i, phi = np.asarray(pts).T
        ax.plot(i, phi, ".", ms=2, color=colour, alpha=0.3)
        a1, a2 = fitting.phi_of_I(i, phi)
        ii = np.linspace(i_min, max(i), 50)
        ax.plot(ii, a1 / (1 + a2 * ii), color=colour, label=f"{name}: a1 = {a1:.3f}, a2 = {a2:.3f} ({len(pts)} points)")
        lines.append((name, a1, a2, len(pts)))
    ax.set(xlabel="I", ylabel="phi", title=title)
    ax.title.set_fontsize(9)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    plots.save(fig, png, dpi=110)
    with open(txt, "w") as fh:
        fh.write(f"# {header}\n")
        for name, a1, a2, n in lines:
            fh.write(f"{name}: a1 = {a1:.5g}, a2 = {a2:.5g}, points = {n}\n")
    return lines
