#!/usr/bin/python3
"""The coarse-grained DEM of the wedge silo converged in parcel size at b = 10 mm
(README, "Parcel-size convergence of the DEM"), and the calibrated continuum against it.

The DEM-only runs at several s (`study.py --size demo --b 10 --runs noair --s S`, every
other setting the demo's; the small results of each in reference-parcel-size/s<S>/):
each run's W is the case's own steady rate (the slope of the discharged mass over its
steady window, level.json), its standard error that of the rates in the window's
WINDOW-wide sub-windows (gc.fits.mean_se: sd / sqrt(n), inflated for their lag-1
autocorrelation). Hagen-Beverloo's size term for a slot, W = C rho_b sqrt(g) L (b - k d)^1.5
at fixed b, makes W^(2/3) linear in the parcel d (gc.size_study.analyse, exponent 1.5);
the line is extrapolated to the primary lactose d, the number mean of the case's PSD
(parameters.py psd_moments: 218 um; the parcels are s times it). Every pair of sizes is
extrapolated too, the fit is repeated without each run in turn and over the three finest
sizes alone, and the circular form
(exponent 2.5) is fitted as the form's sensitivity. Runs with another packing seed
(reference-parcel-size/seed<n>/s<S>/, `--seed n`) are not in the fit: each is compared
with the seed-1 run of its size in units of their combined standard error (does the
window error cover the run-to-run scatter?), and the fit is repeated over all runs.

The calibrated continuum (`continuum.py --rheology-from calibration --dem-size demo --b 10
--air off`, N = 12) at the grain size its I uses (reference-continuum-calibrated-demo/
itself: the demo parcels, 1.67 mm; d<um>um/: `--rheology-d`) against the size-converged DEM.

Writes reference-parcel-size/parcel_size.{json,csv,png} and converged/level.json (the
extrapolated rate as a cg-dem level of `./granair compare`, without a time series).

    parcel_size.py [--out DIR]
"""
import argparse
import glob
import json
import math
import os
import re

import numpy as np

import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))
DEM = os.path.join(HERE, "reference-parcel-size")
CONTINUUM = os.path.join(HERE, "reference-continuum-calibrated-demo")
B_MM = 10
WINDOW = 0.025      # sub-window of the error [s]: 10 of them in the demo's 0.25 s steady window
TARGET = 0.15       # issue 16: the continuum within 15 % of the DEM


def dem_runs(pattern="s[0-9]*"):
    """The DEM-only runs at b = 10 mm, one per folder matching `pattern` under DEM (default the
    seed-1 runs, one per s): [{s, d, W, se, sd, n, rho_b, parcels, cpu, folder}]."""
    out = []
    for folder in sorted(glob.glob(os.path.join(DEM, pattern))):
        lv = os.path.join(folder, f"b{B_MM}_noair.level.json")
        with open(lv) as fh:
            level = json.load(fh)
        if level["air"] or level["b_mm"] != B_MM or "demo size" not in level["model"]:
            raise gc.CaseError(f"{lv}: {level['model']}, b = {level['b_mm']} mm, air {level['air']}; "
                               f"the size study needs the demo's DEM-only runs at b = {B_MM} mm")
        c = gc.series.read_csv(os.path.join(folder, level["timeseries"]))
        if abs(c["t"][-1] - P.SIZES["demo"]["t_end"]) > 1e-6:
            raise gc.CaseError(f"{folder}: the run ends at {c['t'][-1]:g} s, the demo's at {P.SIZES['demo']['t_end']:g} s")
        t0, t1 = level["steady_window_s"]
        rates = gc.size_study.window_rates(c["t"], c["discharged_kg"], t0, t1, WINDOW)
        _, se = gc.fits.mean_se(rates)
        row = next(r for r in gc.series.read_table(os.path.join(folder, "summary.csv")) if r["run"] == f"b{B_MM}_noair")
        with open(os.path.join(folder, "timings.json")) as fh:
            cpu = sum(t["cpu_s"] for t in json.load(fh).values())
        s = level["coarse_graining_factor"]
        out.append(dict(s=s, d=s * P.psd_moments()[0], W=level["steady_mass_flow_kg_s"], se=se,
                        sd=float(np.std(rates, ddof=1)), n=int(rates.size), window_s=[t0, t1],
                        rho_b=float(row["rho_b_kg_m3"]), parcels=int(row["inserted"]), cpu=cpu,
                        folder=os.path.relpath(folder, HERE)))
    return out


def continuum_runs():
    """The calibrated continuum at b = 10 mm, dry, N = 12, the demo's fill: [{d, W, folder}];
    d the grain size in I (the run's silo.json, else the folder's name d<um>um, else the
    demo parcels' b / 6)."""
    out = []
    for folder in [CONTINUUM] + sorted(glob.glob(os.path.join(CONTINUUM, "d*um*"))):
        p = os.path.join(folder, "summary.csv")
        if not os.path.exists(p):
            continue
        row = next((r for r in gc.series.read_table(p) if r["run"] == f"b{B_MM}_noair"), None)
        if row is None:
            continue
        silo = os.path.join(folder, f"b{B_MM}_noair", "silo.json")
        m = re.match(r"d(\d+)um", os.path.basename(folder))
        if os.path.exists(silo):
            with open(silo) as fh:
                d = json.load(fh)["D_LACTOSE"]
        elif m:
            d = float(m.group(1)) * 1e-6
        else:
            d = B_MM * 1e-3 / P.SIZES["demo"]["per_b"][B_MM]["b_over_d"]
        out.append(dict(d=float(d), W=float(row["W_kg_s"]), dilatancy="dilatancy" in os.path.basename(folder),
                        folder=os.path.relpath(folder, HERE)))
    return sorted(out, key=lambda r: (r["d"], r["dilatancy"]))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=DEM, help="output folder (default reference-parcel-size/)")
    a = ap.parse_args()
    b, d0 = B_MM * 1e-3, P.psd_moments()[0]
    runs = dem_runs()
    size = gc.size_study.analyse(runs, b, d0, exponent=1.5)         # a slot: Hagen-Beverloo's 1.5
    fit, pairs = size["fit"], size["pairs"]
    rho_b = float(np.mean([r["rho_b"] for r in runs]))
    fit["C"] = (fit["b0"] / b) ** 1.5 / (rho_b * math.sqrt(P.G) * P.DEPTH)
    # repeats with another packing seed (seed<n>/s<S>/): not in the fit
    seeds, fit_all = gc.size_study.seed_repeats(runs, dem_runs(os.path.join("seed[0-9]*", "s[0-9]*")), b, d0, 1.5)
    # the three finest sizes alone (nearest the primary d; runs are sorted by d)
    fine = gc.fits.beverloo_size([r["d"] for r in runs[:3]], [r["W"] for r in runs[:3]], [r["se"] for r in runs[:3]],
                                 b, d0, 1.5) if len(runs) > 3 else None
    circ = gc.fits.beverloo_size([r["d"] for r in runs], [r["W"] for r in runs], [r["se"] for r in runs], b, d0, 2.5)
    w_ext, w_ext_se = fit["w_at"], fit["w_at_se"]
    bev = gc.closed_forms.beverloo_band("slot", b, d0, rho_b, P.K_RANGE, P.BEVERLOO_C, P.DEPTH)
    cont = continuum_runs()
    gc.size_study.against(cont, runs, w_ext, w_ext_se, TARGET)
    result = dict(
        form="W^(2/3) = b0 + b1 d (Hagen-Beverloo slot, W = C rho_b sqrt(g) L (b - k d)^1.5 at b = 10 mm, L = 60 mm); "
             f"weighted least squares, sigma_W = standard error of the {WINDOW * 1e3:g} ms window rates in the steady "
             "window (AR(1)-inflated); w_at_se scaled by the Birge ratio when > 1",
        primary_d_m=d0, runs=runs, fit=fit, mean_settled_bulk_density_kg_m3=rho_b, pairs=pairs,
        leave_one_out=size["leave_one_out"], seed_repeats=seeds, fit_all_seeds=fit_all,
        finest_three=dict({k: v for k, v in fine.items() if k != "residuals"}, s=[r["s"] for r in runs[:3]]) if fine else None,
        circular_form_sensitivity={k: v for k, v in circ.items() if k != "residuals"},
        hagen_beverloo_primary_kg_s=[bev[0], bev[1]], dem_size_converged_kg_s=w_ext,
        dem_size_converged_se_kg_s=w_ext_se, continuum=cont, target=TARGET)
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "parcel_size.json"), "w") as fh:
        json.dump(result, fh, indent=1)
        fh.write("\n")
    gc.series.write_rows(os.path.join(a.out, "parcel_size.csv"),
                         [dict(s=f"{r['s']:.4g}", d_mm=f"{r['d'] * 1e3:.4g}", b_over_d=f"{b / r['d']:.3g}",
                               W_kg_s=f"{r['W']:.5g}", W_se_kg_s=f"{r['se']:.2g}", window_sd_kg_s=f"{r['sd']:.2g}",
                               line_W_kg_s=f"{r['line_W']:.5g}", residual_sigma=f"{r['residual_sigma']:+.2f}",
                               settled_bulk_density_kg_m3=f"{r['rho_b']:.1f}", parcels=r["parcels"],
                               cpu_s=f"{r['cpu']:.0f}") for r in runs])
    plot(runs, size, cont, bev, d0, seeds, os.path.join(a.out, "parcel_size.png"))
    resid, sizes = (", ".join(f"{r[k]:{f}}" for r in runs) for k, f in (("residual_sigma", "+.2f"), ("s", ".3g")))
    # the extrapolation as a level of `./granair compare` (no time series: it is a fit, not a run)
    os.makedirs(os.path.join(a.out, "converged"), exist_ok=True)
    gc.levels.write(os.path.join(a.out, "converged", "level.json"), case="wedge-silo", level="cg-dem",
                    model=f"cg-DEM converged in parcel size: Hagen-Beverloo size fit over s = {sizes}, "
                          f"extrapolated to d = {d0 * 1e6:.0f} um (+- {w_ext_se:.4f} kg/s)",
                    b_mm=B_MM, air=False, steady_mass_flow_kg_s=w_ext, steady_window_s=runs[0]["window_s"],
                    outlet_dpdz_Pa_m=None, wall_time_s=None, cores=1, timeseries=None,
                    steady_mass_flow_se_kg_s=w_ext_se, cpu_s=sum(r["cpu"] for r in runs),
                    source="parcel_size.py, ../parcel_size.json")
    print(f"wedge-silo parcel size, b = {B_MM} mm: {len(runs)} DEM runs (s = {sizes}): "
          f"k = {fit['k']:.3f} +- {fit['k_se']:.3f}, C = {fit['C']:.3f}, chi2 {fit['chi2']:.2f} on {fit['dof']} dof "
          f"(Birge {fit['birge']:.2f}; residuals {resid} sigma); W at d = {d0 * 1e6:.0f} um {w_ext:.4f} +- {w_ext_se:.4f} kg/s")
    for r in runs:
        print(f"  s = {r['s']:.3g}: d {r['d'] * 1e3:.3f} mm (b/d {b / r['d']:.2f}), {r['parcels']} parcels, "
              f"W {r['W']:.5f} +- {r['se']:.5f} kg/s (sd of {r['n']} window rates {r['sd']:.4f}), line {r['line_W']:.5f}, "
              f"rho_b {r['rho_b']:.1f}, {r['cpu']:.0f} CPU-s")
    for p in pairs:
        print(f"  pair s = {p['s'][0]:.3g}, {p['s'][1]:.3g}: k = {p['k']:.3f}, W({d0 * 1e6:.0f} um) = {p['W']:.4f} +- {p['se']:.4f}")
    for x in size["leave_one_out"]:
        print(f"  without s = {x['without_s']:.3g}: k = {x['k']:.3f}, chi2 {x['chi2']:.2f} on {x['dof']} dof, "
              f"W({d0 * 1e6:.0f} um) = {x['W']:.4f} +- {x['se']:.4f}")
    for r in seeds:
        print(f"  seed repeat {r['folder']}: W {r['W']:.5f} +- {r['se']:.5f} against seed 1 {r['W_seed1']:.5f} +- "
              f"{r['se_seed1']:.5f}: difference {r['z']:+.2f} combined s.e.")
    if fit_all:
        print(f"  fit over all {len(runs) + len(seeds)} runs (seeds included): k = {fit_all['k']:.3f} +- {fit_all['k_se']:.3f}, "
              f"chi2 {fit_all['chi2']:.2f} on {fit_all['dof']} dof; W({d0 * 1e6:.0f} um) {fit_all['w_at']:.4f} +- "
              f"{fit_all['w_at_se']:.4f} kg/s")
    if fine:
        fine_s = [r["s"] for r in runs[:3]]
        print(f"  the three finest (s = {', '.join(f'{x:.3g}' for x in fine_s)}) alone: k = {fine['k']:.3f} +- "
              f"{fine['k_se']:.3f}, chi2 {fine['chi2']:.2f} on {fine['dof']} dof, W({d0 * 1e6:.0f} um) = {fine['w_at']:.4f} "
              f"+- {fine['w_at_se']:.4f}")
    print(f"  circular form (exponent 2.5) instead: k = {circ['k']:.3f}, chi2 {circ['chi2']:.2f}, W = {circ['w_at']:.4f} "
          f"+- {circ['w_at_se']:.4f}; Hagen-Beverloo at {d0 * 1e6:.0f} um (C = {P.BEVERLOO_C}, k = 1..3): "
          f"{bev[0]:.4f}..{bev[1]:.4f} kg/s")
    for c in cont:
        print("  " + gc.size_study.against_line(c, "calibrated mu(I)" + (", dilatancy" if c["dilatancy"] else ""), TARGET))


def plot(runs, size, cont, bev, d0, seeds, path):
    plt = gc.plots.pyplot()
    fig, (ax, lin) = plt.subplots(1, 2, figsize=(12, 4.6), gridspec_kw=dict(width_ratios=[1.6, 1]))
    x = gc.size_study.plot_fit(ax, runs, size, d0, f"{d0 * 1e6:.0f} µm", TARGET)
    # the fitted form itself: W^(1/n) against d, a straight line
    fit, n = size["fit"], size["fit"]["exponent"]
    lin.plot(x * 1e3, fit["b0"] + fit["b1"] * x, "k-", lw=1)
    lin.errorbar([r["d"] * 1e3 for r in runs], [r["W"] ** (1 / n) for r in runs],
                 yerr=[r["W"] ** (1 / n - 1) * r["se"] / n for r in runs], fmt="o", color="tab:blue", capsize=3)
    lin.plot([d0 * 1e3], [fit["w_at"] ** (1 / n)], "ks")
    lin.set(xlabel="parcel diameter d [mm]", ylabel=f"W^(1/{n:g}) [(kg/s)^(1/{n:g})]", xlim=(0, x[-1] * 1e3),
            title=f"the fitted form: chi2 {fit['chi2']:.2f} on {fit['dof']} dof")
    lin.grid(alpha=0.3)
    if seeds:
        ax.errorbar([r["d"] * 1e3 for r in seeds], [r["W"] for r in seeds], yerr=[r["se"] for r in seeds], fmt="o",
                    mfc="none", color="tab:blue", capsize=3, label="another packing seed (not in the fit)")
    for dil, mk in ((False, "D"), (True, "v")):
        cc = [c for c in cont if c["dilatancy"] == dil]
        if cc:
            ax.plot([c["d"] * 1e3 for c in cc], [c["W"] for c in cc], mk + "--", color="tab:red", ms=5, lw=0.8,
                    label="continuum, calibrated mu(I)" + (" + dilatancy" if dil else "") + ", N = 12, d in I")
    ax.plot([d0 * 1e3 + 0.08] * 2, bev, color="tab:orange", lw=4, alpha=0.5,
            label=f"Hagen-Beverloo, d = {d0 * 1e6:.0f} µm, C = {P.BEVERLOO_C}, k = 1..3 (beside it)")
    ax.set(xlabel="parcel (or grain) diameter d [mm]", ylabel="steady mass flow W [kg/s]", xlim=(0, x[-1] * 1e3),
           ylim=(0, 0.25), title=f"wedge silo, b = {B_MM} mm, demo, dry: cg-DEM against its parcel size (x: pairs)")
    ax.legend(loc="lower left", fontsize=7)
    fig.tight_layout()
    gc.plots.save(fig, path, dpi=110)


if __name__ == "__main__":
    gc.cli.main(main)
