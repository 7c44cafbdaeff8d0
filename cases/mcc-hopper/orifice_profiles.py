#!/usr/bin/env python3
"""Where the continuum's orifice flux exceeds the CG-DEM's: phi or v (issue 16).

    orifice_profiles.py LABEL=RUN_FOLDER [...] [--out DIR]

RUN_FOLDER: a continuum run written with --ascii (OUT/runs/N28). Reads the
s = 5 CG-DEM's orifice profile (reference-cg-dem/fields400g/cg/cg_orifice.csv,
cg.py) and each continuum run's orifice-plane fields over the DEM's window
(xval.continuum_fields), and splits the plane's mass flux exactly into a solid
fraction and a mass-weighted velocity:

    F = rho_p int phi v_z dA = rho_p * (int phi dA) * v_m,   v_m = int phi v_z dA / int phi dA

so F_cont / F_dem = (phi ratio) x (v_m ratio). Integrals over the whole plane
(the DEM's CG kernel spreads its stream's edge 1-2 w beyond the orifice rim;
that mass is the stream's), phi as a mean over the orifice area pi R^2; also
over the core r < R - k d / 2 (k of the DEM's Beverloo fit, d of the parcels:
outside the empty annulus). Writes results/calibrated/orifice_profiles.{json,md,png}.
"""
import argparse
import json
import math
import os

import numpy as np

import granair_cases as gc
import parameters as P
import xval

HERE = os.path.dirname(os.path.abspath(__file__))
CG = os.path.join(HERE, "reference-cg-dem", "fields400g", "cg")
D_PARCEL = 3.3e-3        # the s = 5 parcels of the field run


def split(r, phi, vz, rho_p, r_max=None):
    """Mass flux [kg/s], area-mean phi over pi R^2 (or the core's area), mass-weighted v_z, over r <= r_max
    (the profile interpolated linearly onto a fine grid, held at its end values, zero where it has no data)."""
    sel = np.isfinite(phi) & np.isfinite(vz)
    top = r_max if r_max else float(r[sel].max())
    x = np.linspace(0.0, top, 2001)
    f = np.interp(x, r[sel], phi[sel], right=0.0)
    fv = np.interp(x, r[sel], (phi * vz)[sel], right=0.0)
    mass, mflux = np.trapz(2 * math.pi * x * f, x), np.trapz(2 * math.pi * x * fv, x)
    return dict(flux_kg_s=float(-rho_p * mflux), phi_mean=float(mass / (math.pi * (r_max if r_max else P.R_OUT) ** 2)),
                v_m=float(mflux / mass))


def plot(dem, rows, r_core, path):
    """Solid fraction and v_z across the orifice plane, the DEM's rings and the continuum runs side by side."""
    plt = gc.plots.pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for r in [dem] + rows:
        x = [g["r_mm"] for g in r["rings"]]
        style = dict(marker="o", ls="-", color="k") if r is dem else dict(ls="-")
        axes[0].plot(x, [g["phi"] for g in r["rings"]], label=r["label"], **style)
        axes[1].plot(x, [g["v_z"] for g in r["rings"]], label=r["label"], **style)
    for ax, name in zip(axes, ("solid fraction", "v_z [m/s]")):
        ax.axvline(P.R_OUT * 1e3, color="0.6", lw=0.6)
        ax.axvline(r_core * 1e3, color="0.6", lw=0.6, ls=":")
        ax.set_xlabel("r [mm] (orifice plane z = 0; rim solid, core limit dotted)")
        ax.set_ylabel(name)
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    gc.plots.save(fig, path, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("runs", nargs="+", help="LABEL=RUN_FOLDER (a continuum run folder written with --ascii)")
    ap.add_argument("--out", default=os.path.join(HERE, "results", "calibrated"))
    a = ap.parse_args()
    with open(os.path.join(CG, "cg_numbers.json")) as fh:
        dem_n = json.load(fh)
    with open(os.path.join(HERE, "reference-cg-dem", "parcel_size.json")) as fh:
        k = json.load(fh)["fit"]["k"]
    r_core = P.R_OUT - k * D_PARCEL / 2
    t = np.genfromtxt(os.path.join(CG, "cg_orifice.csv"), delimiter=",", names=True)
    dem = dict(label="CG-DEM s = 5, 400 g", rings=[dict(r_mm=float(r * 1e3), phi=float(f), v_z=float(v), I=float(i))
                                                     for r, f, v, i in zip(t["r_m"], t["volume_fraction"],
                                                                           t["velocity_z"], t["inertial_number"])
                                                     if f > 0],
               plane=split(t["r_m"], t["volume_fraction"], t["velocity_z"], P.RHO_P),
               core=split(t["r_m"], t["volume_fraction"], t["velocity_z"], P.RHO_P, r_core))
    rows = []
    for spec in a.runs:
        label, run = spec.rsplit("=", 1)
        c, times, settings = xval.continuum_fields(run, dem_n["t_from_s"], dem_n["t_to_s"], dem_n["axis_ring_r_m"])
        coord, v = c["orifice"]
        rho_p = gc.calibration.fit(P.CALIBRATION)["rho_p"] if settings.get("rheology_from") == "calibration" \
            else P.RHO_P
        rows.append(dict(label=label, run=run, times=times, rho_p=float(rho_p),
                         rings=[dict(r_mm=float(r * 1e3), phi=float(f), phi_I=float(g), v_z=float(w))
                                for r, f, g, w in zip(coord, v["solid"], v["dilatant"], v["velocity_z"])
                                if np.isfinite(f)][::4],
                         plane=split(coord, v["solid"], v["velocity_z"], rho_p),
                         core=split(coord, v["solid"], v["velocity_z"], rho_p, r_core)))
    for r in rows:
        for part in ("plane", "core"):
            d, c = dem[part], r[part]
            r[part]["over_dem"] = dict(flux=c["flux_kg_s"] / d["flux_kg_s"], phi=c["phi_mean"] / d["phi_mean"],
                                       v_m=c["v_m"] / d["v_m"])
    out = dict(r_core_mm=r_core * 1e3, k=k, d_parcel_m=D_PARCEL, dem=dem, continuum=rows)
    with open(os.path.join(a.out, "orifice_profiles.json"), "w") as fh:
        json.dump(out, fh, indent=1)
    lines = ["| orifice plane z = 0 | part | flux [kg/s] | mean phi | v_m [m/s] | flux / DEM | phi / DEM | v_m / DEM |",
             "|---|---|---|---|---|---|---|---|"]
    for r in [dem] + rows:
        for part, name in (("plane", "whole plane"), ("core", f"core r < {r_core * 1e3:.1f} mm")):
            p = r[part]
            o = p.get("over_dem")
            lines.append(f"| {r['label']} | {name} | {p['flux_kg_s']:.4f} | {p['phi_mean']:.3f} | {p['v_m']:.3f} | "
                         + (f"{o['flux']:.2f} | {o['phi']:.2f} | {o['v_m']:.2f} |" if o else "— | — | — |"))
    plot(dem, rows, r_core, os.path.join(a.out, "orifice_profiles.png"))
    with open(os.path.join(a.out, "orifice_profiles.md"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
