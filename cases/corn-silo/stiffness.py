#!/usr/bin/python3
"""The effect of the softening (README "Effect of the softening"): one angle's run
at the study's Young's modulus against the same run (same seed, same grains) at a
stiffer one, on what both have: the fill at rest, and the mass flow and the hull
strain over the same window of the (shorter) stiff discharge.

    stiffness.py [--soft DIR] [--stiff DIR] [--angle A] [--seed K]

DIR are study outputs (results/, results-stiff/) with their run folders (runs/).
Writes STIFF/comparison.csv (quantity, soft, stiff, stiff / soft)."""
import argparse
import glob
import json
import os

import numpy as np

import granair_cases as gc
import post

HERE = os.path.dirname(os.path.abspath(__file__))
STATIC = ("youngs_Pa", "dt_s", "bulk_density_kg_m3", "fill_surface_m", "hopper_static_normal_max_Pa",
          "hopper_static_shear_max_Pa", "shaft_static_normal_max_Pa", "shaft_static_shear_max_Pa",
          "shaft_static_mean_Pa", "K_eff", "mu_mobilised", "fill_walls_over_weight", "cpu_fill_s")


def window(out, angle, k, t0, t1):
    """Mass flow [kg/s] (slope of the discharged mass) and the mean hull I1, J2 over [t0, t1]."""
    run = os.path.join(out, "runs", f"a{angle}-s{k}")
    with open(os.path.join(run, "numbers.json")) as fh:
        dt = json.load(fh)["DT"]
    flow = post.read_flow(sorted(glob.glob(os.path.join(run, "post", "flow_*.txt"))))
    t = flow["step"] * dt
    w = gc.series.slope(t, flow["discharged_kg"], t0 - 1e-9, t1 + 1e-9)
    st = gc.series.read_csv(os.path.join(out, f"a{angle}", f"s{k}_strain.csv"))
    s = (st["t0"] >= t0 - 1e-9) & (st["t1"] <= t1 + 1e-6)
    return w, float(np.mean(st["I1"][s])), float(np.mean(st["J2"][s])), int(s.sum())


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--soft", default=os.path.join(HERE, "results"))
    ap.add_argument("--stiff", default=os.path.join(HERE, "results-stiff"))
    ap.add_argument("--angle", default="27")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    runs = []
    for out in (a.soft, a.stiff):
        with open(os.path.join(out, f"a{a.angle}", f"s{a.seed}.json")) as fh:
            runs.append(json.load(fh))
    soft, stiff = runs
    t0, t1 = stiff["steady_from_s"], stiff["discharge_s"]        # the stiff run's window (the shorter)
    rows = [(key, soft[key], stiff[key]) for key in STATIC]
    ws = [window(out, a.angle, a.seed, t0, t1) for out in (a.soft, a.stiff)]
    for i, name in enumerate((f"mass_flow_kg_s_{t0:.2f}_{t1:.2f}_s", f"I1_hull_{t0:.2f}_{t1:.2f}_s",
                              f"J2_hull_{t0:.2f}_{t1:.2f}_s", "strain_intervals")):
        rows.append((name, ws[0][i], ws[1][i]))
    path = os.path.join(a.stiff, "comparison.csv")
    with open(path, "w") as fh:
        fh.write("quantity,soft,stiff,stiff_over_soft\n")
        for key, x, y in rows:
            fh.write(f"{key},{x:.6g},{y:.6g},{y / x if x else float('nan'):.4g}\n")
    print(f"corn-silo stiffness: {a.angle} deg, seed {a.seed}, E {soft['youngs_Pa']:.3g} vs {stiff['youngs_Pa']:.3g} Pa "
          f"-> {path}")
    for key, x, y in rows:
        print(f"  {key:40s} {x:12.5g} {y:12.5g}  x{y / x if x else float('nan'):.3f}")


if __name__ == "__main__":
    gc.cli.main(main)
