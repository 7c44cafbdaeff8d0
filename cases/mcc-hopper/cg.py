"""CG fields of the MCC hopper's coarse-grained DEM (dem.py --cg-every; README,
"Cross-validation: fields").

From the dumps the discharge writes (dem/post/cg: particles, pairs, cone
contacts), granairCG computes the fields in RZ about the hopper axis
(azimuthal averages), Gaussian kernel of width w = d/2 of the parcel, time
averaged uniformly over the snapshots of the steady window, on a grid of
spacing w from r = 0 to R_WINDOW and z from below the sink to Z_TOP.
OUT holds cg_rz.csv (the grid), cg_axis.csv (the ring nearest AXIS_R, by z),
cg_orifice.csv (the orifice plane z = 0, by r) and cg_numbers.json (with the
cone's effective wall friction sum |F_t| / sum F_n of the wall contacts, against
the contact law's particle-wall coefficient and the continuum's mu_w).

Checked: the CG mass flow through the orifice plane, -int 2 pi r j_z dr, equals
the counted steady rate (the slope of the discharged mass over the same window)
within MASS_FLOW_TOL: in a steady flow the time average of the kernel-smoothed
flux through a plane is the rate at which mass crosses it; what differs is the
sampling of the snapshots (the sd of the 50 ms means is 4 % of the rate).
"""
import glob
import json
import math
import os
import re

import numpy as np

import granair_cases as gc
import parameters as P

R_WINDOW = 0.030            # m: the grid's outer radius (the cylinder wall, whose primitive contacts
                            # are not in the dumps, is at 63.5 mm: more than 3 w outside)
Z_TOP = 0.075               # m: above the settled 400 g fill (59 mm); the 1000 g fill's top is at 111 mm
AXIS_R = 1.0e-3             # m: the axis profile is the ring nearest this radius (the continuum's cell
                            # centres start at half a cell from the axis)
MASS_FLOW_TOL = 0.10        # CG flux through z = 0 vs the counted rate (snapshot sampling, above)
FIELDS = ("volume_fraction", "velocity_z", "velocity_r", "pressure", "shear_rate", "inertial_number",
          "friction_coefficient", "momentum_density_z")


def snapshot_steps(run):
    return sorted(int(re.search(r"_(\d+)\.dump$", p).group(1))
                  for p in glob.glob(os.path.join(run, "dem", "post", "cg", "particles_*.dump")))


def grid_options(v):
    """Kernel width w = d/2, spacing h = w (the kernel's standard deviation, granairCG's default;
    w/2 cost 7 CPU-s per snapshot of the 400 g fill); r rings at (i + 1/2) h, z points on
    multiples of h (so z = 0, the orifice plane, is a grid row): gc.cg_runs.aligned."""
    w = v["D"] / 2
    h = w
    return w, h, gc.cg_runs.aligned("RZ", h, R_WINDOW, P.SINK_Z - 0.005, Z_TOP, P.BOX_HALF, P.BOX_HALF)


def wall_friction(run, steps, v):
    """The cone's effective Coulomb friction in the DEM: sum |F_t| / sum F_n of the wall
    forces on the parcels in the cone contacts of the snapshots (walls_<step>.dump: contact
    point, centre, ids, force), over all contacts and over those within 3 d of the orifice
    edge (where the powder slides); the normal is the cone's, n = (r_hat - tan ez)/sqrt(1 + tan^2)
    outwards. Returns (all, near the orifice, contacts counted)."""
    sums = np.zeros((2, 2))
    n_contacts = 0
    norm = math.sqrt(1 + P.TAN_CONE ** 2)
    for step in steps:
        for _, d in gc.dem.read_dumps(os.path.join(run, "dem", "post", "cg", f"walls_{step}.dump")):
            if not len(d.get("c_cg_walls[1]", [])):
                continue
            x, y, z = (d[f"c_cg_walls[{k}]"] for k in (1, 2, 3))
            f = np.stack([d[f"c_cg_walls[{k}]"] for k in (10, 11, 12)], axis=1)
            r = np.hypot(x, y)
            nrm = np.stack([x / r / norm, y / r / norm, np.full_like(r, -P.TAN_CONE / norm)], axis=1)
            fn = -np.sum(f * nrm, axis=1)                     # the wall pushes the parcel inwards: fn > 0
            ft = np.linalg.norm(f + fn[:, None] * nrm, axis=1)
            near = np.hypot(r - P.R_OUT, z) < 3 * v["D"]
            for k, sel in enumerate((np.ones_like(near), near)):
                sums[k] += (np.sum(ft[sel]), np.sum(fn[sel]))
            n_contacts += len(fn)
    return float(sums[0, 0] / sums[0, 1]), float(sums[1, 0] / sums[1, 1]), n_contacts


def fields(run, v, t_from, t_to, out, c, reuse=False):
    """granairCG on the snapshots of [t_from, t_to] of the discharge folder `run`; the profiles
    and numbers into out; the mass-flow check into c. Returns the numbers. reuse: keep an
    existing out/cg_rz.csv (post-processing again)."""
    dt = v["DEM_DT"]
    steps = [s for s in snapshot_steps(run) if t_from - 1e-9 <= s * dt <= t_to + 1e-9]
    if len(steps) < 2:
        raise gc.CaseError(f"{run}/dem/post/cg: {len(steps)} CG snapshots in t = {t_from:g}-{t_to:g} s, "
                           "expected at least 2 (dem.py --cg-every below the window's length)")
    os.makedirs(out, exist_ok=True)
    w, h, opts = grid_options(v)
    cg_dir = os.path.join("dem", "post", "cg")
    stem = os.path.abspath(os.path.join(out, "cg_rz"))
    # reuse: a grid of the same snapshots already computed (granairCG costs ~10 CPU-s a snapshot)
    cpu = 0.0 if reuse and os.path.exists(stem + ".csv") else gc.cg.run(run, stem, dict(
        particles=os.path.join(cg_dir, "particles_*.dump"), pairs=os.path.join(cg_dir, "pairs_*.dump"),
        walls=os.path.join(cg_dir, "walls_*.dump"), dt=f"{dt:.12g}", kernel="gauss", width=f"{w:.9g}",
        spacing=f"{h:.9g}", **opts, **{"time-average": "uniform", "from": f"{t_from - 1e-9:.9g}",
                                        "to": f"{t_to + 1e-9:.9g}"}, threads=1, format="csv"), log="granairCG")
    f = gc.cg.read(stem + ".csv")
    r, z = f["r"], f["z"]
    ia, iz = int(np.argmin(np.abs(r - AXIS_R))), int(np.argmin(np.abs(z)))
    gc.series.write_csv(os.path.join(out, "cg_axis.csv"), [("z_m", z)] + [(k, f[k][ia, :]) for k in FIELDS],
                        fmt="{:.6g}")
    gc.series.write_csv(os.path.join(out, "cg_orifice.csv"), [("r_m", r)] + [(k, f[k][:, iz]) for k in FIELDS],
                        fmt="{:.6g}")
    flux = -float(np.sum(f["momentum_density_z"][:, iz] * 2 * math.pi * r) * (r[1] - r[0]))
    # the counted rate over the same window: the slope of the discharged mass
    ts = gc.powder.dem(run)
    counted = gc.series.slope(ts["t"], ts["series"]["discharged_kg"], t_from, t_to)
    inside = r < P.R_OUT
    jz = -f["momentum_density_z"][:, iz]
    num = dict(snapshots=len(steps), t_from_s=steps[0] * dt, t_to_s=steps[-1] * dt, kernel_width_m=w, spacing_m=h,
               axis_ring_r_m=float(r[ia]), orifice_row_z_m=float(z[iz]), cg_mass_flow_kg_s=flux,
               counted_mass_flow_kg_s=counted, granairCG_cpu_s=round(cpu, 1),
               # the orifice plane's means over |r| < R_OUT, area-weighted (2 pi r dr)
               orifice_solid_fraction=float(np.sum((f["volume_fraction"][:, iz] * r)[inside]) / np.sum(r[inside])),
               orifice_velocity_z_flux_weighted=float(np.sum((f["velocity_z"][:, iz] * jz * r)[inside])
                                                      / np.sum((jz * r)[inside])),
               orifice_pressure=float(np.sum((f["pressure"][:, iz] * r)[inside]) / np.sum(r[inside])))
    mu_all, mu_edge, n_wall = wall_friction(run, steps, v)
    num.update(dem_wall_friction_cone=mu_all, dem_wall_friction_near_orifice=mu_edge, wall_contacts=n_wall,
               particle_wall_friction=P.FRICTION_PW)
    with open(os.path.join(out, "cg_numbers.json"), "w") as fh:
        json.dump(num, fh, indent=1)
    print(f"mcc-hopper cg-dem CG fields: {len(steps)} snapshots t = {num['t_from_s']:g}-{num['t_to_s']:g} s, "
          f"w = {w * 1e3:.3g} mm; mass flow through z = 0 {flux:.4g} kg/s (counted {counted:.4g}); orifice solid "
          f"fraction {num['orifice_solid_fraction']:.3f}; cone wall friction {mu_all:.3f} ({mu_edge:.3f} within 3 d of the "
          f"orifice edge, {n_wall} contacts); {cpu:.0f} CPU-s", flush=True)
    c.close("CG mass flow through the orifice plane vs the counted steady rate [kg/s]", flux, counted, MASS_FLOW_TOL,
            "the time average of the smoothed flux through a plane is the crossing rate; the snapshots sample a "
            "flow whose 50 ms means scatter by 4 %")
    return num
