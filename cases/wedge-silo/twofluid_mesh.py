#!/usr/bin/python3
"""Mesh study of the wedge silo's two-fluid level at b = 10 mm (docs/two-fluid-model.md
"On a silo"), from finished twofluid.py runs that differ only in --mesh.

    twofluid_mesh.py --runs DIR [DIR ...] [--out DIR] [--level] [--late T0 T1]

Each DIR is a twofluid.py --out folder with the runs b10_air and b10_noair
(summary.txt, level.json, cost.txt, timeseries.csv of each). Writes
OUT/mesh.{csv,json,md,png}: per mesh (N cells across the slot) the dry and
air rates W over each run's window (the DEM case's: from min(0.3 s, t1/2) to
t1, t1 when half the fill has left), the air effect W_air/W_dry - 1, the
outlet dp/dz and the slot row's solid fraction of the air run, the CPU
seconds; how steady each window is (the spread of its 50 ms means and the
drift of a straight-line fit over it, relative to W); the same over a
common late window (--late, default LATE) where every run covers it (else
the report says which runs end before it); Roache's grid
convergence index (gc.gci, safety factor 1.25, h = 1/N) of each quantity
over the three finest meshes where it is monotonic. --level: the W study
goes into the finest mesh's b10_air / b10_noair level.json as "mesh_study"
(the compare tool's line on it).
"""
import json
import os

import numpy as np

import granair_cases as gc

HERE = os.path.dirname(os.path.abspath(__file__))
B = 10
BLOCK = 0.05        # [s] the steadiness check's block means
# [s] a window every run covers (runs with --past-half for the dry ones):
# the start-up overshoot is over and the fill level is still in the shaft;
# a check of the DEM-case window's means where those windows are unsteady
LATE = (0.6, 0.85)


def one(d, air, late_window=LATE):
    name = f"b{B}_{'air' if air else 'noair'}"
    s = gc.series.read_keys(os.path.join(d, name, "summary.txt"))
    c = gc.series.read_keys(os.path.join(d, name, "cost.txt"))
    lv = gc.levels.read(os.path.join(d, name, "level.json"))
    ts = gc.series.read_csv(os.path.join(d, name, "timeseries.csv"))
    t, w = ts["t"], ts["mass_flow_kg_s"]
    t0, t1 = float(s["window_t0_s"]), float(s["window_t1_s"])
    sel = (t >= t0) & (t <= t1)
    _, (blocks,) = gc.series.window_means(t[sel], gc.series.step_lengths(t[sel], t0), [w[sel]], BLOCK, keep_last=0.5)
    W = float(s["W_kg_s"])
    drift = gc.series.slope(t, w, t0, t1) * (t1 - t0) / W
    lo, hi = late_window
    late = [gc.series.time_mean(t, ts[k], lo, hi, dt=gc.series.step_lengths(t))
            for k in ("mass_flow_kg_s", "outlet_dpdz_Pa_m")] if t[-1] >= hi else [float("nan")] * 2
    return dict(W=W, W_late=late[0], dpdz_late=late[1], dpdz=float(s["outlet_dpdz_Pa_m"]), alpha=float(s["slot_row_alpha"]), t0=t0, t1=t1,
                t_end=float(s["t_end_s"]), cpu_s=float(c["cpu_s"]), cells=int(float(c["cells"])),
                spread=(float(blocks.max() - blocks.min()) / W) if blocks.size else float("nan"), drift=drift,
                N=int(lv["model"].split("staircase mesh b/")[1].split(",")[0]), t=t, w=w)


def main():
    ap = gc.cli.parser(__doc__)
    ap.add_argument("--runs", nargs="+", required=True)
    ap.add_argument("--level", action="store_true", help="write the W study into the finest mesh's level.json files")
    ap.add_argument("--late", type=float, nargs=2, default=list(LATE), metavar=("T0", "T1"),
                    help="the common late window [s] (default %(default)s)")
    a = gc.cli.parse(ap, os.path.join(HERE, "reference-two-fluid-mesh"))
    if not 0 <= a.late[0] < a.late[1]:
        ap.error(f"--late {a.late[0]:g} {a.late[1]:g}: expected 0 <= T0 < T1 [s]")
    rows, series = [], {}
    for d in a.runs:
        wet, dry = one(d, True, a.late), one(d, False, a.late)
        if wet["N"] != dry["N"]:
            raise gc.CaseError(f"{d}: the air run is on mesh b/{wet['N']}, the dry run on b/{dry['N']}")
        series[wet["N"]] = (wet, dry)
        rows.append(dict(N=wet["N"], cell_mm=B / wet["N"], cells=wet["cells"], W_dry_kg_s=dry["W"],
                         W_air_kg_s=wet["W"], air_effect=wet["W"] / dry["W"] - 1, outlet_dpdz_Pa_m=wet["dpdz"],
                         slot_row_alpha_air=wet["alpha"], slot_row_alpha_dry=dry["alpha"],
                         window_air_s=f"{wet['t0']:.3f}-{wet['t1']:.3f}", window_dry_s=f"{dry['t0']:.3f}-{dry['t1']:.3f}",
                         spread_air=wet["spread"], spread_dry=dry["spread"], drift_air=wet["drift"],
                         drift_dry=dry["drift"], W_dry_late_kg_s=dry["W_late"], W_air_late_kg_s=wet["W_late"],
                         air_effect_late=wet["W_late"] / dry["W_late"] - 1, outlet_dpdz_late_Pa_m=wet["dpdz_late"],
                         cpu_air_s=wet["cpu_s"], cpu_dry_s=dry["cpu_s"],
                         folder=os.path.relpath(os.path.abspath(d), HERE)))
    rows.sort(key=lambda r: r["N"])
    if len({r["N"] for r in rows}) != len(rows):
        raise gc.CaseError("--runs: two folders on the same mesh (" + ", ".join(str(r["N"]) for r in rows) + ")")
    # runs that end before the late window's end have no late means (nan): no table, no GCI of them
    short = sorted({f"b/{n} {what} (t_end {r['t_end']:g} s)" for n, pair in series.items()
                    for r, what in zip(pair, ("air", "dry")) if np.isnan(r["W_late"])})
    keys = ("W_dry_kg_s", "W_air_kg_s", "air_effect", "outlet_dpdz_Pa_m", "slot_row_alpha_air") + (
        () if short else ("W_dry_late_kg_s", "W_air_late_kg_s", "air_effect_late", "outlet_dpdz_late_Pa_m"))
    three = rows[-3:][::-1]
    study = {}
    for k in keys:
        if len(three) == 3:
            study[k] = gc.gci.gci(tuple(r[k] for r in three), tuple(1.0 / r["N"] for r in three))
    os.makedirs(a.out, exist_ok=True)
    gc.series.write_rows(os.path.join(a.out, "mesh.csv"), rows, "{:.6g}")
    with open(os.path.join(a.out, "mesh.json"), "w") as fh:
        json.dump(dict(b_mm=B, N=[r["N"] for r in rows], rows=rows, gci=study, gci_meshes=[r["N"] for r in three]),
                  fh, indent=1)
    lines = [f"# Wedge silo b = {B} mm, two-fluid level: mesh study", "",
             "| N | cell [mm] | cells | W dry [kg/s] | W air [kg/s] | air effect | outlet dp/dz [Pa/m] "
             "| slot-row alpha air / dry | window air / dry [s] | 50 ms spread air / dry | drift air / dry "
             "| CPU air / dry [s] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    lines += ["| %d | %.3g | %d | %.4f | %.4f | %+.1f %% | %.0f | %.3f / %.3f | %s / %s | %.1f / %.1f %% "
              "| %+.1f / %+.1f %% | %.0f / %.0f |" % (
                  r["N"], r["cell_mm"], r["cells"], r["W_dry_kg_s"], r["W_air_kg_s"], 100 * r["air_effect"],
                  r["outlet_dpdz_Pa_m"], r["slot_row_alpha_air"], r["slot_row_alpha_dry"], r["window_air_s"],
                  r["window_dry_s"], 100 * r["spread_air"], 100 * r["spread_dry"], 100 * r["drift_air"],
                  100 * r["drift_dry"], r["cpu_air_s"], r["cpu_dry_s"]) for r in rows]
    lo, hi = a.late
    if short:
        lines += ["", f"No common window {lo:g}-{hi:g} s: these runs end before it: {', '.join(short)} "
                      f"(--late T0 T1 picks one they cover)."]
    else:
        lines += ["", f"Over the common window {lo:g}-{hi:g} s (every run, the dry ones past half the fill out):", "",
                  "| N | W dry [kg/s] | W air [kg/s] | air effect | outlet dp/dz [Pa/m] |", "|---|---|---|---|---|"]
        lines += ["| %d | %.4f | %.4f | %+.1f %% | %.0f |" % (r["N"], r["W_dry_late_kg_s"], r["W_air_late_kg_s"],
                                                           100 * r["air_effect_late"], r["outlet_dpdz_late_Pa_m"])
                  for r in rows]
    lines += ["", f"GCI (Roache, safety 1.25, h = 1/N) over N = {'/'.join(str(r['N']) for r in three[::-1])}:", ""]
    for k, g in study.items():
        lines.append(f"- {k}: " + ("GCI_fine %.1f %%, order %.2f, extrapolated %.5g" % (
            100 * g["gci_fine"], g["order"], g["extrapolated"]) if g["convergence"] == "monotonic"
            else f"no GCI: the sequence is {g['convergence']} (e21 {g['e21']:.4g}, e32 {g['e32']:.4g})"))
    lines.append("")
    with open(os.path.join(a.out, "mesh.md"), "w") as fh:
        fh.write("\n".join(lines))
    print("\n".join(lines))

    plt = gc.plots.pyplot()
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4))
    for n, (wet, dry) in sorted(series.items()):
        for r, style, what in ((wet, "-", "air"), (dry, "--", "dry")):
            c, (m,) = gc.series.window_means(r["t"], gc.series.step_lengths(r["t"]), [r["w"]], 0.01)
            line, = ax.plot(c, m, style, lw=1, label=f"b/{n} {what}",
                            color=ax.lines[-1].get_color() if what == "dry" else None)
            ax.plot([r["t0"], r["t1"]], [r["W"]] * 2, color=line.get_color(), lw=3, alpha=0.5)
    ax.set(xlabel="t [s]", ylabel="W [kg/s] (10 ms means; bars: window means)", ylim=(0, None))
    ax.legend(fontsize=7, ncol=2)
    ax.grid(alpha=0.3)
    n = [r["N"] for r in rows]
    for k, label in (("W_dry_kg_s", "dry"), ("W_air_kg_s", "air")):
        g = study.get(k, dict(convergence="too few meshes"))
        gc.plots.mesh_study(bx, n, [r[k] for r in rows], g, label, "the slot")
    bx.set_title(f"air effect: {', '.join('b/%d %+.1f %%' % (r['N'], 100 * r['air_effect']) for r in rows)}",
                 fontsize=9)
    bx.legend(fontsize=7)
    fig.suptitle(f"wedge silo b = {B} mm, two-fluid level: mesh study", fontsize=10)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(a.out, "mesh.png"))
    if a.level and len(three) == 3:
        fine = next(d for d in a.runs if one(d, True)["N"] == three[0]["N"])
        for k, air in (("W_air_kg_s", True), ("W_dry_kg_s", False)):
            path = os.path.join(fine, f"b{B}_{'air' if air else 'noair'}", "level.json")
            g = study[k]
            lv = gc.levels.read(path)
            lv["mesh_study"] = dict(N=[r["N"] for r in three], W=[r[k] for r in three], order=g["order"],
                                    extrapolated=g["extrapolated"], gci_fine=g["gci_fine"],
                                    convergence=g["convergence"],
                                    source=os.path.relpath(os.path.join(a.out, "mesh.json"), os.path.dirname(path)))
            gc.levels.write(path, **lv)
    return 0


if __name__ == "__main__":
    gc.cli.main(main)
