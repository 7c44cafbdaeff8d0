"""The coarse-grained DEM converged in its resolution parameter, the parcel size: runs
at several coarse-graining factors s of one orifice, Beverloo's size term fitted over
them (fits.beverloo_size) and extrapolated to the primary grain size. Shared by the
cases' parcel_size.py (mcc-hopper: circular orifice, wedge-silo: slot).

    rates = window_rates(t, m, t0, t1, width)     slopes of a cumulative mass over whole windows
    res = analyse(runs, outlet, at, exponent)     the fit over runs [{s, d, W, se}], every pair, each left out
    plot_fit(ax, runs, res, at, at_label, target) the common part of the W-against-d figure
    seeds, fit_all = seed_repeats(runs, repeats, outlet, at, exponent)   repeats against the runs of their s
    against(levels, runs, w, w_se, target)        another level's runs [{d, W}] over the size-converged W
"""
import math

import numpy as np

from . import CaseError
from . import fits


def window_rates(t, m, t0, t1, width):
    """The mass flow in each whole window of `width` [s] from t0 up to t1: the rise of
    the cumulative mass m(t) (interpolated at the window edges) over the width."""
    t, m = np.asarray(t, float), np.asarray(m, float)
    n = int(np.floor((t1 - t0) / width + 1e-9))
    if n < 1:
        raise CaseError(f"window_rates: the window {t0:g}..{t1:g} s holds no whole {width:g} s window")
    edges = t0 + width * np.arange(n + 1)
    return np.diff(np.interp(edges, t, m)) / width


def analyse(runs, outlet, at, exponent=2.5):
    """The size fit over `runs` (dicts with s, d [m], W and se [kg/s]; sorted by d here)
    and the fit through every pair of them (how much one run moves the answer). Adds
    residual_sigma and line_W (the fit's W at the run's d) to each run. Returns
    dict(fit=..., pairs=[{s: [s_i, s_j], k, W, se}], leave_one_out=[{without_s, k, W, se,
    chi2, dof}] (the fit without each run, with three runs or more)): the fit's entries as
    fits.beverloo_size's (W at d = at: w_at, w_at_se), without the residuals."""
    if len(runs) < 2:
        raise CaseError(f"size study: {len(runs)} run(s); the size fit needs two or more")
    runs.sort(key=lambda r: r["d"])
    d, w, se = (np.array([r[k] for r in runs]) for k in ("d", "W", "se"))
    fit = fits.beverloo_size(d, w, se, outlet, at, exponent)
    for r, res in zip(runs, fit.pop("residuals")):
        r["residual_sigma"] = res
        r["line_W"] = max(fit["b0"] + fit["b1"] * r["d"], 0.0) ** exponent
    pairs = []
    for i in range(len(runs)):
        for j in range(i + 1, len(runs)):
            f2 = fits.beverloo_size(d[[i, j]], w[[i, j]], se[[i, j]], outlet, at, exponent)
            pairs.append(dict(s=[runs[i]["s"], runs[j]["s"]], k=f2["k"], W=f2["w_at"], se=f2["w_at_se"]))
    drop = []       # the fit without each run in turn (three or more runs): how much one run moves the answer
    for i in range(len(runs)) if len(runs) >= 3 else ():
        keep = [j for j in range(len(runs)) if j != i]
        f = fits.beverloo_size(d[keep], w[keep], se[keep], outlet, at, exponent)
        drop.append(dict(without_s=runs[i]["s"], k=f["k"], W=f["w_at"], se=f["w_at_se"], chi2=f["chi2"], dof=f["dof"]))
    return dict(fit=fit, pairs=pairs, leave_one_out=drop)



def seed_repeats(runs, repeats, outlet, at, exponent=2.5):
    """Runs with another packing seed (not in the fit) against the run of their s in `runs`:
    each repeat that has one gets W_seed1, se_seed1 and z, their difference in units of the
    combined standard error (does the window error cover the run-to-run scatter?). Returns
    (those repeats, the size fit over runs and repeats together, or None without repeats)."""
    seeds = []
    for r in repeats:
        ref = next((x for x in runs if abs(x["s"] - r["s"]) < 1e-9), None)
        if ref:
            r.update(W_seed1=ref["W"], se_seed1=ref["se"], z=(r["W"] - ref["W"]) / math.hypot(r["se"], ref["se"]))
            seeds.append(r)
    if not seeds:
        return seeds, None
    every = runs + seeds
    return seeds, fits.beverloo_size([r["d"] for r in every], [r["W"] for r in every], [r["se"] for r in every],
                                     outlet, at, exponent)

def plot_fit(ax, runs, res, at, at_label, target):
    """The fit line (W^(1/n) linear in d, drawn as W), the runs with their standard
    errors, W extrapolated to d = at (`at_label`, e.g. "660 µm") with its error, the band
    of +- `target` about it and the pairs' extrapolations (x). Returns the line's x range [m]."""
    fit, n = res["fit"], res["fit"]["exponent"]
    x = np.linspace(0.0, max(r["d"] for r in runs) * 1.1, 200)
    ax.plot(x * 1e3, np.clip(fit["b0"] + fit["b1"] * x, 0.0, None) ** n, "k-", lw=1,
            label=f"Beverloo size fit, W^(1/{n:g}) linear in d: k = {fit['k']:.2f} ± {fit['k_se']:.2f}")
    ax.errorbar([r["d"] * 1e3 for r in runs], [r["W"] for r in runs], yerr=[r["se"] for r in runs], fmt="o",
                color="tab:blue", capsize=3, label="cg-DEM at s = " + ", ".join(f"{r['s']:.3g}" for r in runs) + " (± s.e.)")
    ax.errorbar([at * 1e3], [fit["w_at"]], yerr=[fit["w_at_se"]], fmt="s", color="k", capsize=4,
                label=f"extrapolated to {at_label}: {fit['w_at']:.4f} ± {fit['w_at_se']:.4f} kg/s")
    ax.axhspan(fit["w_at"] * (1 - target), fit["w_at"] * (1 + target), color="0.85", zorder=0,
               label=f"± {100 * target:g} % of it (issue 16)")
    for p in res["pairs"]:
        ax.plot([at * 1e3], [p["W"]], "x", color="0.4", ms=5)
    return x


def against(levels, runs, w, w_se, target):
    """Each of another level's runs ({d: the grain size its I uses, W}, e.g. the continuum's)
    against the size-converged DEM rate w +- w_se: the ratio, its band, the ratio to the DEM
    run of the same d if there is one, and whether the ratio is within 1 +- target. In place."""
    dem_at = {round(r["d"] * 1e6): r for r in runs}
    for c in levels:
        c["over_dem_converged"] = c["W"] / w
        c["over_dem_converged_band"] = [c["W"] / (w + w_se), c["W"] / (w - w_se)]
        same = dem_at.get(round(c["d"] * 1e6))
        c["over_dem_same_d"] = c["W"] / same["W"] if same else None
        c["within_target"] = abs(c["over_dem_converged"] - 1) <= target
    return levels


def against_line(c, model="calibrated mu(I)", target=0.15):
    """One printed line of a level's run after against(): its W as a multiple of the
    size-converged DEM's (and of the DEM run at the same d, if any)."""
    same = f", {c['over_dem_same_d']:.3f} x the DEM at that d" if c["over_dem_same_d"] else ""
    lo, hi = c["over_dem_converged_band"]
    return (f"continuum, {model}, d in I = {c['d'] * 1e6:.0f} um ({c['folder']}): W {c['W']:.4f} kg/s = "
            f"{c['over_dem_converged']:.3f} x the size-converged DEM ({lo:.3f}-{hi:.3f}){same}; "
            f"within {100 * target:g} %: {'yes' if c['within_target'] else 'no'}")
