"""stage_cpu.py: per-stage CPU time of granairFoam runs, grouped, as a
Markdown table (before/after comparisons of the coupling's own stages).

    stage_cpu.py --group NAME LOG [LOG ...] [--group NAME LOG ...] [--title T]

Each LOG is a granairFoam log (log/granairFoam.log of a run folder). For
every group: the runs, and per run the coupling loop's CPU time (busiest
rank), the CPU time of the DEM, CFD, void fraction + mapping and exchange
stages (max over ranks) and the share of mapping + exchange in the loop's
CPU time; then the group's mean, min and max of that share. CPU times are
the stages' thread CPU (granairFoam's timing breakdown), so they hold on a
loaded machine where wall times do not (bench/README.md, "Noise").
"""

import argparse
import os
import statistics

from parse_log import parse_log


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--group", nargs="+", action="append", metavar=("NAME", "LOG"), required=True)
    ap.add_argument("--title", default="Stage CPU times")
    a = ap.parse_args()
    lines = [f"## {a.title}", "",
             "| group | run | loop CPU s | DEM | CFD | void fraction + mapping | exchange | mapping + exchange, "
             "share of loop CPU |", "|---|---|---:|---:|---:|---:|---:|---:|"]
    summary = []
    for g in a.group:
        name, logs = g[0], g[1:]
        if not logs:
            raise SystemExit(f"stage_cpu.py: group {name} has no logs")
        shares = []
        for log in logs:
            r = parse_log(log)
            share = 100 * (r["cpu_mapping_s"] + r["cpu_exchange_s"]) / r["cpu_max_s"]
            shares.append(share)
            run = os.path.relpath(log).replace("/log/granairFoam.log", "")
            lines.append(f"| {name} | {run} | {r['cpu_max_s']:.3f} | {r['cpu_dem_s']:.3f} | {r['cpu_cfd_s']:.3f} | "
                         f"{r['cpu_mapping_s']:.3f} | {r['cpu_exchange_s']:.3f} | {share:.2f} % |")
        summary.append(f"- {name}: mapping + exchange {statistics.mean(shares):.2f} % of the loop's CPU "
                       f"(min {min(shares):.2f}, max {max(shares):.2f}, {len(shares)} runs)")
    print("\n".join(lines + [""] + summary + [""]))


if __name__ == "__main__":
    main()
