"""fit.py: the cost model's constants (tools/granair_cases/costs.py,
docs/scaling.md) from the benchmark results of this machine, and the model
checked against every measured run.

    fit.py [--results bench/results] [--np1 coupled-np1] [--np2 coupled]
           [--memory memory] [--check NAME=LOG:INTERVAL:air|off ...]
           [--calibrate NAME=LOG:INTERVAL ...]
           [--check-run NAME=P:C:STEPS:INTERVAL:CPU_S[:CALIBRATION] ...]

Reads RESULTS/<np1>.csv and <np2>.csv (bench/coupled/run.sh at 1 and 2 ranks)
and RESULTS/<memory>.csv (bench/memory/run.sh), writes RESULTS/costs.json
(the constants) and RESULTS/costs-check.md (predicted vs measured loop time
of every benchmark run, and of the granairFoam logs given with --check, e.g.
the wedge-silo demo: runs the constants did not come from).
--calibrate stores a case's own DEM and coupling cost per particle-step,
measured on a run of it (its log), under costs["cases"][NAME]
(`./granair estimate --calibration NAME`); --check-run checks a run known
only by its figures (particles, cells, coupling steps, interval, measured
CPU seconds), with the benchmark's costs or a calibration.

Every time is CPU time (the stages' CPU time and the loop's CPU time on the
busiest rank, from granairFoam's report): on this shared machine wall times
carry the other processes' load, CPU times do not, and on a machine to
oneself a rank's wall time is its CPU time (MPI waits spin). The model so
predicts the wall time of a run with a core per rank.

Fits, all from the 1-rank runs unless said:
  dem, dem_off  DEM seconds per particle-step, air on / air off (sum over sizes
                of DEM time / sum of particle-steps: the largest size weighs most)
  cfd0, cfd     air solver per coupling step = cfd0 + cfd * cells (least squares)
  couple        (void fraction + mapping + exchange) per particle and coupling step
  fixed         the rest of the loop per coupling step (mean over sizes)
  eff2          parallel efficiency at 2 ranks: 1-rank prediction / (2 x measured
                2-rank loop less its latency), at the largest size
  latency       seconds per coupling step of an air run at more than one rank that
                do not shrink with the ranks (the air solver's global reductions,
                the exchange's messages): the smallest 2-rank air run's loop less
                its prediction without it, per coupling step (fitted with eff2,
                twice round)
  memory        per particle: slope of peak RSS with the air on between the two
                beds of bench/memory (one mesh); per cell and per rank: least
                squares of the rest over the 1-rank coupled runs.
"""
import argparse
import csv
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from granair_cases import costs as cm  # noqa: E402

INTERVAL = 50  # bench/coupled's coupling interval (make_case.py)


def rows(path):
    with open(path) as f:
        out = []
        for r in csv.DictReader(f):
            for k, v in r.items():
                try:
                    r[k] = float(v)
                except ValueError:
                    pass
            out.append(r)
        return out


def linfit(xs, ys):
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else 0.0
    return my - b * mx, b


def cpu(r, key):
    """CPU seconds of a stage (busiest rank), the wall figure if the log had none."""
    v = r.get("cpu_" + key)
    return v if isinstance(v, float) and v == v else r[key]


def loop(r):
    return r["cpu_max_s"]


def psteps(r):
    return r["particles"] * r["coupling_steps"] * INTERVAL


def fit(np1, np2, memory):
    on = sorted((r for r in np1 if r["air"] == "on"), key=lambda r: r["particles"])
    off = [r for r in np1 if r["air"] == "off"]
    t = {
        "dem_s_per_particle_step": sum(cpu(r, "dem_s") for r in on) / sum(psteps(r) for r in on),
        "dem_off_s_per_particle_step": sum(cpu(r, "dem_s") for r in off) / sum(psteps(r) for r in off),
        "couple_s_per_particle_step": sum(cpu(r, "mapping_s") + cpu(r, "exchange_s") for r in on) /
        sum(r["particles"] * r["coupling_steps"] for r in on),
    }
    a, b = linfit([r["cells"] for r in on], [cpu(r, "cfd_s") / r["coupling_steps"] for r in on])
    t["cfd_s_per_step"], t["cfd_s_per_cell_step"] = max(a, 0.0), b
    t["fixed_s_per_step"] = sum(max(0.0, loop(r) - cpu(r, "dem_s") - cpu(r, "cfd_s") - cpu(r, "mapping_s") -
                                    cpu(r, "exchange_s")) / r["coupling_steps"] for r in on) / len(on)
    t["latency_s_per_step"] = 0.0
    costs = {"time": t, "parallel_efficiency_2": 1.0, "memory": {"rank_mib": 0.0, "particle_b": 0.0, "cell_b": 0.0}}
    on2 = sorted((r for r in np2 if r["air"] == "on"), key=lambda r: r["particles"])
    big2, small2 = on2[-1], on2[0]
    p1 = cm.predict(costs, as_run(big2), 1)["wall_s"]
    for _ in range(2):
        costs["parallel_efficiency_2"] = p1 / (2 * (loop(big2) - t["latency_s_per_step"] * big2["coupling_steps"]))
        without = cm.predict(costs, as_run(small2), 2)["wall_s"] - t["latency_s_per_step"] * small2["coupling_steps"]
        t["latency_s_per_step"] = max(0.0, (loop(small2) - without) / small2["coupling_steps"])
    # memory
    mem_on = sorted(memory, key=lambda r: r["particles"])
    lo, hi = mem_on[0], mem_on[-1]
    particle_b = (hi["hwm_on_mib"] - lo["hwm_on_mib"]) * 2 ** 20 / (hi["particles"] - lo["particles"])
    rest = [(r["cells"], r["hwm_max_mib"] * 2 ** 20 - particle_b * r["particles"]) for r in on]
    # (the per-rank part: 1-rank runs, so hwm_max is the whole run)
    m0, mc = linfit([c for c, _ in rest], [v for _, v in rest])
    costs["memory"] = {"rank_mib": m0 / 2 ** 20, "particle_b": particle_b, "cell_b": mc}
    costs["source"] = "bench/costs/fit.py from bench/results/coupled-np1.csv, coupled.csv, memory.csv"
    return costs


def as_run(r):
    return {"particles": r["particles"], "cells": r["cells"], "cfd_steps": r["coupling_steps"],
            "interval": INTERVAL, "air": r["air"] != "off"}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument("--results", default=os.path.join(here, "..", "results"))
    ap.add_argument("--np1", default="coupled-np1")
    ap.add_argument("--np2", default="coupled")
    ap.add_argument("--memory", default="memory")
    ap.add_argument("--check", nargs="*", default=[], help="NAME=LOG:INTERVAL:air|off")
    ap.add_argument("--calibrate", nargs="*", default=[], help="NAME=LOG:INTERVAL")
    ap.add_argument("--check-run", nargs="*", default=[], help="NAME=P:C:STEPS:INTERVAL:CPU_S[:CALIBRATION]")
    a = ap.parse_args()
    np1 = rows(os.path.join(a.results, a.np1 + ".csv"))
    np2 = rows(os.path.join(a.results, a.np2 + ".csv"))
    memory = rows(os.path.join(a.results, a.memory + ".csv"))
    costs = fit(np1, np2, memory)
    for spec in a.calibrate:
        name, rest = spec.split("=", 1)
        log, interval = rest.rsplit(":", 1)
        run = cm.run_from_log(log, int(interval))
        if run["cpu_dem_s"] is None:
            raise SystemExit(f"fit.py: {log} has no stage CPU times (an older granairFoam)")
        costs.setdefault("cases", {})[name] = {
            "dem_s_per_particle_step": run["cpu_dem_s"] / run["particle_steps"],
            "couple_s_per_particle_step": (run["cpu_mapping_s"] + run["cpu_exchange_s"]) /
            (run["particles"] * run["cfd_steps"]),
            "source": f"{os.path.basename(os.path.dirname(os.path.dirname(log)))}: {run['particles']:.0f} particles "
                      f"(mean), {run['cfd_steps']} coupling steps of {interval}, 1 rank"}
    with open(os.path.join(a.results, "costs.json"), "w") as f:
        json.dump(costs, f, indent=1)
        f.write("\n")
    lines = ["# Cost model checked against measured runs", "",
             "Written by `bench/costs/fit.py` (docs/scaling.md). Constants (`costs.json`) fitted to the",
             "1-rank bench/coupled runs (the 2-rank efficiency to the largest 2-rank run, the latency per",
             "coupling step to the smallest); predicted",
             "coupling-loop time against the measured one: the loop's CPU time on the busiest rank (the",
             "wall time with a core per rank; this machine's wall times carry other users' load).", "",
             "| run | ranks | particles | cells | coupling steps | predicted s | measured CPU s | error |",
             "|---|---:|---:|---:|---:|---:|---:|---:|"]
    worst = 0.0
    for label, rs in (("bench/coupled", np1), ("bench/coupled", np2)):
        for r in sorted(rs, key=lambda r: (r["particles"], r["air"])):
            if r["air"] == "forces-off":
                continue
            pred = cm.predict(costs, as_run(r), int(r["ranks"]))["wall_s"]
            err = pred / loop(r) - 1
            worst = max(worst, abs(err))
            lines.append(f"| {label} air {r['air']} | {int(r['ranks'])} | {int(r['particles'])} | {int(r['cells'])} | "
                         f"{int(r['coupling_steps'])} | {pred:.2f} | {loop(r):.2f} | {100 * err:+.0f} % |")
    for spec in a.check:
        name, rest = spec.split("=", 1)
        log, interval, air = rest.rsplit(":", 2)
        run = cm.run_from_log(log, int(interval), air == "air")
        pred = cm.predict(costs, run, run["ranks"])
        err = pred["wall_s"] / run["cpu_max_s"] - 1
        lines.append(f"| {name} | {run['ranks']} | {run['particles']:.0f} | {run['cells']:.0f} | "
                     f"{run['cfd_steps']} | {pred['wall_s']:.2f} | {run['cpu_max_s']:.2f} | {100 * err:+.0f} % |")
        if run["hwm_max_mib"]:
            lines.append(f"|   peak memory per rank (MiB) | | | | | {pred['mem_rank_mib']:.0f} | "
                         f"{run['hwm_max_mib']:.0f} | {100 * (pred['mem_rank_mib'] / run['hwm_max_mib'] - 1):+.0f} % |")
    for spec in a.check_run:
        name, rest = spec.split("=", 1)
        f = rest.split(":")
        run = {"particles": float(f[0]), "cells": float(f[1]), "cfd_steps": int(f[2]), "interval": int(f[3]),
               "air": True}
        measured, calib = float(f[4]), (f[5] if len(f) > 5 else None)
        pred = cm.predict(costs, run, 1, calib)["wall_s"]
        lines.append(f"| {name}{' (calibration ' + calib + ')' if calib else ''} | 1 | {run['particles']:.0f} | "
                     f"{run['cells']:.0f} | {run['cfd_steps']} | {pred:.1f} | {measured:.1f} | "
                     f"{100 * (pred / measured - 1):+.0f} % |")
    lines += ["", f"Largest error over the bench/coupled runs: {100 * worst:.0f} %.", ""]
    with open(os.path.join(a.results, "costs-check.md"), "w") as f:
        f.write("\n".join(lines))
    print(json.dumps(costs, indent=1))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
