"""Post-processing of the corn silo (study.py): one run, one angle (mean +- SD
of its runs), the study (tables against the angle). Plots: figures.py. The
readers, the wall rings, Janssen's slice balance and the strain by hull and by
CG are the package's (gc.dem, gc.wall_rings, gc.strain)."""
import glob
import json
import math
import os
import shutil

import numpy as np

import granair_cases as gc
import figures
import geometry
import parameters as P

COLUMNS = ("step", "atoms", "in_silo", "below_outlet", "discharged", "removed", "discharged_kg", "removed_kg")
# the run scalars averaged over an angle's runs (mean, SD) and put in summary.csv
SCALARS = ("steady_mass_flow_kg_s", "bulk_density_kg_m3", "fill_surface_m",
           "hopper_static_normal_max_Pa", "hopper_static_normal_max_z_m", "hopper_static_shear_max_Pa",
           "hopper_static_shear_max_z_m", "shaft_static_normal_max_Pa", "shaft_static_normal_max_z_m",
           "shaft_static_shear_max_Pa", "shaft_static_shear_max_z_m",
           "hopper_discharge_normal_max_Pa", "hopper_discharge_normal_max_z_m", "hopper_discharge_shear_max_Pa",
           "hopper_discharge_shear_max_z_m", "shaft_discharge_normal_max_Pa", "shaft_discharge_normal_max_z_m",
           "shaft_discharge_shear_max_Pa", "shaft_discharge_shear_max_z_m",
           "hopper_peak_normal_Pa", "shaft_peak_normal_Pa", "hopper_peak_shear_Pa", "shaft_peak_shear_Pa",
           "shaft_pressure_at_janssen_depth_Pa", "shaft_static_over_janssen_mid", "K_eff", "mu_mobilised",
           "fill_walls_over_weight",
           "I1_mean", "J2_mean", "I1_sd_time", "J2_sd_time", "cv_grains_mean", "I1_of_mean", "J2_of_mean",
           "cg_I1", "cg_J2",
           "descent_wall_over_core", "stagnant_mass_fraction", "dead_zone_wall_height_m", "cpu_s", "steady_from_s")


def read_flow(paths):
    """The flow_*.txt files of a run's chunks, in order, as {column: array} (one row per step)."""
    return gc.dem.read_print(paths, COLUMNS)


def run(name, run_dir, v, state, out):
    """Post-process one finished run into OUT/a<angle>/s<k>*: returns its scalars."""
    angle, k = v["ANGLE"], int(name.rsplit("-s", 1)[1])
    pdir, dt, h, d = os.path.join(run_dir, "post"), v["DT"], v["HOPPER_HEIGHT"], P.d_mass_mean()
    adir = os.path.join(out, f"a{angle}")
    os.makedirs(adir, exist_ok=True)
    flow = read_flow(sorted(glob.glob(os.path.join(pdir, "flow_*.txt"))))
    t = flow["step"] * dt
    with open(os.path.join(pdir, "inserted.txt")) as fh:
        inserted = int(float(fh.read().split()[0]))
    last = {c: int(flow[c][-1]) for c in COLUMNS[:6]}
    fill = gc.dem.read_dump(os.path.join(pdir, "fill.dump"))
    final = gc.dem.read_dump(os.path.join(pdir, "final.dump"))
    # the free surface over the 200 highest centres; the shaft's bulk density from 2 d above the hopper
    rho_b, surface = gc.outlet.bulk_density(fill["z"], fill["mass"], math.pi * P.D_SILO ** 2 / 4, d, floor=h,
                                            radius=np.mean(fill["radius"]), min_height=4 * d)
    with open(os.path.join(pdir, "fill_forces.txt")) as fh:
        weight, fz_hopper, fz_shaft, fz_shutter = (float(x) for x in fh.read().split()[:4])
    m = flow["discharged_kg"]
    w = gc.series.slope(t, m, min(P.STEADY_FROM, 0.4 * t[-1]))
    centres, (rate,) = gc.powder.flow_windows(t, m, 0.1, keep_last=None, tol=1e-9)
    gc.series.write_csv(os.path.join(adir, f"s{k}_mass_flow.csv"), [("t", centres), ("mass_flow_kg_s", rate)],
                        fmt="{:.6g}")

    # wall loads: the static fill, and every dump of the discharge (gc.silo_walls)
    rings = geometry.rings(gc.dem.read_mesh_vtk(os.path.join(pdir, "walls_fill.vtk")), angle)
    files = [(s, p) for s, p in gc.dem.numbered(os.path.join(pdir, "walls_*.vtk")) if s > 0]
    steady = [(s, p) for s, p in files if s * dt >= min(P.STEADY_FROM, 0.4 * t[-1]) - 1e-9]
    prof, (sn, ss, el_n, el_s) = gc.silo_walls.profiles(rings, os.path.join(pdir, "walls_fill.vtk"), files, steady)
    res = dict(run=name, angle_deg=angle, seed=v["SEED"], grains=v["GRAINS"], youngs_Pa=v["YOUNGS"], dt_s=dt,
               discharge_s=float(t[-1]), steady_from_s=min(P.STEADY_FROM, 0.4 * t[-1]), steady_mass_flow_kg_s=w,
               bulk_density_kg_m3=rho_b, fill_surface_m=surface, hopper_height_m=h,
               fill_weight_N=weight, fill_hopper_fz_N=fz_hopper, fill_shaft_fz_N=fz_shaft,
               fill_shutter_fz_N=fz_shutter, fill_walls_over_weight=(fz_hopper + fz_shaft + fz_shutter) / weight,
               requested=v["GRAINS"], inserted=inserted, in_silo=last["in_silo"], below_outlet=last["below_outlet"],
               removed=last["removed"], discharged=last["discharged"], atoms=last["atoms"],
               discharged_kg=float(flow["discharged_kg"][-1]), removed_kg=float(flow["removed_kg"][-1]),
               accounting_closes=inserted == last["in_silo"] + last["below_outlet"] + last["removed"],
               cpu_s=state["cpu_fill_s"] + state["cpu_discharge_s"], cpu_fill_s=state["cpu_fill_s"],
               wall_s=state["wall_s"])
    res.update(gc.silo_walls.maxima(rings, prof, [("hopper", rings.is_hopper), ("shaft", ~rings.is_hopper)]))
    # the shaft at rest against Janssen (K band), away from the free surface and the transition,
    # and Janssen's slice balance with the run's own wall shear
    band = ~rings.is_hopper & (surface - rings.z > 2 * d) & (rings.z > h + 2 * d)
    jan, depth = gc.silo_walls.janssen_shaft(rings, prof, ~rings.is_hopper, band, surface, P.D_SILO, rho_b, P.MU_PW,
                                             P.K_JANSSEN, fill["z"], fill["mass"], P.janssen_depth(v["GRAINS"]), P.G)
    res.update(jan)

    # strain invariants over the outlet (gc.strain: the convex hull of the grains in the control volume)
    rows = gc.strain.series(gc.dem.snapshots(os.path.join(pdir, "cv_*.dump")), P.CV_RADIUS, P.CV_HEIGHT)
    res.update(strain_interval_s=P.CV_EVERY)
    res.update(gc.strain.steady(rows, dt, res["steady_from_s"], os.path.join(adir, f"s{k}_strain.csv")))
    # the same from the CG velocity field (granairCG), beside the hull's of the time-mean strain
    cg = cg_strain(run_dir, v, res["steady_from_s"], float(t[-1]))
    res.update(cg_I1=cg[0] if cg else math.nan, cg_J2=cg[1] if cg else math.nan, cg_points=cg[3] if cg else 0,
               cg_width_m=P.CG_WIDTH)
    res["descent_wall_over_core"], res["stagnant_mass_fraction"], res["dead_zone_wall_height_m"] = \
        gc.outlet.flow_pattern(fill, final, d, P.D_SILO / 2, h, surface, P.SINK_Z)

    gc.silo_walls.write(os.path.join(adir, f"s{k}_walls.csv"), os.path.join(adir, f"s{k}_elements.csv"), rings, prof,
                        depth, (sn, ss, el_n, el_s), lambda i: "hopper" if rings.is_hopper[i] else "shaft")
    with open(os.path.join(adir, f"s{k}.json"), "w") as fh:
        json.dump(res, fh, indent=1, default=float)
    print(f"corn-silo {name}: W = {w:.4g} kg/s, {inserted} = {last['in_silo']} + {last['below_outlet']} + "
          f"{last['removed']} ({'closes' if res['accounting_closes'] else 'DOES NOT CLOSE'}), shaft/Janssen "
          f"{res['shaft_static_over_janssen_mid']:.3g}, I1 {res['I1_mean']:.3g}, J2 {res['J2_mean']:.3g}, "
          f"{res['cpu_s']:.0f} s CPU", flush=True)
    return res


def cg_strain(run_dir, v, t0, t1):
    """(I1, J2, eps, grid points) of the strain per CV_EVERY from the CG velocity field
    over the control volume (gc.strain.cg_cylinder; README "Strain from the CG velocity
    field"); None (with a message) when granairCG is not built."""
    if shutil.which("granairCG") is None:
        print(f"corn-silo: granairCG not found (./granair build): no CG strain for {run_dir}", flush=True)
        return None
    post = os.path.join(run_dir, "post")
    return gc.strain.cg_cylinder(run_dir, sorted(glob.glob(os.path.join(post, "cv_*.dump"))), os.path.join(post, "cg_cv"),
                                 v["DT"], P.CV_RADIUS, P.CV_HEIGHT, P.CG_WIDTH, P.CG_SPACING, t0, t1, P.CV_EVERY)


def angle(out, a, runs, seeds, size, run_root):
    """Mean +- SD of one angle's runs (sample SD, n - 1): OUT/a<angle>/mean.json,
    mass_flow.csv (mean of the runs), level.json, walls.csv (mean profiles) and
    the mean wall loads as VTK (when the run folders are there)."""
    adir = os.path.join(out, f"a{a}")
    res = dict(angle_deg=a, runs=len(runs), runs_planned=seeds, grains=size["grains"])
    for key in SCALARS:
        res[key], res[key + "_sd"] = gc.series.mean_sd([r.get(key) for r in runs])
    # mass flow: every grain moves once any is withdrawn (Jenike); funnel flow leaves grains at rest
    res["pattern"] = "mass flow" if res["stagnant_mass_fraction"] < P.STAGNANT_MASS_FLOW else "funnel flow"
    per_run = lambda f: [os.path.join(adir, f"s{r['run'].rsplit('-s', 1)[1]}_{f}.csv") for r in runs]  # noqa: E731
    flows = [gc.series.read_csv(p) for p in per_run("mass_flow")]
    w = gc.series.mean_sd_columns(flows, ["mass_flow_kg_s"])
    gc.series.write_csv(os.path.join(adir, "mass_flow.csv"), [("t", flows[0]["t"][:len(w["mass_flow_kg_s"])]),
                        ("mass_flow_kg_s", w["mass_flow_kg_s"]), ("sd_kg_s", w["mass_flow_kg_s_sd"])], fmt="{:.6g}")
    rows = gc.silo_walls.mean_profiles(per_run("walls"))
    gc.series.write_rows(os.path.join(adir, "walls.csv"), rows, fmt="{:.6g}")
    res["wall_time_s"] = float(np.mean([r["wall_s"] for r in runs]))
    gc.levels.write(os.path.join(adir, "level.json"), case="corn-silo", level="cg-dem",
                    model=f"DEM, unscaled corn (s = 1), hopper {a} deg from the horizontal, {size['grains']} grains, "
                          f"E = {runs[0]['youngs_Pa']:.3g} Pa, Hooke, mean of {len(runs)} runs",
                    b_mm=P.D_OUTLET * 1e3, air=False, steady_mass_flow_kg_s=res["steady_mass_flow_kg_s"],
                    steady_window_s=[runs[0]["steady_from_s"], runs[0]["discharge_s"]], outlet_dpdz_Pa_m=None,
                    wall_time_s=round(res["wall_time_s"], 1), cores=1, timeseries="mass_flow.csv",
                    hopper_angle_deg=a, shaft_wall_pressure_Pa=res["shaft_pressure_at_janssen_depth_Pa"],
                    shaft_wall_pressure_depth_m=P.janssen_depth(size["grains"]))
    # the mean wall loads per element, on the first run's mesh, for ParaView
    first = os.path.join(run_root, runs[0]["run"], "post", "walls_fill.vtk")
    if os.path.exists(first):
        els = [gc.series.read_csv(p) for p in per_run("elements")]
        for state in ("static", "discharge"):
            gc.silo_walls.mean_vtk(first, els, os.path.join(adir, f"wall_loads_{state}.vtk"), state,
                                   f"corn silo {a} deg: {state} wall loads [Pa], mean of {len(runs)} runs")
    with open(os.path.join(adir, "mean.json"), "w") as fh:
        json.dump(res, fh, indent=1, default=float)
    return res


def study(out, done, angles, seeds, size, c):
    """Every angle with runs: its mean (angle()), the checks of every run, the
    study table and figures."""
    run_root = os.path.join(out, "runs")
    by_angle = {}
    for a in angles:
        runs = []
        for k in range(1, seeds + 1):
            path = os.path.join(out, f"a{a}", f"s{k}.json")
            if f"a{a}-s{k}" in done:
                runs.append(done[f"a{a}-s{k}"])
            elif os.path.exists(path):
                with open(path) as fh:
                    runs.append(json.load(fh))
        if runs:
            by_angle[a] = (angle(out, a, runs, seeds, size, run_root), runs)
    for a, (_, runs) in by_angle.items():
        for r in runs:
            check_run(c, r)
    gc.strain.check_hull(c, P.CV_RADIUS)     # the hull method against a homogeneous deformation
    if not by_angle:
        print("corn-silo: no finished runs to post-process", flush=True)
        return
    rows = [m for m, _ in by_angle.values()]
    gc.series.write_rows(os.path.join(out, "summary.csv"), rows, fmt="{:.6g}")
    figures.all(out, by_angle, run_root)
    table(out, rows, P.janssen_depth(size["grains"]))


def check_run(c, r):
    name = r["run"]
    c.exact(f"{name}: inserted = in silo + below the outlet + removed at the sink",
            r["inserted"], r["in_silo"] + r["below_outlet"] + r["removed"], "integer counts: no grain lost")
    c.exact(f"{name}: grains inserted = requested", r["inserted"], r["requested"],
            "LIGGGHTS insert/pack placed every grain asked for")
    c.close(f"{name}: vertical wall forces of the fill at rest (hopper + shaft + shutter) / its weight",
            r["fill_walls_over_weight"], 1.0, 0.02, "static equilibrium of the settled fill: the stress module's "
            "forces carry the weight; 2 %: the fill is settled to an rms speed of 5 mm/s, not to rest (0.1-0.8 % measured)")
    c.within(f"{name}: shaft wall pressure at rest, mean of the rings 2 d below the surface and above the hopper",
             r["shaft_static_mean_Pa"], r["janssen_lo_mean_Pa"], r["hydrostatic_mean_Pa"],
             f"between Janssen's limits: his assumption, the wall friction mu_w = {P.MU_PW} fully mobilised, with "
             f"the lowest K = {P.K_JANSSEN[0]:.3f}, and no wall friction with K = 1 (rho_b g h); measured "
             f"{r['shaft_static_over_janssen_mid']:.2f} x Janssen (K = {sum(P.K_JANSSEN) / 2:.2f}), K_eff "
             f"{r['K_eff']:.2f}, mu mobilised {r['mu_mobilised']:.2f}: README 'Janssen'", " Pa")


def table(out, rows, depth):
    """summary.md: the results against the angle, mean +- SD of the runs (gc.tables)."""
    pm = gc.tables.pm
    head = ["angle [deg]", "runs", "W [kg/s]", "hopper p max static / discharge [Pa]", "hopper tau max static / discharge [Pa]",
            "shaft p max static / discharge [Pa]", "shaft tau max static / discharge [Pa]",
            f"shaft p at {depth:g} m [Pa]", "I1 (per 0.01 s)", "J2 (per 0.01 s)", "wall/core descent",
            "stagnant mass", "pattern"]
    lines = gc.tables.markdown(head, [[
        f"{r['angle_deg']}", f"{r['runs']}", pm(r, "steady_mass_flow_kg_s"),
        *(pm(r, f"{w}_static_{q}_max_Pa") + " / " + pm(r, f"{w}_discharge_{q}_max_Pa")
          for w in ("hopper", "shaft") for q in ("normal", "shear")),
        pm(r, "shaft_pressure_at_janssen_depth_Pa"), pm(r, "I1_mean"), pm(r, "J2_mean"),
        pm(r, "descent_wall_over_core", digits=2), pm(r, "stagnant_mass_fraction", 100, 2) + " %", r["pattern"]]
        for r in rows])
    with open(os.path.join(out, "summary.md"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    print("\n".join(lines), flush=True)
