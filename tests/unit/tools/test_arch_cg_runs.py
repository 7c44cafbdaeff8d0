#!/usr/bin/env python3
"""The case layer's arch, cg_runs and profile_plots modules (tools/granair_cases) on
grids whose answer is known: a kinetic pressure peaked on a paraboloid (its maximum
refined exactly, alpha recovered), an outlet velocity of a known free-fall height, a
contact pressure crossing a level at a known height, block errors by hand; kernels and
windows whose grid points fall on multiples of the spacing, the invariants of an
isotropic and a pure-shear stress, the mass record of a uniform grid, a NaN found, the checks of both,
granairCG runs made once (a stand-in program); and the panels' lines. Last, the
committed orifice-arch fields give the alpha the committed arch table holds."""
import math
import os
import stat
import sys
import tempfile

import numpy as np

from granair_cases import CaseError, arch, cg_runs, plots, profile_plots, series

failures = []
ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))


def check(name, got, want, rel=1e-9, abs_tol=0.0):
    if not (abs(got - want) <= max(rel * abs(want), abs_tol)):
        failures.append(f"{name}: got {got!r}, expected {want!r} (rel {rel}, abs {abs_tol})")


# --- arch: a grid in r at (i + 1/2) h, z on multiples of h; R = 1 --------------------
h, R, alpha0 = 0.1, 1.0, 0.45
r = (np.arange(20) + 0.5) * h
z = np.arange(-15, 31) * h
zc0 = alpha0 * R * (1 - (r / R) ** 2)
Rg, Zg = np.meshgrid(r, z, indexing="ij")
f = {"r": r, "z": z, "p_kinetic": 5.0 - (Zg - zc0[:, None]) ** 2}   # a parabola in z: refined exactly
rs, zc = arch.kinetic_max(f, "r", R, (-1.0, 2.0), 0.9)
check("kinetic_max columns (r <= 0.9 R)", len(rs), 9)
for k in range(len(rs)):
    check(f"kinetic_max z_c at r = {rs[k]:.2f}", zc[k], zc0[k], 1e-9, 1e-12)
a, se = arch.paraboloid(rs, zc, R)
check("paraboloid alpha", a, alpha0, 1e-12)
check("paraboloid se (exact data)", se, 0.0, 0.0, 1e-12)
# a maximum at the range's top (3 spacings below the window's top) is no arch point
f_top = dict(f, p_kinetic=Zg.copy())
check("kinetic_max: increasing pressure, no points", len(arch.kinetic_max(f_top, "r", R)[0]), 0)
# free fall: v_z(r, 0) = -sqrt(2 g z_ff)
g = 9.81
vz = np.zeros_like(Rg)
vz[:, int(np.argmin(abs(z)))] = -np.sqrt(2 * g * np.maximum(zc0, 0.0))     # z = 0 is a grid row
rs, zf = arch.free_fall({"r": r, "z": z, "velocity_z": vz}, "r", R, g, 0.9)
check("free_fall columns", len(rs), 9)
check("free_fall alpha", arch.paraboloid(rs, zf, R)[0], alpha0, 1e-12)
# contact: linear in z, crossing the level at z_s(r); the monolayer's x folded
x = np.concatenate([-r[::-1], r])
zs0 = np.concatenate([zc0[::-1], zc0])
Xg, Zx = np.meshgrid(x, z, indexing="ij")
level = 7.0
fx = {"x": x, "z": z, "p_contact": level + 100.0 * (Zx - zs0[:, None])}
xs, zs = arch.contact_vanish(fx, "x", R, level, (-1.0, 2.0), 0.9)
check("contact_vanish columns (both sides)", len(xs), 18)
check("contact_vanish |x| folded", float(np.min(xs)), 0.05, 1e-12)
check("contact_vanish alpha", arch.paraboloid(xs, zs, R)[0], alpha0, 1e-9)
check("block_se by hand", arch.block_se([1.0, 2.0, 3.0, 4.0]), float(np.std([1, 2, 3, 4], ddof=1)) / 2, 1e-12)
if not (math.isnan(arch.block_se([1.0])) and math.isnan(arch.block_se([1.0, math.nan]))):
    failures.append("block_se: NaN expected with one block or a NaN block")

# --- cg_runs: kernels and windows -----------------------------------------------------
check("gauss spacing", cg_runs.kernel_grid("gauss", 0.02)[1], 0.02)
check("gauss reach", cg_runs.kernel_grid("gauss", 0.02)[2], 0.06)
check("heaviside spacing", cg_runs.kernel_grid("heaviside", 0.02)[1], 0.01)
if cg_runs.tag("gauss", 0.5) != "gauss0.5" or cg_runs.tag("heaviside", 1.0) != "heaviside1":
    failures.append(f"tag: {cg_runs.tag('gauss', 0.5)}, {cg_runs.tag('heaviside', 1.0)}")
hh = 0.03125
w = cg_runs.aligned("RZ", hh, 0.25 + 1e-4, -0.093, 1.02, 0.5, 0.4)
pts = w["min"][2] + (np.arange(5) + 0.5) * hh           # granairCG's first grid points in z
check("RZ window: z points on multiples of h", float(np.max(abs(pts / hh - np.rint(pts / hh)))), 0.0, 0.0, 1e-9)
check("RZ window: rmax rounded up to h", w["rmax"], 9 * hh, 1e-12)
if not (w["min"][2] <= -0.093 and w["max"][2] >= 1.02 and w["min"][:2] == [-0.5, -0.4]):
    failures.append(f"RZ window bounds: {w}")
w = cg_runs.aligned("XZ", hh, 0.25, 0.0, 0.5, None, 0.017)
xp = w["min"][0] + (np.arange(5) + 0.5) * hh
check("XZ window: x points on multiples of h", float(np.max(abs(xp / hh - np.rint(xp / hh)))), 0.0, 0.0, 1e-9)
if w["min"][1] != -0.017 or w["max"][1] != 0.017 or w["coordinates"] != "XZ":
    failures.append(f"XZ window: {w}")
e = cg_runs.enclosing("RZ", 0.09, 0.375, -0.125, 1.6, 0.5, 0.5)
check("enclosing rmax", e["rmax"], 0.465, 1e-12)
check("enclosing z", e["max"][2] - e["min"][2], 1.725 + 0.18, 1e-12)
# invariants: isotropic p (tau 0) and pure shear s (P 0, tau s)
shape = (3, 4)
comp = {f"{n}_{a}{b}": np.zeros(shape) for n in ("contact_stress", "kinetic_stress") for a in "xyz" for b in "xyz"}
for a_ in "xyz":
    comp[f"contact_stress_{a_}{a_}"] = np.full(shape, 2.0)
comp["kinetic_stress_xz"] = comp["kinetic_stress_zx"] = np.full(shape, 3.0)
fg = dict(comp, axes=("x", "z"), x=np.arange(3.0), z=np.arange(4.0), density=np.ones(shape),
          volume_fraction=np.ones(shape), velocity_x=np.zeros(shape), velocity_z=np.zeros(shape))
red = cg_runs.reduce(fg, "x")
check("reduce: isotropic P", float(red["p_contact"][1, 1]), 2.0)
check("reduce: isotropic tau", float(red["tau_contact"][1, 1]), 0.0, 0.0, 1e-15)
check("reduce: shear P", float(red["p_kinetic"][1, 1]), 0.0, 0.0, 1e-15)
check("reduce: shear tau", float(red["tau_kinetic"][1, 1]), 3.0, 1e-12)
if sorted(red) != sorted(["x", "z", "density", "volume_fraction", "velocity_x", "velocity_z", "p_contact",
                          "tau_contact", "p_kinetic", "tau_kinetic"]):
    failures.append(f"reduce keys: {sorted(red)}")

with tempfile.TemporaryDirectory() as tmp:
    # the mass record of a uniform XZ grid: rho dx dz depth x the points
    csv = os.path.join(tmp, "m.csv")
    with open(csv, "w") as fh:
        fh.write("x,z,density\n")
        for xi in (0.5, 1.5, 2.5):
            for zi in (0.5, 1.5):
                fh.write(f"{xi},{zi},10\n")
    log = os.path.join(tmp, "m.log")
    with open(log, "w") as fh:
        fh.write("granairCG: mass on the grid 12 kg, particle mass in the window 12.06 kg\n")
    rec = cg_runs.mass_record(csv, log, depth=0.2)
    check("mass_record grid", rec["grid_mass_kg"], 6 * 10 * 0.2)
    check("mass_record relative", rec["relative_difference"], 12 / 12.06 - 1, 1e-12)
    # nonfinite
    good, badf = os.path.join(tmp, "a.csv"), os.path.join(tmp, "b.csv")
    series.write_csv(good, [("density", np.ones(3)), ("p_contact", np.zeros(3))])
    series.write_csv(badf, [("density", np.ones(3)), ("p_contact", np.array([0.0, math.nan, 1.0]))])
    bad, n = cg_runs.nonfinite([good, badf], ("density", "p_contact"))
    check("nonfinite count", n, 12)
    if bad != ["b.csv:p_contact"]:
        failures.append(f"nonfinite: {bad}")
    from granair_cases import checks
    ch = checks.Checks("unit")
    full = os.path.join(tmp, "c.csv")
    series.write_csv(full, [(k, np.ones(2)) for k in ("density", "p_contact", "tau_contact", "p_kinetic", "tau_kinetic")])
    cg_runs.check(ch, "run", [full], rec, 1e-3)             # finite; 12 vs 12.06 kg is 0.5 % off
    if [ln[:4] for ln in ch.lines] != ["PASS", "FAIL"]:
        failures.append(f"cg_runs.check: {ch.lines}")
    # Batch: a stand-in granairCG that writes <out>.csv; a second run is skipped
    bindir = os.path.join(tmp, "bin")
    os.makedirs(bindir)
    prog = os.path.join(bindir, "granairCG")
    with open(prog, "w") as fh:
        fh.write('#!/bin/sh\nwhile [ $# -gt 0 ]; do [ "$1" = --out ] && out=$2; shift; done\n'
                 'echo "x,z,density" > "$out.csv"\necho ran >> "$(dirname "$0")/calls"\n')
    os.chmod(prog, os.stat(prog).st_mode | stat.S_IEXEC)
    old_path = os.environ["PATH"]
    os.environ["PATH"] = bindir + os.pathsep + old_path
    try:
        case = os.path.join(tmp, "case")
        os.makedirs(case)
        b = cg_runs.Batch(case, [("dt", 1e-5)], True, "needs dumps", "test")
        b.run("post/fields/one", {"kernel": "gauss"}, "gauss1, whole window")
        b.run("post/fields/one", {"kernel": "gauss"}, "gauss1, whole window")
        with open(os.path.join(bindir, "calls")) as fh:
            check("Batch: one run for two calls", len(fh.read().split()), 1)
        cost = os.path.join(tmp, "cost.txt")
        b.write_costs(cost, [("snapshots", 3)], "test")
        b.write_costs(cost, [("snapshots", 3)], "test")
        k = series.read_keys(cost)
        if "gauss1_whole_window_cpu_s" not in k or k["snapshots"] != 3:
            failures.append(f"write_costs keys: {k}")
        check("write_costs: total over passes", k["total_cpu_s"], round(2 * b.cpu, 1), 1e-9, 0.051)
        try:
            cg_runs.Batch(case, [], False, "needs the dumps", "test").run("post/fields/two", {}, "x")
            failures.append("Batch without dumps: no CaseError")
        except CaseError as err:
            if "needs the dumps" not in str(err):
                failures.append(f"Batch error: {err}")
    finally:
        os.environ["PATH"] = old_path

# --- profile_plots: the lines drawn -----------------------------------------------------
plt = plots.pyplot()
fig, ax = plt.subplots()
c = profile_plots.paraboloid(ax, np.array([0.0, 0.5]), np.array([0.3, 0.225]), 1.0, 0.3, "p", "o")
xl, yl = ax.lines[1].get_data()
check("paraboloid curve", float(np.max(abs(yl - 0.3 * (1 - xl ** 2)))), 0.0, 0.0, 1e-15)
if ax.lines[1].get_color() != c:
    failures.append("paraboloid: the curve not in the points' colour")
fig2, axes = plt.subplots(1, 2)
profile_plots.at_heights(axes, {"a": {"x": x, "z": z, "u": Xg * 2.0, "w": Zx * 1.0}, "b": {"x": x, "z": z, "u": Xg,
                                                                                            "w": Zx}},
                         "x", ["u", "w"], [0.0, 1.0], 2.0, "a", d=1.0)
check("at_heights: lines", len(axes[0].lines), 4)
check("at_heights: u / scale", float(axes[0].lines[0].get_ydata()[3]), x[3], 1e-12)
check("at_heights: w at z = 1", float(axes[1].lines[2].get_ydata()[0]), 0.5, 1e-12)
if axes[0].lines[1].get_label().startswith("z ="):
    failures.append("at_heights: only the first grid's lines are labelled")
with tempfile.TemporaryDirectory() as tmp:
    png = profile_plots.profiles_figure(os.path.join(tmp, "p.png"), {"a": {"x": x, "z": z, "u": Xg, "w": Zx}}, "x",
                                        ["u", "w"], ["u", "w"], [0.0, 1.0], 1.0, "a", mark=0.5, suptitle=True)
    if not os.path.getsize(png) > 1000:
        failures.append("profiles_figure: no picture")
fig3, ax3 = plt.subplots()
ax3.plot([0, 1], [0, 10])
profile_plots.rates(ax3, [("run", np.array([0.0, 1.0]), np.array([5.0, 6.0]), (4.0, 7.0))], 0.5)
check("rates: lines (data, run, window)", len(ax3.lines), 3)
check("rates: one band", len(ax3.patches), 1)
for fg_ in (fig, fig2, fig3):
    plt.close(fg_)

# --- the committed orifice-arch fields against its committed arch table ----------------
fields_dir = os.path.join(ROOT, "cases", "orifice-arch", "results", "fields")
if os.path.exists(os.path.join(fields_dir, "silo_R4_gauss1.csv")):
    from granair_cases import cg_grids
    rows = {(r_["variant"], r_["R_over_d"], r_["kernel"], r_["w_over_d"]): r_
            for r_ in series.read_table(os.path.join(fields_dir, "arch.csv"))}
    d = 1 / 32
    for var, R_d, ax_ in (("silo", 4, "r"), ("slab", 17, "x")):
        red = cg_grids.read(os.path.join(fields_dir, f"{var}_R{R_d}_gauss1.csv"), ax_)
        a_ = arch.paraboloid(*arch.kinetic_max(red, ax_, R_d * d), R_d * d)[0]
        want = [v for k, v in rows.items() if k[0] == var and float(k[1]) == R_d and k[2] == "gauss"
                and float(k[3]) == 1.0][0]
        check(f"committed {var} R = {R_d} d alpha (arch.csv, 6 digits)", a_, float(want["alpha"]), 5e-6)

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("arch, cg_runs, profile_plots: all checks passed")
