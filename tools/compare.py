#!/usr/bin/env python3
"""compare.py: every fidelity level of one case at one orifice size, side by side.

    ./granair compare CASE_DIR [--b MM] [--run LEVEL ...|all] [--from DIR ...] [--out DIR]

Levels (docs/fidelity-levels.md): closed-form (Beverloo / Hagen-Beverloo and
Carleton's air-impeded estimate, computed here; Janssen's shaft wall pressure
for a case whose compare.json has a `janssen` block), continuum
(granairContinuumFoam), cg-dem and cg-dem-cfd (coarse-grained DEM without and
with air, granairFoam), dem-cfd (unscaled particles, where it was run).

The case folder's compare.json holds the closed-form inputs, where each level
writes its results and the command that produces them. Each run writes a
`level.json` (or `<name>.level.json`) next to its time series; this script
collects those under the case's result folders (committed references
included), `--from` folders and its own `--run` output, and writes to --out
(default CASE_DIR/compare/b<MM>):
    compare.csv, compare.md   level, model, air, steady mass flow, outlet dp/dz,
                              wall time, cores (+ W over the Beverloo middle,
                              the Crewdson check, the source folder, and the
                              grid convergence index of a level whose
                              level.json carries a 'mesh_study')
    mass_flow.png             mass flow vs time of every level with a time
                              series, the Beverloo band and the Carleton estimate
    outlet_dpdz.png           outlet air pressure gradient vs time (runs with air)
    fill_level.png            mass flow and outlet dp/dz against the fill level (the bed
                              height above the orifice), for the levels whose time
                              series has a fill_level_m column (whole-discharge runs)
Without --run nothing is simulated: levels with no results are listed with
the command that would produce them. --run LEVEL runs that level's command
first (its output under OUT/runs/), --run all every level the case can run.
"""
import argparse
import csv
import glob
import json
import math
import os
import subprocess
import sys
import time

from granair_cases import CaseError as CompareError, closed_forms as cf, levels, plots, series as ts

LEVELS = levels.LEVELS


# ------------------------------------------------------------------ inputs
def load_spec(case_dir):
    path = os.path.join(case_dir, "compare.json")
    if not os.path.exists(path):
        raise CompareError(f"{path}: not found (a comparable case folder has a compare.json)")
    with open(path) as fh:
        try:
            spec = json.load(fh)
        except json.JSONDecodeError as e:
            raise CompareError(f"{path}: not valid JSON ({e})")

    def need(d, key, where, kind=None):
        if key not in d:
            raise CompareError(f"{path}: key '{where}{key}' missing")
        if kind is not None and not isinstance(d[key], kind):
            raise CompareError(f"{path}: key '{where}{key}' must be {kind.__name__ if isinstance(kind, type) else 'a number'}, "
                               f"got {d[key]!r}")
        return d[key]

    num = (int, float)
    need(spec, "case", "", str)
    orifice = need(spec, "orifice", "", str)
    if orifice not in ("slot", "circular"):
        raise CompareError(f"{path}: key 'orifice' must be 'slot' or 'circular', got {orifice!r}")
    if orifice == "slot":
        need(spec, "slot_length_m", "", num)
    for key in ("hopper_half_angle_deg", "d_m", "rho_p", "rho_b"):
        if not need(spec, key, "", num) > 0:
            raise CompareError(f"{path}: key '{key}' must be > 0, got {spec[key]}")
    air = need(spec, "air", "", dict)
    need(air, "rho", "air.", num)
    need(air, "mu", "air.", num)
    bev = need(spec, "beverloo", "", dict)
    need(bev, "C", "beverloo.", num)
    k = need(bev, "k", "beverloo.", list)
    if len(k) != 2:
        raise CompareError(f"{path}: key 'beverloo.k' must be [k_min, k_max], got {k!r}")
    need(spec, "b_mm", "", list)
    need(spec, "results", "", list)
    if "janssen" in spec:                  # the shaft wall pressure at rest (cases/corn-silo)
        jan = need(spec, "janssen", "", dict)
        for key in ("D_m", "mu_w", "rho_b", "depth_m"):
            if not need(jan, key, "janssen.", num) > 0:
                raise CompareError(f"{path}: key 'janssen.{key}' must be > 0, got {jan[key]}")
        kk = need(jan, "K", "janssen.", list)
        if len(kk) != 2 or not all(isinstance(x, num) and x > 0 for x in kk):
            raise CompareError(f"{path}: key 'janssen.K' must be [K_min, K_max] > 0, got {kk!r}")
    for i, r in enumerate(spec.get("runs", [])):
        need(r, "levels", f"runs[{i}].", list)
        need(r, "command", f"runs[{i}].", str)
        for lv in r["levels"]:
            if lv not in LEVELS:
                raise CompareError(f"{path}: runs[{i}].levels has unknown level {lv!r}; known: {', '.join(LEVELS)}")
    spec["_path"] = path
    return spec


def read_level(path):
    d = levels.read(path)
    d["_path"] = path
    d["_dir"] = os.path.dirname(path)
    return d


def read_series(level):
    if level["timeseries"] is None:     # a level that is a fit or an extrapolation, not a run
        return None
    path = os.path.join(level["_dir"], level["timeseries"])
    if not os.path.exists(path):
        raise CompareError(f"{level['_path']}: key 'timeseries' names {path}, which does not exist")
    cols = ts.read_csv(path, min_rows=0)
    for col in ("t", "mass_flow_kg_s"):
        if col not in cols:
            raise CompareError(f"{path}: column {col} missing (header {','.join(cols)})")
    return cols


def find_levels(case, b_mm, dirs):
    found, seen = [], set()
    for d in dirs:
        for path in sorted(glob.glob(os.path.join(d, "**", "*level.json"), recursive=True)):
            real = os.path.realpath(path)
            # A study's runs/ folder holds its work (chunks, scratch copies of
            # its results): the committed results beside it are what counts.
            if "runs" in os.path.relpath(path, d).split(os.sep)[:-1]:
                continue
            if real in seen:
                continue
            seen.add(real)
            lv = read_level(path)
            if lv["case"] == case and abs(float(lv["b_mm"]) - b_mm) < 1e-6:
                found.append(lv)
    return found


# -------------------------------------------------------------- closed form
def closed_form_rows(spec, b_mm):
    t0 = time.perf_counter()
    B = b_mm * 1e-3
    bev = spec["beverloo"]
    lo, hi = cf.beverloo_band(spec["orifice"], B, spec["d_m"], spec["rho_b"], tuple(bev["k"]), bev["C"],
                              spec.get("slot_length_m"))
    ratio = cf.carleton_ratio(B, spec["hopper_half_angle_deg"], spec["d_m"], spec["rho_p"],
                              spec["air"]["rho"], spec["air"]["mu"])
    # Rounded to the millisecond: the closed forms take microseconds, and the
    # unrounded timer made every rewritten compare table differ from the last.
    wall = round(time.perf_counter() - t0, 3)
    name = "Hagen-Beverloo (slot)" if spec["orifice"] == "slot" else "Beverloo"
    kk = f"C = {bev['C']}, k = {min(bev['k']):g}..{max(bev['k']):g}"
    mid = 0.5 * (lo + hi)
    rows = [dict(level="closed-form", model=f"{name}, {kk}: band {lo:.4g}..{hi:.4g} kg/s", air=False,
                 steady_mass_flow_kg_s=mid, outlet_dpdz_Pa_m=None, wall_time_s=wall, cores=1,
                 source="compare.json"),
             dict(level="closed-form", model=f"{name} x Carleton (1972) air drag: x{ratio:.3f}", air=True,
                  steady_mass_flow_kg_s=mid * ratio, outlet_dpdz_Pa_m=None, wall_time_s=wall, cores=1,
                  source="compare.json")]
    if "janssen" in spec:
        j = spec["janssen"]
        p = [float(cf.janssen(j["depth_m"], j["D_m"], j["rho_b"], j["mu_w"], k)[1]) for k in sorted(j["K"])]
        p_mid = float(cf.janssen(j["depth_m"], j["D_m"], j["rho_b"], j["mu_w"], sum(j["K"]) / 2)[1])
        rows.append(dict(level="closed-form", air=False, steady_mass_flow_kg_s=None, outlet_dpdz_Pa_m=None,
                         model=f"Janssen (1895), shaft wall pressure at rest {j['depth_m']:g} m below the surface, "
                               f"D = {j['D_m']:g} m, mu_w = {j['mu_w']:g}, K = {min(j['K']):.3g}..{max(j['K']):.3g}: "
                               f"band {p[0]:.4g}..{p[1]:.4g} Pa", shaft_wall_pressure_Pa=p_mid,
                         wall_time_s=wall, cores=1, source="compare.json"))
    return rows, (lo, hi), ratio


# ------------------------------------------------------------------ runs
def run_levels(spec, case_dir, b_mm, wanted, out):
    runs = spec.get("runs", [])
    done = []
    for i, r in enumerate(runs):
        if not (set(r["levels"]) & wanted):
            continue
        run_out = os.path.join(out, "runs", f"{i}-{'-'.join(r['levels'])}")
        cmd = r["command"].format(b=f"{b_mm:g}", out=run_out, case=case_dir)
        print(f"[compare] running {', '.join(r['levels'])}: {cmd}", flush=True)
        t0 = time.time()
        proc = subprocess.run(["bash", "-c", cmd], cwd=case_dir)
        if proc.returncode != 0:
            raise CompareError(f"[compare] `{cmd}` failed (exit {proc.returncode}) in {case_dir}")
        print(f"[compare] {', '.join(r['levels'])} done after {time.time() - t0:.0f} s", flush=True)
        done.append(run_out)
    unknown = wanted - {lv for r in runs for lv in r["levels"]}
    if unknown:
        raise CompareError(f"{spec['_path']}: no run command for level(s) {', '.join(sorted(unknown))}; "
                           f"runnable: {', '.join(sorted({lv for r in runs for lv in r['levels']})) or 'none'}")
    return done


# ------------------------------------------------------------------ output
def fmt(v, spec="{:.4g}"):
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return "-"
    return spec.format(v)


def table(rows, band, shaft=False):
    """The table's header and rows; shaft: a column of the shaft wall pressure
    (cases with a `janssen` block), before the source."""
    mid = 0.5 * (band[0] + band[1])
    head = ["level", "model", "air", "steady mass flow [kg/s]", "outlet dp/dz [Pa/m]", "wall time [s]",
            "cores", "W / Beverloo middle", "Crewdson check [kg/s]"] + \
        (["shaft wall pressure [Pa]"] if shaft else []) + ["source"]
    body = []
    for r in rows:
        w = r.get("steady_mass_flow_kg_s")
        body.append([r["level"], r["model"], "yes" if r["air"] else "no", fmt(w), fmt(r.get("outlet_dpdz_Pa_m")),
                     fmt(r.get("wall_time_s"), "{:.3g}"), fmt(r.get("cores"), "{}"),
                     fmt(None if w is None else w / mid, "{:.2f}"), fmt(r.get("crewdson_kg_s"))] +
                    ([fmt(r.get("shaft_wall_pressure_Pa"))] if shaft else []) + [r.get("source", "")])
    return head, body


# the dry level a run with air is checked against (same particles or same continuum model)
DRY_OF = {"cg-dem-cfd": "cg-dem", "continuum": "continuum", "dem-cfd": "dem-cfd"}


def add_crewdson(rows, rho_b):
    """Crewdson's estimate for each run with air, from the dry run of the matching
    level in the same results folder (else the dry run with the same model
    description): W_dry sqrt(1 + (dp/dz)/(rho_b g)), to set beside the run's
    own W (does the outlet gradient explain the slow-down?)."""
    for r in rows:
        if r["air"] and r.get("outlet_dpdz_Pa_m") is not None and r["level"] in DRY_OF:
            cands = [x for x in rows if x["level"] == DRY_OF[r["level"]] and not x["air"]]
            dry = [x for x in cands if x.get("group") == r.get("group")] or \
                  [x for x in cands if x["model"] == r["model"]]
            if dry:
                r["crewdson_kg_s"] = cf.crewdson(dry[0]["steady_mass_flow_kg_s"], r["outlet_dpdz_Pa_m"], rho_b)
                r["pair"] = dry[0]


def mesh_study_line(row):
    """One line on a level's mesh study (its level.json 'mesh_study': N, W finest first, order,
    extrapolated, gci_fine, convergence, source)."""
    m = row["mesh_study"]
    meshes = ", ".join("N = %s: %.4g" % (n, w) for n, w in zip(m["N"], m["W"]))
    if m.get("convergence") == "monotonic":
        result = "GCI_fine %.2f %%, observed order %.2f, extrapolated W %.4g kg/s" % (
            100 * m["gci_fine"], m["order"], m["extrapolated"])
    else:
        result = "no GCI: the sequence is %s" % m.get("convergence", "unknown")
    return "%s, %s (%s kg/s): %s (%s)" % (row["level"], row["model"], meshes, result,
                                         os.path.join(row.get("source", ""), m.get("source", "")))


def group_of(level):
    """Runs written together: one folder of <name>.level.json files, or sibling
    run folders each holding a level.json."""
    d = os.path.realpath(level["_dir"])
    return os.path.dirname(d) if os.path.basename(level["_path"]) == "level.json" else d


def legend_room(plt, n_axes, n_entries, width, fontsize, plot_height=4.6):
    """A figure of n_axes side by side with room below them for a one-column legend
    of n_entries lines (a case collects tens of runs: a legend inside the axes
    would hide the curves, a fixed figure cut it off): the figure, its axes and the
    legend's top in figure coordinates, which legend_below(fig, ax, top, ...) takes."""
    line = 1.5 * fontsize / 72.0                # inches per legend line
    top, xlabel, legend = 0.45, 0.75, n_entries * line + 0.2
    height = top + plot_height + xlabel + legend
    fig, axes = plt.subplots(1, n_axes, figsize=(width, height), squeeze=False)
    fig.subplots_adjust(left=0.9 / width, right=1 - 0.3 / width, top=1 - top / height,
                        bottom=(xlabel + legend) / height, wspace=0.28)
    return fig, list(axes[0]), legend / height


def legend_below(fig, ax, top, fontsize):
    box = ax.get_position()
    ax.legend(fontsize=fontsize, loc="upper center", bbox_to_anchor=(0.5 * (box.x0 + box.x1), top),
              bbox_transform=fig.transFigure, ncol=1, frameon=False)


def plot(rows, band, ratio, out, title):
    plt = plots.pyplot()
    # one colour per dry run and the run with air checked against it (the
    # Crewdson pair), one per unpaired run: dry dotted, with air solid
    # (matplotlib's ten colours, or tab20's twenty when there are more groups:
    # a repeated colour would make two levels one in the legend)
    group, n = {}, 0
    for r in [x for x in rows if not x["air"]] + [x for x in rows if x["air"]]:
        if r.get("series") is None:
            continue
        pair = r.get("pair")
        if pair is not None and id(pair) in group:
            group[id(r)] = group[id(pair)]
        else:
            group[id(r)] = n
            n += 1
    palette = [f"C{i}" for i in range(10)] if n <= 10 else [plt.get_cmap("tab20")(i) for i in range(20)]
    colour = {k: palette[g % len(palette)] for k, g in group.items()}

    def colour_of(r):
        return colour[id(r)]

    def label_of(r):
        # the source folder, which compare.md's rows also name: runs of one
        # model differ late in its description (mesh, packing, window), so a
        # shortened description repeats in the legend; the folder does not
        return f"{r['level']}, {'air' if r['air'] else 'dry'}: {r.get('source', '')}"

    plotted = [r for r in rows if r.get("series") is not None]
    fig, (ax,), top = legend_room(plt, 1, len(plotted) + 2, 8, 7)
    ax.axhspan(band[0], band[1], color="0.85", label="Beverloo band (closed form, dry)")
    ax.axhline(0.5 * (band[0] + band[1]) * ratio, color="0.4", ls="--", lw=1,
               label="Beverloo x Carleton (closed form, air)")
    for r in rows:
        s = r.get("series")
        if s is None:
            continue
        ax.plot(s["t"], s["mass_flow_kg_s"], lw=1.2, ls="-" if r["air"] else ":", color=colour_of(r),
                label=label_of(r))
    ax.set_xlabel("t [s]")
    ax.set_ylabel("mass flow [kg/s]")
    ax.set_title(title, fontsize=10)
    legend_below(fig, ax, top, 7)
    ax.grid(alpha=0.3)
    plots.save(fig, os.path.join(out, "mass_flow.png"), tight=True)

    with_dpdz = [r for r in rows if r.get("series") is not None and r["air"] and "outlet_dpdz_Pa_m" in r["series"]]
    fig, (ax,), top = legend_room(plt, 1, len(with_dpdz), 8, 7)
    n = 0
    for r in rows:
        s = r.get("series")
        if s is None or not r["air"] or "outlet_dpdz_Pa_m" not in s:
            continue
        ax.plot(s["t"], s["outlet_dpdz_Pa_m"], lw=1.0, color=colour_of(r), label=label_of(r))
        n += 1
    if n == 0:
        ax.text(0.5, 0.5, "no run with air has an outlet pressure gradient", ha="center",
                transform=ax.transAxes)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("outlet air pressure gradient dp/dz [Pa/m]")
    ax.set_title(title, fontsize=10)
    if n:
        legend_below(fig, ax, top, 7)
    ax.grid(alpha=0.3)
    plots.save(fig, os.path.join(out, "outlet_dpdz.png"), tight=True)
    with_level = [r for r in rows if r.get("series") is not None and "fill_level_m" in r["series"]]
    if with_level:
        fill_level_plot(with_level, band, ratio, out, title, colour_of, label_of)


def fill_level_plot(rows, band, ratio, out, title, colour_of, label_of, width=0.1):
    """Mass flow and outlet dp/dz against the fill level: means over `width` s windows of
    each series (a per-step series is noisy; a series of window means is used as it is)."""
    plt = plots.pyplot()
    n_air = sum(1 for r in rows if r["air"] and "outlet_dpdz_Pa_m" in r["series"])
    fig, axes, top = legend_room(plt, 2, max(len(rows) + 2, n_air), 13, 6)
    axes[0].axhspan(band[0], band[1], color="0.85", label="Beverloo band (closed form, dry)")
    axes[0].axhline(0.5 * (band[0] + band[1]) * ratio, color="0.4", ls="--", lw=1,
                    label="Beverloo x Carleton (closed form, air)")
    for r in rows:
        s = r["series"]
        cols = [s["mass_flow_kg_s"], s["fill_level_m"]] + ([s["outlet_dpdz_Pa_m"]] if r["air"] and
                                                            "outlet_dpdz_Pa_m" in s else [])
        t = s["t"]
        if len(t) > 1 and float(t[1] - t[0]) < 0.5 * width:
            _, cols = ts.window_means(t, ts.step_lengths(t), cols, width)
        axes[0].plot(1e3 * cols[1], cols[0], lw=1.2, ls="-" if r["air"] else ":", color=colour_of(r),
                     label=label_of(r))
        if len(cols) > 2:
            axes[1].plot(1e3 * cols[1], cols[2], lw=1.2, color=colour_of(r), label=label_of(r))
    axes[0].set_ylabel("mass flow [kg/s]")
    axes[1].set_ylabel("outlet air pressure gradient dp/dz [Pa/m]")
    for ax in axes:
        ax.set_xlabel("fill level: bed height above the orifice [mm] (discharge goes right to left)")
        ax.grid(alpha=0.3)
        legend_below(fig, ax, top, 6)
    fig.suptitle(f"{title}: against the fill level", fontsize=10)
    plots.save(fig, os.path.join(out, "fill_level.png"), tight=True)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case_dir")
    ap.add_argument("--b", type=float, default=None, help="orifice width/diameter [mm] (default: the case's default)")
    ap.add_argument("--run", nargs="+", default=[], metavar="LEVEL",
                    help=f"run these levels first ({', '.join(LEVELS[1:])} or all)")
    ap.add_argument("--from", dest="from_dirs", nargs="+", default=[], metavar="DIR",
                    help="more folders to collect level.json files from")
    ap.add_argument("--out", default=None)
    a = ap.parse_args(argv)

    case_dir = os.path.abspath(a.case_dir)
    spec = load_spec(case_dir)
    b_mm = a.b if a.b is not None else float(spec.get("default_b_mm", spec["b_mm"][0]))
    if b_mm not in [float(x) for x in spec["b_mm"]]:
        print(f"[compare] note: b = {b_mm:g} mm is not one of the case's studied sizes "
              f"({', '.join(str(x) for x in spec['b_mm'])}); only what exists for it is shown", flush=True)
    out = os.path.abspath(a.out or os.path.join(case_dir, "compare", f"b{b_mm:g}"))
    os.makedirs(out, exist_ok=True)

    wanted = set()
    for lv in a.run:
        if lv == "all":
            wanted |= {x for r in spec.get("runs", []) for x in r["levels"]}
        elif lv in LEVELS[1:]:
            wanted.add(lv)
        else:
            raise CompareError(f"--run: unknown level {lv!r}; known: {', '.join(LEVELS[1:])}, all")
    ran = run_levels(spec, case_dir, b_mm, wanted, out) if wanted else []

    dirs = [os.path.join(case_dir, d) for d in spec["results"]] + \
           [os.path.abspath(d) for d in a.from_dirs] + ran
    rows, band, ratio = closed_form_rows(spec, b_mm)
    for lv in find_levels(spec["case"], b_mm, dirs):
        series = read_series(lv)
        rows.append(dict(level=lv["level"], model=lv["model"], air=bool(lv["air"]),
                         steady_mass_flow_kg_s=lv["steady_mass_flow_kg_s"],
                         outlet_dpdz_Pa_m=lv["outlet_dpdz_Pa_m"] if lv["air"] else None,
                         wall_time_s=lv["wall_time_s"], cores=lv["cores"],
                         shaft_wall_pressure_Pa=lv.get("shaft_wall_pressure_Pa"), group=group_of(lv),
                         mesh_study=lv.get("mesh_study"),
                         source=os.path.relpath(lv["_dir"], case_dir), series=series))
    add_crewdson(rows, spec["rho_b"])
    rows.sort(key=lambda r: (LEVELS.index(r["level"]), r["air"], r.get("source", "")))
    present = {r["level"] for r in rows}
    missing = []
    for lv in LEVELS:
        if lv in present:
            continue
        cmd = [r["command"] for r in spec.get("runs", []) if lv in r["levels"]]
        why = spec.get("not_run", {}).get(lv, "")
        how = f"run it: `./granair compare {os.path.relpath(case_dir)} --b {b_mm:g} --run {lv}`" if cmd else ""
        missing.append((lv, " ".join(x for x in (why or "no results found;", how) if x)))

    shaft = "janssen" in spec
    head, body = table(rows, band, shaft)
    with open(os.path.join(out, "compare.csv"), "w", newline="") as fh:
        w = csv.writer(fh)
        csv_head = (["level", "model", "air", "steady_mass_flow_kg_s", "outlet_dpdz_Pa_m", "wall_time_s",
                     "cores", "w_over_beverloo_middle", "crewdson_kg_s"] +
                    (["shaft_wall_pressure_Pa"] if shaft else []) + ["source", "gci_fine"])
        w.writerow(csv_head)
        for r, line in zip(rows, body):
            w.writerow([r["level"], r["model"], int(r["air"]), r["steady_mass_flow_kg_s"],
                        "" if r.get("outlet_dpdz_Pa_m") is None else r["outlet_dpdz_Pa_m"],
                        r["wall_time_s"], r["cores"], line[7] if line[7] != "-" else "",
                        r.get("crewdson_kg_s", "")] +
                       ([r.get("shaft_wall_pressure_Pa", "")] if shaft else []) +
                       [r.get("source", ""), (r.get("mesh_study") or {}).get("gci_fine", "")])
        for lv, why in missing:
            w.writerow([lv, why] + [""] * (len(csv_head) - 2))
    title = f"{spec['case']}, {'slot' if spec['orifice'] == 'slot' else 'orifice'} b = {b_mm:g} mm"
    lines = [f"# Fidelity levels: {title}", "",
             f"Written by `./granair compare` from {os.path.relpath(spec['_path'])} and the runs' level.json files "
             f"(source: folder relative to the case). "
             f"Steady mass flow for the whole {'silo (full depth)' if spec['orifice'] == 'slot' else 'hopper'}; "
             f"outlet dp/dz is the mean air pressure gradient at the orifice over the steady window (z up: "
             f"negative = suction). Crewdson check: W(dry, same level) x sqrt(1 + (dp/dz)/(rho_b g)) with "
             f"rho_b = {spec['rho_b']:g} kg/m3. Closed forms: tools/granair_cases/closed_forms.py." +
             (f" Shaft wall pressure: the fill at rest, {spec['janssen']['depth_m']:g} m below its surface "
              f"(Janssen: the middle of the K band)." if shaft else ""), "",
             "| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    lines += ["| " + " | ".join(str(x) for x in line) + " |" for line in body]
    studies = [r for r in rows if r.get("mesh_study")]
    if studies:
        lines += ["", "Mesh convergence (Roache's grid convergence index over the three finest meshes, safety "
                  "factor 1.25; tools/granair_cases/gci.py):"]
        lines += ["- " + mesh_study_line(r) for r in studies]
    if missing:
        lines += ["", "Not in the table:"]
        lines += [f"- **{lv}**: {why}" for lv, why in missing]
    by_level = any(r.get("series") is not None and "fill_level_m" in r["series"] for r in rows)
    lines += ["", "Plots: mass_flow.png, outlet_dpdz.png"
              + (", fill_level.png (against the bed height above the orifice)." if by_level else ".")]
    md = "\n".join(lines) + "\n"
    with open(os.path.join(out, "compare.md"), "w") as fh:
        fh.write(md)
    plot(rows, band, ratio, out, title)
    print(md)
    print(f"[compare] results in {out}: compare.csv, compare.md, mass_flow.png, outlet_dpdz.png"
          + (", fill_level.png" if by_level else ""), flush=True)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except CompareError as e:
        print(f"granair compare: {e}", file=sys.stderr)
        sys.exit(2)
