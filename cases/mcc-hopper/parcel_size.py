#!/usr/bin/python3
"""The coarse-grained DEM converged in its resolution parameter, the parcel size
(README, "Parcel-size convergence of the DEM"), and the continuum against it.

The DEM runs at s = 4, 5, 6 (and 3 when it exists; `Allrun-dem --s S --out
reference-cg-dem/sS`, s = 5 in reference-cg-dem/ itself), the same 1000 g fill,
material and 0.5-1.5 s window: each run's W (the slope of the discharged mass)
and its standard error (fits.mean_se of its 50 ms window means: sd / sqrt(n),
inflated for their lag-1 autocorrelation). Beverloo's size term,
W = C rho_b sqrt(g) (D - k d)^2.5 at fixed D, makes W^0.4 linear in the parcel
d: gc.size_study.analyse (fits.beverloo_size) fits that line, checks the points against it (chi2, the
Birge ratio, residuals in sigmas), and extrapolates to the primary d = 660 um;
every pair of sizes is extrapolated too (how much one run moves the answer).
Runs with another packing seed (reference-cg-dem/seed<n>/s<S>/, `Allrun-dem
--s S --seed n`) are not in the fit: each is compared with the seed-1 run of
its size, the difference in units of their combined standard error (a test of
whether the window noise covers the run-to-run scatter), and the fit is repeated
over all runs, seeds included (`fit_all_seeds`).

The continuum with the DEM-calibrated mu(I) (results/calibrated/, N = 28) at the
grain size its I uses: d = 3.3 mm (the parcels the law was fitted on), 660 um
(d660um/) and any results/calibrated/d<um>um/ run (`Allrun --rheology-from
calibration --rheology-d D --out ...`), each against the size-converged DEM and
against the DEM run at the same d where there is one.

Writes reference-cg-dem/parcel_size.{json,csv,png}.

    parcel_size.py [--out DIR]
"""
import argparse
import glob
import json
import math
import os

import numpy as np

import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))
DEM = os.path.join(HERE, "reference-cg-dem")
CALIBRATED = os.path.join(HERE, "results", "calibrated")
TARGET = 0.15          # issue 16: the continuum within 15 % of the DEM


def dem_runs(folders=None):
    """The DEM runs at each s (seed 1; or those in `folders`):
    [{s, d, W, se, sd, n, rho_b, cpu, folder}], by d."""
    out = []
    for folder in folders or [DEM] + sorted(glob.glob(os.path.join(DEM, "s[0-9]*"))):
        p = os.path.join(folder, "summary.txt")
        if not os.path.exists(p):
            continue
        k = gc.series.read_keys(p)
        if k["fill_g"] != 1000 or k["t_end_s"] < 1.5 - 1e-6 or k["steady_from_s"] != 0.5:
            raise gc.CaseError(f"{p}: fill {k['fill_g']:g} g, end {k['t_end_s']:g} s, window from "
                               f"{k['steady_from_s']:g} s; the size study needs 1000 g, 1.5 s, 0.5 s")
        c = gc.series.read_csv(os.path.join(folder, "mass_flow.csv"))
        sel = c["mass_flow_kg_s"][c["t"] >= k["steady_from_s"]]
        _, se = gc.fits.mean_se(sel)
        out.append(dict(s=k["coarse_graining_factor"], d=k["d_parcel_m"], W=k["steady_mass_flow_kg_s"], se=se,
                        sd=k["window_mass_flow_sd_kg_s"], n=int(sel.size), rho_b=k["settled_bulk_density_kg_m3"],
                        parcels=int(k["parcels_packed"]), cpu=k["total_cpu_s"],
                        folder=os.path.relpath(folder, HERE)))
    return sorted(out, key=lambda r: r["d"])


def continuum_runs():
    """The calibrated continuum at N = 28 and the grain size its I uses: [{d, W, folder}]."""
    out = []
    for folder in [CALIBRATED] + sorted(glob.glob(os.path.join(CALIBRATED, "d*um"))):
        p, s = os.path.join(folder, "summary.txt"), os.path.join(folder, "settings.json")
        if not (os.path.exists(p) and os.path.exists(s)):
            continue
        with open(s) as fh:
            st = json.load(fh)
        if st.get("rheology_from") != "calibration" or st.get("mesh") != 28 or st.get("orifice", P.D_OUTLET) != P.D_OUTLET:
            continue
        d = st.get("rheology_d") or gc.calibration.fit(P.CALIBRATION)["d"]
        out.append(dict(d=float(d), W=gc.series.read_keys(p)["steady_mass_flow_kg_s"], folder=os.path.relpath(folder, HERE)))
    return sorted(out, key=lambda r: r["d"])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=DEM, help="output folder (default reference-cg-dem/)")
    a = ap.parse_args()
    runs = dem_runs()
    if len(runs) < 2:
        raise gc.CaseError(f"{DEM}: {len(runs)} DEM run(s) with a summary.txt; the size fit needs two or more")
    size = gc.size_study.analyse(runs, P.D_OUTLET, P.D_PARTICLE)      # circular orifice: exponent 2.5
    fit, pairs = size["fit"], size["pairs"]
    rho_b = float(np.mean([r["rho_b"] for r in runs]))
    fit["C"] = (fit["b0"] / P.D_OUTLET) ** 2.5 / (rho_b * math.sqrt(P.G))
    w_ext, w_ext_se = fit["w_at"], fit["w_at_se"]
    seeds, fit_all = gc.size_study.seed_repeats(
        runs, dem_runs(sorted(glob.glob(os.path.join(DEM, "seed[0-9]*", "s[0-9]*")))), P.D_OUTLET, P.D_PARTICLE)
    cont = continuum_runs()
    gc.size_study.against(cont, runs, w_ext, w_ext_se, TARGET)
    result = dict(
        form="W^0.4 = b0 + b1 d (Beverloo, W = C rho_b sqrt(g) (D - k d)^2.5 at D = 25 mm); weighted least squares, "
             "sigma_W = standard error of the 50 ms window means (AR(1)-inflated); w_at_se scaled by the Birge ratio when > 1",
        primary_d_m=P.D_PARTICLE, runs=runs, fit=fit,
        mean_settled_bulk_density_kg_m3=rho_b, pairs=pairs,
        dem_size_converged_kg_s=w_ext, dem_size_converged_se_kg_s=w_ext_se, seed_repeats=seeds, fit_all_seeds=fit_all, continuum=cont,
        target=TARGET)
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "parcel_size.json"), "w") as fh:
        json.dump(result, fh, indent=1)
        fh.write("\n")
    gc.series.write_rows(os.path.join(a.out, "parcel_size.csv"),
                         [dict(s=r["s"], d_mm=r["d"] * 1e3, W_kg_s=r["W"], W_se_kg_s=r["se"], window_sd_kg_s=r["sd"],
                               line_W_kg_s=r["line_W"], residual_sigma=r["residual_sigma"],
                               settled_bulk_density_kg_m3=r["rho_b"], parcels=r["parcels"], cpu_s=r["cpu"])
                          for r in runs])
    plot(runs, fit, pairs, cont, seeds, os.path.join(a.out, "parcel_size.png"))
    sizes = ", ".join(f"{r['s']:g}" for r in runs)
    resid = ", ".join(f"{r['residual_sigma']:+.2f}" for r in runs)
    print(f"mcc-hopper parcel size: {len(runs)} DEM runs (s = {sizes}): "
          f"k = {fit['k']:.3f} +- {fit['k_se']:.3f}, C = {fit['C']:.3f}, chi2 {fit['chi2']:.2f} on {fit['dof']} dof "
          f"(residuals {resid} sigma); W at d = 660 um "
          f"{w_ext:.4f} +- {w_ext_se:.4f} kg/s")
    for p in pairs:
        print(f"  pair s = {p['s'][0]:g}, {p['s'][1]:g}: k = {p['k']:.3f}, W(660 um) = {p['W']:.4f} +- {p['se']:.4f}")
    for r in seeds:
        print(f"  seed repeat {r['folder']}: W {r['W']:.4f} +- {r['se']:.4f} against seed 1 {r['W_seed1']:.4f} +- "
              f"{r['se_seed1']:.4f}: difference {r['z']:+.2f} combined s.e.")
    if fit_all:
        print(f"  fit over all {len(runs) + len(seeds)} runs (seeds included): k = {fit_all['k']:.3f} +- "
              f"{fit_all['k_se']:.3f}, chi2 {fit_all['chi2']:.2f} on {fit_all['dof']} dof (Birge {fit_all['birge']:.2f}); "
              f"W at 660 um {fit_all['w_at']:.4f} +- {fit_all['w_at_se']:.4f} kg/s")
    for c in cont:
        print("  " + gc.size_study.against_line(c, target=TARGET))


def plot(runs, fit, pairs, cont, seeds, path):
    plt = gc.plots.pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 4.6))
    x = gc.size_study.plot_fit(ax, runs, dict(fit=fit, pairs=pairs), P.D_PARTICLE, "660 µm", TARGET)
    if seeds:
        ax.errorbar([r["d"] * 1e3 for r in seeds], [r["W"] for r in seeds], yerr=[r["se"] for r in seeds], fmt="o",
                    mfc="none", color="tab:blue", capsize=3, label="another packing seed (not in the fit)")
    if cont:
        ax.plot([c["d"] * 1e3 for c in cont], [c["W"] for c in cont], "D--", color="tab:red", ms=5, lw=0.8,
                label="continuum, calibrated mu(I), N = 28, d in I")
    bev = [P.beverloo(k) for k in (3, 1)]
    ax.axvline(P.D_PARTICLE * 1e3, color="tab:orange", lw=0.8, ls=":")
    ax.plot([P.D_PARTICLE * 1e3 - 0.12] * 2, bev, color="tab:orange", lw=4, alpha=0.5,
            label="Beverloo, d = 660 µm, k = 1..3 (beside it)")
    ax.set(xlabel="parcel (or grain) diameter d [mm]", ylabel="steady mass flow W [kg/s]", xlim=(0, x[-1] * 1e3),
           ylim=(0, 0.2), title="MCC hopper, D = 25 mm, 1000 g, dry: cg-DEM against its parcel size (x: pairs)")
    ax.legend(loc="lower left", fontsize=7)
    fig.tight_layout()
    gc.plots.save(fig, path, dpi=110)


if __name__ == "__main__":
    gc.cli.main(main)
