#!/usr/bin/python3
"""Two-fluid (and continuum) runs of the wedge silo along the slot's axis: solid fraction,
the powder's vertical velocity and its frictional pressure against height
above the orifice, averaged over written times (issue 17's mesh study).

    axis_profile.py --run LABEL=RUN_DIR[@T1,T2,...] [--run ...] [--b 10]
                    [--times 0.5 1 1.5 | --at-mass G1 G2 ...] [--top 4] [--out DIR]

Why: the calibrated two-fluid's dry rate falls by a quarter from 4 to 6
cells across the slot at b = 10 mm (README, "At b = 10 mm on b/6") while
the single-phase continuum's stays within 1.5 % over 6-24 cells. This
shows where along the axis the runs part: in the stress-free arch over the
orifice (pf = 0, free fall) or in the dense flow above it.

RUN_DIR is a two-fluid run folder (twofluid.py's OUT/runs/b<B>_air or
_noair: time folders of alpha.particles, U.particles, pf.particles on an
ASCII mesh) or a continuum one (continuum.py --write-every's OUT/runs/...:
alpha.powder times the fill's packing, U, and p as "pf", the powder's
pressure in a dry run), so the two levels can be set side by side on the
same mesh; fields are interpolated linearly between cell centres onto
x = 0 (gc.foam.line_profile) from z = -b/2 to 4b, and averaged over
--times, over the run's own times after `@`, or (--at-mass) over the
written times nearest to those at which each run had discharged G1, G2, ...
grams (a faster run's fill is lower at a given time; from its outlet and
free-fall flow files, gc.two_fluid.out_flow). Writes
DIR/axis_profile.{csv,md,png} (default build/axis-profile).
"""
import argparse
import json
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
import granair_cases as gc  # noqa: E402

FIELDS = ["alpha.particles", "U.particles", "pf.particles"]
COLUMNS = [("alpha", "alpha.particles"), ("w", "U.particles_z"), ("pf", "pf.particles")]


# A continuum run (granairContinuumFoam, continuum.py --write-every): its VOF
# powder fraction times the fill's packing (silo.json RHO_B / RHO_P), its
# velocity, and its pressure p, the powder's in a dry run
CONTINUUM_FIELDS = ["alpha.powder", "U", "p"]
CONTINUUM_COLUMNS = [("alpha", "alpha.powder"), ("w", "U_z"), ("pf", "p")]


def is_continuum(run):
    """Whether a run folder is the continuum level's (its fields are alpha.powder, U, p)."""
    return any(os.path.exists(os.path.join(d, "alpha.powder")) for _, d in gc.foam.time_dirs(run))


def profile(run, times, z):
    """{column: mean over times} on the axis at heights z [m] (a two-fluid or a continuum run)."""
    continuum = is_continuum(run)
    fields, columns = (CONTINUUM_FIELDS, CONTINUUM_COLUMNS) if continuum else (FIELDS, COLUMNS)
    scale = {c: 1.0 for c, _ in COLUMNS}
    if continuum:
        with open(os.path.join(run, "silo.json")) as fh:
            silo = json.load(fh)
        scale["alpha"] = silo["RHO_B"] / silo["RHO_P"]
    sums = {c: np.zeros_like(z) for c, _ in COLUMNS}
    for t in times:
        f = gc.foam.line_profile(run, t, fields, [(0.0, zi) for zi in z])
        for c, key in columns:
            sums[c] += scale[c] * f[key]
    return {c: v / len(times) for c, v in sums.items()}


def mass_times(run, grams):
    """The written times of a run nearest to those at which it had discharged each of `grams`."""
    flow = gc.two_fluid.out_flow(run)
    if flow is None:
        raise gc.CaseError(f"{run}: no outlet and free-fall flow files (postProcessing/*Flow)")
    t, rate = flow
    out = gc.two_fluid.mass_out(t, rate)
    written = np.array([tt for tt, _ in gc.foam.time_dirs(run)])
    picked = []
    for g in grams:
        if not out[-1] >= g * 1e-3:
            raise gc.CaseError(f"{run}: {out[-1] * 1e3:.1f} g out by t = {t[-1]:g} s, not {g:g} g")
        picked.append(float(written[np.argmin(np.abs(written - np.interp(g * 1e-3, out, t)))]))
    return picked


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--run", action="append", required=True, metavar="LABEL=RUN_DIR[@T1,T2,...]")
    ap.add_argument("--b", type=float, default=10.0, help="slot width [mm] (default 10)")
    ap.add_argument("--times", type=float, nargs="+", default=[0.5, 1.0, 1.5])
    ap.add_argument("--at-mass", type=float, nargs="+", metavar="G",
                    help="each run's written times nearest to G grams discharged (instead of --times)")
    ap.add_argument("--top", type=float, default=4.0, help="highest height in slot widths (default 4)")
    ap.add_argument("--out", default=os.path.join(HERE, "..", "..", "build", "axis-profile"))
    a = ap.parse_args()
    runs, times = [], {}
    for item in a.run:
        label, sep, rest = item.partition("=")
        path, at, own = rest.partition("@")
        if not sep or not os.path.isdir(path):
            ap.error(f"--run {item}: expected LABEL=RUN_DIR[@T1,T2,...] with an existing run folder")
        try:
            times[label] = ([float(t) for t in own.split(",")] if at else
                            mass_times(path, a.at_mass) if a.at_mass else a.times)
        except ValueError:
            ap.error(f"--run {item}: expected times [s] after @, separated by commas")
        except gc.CaseError as e:
            ap.error(f"--run {item}: {e}")
        runs.append((label, path))
    b = a.b * 1e-3
    z = np.arange(-0.5 * b, a.top * b + 1e-12, 0.05 * b)
    prof = {label: profile(path, times[label], z) for label, path in runs}
    when = {label: ", ".join(f"{t:g}" for t in times[label]) for label, _ in runs}

    os.makedirs(a.out, exist_ok=True)
    header = ["z_mm"] + [f"{label}:{c}" for label, _ in runs for c, _ in COLUMNS]
    rows = [[zi * 1e3] + [prof[label][c][i] for label, _ in runs for c, _ in COLUMNS] for i, zi in enumerate(z)]
    gc.template.write(os.path.join(a.out, "axis_profile.csv"),
                      ",".join(header) + "\n" + "".join(",".join(f"{v:.6g}" for v in r) + "\n" for r in rows))

    # The table: at the orifice and 1-3 b above it; the arch's top as the
    # lowest height above which pf > 0 all the way up.
    lines = [f"# Runs on the slot's axis, b = {a.b:g} mm", "",
             "Written by `axis_profile.py` (its docstring). w: the powder's vertical velocity [m/s]; pf: the "
             "frictional pressure [Pa] (a continuum run's p); arch top: the lowest height above which pf > 0; each run's mean over the "
             "times given.", "",
             "| run | t [s] | arch top [mm] | " + " | ".join(f"alpha, w, pf at z = {k:g} b" for k in (0, 1, 2, 3)) + " |",
             "|---|---|---:|" + "---:|" * 4]
    for label, _ in runs:
        p = prof[label]
        stressed = np.nan_to_num(p["pf"]) > 0
        top = next((z[i] for i in range(len(z)) if stressed[i:].all()), np.nan)
        cells = []
        for k in (0, 1, 2, 3):
            i = int(np.argmin(np.abs(z - k * b)))
            cells.append(f"{p['alpha'][i]:.3f}, {p['w'][i]:+.3f}, {p['pf'][i]:.1f}")
        lines.append(f"| {label} | {when[label]} | {top * 1e3:.1f} | " + " | ".join(cells) + " |")
    gc.template.write(os.path.join(a.out, "axis_profile.md"), "\n".join(lines) + "\n")
    print("\n".join(lines))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(12, 4.5), sharey=True)
    for label, _ in runs:
        for ax, (c, _) in zip(axes, COLUMNS):
            ax.plot(prof[label][c], z * 1e3, label=f"{label} (t = {when[label]} s)")
    for ax, name in zip(axes, ["solid fraction", "w [m/s]", "pf [Pa]"]):
        ax.set_xlabel(name)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("height above the orifice [mm]")
    axes[0].legend(fontsize=8)
    fig.suptitle(f"runs on the slot's axis, b = {a.b:g} mm")
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "axis_profile.png"), dpi=120)


if __name__ == "__main__":
    main()
