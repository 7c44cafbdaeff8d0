#!/usr/bin/env python3
"""verify.py: the continuum solver against closed forms (README.md).

Usage: verify.py [--case inclined-plane|couette-coulomb|all] [--out DIR] [--check]
                 [--cells N] [--end T]

  inclined-plane   steady mu(I) flow down a plane (Bagnold profile), the Jop
                   form and the Barker & Gray (2017) form: 2 runs
  couette-coulomb  plane shear over a Coulomb wall, one run per regime:
                   stick, slide of a sheared layer, rigid sliding: 3 runs

Each run is a granairContinuumFoam case written here (blockMesh, fields,
dictionaries) in DIR/runs/<name>; results in DIR: <name>.csv (y, u, u_exact),
profiles.png, summary.txt (key = value). --check exits 1 unless
  inclined plane:  max |u - u_exact| over the powder cells <= 1 % of the
                   exact surface velocity, the flux within 1 %, and steady
                   (the last two written profiles within 1e-4 of each other);
  couette-coulomb: max |u - u_exact| <= 0.5 % of the wall velocity, the
                   regime (stick / slide) as the closed form says, and steady
                   (the last two written profiles within 1e-4 of V).
"""
import argparse
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import exact  # noqa: E402

# Glass beads of Jop, Forterre & Pouliquen (2006).
GLASS = dict(muS=math.tan(math.radians(20.9)), mu2=math.tan(math.radians(32.76)), I0=0.279, d=0.53e-3,
             rhoP=2450.0, etaMax=1e5, gammaDotMin=1e-6)
PHI = 0.6                  # solid fraction of the flowing layer (bulk density PHI rho_p)
THETA = 25.0               # plane inclination [deg]: tan 25 = 0.466 between mu_s and mu_2
DEPTH_D = 20               # layer depth in grain diameters
AIR = dict(rho=1.2, mu=1.8e-5)

COUETTE_H = 10e-3          # layer height [m]
COUETTE_V = 0.5            # top wall velocity [m/s]
COUETTE_P = 1000.0         # pressure [Pa]
# (name, mu_w): the no-slip shear (I = 0.0415) needs mu = 0.416: 0.5 holds it,
# 0.40 lets a sheared layer slide, 0.30 < mu_s a rigid block slide.
COUETTE_RUNS = [("couette-stick", 0.50), ("couette-slide", 0.40), ("couette-rigid", 0.30)]

RUNS = {"inclined-plane": [("plane-jop", "none"), ("plane-barkerGray", "barkerGray2017")],
        "couette-coulomb": COUETTE_RUNS}


def header(cls, obj):
    return "FoamFile { version 2.0; format ascii; class %s; object %s; }\n" % (cls, obj)


def rheology_block(regularisation):
    q = GLASS
    lines = ["rheology", "{", "    type        muI;"]
    for k in ("muS", "mu2", "I0", "d", "rhoP", "etaMax", "gammaDotMin"):
        lines.append("    %-11s %.10g;" % (k, q[k]))
    lines.append("    regularisation %s;" % regularisation)
    lines.append("}")
    return "\n".join(lines) + "\n"


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as fh:
        fh.write(text)


def block_mesh(lx, ly, ny, top_type):
    return header("dictionary", "blockMeshDict") + f"""convertToMeters 1;
vertices ( (0 0 0) ({lx} 0 0) ({lx} {ly} 0) (0 {ly} 0) (0 0 {lx}) ({lx} 0 {lx}) ({lx} {ly} {lx}) (0 {ly} {lx}) );
blocks ( hex (0 1 2 3 4 5 6 7) (1 {ny} 1) simpleGrading (1 1 1) );
edges ();
boundary
(
    left   {{ type cyclic; neighbourPatch right; faces ((0 4 7 3)); }}
    right  {{ type cyclic; neighbourPatch left;  faces ((1 2 6 5)); }}
    bottom {{ type wall; faces ((0 1 5 4)); }}
    top    {{ type {top_type}; faces ((3 7 6 2)); }}
    frontAndBack {{ type empty; faces ((0 3 2 1) (4 5 6 7)); }}
);
mergePatchPairs ();
"""


def control_dict(end, dt_max, write_interval):
    return header("dictionary", "controlDict") + f"""application granairContinuumFoam;
startFrom startTime; startTime 0; stopAt endTime; endTime {end};
deltaT 1e-4; writeControl adjustableRunTime; writeInterval {write_interval}; purgeWrite 0;
writeFormat ascii; writePrecision 12; writeCompression off; timeFormat general; timePrecision 8;
runTimeModifiable false; adjustTimeStep yes; maxCo 0.4; maxAlphaCo 0.4; maxDeltaT {dt_max};
"""


FV_SCHEMES = header("dictionary", "fvSchemes") + """ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default none; div(rhoPhi,U) Gauss linearUpwind grad(U); div(phi,alpha) Gauss vanLeer;
             div(phirb,alpha) Gauss linear; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
"""


def fv_solution(p_ref):
    ref = f"pRefCell 0; pRefValue {p_ref};" if p_ref is not None else ""
    return header("dictionary", "fvSolution") + f"""solvers
{{
    alpha.powder {{ nAlphaCorr 2; cAlpha 1; nLimiterIter 3; }}
    p_rgh {{ solver PCG; preconditioner DIC; tolerance 1e-12; relTol 0.01; minIter 1; }}
    p_rghFinal {{ $p_rgh; relTol 0; }}
    "U|UFinal" {{ solver PBiCGStab; preconditioner DILU; tolerance 1e-12; relTol 0; }}
}}
PIMPLE
{{
    momentumPredictor yes; nOuterCorrectors 1; nCorrectors 3;
    nNonOrthogonalCorrectors 0; pressureCorrection inertial; transposeStress on; {ref}
}}
relaxationFactors {{ equations {{ ".*" 1; }} }}
"""


def scalar_field(name, internal, patches, dims="[0 0 0 0 0 0 0]"):
    body = "\n".join("    %s { %s }" % (k, v) for k, v in patches.items())
    return header("volScalarField", name) + f"dimensions {dims};\ninternalField {internal};\nboundaryField\n{{\n{body}\n}}\n"


def vector_field(name, internal, patches):
    body = "\n".join("    %s { %s }" % (k, v) for k, v in patches.items())
    return header("volVectorField", name) + f"dimensions [0 1 -1 0 0 0 0];\ninternalField {internal};\nboundaryField\n{{\n{body}\n}}\n"


def nonuniform(values):
    return "nonuniform List<scalar> %d (%s)" % (len(values), " ".join("%g" % v for v in values))


def properties(rho_powder, regularisation, acceleration, outlet):
    return f"""// written by cases/continuum-verification/verify.py
outletPatch {outlet};
acceleration ({acceleration[0]:.12g} {acceleration[1]:.12g} {acceleration[2]:.12g});
viscosityRelaxation 0.5;
powder {{ rho {rho_powder:.10g}; }}
air {{ rho {AIR['rho']}; mu {AIR['mu']}; model none; }}
""" + rheology_block(regularisation)


CYCLIC = {"left": "type cyclic;", "right": "type cyclic;", "frontAndBack": "type empty;"}


def setup_plane(run, regularisation, cells, end):
    """Layer of DEPTH_D grains on a plane at THETA: gravity's normal part in
    constant/g, its along-slope part as the uniform acceleration (periodic in x)."""
    h = DEPTH_D * GLASS["d"]
    dy = h / cells
    n_air = max(4, cells // 6)
    ny = cells + n_air
    th = math.radians(THETA)
    write(os.path.join(run, "system", "blockMeshDict"), block_mesh(2 * h, ny * dy, ny, "patch"))
    write(os.path.join(run, "system", "controlDict"), control_dict(end, 5e-3, end / 8))
    write(os.path.join(run, "system", "fvSchemes"), FV_SCHEMES)
    write(os.path.join(run, "system", "fvSolution"), fv_solution(None))
    write(os.path.join(run, "constant", "g"), header("uniformDimensionedVectorField", "g")
          + "dimensions [0 1 -2 0 0 0 0];\nvalue (0 %.12g 0);\n" % (-exact.G * math.cos(th)))
    write(os.path.join(run, "constant", "granularProperties"),
          properties(PHI * GLASS["rhoP"], regularisation, (exact.G * math.sin(th), 0, 0), "top"))
    alpha = [1.0 if j < cells else 0.0 for j in range(ny)]
    walls = dict(CYCLIC, bottom="type zeroGradient;", top="type zeroGradient;")
    write(os.path.join(run, "0", "alpha.powder"), scalar_field("alpha.powder", nonuniform(alpha), walls))
    write(os.path.join(run, "0", "U"), vector_field("U", "uniform (0 0 0)", dict(
        CYCLIC, bottom="type noSlip;", top="type slip;")))
    write(os.path.join(run, "0", "p_rgh"), scalar_field("p_rgh", "uniform 0", dict(
        CYCLIC, bottom="type fixedFluxPressure; value uniform 0;",
        top="type prghPressure; p uniform 0; value uniform 0;"), "[1 -1 -2 0 0 0 0]"))
    return dict(h=h, dy=dy, ny=ny, cells=cells)


def setup_couette(run, mu_w, cells, end):
    H = COUETTE_H
    write(os.path.join(run, "system", "blockMeshDict"), block_mesh(H, H, cells, "wall"))
    write(os.path.join(run, "system", "controlDict"), control_dict(end, 1e-3, end / 8))
    write(os.path.join(run, "system", "fvSchemes"), FV_SCHEMES)
    write(os.path.join(run, "system", "fvSolution"), fv_solution(COUETTE_P))
    write(os.path.join(run, "constant", "g"), header("uniformDimensionedVectorField", "g")
          + "dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 0);\n")
    write(os.path.join(run, "constant", "granularProperties"),
          properties(PHI * GLASS["rhoP"], "none", (0, 0, 0), "top"))
    walls = dict(CYCLIC, bottom="type zeroGradient;", top="type zeroGradient;")
    write(os.path.join(run, "0", "alpha.powder"), scalar_field("alpha.powder", "uniform 1", walls))
    # Start from the no-slip shear profile (not from rest, where the whole layer
    # would sit at the viscosity cap).
    u0 = "nonuniform List<vector> %d (%s)" % (cells, " ".join(
        "(%g 0 0)" % (COUETTE_V * (j + 0.5) / cells) for j in range(cells)))
    write(os.path.join(run, "0", "U"), vector_field("U", u0, dict(
        CYCLIC, bottom="type coulombWallSlip; frictionCoefficient %.10g; value uniform (0 0 0);" % mu_w,
        top="type fixedValue; value uniform (%g 0 0);" % COUETTE_V)))
    write(os.path.join(run, "0", "p_rgh"), scalar_field("p_rgh", "uniform %g" % COUETTE_P, dict(
        CYCLIC, bottom="type fixedFluxPressure; value uniform %g;" % COUETTE_P,
        top="type fixedFluxPressure; value uniform %g;" % COUETTE_P), "[1 -1 -2 0 0 0 0]"))
    return dict(H=H, dy=H / cells, ny=cells, cells=cells)


def run_case(run):
    t0 = time.time()
    for app in (["blockMesh"], ["granairContinuumFoam"]):
        log = os.path.join(run, "log." + app[0])
        with open(log, "w") as fh:
            if subprocess.run(app, cwd=run, stdout=fh, stderr=subprocess.STDOUT).returncode != 0:
                tail = open(log).read().splitlines()[-25:]
                sys.exit(f"verify.py: {app[0]} failed in {run}; last lines of {log}:\n" + "\n".join(tail))
    return time.time() - t0


def times(run):
    out = []
    for d in os.listdir(run):
        try:
            t = float(d)
        except ValueError:
            continue
        if t > 0 and os.path.exists(os.path.join(run, d, "U")):
            out.append((t, d))
    return [d for _, d in sorted(out)]


def read_ux(path):
    """x components of the cell velocities of an ASCII volVectorField (a list
    on many lines, or inline as OpenFOAM writes short ones), or (None, value)
    for a uniform field."""
    text = open(path).read()
    start = text.find("internalField")
    body = text[start:text.find("boundaryField", start)]
    m = re.search(r"uniform\s+\(([^)]*)\)", body)
    if "nonuniform" not in body:
        if not m:
            sys.exit(f"verify.py: cannot read the internalField of {path}")
        return None, float(m.group(1).split()[0])
    n = int(re.search(r"List<vector>\s*(\d+)", body).group(1))
    vecs = re.findall(r"\(([-+0-9.eE]+)\s+[-+0-9.eE]+\s+[-+0-9.eE]+\)", body)
    if len(vecs) != n:
        sys.exit(f"verify.py: {path} lists {len(vecs)} vectors, header says {n}")
    return [float(v) for v in vecs], None


def profile(run, geo, time_dir):
    """u_x per cell row, bottom to top."""
    ux, uniform = read_ux(os.path.join(run, time_dir, "U"))
    return [uniform] * geo["ny"] if ux is None else ux


def check_plane(name, regularisation, run, geo, out, wall):
    q = dict(GLASS, regularisation=regularisation)
    h, dy = geo["h"], geo["dy"]
    tdirs = times(run)
    u = profile(run, geo, tdirs[-1])
    u_prev = profile(run, geo, tdirs[-2])
    rows, err, flux, flux_exact = [], 0.0, 0.0, exact.bagnold_flux(h, THETA, PHI, q)
    us, I = exact.bagnold(h, h, THETA, PHI, q)
    for j in range(geo["cells"]):
        y = (j + 0.5) * dy
        ue, _ = exact.bagnold(y, h, THETA, PHI, q)
        rows.append((y, u[j], ue))
        err = max(err, abs(u[j] - ue))
        flux += u[j] * dy
    steady = max(abs(a - b) for a, b in zip(u[:geo["cells"]], u_prev[:geo["cells"]])) / us
    res = dict(name=name, regularisation=regularisation, theta_deg=THETA, depth_m=h, cells_in_layer=geo["cells"],
               inertial_number=I, surface_velocity_exact_m_s=us, surface_cell_velocity_m_s=u[geo["cells"] - 1],
               max_error_over_surface_velocity=err / us, flux_m2_s=flux, flux_exact_m2_s=flux_exact,
               flux_error=(flux - flux_exact) / flux_exact, change_last_two_writes=steady,
               times=f"{tdirs[-2]} {tdirs[-1]}", run_wall_s=wall)
    ok = res["max_error_over_surface_velocity"] <= 0.01 and abs(res["flux_error"]) <= 0.01 and steady <= 1e-4
    return res, rows, ok


def check_couette(name, mu_w, run, geo, out, wall):
    q = dict(GLASS, regularisation="none")
    H, dy = geo["H"], geo["dy"]
    tdirs = times(run)
    u = profile(run, geo, tdirs[-1])
    u_prev = profile(run, geo, tdirs[-2])
    steady = max(abs(a - b) for a, b in zip(u, u_prev)) / COUETTE_V
    rows, err = [], 0.0
    regime = None
    for j in range(geo["cells"]):
        y = (j + 0.5) * dy
        ue, regime, gd = exact.couette_coulomb(y, H, COUETTE_V, COUETTE_P, mu_w, q)
        rows.append((y, u[j], ue))
        err = max(err, abs(u[j] - ue))
    slip_exact = exact.couette_coulomb(0.0, H, COUETTE_V, COUETTE_P, mu_w, q)[0]
    # wall velocity of the run: extrapolate the two lowest cells to y = 0
    slip = u[0] - 0.5 * (u[1] - u[0])
    res = dict(name=name, friction_coefficient=mu_w, regime_exact=regime, shear_rate_exact_1_s=gd,
               slip_velocity_exact_m_s=slip_exact, slip_velocity_m_s=slip,
               max_error_over_wall_velocity=err / COUETTE_V, change_last_two_writes=steady,
               times=f"{tdirs[-2]} {tdirs[-1]}", cells=geo["cells"], run_wall_s=wall)
    run_regime = "stick" if abs(slip) < 1e-3 * COUETTE_V else "slide"
    res["regime_run"] = run_regime
    ok = res["max_error_over_wall_velocity"] <= 0.005 and run_regime == regime and steady <= 1e-4
    return res, rows, ok


def plot(results, out):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("verify.py: matplotlib missing, no profiles.png")
        return
    n = len(results)
    fig, axes = plt.subplots(1, n, figsize=(3.2 * n, 3.8), squeeze=False)
    for ax, (res, rows) in zip(axes[0], results):
        y = [r[0] * 1e3 for r in rows]
        ax.plot([r[2] for r in rows], y, "k-", lw=1.5, label="closed form")
        ax.plot([r[1] for r in rows], y, "o", ms=3, mfc="none", color="C0", label="granairContinuumFoam")
        ax.set_xlabel("u [m/s]")
        ax.set_ylabel("y [mm]")
        ax.set_title(res["name"], fontsize=9)
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "profiles.png"), dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--case", choices=["inclined-plane", "couette-coulomb", "all"], default="all")
    ap.add_argument("--out", default=os.path.join(HERE, "results"))
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--cells", type=int, default=None, help="cells across the layer (default 80 plane, 10 Couette)")
    ap.add_argument("--end", type=float, default=None, help="simulated time [s] (default 8 plane, 10 Couette)")
    a = ap.parse_args()
    out = os.path.abspath(a.out)
    os.makedirs(out, exist_ok=True)
    kinds = ["inclined-plane", "couette-coulomb"] if a.case == "all" else [a.case]
    results, failed, summary = [], [], []
    for kind in kinds:
        for name, param in RUNS[kind]:
            run = os.path.join(out, "runs", name)
            shutil.rmtree(run, ignore_errors=True)
            if kind == "inclined-plane":
                geo = setup_plane(run, param, a.cells or 80, a.end or 8.0)
            else:
                geo = setup_couette(run, param, a.cells or 10, a.end or 10.0)
            print(f"verify: {name} ...", flush=True)
            wall = run_case(run)
            check = check_plane if kind == "inclined-plane" else check_couette
            res, rows, ok = check(name, param, run, geo, out, wall)
            with open(os.path.join(out, name + ".csv"), "w", newline="") as fh:
                w = csv.writer(fh)
                w.writerow(["y_m", "u_m_s", "u_exact_m_s"])
                w.writerows(rows)
            results.append((res, rows))
            summary += [f"[{name}]"] + [f"{k} = {v:.6g}" if isinstance(v, float) else f"{k} = {v}"
                                       for k, v in res.items() if k != "name"] + [f"pass = {int(ok)}", ""]
            print("verify: %s %s (%.0f s): %s" % (name, "PASS" if ok else "FAIL", wall, ", ".join(
                f"{k} {v:.4g}" for k, v in res.items() if isinstance(v, float) and ("error" in k or "velocity" in k))),
                flush=True)
            if not ok:
                failed.append(name)
    with open(os.path.join(out, "summary.txt"), "w") as fh:
        fh.write("\n".join(summary))
    plot(results, out)
    print(f"verify: results in {out} (summary.txt, profiles.png, one CSV per run)")
    if a.check and failed:
        print("verify: FAILED: " + ", ".join(failed), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
