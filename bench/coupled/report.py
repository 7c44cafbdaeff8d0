"""report.py: turns the runs of bench/coupled/run.sh into results/coupled.csv
and results/coupled.md (the speed targets as ratios).

    report.py WORKDIR RESULTSDIR [NAME]      (writes NAME.md/.csv, default coupled)

WORKDIR holds one folder per run, <particles>_<config>_<repeat>/ (config: off =
DEM only, forces-off = the coupled run with no fluid force, on), each with
bench.json (written by make_case.py) and log/granairFoam.log. Of the repeats
of one configuration the fastest coupling loop is reported (the least
disturbed by other load on the machine), with the slowest beside it.

Targets (issue 22):
  (a) coupled throughput / DEM-only throughput >= 0.90, reported two ways:
      the coupling overhead on the same DEM problem (forces-off / DEM only)
      and the plain ratio (on / DEM only), which also holds the change of the
      DEM's own work under the fluid force (on / forces-off); bench/README.md
  (b) (void fraction + mapping + exchange) / coupling-loop wall time <= 2 %
  (c) cost per particle-step flat (linear total cost) from 1e3 to 1e5
"""

import csv
import json
import os
import sys

from parse_log import parse_log


def contacts_per_particle(path):
    """Mean contacts per particle over the run, from the thermo lines
    (step, atoms, contact sum) the benchmark's LIGGGHTS script prints; nan
    if the log has none (a run from before they were printed)."""
    seen = {}
    try:
        with open(path, errors="replace") as f:
            for line in f:
                parts = line.split()
                if len(parts) == 3 and parts[0].isdigit() and parts[1].isdigit():
                    step, atoms, total = int(parts[0]), int(parts[1]), float(parts[2])
                    if step > 0 and atoms > 0:
                        seen[step] = total / atoms
    except (OSError, ValueError):
        return float("nan")
    return sum(seen.values()) / len(seen) if seen else float("nan")


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
        meta["contacts_per_particle"] = contacts_per_particle(os.path.join(d, "log", "log.liggghts"))
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
        row["dem_ns_per_particle_step"] = 1e9 * best["dem_s"] / best["particle_steps"]
        row["coupling_share_pct"] = 100.0 * (best["mapping_s"] + best["exchange_s"]) / best["loop_s"]
        # the same share from the stages' CPU time (busiest rank), immune to descheduling
        row["coupling_share_cpu_pct"] = 100.0 * (best["cpu_mapping_s"] + best["cpu_exchange_s"]) / best["cpu_max_s"]
        row["cpu_sum_s_min"] = min(r["cpu_sum_s"] for r in rs)
        # DEM share of the coupled loop: (a) if the DEM cost the same with and
        # without air, from one run (immune to load changes between runs).
        row["dem_share"] = best["dem_s"] / best["loop_s"]
        rows[key] = row
    return rows


COLUMNS = ["particles", "cells", "air", "ranks", "coupling_steps", "repeats", "loop_s_min", "loop_s_max",
           "throughput", "ns_per_particle_step", "dem_s", "cfd_s", "mapping_s", "exchange_s", "output_s",
           "coupling_share_pct", "dem_share", "cpu_sum_s_min", "hwm_max_mib", "buf_per_particle", "buf_per_cell",
           "cpu_max_s", "cpu_dem_s", "cpu_cfd_s", "cpu_mapping_s", "cpu_exchange_s", "cpu_output_s",
           "coupling_share_cpu_pct", "contacts_per_particle", "dem_ns_per_particle_step", "bed"]


def write_csv(rows, path):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for key in sorted(rows):
            r = rows[key]
            w.writerow([r.get(c, "") if not isinstance(r.get(c), float) else f"{r[c]:.6g}" for c in COLUMNS])


def _ratio_cells(num, den):
    """Throughput ratio num/den by wall time and by CPU time summed over ranks."""
    if not (num and den):
        return "- | -"
    return (f"{num['throughput'] / den['throughput']:.3f} | "
            f"{den['cpu_sum_s_min'] / num['cpu_sum_s_min']:.3f}")


def write_md(rows, path, machine):
    sizes = sorted({n for n, _ in rows})
    ranks = sorted({r["ranks"] for r in rows.values()})
    beds = sorted({r.get("bed", "lattice") for r in rows.values()})
    bed_text = {"lattice": "simple cubic lattice", "random": "random packed bed, settled once per size"}
    lines = ["# Coupled benchmark: speed targets as ratios (" + ", ".join(map(str, ranks)) + " rank(s))", "",
             "Written by `bench/coupled/run.sh` (see bench/README.md). Packed column of d = 1 mm",
             "spheres (" + "; ".join(bed_text[b] for b in beds) + ") with air at 0.2 m/s flowing up through it, cells of",
             "3 d, coupling interval 50, centre void fraction, Ergun/Gidaspow drag. Each size",
             "runs three ways, back to back: `air off;` (DEM only), the coupled run with its fluid",
             "forces off (`forces { drag off; pressureGradient off; buoyancy off; }`: the same DEM",
             "problem as DEM only, with all of the coupling's work) and `air on;`. The fastest of",
             "the repeats is shown (slowest in brackets). Times are the coupling loop only",
             "(set-up excluded), max over ranks.", ""]
    if machine:
        lines += ["Machine while running: " + machine, ""]
    lines += ["| particles | cells | Mps/s DEM only | Mps/s forces off | Mps/s coupled |"
              " overhead: forces off / DEM only, wall | CPU | coupled / DEM only, wall | CPU |"
              " coupled / forces off, wall | CPU | (b) mapping+exchange share, wall | CPU | loop s off |"
              " loop s forces off | loop s on |",
              "|" + "---:|" * 16]
    for n in sizes:
        off, ref, on = rows.get((n, "off")), rows.get((n, "forces-off")), rows.get((n, "on"))
        any_run = on or ref or off

        def mps(r):
            return f"{r['throughput'] / 1e6:.3g}" if r else "-"

        def loop(r):
            return f"{r['loop_s_min']:.2f} ({r['loop_s_max']:.2f})" if r else "-"
        share = on or ref
        lines.append(f"| {n} | {any_run['cells']} | {mps(off)} | {mps(ref)} | {mps(on)} | "
                     f"{_ratio_cells(ref, off)} | {_ratio_cells(on, off)} | {_ratio_cells(on, ref)} | "
                     f"{share['coupling_share_pct']:.2f} % | {share['coupling_share_cpu_pct']:.2f} % | "
                     f"{loop(off)} | {loop(ref)} | {loop(on)} |"
                     if share else f"| {n} | {any_run['cells']} | {mps(off)} | - | - | - | - | - | - | - | - | - | "
                     f"{loop(off)} | - | - |")
    lines += ["", "Mps/s = million particle-steps per second of wall time (particles x DEM steps / loop time).",
              "Each ratio is a throughput ratio, once from wall time and once from the loop's CPU time",
              "summed over ranks (fastest repeat; less disturbed by other load than wall time, but it",
              "still counts a rank's busy wait for a descheduled partner). The overhead column is the",
              "cost of coupling on an unchanged DEM problem (target >= 0.90); coupled / forces off is",
              "how much more work the DEM itself does when the air pushes on the bed (a different",
              "contact state, not a cost of the coupling code); coupled / DEM only is their product.",
              "(b): (void fraction + mapping + exchange) / loop time of the coupled run (forces-off run",
              "if there is none), from wall time and from the stages' CPU time on the busiest rank.",
              "", "## Where the time goes (s, max over ranks)", "",
              "| particles | run | DEM | CFD | void fraction + mapping | exchange | output | loop | CPU s, all ranks |"
              " CPU s of DEM / CFD / mapping / exchange, busiest rank |",
              "|---:|---|---:|---:|---:|---:|---:|---:|---:|---|"]
    for n in sizes:
        for cfg in ("off", "forces-off", "on"):
            r = rows.get((n, cfg))
            if r:
                lines.append(f"| {n} | {cfg} | {r['dem_s']:.2f} | {r['cfd_s']:.2f} | {r['mapping_s']:.3f} | "
                             f"{r['exchange_s']:.3f} | {r['output_s']:.3f} | {r['loop_s_min']:.2f} | "
                             f"{r['cpu_sum_s_min']:.2f} | {r['cpu_dem_s']:.2f} / {r['cpu_cfd_s']:.2f} / "
                             f"{r['cpu_mapping_s']:.3f} / {r['cpu_exchange_s']:.3f} |")
    lines += ["", "## The DEM's own work", "",
              "| particles | contacts per particle: DEM only | forces off | coupled |"
              " DEM ns per particle-step: DEM only | forces off | coupled |", "|---:|---:|---:|---:|---:|---:|---:|"]
    for n in sizes:
        cells = []
        for key in ("contacts_per_particle", "dem_ns_per_particle_step"):
            for cfg in ("off", "forces-off", "on"):
                r = rows.get((n, cfg))
                cells.append(f"{r[key]:.{2 if key.startswith('contacts') else 1}f}" if r else "-")
        lines.append(f"| {n} | " + " | ".join(cells) + " |")
    lines += ["", "Contacts per particle: LIGGGHTS' contact/atom (particle pairs in contact, walls not",
              "counted), mean over the run. The DEM's cost follows its contacts: where the fluid force",
              "adds contacts the coupled run's DEM does more work than DEM only's for a reason of",
              "physics, not of the coupling code.",
              "", "## (c) Cost per particle-step (ns of wall time, all ranks together)", "",
              "| particles | DEM only | forces off | coupled | coupled / smallest size |", "|---:|---:|---:|---:|---:|"]
    base = None
    for n in sizes:
        off, ref, on = rows.get((n, "off")), rows.get((n, "forces-off")), rows.get((n, "on"))
        if not on:
            continue
        base = base or on["ns_per_particle_step"]

        def ns(r):
            return f"{r['ns_per_particle_step']:.1f}" if r else "-"
        lines.append(f"| {n} | {ns(off)} | {ns(ref)} | {ns(on)} | {on['ns_per_particle_step'] / base:.2f} |")
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
