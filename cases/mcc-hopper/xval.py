#!/usr/bin/python3
"""The continuum with the DEM-calibrated mu(I) against the coarse-grained DEM
(README, "Cross-validation with the DEM-calibrated mu(I)"): W against the
mesh N of the calibrated runs (results/calibrated/, N = 28, and
results/calibrated/N<n>/, `./Allrun --rheology-from calibration --mesh N
--out ...`) and of the literature mesh study (results/convergence/), with the
DEM's rate (reference-cg-dem/) and issue 16's +-15 % band.
Writes results/calibrated/xval.{csv,png}.

    xval.py [--out DIR]
"""
import csv
import json
import os

import granair_cases as gc

HERE = os.path.dirname(os.path.abspath(__file__))
TARGET = 0.15


def main():
    ap = gc.cli.parser(__doc__)
    a = gc.cli.parse(ap, os.path.join(HERE, "results", "calibrated"))
    dem = gc.series.read_keys(os.path.join(HERE, "reference-cg-dem", "summary.txt"))
    w_dem, sd_dem = float(dem["steady_mass_flow_kg_s"]), float(dem["window_mass_flow_sd_kg_s"])
    cal = os.path.join(HERE, "results", "calibrated")
    rows = []
    for res in [cal] + [os.path.join(cal, n) for n in sorted(os.listdir(cal)) if n.startswith("N") or n == "d660um"]:
        if not os.path.exists(os.path.join(res, "summary.txt")):
            continue
        s = gc.series.read_keys(os.path.join(res, "summary.txt"))
        with open(os.path.join(res, "settings.json")) as fh:
            run = json.load(fh)
        n, d = run["mesh"], run.get("rheology_d") or 3.3e-3    # the parcel d unless --rheology-d
        w = float(s["steady_mass_flow_kg_s"])
        kind = "calibrated" if d == 3.3e-3 else f"calibrated, d = {d * 1e6:.0f} um"
        rows.append(dict(rheology=kind, N=n, orifice_cell_mm=25.0 / n, cell_over_d=25e-3 / n / d,
                         W_kg_s=w, W_sd_kg_s=float(s["window_mass_flow_sd_kg_s"]), W_over_dem=w / w_dem,
                         mass_balance=float(s["mass_balance_error"]), cpu_s=float(s["run_cpu_s"])))
    with open(os.path.join(HERE, "results", "convergence", "convergence.csv")) as fh:
        lit = list(csv.DictReader(fh))
    for x in lit:
        if x["tag"][1:].isdigit():         # the mesh sequence, not the sensitivity runs
            rows.append(dict(rheology="literature", N=int(x["N"]), orifice_cell_mm=float(x["orifice_cell_mm"]),
                             cell_over_d=float(x["orifice_cell_mm"]) / 0.66, W_kg_s=float(x["W"]),
                             W_sd_kg_s=float(x["W_sd"]), W_over_dem=float(x["W"]) / w_dem,
                             mass_balance=float(x["mass_balance"]), cpu_s=float(x["cpu_s"])))
    rows.sort(key=lambda r: (r["rheology"], r["N"]))
    gc.series.write_rows(os.path.join(a.out, "xval.csv"), rows, "{:.6g}")
    plt = gc.plots.pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.2))
    ax.axhspan(w_dem * (1 - TARGET), w_dem * (1 + TARGET), color="0.85", label="cg-DEM +-15 % (issue 16 target)")
    ax.axhline(w_dem, color="k", lw=1.2, label=f"cg-DEM s = 5 (3.3 mm parcels): {w_dem * 1e3:.1f} g/s "
                                                f"(sd of 50 ms means {sd_dem * 1e3:.1f})")
    for kind, style, label in (("calibrated", "o-", "continuum, DEM-calibrated mu(I), d = 3.3 mm"),
                               ("literature", "s--", "continuum, Remmelgas et al. mu(I), d = 0.66 mm")):
        r = [x for x in rows if x["rheology"] == kind]
        ax.plot([x["N"] for x in r], [x["W_kg_s"] for x in r], style, label=label)
    for r in rows:
        if r["rheology"] not in ("calibrated", "literature"):
            ax.plot([r["N"]], [r["W_kg_s"]], "^", color="tab:green", label=f"continuum, DEM-calibrated mu(I), {r['rheology'][12:]}")
    ax.axvline(25 / 3.3, color="tab:blue", lw=0.6, ls=":")
    ax.text(25 / 3.3 + 0.3, 0.07, "cells = 3.3 mm", fontsize=7, color="tab:blue")
    ax.set(xlabel="N, cells across the 25 mm orifice", ylabel="steady mass flow W [kg/s]", ylim=(0, 0.2),
           xlim=(6, 30), title="MCC hopper, dry, Coulomb walls mu_w 0.3 (the DEM's particle-wall friction)")
    ax.title.set_fontsize(9)
    ax.legend(fontsize=7, loc="lower right")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(a.out, "xval.png"))
    for r in rows:
        print(f"{r['rheology']:22s} N = {r['N']:2d} ({r['orifice_cell_mm']:.2f} mm = {r['cell_over_d']:.2f} d): "
              f"W {r['W_kg_s']:.4f} kg/s = {r['W_over_dem']:.3f} x cg-DEM")


if __name__ == "__main__":
    gc.cli.main(main)
