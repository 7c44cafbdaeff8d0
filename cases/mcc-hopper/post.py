#!/usr/bin/env python3
"""post.py: mass flow of one continuum MCC hopper run against Beverloo.

Usage: post.py RUN_DIR OUT_DIR [--steady-from T] [--check] [--label TEXT]
               [--model TEXT --wall-s S --cores N]
               [--bulk-density RHO --particle-diameter D --material TEXT]
               [--temperature-floor TMIN]

Reads RUN_DIR/postProcessing/timeSeries.csv (written by granairContinuumFoam,
cfd-side/continuum/PowderBalance.H) and writes
  OUT_DIR/mass_flow.csv   t [s], mass_flow_kg_s: the outlet mass flow averaged
                          over consecutive 10 ms windows (the outlet flux of
                          each solver step times its step, summed per window,
                          over the window length; the per-step value carries
                          a step-to-step oscillation that this removes)
  OUT_DIR/mass_flow.png   that flow against time with the Beverloo band
  OUT_DIR/summary.txt     key = value lines (steady mass flow, balance error, ...)
  OUT_DIR/level.json      (unless --no-level-json) this run as the continuum level of `./granair compare`
                          (docs/fidelity-levels.md); with air, mass_flow.csv and
                          level.json also carry the outlet air pressure gradient

The steady mass flow is the slope of the discharged outlet mass over
[steady-from, end] (least squares), i.e. the mean flow in that window.

--check exits 1 unless (tolerances from issue 8):
  - every value in the time series is finite (no NaN/inf);
  - the powder mass balance closes within 0.5 %:
        |(m_domain(end) + m_out(end) - m_domain(0)) / m_domain(0)| <= 0.005,
    m_out the time integral of the outlet flow recomputed here (so powder
    leaving through any other boundary counts as a balance error), and the
    solver's own mass_balance_error column (all boundaries) too;
  - the initial powder mass is the 1000 g fill of Remmelgas et al. within
    0.5 % (the fill is set by cases/mcc-hopper/mesh.py);
  - the steady mass flow is > 0;
  - with --temperature-floor TMIN (rheology latzSchmidt, ASCII fields): every
    written granular temperature T (all time directories > 0, serial or
    processor*/) is finite and >= TMIN (to the 10 written digits).
--bulk-density and --particle-diameter (default MCC: 900 kg/m3, 660 um) set
the Beverloo band; the fill is 1000 g whatever the density (mesh.py).
"""
import argparse
import csv
import glob
import json
import math
import os
import re
import sys

# Beverloo et al. (1961), circular orifice: W = C rho_b sqrt(g) (D - k d)^2.5
C_BEVERLOO = 0.58
K_RANGE = (1.0, 3.0)
RHO_BULK = 900.0     # kg/m3, VIVAPUR MCC Spheres 500 (reference case B)
D_OUTLET = 0.025     # m
D_PARTICLE = 660e-6  # m
G = 9.81             # m/s2
FILL_MASS = 1.0      # kg
TOLERANCE = 0.005    # mass balance and fill, relative
WINDOW = 0.01        # s, averaging window of mass_flow.csv


def beverloo(k, rho_bulk=RHO_BULK, d_particle=D_PARTICLE):
    return C_BEVERLOO * rho_bulk * math.sqrt(G) * (D_OUTLET - k * d_particle) ** 2.5


def temperature_values(run):
    """All cell values of the written granular temperature fields T (ASCII) of RUN, time > 0."""
    dirs = [run] + sorted(d for d in glob.glob(os.path.join(run, "processor*")) if os.path.isdir(d))
    values, files = [], []
    for base in dirs:
        for path in glob.glob(os.path.join(base, "*", "T")):
            try:
                if float(os.path.basename(os.path.dirname(path))) <= 0:
                    continue
            except ValueError:
                continue
            text = open(path).read()
            m = re.search(r"internalField\s+uniform\s+([^;]+);", text)
            if m:
                values.append(float(m.group(1)))
            else:
                m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\((.*?)\)\s*;", text, re.S)
                if not m:
                    sys.exit(f"post.py: cannot read the internalField of {path} (expected ASCII)")
                cells = [float(v) for v in m.group(2).split()]
                if len(cells) != int(m.group(1)):
                    sys.exit(f"post.py: {path} lists {len(cells)} values, header says {m.group(1)}")
                values += cells
            files.append(path)
    return values, files


def read_series(path):
    with open(path) as fh:
        rows = list(csv.DictReader(fh))
    if len(rows) < 2:
        sys.exit(f"post.py: {path} has {len(rows)} rows, expected at least 2")
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def least_squares_slope(x, y):
    n = len(x)
    mx, my = sum(x) / n, sum(y) / n
    sxx = sum((a - mx) ** 2 for a in x)
    if sxx == 0:
        return float("nan")
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sxx


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run")
    ap.add_argument("out")
    ap.add_argument("--steady-from", type=float, default=0.5)
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--label", default="granairContinuumFoam")
    ap.add_argument("--model", default="mu(I)", help="level.json: short description of the run")
    ap.add_argument("--wall-s", type=float, default=float("nan"), help="level.json: wall time of the run [s]")
    ap.add_argument("--cores", type=int, default=1, help="level.json: MPI ranks of the run")
    ap.add_argument("--bulk-density", type=float, default=RHO_BULK, help="Beverloo: bulk density [kg/m3]")
    ap.add_argument("--particle-diameter", type=float, default=D_PARTICLE, help="Beverloo: particle diameter [m]")
    ap.add_argument("--material", default="MCC", help="plot title: the material of the run")
    ap.add_argument("--temperature-floor", type=float, default=None,
                    help="latzSchmidt: check T >= this floor [m2/s2] in every written field")
    ap.add_argument("--no-level-json", action="store_true",
                    help="write no level.json (Allrun --rheology latzSchmidt: another material's closure on this "
                         "geometry is a solver test, not a level of the MCC comparison)")
    args = ap.parse_args()

    s = read_series(os.path.join(args.run, "postProcessing", "timeSeries.csv"))
    t, flow, mass = s["t"], s["mass_flow_kg_s"], s["powder_mass_kg"]
    finite = all(math.isfinite(v) for col in s.values() for v in col)

    # Outlet mass passed up to each row: the flow of step i acts over (t[i-1], t[i]].
    # Row 0 is the first step, taken from t = 0.
    out_mass = []
    acc = 0.0
    for i in range(len(t)):
        acc += flow[i] * (t[i] - (t[i - 1] if i > 0 else 0.0))
        out_mass.append(acc)
    initial = mass[0] + out_mass[0]
    balance = (mass[-1] + out_mass[-1] - initial) / initial
    solver_balance = max(abs(v) for v in s["mass_balance_error"])
    fill_error = (initial - FILL_MASS) / FILL_MASS

    # 10 ms window means (flow from the outlet mass; air gradient as a time mean).
    dpdz = s.get("outlet_dpdz_Pa_m")
    win_t, win_w, win_g = [], [], []
    start, i0 = 0.0, 0
    for i in range(len(t)):
        if t[i] >= start + WINDOW or i == len(t) - 1:
            prev = out_mass[i0 - 1] if i0 > 0 else 0.0
            t_prev = t[i0 - 1] if i0 > 0 else 0.0
            if t[i] > t_prev:
                win_t.append(0.5 * (t_prev + t[i]))
                win_w.append((out_mass[i] - prev) / (t[i] - t_prev))
                if dpdz is not None:
                    win_g.append(sum(dpdz[j] * (t[j] - (t[j - 1] if j > 0 else 0.0)) for j in range(i0, i + 1))
                                 / (t[i] - t_prev))
            start, i0 = t[i], i + 1

    steady = [(a, b) for a, b in zip(t, out_mass) if a >= args.steady_from]
    if len(steady) >= 2:
        w_steady = least_squares_slope([a for a, _ in steady], [b for _, b in steady])
        w_sd = math.sqrt(sum((w - w_steady) ** 2 for a, w in zip(win_t, win_w) if a >= args.steady_from)
                         / max(1, sum(1 for a in win_t if a >= args.steady_from)))
    else:
        w_steady, w_sd = float("nan"), float("nan")
    bev_hi = beverloo(K_RANGE[0], args.bulk_density, args.particle_diameter)
    bev_lo = beverloo(K_RANGE[1], args.bulk_density, args.particle_diameter)
    t_values, t_files = temperature_values(args.run) if args.temperature_floor is not None else ([], [])

    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "mass_flow.csv"), "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["t", "mass_flow_kg_s"] + (["outlet_dpdz_Pa_m"] if dpdz is not None else []))
        for i, (a, b) in enumerate(zip(win_t, win_w)):
            w.writerow([f"{a:.6g}", f"{b:.6g}"] + ([f"{win_g[i]:.6g}"] if dpdz is not None else []))
    dpdz_steady = None
    if dpdz is not None:
        sel = [(t[j] - (t[j - 1] if j > 0 else 0.0), dpdz[j]) for j in range(len(t)) if t[j] >= args.steady_from]
        dpdz_steady = sum(a * b for a, b in sel) / sum(a for a, _ in sel) if sel else float("nan")
    if not args.no_level_json:
        with open(os.path.join(args.out, "level.json"), "w") as fh:
            json.dump({"case": "mcc-hopper", "level": "continuum", "model": args.model, "b_mm": D_OUTLET * 1e3,
                       "air": dpdz is not None, "steady_mass_flow_kg_s": w_steady,
                       "steady_window_s": [args.steady_from, t[-1]], "outlet_dpdz_Pa_m": dpdz_steady,
                       "wall_time_s": args.wall_s, "cores": args.cores, "timeseries": "mass_flow.csv"},
                      fh, indent=1)
    summary = {
        "t_end_s": t[-1],
        "steady_from_s": args.steady_from,
        "steady_mass_flow_kg_s": w_steady,
        "window_mass_flow_sd_kg_s": w_sd,
        "beverloo_k3_kg_s": bev_lo,
        "beverloo_k1_kg_s": bev_hi,
        "steady_over_beverloo_k1": w_steady / bev_hi,
        "initial_powder_kg": initial,
        "fill_error": fill_error,
        "final_powder_kg": mass[-1],
        "discharged_outlet_kg": out_mass[-1],
        "mass_balance_error": balance,
        "solver_mass_balance_error_max": solver_balance,
        "all_finite": int(finite),
    }
    if args.temperature_floor is not None:
        summary.update({
            "temperature_fields": len(t_files),
            "temperature_min_m2_s2": min(t_values) if t_values else float("nan"),
            "temperature_max_m2_s2": max(t_values) if t_values else float("nan"),
        })
    with open(os.path.join(args.out, "summary.txt"), "w") as fh:
        for k, v in summary.items():
            fh.write(f"{k} = {v:.6g}\n" if isinstance(v, float) else f"{k} = {v}\n")
    print(f"mcc-hopper: steady mass flow {w_steady:.4g} kg/s (t >= {args.steady_from} s; sd of 10 ms means "
          f"{w_sd:.2g}); Beverloo {bev_lo:.4g}-{bev_hi:.4g} kg/s (k = 3..1); mass balance error {balance:.2e} "
          f"(solver max {solver_balance:.1e}); initial {initial:.6g} kg")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4))
        ax.axhspan(bev_lo, bev_hi, color="tab:orange", alpha=0.3,
                   label=f"Beverloo, C = {C_BEVERLOO}, k = 1..3")
        ax.plot(win_t, win_w, color="tab:blue", lw=1, label=f"{args.label} (10 ms means)")
        if math.isfinite(w_steady):
            ax.hlines(w_steady, args.steady_from, t[-1], colors="k", linestyles="--",
                      label=f"mean for t >= {args.steady_from:g} s: {w_steady * 1e3:.1f} g/s")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("powder mass flow [kg/s]")
        ax.set_ylim(0, max(1.3 * bev_hi, 1.1 * max(win_w + [0.0])))
        ax.set_title(f"{args.material}, D_o = 25 mm, 1000 g fill", fontsize=9)
        ax.legend(loc="upper right", fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(args.out, "mass_flow.png"), dpi=120)
    except ImportError as e:  # plotting is a convenience; the checks below still run
        print(f"post.py: no plot ({e}); use $GRANAIR_PYTHON (Debian python3 with matplotlib)", file=sys.stderr)

    if args.check:
        failures = []
        if not finite:
            failures.append("non-finite values in timeSeries.csv")
        if not abs(balance) <= TOLERANCE:
            failures.append(f"mass balance error {balance:.3e} exceeds {TOLERANCE}")
        if not solver_balance <= TOLERANCE:
            failures.append(f"solver mass balance error {solver_balance:.3e} exceeds {TOLERANCE}")
        if not abs(fill_error) <= TOLERANCE:
            failures.append(f"initial powder {initial:.6g} kg differs from the {FILL_MASS} kg fill by {fill_error:.3e}")
        if not w_steady > 0:
            failures.append(f"steady mass flow {w_steady} kg/s is not > 0")
        if args.temperature_floor is not None:
            # Written with 10 significant digits: allow that rounding below the floor.
            floor = args.temperature_floor * (1 - 1e-9)
            if not t_files:
                failures.append("no granular temperature field T written (time > 0)")
            elif not all(math.isfinite(v) and v >= floor for v in t_values):
                bad = [v for v in t_values if not (math.isfinite(v) and v >= floor)]
                failures.append(f"{len(bad)} granular temperature values not finite or below "
                                f"{args.temperature_floor} m2/s2, e.g. {bad[0]}")
        if failures:
            print("mcc-hopper check FAILED: " + "; ".join(failures), file=sys.stderr)
            sys.exit(1)
        print(f"mcc-hopper check passed: |balance| {abs(balance):.2e} <= {TOLERANCE}, fill {fill_error:.2e}, "
              f"steady mass flow {w_steady:.4g} kg/s > 0"
              + (f", T in [{min(t_values):.3g}, {max(t_values):.3g}] m2/s2 >= {args.temperature_floor:g} "
                 f"({len(t_files)} fields)" if args.temperature_floor is not None else ""))


if __name__ == "__main__":
    main()
