"""The mesh study of the continuum MCC hopper (study.py --convergence; README
"Mesh convergence"): one run per N of parameters.MESHES (cells across the
orifice diameter, ratio sqrt 2) and the sensitivity runs of
parameters.SENSITIVITY on the finest mesh, then Roache's grid convergence
index over the three finest meshes (granair_cases.gci, safety factor 1.25).

Writes OUT/convergence/:
  N<n>/, N<n>-<tag>/    each run's summary.txt, mass_flow.csv/png (study.py)
  convergence.csv       one row per run: N, cells, orifice cell [mm], W, sd of the
                        10 ms means, change against the finest mesh, mass balance,
                        packed cells with p <= 0 beyond two cells of the outlet and
                        the orifice plane (mean, max over the steady window),
                        outer-corrector statistics, wall and CPU seconds
  convergence.json      the study: N, h = 1/N, W of the three finest, order,
                        extrapolated W, GCI_fine, the sensitivity changes
  convergence.md        the same as tables, with the targets of issue 16
  convergence.png       W against 1/N with the extrapolation and Beverloo
"""
import copy
import json
import os

import granair_cases as gc
import parameters as P


def rows_of(study_runs):
    rows = []
    for tag, n, s in study_runs:
        rows.append(dict(tag=tag, N=n, cells=int(s["cells"]), orifice_cell_mm=P.D_OUTLET / n * 1e3,
                         W=float(s["steady_mass_flow_kg_s"]), W_sd=float(s["window_mass_flow_sd_kg_s"]),
                         mass_balance=float(s["mass_balance_error"]), tension_mean=float(s["tension_fraction_mean"]),
                         tension_max=float(s["tension_fraction_max"]), steps=int(s["steps"]),
                         outer_mean=float(s["outer_correctors_mean"]), unconverged=int(s["unconverged_steps"]),
                         wall_s=float(s["run_wall_s"]), cpu_s=float(s["run_cpu_s"])))
    return rows


def study(a, run):
    """Run (or reuse) every run of the study with run(options, n, res) -> summary;
    write the tables and the plot; return the study dict."""
    out = os.path.join(a.out, "convergence")
    meshes = sorted(P.MESHES)
    done = []
    for n in meshes:
        b = copy.copy(a)
        b.mesh = n
        done.append((f"N{n}", n, run(b, n, os.path.join(out, f"N{n}"))))
    fine = meshes[-1]
    for tag, change in P.SENSITIVITY.items():
        b = copy.copy(a)
        b.mesh = fine
        for k, v in change.items():
            setattr(b, k, v)
        done.append((f"N{fine}-{tag}", fine, run(b, fine, os.path.join(out, f"N{fine}-{tag}"))))
    rows = rows_of(done)
    ref = rows[len(meshes) - 1]
    for r in rows:
        r["change_vs_finest"] = (r["W"] - ref["W"]) / ref["W"]
    mesh_rows = rows[:len(meshes)]
    three = mesh_rows[-3:][::-1]   # finest first
    g = gc.gci.gci(tuple(r["W"] for r in three), tuple(1.0 / r["N"] for r in three))
    w_all = [r["W"] for r in mesh_rows]
    monotonic = all(x < y for x, y in zip(w_all, w_all[1:])) or all(x > y for x, y in zip(w_all, w_all[1:]))
    s = dict(walls=a.walls, wall_friction=a.wall_friction if a.walls == "coulomb" else None,
             N=[r["N"] for r in three], h=[1.0 / r["N"] for r in three], W=[r["W"] for r in three],
             meshes_all=meshes, W_all=w_all, monotonic=monotonic, gci=g,
             sensitivity={r["tag"]: r["change_vs_finest"] for r in rows[len(meshes):]},
             tension_max_finest=ref["tension_max"], tension_mean_finest=ref["tension_mean"])
    with open(os.path.join(out, "convergence.json"), "w") as fh:
        json.dump(s, fh, indent=1)
        fh.write("\n")
    keys = ["tag", "N", "cells", "orifice_cell_mm", "W", "W_sd", "change_vs_finest", "mass_balance", "tension_mean",
            "tension_max", "steps", "outer_mean", "unconverged", "wall_s", "cpu_s"]
    gc.series.write_rows(os.path.join(out, "convergence.csv"), [{k: r[k] for k in keys} for r in rows], fmt="{:.6g}")
    bev = (P.beverloo(P.K_RANGE[1]), P.beverloo(P.K_RANGE[0]))
    text = table(a, rows, s, fine, bev)
    with open(os.path.join(out, "convergence.md"), "w") as fh:
        fh.write(text)
    plot(mesh_rows, s, out, bev)
    print(text)
    return s


def table(a, rows, s, fine, bev):
    g, t = s["gci"], P.TARGETS
    ok = lambda c: "yes" if c else "**no**"  # noqa: E731
    walls = f"Coulomb walls, mu_w {a.wall_friction:g}" if a.walls == "coulomb" else f"{a.walls} walls"
    lines = [f"# MCC hopper, continuum: mesh convergence ({walls})", "",
             f"Written by `cases/mcc-hopper/Allrun --convergence`; {a.end:g} s of discharge, W = slope of the "
             f"discharged mass over t >= {a.steady_from:g} s; N = cells across the orifice diameter.", "",
             "| run | N | cells | orifice cell [mm] | W [kg/s] | vs finest | sd of 10 ms means | "
             "packed cells p <= 0 (mean / max) | CPU [s] |", "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %d | %d | %.2f | %.5f | %+.2f %% | %.2g | %.2g / %.2g | %.0f |" % (
            r["tag"], r["N"], r["cells"], r["orifice_cell_mm"], r["W"], 100 * r["change_vs_finest"], r["W_sd"],
            r["tension_mean"], r["tension_max"], r["cpu_s"]))
    gci_text = ("%.2f %% (order %.2f, extrapolated W %.4f kg/s)" % (100 * g["gci_fine"], g["order"], g["extrapolated"])
                if g["convergence"] == "monotonic" else g["convergence"])
    lines += ["", "| target (issue 16) | measured | met |", "|---|---|---|",
              "| W monotonic in N | %s kg/s | %s |" % (" / ".join("%.4f" % x for x in s["W_all"]), ok(s["monotonic"])),
              "| GCI_fine (Roache, Fs 1.25) over N = %s < %g %% | %s | %s |" % (
                  "/".join(str(n) for n in s["N"][::-1]), 100 * t["gci"], gci_text,
                  ok(g["convergence"] == "monotonic" and g["gci_fine"] < t["gci"]))]
    sens = s["sensitivity"]
    for tag, text in [("maxCo0.2", "maxCo halved"), ("etaMax1e6", "etaMax x 10")]:
        v = sens.get(f"N{fine}-{tag}")
        if v is not None:
            lines.append("| %s changes W < %g %% | %+.2f %% | %s |" % (text, 100 * t["sensitivity"], 100 * v,
                                                                      ok(abs(v) < t["sensitivity"])))
    lines.append("| packed cells with p <= 0 beyond two cells of the outlet < %g %% (N = %d, max over the window) "
                 "| %.3g %% | %s |" % (100 * t["tension"], fine, 100 * s["tension_max_finest"],
                                       ok(s["tension_max_finest"] < t["tension"])))
    for tag, text in [("transposeOff", "transposeStress off (not a target: the size of the term)"),
                      ("freefall25mm", "free-fall region 25 mm instead of 12.5 mm (not a target)")]:
        v = sens.get(f"N{fine}-{tag}")
        if v is not None:
            lines.append("| %s | %+.2f %% | - |" % (text, 100 * v))
    lines += ["", "Beverloo (C = %g, k = 3..1): %.4f-%.4f kg/s." % (P.BEVERLOO_C, *bev), "",
              "![convergence](convergence.png)", ""]
    return "\n".join(lines)


def plot(mesh_rows, s, out, bev):
    plt = gc.plots.pyplot()
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.axhspan(*bev, color="0.88", label="Beverloo, k = 3..1")
    gc.plots.mesh_study(ax, [r["N"] for r in mesh_rows], [r["W"] for r in mesh_rows], s["gci"], "granairContinuumFoam",
                        "the orifice diameter")
    ax.set_title("MCC hopper, continuum mu(I): mesh convergence", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(out, "convergence.png"))


def add_to_level(s, path):
    """The study as "mesh_study" of the run's level.json (`./granair compare` prints it)."""
    lv = gc.levels.read(path)
    g = s["gci"]
    lv["mesh_study"] = dict(N=s["N"], W=s["W"], order=g["order"], extrapolated=g["extrapolated"],
                            gci_fine=g["gci_fine"], convergence=g["convergence"],
                            source=os.path.relpath(os.path.join(os.path.dirname(path), "convergence",
                                                                "convergence.json"), os.path.dirname(path)))
    gc.levels.write(path, **lv)
