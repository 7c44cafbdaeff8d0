#!/usr/bin/python3
"""The MCC hopper at the two-fluid level (issue 17; docs/two-fluid-model.md):
Debian's twoPhaseEulerFoam with granair's muI frictional stress (the literature
mu(I) of Remmelgas et al. 2019, rheology/muI), granair drag (ErgunGidaspow on
the 660 um spheres) and Coulomb walls (mu_w of parameters.py), with air and dry,
on an axisymmetric staircase wedge.

    twofluid.py [--air on|off|both] [--dry drag|viscosity] [--rheology-from literature|calibration]
                [--mesh N] [--end T] [--chunk T]
                [--steady-from T] [--resume] [--out DIR] [--setup-only]

--rheology-from calibration: the DEM calibration's mu(I) at the primary
660 um in I, filled at its phi_max; --shear-pressure-phi-max alphaMax puts
p_I's packing at the contact law's alphaMax (the calibrated phiMax 0.591 is
below it; README "Two-fluid level").

Dry: the solver has two phases, so the air stays, all but uncoupled: by
default its drag times 1/100 (`--dry drag`, granair drag's `scale`), or its
viscosity times 1/100 as the wedge silo's dry runs (`--dry viscosity`), which
keeps Ergun's inertial term: for these 660 um spheres (Re_p ~ 10 at the
orifice) a quarter of the drag, so such a "dry" run is still slowed by air.

The mesh (staircase()): a 5 deg wedge about the axis, as the continuum level's,
but of rectangular cells, N across the orifice radius (default 5: 2.5 mm,
3.8 grains) and the cylinder's annulus in cells as close to that as its width
allows; the free fall below the orifice as the continuum's (12.5 mm); the cells
whose centres lie outside the cone removed (their faces become the walls).
Why rectangular: Debian's twoPhaseEulerFoam gives wrong cell velocities in
non-orthogonal cells (docs/two-fluid-model.md, "On a silo"). The fill: the
cells whose centres lie below the row boundary nearest to the 1000 g fill at
the bulk density 900 kg/m3 (solid fraction 0.6), its mass as filled (the
staircase's volume, exact for this wedge: pi/tan(2.5 deg) wedges make the
hopper) in summary.txt. The dictionaries are the wedge silo's two-fluid
template (cases/wedge-silo/two-fluid/template, gc.two_fluid), the frictional
closure's numbers gc.two_fluid.closure()'s, as there.

Per run OUT/<air|noair>/: timeseries.csv (10 ms means: t, W [kg/s] of the full
hopper through the outlet and the free fall's side, outlet dp/dz [Pa/m]: the
area-weighted mean over the orifice's cells of the gradient between the cell
centres just above and below the orifice plane (as DEM-CFD's outlet monitor;
runs before 2026-12-07 had one pair on the axis, gc.two_fluid.series), the mean
solid fraction of the cell row just above the orifice), summary.txt (their
means over [--steady-from, end], the fill, the cost), level.json (level
`two-fluid`); OUT/summary.md, the two runs beside the continuum (with and
without air) and the coarse-grained DEM (dry) of the committed references:
W, the air effect and the outlet gradient. A run goes in chunks of --chunk s
(--resume goes on from the newest time folder).
"""
import math
import os

import numpy as np

import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))
T = os.path.join(HERE, "..", "wedge-silo", "two-fluid", "template")
BLOCK = 0.01      # [s] timeseries.csv's block means (the continuum's mass_flow.csv window)
# the full hopper is this many wedges (the wedge's faces at +-r tan(a): exact)
WEDGES = math.pi / math.tan(P.WEDGE_HALF_ANGLE)
PHI = P.RHO_BULK / P.RHO_P    # the fill's solid fraction
DRY = gc.two_fluid.DRY


def layout(n):
    """The staircase: cell size dr = dz in the orifice column (n across its radius), the
    annulus' cells, the rows, and per row the outer cells kept (centre inside the cone)."""
    dz = P.R_OUT / n
    ns = max(1, round((P.R_CYL - P.R_OUT) / dz))
    dr2 = (P.R_CYL - P.R_OUT) / ns
    nf = max(1, round(P.FREEFALL / dz))
    # rows up to 20 mm above the fill at the cone's true volume (the staircase holds about as much)
    nz = math.ceil((P.fill_height(P.FILL_MASS) + 0.02) / dz)
    kept = []
    for k in range(nz):
        zc = (k + 0.5) * dz
        kept.append(sum(1 for i in range(ns) if P.R_OUT + (i + 0.5) * dr2 <= P.R_OUT + zc * P.TAN_CONE))
    return dict(dz=dz, ns=ns, dr2=dr2, nf=nf, nz=nz, kept=kept)


def fill(lay, phi=PHI):
    """The fill: the row boundary whose powder below it (solid fraction phi) is nearest
    the fill mass, and that mass [g] (full hopper)."""
    best, mass = (0.0, 0.0), 0.0
    for k, m in enumerate(lay["kept"]):
        r_outer = P.R_OUT + m * lay["dr2"]
        mass += P.RHO_P * phi * math.pi * r_outer ** 2 * lay["dz"]
        if abs(mass - P.FILL_MASS) < abs(best[1] - P.FILL_MASS):
            best = ((k + 1) * lay["dz"], mass)
    return best[0], best[1] * 1e3


def staircase(run, lay):
    """system/blockMeshDict (three blocks of the wedge: the free fall, the orifice
    column and the annulus up to the top) and system/topoSetDict (cellSet silo:
    all but the annulus cells outside the cone)."""
    t = math.tan(P.WEDGE_HALF_ANGLE)
    n, dz = round(P.R_OUT / lay["dz"]), lay["dz"]
    zf, h = lay["nf"] * dz, lay["nz"] * dz
    axis = [(0.0, -zf), (0.0, 0.0), (0.0, h)]
    rims = [(P.R_OUT, -zf), (P.R_OUT, 0.0), (P.R_OUT, h), (P.R_CYL, 0.0), (P.R_CYL, h)]
    pts = [(0.0, 0.0, z) for _, z in axis]
    for r, z in rims:     # front (y = -r tan a), then back
        pts += [(r, -r * t, z), (r, r * t, z)]
    verts = "\n".join(f"    ({x:.17g} {y:.17g} {z:.17g})" for x, y, z in pts)
    # 0 1 2: the axis at -zf, 0, h; 3/4, 5/6, 7/8: the orifice rim (front/back) at -zf, 0, h;
    # 9/10, 11/12: the cylinder wall at 0, h
    text = f"""FoamFile {{ version 2.0; format ascii; class dictionary; object blockMeshDict; }}
// The MCC hopper as a staircase wedge of rectangular cells (cases/mcc-hopper/twofluid.py staircase()):
// {n} cells of {dz * 1e3:g} mm across the orifice radius, {lay['ns']} of {lay['dr2'] * 1e3:.4g} mm across the annulus.
scale 1;
vertices
(
{verts}
);
blocks
(
    hex (0 4 6 1 0 3 5 1) ({n} {lay['nf']} 1) simpleGrading (1 1 1)          // free fall
    hex (1 6 8 2 1 5 7 2) ({n} {lay['nz']} 1) simpleGrading (1 1 1)          // orifice column
    hex (6 10 12 8 5 9 11 7) ({lay['ns']} {lay['nz']} 1) simpleGrading (1 1 1)   // annulus
);
boundary
(
    outlet     {{ type patch; faces ((0 0 4 3)); }}
    freefall   {{ type patch; faces ((3 4 6 5)); }}
    atmosphere {{ type patch; faces ((2 7 8 2) (7 11 12 8)); }}
    walls      {{ type wall;  faces ((5 9 10 6) (9 10 12 11)); }}
    front      {{ type wedge; faces ((0 3 5 1) (1 5 7 2) (5 9 11 7)); }}
    back       {{ type wedge; faces ((0 1 6 4) (1 2 8 6) (6 8 12 10)); }}
    axis       {{ type empty; faces ((0 1 1 0) (1 2 2 1)); }}
);
"""
    gc.template.write(os.path.join(run, "system", "blockMeshDict"), text)
    gc.two_fluid.silo_cells(run, [(P.R_OUT + m * lay["dr2"] + 1e-9, k * dz + 1e-9, 1, (k + 1) * dz - 1e-9)
                                  for k, m in enumerate(lay["kept"]) if m < lay["ns"]])


def numbers(a, air):
    lay = layout(a.mesh)
    block = os.path.join(HERE, "rheology", "muI")
    with open(block) as fh:
        rheology = gc.template.fill(fh.read(), dict(ETA_MAX=P.ETA_MAX), block)
    phi = PHI
    if a.rheology_from == "calibration":
        # the DEM calibration's mu(I) and phi(I) at the primary 660 um in I (as the
        # continuum's results/calibrated/d660um), filled at its phi_max
        f = gc.calibration.fit(P.CALIBRATION)
        rheology = gc.calibration.block(rheology, P.CALIBRATION, d=P.D_PARTICLE, where=block)
        phi = f["rho_p"] * f["phi_max"] / P.RHO_P
    if a.shear_pressure_phi_max is not None:
        # as the wedge silo's --shear-pressure-phi-max: p_I's packing at alphaMax
        # (or a number), phiMin moved with it
        phi_p = gc.two_fluid.p_i_phi_max(a.shear_pressure_phi_max, gc.two_fluid.closure(phi)["ALPHA_MAX"])
        span = gc.calibration.entry(rheology, "phiMax", block) - gc.calibration.entry(rheology, "phiMin", block)
        rheology = gc.two_fluid.p_i_packing(rheology, phi_p, span, "twofluid.py --shear-pressure-phi-max (span kept)")
    fill_z, fill_g = fill(lay, phi)
    dz = lay["dz"]
    mu_factor, drag_scale = gc.two_fluid.dry(air, a.dry)
    v = dict(gc.two_fluid.closure(phi), N=a.mesh, RHEOLOGY_FROM=a.rheology_from, AIR=int(air), END=a.end, WRITE_INTERVAL=a.chunk,
             TITLE=f"The MCC hopper (cases/mcc-hopper/twofluid.py), {'with air' if air else 'dry'}",
             D=P.D_PARTICLE, D_DRAG=P.D_PARTICLE, RHO_P=P.RHO_P, G=P.G, RHO_F=P.AIR_RHO,
             MU=P.AIR_MU * mu_factor, DRAG_SCALE=drag_scale,
             AIR_EOS="rhoConst",
             DRAG_LAW="ErgunGidaspow", PHI_FILL=phi, FILL=fill_z, FILL_G=fill_g, WALL_FRICTION=P.WALL_FRICTION,
             RHEOLOGY=rheology, PROBE_Z=dz / 2,
             # the outlet's dp/dz: the orifice's N cells and the N below, their mean
             # weighted by area (the wedge's faces at radius r: width ~ r), as
             # DEM-CFD's outlet monitor averages snGrad(p) over the orifice's faces
             ORIFICE_PROBES=gc.two_fluid.orifice_probes(orifice_rs(a.mesh, dz), dz),
             SLOT_ROW_PROBES=gc.two_fluid.row_probes(orifice_rs(a.mesh, dz), dz / 2))
    return v, lay


def orifice_rs(n, dz):
    """The radii of the centres of the orifice's n cells (dz across each)."""
    return [(i + 0.5) * dz for i in range(n)]


def post(run, out, name, v, a, rec):
    os.makedirs(out, exist_ok=True)
    rs = orifice_rs(v["N"], 2 * v["PROBE_Z"])
    t, w, dpdz, alpha = gc.two_fluid.series(run, 2 * v["PROBE_Z"], v["N"], f"mcc-hopper two-fluid {name}",
                                            xs=rs, weights=rs, patch="front")
    w = w * WEDGES
    dt = gc.series.step_lengths(t)
    ends, blocks = gc.two_fluid.block_means(t, dt, [w, dpdz, alpha], BLOCK)
    gc.series.write_csv(os.path.join(out, "timeseries.csv"),
                        [("t", ends), ("mass_flow_kg_s", blocks[0]), ("outlet_dpdz_Pa_m", blocks[1]),
                         ("orifice_row_alpha", blocks[2])])
    t0, t1 = a.steady_from, float(t[-1])
    W, G, A = (gc.series.time_mean(t, x, t0, t1, dt=dt) for x in (w, dpdz, alpha))
    out_g = float(np.sum(w * dt)) * 1e3
    wall = sum(c["wall_s"] for c in rec["chunks"])
    cells = gc.foam.checkmesh(os.path.join(run, "log", "checkMesh.log"))[0]
    gc.series.write_keys(os.path.join(out, "summary.txt"),
                         [("W_kg_s", W), ("outlet_dpdz_Pa_m", G), ("orifice_row_alpha", A), ("window_t0_s", t0),
                          ("window_t1_s", t1), ("discharged_g", out_g), ("fill_g", v["FILL_G"]),
                          ("fill_z_m", v["FILL"]), ("cells", cells), ("cpu_s", rec["cpu_s"]), ("wall_s", wall)])
    air = bool(v["AIR"])
    gc.levels.write(os.path.join(out, "level.json"), case="mcc-hopper", level="two-fluid",
                    # what tells the runs apart first (the compare plot's legend cuts long names)
                    model=(("with air" if air else DRY[a.dry]) + f", staircase wedge R_o/{v['N']}: twoPhaseEulerFoam + "
                           "granair muI (" + ("DEM-calibrated mu(I), d 660 um in I" if v["RHEOLOGY_FROM"] == "calibration"
                                              else "Remmelgas et al. mu(I)")
                           + (f", p_I packing {a.shear_pressure_phi_max}" if a.shear_pressure_phi_max else "")
                           + f"), ErgunGidaspow, Coulomb walls (mu_w {P.WALL_FRICTION:g})"),
                    b_mm=P.D_OUTLET * 1e3, air=air, steady_mass_flow_kg_s=W, steady_window_s=[t0, t1],
                    outlet_dpdz_Pa_m=G if air else None, wall_time_s=wall, cores=1, timeseries="timeseries.csv")
    print(f"mcc-hopper two-fluid {name}: W = {W:.4g} kg/s, outlet dp/dz {G:.4g} Pa/m, orifice row alpha {A:.3f} "
          f"over [{t0:g}, {t1:g}] s; {out_g:.1f} g out of {v['FILL_G']:.1f} g; {rec['cpu_s']:.0f} CPU-s", flush=True)
    return dict(run=name, W_kg_s=W, outlet_dpdz_Pa_m=G, orifice_row_alpha=A, cpu_s=rec["cpu_s"], cells=cells)


def run_one(a, air):
    name = "air" if air else "noair"
    run = os.path.join(a.out, "runs", name)
    v, lay = numbers(a, air)
    gc.two_fluid.setup(run, T, v, lambda d: staircase(d, lay), a.resume)
    if a.setup_only:
        return None
    rec = gc.two_fluid.run(run, T, v, a.end, a.chunk, f"mcc-hopper two-fluid {name}", v["FILL_G"], until=0.9)
    return post(run, os.path.join(a.out, name), name, v, a, rec)


def reference(folder):
    """(W [kg/s], outlet dp/dz [Pa/m] or None) of a committed level.json."""
    lv = gc.levels.read(os.path.join(HERE, folder, "level.json"))
    return lv["steady_mass_flow_kg_s"], lv.get("outlet_dpdz_Pa_m")


def compare(a, res):
    """OUT/summary.md: the two-fluid runs beside the committed continuum and cg-DEM levels."""
    rows = [("two-fluid, with air", res["air"]["W_kg_s"], res["air"]["outlet_dpdz_Pa_m"]),
            (f"two-fluid, {DRY[a.dry]}", res["noair"]["W_kg_s"], None),
            ("continuum mu(I), with air (reference-continuum-air)", *reference("reference-continuum-air")),
            ("continuum mu(I), dry (results)", reference("results")[0], None),
            ("coarse-grained DEM s = 5, dry (reference-cg-dem)", reference("reference-cg-dem")[0], None)]
    if a.rheology_from == "calibration":
        rows.append(("continuum DEM-calibrated mu(I), d 660 um in I, dry (results/calibrated/d660um)",
                     float(gc.series.read_keys(os.path.join(HERE, "results", "calibrated", "d660um", "summary.txt"))
                           ["steady_mass_flow_kg_s"]), None))
    lines = [f"# MCC hopper, two-fluid level against the others (twofluid.py --mesh {a.mesh}"
             f"{' --rheology-from calibration' if a.rheology_from == 'calibration' else ''}"
             f"{f' --shear-pressure-phi-max {a.shear_pressure_phi_max}' if a.shear_pressure_phi_max else ''})", "",
             "| run | W [kg/s] | outlet dp/dz [Pa/m] |", "|---|---:|---:|"]
    lines += [f"| {r} | {w:.4g} | {'' if g is None else f'{g:.4g}'} |" for r, w, g in rows]
    effect = {"two-fluid": rows[0][1] / rows[1][1] - 1, "continuum": rows[2][1] / rows[3][1] - 1}
    lines += ["", "Air effect on W (with air / dry - 1): "
              + ", ".join(f"{k} {100 * e:+.1f} %" for k, e in effect.items())
              + f"; Carleton's estimate for 660 um spheres here: {100 * a.carleton:+.1f} %."]
    with open(os.path.join(a.out, "summary.md"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    print("\n".join(lines), flush=True)


def main():
    ap = gc.cli.parser(__doc__)
    ap.add_argument("--air", choices=["on", "off", "both"], default="both")
    ap.add_argument("--dry", choices=sorted(DRY), default="drag",
                    help="how the dry run uncouples the air: its drag or its viscosity times 1/100 (default drag)")
    ap.add_argument("--rheology-from", choices=["literature", "calibration"], default="literature",
                    help="the mu(I) block: Remmelgas et al.'s (default) or the DEM calibration of the cg-DEM's "
                         "parcels at the primary d = 660 um in I, filled at its phi_max (study.py --rheology-from)")
    ap.add_argument("--shear-pressure-phi-max", default=None, metavar="PHI|alphaMax",
                    help="p_I's solid fraction at I = 0, phiMin moved with it; alphaMax: the contact law's "
                         "(the fill + 0.04) (default: the rheology's phiMax)")
    ap.add_argument("--mesh", type=int, default=5, help="cells across the orifice radius (default 5: 2.5 mm)")
    ap.add_argument("--end", type=float, default=2.0, help="simulated time [s] (default 2, the continuum's)")
    ap.add_argument("--chunk", type=float, default=0.25,
                    help="simulated time per solver call [s], also the field output interval (default 0.25)")
    ap.add_argument("--steady-from", type=float, default=0.5,
                    help="start of the averaging window [s] (default 0.5, the continuum's)")
    ap.add_argument("--resume", action="store_true", help="go on with the runs in OUT/runs to --end")
    a = gc.cli.parse(ap, os.path.join(HERE, "two-fluid-results"))
    if not (a.chunk > 0 and a.end > a.steady_from >= 0 and a.mesh >= 2):
        ap.error(f"--chunk {a.chunk:g}, --end {a.end:g}, --steady-from {a.steady_from:g}, --mesh {a.mesh}: "
                 "expected chunk > 0, end > steady-from >= 0 and at least 2 cells across the radius")
    gc.two_fluid.check_p_i_option(ap, a.shear_pressure_phi_max)
    airs = {"on": [True], "off": [False], "both": [True, False]}[a.air]
    res = gc.runner.pool([("air" if x else "noair", run_one, (a, x)) for x in airs], 2, "mcc-hopper two-fluid")
    if a.setup_only or len(res) < 2:
        return 0
    theta = math.degrees(math.atan(P.TAN_CONE))
    a.carleton = gc.closed_forms.carleton_ratio(P.D_OUTLET, theta, P.D_PARTICLE, P.RHO_P, P.AIR_RHO, P.AIR_MU,
                                                P.G) - 1
    compare(a, res)
    return 0


if __name__ == "__main__":
    gc.cli.main(main)
