#!/usr/bin/python3
"""MCC hopper discharge with the continuum solver granairContinuumFoam (README.md).

    study.py [--out DIR] [--quick] [--check] [--mesh N] [--end T] [--steady-from T] [--np N]
             [--air] [--walls coulomb|slip|noSlip] [--wall-friction MU] [--eta-max V]
             [--max-co C] [--transpose-stress on|off] [--freefall L] [--convergence] [--resume]
             [--rheology muI|latzSchmidt] [--rheology-from literature|calibration] [--rheology-d D]
             [--eta-min V] [--orifice D] [--outer N] [--outer-tolerance R] [--fill-g G]

One run from template/: the axisymmetric wedge mesh at resolution N (cells
across the orifice diameter) with the free-fall region below the orifice, the
1000 g fill, mu(I) of Remmelgas et al. (2019) (or the lactose latzSchmidt
closure of reference case A on this geometry: a solver test), Coulomb wall
friction by default. Per run OUT: mass_flow.csv (t, mass_flow_kg_s[,
outlet_dpdz_Pa_m]: 10 ms window means of the outlet flow; the per-step flux
carries a step-to-step oscillation), mass_flow.png, summary.txt (with the
fraction of packed cells with p <= 0 and the outer-corrector statistics),
level.json (muI only: a level of `./granair compare`).

--rheology-from calibration: the mu(I) of the coarse-grained DEM's material
(MCC parcels, s = 5, d = 3.3 mm), fitted from a DEM shear cell in
cases/rheology-calibration (gc.calibration), in place of Remmelgas et al.'s
fit of the real spheres (the default, `literature`: the material
prediction); bulk density rho_p phi_max, Beverloo band with the parcel d.
The run to compare with reference-cg-dem/ (README, "Cross-validation"); no
level.json (the compare tool's continuum level is the material prediction).

--convergence: first the mesh study (convergence.py, README "Mesh
convergence"): one run per N of parameters.MESHES into OUT/convergence/N<n>
and the sensitivity runs of parameters.SENSITIVITY on the finest mesh
(OUT/convergence/N<n>-<tag>); runs with a summary.txt are not run again, so an
interrupted study resumes (--resume does the same for a single run). Then Roache's GCI over the three finest meshes
goes into OUT/convergence/convergence.{csv,json,md,png} and, as "mesh_study",
into the level.json of the run (`./granair compare` prints it).

Sensitivity options (README, "Cross-validation"): --eta-min sets the
viscosity floor of mu(I) (default rho_p d sqrt(g d) of the block's d);
--orifice D [m] makes the orifice D wide with the same cone slope (the cone
continues down to it, z = 0 stays the orifice plane); --outer N iterates
each step with up to N outer correctors until U and p change by less than
--outer-tolerance (default one corrector per step); --fill-g the fill mass
(the DEM field runs use a smaller fill than 1000 g).

Steady mass flow: least-squares slope of the discharged outlet mass over
[steady-from, end]. Checked (--check exits 1 on a failure): every value
finite; the powder mass balance |m(end) + m_out(end) - m(0)| / m(0) <= 0.5 %
(m_out the time integral of the outlet flow, so powder leaving elsewhere is
an error) and the solver's own; the 1000 g fill within 0.5 %; the steady mass
flow against the Beverloo band (k = 1..3) within the range this solver gives
on these meshes (README); with latzSchmidt every written T finite and >= TMin.
"""
import glob
import json
import math
import os
import time

import numpy as np

import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))


def geometry(n_diameter, rho_b, freefall, outlet=P.D_OUTLET, fill=P.FILL_MASS):
    """The numbers of the wedge mesh with n_diameter cells across the orifice
    diameter (n_diameter/2 across the wedge's radius), the free-fall region of
    length `freefall` [m] below the orifice, and the fill (template placeholders).
    outlet: the orifice diameter; the cone keeps its slope and ends at it (a smaller
    orifice makes the cone taller by the difference of the radii over its slope); fill [kg]
    the powder mass, which must fill the cone."""
    n = n_diameter // 2
    t = math.tan(P.WEDGE_HALF_ANGLE)
    r_out = outlet / 2
    h_cone = (P.R_CYL - r_out) / P.TAN_CONE
    z_apex = -h_cone * r_out / (P.R_CYL - r_out)              # cone apex, below the orifice
    rho_out = math.hypot(r_out, z_apex)                        # radius of the exit cap
    z_cap = z_apex + rho_out
    wall = math.atan2(P.R_CYL - r_out, h_cone)                 # cone wall from the vertical
    # junction arc: centre on the axis, tangent at the wall corner to the bisector
    bisector = math.pi - 0.5 * wall
    z_centre = h_cone - (-math.cos(bisector) / math.sin(bisector)) * P.R_CYL
    r_junction = math.hypot(P.R_CYL, h_cone - z_centre)
    phi_c = math.atan2(P.R_CYL, h_cone - z_centre)
    cap = (rho_out * math.sin(wall / 2), z_apex + rho_out * math.cos(wall / 2))
    junction = (r_junction * math.sin(phi_c / 2), z_centre + r_junction * math.cos(phi_c / 2))
    # fill: the frustum (the lens between the exit cap and the orifice plane is in the
    # free-fall block, above z = 0, so it is filled too), then the cylinder
    frustum = math.pi * h_cone / 3 * (P.R_CYL * P.R_CYL + P.R_CYL * r_out + r_out * r_out)
    fill_z = h_cone + (fill / rho_b - frustum) / (math.pi * P.R_CYL * P.R_CYL)
    if not h_cone < fill_z < h_cone + P.H_CYL:
        raise gc.CaseError(f"{fill * 1e3:.0f} g at {rho_b:g} kg/m3: expected a fill above the cone "
                           f"({frustum * rho_b * 1e3:.0f} g) that fits in the hopper")
    # free-fall cells about as tall as the orifice cells are wide (its axis runs from -L to the cap)
    n_fall = max(2, round((freefall + 0.5 * z_cap) / (r_out / n)))
    return dict(N=n, N_DIAMETER=n_diameter, N_CONE=max(4, n), N_CYL=max(8, 2 * n), N_FALL=n_fall,
                FREEFALL=freefall, Z_CAP=z_cap, R_OUT=r_out, R_OUT_T=r_out * t,
                R_CYL=P.R_CYL, R_CYL_T=P.R_CYL * t, H_CONE=h_cone, H_TOP=h_cone + P.H_CYL,
                Z_JUNCTION=z_centre + r_junction, CAP_R=cap[0], CAP_RT=cap[0] * t, CAP_Z=cap[1],
                JUNCTION_R=junction[0], JUNCTION_RT=junction[0] * t, JUNCTION_Z=junction[1],
                FILL_G=fill * 1e3, FILL_Z=fill_z, RHO_B=rho_b)


def walls_text(a):
    return f"Coulomb (mu_w {a.wall_friction:g})" if a.walls == "coulomb" else a.walls


def material(a):
    """(bulk density [kg/m3], particle diameter [m]) of the run's powder: the latzSchmidt
    closure's, the DEM calibration's (rho_p phi_max, the parcel d) or the real spheres'."""
    if a.rheology == "latzSchmidt":
        return P.LATZ["rho_bulk"], P.LATZ["d"]
    if a.rheology_from == "calibration":
        f = gc.calibration.fit(P.CALIBRATION)
        return f["rho_p"] * f["phi_max"], a.rheology_d or f["d"]
    return P.RHO_BULK, P.D_PARTICLE


def write_run(a, n, run):
    latz = a.rheology == "latzSchmidt"
    block = os.path.join(HERE, P.LATZ["block"] if latz else "rheology/muI")
    with open(block) as fh:
        rheology = gc.template.fill(fh.read(), dict(ETA_MAX=a.eta_max), block)
    if a.rheology_from == "calibration":
        rheology = gc.calibration.block(rheology, P.CALIBRATION, d=a.rheology_d, where=block)
    if a.eta_min is not None:
        rheology = gc.calibration.set_entry(rheology, "etaMin", a.eta_min, "study.py --eta-min")
    rho_b, d = material(a)
    values = dict(geometry(n, rho_b, a.freefall, outlet(a), a.fill_g * 1e-3), END=a.end, NP=a.np,
                  N_OUTER=a.outer, OUTER_TOL=a.outer_tolerance,
                  WRITE_FORMAT="ascii" if latz or a.ascii else "binary",
                  WALL_U=gc.foam.wall_velocity(a.walls, a.wall_friction),
                  MAX_CO=a.max_co, TRANSPOSE=a.transpose_stress,
                  AIR_MODEL="darcyErgun" if a.air else "none", DIAMETER=f"{d:.6g}",
                  DILATANCY=gc.dilatancy.block(a, "study.py"),
                  RHEOLOGY=rheology)
    gc.template.render(os.path.join(HERE, "template"), run, values)
    if latz:
        gc.template.render(os.path.join(HERE, "latzSchmidt"), run, values, only=["0/T"])


SETTINGS = ("mesh", "end", "steady_from", "air", "walls", "wall_friction", "eta_max", "max_co", "transpose_stress",
            "freefall", "rheology")
CALIBRATION_SETTINGS = ("rheology_from", "rheology_d")   # only with --rheology-from calibration, so the
                                                          # literature runs' settings.json stay as they were
OPTIONAL_SETTINGS = dict(eta_min=None, orifice=None, outer=1, outer_tolerance=P.OUTER_TOLERANCE,
                         fill_g=P.FILL_MASS * 1e3, dilatancy=False,
                         dilatancy_rate=P.DILATANCY_RATE, dilatancy_relaxation=P.DILATANCY_RELAXATION)                 # only when not
                                                          # the default, for the same reason


def settings(a, n):
    """What a run's result depends on (res/settings.json; a study reuses a run only if they match)."""
    keys = SETTINGS + (CALIBRATION_SETTINGS if a.rheology_from == "calibration" else ())
    keys += tuple(k for k, default in OPTIONAL_SETTINGS.items() if getattr(a, k) != default)
    return dict({k: getattr(a, k) for k in keys}, mesh=n, eta_max=float(a.eta_max))


def outlet(a):
    return a.orifice if a.orifice is not None else P.D_OUTLET


def finished(res, n, a):
    """'summary' if res holds the finished result of these settings, 'solved' if only the
    solver finished (post-processing left), else None."""
    try:
        with open(os.path.join(res, "settings.json")) as fh:
            if json.load(fh) != settings(a, n):
                return None
    except (OSError, ValueError):
        return None
    if os.path.exists(os.path.join(res, "summary.txt")):
        return "summary"
    if os.path.exists(os.path.join(res, "run.json")):
        return "solved"
    return None


def run_one(a, n, res, checks, level=True, reuse=False):
    """One run into res/runs/N<n>, post-processed into res; returns its summary. With
    reuse, a finished run of the same settings is not run again (a resumed study)."""
    run = os.path.join(res, "runs", f"N{n}")
    state = finished(res, n, a) if reuse else None
    if state == "summary":
        print(f"mcc-hopper: {os.path.relpath(res, HERE)} finished before: not run again", flush=True)
        return gc.series.read_keys(os.path.join(res, "summary.txt"))
    if state is None:
        gc.runner.clean(run)
        write_run(a, n, run)
        if a.setup_only:
            return None
        gc.runner.run(["blockMesh"], run)
        gc.runner.run(["checkMesh"], run)
        gc.runner.run(["setAlphaField"], run)
        gc.runner.run(["setFields"], run)
        gc.runner.decompose(run, a.np)
        cells, nonorth = gc.foam.checkmesh(os.path.join(run, "log", "checkMesh.log"))
        print(f"mcc-hopper: N = {n}, {cells} cells, max non-orthogonality {nonorth:g}; running to t = {a.end:g} s "
              f"({a.np} rank(s))", flush=True)
        os.makedirs(res, exist_ok=True)
        with open(os.path.join(res, "settings.json"), "w") as fh:
            json.dump(settings(a, n), fh, indent=1)
        t0 = time.time()
        cpu = gc.runner.run(["granairContinuumFoam"], run, np=a.np)
        with open(os.path.join(res, "run.json"), "w") as fh:
            json.dump(dict(run_wall_s=round(time.time() - t0), run_cpu_s=round(cpu)), fh)
    with open(os.path.join(res, "run.json")) as fh:
        cost = json.load(fh)
    summary = post(a, run, res, n, cost["run_wall_s"], cost["run_cpu_s"], checks, level)
    print(f"mcc-hopper: N = {n} took {cost['run_wall_s']} s ({cost['run_cpu_s']:.0f} CPU-s)")
    return summary


def numerics(run, t0):
    """The step statistics of the time series (PowderBalance.H): the fraction of packed
    cells with p <= 0 beyond two cells of the outlet and the orifice plane (mean and max
    over t >= t0), the outer correctors per step and the steps that did not converge."""
    s = gc.series.read_csv(os.path.join(run, "postProcessing", "timeSeries.csv"), min_rows=2)
    steady = s["t"] >= t0
    ten = s["tension_fraction"][steady] if np.any(steady) else s["tension_fraction"]
    return [("tension_fraction_mean", float(np.mean(ten))), ("tension_fraction_max", float(np.max(ten))),
            ("steps", int(len(s["t"]))), ("outer_correctors_mean", float(np.mean(s["outer_correctors"]))),
            ("unconverged_steps", int(np.sum(s["outer_converged"] == 0)))]


def post(a, run, res, n, wall, cpu, c, level=True):
    latz = a.rheology == "latzSchmidt"
    rho_b, d = material(a)
    r = gc.powder.continuum(run)
    t = r["t"]
    calibrated = a.rheology_from == "calibration"
    model = (f"{P.LATZ['model'] if latz else 'DEM-calibrated mu(I)' if calibrated else 'mu(I)'}, N = {n}, "
             f"{walls_text(a)} walls")
    o = gc.powder.continuum_outputs(r, res, a.steady_from, None, P.WINDOW, 0.0, "mass_flow.csv",
                                    None if latz or calibrated or not level else dict(
        case="mcc-hopper", model=model, b_mm=P.D_OUTLET * 1e3, wall_time_s=float(wall), cores=a.np))
    w, in_window = o["w"], o["flow"][o["centres"] >= a.steady_from]
    w_sd = float(np.sqrt(np.sum((in_window - w) ** 2) / max(1, len(in_window))))
    bev = (P.beverloo(P.K_RANGE[1], rho_b, d, outlet(a)), P.beverloo(P.K_RANGE[0], rho_b, d, outlet(a)))
    fill_error = (r["initial"] - a.fill_g * 1e-3) / (a.fill_g * 1e-3)
    keys = [("t_end_s", float(t[-1])), ("steady_from_s", a.steady_from), ("steady_mass_flow_kg_s", w),
            ("window_mass_flow_sd_kg_s", w_sd), ("beverloo_k3_kg_s", bev[0]), ("beverloo_k1_kg_s", bev[1]),
            ("steady_over_beverloo_k1", w / bev[1]), ("initial_powder_kg", r["initial"]), ("fill_error", fill_error),
            ("final_powder_kg", float(r["mass"][-1])), ("discharged_outlet_kg", float(r["out"][-1])),
            ("mass_balance_error", r["balance"]), ("solver_mass_balance_error_max", r["solver_balance"]),
            ("all_finite", int(r["finite"]))]
    temps = temperatures(run) if latz else None
    if temps is not None:
        keys += [("temperature_fields", temps[1]), ("temperature_min_m2_s2", float(np.min(temps[0]))),
                 ("temperature_max_m2_s2", float(np.max(temps[0])))]
    keys += numerics(run, a.steady_from)
    keys += [("run_wall_s", wall), ("run_cpu_s", float(cpu)), ("cells", cells_of(run))]
    gc.series.write_keys(os.path.join(res, "summary.txt"), keys)
    print(f"mcc-hopper: steady mass flow {w:.4g} kg/s (t >= {a.steady_from} s; sd of 10 ms means {w_sd:.2g}); "
          f"Beverloo {bev[0]:.4g}-{bev[1]:.4g} kg/s (k = 3..1); mass balance error {r['balance']:.2e} "
          f"(solver max {r['solver_balance']:.1e}); initial {r['initial']:.6g} kg")
    plot(o["centres"], o["flow"], w, bev, a, t[-1], f"granairContinuumFoam, N = {n}, {walls_text(a)} walls",
         P.LATZ["material"] if latz else ("MCC parcels (s = 5), mu(I) calibrated from DEM" if calibrated else
                                          "MCC hopper (Remmelgas et al. 2019)"), os.path.join(res, "mass_flow.png"))
    gc.powder.check_continuum(c, f"N = {n}", r, P.TOLERANCE, "0.5 %: ~2e-4 of the powder leaves through the open "
                              "side of the free-fall region, which the outlet integral counts as error (README)")
    c.near(f"N = {n}: initial powder / {a.fill_g:g} g fill - 1", fill_error, 0.0, P.TOLERANCE, "setAlphaField of the fill plane")
    band = P.LATZ["band"] if latz else P.BAND
    c.within(f"N = {n}: steady mass flow / Beverloo (k = 1)", w / bev[1], *band,
             "the range of the runs in the README: outside it the flow has stopped, burst or changed model")
    if temps is not None:
        floor = P.LATZ["t_floor"] * (1 - 1e-9)     # written with 10 digits
        c.within(f"N = {n}: lowest granular temperature of {temps[1]} fields [m2/s2]", float(np.min(temps[0])),
                 floor, math.inf, "TMin = 1e-12 is the closure's floor")
    return dict(keys)


def temperatures(run):
    """Every cell value of the written T fields (ASCII, times > 0, serial or processor*/)."""
    vals = [gc.foam.read_field(p).ravel() for base in [run] + sorted(glob.glob(os.path.join(run, "processor*")))
            for t, d in gc.foam.time_dirs(base) if t > 0 for p in [os.path.join(d, "T")] if os.path.exists(p)]
    return (np.concatenate(vals), len(vals)) if vals else (np.array([math.nan]), 0)


def cells_of(run):
    return gc.foam.checkmesh(os.path.join(run, "log", "checkMesh.log"))[0]


def plot(tw, flow, w, bev, a, t_end, label, material, path):
    plt = gc.plots.pyplot()
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.axhspan(bev[0], bev[1], color="tab:orange", alpha=0.3, label=f"Beverloo, C = {P.BEVERLOO_C}, k = 1..3")
    ax.plot(tw, flow, color="tab:blue", lw=1, label=f"{label} (10 ms means)")
    if math.isfinite(w):
        ax.hlines(w, a.steady_from, t_end, colors="k", linestyles="--",
                  label=f"mean for t >= {a.steady_from:g} s: {w * 1e3:.1f} g/s")
    ax.set(xlabel="t [s]", ylabel="powder mass flow [kg/s]", ylim=(0, max(1.3 * bev[1], 1.1 * max(list(flow) + [0.0]))))
    ax.set_title(f"{material}, D_o = 25 mm, {a.fill_g:g} g fill", fontsize=9)
    ax.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    gc.plots.save(fig, path)


def main():
    ap = gc.cli.parser(__doc__)
    ap.add_argument("--quick", action="store_true", help="N = 14, 1 s (the case test)")
    ap.add_argument("--mesh", type=int, default=P.MESHES[-1],
                    help=f"cells across the orifice diameter, even (default {P.MESHES[-1]})")
    ap.add_argument("--end", type=float, default=None, help="simulated time [s] (default 2; --quick 1)")
    ap.add_argument("--steady-from", type=float, default=0.5, help="start of the steady window [s]")
    ap.add_argument("--air", action="store_true", help="Darcy-Ergun air drag instead of the dry model")
    ap.add_argument("--walls", choices=gc.foam.WALLS, default="coulomb",
                    help="coulomb (Coulomb wall friction, default), slip (free slip) or noSlip")
    ap.add_argument("--wall-friction", type=float, default=P.WALL_FRICTION,
                    help=f"wall friction coefficient of --walls coulomb (default {P.WALL_FRICTION:g})")
    ap.add_argument("--eta-max", default=P.ETA_MAX, help=f"viscosity cap of mu(I) [Pa s] (default {P.ETA_MAX})")
    ap.add_argument("--max-co", type=float, default=P.MAX_CO, help=f"maxCo and maxAlphaCo (default {P.MAX_CO:g})")
    ap.add_argument("--transpose-stress", choices=["on", "off"], default="on",
                    help="the grad U^T part of the viscous stress (default on)")
    ap.add_argument("--freefall", type=float, default=P.FREEFALL,
                    help=f"length of the free-fall region below the orifice [m] (default {P.FREEFALL:g})")
    ap.add_argument("--convergence", action="store_true",
                    help="the mesh study and the sensitivity runs first (OUT/convergence), the GCI into level.json")
    ap.add_argument("--resume", action="store_true",
                    help="a finished run of the same settings (OUT/settings.json) is not run again")
    ap.add_argument("--rheology", choices=["muI", "latzSchmidt"], default="muI")
    ap.add_argument("--rheology-from", choices=["literature", "calibration"], default="literature",
                    help="muI parameters: Remmelgas et al.'s fit of the real spheres (default) or the DEM "
                         "calibration of the coarse-grained DEM's parcels (cases/rheology-calibration)")
    ap.add_argument("--rheology-d", type=float, default=None,
                    help="with the calibration: the grain diameter of I [m] instead of the parcel's (sensitivity)")
    gc.dilatancy.options(ap, P.DILATANCY_RATE, P.DILATANCY_RELAXATION)
    ap.add_argument("--ascii", action="store_true", help="write the fields as ASCII (for the field profiles)")
    ap.add_argument("--eta-min", type=float, default=None,
                    help="viscosity floor of mu(I) [Pa s] (default the block's rho_p d sqrt(g d))")
    ap.add_argument("--orifice", type=float, default=None,
                    help=f"orifice diameter [m], the cone's slope kept (default {P.D_OUTLET:g})")
    ap.add_argument("--fill-g", type=float, default=P.FILL_MASS * 1e3,
                    help=f"fill mass [g] (default {P.FILL_MASS * 1e3:g}; as the DEM's Allrun-dem --fill-g)")
    ap.add_argument("--outer", type=int, default=1,
                    help="outer correctors per step, at most (default 1: a semi-implicit time march)")
    ap.add_argument("--outer-tolerance", type=float, default=P.OUTER_TOLERANCE,
                    help=f"with --outer > 1: the relative change of U and p that ends a step (default {P.OUTER_TOLERANCE:g})")
    a = gc.cli.parse(ap, os.path.join(HERE, "results"))
    if a.quick:
        a.mesh = 14
    a.end = a.end if a.end is not None else (1.0 if a.quick else 2.0)
    if a.mesh < 8 or a.mesh % 2:
        ap.error(f"--mesh {a.mesh}: expected an even N >= 8 (cells across the orifice diameter)")
    if not a.freefall > 0:
        ap.error(f"--freefall {a.freefall:g}: expected a length > 0 [m]")
    if not a.wall_friction > 0:
        ap.error(f"--wall-friction {a.wall_friction:g}: expected a coefficient > 0")
    if a.rheology_from == "calibration" and a.rheology != "muI":
        ap.error("--rheology-from calibration: the calibration is a muI block (--rheology muI)")
    if a.rheology_d is not None and not (a.rheology_d > 0 and a.rheology_from == "calibration"):
        ap.error(f"--rheology-d {a.rheology_d:g}: expected a diameter > 0 [m], with --rheology-from calibration")
    gc.dilatancy.check(ap, a, P.DILATANCY_RATE, P.DILATANCY_RELAXATION)
    if not a.max_co > 0:
        ap.error(f"--max-co {a.max_co:g}: expected a Courant number > 0")
    if a.eta_min is not None and not a.eta_min > 0:
        ap.error(f"--eta-min {a.eta_min:g}: expected a viscosity > 0 [Pa s]")
    if a.orifice is not None and not 0.004 <= a.orifice <= 2 * P.R_OUT + 0.01:
        ap.error(f"--orifice {a.orifice:g}: expected a diameter in 0.004-{2 * P.R_OUT + 0.01:g} m")
    if a.outer < 1 or not 0 < a.outer_tolerance < 1:
        ap.error(f"--outer {a.outer} (>= 1), --outer-tolerance {a.outer_tolerance:g} (0-1)")
    checks = gc.checks.Checks("mcc-hopper")
    study = None
    if a.convergence and not a.setup_only:
        import convergence
        study = convergence.study(a, lambda b, n, res: run_one(b, n, res, checks, level=False, reuse=True))
    run_one(a, a.mesh, a.out, checks, reuse=a.convergence or a.resume)
    if a.setup_only:
        return print(f"mcc-hopper: run folder written to {a.out}/runs")
    if study is not None:
        convergence.add_to_level(study, os.path.join(a.out, "level.json"))
    checks.report(enforce=a.check)


if __name__ == "__main__":
    gc.cli.main(main)
