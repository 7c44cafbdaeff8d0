#!/usr/bin/env python3
"""estimate.py: wall time, core-hours and memory per rank of a granairFoam run
from the costs measured on this machine (docs/scaling.md).

    ./granair estimate CASE_DIR --ranks N [N ...] [overrides]
    ./granair estimate --particles P --cells C --dem-dt DT --cfd-dt DT --time T --ranks N [N ...]

CASE_DIR is a run folder (an OpenFOAM case with constant/couplingProperties,
e.g. one written by `./granair run cases/wedge-silo --setup-only`); read from it:
  cells              constant/polyMesh/owner (after blockMesh) or the blocks
                     of system/blockMeshDict
  CFD step, time     system/controlDict: deltaT, endTime - startTime
  coupling interval  constant/couplingProperties: couplingInterval; air on/off
  particles          log/granairFoam.log of a finished run (mean over its loop);
                     else give --particles.
Every value can be overridden (--particles, --cells, --cfd-dt, --interval or
--dem-dt, --time, --air). --calibration NAME: the DEM and coupling cost per
particle-step measured on a run of that case (stored in costs.json by
bench/costs/fit.py --calibrate) instead of the packed-column benchmark's; the
DEM's cost per particle-step depends on the case (contacts, cohesion, walls).
--costs FILE: another machine's costs.json. The model and its check:
docs/scaling.md.
"""
import argparse
import math
import os
import re
import sys

from granair_cases import costs as cm

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_COSTS = os.path.join(ROOT, "bench", "results", "costs.json")


def _read(path):
    with open(path, errors="replace") as f:
        return f.read()


def _strip_comments(text):
    return re.sub(r"//[^\n]*", "", re.sub(r"/\*.*?\*/", "", text, flags=re.S))


def _key(text, key, path):
    m = re.search(r"(?:^|[\s;{])" + re.escape(key) + r"\s+([^;]+);", _strip_comments(text))
    if not m:
        raise SystemExit(f"estimate: {path} has no '{key}'; give it on the command line")
    return m.group(1).strip()


def case_cells(case):
    owner = os.path.join(case, "constant", "polyMesh", "owner")
    if os.path.isfile(owner):
        with open(owner, "rb") as f:
            head = f.read(2000).decode("latin-1")
        m = re.search(r"nCells:\s*(\d+)", head)
        if m:
            return int(m.group(1))
    bmd = os.path.join(case, "system", "blockMeshDict")
    if os.path.isfile(bmd):
        text = _strip_comments(_read(bmd))
        blocks = re.findall(r"hex\s*\([\d\s]+\)\s*(?:\w+\s*)?\(\s*(\d+)\s+(\d+)\s+(\d+)\s*\)", text)
        if blocks:
            return sum(int(a) * int(b) * int(c) for a, b, c in blocks)
    return None


def case_particles(case, interval):
    log = os.path.join(case, "log", "granairFoam.log")
    if os.path.isfile(log):
        try:
            return cm.run_from_log(log, interval)["particles"], log
        except ValueError:
            pass
    return None, None


def from_case(case):
    cp = os.path.join(case, "constant", "couplingProperties")
    cd = os.path.join(case, "system", "controlDict")
    for p in (cp, cd):
        if not os.path.isfile(p):
            raise SystemExit(f"estimate: {p} not found; CASE_DIR must be a run folder (an OpenFOAM case with "
                             f"constant/couplingProperties), e.g. written by ./granair run CASE --setup-only")
    cpt, cdt = _read(cp), _read(cd)
    interval = int(float(_key(cpt, "couplingInterval", cp)))
    air = _key(cpt, "air", cp) in ("on", "yes", "true")
    dt = float(_key(cdt, "deltaT", cd))
    t = float(_key(cdt, "endTime", cd)) - float(_key(cdt, "startTime", cd))
    particles, src = case_particles(case, interval)
    return {"cells": case_cells(case), "cfd_dt": dt, "interval": interval, "time": t, "air": air,
            "particles": particles, "particles_from": src}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case", nargs="?")
    ap.add_argument("--ranks", type=int, nargs="+", required=True)
    ap.add_argument("--particles", type=float)
    ap.add_argument("--cells", type=float)
    ap.add_argument("--cfd-dt", type=float, help="coupling (CFD) step [s]")
    ap.add_argument("--interval", type=int, help="DEM steps per coupling step")
    ap.add_argument("--dem-dt", type=float, help="DEM step [s] (sets the interval from --cfd-dt)")
    ap.add_argument("--time", type=float, help="simulated time [s]")
    ap.add_argument("--air", choices=["on", "off"])
    ap.add_argument("--costs", default=DEFAULT_COSTS)
    ap.add_argument("--calibration", help="a case's own measured DEM cost (costs.json 'cases'), e.g. wedge-silo")
    a = ap.parse_args(argv)
    run = from_case(a.case) if a.case else {}
    for k in ("particles", "cells", "cfd_dt", "time"):
        if getattr(a, k) is not None:
            run[k] = getattr(a, k)
    if a.air:
        run["air"] = a.air == "on"
    run.setdefault("air", True)
    if a.interval:
        run["interval"] = a.interval
    if a.dem_dt:
        if not run.get("cfd_dt"):
            raise SystemExit("estimate: --dem-dt needs the CFD step (--cfd-dt or a CASE_DIR)")
        run["interval"] = max(1, math.ceil(run["cfd_dt"] / a.dem_dt - 1e-9))
    missing = [k for k in ("particles", "cells", "cfd_dt", "interval", "time") if not run.get(k)]
    if missing:
        raise SystemExit("estimate: unknown " + ", ".join(missing) + "; give --" +
                         ", --".join(m.replace("_", "-") for m in missing))
    if not os.path.isfile(a.costs):
        raise SystemExit(f"estimate: {a.costs} not found: run bench/coupled, bench/memory, then bench/costs/fit.py")
    if any(r < 1 for r in a.ranks):
        raise SystemExit("estimate: --ranks must be >= 1")
    costs = cm.load(a.costs)
    run["cfd_steps"] = round(run["time"] / run["cfd_dt"])
    dem_dt = run["cfd_dt"] / run["interval"]
    src = f"calibration {a.calibration}" if a.calibration else "the benchmark's DEM cost"
    print(f"granair estimate ({os.path.relpath(a.costs)}, {src}; docs/scaling.md)")
    print(f"  {run['particles']:.4g} particles, {run['cells']:.4g} cells, air {'on' if run['air'] else 'off'}; "
          f"{run['time']:g} s simulated: {run['cfd_steps']} coupling steps of {run['cfd_dt']:g} s, "
          f"{run['interval']} DEM steps of {dem_dt:.4g} s each")
    if a.calibration and not run["air"] and "dem_off_s_per_particle_step" not in costs.get("cases", {}).get(
            a.calibration, {"dem_off_s_per_particle_step": 0}):
        # a case calibrated on its air run only: its DEM-only cost is the benchmark's, said so
        print(f"  note: calibration {a.calibration} was measured with air on; the DEM-only cost per particle-step "
              "is the benchmark's")
    if run.get("particles_from"):
        print(f"  particle count from {run['particles_from']}")
    print(f"  {'ranks':>6} {'wall':>12} {'core-hours':>11} {'memory/rank':>12}  DEM / CFD / coupling share")
    for r in a.ranks:
        try:
            p = cm.predict(costs, run, r, a.calibration)
        except KeyError as e:
            raise SystemExit(f"estimate: {e.args[0]} ({a.costs})")
        w = p["wall_s"]
        wall = f"{w:.0f} s" if w < 3600 else (f"{w / 3600:.1f} h" if w < 86400 * 3 else f"{w / 86400:.0f} d")
        mem = p["mem_rank_mib"]
        mems = f"{mem:.0f} MiB" if mem < 4096 else f"{mem / 1024:.1f} GiB"
        shares = " / ".join(f"{100 * p[k] / w:.0f} %" for k in ("dem_s", "cfd_s", "couple_s"))
        per = run["particles"] / r
        note = "  (below 1e4 particles per rank: communication not in the model)" if per < 1e4 and r > 1 else ""
        print(f"  {r:6d} {wall:>12} {p['cpu_h']:11.3g} {mems:>12}  {shares}{note}")
    if any(r > 2 for r in a.ranks):
        print("  Ranks > 2 use the 2-rank parallel efficiency measured here "
              f"({costs['parallel_efficiency_2']:.2f}); not measured beyond 2 ranks on this machine.")


if __name__ == "__main__":
    sys.exit(main())
