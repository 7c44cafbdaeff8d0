#!/usr/bin/env python3
"""case/compare_levels: `./granair compare` on the committed references.

Checks (no simulation is run):
- wedge-silo, b = 10 mm: the table has the closed-form rows (dry and air),
  the coarse-grained DEM rows with and without air, and every DEM row's
  steady mass flow and outlet gradient equal the run's own summary
  (reference-demo/summary.csv) to its 5 printed digits; the Crewdson check of
  the air row is W_dry sqrt(1 + (dp/dz)/(rho_b g)) from those numbers;
  levels without results are listed (dem-cfd with its reason); both plots exist.
- mcc-hopper: the continuum rows (Coulomb and free-slip walls) carry the
  steady rates of results/summary.txt and results/slip/summary.txt, and the
  Coulomb row carries the grid convergence index of its mesh study
  (results/convergence/convergence.json) in compare.csv and compare.md.
- bad input: a compare.json without `rho_b` and an unknown --run level stop
  with exit 2 and a message naming the file and key / the level.
Usage: compare_check.py REPO_ROOT WORK_DIR
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys

root, work = sys.argv[1], sys.argv[2]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
py = sys.executable
tool = os.path.join(root, "tools", "compare.py")
problems = []


def run(*args):
    return subprocess.run([py, tool, *args], capture_output=True, text=True)


def rows_of(out):
    with open(os.path.join(out, "compare.csv")) as fh:
        return list(csv.DictReader(fh))


def close(a, b, rel):
    return abs(a - b) <= rel * abs(b)


# --- wedge silo, b = 10
out = os.path.join(work, "wedge-b10")
r = run(os.path.join(root, "cases", "wedge-silo"), "--b", "10", "--out", out)
if r.returncode != 0:
    sys.exit(f"compare on wedge-silo failed:\n{r.stdout}\n{r.stderr}")
rows = rows_of(out)
levels = [(x["level"], x["air"]) for x in rows]
for want in [("closed-form", "0"), ("closed-form", "1"), ("cg-dem", "0"), ("cg-dem-cfd", "1")]:
    if want not in levels:
        problems.append(f"wedge b = 10: row {want} missing (have {levels})")
with open(os.path.join(root, "cases", "wedge-silo", "reference-demo", "summary.csv")) as fh:
    ref = {x["run"]: x for x in csv.DictReader(fh)}
rho_b = json.load(open(os.path.join(root, "cases", "wedge-silo", "compare.json")))["rho_b"]
demo = [x for x in rows if x["source"].endswith("reference-demo")]
by_air = {x["air"]: x for x in demo}
for air, name in (("0", "b10_noair"), ("1", "b10_air")):
    if air not in by_air:
        problems.append(f"wedge b = 10: no reference-demo row with air = {air}")
        continue
    if not close(float(by_air[air]["steady_mass_flow_kg_s"]), float(ref[name]["W_kg_s"]), 1e-4):
        problems.append(f"{name}: table W {by_air[air]['steady_mass_flow_kg_s']} != summary {ref[name]['W_kg_s']}")
if "1" in by_air and "0" in by_air:
    g = float(by_air["1"]["outlet_dpdz_Pa_m"])
    if not close(g, float(ref["b10_air"]["outlet_dpdz_Pa_m"]), 1e-4):
        problems.append(f"b10_air: table dp/dz {g} != summary {ref['b10_air']['outlet_dpdz_Pa_m']}")
    want = float(by_air["0"]["steady_mass_flow_kg_s"]) * math.sqrt(1 + g / (rho_b * 9.81))
    if not close(float(by_air["1"]["crewdson_kg_s"]), want, 1e-9):
        problems.append(f"b10_air: Crewdson check {by_air['1']['crewdson_kg_s']} != {want}")
if not any(x["level"] == "dem-cfd" and "not run" in x["model"] for x in rows):
    problems.append("wedge b = 10: dem-cfd not listed as not run")
for f in ("compare.md", "mass_flow.png", "outlet_dpdz.png"):
    if not os.path.exists(os.path.join(out, f)):
        problems.append(f"wedge b = 10: {f} missing")

# --- mcc hopper
out = os.path.join(work, "mcc")
r = run(os.path.join(root, "cases", "mcc-hopper"), "--out", out)
if r.returncode != 0:
    sys.exit(f"compare on mcc-hopper failed:\n{r.stdout}\n{r.stderr}")
rows = rows_of(out)
for sub in ("", "slip"):
    summ = os.path.join(root, "cases", "mcc-hopper", "results", sub, "summary.txt")
    w = float([ln.split("=")[1] for ln in open(summ) if ln.startswith("steady_mass_flow_kg_s")][0])
    match = [x for x in rows if x["level"] == "continuum" and x["steady_mass_flow_kg_s"]
             and close(float(x["steady_mass_flow_kg_s"]), w, 1e-4)]
    if not match:
        problems.append(f"mcc-hopper: no continuum row with W = {w} (results/{sub})")
    elif sub == "":
        study = json.load(open(os.path.join(root, "cases", "mcc-hopper", "results", "convergence",
                                            "convergence.json")))
        got = match[0].get("gci_fine", "")
        if not got or not close(float(got), study["gci"]["gci_fine"], 1e-9):
            problems.append(f"mcc-hopper: GCI {got!r} in compare.csv != {study['gci']['gci_fine']} of the study")
        if "GCI_fine" not in open(os.path.join(out, "compare.md")).read():
            problems.append("mcc-hopper: compare.md has no GCI line")

# --- bad input
bad = os.path.join(work, "bad-case")
shutil.copytree(os.path.join(root, "cases", "wedge-silo"), bad,
                ignore=shutil.ignore_patterns("run", "compare", "*.png", "vtk"))
spec = json.load(open(os.path.join(bad, "compare.json")))
del spec["rho_b"]
json.dump(spec, open(os.path.join(bad, "compare.json"), "w"))
r = run(bad, "--out", os.path.join(work, "bad-out"))
if r.returncode != 2 or "compare.json" not in r.stderr or "'rho_b'" not in r.stderr:
    problems.append(f"missing rho_b: exit {r.returncode}, stderr {r.stderr.strip()!r}")
r = run(os.path.join(root, "cases", "wedge-silo"), "--run", "warp-drive", "--out", os.path.join(work, "bad-out2"))
if r.returncode != 2 or "warp-drive" not in r.stderr or "continuum" not in r.stderr:
    problems.append(f"unknown level: exit {r.returncode}, stderr {r.stderr.strip()!r}")

if problems:
    print("compare check FAILED:\n  " + "\n  ".join(problems))
    sys.exit(1)
print("compare check passed")
