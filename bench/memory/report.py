"""report.py: bytes per particle and per cell that the coupling layer adds,
from the runs of bench/memory/run.sh; writes results/memory.{md,csv}.

    report.py WORKDIR RESULTSDIR

WORKDIR holds bed<H>_<air>/ folders (bench.json + log/granairFoam.log), all
on the same mesh, beds of different heights, air on and off.

Two measures:
  counted   the coupling layer's own buffers as granairFoam counts them
            (vector capacities, i.e. high-water marks, of CoupledRun,
            ParticleExchange and CouplingStep), per particle and per cell;
  RSS       peak resident memory (VmHWM summed over ranks) of the air-on run
            minus the air-off run of the same bed: everything the air adds
            (OpenFOAM's solver fields and matrices, the cell locator's search
            tree, the coupling buffers). Its slope between two beds on one
            mesh is the per-particle part; what is left at the smaller bed,
            divided by the cells, the per-cell part. RSS moves in pages and
            malloc arenas, so the split is approximate (a few bytes).
Also reported: the slope of the air-on runs alone between the beds (all a
particle costs the run: LIGGGHTS, the coupling, everything).
Not in the counted figure (estimated from the code, per particle): LIGGGHTS'
fluid-force arrays, fix property/atom (24 B) + fix external (24 B) sized to
local + ghost atoms, and LiggghtsDriver's tag list (4 B); they are in the
RSS slope.
Targets (issue 22): 150 bytes per particle (counted and RSS slope), 64 bytes
per cell beyond OpenFOAM's own fields (the counted per-cell buffers).
"""

import csv
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "coupled"))
from parse_log import parse_log  # noqa: E402

MIB = 1024.0 * 1024.0
TARGET = 150.0
TARGET_CELL = 64.0


def load(work):
    runs = {}
    for name in sorted(os.listdir(work)):
        d = os.path.join(work, name)
        meta_path, log = os.path.join(d, "bench.json"), os.path.join(d, "log", "granairFoam.log")
        if os.path.isfile(meta_path) and os.path.isfile(log):
            with open(meta_path) as f:
                meta = json.load(f)
            meta.update(parse_log(log))
            runs[(meta["bed_height_d"], meta["air"])] = meta
    return runs


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    work, results = sys.argv[1], sys.argv[2]
    os.makedirs(results, exist_ok=True)
    runs = load(work)
    beds = sorted({h for h, air in runs if (h, "on") in runs and (h, "off") in runs})
    if not beds:
        raise SystemExit(f"report.py: no bed with both an air-on and an air-off run in {work}")
    rows = []
    for h in beds:
        on, off = runs[(h, "on")], runs[(h, "off")]
        rows.append({"bed_height_d": h, "particles": on["particles"], "cells": on["cells"], "ranks": on["ranks"],
                     "hwm_off_mib": off["hwm_sum_mib"], "hwm_on_mib": on["hwm_sum_mib"],
                     "delta_mib": on["hwm_sum_mib"] - off["hwm_sum_mib"],
                     "counted_B_per_particle": on["buf_per_particle"], "counted_run": on["buf_run"],
                     "counted_exchange": on["buf_exchange"], "counted_step": on["buf_step"],
                     "counted_B_per_cell": on["buf_per_cell"],
                     "off_counted_B_per_particle": off["buf_per_particle"]})
    with open(os.path.join(results, "memory.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})

    lines = ["# Memory the coupling layer adds", "",
             "Written by `bench/memory/run.sh` (see bench/README.md): the packed column of",
             "bench/coupled, one mesh, beds of different heights, each run with the air on and off",
             f"on {rows[0]['ranks']} ranks. Targets: {TARGET:.0f} bytes per particle (counted and as RSS",
             f"slope), {TARGET_CELL:.0f} bytes per cell beyond OpenFOAM's own fields (counted).", "",
             "## Counted: the coupling layer's own buffers (granairFoam's report)", "",
             "| bed layers | particles | cells | B/particle | of which CoupledRun | exchange | coupling step |"
             " B/cell |", "|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['bed_height_d']} | {r['particles']} | {r['cells']} | {r['counted_B_per_particle']:.1f} | "
                     f"{r['counted_run']:.1f} | {r['counted_exchange']:.1f} | {r['counted_step']:.1f} | "
                     f"{r['counted_B_per_cell']:.1f} |")
    lines += ["", "With the air off (the void fraction for the output: particle copy, exchange, stencils): "
              + ", ".join(f"{r['off_counted_B_per_particle']:.1f} B/particle" for r in rows) + ".",
              "Per cell: the coupling step's solid volume and drag sums (8 B each), plus, with the gaussian",
              "void fraction, the cell locator's flat neighbour list (~28 B on hexes) and the kernel's visit",
              "stamps (4 B); OpenFOAM's fields (voidfraction, Ksl, Us, ...) are the air solver's.", "",
              "## Peak resident memory, air on minus air off (all ranks)", "",
              "| bed layers | particles | air off MiB | air on MiB | difference MiB |", "|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['bed_height_d']} | {r['particles']} | {r['hwm_off_mib']:.1f} | {r['hwm_on_mib']:.1f} | "
                     f"{r['delta_mib']:.2f} |")
    if len(rows) >= 2:
        a, b = rows[0], rows[-1]
        per_particle = (b["delta_mib"] - a["delta_mib"]) * MIB / (b["particles"] - a["particles"])
        per_cell = (a["delta_mib"] * MIB - per_particle * a["particles"]) / a["cells"]
        whole = (b["hwm_on_mib"] - a["hwm_on_mib"]) * MIB / (b["particles"] - a["particles"])
        lines += ["", f"Slope between the beds: **{per_particle:.0f} B per particle** added by the air side "
                  f"(target {TARGET:.0f}); rest at {a['particles']} particles: **{per_cell:.0f} B per cell** "
                  "(OpenFOAM's air solver fields and matrices, the cell search tree, the per-cell coupling "
                  "buffers; with one mesh, any fixed cost of switching the air on is in this figure too, so it "
                  "is an upper bound).", "",
                  f"Slope of the air-on runs alone: {whole:.0f} B per particle (everything a particle costs "
                  "the run, LIGGGHTS' own atom arrays and neighbour lists included).", ""]
    lines += ["Not counted above (per particle, from the code): LIGGGHTS' fluid-force arrays (fix property/atom",
              "24 B + fix external 24 B, sized to local + ghost atoms) and LiggghtsDriver's tag list (4 B).", ""]
    with open(os.path.join(results, "memory.md"), "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
