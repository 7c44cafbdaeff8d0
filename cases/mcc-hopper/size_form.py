#!/usr/bin/env python3
"""How much the size-converged DEM depends on the form of its extrapolation (issue 16).

    size_form.py [--out DIR]

parcel_size.py extrapolates the cg-DEM's W over its sizes (s = 3, 4, 5, 6) to
d = 660 um with Beverloo's size term alone (W^0.4 linear in d: the parcels'
k d annulus is the only size effect). The calibrated continuum says the material
law itself depends on d (I = gammaDot d / sqrt(p / rho_p)): its W at fixed
orifice falls with the d in I by f(d) = W_cont(d) / W_cont(660 um), with no
annulus. If the DEM's material has that dependence too, its W is f(d) times
Beverloo's, and the same fit of W / f(d) extrapolates to another W at 660 um
(f = 1 there).

The test between the forms: each is fitted to the s = 4, 5, 6 runs (where both
fit with chi2 ~ 0) and predicts the DEM at s = 3 (1.98 mm); the prediction
against the s = 3 run (reference-cg-dem/s3/), in units of their combined
standard error, says which form the finer parcels follow. Each form is then fitted over all sizes (chi2 on
n - 2 degrees of freedom). Every DEM size needs the continuum at its d in I
(`Allrun --rheology-from calibration --rheology-d D [--dilatancy] --out
results/calibrated/d<um>um[-dilatancy]`, ~1 CPU-min each).
Writes results/calibrated/size_form.{json,md}.
"""
import argparse
import json
import math
import os

import numpy as np

import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))
CAL = os.path.join(HERE, "results", "calibrated")
S3 = 1.98e-3   # the finest DEM size (s = 3): predicted by each form from s = 4, 5, 6, against its run
# the calibrated continuum at N = 28 by the d in I (the DEM sizes and the primaries): its folder under CAL
SERIES = {"without phi(I)": {660e-6: "d660um", 1.98e-3: "d1980um", 2.64e-3: "d2640um", 3.3e-3: ".", 3.96e-3: "d3960um"},
          "with phi(I)": {660e-6: "d660um-dilatancy", 1.98e-3: "d1980um-dilatancy", 2.64e-3: "d2640um-dilatancy",
                          3.3e-3: "d3300um-dilatancy", 3.96e-3: "d3960um-dilatancy"}}


def continuum_w(runs, d_needed):
    """The continuum's W by d in I for the DEM sizes d_needed and 660 um; a CaseError naming the missing run."""
    wc = {}
    for dd in [660e-6] + list(d_needed):
        key = min(runs, key=lambda k: abs(k - dd))
        path = os.path.join(CAL, runs[key], "summary.txt")
        if abs(key - dd) > 1e-6 or not os.path.exists(path):
            raise gc.CaseError(f"{path}: no calibrated continuum run at d = {dd * 1e6:.0f} um in I (expected from "
                               f"`Allrun --rheology-from calibration --rheology-d {dd:g} --out "
                               f"{os.path.relpath(os.path.dirname(path), HERE)}`)")
        wc[dd] = gc.series.read_keys(path)["steady_mass_flow_kg_s"]
    return wc


def fit_form(d, w, se, f, at):
    """Beverloo's size line through W / f(d) (f = 1: the pure form), extrapolated to d = at."""
    return gc.fits.beverloo_size(d, w / f, se / f, P.D_OUTLET, at)


def predicted(d, w, se, f_of, at):
    """The DEM at d = at (s = 3) from the runs at coarser parcels (s = 4, 5, 6), W = f(at) line(at)^2.5:
    dict(d, predicted, predicted_se) and, when a run at `at` exists, measured, measured_se and z
    (measured - predicted in units of their combined standard error)."""
    coarse = d > at * (1 + 1e-6)
    fit = gc.fits.beverloo_size(d[coarse], w[coarse] / f_of(d[coarse]), se[coarse] / f_of(d[coarse]), P.D_OUTLET, at)
    out = dict(d=at, predicted=float(f_of(np.array([at]))[0] * fit["w_at"]),
               predicted_se=float(f_of(np.array([at]))[0] * fit["w_at_se"]))
    i = np.flatnonzero(np.abs(d - at) < 1e-6 * at)
    if i.size:
        out.update(measured=float(w[i[0]]), measured_se=float(se[i[0]]),
                   z=float((w[i[0]] - out["predicted"]) / math.hypot(se[i[0]], out["predicted_se"])))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=CAL)
    a = ap.parse_args()
    with open(os.path.join(HERE, "reference-cg-dem", "parcel_size.json")) as fh:
        ps = json.load(fh)
    d = np.array([r["d"] for r in ps["runs"]])
    w = np.array([r["W"] for r in ps["runs"]])
    se = np.array([r["se"] for r in ps["runs"]])
    at = ps["primary_d_m"]
    ones = np.ones_like(d)
    pure = fit_form(d, w, se, ones, at)
    out = dict(dem_runs=dict(d=d.tolist(), W=w.tolist(), se=se.tolist()),
               pure=dict(k=pure["k"], k_se=pure["k_se"], w_at=pure["w_at"], w_at_se=pure["w_at_se"], chi2=pure["chi2"],
                         dof=pure["dof"]), series={})
    out["pure"]["s3"] = predicted(d, w, se, np.ones_like, S3)
    measured = "measured" in out["pure"]["s3"]
    sizes = ", ".join(f"{x * 1e3:.2f}" for x in d)
    lines = [f"DEM sizes d = {sizes} mm; fits over all of them (chi2 on {d.size - 2} dof)"
             + "; the DEM at s = 3 (1.98 mm) predicted from s = 4, 5, 6"
             + (" against its run (z: measured - predicted in combined standard errors)" if measured else ""),
             "", "| extrapolation form | continuum series | k | DEM W at 660 um [kg/s] | chi2 | continuum W at 660 um "
             "| continuum / DEM | s = 3 predicted [kg/s] |" + (" measured | z |" if measured else ""),
             "|---|---|---|---|---|---|---|---|" + ("---|---|" if measured else "")]

    def row(form, name, fit, w660, ho):
        r = (f"| {form} | {name} | {fit['k']:.3f} +- {fit['k_se']:.3f} | {fit['w_at']:.4f} +- {fit['w_at_se']:.4f} | "
             f"{fit['chi2']:.2f} | {w660:.4f} | {w660 / fit['w_at']:.3f} |")
        r += f" {ho['predicted']:.4f} +- {ho['predicted_se']:.4f} |"
        if "measured" in ho:
            r += f" {ho['measured']:.4f} +- {ho['measured_se']:.4f} | {ho['z']:+.2f} |"
        return r
    for name, runs in SERIES.items():
        wc = continuum_w(runs, list(d) + [S3])

        def f_of(x, wc=wc):
            return np.array([wc[min(wc, key=lambda k: abs(k - xx))] / wc[660e-6] for xx in x])
        f = f_of(d)
        fit = fit_form(d, w, se, f, at)
        ho = predicted(d, w, se, f_of, S3)
        out["series"][name] = dict(continuum_W={str(k): v for k, v in wc.items()}, f=f.tolist(), k=fit["k"],
                                   k_se=fit["k_se"], w_at=fit["w_at"], w_at_se=fit["w_at_se"], chi2=fit["chi2"],
                                   dof=fit["dof"], ratio_pure=wc[660e-6] / pure["w_at"], ratio_with_f=wc[660e-6] / fit["w_at"],
                                   ratio_at_dem_sizes=[wc[dd] / ww for dd, ww in zip(d, w)], s3=ho)
        lines.append(row("Beverloo k d only (parcel_size.py)", name, pure, wc[660e-6], out["pure"]["s3"]))
        lines.append(row("Beverloo k d x the continuum's f(d)", name, fit, wc[660e-6], ho))
    with open(os.path.join(a.out, "size_form.json"), "w") as fh:
        json.dump(out, fh, indent=1)
        fh.write("\n")
    with open(os.path.join(a.out, "size_form.md"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    gc.cli.main(main)
