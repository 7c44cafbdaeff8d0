"""The cost model of a granairFoam run (docs/scaling.md): wall time and memory
per rank from costs measured on this machine (bench/results/costs.json,
written by bench/costs/fit.py from bench/coupled and bench/memory).

    load(path)                     the measured costs
    predict(costs, run, ranks)     {"wall_s", "cpu_h", "mem_rank_mib", stage times...}
    run_from_log(log, interval)    particles, cells, steps of a finished run (for checks)

A run is a dict: particles P, cells C, cfd_steps S (coupling steps), interval
K (DEM steps per coupling step), air (True/False). On one rank

    wall = dem * P * S * K  +  (cfd0 + cfd * C) * S  +  couple * P * S  +  fixed * S

(dem: seconds per particle-step of the DEM with granair's fixes attached;
cfd0 + cfd * C: the air solver's step; couple: void fraction + mapping +
exchange per particle and coupling step; fixed: the rest of a coupling step:
monitors, time series, progress). With the air off the cfd and couple terms
are 0. On R ranks every term is divided by R and by the parallel efficiency
measured at 2 ranks (the only rank count measured on this machine; R > 2 is
an extrapolation, see docs/scaling.md), and, with the air on, a latency per
coupling step is added that does not shrink with R (the air solver's global
reductions and the exchange's messages: what a small coupled run on 2 ranks
is made of; `latency_s_per_step`, 0 in a costs file fitted before it).
Memory per rank:
mem0 + mem_particle * P / R + mem_cell * C / R (peak resident).
"""
import json
import re


def load(path):
    with open(path) as f:
        return json.load(f)


def predict(costs, run, ranks, calibration=None):
    """calibration: the name of a case in costs["cases"] (its own DEM and
    coupling cost per particle-step, measured on a run of it), else the
    benchmark's."""
    c = dict(costs["time"])
    if calibration:
        if calibration not in costs.get("cases", {}):
            raise KeyError(f"no calibration '{calibration}' in the costs file (have: "
                           f"{', '.join(sorted(costs.get('cases', {}))) or 'none'})")
        c.update({k: v for k, v in costs["cases"][calibration].items() if k.endswith("_per_particle_step")})
    p, cells, s, k = float(run["particles"]), float(run["cells"]), float(run["cfd_steps"]), float(run["interval"])
    air = run.get("air", True)
    dem_key = "dem_s_per_particle_step" if air else "dem_off_s_per_particle_step"
    stages = {
        "dem_s": c[dem_key] * p * s * k,
        "cfd_s": (c["cfd_s_per_step"] + c["cfd_s_per_cell_step"] * cells) * s if air else 0.0,
        "couple_s": c["couple_s_per_particle_step"] * p * s if air else 0.0,
        "fixed_s": c["fixed_s_per_step"] * s,
    }
    serial = sum(stages.values())
    eff = 1.0 if ranks == 1 else costs["parallel_efficiency_2"]
    latency = c.get("latency_s_per_step", 0.0) * s if ranks > 1 and air else 0.0
    wall = serial / ranks / eff + latency
    m = costs["memory"]
    mem = m["rank_mib"] + (m["particle_b"] * p + m["cell_b"] * cells) / ranks / 2 ** 20
    out = {k_: v / ranks / eff for k_, v in stages.items()}
    out.update(latency_s=latency, wall_s=wall, cpu_h=wall * ranks / 3600.0, mem_rank_mib=mem, particle_steps=p * s * k)
    return out


_NUM = r"([-+0-9.eE]+)"


def run_from_log(log_path, interval, air=True):
    """particles (mean over the loop), cells, coupling steps of a finished run,
    from granairFoam's end-of-run report."""
    text = open(log_path, errors="replace").read()
    m = re.search(r"Coupling loop: " + _NUM + r" s wall for (\d+) coupling steps, " + _NUM + r" particle-steps",
                  text)
    if not m:
        raise ValueError(f"{log_path}: no 'Coupling loop:' line (did the run finish?)")
    loop_s, steps, psteps = float(m.group(1)), int(m.group(2)), float(m.group(3))
    mc = re.search(r"B/cell for " + _NUM + r" cells", text)
    if not mc:
        raise ValueError(f"{log_path}: no 'Coupling buffers' line")
    mu = re.search(r"Coupling loop CPU time \(user \+ system\): " + _NUM + r" s on the busiest rank", text)
    mr = re.search(r"Peak memory \(VmHWM\): " + _NUM + r" MiB on the largest rank, " + _NUM +
                   r" MiB on all (\d+) rank", text)
    stage = {}
    for label, key in (("DEM (LIGGGHTS)", "dem"), ("void fraction + mapping", "mapping"), ("exchange (MPI)", "exchange")):
        ms = re.search(r"^\s+" + re.escape(label) + r"\s+" + _NUM + r" s\s+" + _NUM + r" %\s+cpu\s+" + _NUM + r" s",
                       text, re.M)
        stage["cpu_" + key + "_s"] = float(ms.group(3)) if ms else None
    return {**stage, "particles": psteps / (steps * interval), "particle_steps": psteps, "cells": float(mc.group(1)), "cfd_steps": steps,
            "interval": interval, "air": air, "loop_s": loop_s, "cpu_max_s": float(mu.group(1)) if mu else loop_s,
            "hwm_max_mib": float(mr.group(1)) if mr else None, "ranks": int(mr.group(3)) if mr else 1}
