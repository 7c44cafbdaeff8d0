#!/usr/bin/python3
"""The calibrated continuum at the primary d = 660 um with and without the solid
fraction fed back into the powder's volume (`--dilatancy`, cfd-side/continuum/
Dilatancy.H), against the coarse-grained DEM converged in parcel size
(reference-cg-dem/parcel_size.json: 0.1364 +- 0.0030 kg/s) and against the DEM's
orifice solid fraction (reference-cg-dem/fields400g/cg, cg.py): README section
"Dilatancy: phi(I) in the continuum's mass".

Reads results/calibrated/d660um/ (without; N<n>/ its coarser meshes) and
results/calibrated/d660um-dilatancy/ (with; N<n>/ the mesh series, w<x>/ and
k<x>/ the sensitivity runs), each a `./Allrun --rheology-from calibration
--rheology-d 660e-6 [--dilatancy] [--mesh N] --out ...` result. Roache's GCI
(gc.gci) over the three finest meshes of each series; the orifice-plane means
(area means over r < 12.5 mm on z = 0, xval.continuum_fields, the DEM's window)
of the runs written with --ascii whose run folder is still there.
Writes results/calibrated/dilatancy.{json,csv,md}.

    dilatancy.py [--out DIR]
"""
import json
import math
import os
import re

import numpy as np

import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))
CAL = os.path.join(HERE, "results", "calibrated")
SERIES = {"without": os.path.join(CAL, "d660um"), "with phi(I)": os.path.join(CAL, "d660um-dilatancy")}


def runs(top):
    """(tag, folder, settings, summary) of the finished runs in top and its subfolders."""
    out = []
    for tag, d in [("", top)] + [(n, os.path.join(top, n)) for n in sorted(os.listdir(top)) if n != "runs"]:
        if os.path.isdir(d) and os.path.exists(os.path.join(d, "summary.txt")):
            with open(os.path.join(d, "settings.json")) as fh:
                out.append((tag, d, json.load(fh), gc.series.read_keys(os.path.join(d, "summary.txt"))))
    return out


def orifice(res, dem):
    """The continuum's orifice-plane means of a run written with --ascii, or None."""
    run = os.path.join(res, "runs", "N%d" % json.load(open(os.path.join(res, "settings.json")))["mesh"])
    try:
        with open(os.path.join(run, "system", "controlDict")) as fh:
            if not re.search(r"^\s*writeFormat\s+ascii\s*;", fh.read(), re.M):
                return None                            # binary fields: no profiles
    except OSError:
        return None                                    # the run folder is gone (not committed)
    c, times, _ = __import__("xval").continuum_fields(run, dem["t_from_s"], dem["t_to_s"], dem["axis_ring_r_m"])
    coord, v = c["orifice"]
    sel = coord <= P.R_OUT + 1e-12
    w = np.where(sel, coord, 0.0)
    mean = lambda y: float(np.nansum((y * w)[sel]) / np.sum(w[sel]))
    return dict(times=times, solid_fraction=mean(v["solid"]), phi_I=mean(v["dilatant"]),
                velocity_z=mean(v["velocity_z"]), pressure=mean(v["pressure"]))


def main():
    ap = gc.cli.parser(__doc__)
    a = gc.cli.parse(ap, CAL)
    with open(os.path.join(HERE, "reference-cg-dem", "parcel_size.json")) as fh:
        ps = json.load(fh)
    w_dem, se_dem = ps["dem_size_converged_kg_s"], ps["dem_size_converged_se_kg_s"]
    cg_numbers = os.path.join(HERE, "reference-cg-dem", "fields400g", "cg", "cg_numbers.json")
    dem = json.load(open(cg_numbers)) if os.path.exists(cg_numbers) else None
    rows, gcis = [], {}
    for kind, top in SERIES.items():
        mesh = []
        for tag, d, s, k in runs(top):
            w = float(k["steady_mass_flow_kg_s"])
            extra = {key: s[key] for key in ("dilatancy_rate", "dilatancy_relaxation") if key in s}
            o = orifice(d, dem) if dem else None
            row = dict(series=kind, run=os.path.relpath(d, HERE), N=s["mesh"], **extra, W_kg_s=w,
                       W_sd_kg_s=float(k["window_mass_flow_sd_kg_s"]), W_over_dem=w / w_dem,
                       W_over_dem_lo=w / (w_dem + se_dem), W_over_dem_hi=w / (w_dem - se_dem),
                       tension_fraction_mean=float(k["tension_fraction_mean"]),
                       tension_fraction_max=float(k["tension_fraction_max"]),
                       mass_balance=float(k["mass_balance_error"]), cpu_s=float(k["run_cpu_s"]),
                       orifice_solid_fraction=o["solid_fraction"] if o else math.nan,
                       orifice_phi_I=o["phi_I"] if o else math.nan,
                       orifice_velocity_z=o["velocity_z"] if o else math.nan,
                       orifice_pressure=o["pressure"] if o else math.nan)
            rows.append(row)
            if not extra:                      # the mesh series: default settings but the mesh
                mesh.append(row)
        mesh.sort(key=lambda r: r["N"])
        fine = mesh[-3:][::-1]
        if len(fine) == 3:
            g = gc.gci.gci(tuple(r["W_kg_s"] for r in fine), tuple(1.0 / r["N"] for r in fine))
            gcis[kind] = dict(N=[r["N"] for r in fine], W=[r["W_kg_s"] for r in fine],
                              monotonic_all=bool(np.all(np.diff([r["W_kg_s"] for r in mesh]) < 0)
                                                 or np.all(np.diff([r["W_kg_s"] for r in mesh]) > 0)),
                              N_all=[r["N"] for r in mesh], W_all=[r["W_kg_s"] for r in mesh], **g)
            if g["convergence"] == "monotonic":
                gcis[kind]["extrapolated_over_dem"] = g["extrapolated"] / w_dem
    out = dict(dem_size_converged_kg_s=w_dem, dem_size_converged_se_kg_s=se_dem,
               dem_orifice_solid_fraction=dem["orifice_solid_fraction"] if dem else None, target=P_TARGET,
               runs=rows, gci=gcis)
    with open(os.path.join(a.out, "dilatancy.json"), "w") as fh:
        json.dump(out, fh, indent=1)
    gc.series.write_rows(os.path.join(a.out, "dilatancy.csv"), rows, "{:.6g}")
    lines = ["| series | run | N | W [kg/s] | / size-converged DEM (+- its s.e.) | orifice solid fraction "
             "(DEM %s) | orifice v_z [m/s] | packed cells p <= 0 (mean / max) | CPU [s] |"
             % (f"{dem['orifice_solid_fraction']:.3f}" if dem else "n/a"), "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['series']} | `{r['run']}` | {r['N']} | {r['W_kg_s']:.4f} | {r['W_over_dem']:.3f} "
                     f"({r['W_over_dem_lo']:.3f}-{r['W_over_dem_hi']:.3f}) | "
                     + (f"{r['orifice_solid_fraction']:.3f}" if math.isfinite(r["orifice_solid_fraction"]) else "-")
                     + " | " + (f"{r['orifice_velocity_z']:.3f}" if math.isfinite(r["orifice_velocity_z"]) else "-")
                     + f" | {r['tension_fraction_mean']:.2g} / {r['tension_fraction_max']:.2g} | {r['cpu_s']:.0f} |")
    for kind, g in gcis.items():
        lines.append("")
        lines.append(f"{kind}: W over N = {'/'.join(str(n) for n in g['N_all'])}: "
                     f"{' / '.join(f'{w:.4f}' for w in g['W_all'])} kg/s (monotonic: {'yes' if g['monotonic_all'] else 'no'}); "
                     f"GCI over N = {'/'.join(str(n) for n in g['N'][::-1])}: {g['convergence']}"
                     + (f", GCI_fine {100 * g['gci_fine']:.2f} %, order {g['order']:.2f}, extrapolated "
                        f"{g['extrapolated']:.4f} kg/s = {g['extrapolated_over_dem']:.3f} x the size-converged DEM"
                        if g["convergence"] == "monotonic" else ""))
    with open(os.path.join(a.out, "dilatancy.md"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    print("\n".join(lines))


P_TARGET = 0.15       # issue 16: W within 15 % of the DEM

if __name__ == "__main__":
    gc.cli.main(main)
