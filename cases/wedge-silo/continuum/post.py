#!/usr/bin/env python3
"""post.py: post-processing of the continuum wedge-silo runs (numpy + matplotlib).

    post.py run RUN_DIR OUT_DIR --name b10_air --wall-time S [--cores N] [--check]
    post.py summary OUT_DIR [--check]

`run` reads RUN_DIR/postProcessing/timeSeries.csv (granairContinuumFoam,
cfd-side/continuum/PowderBalance.H; full 60 mm depth: the mesh is one cell of
the whole depth) and RUN_DIR/silo.json (mesh.py) and writes into OUT_DIR:
  timeseries.csv  t, mass_flow_kg_s[, outlet_dpdz_Pa_m]: 10 ms means (the
                  per-step outlet flux can oscillate from step to step, as in
                  cases/mcc-hopper; the mean over each window is the time integral
                  of the per-step values over the window length); no
                  third column for dry runs
  level.json      the level contract of helper-brief-3 (case wedge-silo,
                  level continuum)
  fields.png      powder fraction (and air pressure) at t = 0 and the end
The steady window is the DEM case's (cases/wedge-silo/post.py): from
min(0.3 s, t1/2) to t1, t1 the time half of the fill has left (or the end);
the steady mass flow is the least-squares slope of the discharged mass in it,
the outlet dp/dz the time mean of the per-step values in it.

--check (run) exits 1 unless:
  - every value of the time series is finite;
  - the powder mass balance closes within 0.5 %: |m(end) + m_out(end) - m(0)|/m(0)
    <= 0.005 with m_out the time integral of the outlet flow recomputed here,
    and the solver's own mass_balance_error column (all boundaries) too;
  - the steady mass flow is > 0;
  - with air: the outlet dp/dz mean is finite and the pore air is below
    ambient while discharging (mean of the lowest air pressure over the steady
    window < 0; the outlet face itself is held at ambient, p_air = 0).

`summary` collects OUT_DIR/*/level.json into OUT_DIR/summary.csv (with the
DEM-CFD demo rates of ../reference-demo/summary.csv) and plots
mass_flow.png and outlet_pressure_gradient.png across the runs.
"""
import argparse
import csv
import glob
import json
import math
import os
import re
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt   # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DEM_SUMMARY = os.path.join(os.path.dirname(HERE), "reference-demo", "summary.csv")
STEADY_FROM = 0.3      # s, as cases/wedge-silo/post.py
WINDOW = 0.01          # s, averaging window of timeseries.csv
TOLERANCE = 0.005      # mass balance, relative


def read_series(run_dir):
    path = os.path.join(run_dir, "postProcessing", "timeSeries.csv")
    with open(path) as fh:
        rows = list(csv.reader(fh))
    if len(rows) < 3:
        sys.exit(f"post.py: {path} has {len(rows) - 1} rows, expected at least 2")
    data = np.array([[float(v) for v in r] for r in rows[1:]])
    return {h: data[:, i] for i, h in enumerate(rows[0])}


def air_text(silo):
    if silo.get("rheology", "muI") == "muI":
        return "Darcy-Ergun air, packing relaxing to phi(I) (span %.3g)" % (silo["phi_max"] - silo["phi_min"])
    return "Darcy-Ergun air, packing relaxing to the closure's c"


def window_means(t, dt, values, width):
    """Time means of per-step values over consecutive windows of `width` s:
    (window centres, means). Step i covers (t[i] - dt[i], t[i]]. A last window
    shorter than width/2 is dropped."""
    centres, means = [], []
    start, acc, span = 0.0, np.zeros(len(values)), 0.0
    for i in range(len(t)):
        acc += np.array([v[i] for v in values]) * dt[i]
        span += dt[i]
        if t[i] >= start + width or i == len(t) - 1:
            if span > 0.5 * width:   # a last, shorter window of a few steps is left out
                centres.append(start + 0.5 * span)
                means.append(acc / span)
            start, acc, span = t[i], np.zeros(len(values)), 0.0
    return np.array(centres), np.array(means)


def read_internal(path, n):
    """internalField of an ASCII OpenFOAM volScalarField (uniform or nonuniform)."""
    with open(path) as fh:
        text = fh.read()
    m = re.search(r"internalField\s+uniform\s+([-+\deE.]+)", text)
    if m:
        return np.full(n, float(m.group(1)))
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(", text)
    vals = np.array(text[m.end():text.index(")", m.end())].split()[:int(m.group(1))], dtype=float)
    return vals


def time_dirs(run_dir):
    out = []
    for name in os.listdir(run_dir):
        try:
            out.append((float(name), os.path.join(run_dir, name)))
        except ValueError:
            pass
    return sorted(out)


def plot_fields(run_dir, silo, name, path):
    """Powder fraction (and air pressure) at t = 0 and the last written time,
    cell centres from `postProcess -func writeCellCentres` (0/Cx, 0/Cz)."""
    if not os.path.exists(os.path.join(run_dir, "0", "Cx")):
        return None
    n = silo["cells"]
    cx = read_internal(os.path.join(run_dir, "0", "Cx"), n) * 1e3
    cz = read_internal(os.path.join(run_dir, "0", "Cz"), n) * 1e3
    times = time_dirs(run_dir)
    picks = [times[0], times[-1]] if len(times) > 1 else times
    air = silo["air"]
    rows = 2 if air else 1
    fig, axes = plt.subplots(rows, len(picks), squeeze=False, figsize=(2.4 * len(picks) + 1.5, 4.2 * rows))
    ztop = (silo["fill_height_m"] + 0.02) * 1e3
    for j, (t, d) in enumerate(picks):
        a = read_internal(os.path.join(d, "alpha.powder"), n)
        sc = axes[0][j].scatter(cx, cz, c=a, s=9, marker="s", cmap="viridis", vmin=0, vmax=1)
        axes[0][j].set_title(f"t = {t:.3g} s", fontsize=9)
        if air:
            pa_path = os.path.join(d, "p_air")
            pa = read_internal(pa_path, n) if os.path.exists(pa_path) else np.zeros(n)
            lim = max(1.0, float(np.percentile(np.abs(pa), 99)))
            sp = axes[1][j].scatter(cx, cz, c=pa, s=9, marker="s", cmap="RdBu_r", vmin=-lim, vmax=lim)
            fig.colorbar(sp, ax=axes[1][j], fraction=0.08, label="air pressure - ambient [Pa]")
            if j > 0:
                axes[1][j].set_title("air pressure of the last step", fontsize=8)
    fig.colorbar(sc, ax=list(axes[0]), fraction=0.05, label="powder fraction alpha")
    for ax in axes.flat:
        ax.set_xlim(-22.5, 22.5)
        ax.set_ylim(0, ztop)
        ax.set_aspect("equal")
        ax.set_xlabel("x [mm]", fontsize=8)
        ax.tick_params(labelsize=7)
    axes[0][0].set_ylabel("z [mm]", fontsize=8)
    fig.suptitle(f"{name}: continuum mu(I), b = {silo['b_mm']} mm", fontsize=10)
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def post_run(a):
    s = read_series(a.run_dir)
    with open(os.path.join(a.run_dir, "silo.json")) as fh:
        silo = json.load(fh)
    air = silo["air"]
    t = s["t"]
    dt = np.diff(np.concatenate([[0.0], t]))
    flow = s["mass_flow_kg_s"]
    out_mass = np.cumsum(flow * dt)
    initial = s["powder_mass_kg"][0]
    finite = all(np.all(np.isfinite(v)) for v in s.values())
    balance = (s["powder_mass_kg"][-1] + out_mass[-1] - initial) / initial
    solver_balance = float(np.max(np.abs(s["mass_balance_error"])))

    half = np.nonzero(out_mass >= 0.5 * initial)[0]
    t1 = float(t[half[0]]) if half.size else float(t[-1])
    t0 = min(STEADY_FROM, 0.5 * t1)
    sel = (t >= t0) & (t <= t1)
    w_steady = float(np.polyfit(t[sel], out_mass[sel], 1)[0]) if sel.sum() >= 3 else float("nan")
    dpdz = pmin = dpdz_sd = None
    if air:
        dpdz = float(np.sum(s["outlet_dpdz_Pa_m"][sel] * dt[sel]) / np.sum(dt[sel]))
        # spread of the per-step values about that mean: a check on step-to-step
        # noise (before the packing relaxation of AirPercolation they alternated
        # in sign, README "Continuum fidelity")
        dpdz_sd = float(np.sqrt(np.sum((s["outlet_dpdz_Pa_m"][sel] - dpdz) ** 2 * dt[sel]) / np.sum(dt[sel])))
        pmin = float(np.sum(s["air_p_min_Pa"][sel] * dt[sel]) / np.sum(dt[sel]))

    os.makedirs(a.out_dir, exist_ok=True)
    cols = [flow] + ([s["outlet_dpdz_Pa_m"]] if air else [])
    wc, wm = window_means(t, dt, cols, WINDOW)
    with open(os.path.join(a.out_dir, "timeseries.csv"), "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["t", "mass_flow_kg_s"] + (["outlet_dpdz_Pa_m"] if air else []))
        for c, m in zip(wc, wm):
            w.writerow([f"{c:.6g}"] + [f"{v:.6g}" for v in m])
    rheology = (f"mu(I) (mu_s {silo['mu_s']:.3f}, mu_2 {silo['mu_2']:.3f}, I0 {silo['I0']:g})"
                if silo.get("rheology", "muI") == "muI" else "Latz-Schmidt (lactose calibration of case A)")
    model = (f"{rheology}, VOF, "
             f"{'free-slip' if silo['walls'] == 'slip' else 'no-slip'} walls, "
             f"{air_text(silo) if air else 'no air'}, plane mesh N = {silo['mesh_n']} "
             f"({silo['cells']} cells), full 60 mm depth")
    level = {"case": "wedge-silo", "level": "continuum", "model": model, "b_mm": silo["b_mm"], "air": air,
             "steady_mass_flow_kg_s": w_steady, "steady_window_s": [t0, t1],
             "outlet_dpdz_Pa_m": dpdz, "wall_time_s": a.wall_time, "cores": a.cores,
             "timeseries": "timeseries.csv"}
    with open(os.path.join(a.out_dir, "level.json"), "w") as fh:
        json.dump(level, fh, indent=1)
        fh.write("\n")
    cpu = None
    log = os.path.join(a.run_dir, "log", "granairContinuumFoam.log")
    if os.path.exists(log):
        with open(log) as fh:
            found = re.findall(r"ExecutionTime = ([\d.eE+-]+) s", fh.read())
        cpu = float(found[-1]) if found else None
    extra = dict(initial_powder_kg=initial, solver_cpu_time_s=cpu, final_powder_kg=float(s["powder_mass_kg"][-1]),
                 discharged_outlet_kg=float(out_mass[-1]), mass_balance_error=float(balance),
                 solver_mass_balance_error_max=solver_balance, t_end_s=float(t[-1]), steps=len(t),
                 air_p_min_window_mean_Pa=pmin, outlet_dpdz_step_sd_Pa_m=dpdz_sd, all_finite=bool(finite))
    with open(os.path.join(a.out_dir, "details.json"), "w") as fh:
        json.dump(extra, fh, indent=1)
        fh.write("\n")
    plot_fields(a.run_dir, silo, a.name, os.path.join(a.out_dir, "fields.png"))
    print(f"wedge-silo continuum {a.name}: W = {w_steady:.4g} kg/s over [{t0:.3g}, {t1:.3g}] s"
          + (f", outlet dp/dz {dpdz:.4g} Pa/m, min air p {pmin:.4g} Pa" if air else "")
          + f"; balance {balance:.1e} (solver {solver_balance:.1e}); {len(t)} steps, {a.wall_time:g} s")

    if a.check:
        fails = []
        if not finite:
            fails.append("non-finite values in timeSeries.csv")
        if not abs(balance) <= TOLERANCE:
            fails.append(f"mass balance error {balance:.3e} exceeds {TOLERANCE}")
        if not solver_balance <= TOLERANCE:
            fails.append(f"solver mass balance error {solver_balance:.3e} exceeds {TOLERANCE}")
        if not w_steady > 0:
            fails.append(f"steady mass flow {w_steady} kg/s is not > 0")
        if air and not math.isfinite(dpdz):
            fails.append(f"outlet dp/dz {dpdz} is not finite")
        if air and not pmin < 0:
            fails.append(f"pore air not below ambient while discharging (mean min air p {pmin} Pa)")
        if fails:
            print(f"wedge-silo continuum check FAILED ({a.name}): " + "; ".join(fails), file=sys.stderr)
            sys.exit(1)
        print(f"wedge-silo continuum check passed ({a.name}): |balance| {abs(balance):.1e} <= {TOLERANCE}, "
              f"W {w_steady:.4g} kg/s > 0" + (f", dp/dz finite, min air p {pmin:.3g} Pa < 0" if air else ""))


def dem_rates():
    out = {}
    if os.path.exists(DEM_SUMMARY):
        with open(DEM_SUMMARY) as fh:
            for r in csv.DictReader(fh):
                out[(int(r["b_mm"]), r["air"] == "1")] = (float(r["W_kg_s"]), float(r["outlet_dpdz_Pa_m"]))
    return out


def summary(a):
    runs = []
    for path in sorted(glob.glob(os.path.join(a.out_dir, "*", "level.json"))):
        with open(path) as fh:
            lv = json.load(fh)
        lv["dir"] = os.path.dirname(path)
        with open(os.path.join(lv["dir"], "details.json")) as fh:
            lv["details"] = json.load(fh)
        runs.append(lv)
    if not runs:
        sys.exit(f"post.py summary: no */level.json under {a.out_dir}")
    runs.sort(key=lambda r: (r["b_mm"], not r["air"]))
    dem = dem_rates()
    with open(os.path.join(a.out_dir, "summary.csv"), "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["run", "b_mm", "air", "W_kg_s", "outlet_dpdz_Pa_m", "dpdz_step_sd_Pa_m", "window_t0_s",
                    "window_t1_s",
                    "W_demo_dem_cfd_kg_s", "W_over_dem", "dpdz_demo_dem_cfd_Pa_m", "wall_time_s"])
        for r in runs:
            wd, pd = dem.get((r["b_mm"], r["air"]), (float("nan"), float("nan")))
            w.writerow([os.path.basename(r["dir"]), r["b_mm"], int(r["air"]), f"{r['steady_mass_flow_kg_s']:.5g}",
                        "" if r["outlet_dpdz_Pa_m"] is None else f"{r['outlet_dpdz_Pa_m']:.5g}",
                        "" if not r["details"].get("outlet_dpdz_step_sd_Pa_m") else
                        f"{r['details']['outlet_dpdz_step_sd_Pa_m']:.3g}",
                        f"{r['steady_window_s'][0]:.3g}", f"{r['steady_window_s'][1]:.3g}",
                        f"{wd:.5g}", f"{r['steady_mass_flow_kg_s'] / wd:.3g}", f"{pd:.5g}" if r["air"] else "",
                        f"{r['wall_time_s']:.0f}"])
    colours = {5: "tab:blue", 10: "tab:orange", 15: "tab:green"}
    fig, ax = plt.subplots(figsize=(7, 4.2))
    fig2, ax2 = plt.subplots(figsize=(7, 4.2))
    for r in runs:
        with open(os.path.join(r["dir"], r["timeseries"])) as fh:
            rows = list(csv.DictReader(fh))
        t = np.array([float(x["t"]) for x in rows])
        c = colours.get(r["b_mm"], "k")
        ls = "-" if r["air"] else "--"
        lab = f"b = {r['b_mm']} mm, {'air' if r['air'] else 'no air'}"
        ax.plot(t, [float(x["mass_flow_kg_s"]) for x in rows], color=c, ls=ls, lw=1, label=lab)
        ax.hlines(r["steady_mass_flow_kg_s"], *r["steady_window_s"], colors=c, linestyles=":", lw=1.5)
        if r["air"]:
            ax2.plot(t, [float(x["outlet_dpdz_Pa_m"]) for x in rows], color=c, lw=0.8, label=lab)
            ax2.hlines(r["outlet_dpdz_Pa_m"], *r["steady_window_s"], colors=c, linestyles=":", lw=1.5)
    for (b, airflag), (wd, pd) in sorted(dem.items()):
        if any(r["b_mm"] == b for r in runs):
            ax.plot([0.05], [wd], marker="o" if airflag else "s", color=colours.get(b, "k"), ms=5, ls="none",
                    mfc="none" if not airflag else colours.get(b, "k"))
            if airflag:
                ax2.plot([0.05], [pd], marker="o", color=colours.get(b, "k"), ms=5, ls="none")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("powder mass flow, 60 mm depth [kg/s]")
    ax.set_title("wedge silo, continuum mu(I) (10 ms means; dotted: steady means;\n"
                 "markers at t = 0.05: DEM-CFD demo rates, filled with air, open without)", fontsize=9)
    ax.legend(fontsize=7)
    ax.set_ylim(bottom=0)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out_dir, "mass_flow.png"), dpi=120)
    ax2.set_xlabel("t [s]")
    ax2.set_ylabel("outlet air dp/dz [Pa/m]")
    ax2.set_title("outlet air pressure gradient (10 ms means; dotted: steady means;\n"
                  "markers: DEM-CFD demo means)", fontsize=9)
    ax2.axhline(0, color="k", lw=0.5)
    ax2.legend(fontsize=7)
    fig2.tight_layout()
    fig2.savefig(os.path.join(a.out_dir, "outlet_pressure_gradient.png"), dpi=120)
    with open(os.path.join(a.out_dir, "summary.csv")) as fh:
        print(fh.read(), end="")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run")
    r.add_argument("run_dir")
    r.add_argument("out_dir")
    r.add_argument("--name", required=True)
    r.add_argument("--wall-time", type=float, required=True)
    r.add_argument("--cores", type=int, default=1)
    r.add_argument("--check", action="store_true")
    su = sub.add_parser("summary")
    su.add_argument("out_dir")
    a = ap.parse_args()
    post_run(a) if a.cmd == "run" else summary(a)


if __name__ == "__main__":
    main()
