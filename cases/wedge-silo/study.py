#!/usr/bin/env python3
"""study.py: the wedge-silo study. For each orifice width b: one DEM-only fill
(settled on the closed shutter), then two discharge runs from that restart,
with air and without air (DEM only). Then the results tables, pictures, VTK
files and the study plots. See README.md.

    study.py [--size demo|study] [--b 5 10 15] [--runs air noair] [--out DIR]
             [--jobs 2] [--np 1] [--t-end T] [--write-interval T] [--check]

Fills and runs are independent serial jobs, --jobs of them at a time (on a
shared machine this beats one 2-rank job: the thin periodic slice gives every
rank as many ghost particles as it owns); --np N runs each discharge under
mpirun with N ranks instead (--fill-np likewise for the fills).

--check exits non-zero unless every run's particle accounting closes
exactly, the mass flow is positive, the outlet air pressure is below ambient
while discharging (runs with air) and every output file exists.
"""
import argparse
import concurrent.futures as cf
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import make_case as mc    # noqa: E402
import post               # noqa: E402


def sh(cmd, cwd, log):
    """Run cmd in cwd with its output in cwd/log/<log>.log; raise with the tail on
    failure. Returns the CPU time [s] of the command and everything it waited for
    (a load-independent measure of its cost, unlike wall time on a shared machine)."""
    os.makedirs(os.path.join(cwd, "log"), exist_ok=True)
    path = os.path.join(cwd, "log", log + ".log")
    with open(path, "w") as fh:
        proc = subprocess.Popen(cmd, cwd=cwd, stdout=fh, stderr=subprocess.STDOUT,
                                env=dict(os.environ, PWD=cwd))
        _, status, usage = os.wait4(proc.pid, 0)
        proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        with open(path) as fh:
            tail = "".join(fh.readlines()[-25:])
        raise RuntimeError(f"{' '.join(cmd)} failed in {cwd} (exit {proc.returncode}); "
                           f"last lines of {path}:\n{tail}")
    return usage.ru_utime + usage.ru_stime


def mpi(np_, cmd, parallel_flag):
    if np_ <= 1:
        return cmd
    # A waiting rank yields its core instead of spinning: on a shared machine
    # a spinning rank takes the CPU its partner needs (LIGGGHTS synchronises
    # every step); on an idle machine yielding costs next to nothing.
    os.environ.setdefault("OMPI_MCA_mpi_yield_when_idle", "1")
    return ["mpirun", "-np", str(np_)] + cmd + (["-parallel"] if parallel_flag else [])


def case_for(a, b, air):
    return mc.Case(a.size, b, air=air, s=a.s, t_end=a.t_end, write_interval=a.write_interval,
                   youngs=a.youngs, cohesion=a.cohesion, np=a.np, seed=a.seed, fill=a.fill_height)


def do_fill(a, b, work):
    d = os.path.join(work, f"b{b}", "fill")
    shutil.rmtree(d, ignore_errors=True)
    t0 = time.time()
    case = case_for(a, b, False)
    mc.write_fill(case, d)
    t1 = time.time()
    cpu = sh(mpi(a.fill_np, ["liggghts", "-in", "dem/in.fill", "-log", "log/log.liggghts",
                             "-screen", "log/screen.liggghts"], False), d, "fill")
    return dict(b=b, stage=f"b{b}_fill", packing_s=t1 - t0, run_s=time.time() - t1, run_cpu_s=cpu)


def do_run(a, b, air, work):
    name = f"b{b}_{'air' if air else 'noair'}"
    d = os.path.join(work, f"b{b}", "air" if air else "noair")
    fill = os.path.join(work, f"b{b}", "fill")
    shutil.rmtree(d, ignore_errors=True)
    t0 = time.time()
    case = case_for(a, b, air)
    mc.write_run(case, d, fill)
    if air:
        mc.write_initial_void_fraction(case, d, os.path.join(fill, "dem", "fill.dump"))
    sh(["blockMesh"], d, "blockMesh")
    if a.np > 1:
        sh(["decomposePar", "-force"], d, "decomposePar")
    t1 = time.time()
    cpu = sh(mpi(a.np, ["granairFoam"], True), d, "granairFoam")
    t2 = time.time()
    if air and a.np > 1:
        sh(["reconstructPar"], d, "reconstructPar")
    if air:
        times = ",".join(f"{t:g}" for t in post.field_times(case))
        sh(["foamToVTK", "-time", times, "-fields", "(voidfraction p U)"],
           d, "foamToVTK")
    return dict(b=b, stage=name, setup_s=t1 - t0, run_s=t2 - t1, run_cpu_s=cpu,
                post_s=time.time() - t2)


def pool(jobs, tasks, t_start):
    """Run tasks [(fn, args)] with at most `jobs` at a time; re-raise the first failure.
    Prints one line per finished task (runs take minutes each: the user sees it move)."""
    results = []
    with cf.ThreadPoolExecutor(max_workers=jobs) as ex:
        futs = [ex.submit(fn, *args) for fn, args in tasks]
        for done, f in enumerate(cf.as_completed(futs), 1):
            r = f.result()
            results.append(r)
            print(f"wedge-silo: [{done}/{len(futs)}] {r['stage']} done: {r['run_s']:.0f} s wall, "
                  f"{r['run_cpu_s']:.0f} s CPU ({time.time() - t_start:.0f} s since start)", flush=True)
    return results


def study_plots(summaries, fills, series, out, size):
    import numpy as np
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    colours = {5: "tab:blue", 10: "tab:orange", 15: "tab:green"}
    bs = sorted({s["b_mm"] for s in summaries})

    # Mass flow vs time with the Beverloo band and the Crewdson estimate.
    fig, ax = plt.subplots(figsize=(11.5, 5.5))
    for b in bs:
        c = colours.get(b, "k")
        fs = fills[b]
        lo, hi = fs["beverloo_kg_s"][1], fs["beverloo_kg_s"][0]
        ax.axhspan(lo, hi, color=c, alpha=0.15, lw=0,
                   label=f"b = {b} mm, Hagen-Beverloo, k = 1..3")
        for s in summaries:
            if s["b_mm"] != b:
                continue
            ts = series[s["name"]]
            ax.plot(ts["t"], ts["mass_flow_kg_s"], color=c, ls="-" if s["air"] else ":",
                    lw=1.6, label=f"b = {b} mm, {'with air' if s['air'] else 'DEM only'}")
        if f"b{b}_air" in series and f"b{b}_noair" in series:
            w0 = next(s["W_kg_s"] for s in summaries if s["name"] == f"b{b}_noair")
            ts = series[f"b{b}_air"]
            dpdz = post.trailing_mean(ts["t"], ts["outlet_dpdz_Pa_m"], 0.1)
            ax.plot(ts["t"], post.crewdson(w0, dpdz, fs["rho_b"]), color=c, ls="--", lw=1,
                    label=f"b = {b} mm, Crewdson: W0 sqrt(1 + (dp/dz)/(rho_b g))")
    ax.set_xlabel("time since the shutter opened [s]")
    ax.set_ylabel("mass flow rate, full 60 mm depth [kg/s]")
    ax.set_title(f"Wedge silo ({size}): mass flow; shaded: Hagen-Beverloo slot band "
                 f"(C = {post.BEVERLOO_C}, k = 1..3)", fontsize=9)
    ax.set_ylim(bottom=0)
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "mass_flow.png"), dpi=120)
    plt.close(fig)

    # Outlet pressure gradient vs time.
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for s in summaries:
        if not s["air"]:
            continue
        b = s["b_mm"]
        ts = series[s["name"]]
        rho_g = fills[b]["rho_b"] * post.G
        axes[0].plot(ts["t"], ts["outlet_dpdz_Pa_m"], color=colours.get(b, "k"), lw=0.4, alpha=0.35)
        axes[0].plot(ts["t"], post.trailing_mean(ts["t"], ts["outlet_dpdz_Pa_m"], 0.1),
                     color=colours.get(b, "k"), lw=1.8, label=f"b = {b} mm (0.1 s mean)")
        axes[0].axhline(-rho_g, color=colours.get(b, "k"), lw=0.8, ls=":")
        axes[1].plot(ts["t"], post.trailing_mean(ts["t"], ts["outlet_p_Pa"], 0.1),
                     color=colours.get(b, "k"), lw=1.8, label=f"b = {b} mm, orifice plane")
        axes[1].plot(ts["t"], post.trailing_mean(ts["t"], ts["above_p_Pa"], 0.1),
                     color=colours.get(b, "k"), lw=1.2, ls="--", label=f"b = {b} mm, about b above")
    axes[0].set_title("air pressure gradient at the orifice, dp/dz (z up); dotted: -rho_b g",
                      fontsize=9)
    axes[0].set_xlabel("time [s]")
    axes[0].set_ylabel("dp/dz [Pa/m]")
    axes[1].set_title("air pressure relative to ambient (0.1 s mean)", fontsize=9)
    axes[1].set_xlabel("time [s]")
    axes[1].set_ylabel("p [Pa]")
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "outlet_pressure_gradient.png"), dpi=120)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--size", default="demo", choices=sorted(mc.SIZES))
    ap.add_argument("--b", type=int, nargs="+", default=[5, 10, 15])
    ap.add_argument("--runs", nargs="+", default=["air", "noair"], choices=["air", "noair"])
    ap.add_argument("--out", default=os.path.join(HERE, "run"))
    ap.add_argument("--jobs", type=int, default=2, help="runs at a time")
    ap.add_argument("--np", type=int, default=1, help="MPI ranks per discharge run")
    ap.add_argument("--fill-np", type=int, default=1, help="MPI ranks per fill (plain LIGGGHTS)")
    ap.add_argument("--s", type=float, default=None, help="coarse-graining factor for every b")
    ap.add_argument("--t-end", type=float, default=None, help="discharge time [s]")
    ap.add_argument("--write-interval", type=float, default=None,
                    help="field interval [s] (default: the size's, demo 0.25, study 1)")
    ap.add_argument("--youngs", type=float, default=None)
    ap.add_argument("--cohesion", default="matched", choices=["matched", "raw", "off"])
    ap.add_argument("--fill-height", type=float, default=None)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--stage", default="all", choices=["all", "fill", "runs", "post"],
                    help="all (default); fill: the fills only; runs: the runs from existing fills, "
                         "then post-processing; post: post-process existing runs")
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args()
    out = os.path.abspath(a.out)
    work = os.path.join(out, "runs")
    res = os.path.join(out, "results")
    os.makedirs(work, exist_ok=True)
    os.makedirs(res, exist_ok=True)
    t_start = time.time()
    timings = []
    print(f"wedge-silo: size {a.size}, b = {a.b} mm, runs {a.runs}, stage {a.stage}, {a.jobs} job(s) "
          f"of {a.np} rank(s); work in {work}", flush=True)
    timing_file = os.path.join(res, "timings.json")
    if a.stage in ("all", "fill"):
        timings += pool(a.jobs, [(do_fill, (a, b, work)) for b in a.b], t_start)
        print(f"wedge-silo: fills done after {time.time() - t_start:.0f} s", flush=True)
    if a.stage in ("all", "runs"):
        print(f"wedge-silo: discharge runs started; each prints its progress (simulated time, ETA) "
              f"to {work}/b<b>/<air|noair>/log/granairFoam.log", flush=True)
        # small b first: its parcels are the smallest and its runs the longest
        tasks = [(do_run, (a, b, r == "air", work)) for b in a.b for r in a.runs]
        timings += pool(a.jobs, tasks, t_start)
        print(f"wedge-silo: runs done after {time.time() - t_start:.0f} s", flush=True)
    # stage times accumulate over invocations (e.g. --stage fill, then --stage runs)
    old = []
    if os.path.exists(timing_file):
        with open(timing_file) as fh:
            old = [t for t in json.load(fh) if t["stage"] not in {x["stage"] for x in timings}]
    timings = old + timings
    with open(timing_file, "w") as fh:
        json.dump(timings, fh, indent=1)
    if a.stage == "fill":
        return

    # Post-processing.
    import numpy as np
    fills, summaries, series = {}, [], {}
    for b in a.b:
        fill_dir = os.path.join(work, f"b{b}", "fill")
        case = case_for(a, b, False)
        fs = post.fill_stats(fill_dir, case)
        fs["beverloo_kg_s"] = [post.beverloo(case.b, case.d_primary_mean, fs["rho_b"], k)
                               for k in post.K_RANGE]
        fs["beverloo_parcel_kg_s"] = [post.beverloo(case.b, case.d_parcel_mean, fs["rho_b"], k)
                                      for k in post.K_RANGE]
        fs["case"] = case.info()
        fills[b] = fs
        for r in a.runs:
            name = f"b{b}_{r}"
            run_dir = os.path.join(work, f"b{b}", r)
            s = post.post_run(run_dir, res, name)
            if r == "air":
                vtk_src = os.path.join(run_dir, "VTK")
                if os.path.isdir(vtk_src):
                    dst = os.path.join(res, "vtk", name, "openfoam")
                    shutil.rmtree(dst, ignore_errors=True)
                    shutil.copytree(vtk_src, dst)
            summaries.append(s)
            series[name] = post.read_series(run_dir)
    # Crewdson estimate with the measured mean outlet gradient.
    for s in summaries:
        if s["air"]:
            ref = [x for x in summaries if x["b_mm"] == s["b_mm"] and not x["air"]]
            if ref:
                s["crewdson_kg_s"] = float(post.crewdson(ref[0]["W_kg_s"], s["outlet_dpdz_Pa_m"],
                                                         fills[s["b_mm"]]["rho_b"]))
    study_plots(summaries, fills, series, res, a.size)
    write_summary(summaries, fills, timings, res, time.time() - t_start, a)
    write_levels(summaries, fills, res)
    problems = check(summaries, res) if a.check else []
    print(open(os.path.join(res, "summary.txt")).read())
    if problems:
        print("wedge-silo: CHECK FAILED:\n  " + "\n  ".join(problems))
        sys.exit(1)
    if a.check:
        print("wedge-silo: checks passed")
    print(f"wedge-silo: results in {res}\n"
          f"  mass_flow.png, outlet_pressure_gradient.png   the study plots\n"
          f"  summary.txt (.csv, .json)                     rates, gradients, Beverloo band, balance, times\n"
          f"  b<b>_<air|noair>.csv                          time series (t, mass_flow_kg_s, outlet_dpdz_Pa_m, ...)\n"
          f"  b<b>_<air|noair>_fields.png, vtk/             void fraction and air pressure fields\n"
          f"  the OpenFOAM cases (open in ParaView):        {work}/b<b>/air", flush=True)


def write_summary(summaries, fills, timings, res, wall, a):
    with open(os.path.join(res, "summary.json"), "w") as fh:
        json.dump(dict(size=a.size, fills={str(k): v for k, v in fills.items()}, runs=summaries,
                       timings=timings, wall_s=wall), fh, indent=1, default=float)
    with open(os.path.join(res, "summary.csv"), "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["run", "b_mm", "air", "s", "W_kg_s", "outlet_dpdz_Pa_m", "outlet_p_Pa", "above_p_Pa",
                    "crewdson_kg_s", "beverloo_k3_kg_s", "beverloo_k1_kg_s", "rho_b_kg_m3",
                    "inserted", "present", "removed", "lost", "run_wall_s"])
        for s in summaries:
            f = fills[s["b_mm"]]
            bal = s["balance"]
            w.writerow([s["name"], s["b_mm"], int(s["air"]), f"{s['s']:.4g}", f"{s['W_kg_s']:.5g}",
                        f"{s.get('outlet_dpdz_Pa_m', 0):.5g}", f"{s.get('outlet_p_Pa', 0):.5g}",
                        f"{s.get('above_p_Pa', 0):.5g}", f"{s.get('crewdson_kg_s', float('nan')):.5g}",
                        f"{f['beverloo_kg_s'][1]:.5g}", f"{f['beverloo_kg_s'][0]:.5g}",
                        f"{f['rho_b']:.5g}", bal["inserted"], bal["present"], bal["removed"],
                        bal["lost"], f"{bal['wall_time_s']:.1f}"])
    lines = [f"wedge-silo study, size {a.size} (total wall time {wall:.0f} s)", ""]
    for b, f in sorted(fills.items()):
        c = f["case"]
        lines.append(f"b = {b} mm: s = {c['coarse_graining_factor']:.3g}, parcel d = "
                     f"{c['d_parcel_mean_m'] * 1e3:.3g} mm (b/d = {c['b_over_d_parcel']:.3g}), slice "
                     f"{c['slice_m'] * 1e3:.3g} mm (x{c['depth_scale']:.3g} to 60 mm), {f['n_parcels']} parcels; "
                     f"settled fill {f['fill_top_m'] * 1e3:.0f} mm, rho_b = {f['rho_b']:.0f} kg/m3 "
                     f"(solid fraction {f['solid_fraction']:.3f}); full 60 mm silo at d = 225 um: "
                     f"{f['full_silo_primaries_d225']:.3g} particles")
        lines.append(f"   Hagen-Beverloo (C = {post.BEVERLOO_C}, k = 1..3, primary d): "
                     f"{f['beverloo_kg_s'][1]:.4g} .. {f['beverloo_kg_s'][0]:.4g} kg/s; "
                     f"with the parcel d: {f['beverloo_parcel_kg_s'][1]:.4g} .. {f['beverloo_parcel_kg_s'][0]:.4g} kg/s")
    lines.append("")
    lines.append(f"{'run':14s} {'W [kg/s]':>10s} {'dp/dz [Pa/m]':>13s} {'p_out [Pa]':>11s} "
                 f"{'p_above [Pa]':>12s} {'Crewdson':>9s} {'balance':>22s} {'wall [s]':>9s}")
    for s in summaries:
        bal = s["balance"]
        lines.append(f"{s['name']:14s} {s['W_kg_s']:10.4g} {s.get('outlet_dpdz_Pa_m', 0):13.4g} "
                     f"{s.get('outlet_p_Pa', 0):11.4g} {s.get('above_p_Pa', 0):12.4g} "
                     f"{s.get('crewdson_kg_s', float('nan')):9.4g} "
                     f"{bal['inserted']:>7d}={bal['present']}+{bal['removed']}"
                     f"{'' if bal['closes'] else ' OPEN'} {bal['wall_time_s']:9.0f}")
    if timings:
        lines.append("")
        lines.append("Stage times: wall [s] (on this machine, at its load) and CPU [s] of the stage's processes")
        for tm in sorted(timings, key=lambda x: x["stage"]):
            lines.append(f"  {tm['stage']:14s} wall {tm['run_s']:8.0f}   cpu {tm['run_cpu_s']:8.0f}")
        lines.append(f"  total CPU {sum(tm['run_cpu_s'] for tm in timings):.0f} s")
        fills_cpu = [tm["run_cpu_s"] for tm in timings if tm["stage"].endswith("_fill")]
        runs_cpu = [tm["run_cpu_s"] for tm in timings if not tm["stage"].endswith("_fill")]
        idle = makespan(fills_cpu, a.jobs) + makespan(runs_cpu, a.jobs)
        lines.append(f"  idle-machine estimate with {a.jobs} job(s): {idle:.0f} s of runs (each job a "
                     f"full core for its CPU time), plus packing and post-processing")
    lines.append("")
    lines.append("Expectations (reported, not asserted):")
    for line in expectations(summaries, fills):
        lines.append("  " + line)
    with open(os.path.join(res, "summary.txt"), "w") as fh:
        fh.write("\n".join(lines) + "\n")


def write_levels(summaries, fills, res):
    """<name>.level.json per run: this run as a fidelity level for `./granair compare`
    (docs/fidelity-levels.md): coarse-grained DEM, with air (cg-dem-cfd) or without (cg-dem)."""
    for s in summaries:
        level = dict(case="wedge-silo", level="cg-dem-cfd" if s["air"] else "cg-dem",
                     model=f"DEM{'-CFD' if s['air'] else ''}, s = {s['s']:.3g}, {s['size']} size",
                     b_mm=s["b_mm"], air=bool(s["air"]), steady_mass_flow_kg_s=s["W_kg_s"],
                     steady_window_s=[s["steady_from_s"], s["steady_to_s"]],
                     outlet_dpdz_Pa_m=s.get("outlet_dpdz_Pa_m") if s["air"] else None,
                     wall_time_s=s["balance"]["wall_time_s"], cores=s["np"],
                     timeseries=f"{s['name']}.csv", parcels=fills[s["b_mm"]]["n_parcels"],
                     coarse_graining_factor=s["s"])
        with open(os.path.join(res, f"{s['name']}.level.json"), "w") as fh:
            json.dump(level, fh, indent=1, default=float)


def makespan(durations, jobs):
    """Wall time of tasks started in order on `jobs` slots (as the pool runs them)."""
    slots = [0.0] * max(1, jobs)
    for d in durations:
        i = slots.index(min(slots))
        slots[i] += d
    return max(slots) if durations else 0.0


def expectations(summaries, fills):
    by = {(s["b_mm"], s["air"]): s for s in summaries}
    bs = sorted({s["b_mm"] for s in summaries})
    out = []
    for b in bs:
        if (b, True) in by and (b, False) in by:
            wa, w0 = by[(b, True)]["W_kg_s"], by[(b, False)]["W_kg_s"]
            out.append(f"b = {b}: with air W {wa:.4g} {'<' if wa < w0 else '>='} without {w0:.4g} kg/s "
                       f"({100 * (wa / w0 - 1):+.1f} %) -> {'agrees' if wa < w0 else 'DISAGREES'}")
        if (b, True) in by:
            p = by[(b, True)]["above_p_Pa"]
            out.append(f"b = {b}: mean air pressure about b above the orifice {p:.3g} Pa "
                       f"-> {'below ambient, agrees' if p < 0 else 'NOT below ambient'}")
        if (b, False) in by:
            w0 = by[(b, False)]["W_kg_s"]
            lo, hi = fills[b]["beverloo_kg_s"][1], fills[b]["beverloo_kg_s"][0]
            where = "inside" if lo <= w0 <= hi else ("above" if w0 > hi else "below")
            out.append(f"b = {b}: DEM-only W {w0:.4g} kg/s is {where} the Beverloo band "
                       f"{lo:.4g}..{hi:.4g} (x{w0 / (0.5 * (lo + hi)):.2f} of its middle)")
    for air in (True, False):
        ws = [by[(b, air)]["W_kg_s"] for b in bs if (b, air) in by]
        if len(ws) > 1:
            inc = all(x < y for x, y in zip(ws, ws[1:]))
            out.append(f"{'with air' if air else 'DEM only'}: W grows with b: "
                       f"{' < '.join(f'{w:.3g}' for w in ws)} -> {'agrees' if inc else 'DISAGREES'}")
    g = [by[(b, True)]["outlet_dpdz_Pa_m"] for b in bs if (b, True) in by]
    if len(g) > 1:
        inc = all(abs(x) < abs(y) for x, y in zip(g, g[1:]))
        out.append(f"outlet |dp/dz| grows with b: {' , '.join(f'{x:.4g}' for x in g)} Pa/m -> "
                   f"{'agrees' if inc else 'DISAGREES'}")
    return out


def check(summaries, res):
    """Hard checks (the case test): accounting, positive flow, sub-ambient outlet, outputs."""
    problems = []
    for s in summaries:
        n = s["name"]
        bal = s["balance"]
        if not bal["closes"]:
            problems.append(f"{n}: accounting does not close: inserted {bal['inserted']} != present "
                            f"{bal['present']} + removed {bal['removed']} (lost {bal['lost']})")
        with open(os.path.join(res, f"{n}.csv")) as fh:
            head = next(csv.reader(fh))
        for col in ("t", "mass_flow_kg_s", "outlet_dpdz_Pa_m"):
            if col not in head:
                problems.append(f"{n}: column {col} missing from {n}.csv")
        if not s["W_kg_s"] > 0:
            problems.append(f"{n}: steady mass flow is {s['W_kg_s']} kg/s, expected > 0")
        if s["air"] and not s["outlet_p_mean_discharging_Pa"] < 0:
            problems.append(f"{n}: mean outlet air pressure while discharging "
                            f"{s['outlet_p_mean_discharging_Pa']:.4g} Pa, expected < 0 (below ambient)")
        if not s.get("png") or not os.path.exists(s["png"]):
            problems.append(f"{n}: field picture missing")
        for t in s["field_times"]:
            if not os.path.exists(os.path.join(res, "vtk", n, f"{n}_cells_t{t:g}.vtk")):
                problems.append(f"{n}: VTK file for t = {t:g} s missing")
        if 0 not in s["field_times"]:
            problems.append(f"{n}: no fields at t = 0")
        if s["air"] and not os.path.isdir(os.path.join(res, "vtk", n, "openfoam")):
            problems.append(f"{n}: foamToVTK output missing")
    for f in ("mass_flow.png", "outlet_pressure_gradient.png", "summary.csv"):
        if not os.path.exists(os.path.join(res, f)):
            problems.append(f"{f} missing")
    return problems


if __name__ == "__main__":
    main()
