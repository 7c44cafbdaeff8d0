#!/usr/bin/python3
"""The MCC hopper in coarse-grained DEM, dry (granairFoam `air off`; README.md,
"Coarse-grained DEM").

    dem.py [--out DIR] [--quick] [--check] [--s S] [--fill-g G] [--end T] [--np 1|2] [--cg-every T] [--setup-only]

Fill (OUT/runs/fill): random sequential addition of parcels of s x 660 um in
the cone and cylinder above the shutter (z = 0), settled on it for at least
settle-min s until the rms speed is below 5 mm/s (LIGGGHTS, template-dem/dem/in.fill).
Discharge (OUT/runs/discharge): granairFoam from the fill's restart, the
shutter gone. OUT: mass_flow.csv (50 ms means of the discharged-mass rate),
level.json (level cg-dem), mass_flow.png (Beverloo bands with the primary and
the parcel d), summary.txt (accounting, steady rate, Beverloo, Carleton, cost).

Steady mass flow: least-squares slope of the discharged mass (parcels crossing
z = 0 the first time) over [steady-from, end]. Checked: the parcel accounting
closes exactly (inserted = in hopper + between outlet and sink + removed at
the sink = parcels packed, lost 0: integer counts), and the steady rate within
the Beverloo band of the parcel diameter (k = 1..3), where the measured
s = 4, 5 and 6 rates fall (k = 1.56, 1.51, 1.46 with C = 0.58; README).

--cg-every T (s, 0 = off): the discharge also writes the CG dumps
(dem-side/liggghts/cg-dumps.liggghts: particles, pairs, cone contacts) every
T; cg.py then computes the CG fields (granairCG, RZ about the axis, time
averaged over the steady window) into OUT/cg/ and checks their mass flow
through the orifice against the counted one (README, "Cross-validation").
"""
import math
import os
import random
import time

import numpy as np

import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))


def numbers(a):
    """The run's numbers (template placeholders and the post-processing's)."""
    d = a.s * P.D_PARTICLE
    n = round(a.fill_g * 1e-3 / (P.RHO_P * math.pi / 6 * d ** 3))
    t_r = gc.dem.rayleigh_time(d / 2, P.YOUNGS, P.NU, P.RHO_P)
    interval, dem_dt = gc.dem.time_steps(P.CFD_DT, t_r, P.RAYLEIGH_FRACTION)
    n_steps = max(1, round(a.end / P.CFD_DT))
    chunk = max(1, round(0.02 / dem_dt))
    return dict(S=a.s, D=d, N_PARCELS=n, SKIN=0.3 * d, YOUNGS=P.YOUNGS, NU=P.NU, E=P.RESTITUTION, MU_PP=P.FRICTION_PP,
                MU_PW=P.FRICTION_PW, DEM_DT=dem_dt, COUPLING_INTERVAL=interval, G=P.G, R_CYL=P.R_CYL, RHO_P=P.RHO_P,
                R_PARCEL=d / 2, SOFT_PARTICLES="soft_particles  yes             # LIGGGHTS asks for this below E = 5e6 Pa"
                if P.YOUNGS < 5e6 else "# (E >= 5e6 Pa: no soft_particles needed)", CHUNK=chunk,
                SETTLE_MIN=a.settle_min, SETTLE_MAX=0.6, N_MIN=math.ceil(a.settle_min / (chunk * dem_dt)),
                N_MAX=math.ceil(0.6 / (chunk * dem_dt)), T_END=n_steps * P.CFD_DT, CFD_DT=P.CFD_DT, N_STEPS=n_steps,
                NP=a.np, SINK_Z=P.SINK_Z, THERMO_EVERY=round(0.1 / dem_dt), FILL="../fill", HALF=P.BOX_HALF,
                Z0=P.SINK_Z - 0.01, RAYLEIGH_S=t_r, CG_EVERY=round(a.cg_every / dem_dt),
                GRANAIR_ROOT=os.path.normpath(os.path.join(HERE, "..", "..")))


def packing(v, seed):
    """Random sequential addition of equal parcels into cone + cylinder above the
    shutter at about PACKING_INSERT solid fraction: [(x, y, z, d)] and the box top."""
    d = v["D"]
    r, gap = d / 2, 0.02 * d
    loose = v["N_PARCELS"] * math.pi / 6 * d ** 3 / P.PACKING_INSERT
    top = P.H_CONE if loose <= P.V_CONE else P.H_CONE + (loose - P.V_CONE) / (math.pi * P.R_CYL ** 2)
    cosc, rmax = math.cos(math.atan(P.TAN_CONE)), P.R_CYL - r - gap

    def sample(rng, r, top):
        z = rng.uniform(r, top)
        rr = min(rmax, P.R_OUT + z * P.TAN_CONE) if z < P.H_CONE else rmax
        return rng.uniform(-rr, rr), rng.uniform(-rr, rr), z

    def inside(x, y, z, r):
        rho = math.hypot(x, y)
        return not (z < r + gap or rho > rmax
                    or (z < P.H_CONE + r and (P.R_OUT + z * P.TAN_CONE - rho) * cosc < r + gap))
    atoms = gc.dem.loose_packing([d] * v["N_PARCELS"], random.Random(seed), sample, inside, lambda t: t + 0.002, top,
                                 d * 1.0001, gap, square=lambda x: x ** 2)   # x ** 2 as the reference packing
    # the DEM box and CFD mesh top: above the loose packing and the cylinder
    h = P.H_CONE + max(0.0, loose - P.V_CONE) / (math.pi * P.R_CYL ** 2)
    box_top = max(P.H_CONE + P.H_CYL, 1.25 * h + 0.01)
    zmax = max(a[2] for a in atoms) + r
    return atoms, zmax + 0.01 if zmax > box_top else box_top


def cone(n_phi=48, n_z=6):
    """The hopper's cone wall, orifice (z = 0) to the cylinder (z = H_CONE), as n_z x n_phi quads."""
    return gc.dem.stl("cone", gc.stl_walls.revolution(P.R_OUT, P.R_OUT + P.H_CONE * P.TAN_CONE, 0.0, P.H_CONE,
                                                       n_z, n_phi))


def setup(a, v, fill, run):
    atoms, top = packing(v, a.seed)
    v.update(Z1=top, NZ=max(4, round((top - v["Z0"]) / 0.02)))
    src = os.path.join(HERE, "template-dem")
    gc.template.render(src, fill, v, only=["dem/in.fill", "dem/in.materials"])
    gc.dem.write_data(os.path.join(fill, "dem", "packing.data"), atoms,
                      (-P.BOX_HALF, P.BOX_HALF, -P.BOX_HALF, P.BOX_HALF, v["Z0"], top), P.RHO_P,
                      f"MCC hopper loose packing: {len(atoms)} parcels of {v['D'] * 1e3:.4g} mm (dem.py)")
    gc.template.render(src, run, v, only=["system", "constant", "0", "dem/in.liggghts", "dem/in.materials"])
    for d in (fill, run):
        gc.template.write(os.path.join(d, "dem", "cone.stl"), cone())
    return len(atoms)


def post(a, v, runs, n_packed, cpu, wall, c):
    r = gc.powder.dem(os.path.join(runs, "discharge"))
    t, m, bal = r["t"], r["series"]["discharged_kg"], r["balance"]
    centres, (flow,) = gc.powder.flow_windows(t, m, P.DEM_WINDOW, keep_last=None, tol=1e-9)
    steady = min(a.steady_from, 0.4 * a.end)       # the window starts at 0.5 s, or earlier in short runs
    w = gc.series.slope(t, m, steady)
    sel = flow[centres >= steady]
    w_sd = float(np.sqrt(np.mean((sel - w) ** 2))) if sel.size else math.nan
    d = v["D"]
    bev = {"primary": (P.beverloo(P.K_RANGE[1]), P.beverloo(P.K_RANGE[0])),
           "parcel": (P.beverloo(P.K_RANGE[1], d=d), P.beverloo(P.K_RANGE[0], d=d))}
    theta = math.degrees(math.atan(P.TAN_CONE))
    carleton = gc.closed_forms.carleton_ratio(P.D_OUTLET, theta, P.D_PARTICLE, P.RHO_P, P.AIR_RHO, P.AIR_MU, P.G)
    in_flight = bal["discharged"] - bal["removed"]
    in_hopper = bal["present"] - in_flight
    dump = gc.dem.read_dump(os.path.join(runs, "fill", "dem", "fill.dump"))
    top = float(np.mean(np.sort(dump["z"])[::-1][:200]))        # the settled fill: the 200 highest parcels
    z0, z1 = P.H_CONE + 2 * d, top - 2 * d                       # bulk density in the cylinder below it
    rho_b = float(dump["mass"][(dump["z"] > z0) & (dump["z"] < z1)].sum() / (math.pi * P.R_CYL ** 2 * (z1 - z0))) \
        if z1 - z0 >= 4 * d else math.nan
    gc.series.write_csv(os.path.join(a.out, "mass_flow.csv"), [("t", centres), ("mass_flow_kg_s", flow)], fmt="{:.6g}")
    gc.levels.write(os.path.join(a.out, "level.json"), case="mcc-hopper", level="cg-dem",
                    model=f"coarse-grained DEM (LIGGGHTS Hertz-Mindlin, no cohesion), s = {a.s:g} ({d * 1e3:.3g} mm "
                          f"parcels), E = {P.YOUNGS:.3g} Pa, e = {P.RESTITUTION}, mu_pp = {P.FRICTION_PP}, mu_pw = "
                          f"{P.FRICTION_PW}, {a.fill_g:g} g fill, dry",
                    b_mm=25, air=False, steady_mass_flow_kg_s=w, steady_window_s=[steady, round(float(t[-1]), 6)],
                    outlet_dpdz_Pa_m=None, wall_time_s=round(sum(wall.values()), 1), cores=a.np,
                    timeseries="mass_flow.csv")
    keys = [("coarse_graining_factor", a.s), ("d_parcel_m", d), ("outlet_over_d_parcel", P.D_OUTLET / d),
            ("fill_g", a.fill_g), ("parcels_packed", n_packed), ("youngs_Pa", P.YOUNGS), ("dem_dt_s", v["DEM_DT"]),
            ("settled_top_m", top), ("settled_bulk_density_kg_m3", rho_b), ("t_end_s", float(t[-1])),
            ("steady_from_s", steady), ("steady_mass_flow_kg_s", w), ("window_mass_flow_sd_kg_s", w_sd),
            ("beverloo_primary_k3_kg_s", bev["primary"][0]), ("beverloo_primary_k1_kg_s", bev["primary"][1]),
            ("beverloo_parcel_k3_kg_s", bev["parcel"][0]), ("beverloo_parcel_k1_kg_s", bev["parcel"][1]),
            ("steady_over_beverloo_primary_k1", w / bev["primary"][1]), ("carleton_air_over_dry", carleton),
            ("inserted", bal["inserted"]), ("in_hopper", in_hopper), ("between_outlet_and_sink", in_flight),
            ("removed_at_sink", bal["removed"]), ("discharged", bal["discharged"]), ("lost", bal["lost"]),
            ("inserted_kg", bal["inserted_kg"]), ("discharged_kg", bal["discharged_kg"]),
            ("accounting_closes", int(bal["lost"] == 0 and bal["inserted"] == in_hopper + in_flight + bal["removed"]
                                      and bal["inserted"] == n_packed))]
    for name in cpu:
        keys += [(f"{name}_cpu_s", round(cpu[name], 2)), (f"{name}_wall_s", wall[name])]
    keys += [("total_cpu_s", round(sum(cpu.values()), 2)), ("total_wall_s", sum(wall.values())), ("ranks_discharge", a.np)]
    gc.series.write_keys(os.path.join(a.out, "summary.txt"), keys, "MCC hopper, coarse-grained DEM, dry (dem.py). "
                         "Accounting: inserted = in_hopper + between_outlet_and_sink + removed_at_sink, lost = 0")
    print(f"mcc-hopper cg-dem: steady mass flow {w:.4g} kg/s (t = {steady:g}-{t[-1]:g} s, sd of 50 ms means {w_sd:.2g}); "
          f"Beverloo {bev['primary'][0]:.4g}-{bev['primary'][1]:.4g} kg/s (primary d), {bev['parcel'][0]:.4g}-"
          f"{bev['parcel'][1]:.4g} kg/s (parcel d); accounting {bal['inserted']} = {in_hopper} + {in_flight} + "
          f"{bal['removed']}, lost {bal['lost']}; CPU {sum(cpu.values()):.0f} s")
    plot(a, centres, flow, w, steady, float(t[-1]), bev, d, os.path.join(a.out, "mass_flow.png"))
    c.exact("parcels packed = inserted = in hopper + between outlet and sink + removed at the sink",
            (n_packed, bal["inserted"]), (in_hopper + in_flight + bal["removed"],) * 2, "integer counts")
    c.exact("parcels lost", bal["lost"], 0, "DischargeCounter: every parcel is in the hopper, below it or removed")
    c.within("steady mass flow [kg/s] in the Beverloo band of the parcel d (k = 3..1)", w, *bev["parcel"],
             "the s = 4, 5, 6 runs give k = 1.56, 1.51, 1.46 in parcel diameters (README)")


def plot(a, tw, flow, w, steady, t_end, bev, d, path):
    plt = gc.plots.pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 4.2))
    ax.axhspan(*bev["primary"], color="tab:orange", alpha=0.3, label=f"Beverloo, d = {P.D_PARTICLE * 1e6:.0f} um, k = 1..3")
    ax.axhspan(*bev["parcel"], facecolor="none", edgecolor="tab:green", hatch="//", lw=0.8,
               label=f"Beverloo, parcel d = {d * 1e3:.2g} mm, k = 1..3")
    ax.plot(tw, flow, color="tab:blue", lw=1.2, label="cg-DEM, dry (50 ms means)")
    if math.isfinite(w):
        ax.hlines(w, steady, t_end, colors="k", linestyles="--", label=f"steady, t >= {steady:g} s: {w * 1e3:.1f} g/s")
    for (label, sub), ls in zip((("continuum mu(I), no-slip walls (N = 20)", "results"),
                                 ("continuum mu(I), free-slip walls (N = 20)", "results/slip")), (":", "-.")):
        p = os.path.join(HERE, sub, "summary.txt")
        if os.path.exists(p):
            val = gc.series.read_keys(p)["steady_mass_flow_kg_s"]
            ax.axhline(val, color="tab:red", ls=ls, lw=1, label=f"{label}: {val * 1e3:.0f} g/s")
    ax.set(xlabel="t [s]", ylabel="mass flow [kg/s]", xlim=(0, t_end), ylim=(0, 1.35 * max([bev["primary"][1]] + list(flow))),
           title=f"MCC hopper, D_o = 25 mm, {a.fill_g:g} g, cg-DEM s = {a.s:g}, no air")
    ax.legend(loc="lower right", fontsize=7)
    fig.tight_layout()
    gc.plots.save(fig, path, dpi=110)


def main():
    ap = gc.cli.parser(__doc__, out_help="results (default: reference-cg-dem/ beside this script)")
    ap.add_argument("--quick", action="store_true", help="150 g (cone only), 0.25 s, short settle (the case test)")
    ap.add_argument("--s", type=float, default=5.0, help="coarse-graining factor: parcel d = s x 660 um (default 5)")
    ap.add_argument("--fill-g", type=float, default=1000.0, help="fill mass [g] (default 1000)")
    ap.add_argument("--end", type=float, default=1.5, help="discharge time [s] (default 1.5)")
    ap.add_argument("--settle-min", type=float, default=0.2, help="minimum settling time [s]")
    ap.add_argument("--steady-from", type=float, default=0.5, help="start of the steady window [s]")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--cg-every", type=float, default=0.0,
                    help="CG dumps every T s of the discharge and the CG fields of the steady window (default 0: off)")
    a = gc.cli.parse(ap, os.path.join(HERE, "reference-cg-dem"))
    if a.quick:
        a.fill_g, a.end, a.settle_min, a.steady_from = 150.0, 0.25, 0.1, 0.1
    if not a.s >= 1 or not 0 < a.fill_g <= 1500 or not a.end > 0 or a.np not in (1, 2) or not 0 <= a.cg_every < a.end:
        ap.error(f"--s {a.s} (>= 1), --fill-g {a.fill_g} (0-1500 g), --end {a.end} (> 0), --np {a.np} (1 or 2), "
                 f"--cg-every {a.cg_every} (0 or a time below --end)")
    runs = gc.runner.clean(os.path.join(a.out, "runs"))
    fill, run = os.path.join(runs, "fill"), os.path.join(runs, "discharge")
    print(f"mcc-hopper cg-dem: s = {a.s:g}, {a.fill_g:g} g, {a.end:g} s of discharge, {a.np} rank(s)", flush=True)
    cpu, wall = {}, {}
    t0 = time.time()
    v = numbers(a)
    n_packed = setup(a, v, fill, run)
    cpu["packing"], wall["packing"] = time.process_time(), round(time.time() - t0)
    if a.setup_only:
        return print(f"mcc-hopper cg-dem: fill and discharge folders written to {runs}")
    for name, d, cmd, np_ in (("fill", fill, ["liggghts", "-in", "dem/in.fill", "-log", "log/log.liggghts",
                                              "-screen", "log/screen.liggghts"], 1),
                              ("granairFoam", run, ["granairFoam"], a.np)):
        t0 = time.time()
        if name == "granairFoam":
            gc.runner.mesh(run, a.np)
        cpu[name] = gc.runner.run(cmd, d, name, np=np_, parallel=name != "fill")
        wall[name] = round(time.time() - t0)
        if name == "fill":
            print(gc.dem.fill_report(os.path.join(fill, "log", "log.liggghts")), flush=True)
    c = gc.checks.Checks("mcc-hopper cg-dem")
    post(a, v, runs, n_packed, cpu, wall, c)
    if a.cg_every > 0:
        import cg
        cg.fields(run, v, min(a.steady_from, 0.4 * a.end), a.end, os.path.join(a.out, "cg"), c)
    c.report(enforce=a.check)


if __name__ == "__main__":
    gc.cli.main(main)
