#!/usr/bin/python3
"""The wedge silo at continuum fidelity: granairContinuumFoam, mu(I) (or the
calibrated Latz-Schmidt closure) with Darcy-Ergun air (README.md, "Continuum
fidelity").

    continuum.py [--b MM ...] [--air on|off|both] [--out DIR] [--quick] [--check] [--end T]
                 [--mesh N] [--walls coulomb|slip|noSlip] [--wall-friction MU] [--freefall L]
                 [--rheology muI|latzSchmidt] [--rheology-from literature|calibration]
                 [--dem-size demo|study|converged] [--rheology-d D] [--write-every T] [--setup-only]
                 [--fills demo|study] [--until F] [--eta-min V]
                 [--dilatancy [--dilatancy-rate K] [--dilatancy-relaxation W]]

One run per b and air setting from continuum/template/ (the silo as a plane
mesh one cell of the whole 60 mm deep with a free-fall region below the slot,
the DEM demo's settled fills, or with --fills study the DEM study's, Coulomb
wall friction by default), run until half of the fill has left (stopAt
writeNow; --until F: the fraction F, e.g. 0.99 for the whole discharge) or
--end. The time series also carries the fill level (the bed height above the
orifice holding the powder left at the fill's bulk density). Per run
OUT/b<b>_<air|noair>/: timeseries.csv (10 ms means of the outlet flow and
gradient), level.json (level continuum), details.json, fields.png; OUT/summary.csv
with the DEM-CFD demo's rates (reference-demo/summary.csv). The steady window
is the DEM case's: from min(0.3 s, t1/2) to t1, t1 the time half of the fill
has left; the steady rate the least-squares slope of the discharged mass in
it, the outlet dp/dz the time mean of the per-step values.

--rheology-from calibration: the mu(I) and phi_max of the DEM's lactose
parcels, fitted from a DEM shear cell (cases/rheology-calibration,
gc.calibration), in place of the literature block (the default: the
shear-test mu_s of the real lactose, Jop et al.'s span and I0; the material
prediction); bulk density rho_p phi_max, d the parcel diameter of the DEM
run of --dem-size (demo: b/6, study: b/7, the calibrated parcels) and that
run's rate the reference (reference-demo/ or reference-study-b<b>/); with
--dem-size converged the reference is the DEM-only rate converged in parcel
size (reference-parcel-size/parcel_size.json, b = 10 mm dry) and d the
primary number mean it was extrapolated to (218 um). The
cross-validation of README "Cross-validation"; --write-every writes the
fields at that interval as well (the profiles against the DEM's CG fields).
--dilatancy feeds the rheology's phi(I) back into the powder's volume
(`dilatancy on;` in granularProperties, cfd-side/continuum/Dilatancy.H, wired
as in cases/mcc-hopper/study.py; default off).

Checked (--check exits 1 on a failure): every value finite; the powder mass
balance within 0.5 % (the outlet flow integrated, and the solver's own); the
steady rate and (with air) the outlet dp/dz against the DEM-CFD demo's,
within the range the committed runs give (parameters.py, README).
"""
import csv
import json
import math
import os
import re
import time

import numpy as np

import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))
C = os.path.join(HERE, "continuum")


def latz():
    """The numbers of the lactose Latz-Schmidt block (continuum/latzSchmidt/rheology)."""
    text, values = gc.calibration.read_block(os.path.join(C, "latzSchmidt", "rheology"), ("c0", "cMax", "TMin"))
    return values, text


def walls_text(v):
    return {"coulomb": f"Coulomb (mu_w {v['WALL_FRICTION']:.3f})", "slip": "free-slip",
            "noSlip": "no-slip"}[v["WALLS"]]


CONVERGED = os.path.join(HERE, "reference-parcel-size", "parcel_size.json")


def dem_rates(a, b_mm):
    """{(b_mm, air): (W, outlet dp/dz)} of the DEM(-CFD) runs the continuum is compared
    with: the demo's, with --dem-size study the study-size run of this b, with
    --dem-size converged the DEM-only rate converged in parcel size and extrapolated to
    the primary d (parcel_size.py; b = 10 mm, dry only: no dp/dz)."""
    if a.dem_size == "converged":
        with open(CONVERGED) as fh:
            return {(10, False): (json.load(fh)["dem_size_converged_kg_s"], math.nan)}
    folder = os.path.join(HERE, "reference-demo" if a.dem_size == "demo" else f"reference-study-b{b_mm}")
    with open(os.path.join(folder, "summary.csv")) as fh:
        return {(int(x["b_mm"]), x["air"] == "1"): (float(x["W_kg_s"]), float(x["outlet_dpdz_Pa_m"]))
                for x in csv.DictReader(fh)}


def calibrated(a, b_mm):
    """(parcel diameter [m], the DEM fit) of --rheology-from calibration: the diameter
    b / b_over_d of the --dem-size DEM run's parcels; with --dem-size converged the
    primary number-mean d the DEM was extrapolated to."""
    d = a.rheology_d or (P.psd_moments()[0] if a.dem_size == "converged" else
                         b_mm * 1e-3 / P.SIZES[a.dem_size]["per_b"][b_mm]["b_over_d"])
    f = gc.calibration.fit(P.CALIBRATION)
    return d, f


def numbers(a, b_mm, air):
    fills = P.FILLS_STUDY if a.fills == "study" else P.FILLS
    if b_mm not in fills:
        raise gc.CaseError(f"parameters.py FILLS{'_STUDY' if a.fills == 'study' else ''} has no fill for b = {b_mm} mm "
                           f"(it has {sorted(fills)})")
    b, fill, rho_b = b_mm * 1e-3, *fills[b_mm]
    cal = calibrated(a, b_mm) if a.rheology_from == "calibration" else None
    if cal:
        rho_b = cal[1]["rho_p"] * cal[1]["phi_max"]     # the calibrated parcels' dense packing
    freefall = a.freefall if a.freefall is not None else 0.5 * b   # default b/2 below the slot
    if a.rheology == "latzSchmidt":
        # the closure fixes its own packing range c0 < c < cMax: the DEM fill's 0.583
        # is above cMax, so the bulk density is its middle, at the DEM fill height
        rho_b = P.RHO_P * 0.5 * (latz()[0]["c0"] + latz()[0]["cMax"])
    mu_s, c_kpa = P.fit_mu_s()
    hh = P.hopper_height(b)
    q = 1 + 2 * math.tan(math.radians(P.HALF_ANGLE)) / a.mesh   # square hopper cells: heights grow by q
    v = dict(gc.template.constants(P), B_MM=b_mm, N=a.mesh, B=b / 2, W=P.WIDTH / 2, HH=hh, HT=hh + P.SHAFT_HEIGHT,
             NZ_HOPPER=max(4, round(math.log(P.WIDTH / b) / math.log(q))), GRADING=P.WIDTH / b,
             NZ_SHAFT=max(4, round(P.SHAFT_HEIGHT / (P.WIDTH / a.mesh))), FILL=fill, RHO_B=rho_b,
             FILL_G=rho_b * P.fill_area(b, fill) * P.DEPTH * 1e3, AIR_MODEL="darcyErgun" if air else "none",
             MU_S=mu_s, COHESION_PA=c_kpa * 1e3, MU_2=mu_s + P.JOP_MU_SPAN, PHI_MAX=rho_b / P.RHO_P,
             PHI_MIN=rho_b / P.RHO_P - P.DILATANCY_SPAN, END=a.end, AIR=air, WALLS=a.walls,
             WALL_U=gc.foam.wall_velocity(a.walls, a.wall_friction), WALL_FRICTION=a.wall_friction,
             FREEFALL=freefall, FREEFALL_MM=freefall * 1e3, NZ_FALL=max(2, round(freefall / (b / a.mesh))),
             RHEOLOGY_NAME=a.rheology, RHEOLOGY_FROM=a.rheology_from,
             WRITE_INTERVAL=a.write_every if a.write_every else a.end,
             DILATANCY=gc.dilatancy.block(a, "continuum.py", off="// (no dilatancy: continuum.py --dilatancy)"))
    if a.rheology == "latzSchmidt":
        v.update(RHEOLOGY=latz()[1], T_MIN=latz()[0]["TMin"])
    else:
        path = os.path.join(C, "muI", "rheology")
        with open(path) as fh:
            v["RHEOLOGY"] = gc.template.fill(fh.read(), v, path)
        if cal:
            v["RHEOLOGY"] = gc.calibration.block(v["RHEOLOGY"], P.CALIBRATION, d=cal[0], where=path)
            v.update(MU_S=cal[1]["mu_s"], MU_2=cal[1]["mu_2"], JOP_I0=cal[1]["I0"], PHI_MAX=cal[1]["phi_max"],
                     PHI_MIN=cal[1]["phi_min"], D_LACTOSE=cal[0], COHESION_PA=0.0)
        if a.eta_min is not None:       # the viscosity floor (default rho_p d sqrt(g d)): a sensitivity
            v["RHEOLOGY"] = gc.calibration.set_entry(v["RHEOLOGY"], "etaMin", a.eta_min, "continuum.py --eta-min")
            v["ETA_MIN"] = a.eta_min
    return v


def run_one(a, b_mm, air):
    name = f"b{b_mm}_{'air' if air else 'noair'}"
    run = gc.runner.clean(os.path.join(a.out, "runs", name))
    v = numbers(a, b_mm, air)
    gc.template.render(os.path.join(C, "template"), run, v)
    if a.rheology == "latzSchmidt":
        gc.template.render(os.path.join(C, "latzSchmidt"), run, v, only=["0/T"])
    with open(os.path.join(run, "silo.json"), "w") as fh:
        json.dump({k: x for k, x in v.items() if k != "RHEOLOGY"}, fh, indent=1)
    if a.setup_only:
        return
    for cmd in (["blockMesh"], ["checkMesh"], ["setAlphaField"], ["setFields"]):
        gc.runner.run(cmd, run)
    cells = gc.foam.checkmesh(os.path.join(run, "log", "checkMesh.log"))[0]
    print(f"wedge-silo continuum {name}: {cells} cells, up to t = {a.end:g} s", flush=True)

    def half_out():
        # the powder that has left through the outlet, against the fill (first row)
        try:
            with open(os.path.join(run, "postProcessing", "timeSeries.csv")) as fh:
                rows = [r for r in csv.DictReader(fh)]
            return len(rows) > 1 and float(rows[-2]["discharged_kg"]) >= a.until * float(rows[0]["powder_mass_kg"])
        except (OSError, ValueError, KeyError):
            return False
    t0 = time.time()
    gc.runner.run(["granairContinuumFoam"], run, stop_when=half_out)
    return post(a, run, os.path.join(a.out, name), name, v, cells, round(time.time() - t0, 1))


def post(a, run, out, name, v, cells, wall):
    r = gc.powder.continuum(run)
    t, dt, s, air, latz_run = r["t"], r["dt"], r["series"], v["AIR"], v["RHEOLOGY_NAME"] == "latzSchmidt"
    half = np.nonzero(r["out"] >= 0.5 * r["mass"][0])[0]         # the steady window: the DEM case's
    t1 = float(t[half[0]]) if half.size else float(t[-1])
    t0 = min(P.STEADY_FROM, 0.5 * t1)
    rheology = ("Latz-Schmidt (lactose calibration of case A)" if latz_run else
                f"{'DEM-calibrated ' if v['RHEOLOGY_FROM'] == 'calibration' else ''}mu(I) (mu_s {v['MU_S']:.3f}, mu_2 {v['MU_2']:.3f}, I0 {v['JOP_I0']:g}, "
                f"d = {v['D_LACTOSE'] * 1e6:.0f} um in I{', dilatancy phi(I)' if a.dilatancy else ''})")
    packing = "the closure's c" if latz_run else f"phi(I) (span {v['PHI_MAX'] - v['PHI_MIN']:.3g})"
    model = (f"{rheology}, VOF, {walls_text(v)} walls, "
             f"{'Darcy-Ergun air, packing relaxing to ' + packing if air else 'no air'}, plane mesh N = {v['N']} "
             f"({cells} cells), free fall {v['FREEFALL_MM']:g} mm below the slot, full 60 mm depth")
    level = P.fill_level(2 * v["B"], r["mass"], v["RHO_B"])    # the bed height holding the powder left
    o = gc.powder.continuum_outputs(r, out, t0, t1, 0.01, 0.5, "timeseries.csv", dict(
        case="wedge-silo", model=model, b_mm=v["B_MM"], wall_time_s=wall, cores=1), [("fill_level_m", level)])
    sel = (t >= t0) & (t <= t1)
    with open(os.path.join(run, "log", "granairContinuumFoam.log")) as fh:
        cpu = re.findall(r"ExecutionTime = ([\d.eE+-]+) s", fh.read())
    details = dict(initial_powder_kg=r["initial"], solver_cpu_time_s=float(cpu[-1]) if cpu else None,
                   final_powder_kg=float(r["mass"][-1]), discharged_outlet_kg=float(r["out"][-1]),
                   mass_balance_error=r["balance"], solver_mass_balance_error_max=r["solver_balance"],
                   t_end_s=float(t[-1]), steps=len(t), all_finite=r["finite"])
    if air:       # the spread of the per-step gradient about its mean: a check on step-to-step noise
        details.update(air_p_min_window_mean_Pa=gc.series.time_mean(t, s["air_p_min_Pa"], t0, t1, dt),
                       outlet_dpdz_step_sd_Pa_m=float(np.sqrt(np.sum((s["outlet_dpdz_Pa_m"][sel] - o["dpdz"]) ** 2
                                                                      * dt[sel]) / np.sum(dt[sel]))))
    with open(os.path.join(out, "details.json"), "w") as fh:
        json.dump(details, fh, indent=1)
    with open(os.path.join(out, "silo.json"), "w") as fh:      # the run's numbers (mesh, d, ...) beside its results
        json.dump({k: x for k, x in v.items() if k != "RHEOLOGY"}, fh, indent=1)
    times = [tt for tt, _ in gc.foam.time_dirs(run)]
    gc.plots.case_fields(os.path.join(out, "fields.png"), f"{name}: continuum {v['RHEOLOGY_NAME']}, b = {v['B_MM']} mm",
                         run, times[:1] + times[-1:], [("alpha.powder", "powder fraction alpha", "viridis", (0, 1))]
                         + ([("p_air", "air pressure - ambient [Pa]", "RdBu_r", None)] if air else []),
                         (-22.5, 22.5), (0, (v["FILL"] + 0.02) * 1e3))
    print(f"wedge-silo continuum {name}: W = {o['w']:.4g} kg/s over [{t0:.3g}, {t1:.3g}] s"
          + (f", outlet dp/dz {o['dpdz']:.4g} Pa/m" if air else "") + f"; balance {r['balance']:.1e} "
          f"(solver {r['solver_balance']:.1e}); {len(t)} steps, {wall:g} s", flush=True)
    return dict(name=name, b_mm=v["B_MM"], air=air, W=o["w"], dpdz=o["dpdz"], t0=t0, t1=t1, wall=wall, r=r,
                sd=details.get("outlet_dpdz_step_sd_Pa_m"))


def summary(a, runs, c):
    dem = {}
    for b in sorted({x["b_mm"] for x in runs}):
        dem.update(dem_rates(a, b))
    w_range, w_why = ((P.CALIBRATED_W_OVER_DEM, "issue 16's cross-validation target: the same material, within 15 %")
                      if a.rheology_from == "calibration" else
                      (P.CONTINUUM_W_OVER_DEM, "the continuum has no k d term: the committed runs give 1.40-1.87 (README)"))
    rows = []
    for x in sorted(runs, key=lambda x: (x["b_mm"], not x["air"])):
        wd, pd = dem.get((x["b_mm"], x["air"]), (math.nan, math.nan))
        rows.append(dict(run=x["name"], b_mm=x["b_mm"], air=int(x["air"]), W_kg_s=f"{x['W']:.5g}",
                         outlet_dpdz_Pa_m="" if x["dpdz"] is None else f"{x['dpdz']:.5g}",
                         dpdz_step_sd_Pa_m="" if not x["sd"] else f"{x['sd']:.3g}", window_t0_s=f"{x['t0']:.3g}",
                         window_t1_s=f"{x['t1']:.3g}", W_demo_dem_cfd_kg_s=f"{wd:.5g}", W_over_dem=f"{x['W'] / wd:.3g}",
                         dpdz_demo_dem_cfd_Pa_m=f"{pd:.5g}" if x["air"] else "", wall_time_s=f"{x['wall']:.0f}"))
        n = x["name"]
        gc.powder.check_continuum(c, n, x["r"])
        against = "the size-converged DEM's" if a.dem_size == "converged" else f"the DEM-CFD {a.dem_size} run's"
        c.within(f"{n}: steady rate / {against}", x["W"] / wd, *w_range, w_why)
        if x["air"]:
            c.within(f"{n}: outlet dp/dz / the DEM-CFD demo's", x["dpdz"] / pd, *P.CONTINUUM_DPDZ_OVER_DEM,
                     "the committed runs give 0.57-1.04: the same suction to within the DEM's own scatter")
    gc.series.write_rows(os.path.join(a.out, "summary.csv"), rows)
    with open(os.path.join(a.out, "summary.csv")) as fh:
        print(fh.read(), end="")


def parser():
    """The command line (twofluid.py takes its defaults for the numbers it shares)."""
    ap = gc.cli.parser(__doc__)
    ap.add_argument("--b", type=int, action="append", choices=[5, 10, 15], help="slot width [mm]; repeat (default all)")
    ap.add_argument("--air", choices=["on", "off", "both"], default=None, help="default both")
    ap.add_argument("--quick", action="store_true", help="N = 8, 0.3 s, and unless given --b 10 --air on (the case test)")
    ap.add_argument("--end", type=float, default=2.0, help="longest simulated time [s] (default 2)")
    ap.add_argument("--mesh", type=int, default=12, help="cells across the slot (default 12)")
    ap.add_argument("--walls", choices=gc.foam.WALLS, default="coulomb",
                    help="coulomb (Coulomb wall friction, default), slip (free slip) or noSlip")
    ap.add_argument("--wall-friction", type=float, default=P.WALL_FRICTION,
                    help=f"mu_w of --walls coulomb (default tan {P.WALL_FRICTION_ANGLE:g} deg = {P.WALL_FRICTION:.3f})")
    ap.add_argument("--freefall", type=float, default=None,
                    help="depth of the free-fall region below the slot [m] (default b/2)")
    ap.add_argument("--rheology", choices=["muI", "latzSchmidt"], default="muI")
    ap.add_argument("--fills", choices=["demo", "study"], default="demo",
                    help="the DEM fills to start from (parameters.py FILLS, FILLS_STUDY)")
    ap.add_argument("--until", type=float, default=0.5,
                    help="stop once this fraction of the fill has left (default 0.5; 0.99: the whole discharge)")
    ap.add_argument("--rheology-from", choices=["literature", "calibration"], default="literature",
                    help="muI parameters: the lactose's shear test with Jop et al.'s span and I0 (default) or "
                         "the DEM calibration of the DEM's parcels (cases/rheology-calibration)")
    ap.add_argument("--dem-size", choices=sorted(P.SIZES) + ["converged"], default="demo",
                    help="the DEM-CFD run compared with (and, with the calibration, its parcel d): default demo; "
                         "converged: the DEM-only rate converged in parcel size (b = 10 mm, dry; d the primary mean)")
    ap.add_argument("--rheology-d", type=float, default=None,
                    help="with the calibration: the grain diameter of I [m] instead of the DEM parcel's (sensitivity)")
    ap.add_argument("--write-every", type=float, default=None, help="field output interval [s] (default: the end)")
    ap.add_argument("--eta-min", type=float, default=None,
                    help="muI: the viscosity floor [Pa s] (default rho_p d sqrt(g d) of the block's d)")
    gc.dilatancy.options(ap, P.DILATANCY_RATE, P.DILATANCY_RELAXATION)
    return ap


def main():
    ap = parser()
    a = gc.cli.parse(ap, lambda a: os.path.join(HERE, "continuum-results" + ("-latz" if a.rheology == "latzSchmidt" else
                                                                             "-calibrated" if a.rheology_from == "calibration" else "")))
    if a.rheology_from == "calibration" and a.rheology != "muI":
        ap.error("--rheology-from calibration: the calibration is a muI block (--rheology muI)")
    if a.rheology_d is not None and not (a.rheology_d > 0 and a.rheology_from == "calibration"):
        ap.error(f"--rheology-d {a.rheology_d:g}: expected a diameter > 0 [m], with --rheology-from calibration")
    if a.eta_min is not None and not (a.eta_min > 0 and a.rheology == "muI"):
        ap.error(f"--eta-min {a.eta_min:g}: expected a viscosity > 0 [Pa s], with --rheology muI")
    if a.dilatancy and a.rheology != "muI":
        ap.error("--dilatancy: phi(I) is the muI block's (--rheology muI)")
    gc.dilatancy.check(ap, a, P.DILATANCY_RATE, P.DILATANCY_RELAXATION)
    if a.write_every is not None and not a.write_every > 0:
        ap.error(f"--write-every {a.write_every:g}: expected an interval > 0 [s]")
    if a.dem_size == "converged" and (set(a.b or [5, 10, 15]) != {10} or a.air != "off"):
        ap.error("--dem-size converged: the size-converged DEM rate is of b = 10 mm without air "
                 f"({os.path.relpath(CONVERGED, HERE)}): give --b 10 --air off")
    if a.quick:
        a.mesh, a.end, a.b, a.air = 8, 0.3, a.b or [10], a.air or "on"
    if a.mesh < 4:
        ap.error(f"--mesh {a.mesh}: expected N >= 4 cells across the slot")
    if a.freefall is not None and not a.freefall > 0:
        ap.error(f"--freefall {a.freefall:g}: expected a depth > 0 [m]")
    if not a.wall_friction > 0:
        ap.error(f"--wall-friction {a.wall_friction:g}: expected a coefficient > 0")
    airs = {"on": [True], "off": [False], "both": [True, False], None: [True, False]}[a.air]
    runs = [run_one(a, b, air) for b in a.b or [5, 10, 15] for air in airs]
    if a.setup_only:
        return print(f"wedge-silo continuum: run folders written to {a.out}/runs")
    c = gc.checks.Checks("wedge-silo continuum")
    summary(a, runs, c)
    c.report(enforce=a.check)


if __name__ == "__main__":
    gc.cli.main(main)
