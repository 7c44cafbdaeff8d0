#!/usr/bin/python3
"""Mesh convergence of the wedge silo's continuum runs (README, "Cross-validation":
the mesh study), from finished runs of continuum.py that differ only in --mesh.

    convergence.py --runs DIR [DIR ...] [--level DIR] [--out DIR] [--label TEXT]

Each DIR is a continuum.py --out folder with one b10_noair run (summary.csv,
silo.json of the run). Writes OUT/convergence.{csv,json,md,png}: W against N
(cells across the slot), Roache's grid convergence index over the three finest
meshes (gc.gci, safety factor 1.25, h = 1/N), the powder that left through the
open sides of the free-fall region (the mass balance error of the outlet
integral); --level DIR: the mesh study goes into DIR/b10_noair/level.json as
"mesh_study" (the compare tool's gci_fine column).
"""
import csv
import json
import os

import granair_cases as gc

HERE = os.path.dirname(os.path.abspath(__file__))
RUN = "b10_noair"


def row(d):
    with open(os.path.join(d, "summary.csv")) as fh:
        s = next(r for r in csv.DictReader(fh) if r["run"] == RUN)
    with open(os.path.join(d, RUN, "silo.json")) as fh:
        v = json.load(fh)
    with open(os.path.join(d, RUN, "details.json")) as fh:
        det = json.load(fh)
    return dict(folder=os.path.relpath(d, HERE), N=int(v["N"]), cell_mm=2 * v["B"] / v["N"] * 1e3,
                cell_over_d=2 * v["B"] / v["N"] / v["D_LACTOSE"], W=float(s["W_kg_s"]),
                W_over_dem=float(s["W_over_dem"]), side_leak=-float(det["mass_balance_error"]),
                cpu_s=det.get("solver_cpu_time_s"))


def main():
    ap = gc.cli.parser(__doc__)
    ap.add_argument("--runs", nargs="+", required=True)
    ap.add_argument("--level", default=None)
    ap.add_argument("--label", default="continuum, DEM-calibrated mu(I), b = 10 mm, dry")
    a = gc.cli.parse(ap, os.path.join(HERE, "reference-continuum-calibrated-demo", "convergence"))
    rows = sorted((row(d) for d in a.runs), key=lambda r: r["N"])
    three = rows[-3:][::-1]
    g = gc.gci.gci(tuple(r["W"] for r in three), tuple(1.0 / r["N"] for r in three))
    w = [r["W"] for r in rows]
    monotonic = all(x < y for x, y in zip(w, w[1:])) or all(x > y for x, y in zip(w, w[1:]))
    os.makedirs(a.out, exist_ok=True)
    gc.series.write_rows(os.path.join(a.out, "convergence.csv"), rows, "{:.6g}")
    s = dict(label=a.label, N=[r["N"] for r in three], W=[r["W"] for r in three], N_all=[r["N"] for r in rows],
             W_all=w, monotonic=monotonic, gci=g)
    with open(os.path.join(a.out, "convergence.json"), "w") as fh:
        json.dump(s, fh, indent=1)
    gci_text = ("%.2f %% (order %.2f, extrapolated W %.4f kg/s)" % (100 * g["gci_fine"], g["order"], g["extrapolated"])
                if g["convergence"] == "monotonic" else "none: the sequence is " + g["convergence"])
    lines = [f"# Wedge silo, {a.label}: mesh convergence", "",
             "| N | cell [mm] | cell / d | W [kg/s] | / DEM | powder out through the free-fall sides | solver CPU [s] | folder |",
             "|---|---|---|---|---|---|---|---|"]
    lines += ["| %d | %.3g | %.2f | %.5f | %.3f | %.2f %% | %s | `%s` |" % (
        r["N"], r["cell_mm"], r["cell_over_d"], r["W"], r["W_over_dem"], 100 * r["side_leak"],
        "%.0f" % r["cpu_s"] if r["cpu_s"] else "-", r["folder"]) for r in rows]
    lines += ["", "W monotonic in N: %s; GCI_fine over N = %s: %s" % (
        "yes" if monotonic else "**no**", "/".join(str(n) for n in s["N"][::-1]), gci_text), ""]
    with open(os.path.join(a.out, "convergence.md"), "w") as fh:
        fh.write("\n".join(lines))
    print("\n".join(lines))
    plt = gc.plots.pyplot()
    fig, ax = plt.subplots(figsize=(6, 4))
    gc.plots.mesh_study(ax, [r["N"] for r in rows], w, g, a.label, "the slot")
    ax.set_title("wedge silo b = 10 mm, dry, continuum: mesh convergence", fontsize=10)
    ax.legend(fontsize=7)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(a.out, "convergence.png"))
    if a.level:
        path = os.path.join(a.level, RUN, "level.json")
        lv = gc.levels.read(path)
        lv["mesh_study"] = dict(N=s["N"], W=s["W"], order=g["order"], extrapolated=g["extrapolated"],
                                gci_fine=g["gci_fine"], convergence=g["convergence"],
                                source=os.path.relpath(os.path.join(a.out, "convergence.json"), os.path.dirname(path)))
        gc.levels.write(path, **lv)


if __name__ == "__main__":
    gc.cli.main(main)
