#!/usr/bin/python3
"""The continuum with the DEM-calibrated mu(I) against the coarse-grained DEM
(README, "Cross-validation with the DEM-calibrated mu(I)"): W against the
mesh N of the calibrated runs (results/calibrated/, N = 28, and
results/calibrated/N<n>/, `./Allrun --rheology-from calibration --mesh N
--out ...`) and of the literature mesh study (results/convergence/), with the
DEM's rate (reference-cg-dem/) and issue 16's +-15 % band.
Writes results/calibrated/xval.{csv,png}.

Fields (when --dem-fields exists, default reference-cg-dem/fields400g/cg/:
`Allrun-dem --cg-every 0.05 --fill-g 400 ...`, cg.py):
the DEM's CG fields, time averaged over its steady window, against the
continuum's, averaged over its written times in the same window (--run, a
calibrated run written with --ascii; and --run2, e.g. the size-corrected
orifice), along the axis (the CG ring nearest 1 mm, by z) and across the
orifice plane z = 0 (by r): solid fraction (the continuum's alpha rho_b /
rho_p, the mass it carries, and alpha phi(I), its calibrated dilatancy, not
fed back; with --dilatancy runs alpha.grains, fed back), vertical velocity, pressure and the vertical mass flux with its
integral over the orifice. Writes results/calibrated/xval_fields.{png,json} and
xval_fields_continuum.csv (the continuum's profiles: run1 = --run, run2 = --run2).

    xval.py [--out DIR] [--dem-fields DIR] [--run DIR] [--run2 DIR] [--label2 TEXT]
"""
import csv
import json
import math
import os

import numpy as np

import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))
TARGET = 0.15


def continuum_fields(run, t0, t1, r_axis):
    """The continuum's fields averaged over its written times in [t0, t1] on the axis ring
    (r_axis, by z) and on the orifice plane (by r): {kind: (coord, {name: values})}."""
    with open(os.path.join(os.path.dirname(os.path.dirname(run)), "settings.json")) as fh:
        settings = json.load(fh)
    study = __import__("study")
    rho_b, _ = study.material(argparse_namespace(settings))
    phi_b = rho_b / gc.calibration.fit(P.CALIBRATION)["rho_p"] if settings.get("rheology_from") == "calibration" \
        else rho_b / P.RHO_P
    # with --dilatancy the continuum's grains are a field of their own (Dilatancy.H): the solid
    # fraction alpha.grains, the mass flux rho_p alpha.grains v_z
    dilatant_run = bool(settings.get("dilatancy"))
    rho_p = gc.calibration.fit(P.CALIBRATION)["rho_p"] if settings.get("rheology_from") == "calibration" else P.RHO_P
    times = [t for t, _ in gc.foam.time_dirs(run) if t0 - 1e-9 <= t <= t1 + 1e-9]
    if not times:
        raise gc.CaseError(f"{run}: no written time in {t0:g}-{t1:g} s (run with --ascii; fields every 0.5 s)")
    cos = math.cos(P.WEDGE_HALF_ANGLE)        # the front patch's vertices lie at x = r cos(a)
    z = np.linspace(-P.FREEFALL, 0.115, 235)
    r = np.linspace(0.0, 0.02, 81)
    lines = {"axis": (z, [(r_axis * cos, zz) for zz in z]), "orifice": (r, [(max(rr, r_axis) * cos, 0.0) for rr in r])}
    out = {}
    for kind, (coord, pts) in lines.items():
        acc = []
        for t in times:
            names = ["alpha.powder", "phiSolid", "U", "p"] + (["alpha.grains"] if dilatant_run else [])
            c = gc.foam.line_profile(run, t, names, pts, patch="front")
            al = c["alpha.powder"]
            solid = c["alpha.grains"] if dilatant_run else al * phi_b
            acc.append(dict(solid=solid, dilatant=al * c["phiSolid"],
                            velocity_z=np.where(al >= 0.05, c["U_z"], np.nan), pressure=np.where(al >= 0.05, c["p"], np.nan),
                            flux=-(solid * rho_p if dilatant_run else al * rho_b) * c["U_z"]))
        vals = {k: np.nanmean([x[k] for x in acc], axis=0) for k in acc[0]}
        if kind == "orifice":      # beyond the orifice edge z = 0 is inside the cone wall: the interpolation
            vals = {k: np.where(coord <= P.R_OUT + 1e-9, y, np.nan) for k, y in vals.items()}   # would cross it
        out[kind] = (coord, vals)
    return out, times, settings


def argparse_namespace(settings):
    import argparse
    return argparse.Namespace(rheology=settings.get("rheology", "muI"), rheology_from=settings.get("rheology_from",
                              "literature"), rheology_d=settings.get("rheology_d"))


def fields(a):
    """The field comparison (module docstring); None without the DEM's CG fields."""
    cgdir = a.dem_fields
    if not os.path.exists(os.path.join(cgdir, "cg_numbers.json")):
        print(f"mcc-hopper xval: no {os.path.relpath(cgdir, HERE)}/cg_numbers.json (Allrun-dem --cg-every T): fields skipped")
        return None
    with open(os.path.join(cgdir, "cg_numbers.json")) as fh:
        num = json.load(fh)
    dem = {"axis": gc.series.read_csv(os.path.join(cgdir, "cg_axis.csv")),
           "orifice": gc.series.read_csv(os.path.join(cgdir, "cg_orifice.csv"))}
    runs = [(a.run, "continuum, calibrated mu(I)")] + ([(a.run2, a.label2)] if a.run2 else [])
    cont = [(label,) + continuum_fields(run, num["t_from_s"], num["t_to_s"], num["axis_ring_r_m"]) for run, label in runs]
    plt = gc.plots.pyplot()
    fig, axes = plt.subplots(2, 4, figsize=(15, 7.5))
    quantities = (("solid fraction", "volume_fraction", "solid"), ("v_z [m/s]", "velocity_z", "velocity_z"),
                  ("pressure [Pa]", "pressure", "pressure"), ("mass flux -rho phi v_z [kg/m2/s]", None, "flux"))
    rows, numbers = [], dict(dem=num, continuum=[])
    for i, kind in enumerate(("axis", "orifice")):
        d = dem[kind]
        key = "z_m" if kind == "axis" else "r_m"
        x = d[key] * 1e3
        for k, (title, dk, ck) in enumerate(quantities):
            ax = axes[i, k]
            y = -d["momentum_density_z"] if dk is None else d[dk]
            if dk == "velocity_z":
                y = np.where(d["volume_fraction"] > 0.05, y, np.nan)
            ax.plot(x, y, "k.-", ms=3, lw=1.2, label=f"CG-DEM s = 5, {num['snapshots']} snapshots "
                                                     f"{num['t_from_s']:g}-{num['t_to_s']:g} s")
            for (label, c, times, _), col in zip(cont, ("tab:red", "tab:blue")):
                coord, vals = c[kind]
                ax.plot(coord * 1e3, vals[ck], color=col, lw=1.5, ls="--", label=f"{label}, t = "
                        + ", ".join(f"{t:g}" for t in times) + " s")
                if ck == "solid":
                    ax.plot(coord * 1e3, vals["dilatant"], color=col, lw=0.8, ls=":", label=f"{label}: alpha phi(I)")
            ax.set(xlabel="z [mm] (axis)" if kind == "axis" else "r [mm] (orifice plane z = 0)",
                   title=f"{'axis' if kind == 'axis' else 'orifice plane'}: {title}")
            ax.title.set_fontsize(9)
            ax.grid(alpha=0.3)
            if kind == "axis":
                ax.axvline(0, color="0.6", lw=0.6)
                if dk == "velocity_z":
                    ax.set_xlim(-15, 60)
            else:
                ax.axvline(P.R_OUT * 1e3, color="0.6", lw=0.6)
                ax.set_xlim(0, 20)
    axes[0, 0].legend(fontsize=6.5)
    fig.suptitle("MCC hopper, dry: coarse-grained DEM (granairCG, RZ, Gauss w = d/2 = 1.65 mm, time averaged) vs "
                 "the continuum with the DEM-calibrated mu(I)", fontsize=10)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(a.out, "xval_fields.png"))
    # the orifice plane: means and the mass flow, DEM vs each continuum run
    rd, dd = dem["orifice"]["r_m"], dem["orifice"]
    inside = rd < P.R_OUT
    for label, c, times, settings in cont:
        coord, vals = c["orifice"]
        sel = coord <= P.R_OUT + 1e-12
        w = np.where(sel, coord, 0.0)
        flux = float(np.trapz(np.nan_to_num(vals["flux"]) * 2 * math.pi * coord, coord))
        flux_dil = float(np.trapz(np.nan_to_num(vals["flux"] * vals["dilatant"] / np.where(vals["solid"] > 0,
                                                                                          vals["solid"], np.nan))
                                  * 2 * math.pi * coord, coord))
        numbers["continuum"].append(dict(
            label=label, settings=settings, times=times, orifice_mass_flow_kg_s=flux,
            orifice_mass_flow_at_phiI_kg_s=flux_dil,
            orifice_solid_fraction=float(np.sum((vals["solid"] * w)[sel]) / np.sum(w[sel])),
            orifice_phiI=float(np.nansum((vals["dilatant"] * w)[sel]) / np.sum(w[sel])),
            orifice_velocity_z=float(np.nansum((vals["velocity_z"] * w)[sel]) / np.sum(w[sel])),
            orifice_pressure=float(np.nansum((vals["pressure"] * w)[sel]) / np.sum(w[sel]))))
    numbers["dem_orifice_velocity_z_area_mean"] = float(np.nansum((dd["velocity_z"] * rd)[inside]) / np.sum(rd[inside]))
    with open(os.path.join(a.out, "xval_fields.json"), "w") as fh:
        json.dump(numbers, fh, indent=1)
    for kind in ("axis", "orifice"):
        coord = cont[0][1][kind][0]
        rows += [dict(profile=kind, coord_m=f"{x:.6g}", **{f"run{j + 1}_{q}": f"{c[kind][1][q][n]:.5g}"
                                                            for j, (_, c, _, _) in enumerate(cont)
                                                            for q in ("solid", "dilatant", "velocity_z", "pressure", "flux")})
                 for n, x in enumerate(coord)]
    gc.series.write_rows(os.path.join(a.out, "xval_fields_continuum.csv"), rows)
    print(f"DEM orifice: solid fraction {num['orifice_solid_fraction']:.3f}, area-mean v_z "
          f"{numbers['dem_orifice_velocity_z_area_mean']:.3f} m/s, CG mass flow {num['cg_mass_flow_kg_s']:.4f} kg/s")
    for n in numbers["continuum"]:
        print(f"{n['label']}: orifice solid fraction {n['orifice_solid_fraction']:.3f} (phi(I) {n['orifice_phiI']:.3f}), "
              f"v_z {n['orifice_velocity_z']:.3f} m/s, p {n['orifice_pressure']:.1f} Pa, mass flow "
              f"{n['orifice_mass_flow_kg_s']:.4f} kg/s ({n['orifice_mass_flow_at_phiI_kg_s']:.4f} at phi(I))")
    return numbers


def main():
    ap = gc.cli.parser(__doc__)
    ap.add_argument("--dem-fields", default=os.path.join(HERE, "reference-cg-dem", "fields400g", "cg"),
                    help="the DEM's CG fields (cg.py's output folder)")
    ap.add_argument("--run", default=os.path.join(HERE, "results", "calibrated", "runs", "N28"),
                    help="the continuum run folder of the field comparison (written with --ascii)")
    ap.add_argument("--run2", default=None, help="a second continuum run folder for the fields")
    ap.add_argument("--label2", default="continuum, second run")
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
    # Roache's GCI of the calibrated sequence over its three finest meshes (as the literature study's)
    seq = [r for r in rows if r["rheology"] == "calibrated"][-3:][::-1]
    g = gc.gci.gci(tuple(r["W_kg_s"] for r in seq), tuple(1.0 / r["N"] for r in seq)) if len(seq) == 3 else None
    if g:
        with open(os.path.join(a.out, "xval_gci.json"), "w") as fh:
            json.dump(dict(N=[r["N"] for r in seq], W=[r["W_kg_s"] for r in seq], **g), fh, indent=1)
        print(f"calibrated, GCI over N = {'/'.join(str(r['N']) for r in seq[::-1])}: {g['convergence']}"
              + (f", GCI_fine {100 * g['gci_fine']:.2f} %, order {g['order']:.2f}, extrapolated {g['extrapolated']:.4f} "
                 f"kg/s = {g['extrapolated'] / w_dem:.3f} x cg-DEM" if g["convergence"] == "monotonic" else ""))
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


    fields(a)


if __name__ == "__main__":
    gc.cli.main(main)
