"""report.py: turns the runs of bench/coupled/run.sh into results/coupled.csv
and results/coupled.md (the speed targets as ratios).

    report.py WORKDIR RESULTSDIR [NAME]      (writes NAME.md/.csv, default coupled)

WORKDIR holds one folder per run, <particles>_<air>_<repeat>/, each with
bench.json (written by make_case.py) and log/granairFoam.log. Of the repeats
of one configuration the fastest coupling loop is reported (the least
disturbed by other load on the machine), with the slowest beside it.

Targets (from the project brief):
  (a) coupled throughput / DEM-only throughput >= 0.85
  (b) (void fraction + mapping + exchange) / coupling-loop wall time <= 2 %
  (c) cost per particle-step flat (linear total cost) from 1e3 to 1e5
"""

import csv
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from parse_log import parse_log  # noqa: E402


def load_runs(work):
    runs = []
    for name in sorted(os.listdir(work)):
        d = os.path.join(work, name)
        meta_path = os.path.join(d, "bench.json")
        log = os.path.join(d, "log", "granairFoam.log")
        if not (os.path.isfile(meta_path) and os.path.isfile(log)):
            continue
        with open(meta_path) as f:
            meta = json.load(f)
        meta.update(parse_log(log))
        meta["run"] = name
        runs.append(meta)
    if not runs:
        raise SystemExit(f"report.py: no finished runs in {work}")
    return runs


def best_of(runs):
    """One row per (particles, air): the fastest loop of the repeats."""
    groups = {}
    for r in runs:
        groups.setdefault((r["particles"], r["air"]), []).append(r)
    rows = {}
    for key, rs in groups.items():
        best = min(rs, key=lambda r: r["loop_s"])
        row = dict(best)
        row["repeats"] = len(rs)
        row["loop_s_min"] = best["loop_s"]
        row["loop_s_max"] = max(r["loop_s"] for r in rs)
        row["ns_per_particle_step"] = 1e9 * best["loop_s"] / best["particle_steps"]
        row["coupling_share_pct"] = 100.0 * (best["mapping_s"] + best["exchange_s"]) / best["loop_s"]
        row["cpu_sum_s_min"] = min(r["cpu_sum_s"] for r in rs)
        # DEM share of the coupled loop: (a) if the DEM cost the same with and
        # without air, from one run (immune to load changes between runs).
        row["dem_share"] = best["dem_s"] / best["loop_s"]
        rows[key] = row
    return rows


COLUMNS = ["particles", "cells", "air", "ranks", "coupling_steps", "repeats", "loop_s_min", "loop_s_max",
           "throughput", "ns_per_particle_step", "dem_s", "cfd_s", "mapping_s", "exchange_s", "output_s",
           "coupling_share_pct", "dem_share", "cpu_sum_s_min", "hwm_max_mib", "buf_per_particle", "buf_per_cell"]


def write_csv(rows, path):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for key in sorted(rows):
            r = rows[key]
            w.writerow([r[c] if not isinstance(r[c], float) else f"{r[c]:.6g}" for c in COLUMNS])


def write_md(rows, path, machine):
    sizes = sorted({n for n, _ in rows})
    ranks = sorted({r["ranks"] for r in rows.values()})
    lines = ["# Coupled benchmark: speed targets as ratios (" + ", ".join(map(str, ranks)) + " rank(s))", "",
             "Written by `bench/coupled/run.sh` (see bench/README.md). Packed column of d = 1 mm",
             "spheres (simple cubic lattice) with air at 0.2 m/s flowing up through it, cells of",
             "3 d, coupling interval 50, centre void fraction, Ergun/Gidaspow drag. Each",
             "configuration is run with `air on;` and with `air off;` (DEM only, same case); the",
             "fastest of the repeats is shown (slowest in brackets). Times are the coupling loop",
             "only (set-up excluded), max over ranks.", ""]
    if machine:
        lines += ["Machine while running: " + machine, ""]
    lines += ["| particles | cells | DEM-only Mps/s | coupled Mps/s | (a) ratio, target >= 0.85 |"
              " (a) by CPU time | (a) from the coupled run alone | (b) mapping+exchange share, target <= 2 % |"
              " loop s off | loop s on |",
              "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for n in sizes:
        off, on = rows.get((n, "off")), rows.get((n, "on"))
        if not (off and on):
            continue
        ratio = on["throughput"] / off["throughput"]
        lines.append(f"| {n} | {on['cells']} | {off['throughput'] / 1e6:.3g} | {on['throughput'] / 1e6:.3g} | "
                     f"{ratio:.3f} | {off['cpu_sum_s_min'] / on['cpu_sum_s_min']:.3f} | {on['dem_share']:.3f} | "
                     f"{on['coupling_share_pct']:.2f} % | "
                     f"{off['loop_s_min']:.2f} ({off['loop_s_max']:.2f}) | "
                     f"{on['loop_s_min']:.2f} ({on['loop_s_max']:.2f}) |")
    lines += ["", "Mps/s = million particle-steps per second of wall time (particles x DEM steps / loop time).",
              "(a) by CPU time: the same ratio from the loop's CPU time summed over ranks (fastest repeat),",
              "less disturbed by other load than wall time, but it still counts a rank's busy wait for a",
              "descheduled partner. (a) from the coupled run alone: DEM time / loop time of the coupled run,",
              "the ratio (a) would have if the DEM cost the same with and without air; both times come from",
              "the same run, so load changes between runs do not enter it.",
              "", "## Where the coupled time goes (s, max over ranks)", "",
              "| particles | DEM | CFD | void fraction + mapping | exchange | output | loop |",
              "|---:|---:|---:|---:|---:|---:|---:|"]
    for n in sizes:
        on = rows.get((n, "on"))
        if on:
            lines.append(f"| {n} | {on['dem_s']:.2f} | {on['cfd_s']:.2f} | {on['mapping_s']:.3f} | "
                         f"{on['exchange_s']:.3f} | {on['output_s']:.3f} | {on['loop_s_min']:.2f} |")
    lines += ["", "## (c) Cost per particle-step (ns of wall time, all ranks together)", "",
              "| particles | DEM-only | coupled | coupled / smallest size |", "|---:|---:|---:|---:|"]
    base = None
    for n in sizes:
        off, on = rows.get((n, "off")), rows.get((n, "on"))
        if not on:
            continue
        base = base or on["ns_per_particle_step"]
        off_s = f"{off['ns_per_particle_step']:.1f}" if off else "-"
        lines.append(f"| {n} | {off_s} | {on['ns_per_particle_step']:.1f} | "
                     f"{on['ns_per_particle_step'] / base:.2f} |")
    lines += ["", "A flat last column means the total cost grows linearly with the particle count.", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))


def main():
    if len(sys.argv) not in (3, 4):
        raise SystemExit(__doc__)
    work, results = sys.argv[1], sys.argv[2]
    name = sys.argv[3] if len(sys.argv) == 4 else "coupled"
    os.makedirs(results, exist_ok=True)
    rows = best_of(load_runs(work))
    machine = ""
    mpath = os.path.join(work, "machine.txt")
    if os.path.isfile(mpath):
        with open(mpath) as f:
            machine = " ".join(f.read().split())
    write_csv(rows, os.path.join(results, name + ".csv"))
    write_md(rows, os.path.join(results, name + ".md"), machine)
    print(open(os.path.join(results, name + ".md")).read())


if __name__ == "__main__":
    main()
