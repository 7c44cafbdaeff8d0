#!/usr/bin/python3
"""The full depth against the periodic slice (issue 22), from the committed series:
the demo b = 10 mm runs of the silo's whole 60 mm depth between front and back walls
(study.py --full-depth, reference-full-depth/) against the slice's (reference-demo/).
Over each run's steady window (its level file's, as study.py's summary
gives W and dp/dz): W with its standard error from 25 ms rates (the rates' scatter, not the
seed-to-seed one), the air effect, the outlet dp/dz. Writes
reference-full-depth/full_depth.{md,png}.

    full_depth.py
"""
import csv
import os

import numpy as np

import granair_cases as gc

HERE = os.path.dirname(os.path.abspath(__file__))
FULL, SLICE = os.path.join(HERE, "reference-full-depth"), os.path.join(HERE, "reference-demo")
RATE_WINDOW = 0.025     # [s] the windows of the rates whose scatter gives W's standard error
LEVELS = (("slice", SLICE, "periodic slice, 5842 parcels, one air cell deep"),
          ("full depth", FULL, "full 60 mm depth, 70103 parcels, 11 air cells deep"))


def run(folder, name):
    s = gc.series.read_csv(os.path.join(folder, f"{name}.csv"))
    t = s["t"]
    t0, t1 = gc.levels.read(os.path.join(folder, f"{name}.level.json"))["steady_window_s"]
    rates = gc.size_study.window_rates(t, s["discharged_kg"], t0, t1, RATE_WINDOW)
    sel = (t >= t0) & (t <= t1)
    _, (g,) = gc.series.window_means(t[sel], gc.series.step_lengths(t[sel], t0), [s["outlet_dpdz_Pa_m"][sel]],
                                     RATE_WINDOW)
    with open(os.path.join(folder, "summary.csv")) as fh:
        row = next(r for r in csv.DictReader(fh) if r["run"] == name)
    return dict(s=s, W=float(row["W_kg_s"]), se=float(rates.std(ddof=1) / np.sqrt(len(rates))), window=(t0, t1),
                dpdz=float(row["outlet_dpdz_Pa_m"]), dpdz_se=float(g.std(ddof=1) / np.sqrt(len(g))))


def main():
    ap = gc.cli.parser(__doc__)
    a = gc.cli.parse(ap, FULL)
    r = {(lv, air): run(folder, f"b10_{air}") for lv, folder, _ in LEVELS for air in ("air", "noair")}
    windows = {"%.3g-%.3g s" % x["window"] for x in r.values()}
    lines = ["# Wedge silo b = 10 mm, demo settings: the full depth against the periodic slice", "",
             f"Steady window {', '.join(sorted(windows))}; W ± the standard error of its {RATE_WINDOW * 1e3:g} ms rates; "
             "mass flows of the slice scaled to the full 60 mm depth (depthScale).", "",
             "| level | W with air [kg/s] | W dry [kg/s] | air effect | outlet dp/dz [Pa/m] |", "|---|---|---|---|---|"]
    for lv, _, what in LEVELS:
        wet, dry = r[lv, "air"], r[lv, "noair"]
        lines.append(f"| {lv} ({what}) | {wet['W']:.4f} ± {wet['se']:.4f} | {dry['W']:.4f} ± {dry['se']:.4f} | "
                     f"{100 * (wet['W'] / dry['W'] - 1):+.1f} % | {wet['dpdz']:.0f} ± {wet['dpdz_se']:.0f} |")

    def over(key, se, air):       # full depth / slice of one quantity, with its error
        f, sl = r["full depth", air], r["slice", air]
        q = f[key] / sl[key]
        return f"{q:.3f} ± {q * np.hypot(f[se] / f[key], sl[se] / sl[key]):.3f}"
    lines += [f"| full depth / slice | {over('W', 'se', 'air')} | {over('W', 'se', 'noair')} | | "
              f"{over('dpdz', 'dpdz_se', 'air')} |", "",
              "W and dp/dz over the steady window as study.py's summary.csv gives them; the errors are the "
              "scatter of the 25 ms means within the window (one run each, one packing seed: the seed-to-seed "
              "scatter of the slice's DEM-only W is 1-2 %, README \"Parcel-size convergence\").", ""]
    with open(os.path.join(a.out, "full_depth.md"), "w") as fh:
        fh.write("\n".join(lines))
    print("\n".join(lines))

    plt = gc.plots.pyplot()
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 4.2))
    for (lv, air), x in sorted(r.items()):
        t, dt = x["s"]["t"], gc.series.step_lengths(x["s"]["t"])
        c, (w, g) = gc.series.window_means(t, dt, [x["s"]["mass_flow_kg_s"], x["s"]["outlet_dpdz_Pa_m"]], 0.025)
        style = dict(color="tab:red" if air == "air" else "tab:blue", ls="-" if lv == "full depth" else "--", lw=1.2)
        label = f"{lv}, {'with air' if air == 'air' else 'dry'}"
        ax.plot(c, w, label=label, **style)
        if air == "air":
            bx.plot(c, g, label=label, **style)
    ax.axvspan(*r["full depth", "air"]["window"], color="0.9", zorder=0, label="steady window")
    ax.set(xlabel="t [s]", ylabel="W [kg/s], full 60 mm depth (25 ms means)", ylim=(0, None))
    bx.set(xlabel="t [s]", ylabel="outlet air dp/dz [Pa/m] (25 ms means)")
    for x in (ax, bx):
        x.grid(alpha=0.3)
        x.legend(fontsize=8)
    fig.suptitle("Wedge silo b = 10 mm (demo): full depth between walls (solid) against the periodic slice (dashed)",
                 fontsize=10)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(a.out, "full_depth.png"))
    return 0


if __name__ == "__main__":
    gc.cli.main(main)
