#!/usr/bin/python3
"""MCC hopper discharge with the continuum solver granairContinuumFoam (README.md).

    study.py [--out DIR] [--quick] [--check] [--mesh N] [--end T] [--steady-from T] [--np N]
             [--air] [--walls slip] [--eta-max V] [--refine N1 N2 ...] [--rheology muI|latzSchmidt]

One run (or one per N with --refine) from template/: the axisymmetric wedge
mesh at resolution N (cells across the radius), the 1000 g fill, mu(I) of
Remmelgas et al. (2019) (or the lactose latzSchmidt closure of reference case
A on this geometry: a solver test). Per run OUT (OUT/N<n> with --refine):
mass_flow.csv (t, mass_flow_kg_s[, outlet_dpdz_Pa_m]: 10 ms window means of
the outlet flow; the per-step flux carries a step-to-step oscillation),
mass_flow.png, summary.txt, level.json (muI only: a level of `./granair
compare`); with --refine OUT/refinement.csv.

Steady mass flow: least-squares slope of the discharged outlet mass over
[steady-from, end]. Checked (--check exits 1 on a failure): every value
finite; the powder mass balance |m(end) + m_out(end) - m(0)| / m(0) <= 0.5 %
(m_out the time integral of the outlet flow, so powder leaving elsewhere is
an error) and the solver's own; the 1000 g fill within 0.5 %; the steady mass
flow against the Beverloo band (k = 1..3) within the range this solver gives
on these meshes (README); with latzSchmidt every written T finite and >= TMin.
"""
import glob
import math
import os
import time

import numpy as np

import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))


def geometry(n, rho_b):
    """The numbers of the wedge mesh at resolution n and of the fill (template placeholders)."""
    t = math.tan(P.WEDGE_HALF_ANGLE)
    z_apex = -P.H_CONE * P.R_OUT / (P.R_CYL - P.R_OUT)        # cone apex, below the orifice
    rho_out = math.hypot(P.R_OUT, z_apex)                      # radius of the exit cap
    z_cap = z_apex + rho_out
    wall = math.atan2(P.R_CYL - P.R_OUT, P.H_CONE)             # cone wall from the vertical
    # junction arc: centre on the axis, tangent at the wall corner to the bisector
    bisector = math.pi - 0.5 * wall
    z_centre = P.H_CONE - (-math.cos(bisector) / math.sin(bisector)) * P.R_CYL
    r_junction = math.hypot(P.R_CYL, P.H_CONE - z_centre)
    phi_c = math.atan2(P.R_CYL, P.H_CONE - z_centre)
    cap = (rho_out * math.sin(wall / 2), z_apex + rho_out * math.cos(wall / 2))
    junction = (r_junction * math.sin(phi_c / 2), z_centre + r_junction * math.cos(phi_c / 2))
    # fill: the frustum less the lens between the exit cap and the orifice plane, then the cylinder
    frustum = math.pi * P.H_CONE / 3 * (P.R_CYL * P.R_CYL + P.R_CYL * P.R_OUT + P.R_OUT * P.R_OUT)
    lens = math.pi * z_cap * z_cap * (3 * rho_out - z_cap) / 3
    fill_z = P.H_CONE + (P.FILL_MASS / rho_b - (frustum - lens)) / (math.pi * P.R_CYL * P.R_CYL)
    if not fill_z < P.H_CONE + P.H_CYL:
        raise gc.CaseError(f"{P.FILL_MASS * 1e3:.0f} g at {rho_b:g} kg/m3 does not fit in the hopper")
    return dict(N=n, N_CONE=max(4, n), N_CYL=max(8, 2 * n), Z_CAP=z_cap, R_OUT=P.R_OUT, R_OUT_T=P.R_OUT * t,
                R_CYL=P.R_CYL, R_CYL_T=P.R_CYL * t, H_CONE=P.H_CONE, H_TOP=P.H_CONE + P.H_CYL,
                Z_JUNCTION=z_centre + r_junction, CAP_R=cap[0], CAP_RT=cap[0] * t, CAP_Z=cap[1],
                JUNCTION_R=junction[0], JUNCTION_RT=junction[0] * t, JUNCTION_Z=junction[1],
                FILL_G=P.FILL_MASS * 1e3, FILL_Z=fill_z, RHO_B=rho_b)


def write_run(a, n, run):
    latz = a.rheology == "latzSchmidt"
    block = os.path.join(HERE, P.LATZ["block"] if latz else "rheology/muI")
    with open(block) as fh:
        rheology = gc.template.fill(fh.read(), dict(ETA_MAX=a.eta_max), block)
    values = dict(geometry(n, P.LATZ["rho_bulk"] if latz else P.RHO_BULK), END=a.end, NP=a.np,
                  WRITE_FORMAT="ascii" if latz else "binary", WALLS=a.walls,
                  AIR_MODEL="darcyErgun" if a.air else "none", DIAMETER=P.LATZ["d"] if latz else "660e-6",
                  RHEOLOGY=rheology)
    gc.template.render(os.path.join(HERE, "template"), run, values)
    if latz:
        gc.template.render(os.path.join(HERE, "latzSchmidt"), run, values, only=["0/T"])


def run_one(a, n, res, checks):
    run = os.path.join(a.out, "runs", f"N{n}")
    gc.runner.clean(run)
    write_run(a, n, run)
    if a.setup_only:
        return None
    gc.runner.run(["blockMesh"], run)
    gc.runner.run(["checkMesh"], run)
    gc.runner.run(["setAlphaField"], run)
    gc.runner.decompose(run, a.np)
    cells, nonorth = gc.foam.checkmesh(os.path.join(run, "log", "checkMesh.log"))
    print(f"mcc-hopper: N = {n}, {cells} cells, max non-orthogonality {nonorth:g}; running to t = {a.end:g} s "
          f"({a.np} rank(s))", flush=True)
    t0 = time.time()
    gc.runner.run(["granairContinuumFoam"], run, np=a.np)
    wall = round(time.time() - t0)
    summary = post(a, run, res, n, wall, checks)
    print(f"mcc-hopper: N = {n} took {wall} s")
    return dict(summary, cells=cells, run_wall_s=wall)


def post(a, run, res, n, wall, c):
    latz = a.rheology == "latzSchmidt"
    rho_b, d = (P.LATZ["rho_bulk"], P.LATZ["d"]) if latz else (P.RHO_BULK, P.D_PARTICLE)
    r = gc.powder.continuum(run)
    t = r["t"]
    model = f"{P.LATZ['model'] if latz else 'mu(I)'}, N = {n}, {a.walls} walls"
    o = gc.powder.continuum_outputs(r, res, a.steady_from, None, P.WINDOW, 0.0, "mass_flow.csv", None if latz else dict(
        case="mcc-hopper", model=model, b_mm=P.D_OUTLET * 1e3, wall_time_s=float(wall), cores=a.np))
    w, in_window = o["w"], o["flow"][o["centres"] >= a.steady_from]
    w_sd = float(np.sqrt(np.sum((in_window - w) ** 2) / max(1, len(in_window))))
    bev = (P.beverloo(P.K_RANGE[1], rho_b, d), P.beverloo(P.K_RANGE[0], rho_b, d))
    fill_error = (r["initial"] - P.FILL_MASS) / P.FILL_MASS
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
    gc.series.write_keys(os.path.join(res, "summary.txt"), keys + [("run_wall_s", wall), ("cells", cells_of(run))])
    print(f"mcc-hopper: steady mass flow {w:.4g} kg/s (t >= {a.steady_from} s; sd of 10 ms means {w_sd:.2g}); "
          f"Beverloo {bev[0]:.4g}-{bev[1]:.4g} kg/s (k = 3..1); mass balance error {r['balance']:.2e} "
          f"(solver max {r['solver_balance']:.1e}); initial {r['initial']:.6g} kg")
    plot(o["centres"], o["flow"], w, bev, a, t[-1], f"granairContinuumFoam, N = {n}, {a.walls} walls",
         P.LATZ["material"] if latz else "MCC hopper (Remmelgas et al. 2019)", os.path.join(res, "mass_flow.png"))
    gc.powder.check_continuum(c, f"N = {n}", r, P.TOLERANCE, "0.5 %: a few mg leave through the top boundary "
                              "at start-up on fine meshes (README)")
    c.near(f"N = {n}: initial powder / 1000 g fill - 1", fill_error, 0.0, P.TOLERANCE, "setAlphaField of the fill plane")
    band = P.LATZ["band"] if latz else P.BAND
    c.within(f"N = {n}: steady mass flow / Beverloo (k = 1)", w / bev[1], *band,
             "the range this solver gives on N = 10-30 (README; the mesh is not converged): "
             "outside it the flow has stopped, burst or changed model")
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
    ax.set_title(f"{material}, D_o = 25 mm, 1000 g fill", fontsize=9)
    ax.legend(loc="upper right", fontsize=8)
    fig.tight_layout()
    gc.plots.save(fig, path)


def main():
    ap = gc.cli.parser(__doc__)
    ap.add_argument("--quick", action="store_true", help="N = 10, 1 s (the case test, ~10 s)")
    ap.add_argument("--mesh", type=int, default=20, help="cells across the radius (default 20)")
    ap.add_argument("--end", type=float, default=None, help="simulated time [s] (default 2; --quick 1)")
    ap.add_argument("--steady-from", type=float, default=0.5, help="start of the steady window [s]")
    ap.add_argument("--air", action="store_true", help="Darcy-Ergun air drag instead of the dry model")
    ap.add_argument("--walls", choices=["noSlip", "slip"], default="noSlip")
    ap.add_argument("--eta-max", default="1e3", help="viscosity cap of mu(I) [Pa s] (default 1e3)")
    ap.add_argument("--refine", nargs="+", type=int, default=None, help="one run per N: OUT/refinement.csv")
    ap.add_argument("--rheology", choices=["muI", "latzSchmidt"], default="muI")
    a = gc.cli.parse(ap, os.path.join(HERE, "results"))
    if a.quick:
        a.mesh = 10
    a.end = a.end if a.end is not None else (1.0 if a.quick else 2.0)
    for n in a.refine or [a.mesh]:
        if n < 4:
            ap.error(f"--mesh/--refine {n}: expected N >= 4")
    checks = gc.checks.Checks("mcc-hopper")
    if not a.refine:
        run_one(a, a.mesh, a.out, checks)
    else:
        rows = [run_one(a, n, os.path.join(a.out, f"N{n}"), checks) for n in a.refine]
        if not a.setup_only:
            path = gc.series.write_rows(os.path.join(a.out, "refinement.csv"), [
                dict(N=n, cells=r["cells"], steady_mass_flow_kg_s=r["steady_mass_flow_kg_s"],
                     window_sd_kg_s=r["window_mass_flow_sd_kg_s"], mass_balance_error=r["mass_balance_error"],
                     run_wall_s=r["run_wall_s"]) for n, r in zip(a.refine, rows)], fmt="{:.6g}")
            print(f"mcc-hopper: refinement table {path}\n" + open(path).read())
    if a.setup_only:
        return print(f"mcc-hopper: run folders written to {a.out}/runs")
    checks.report(enforce=a.check)

if __name__ == "__main__":
    gc.cli.main(main)
