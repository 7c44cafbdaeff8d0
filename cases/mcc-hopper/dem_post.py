#!/usr/bin/env python3
"""dem_post.py: mass flow and parcel accounting of one coarse-grained DEM run
of the MCC hopper (dry), against Beverloo; writes the fidelity-level files.

Usage: dem_post.py RUN_DIR OUT_DIR [--steady-from T] [--cpu FILE] [--check]

Reads RUN_DIR/postProcessing/timeSeries.csv (granairFoam, air off: t,
discharged_kg, mass_flow_kg_s, particles), the discharge balance at the end of
RUN_DIR/log/granairFoam.log, RUN_DIR/case.json (dem_case.py) and the settled
fill (dump of the fill folder). Writes to OUT_DIR
  mass_flow.csv   t,mass_flow_kg_s: 50 ms means of the discharged mass rate
  level.json      the level contract (helper brief 3; case mcc-hopper, level cg-dem)
  mass_flow.png   mass flow against time, Beverloo bands with the primary and the parcel d
  summary.txt     key = value lines: accounting, steady rate, Beverloo, Carleton, cost

The steady mass flow is the least-squares slope of the discharged mass over
[steady-from, end] (the parcels crossing z = 0 for the first time).

--check exits 1 unless: the parcel accounting closes exactly (inserted = in
hopper + between outlet and sink + removed at the sink, lost = 0; integer
counts, no tolerance), every parcel of the packing was inserted, and the
steady mass flow is > 0.
"""
import argparse
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "pylib"))
from granair_cases import closed_forms as cf  # noqa: E402
import dem_io              # noqa: E402

C_BEVERLOO, K_RANGE = 0.58, (1.0, 3.0)     # Beverloo et al. (1961), as cases/mcc-hopper/post.py
RHO_BULK = 900.0                            # kg/m3, reference case B
D_OUTLET = 0.025
D_PRIMARY = 660e-6
G = 9.81
WINDOW = 0.05                               # s, averaging window of mass_flow.csv
CONE_HALF_ANGLE = math.atan((0.0635 - 0.0125) / 0.036)
AIR_RHO, AIR_MU = 1.22, 1.8e-5


def beverloo(k, d, rho_b=RHO_BULK):
    return C_BEVERLOO * rho_b * math.sqrt(G) * (D_OUTLET - k * d) ** 2.5


def carleton_ratio(d=D_PRIMARY, rho_p=1500.0):
    """Carleton (1972) via tools/pylib/closed_forms.py (the compare tool's numbers):
    (V0 with the air term, V0 without it); the mass flow scales with V0. An
    estimate: Carleton's form for coarse particles, theta the cone half angle."""
    th = math.degrees(CONE_HALF_ANGLE)
    return (cf.carleton_velocity(D_OUTLET, th, d, rho_p, AIR_RHO, AIR_MU, G),
            cf.carleton_velocity(D_OUTLET, th, d, rho_p, 0.0, 0.0, G))


def read_series(path):
    with open(path) as fh:
        rows = list(csv.DictReader(fh))
    if len(rows) < 2:
        sys.exit(f"dem_post.py: {path} has {len(rows)} rows, expected at least 2")
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def read_balance(log_path):
    return dem_io.read_discharge_balance(log_path, "dem_post.py")


read_dump = dem_io.read_dump


def settled_fill(dump, d):
    """Top of the settled fill (mean of the 200 highest parcels) and the bulk density
    in the cylinder below it [kg/m3]: parcel mass with centres in the
    cylinder 36 mm + 2d < z < top - 2d, r < 63.5 mm, over that volume (the
    wall layer included, as in the hopper; none if the fill is below that)."""
    atoms = read_dump(dump)
    zs = sorted((a["z"] for a in atoms), reverse=True)
    top = sum(zs[:200]) / min(200, len(zs))
    z0, z1 = 0.036 + 2 * d, top - 2 * d
    if z1 - z0 < 4 * d:
        return top, float("nan")
    m = sum(a["mass"] for a in atoms if z0 < a["z"] < z1)
    return top, m / (math.pi * 0.0635 ** 2 * (z1 - z0))


def least_squares_slope(x, y):
    n = len(x)
    mx, my = sum(x) / n, sum(y) / n
    sxx = sum((a - mx) ** 2 for a in x)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sxx if sxx > 0 else float("nan")


def continuum_results(here):
    """Steady mass flows of the committed continuum runs (results/, results/slip/), if present."""
    out = {}
    for label, sub in (("continuum mu(I), no-slip walls (N = 20)", "results"),
                       ("continuum mu(I), free-slip walls (N = 20)", os.path.join("results", "slip"))):
        p = os.path.join(here, sub, "summary.txt")
        if os.path.exists(p):
            with open(p) as fh:
                for line in fh:
                    k, _, v = line.partition(" = ")
                    if k == "steady_mass_flow_kg_s":
                        out[label] = float(v)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run")
    ap.add_argument("out")
    ap.add_argument("--steady-from", type=float, default=0.5)
    ap.add_argument("--cpu", default=None, help="file of 'stage cpu_s wall_s' lines (Allrun-dem)")
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args()

    with open(os.path.join(a.run, "case.json")) as fh:
        info = json.load(fh)
    s = read_series(os.path.join(a.run, "postProcessing", "timeSeries.csv"))
    bal = read_balance(os.path.join(a.run, "log", "granairFoam.log"))
    fill_dir = os.path.normpath(os.path.join(a.run, info["fill_dir"]))
    top, rho_b_dem = settled_fill(os.path.join(fill_dir, "dem", "fill.dump"), info["d_parcel_m"])
    with open(os.path.join(fill_dir, "dem", "packing.data")) as fh:
        n_packed = int(fh.read().split(" atoms")[0].split()[-1])

    t, m = s["t"], s["discharged_kg"]
    t_end = t[-1]
    # 50 ms means of the discharged-mass rate (t = 0: the shutter opens, nothing out)
    win_t, win_w = [], []
    prev_t, prev_m = 0.0, 0.0
    for ti, mi in zip(t, m):
        if ti >= prev_t + WINDOW - 1e-9:
            win_t.append(0.5 * (prev_t + ti))
            win_w.append((mi - prev_m) / (ti - prev_t))
            prev_t, prev_m = ti, mi
    steady = [(ti, mi) for ti, mi in zip(t, m) if ti >= a.steady_from]
    w = least_squares_slope([x for x, _ in steady], [y for _, y in steady]) if len(steady) >= 2 else float("nan")
    in_win = [x for tt, x in zip(win_t, win_w) if tt >= a.steady_from]
    w_sd = math.sqrt(sum((x - w) ** 2 for x in in_win) / len(in_win)) if in_win else float("nan")

    d_parcel = info["d_parcel_m"]
    bev = {"primary": (beverloo(K_RANGE[1], D_PRIMARY), beverloo(K_RANGE[0], D_PRIMARY)),
           "parcel": (beverloo(K_RANGE[1], d_parcel), beverloo(K_RANGE[0], d_parcel))}
    v_air, v_dry = carleton_ratio()
    in_flight = bal["discharged"] - bal["removed"]
    in_hopper = bal["present"] - in_flight
    closes = (bal["lost"] == 0 and bal["inserted"] == in_hopper + in_flight + bal["removed"]
              and bal["inserted"] == n_packed)

    cost = {}
    if a.cpu and os.path.exists(a.cpu):
        with open(a.cpu) as fh:
            for line in fh:
                name, cpu, wall = line.split()
                cost[name] = (float(cpu), float(wall))
    cpu_total = sum(c for c, _ in cost.values())
    wall_total = sum(wl for _, wl in cost.values()) if cost else bal["wall_time_s"]

    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "mass_flow.csv"), "w", newline="") as fh:
        wr = csv.writer(fh)
        wr.writerow(["t", "mass_flow_kg_s"])
        for x, y in zip(win_t, win_w):
            wr.writerow([f"{x:.6g}", f"{y:.6g}"])
    level = {
        "case": "mcc-hopper", "level": "cg-dem",
        "model": (f"coarse-grained DEM (LIGGGHTS Hertz-Mindlin, no cohesion), s = {info['s']:g} "
                  f"({d_parcel * 1e3:.3g} mm parcels), E = {info['youngs_Pa']:.3g} Pa, e = {info['restitution']}, "
                  f"mu_pp = {info['friction_pp']}, mu_pw = {info['friction_pw']}, {info['fill_g']:g} g fill, dry"),
        "b_mm": 25, "air": False,
        "steady_mass_flow_kg_s": w, "steady_window_s": [a.steady_from, round(t_end, 6)],
        "outlet_dpdz_Pa_m": None,
        "wall_time_s": round(wall_total, 1), "cores": info["np"],
        "timeseries": "mass_flow.csv",
    }
    with open(os.path.join(a.out, "level.json"), "w") as fh:
        json.dump(level, fh, indent=1)
        fh.write("\n")
    summary = [
        ("coarse_graining_factor", info["s"]), ("d_parcel_m", d_parcel),
        ("outlet_over_d_parcel", D_OUTLET / d_parcel), ("fill_g", info["fill_g"]),
        ("parcels_packed", n_packed), ("youngs_Pa", info["youngs_Pa"]), ("dem_dt_s", info["dem_dt_s"]),
        ("settled_top_m", top), ("settled_bulk_density_kg_m3", rho_b_dem),
        ("t_end_s", t_end), ("steady_from_s", a.steady_from),
        ("steady_mass_flow_kg_s", w), ("window_mass_flow_sd_kg_s", w_sd),
        ("beverloo_primary_k3_kg_s", bev["primary"][0]), ("beverloo_primary_k1_kg_s", bev["primary"][1]),
        ("beverloo_parcel_k3_kg_s", bev["parcel"][0]), ("beverloo_parcel_k1_kg_s", bev["parcel"][1]),
        ("steady_over_beverloo_primary_k1", w / bev["primary"][1]),
        ("carleton_air_over_dry", v_air / v_dry),
        ("inserted", bal["inserted"]), ("in_hopper", in_hopper),
        ("between_outlet_and_sink", in_flight), ("removed_at_sink", bal["removed"]),
        ("discharged", bal["discharged"]), ("lost", bal["lost"]),
        ("inserted_kg", bal["inserted_kg"]), ("discharged_kg", bal["discharged_kg"]),
        ("accounting_closes", int(closes)),
    ]
    for name, (c, wl) in cost.items():
        summary += [(f"{name}_cpu_s", c), (f"{name}_wall_s", wl)]
    summary += [("total_cpu_s", cpu_total), ("total_wall_s", wall_total), ("ranks_discharge", info["np"])]
    with open(os.path.join(a.out, "summary.txt"), "w") as fh:
        fh.write(f"# MCC hopper, coarse-grained DEM, dry (dem_post.py). Accounting: inserted = in_hopper "
                 f"+ between_outlet_and_sink + removed_at_sink, lost = 0\n")
        for k, v in summary:
            fh.write(f"{k} = {v:.6g}\n" if isinstance(v, float) else f"{k} = {v}\n")
    print(f"mcc-hopper cg-dem: steady mass flow {w:.4g} kg/s (t = {a.steady_from:g}-{t_end:g} s, sd of 50 ms "
          f"means {w_sd:.2g}); Beverloo {bev['primary'][0]:.4g}-{bev['primary'][1]:.4g} kg/s (primary d), "
          f"{bev['parcel'][0]:.4g}-{bev['parcel'][1]:.4g} kg/s (parcel d); accounting {bal['inserted']} = "
          f"{in_hopper} + {in_flight} + {bal['removed']}, lost {bal['lost']}; CPU {cpu_total:.0f} s")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7.5, 4.2))
        ax.axhspan(*bev["primary"], color="tab:orange", alpha=0.3,
                   label=f"Beverloo, d = {D_PRIMARY * 1e6:.0f} um, k = 1..3")
        ax.axhspan(*bev["parcel"], facecolor="none", edgecolor="tab:green", hatch="//", lw=0.8,
                   label=f"Beverloo, parcel d = {d_parcel * 1e3:.2g} mm, k = 1..3")
        ax.plot(win_t, win_w, color="tab:blue", lw=1.2, label="cg-DEM, dry (50 ms means)")
        if math.isfinite(w):
            ax.hlines(w, a.steady_from, t_end, colors="k", linestyles="--",
                      label=f"steady, t >= {a.steady_from:g} s: {w * 1e3:.1f} g/s")
        for (lab, val), ls in zip(continuum_results(os.path.dirname(os.path.abspath(__file__))).items(), (":", "-.")):
            ax.axhline(val, color="tab:red", ls=ls, lw=1, label=f"{lab}: {val * 1e3:.0f} g/s")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("mass flow [kg/s]")
        ax.set_xlim(0, t_end)
        ax.set_ylim(0, 1.35 * max([bev["primary"][1]] + win_w))
        ax.set_title(f"MCC hopper, D_o = 25 mm, {info['fill_g']:g} g, cg-DEM s = {info['s']:g}, no air")
        ax.legend(loc="lower right", fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(a.out, "mass_flow.png"), dpi=110)
    except ImportError as e:
        print(f"dem_post.py: no plot ({e}); use $GRANAIR_PYTHON", file=sys.stderr)

    if a.check:
        failures = []
        if not closes:
            failures.append(f"accounting does not close: packed {n_packed}, inserted {bal['inserted']}, "
                            f"in hopper {in_hopper} + between outlet and sink {in_flight} + removed "
                            f"{bal['removed']}, lost {bal['lost']}")
        if not w > 0:
            failures.append(f"steady mass flow {w} kg/s is not > 0")
        if failures:
            print("mcc-hopper cg-dem check FAILED: " + "; ".join(failures), file=sys.stderr)
            sys.exit(1)
        print(f"mcc-hopper cg-dem check passed: accounting exact (lost 0), steady mass flow {w:.4g} kg/s > 0")


if __name__ == "__main__":
    main()
