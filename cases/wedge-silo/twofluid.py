#!/usr/bin/python3
"""The wedge silo at the two-fluid level: Debian's twoPhaseEulerFoam with
granair's muI frictional stress, granair drag (ErgunGidaspow on the lactose's
225 um grains) and Coulomb walls (libgranairTwoFluid.so, docs/two-fluid-model.md).

Status: b = 10 mm with and without air on meshes b/4, b/6, b/8
(reference-two-fluid-mesh/, twofluid_mesh.py: no mesh convergence); on
the continuum's body-fitted mesh (--mesh-kind fitted, granairTwoPhaseEulerFoam)
the same model discharges 1.6-3.5x faster than DEM-CFD and does not converge
over N = 6-24: the staircase's stair walls hold the flow (docs/two-fluid-model.md "The staircase walls hold the flow"),
and its rate there depends on how the particle pressure is put on the faces
(--pressure-face: 0.14-0.35 kg/s at N = 6; "The particle pressure across a face");
reference-two-fluid/ and reference-two-fluid-no-shear-pressure/ are earlier
b/4 runs from undefined wall values (see run_one); docs/two-fluid-model.md
"On a silo" gives the measurements and the disagreement with DEM-CFD.
One slot width.

    twofluid.py [--b MM ...] [--air on|off|both] [--end T] [--chunk T] [--resume] [--past-half] [--mesh N]
                [--until F] [--fills demo|study]
                [--dry viscosity|drag] [--outer-until T] [--rheology-from literature|calibration]
                [--dem-size demo|study] [--rheology-d D] [--rheology muI|latzSchmidt]
                [--air-mu-factor F] [--contact-stiffness F] [--shear-pressure on|off] [--shear-pressure-phi-max PHI]
                [--mesh-kind staircase|fitted] [--solver debian|granair]
                [--pressure-face linear|secant|localMin] [--shear-pressure-onset PHI|phiMin] [--contact-onset DPHI]
                [--out DIR] [--setup-only] [--post-only]

The silo, its fill and the mu(I) block are the continuum level's
(continuum.py numbers(): the same mesh with its free-fall region, the DEM
demo's fill height and bulk density, the literature mu(I)); the two-fluid
dictionaries are two-fluid/template/; --rheology-from calibration takes the
continuum's DEM-calibrated block instead (and its bulk density). Without air
the air is kept (the solver has two phases) at 1/100 of its viscosity, so
Ergun's viscous term is 1/100 of the real one (the inertial term stays: the
dry runs' slot dp/dz is 1/9 to 1/13 of the air runs', measured), or with
--dry drag at its real viscosity and the drag times 1/100 (both terms, as
the MCC hopper's dry runs); its density stays (a
lighter air, 1/100 or 1/10 of it, stopped in the start-up with a negative
air temperature from the energy equation the solver always solves, measured).
A run goes in chunks of --chunk s (log/chunks.json records each one's CPU
and wall time; --resume goes on from the newest time folder) and ends at
--end or once half the fill has left, the end of the DEM case's window
(--until F: the share F; 0.95 for the whole discharge, as ~2.7 % stays on
the hopper's staircase cells; past 80 % out a run also ends once its flow
has stalled, under 5 % of its mean rate for 0.5 s, gc.two_fluid.stall_time;
--past-half: at --end, a steadiness check; the window stays the DEM's).
Per run OUT/b<b>_<air|noair>/: timeseries.csv (1 ms means: t, W [kg/s] through the
outlet and the open sides below the slot, outlet dp/dz [Pa/m]: the mean over
the slot's cells of the gradient between the cell centres just above and
below the slot plane, as DEM-CFD's outlet monitor; the mean solid fraction of
the cell row just above the slot), summary.txt (their means over the window;
with air also `fields_*`: p and dp/dz on the slot plane and one b above it
from the fields written in the window, as DEM-CFD's outlet and above
monitors), cost.txt (CPU s of all chunks, cells); summary.csv over the runs
in OUT with the DEM-CFD demo's and study's rates. --post-only posts the runs
in OUT/runs again from their own values.json (runs set up before a change).
"""
import json
import os

import numpy as np

import granair_cases as gc
import continuum
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))
T = os.path.join(HERE, "two-fluid", "template")
SERIES_BLOCK = 1e-3     # [s] timeseries.csv's block means
LATZ_ALPHA_DELTA_MIN = 5e-4    # latzSchmidt's packing cap below cMax (numbers())


def numbers(a, b_mm, air):
    # the continuum level's defaults (its fill, literature mu(I), Coulomb walls, free
    # fall), so an option it gains has its default here too
    c = continuum.parser().parse_args([])
    c.mesh, c.end, c.write_every, c.fills = a.mesh, a.end, a.chunk, a.fills
    # --rheology-from calibration: the continuum's DEM-calibrated mu(I) block, its
    # d the --dem-size run's parcels, the bulk density the calibrated packing
    c.rheology_from, c.dem_size, c.rheology_d = a.rheology_from, a.dem_size, a.rheology_d
    c.rheology = a.rheology
    v = continuum.numbers(c, b_mm, air)
    # Debian's binary is wrong on the fitted mesh's skewed cells; granair's build
    # of the same solver source is not (FvcReconstructOverride.H)
    solver = a.solver or ("granair" if a.mesh_kind == "fitted" else "debian")
    if a.mesh_kind == "fitted" and solver == "debian":
        raise gc.CaseError("--mesh-kind fitted needs --solver granair: Debian's twoPhaseEulerFoam reconstructs "
                           "wrong velocities in the fitted mesh's skewed hopper cells (docs/two-fluid-model.md)")
    v.update(MESH_KIND=a.mesh_kind, SOLVER=gc.two_fluid.SOLVERS[solver])
    phi = v["RHO_B"] / P.RHO_P
    dx = b_mm * 1e-3 / a.mesh
    v.update(gc.two_fluid.closure(phi))
    if a.contact_stiffness != 1.0:     # diagnostic: the contact law's Fr times this
        v["FR"] *= a.contact_stiffness
    if a.contact_onset is not None:
        # diagnostic: the contact pressure's onset moved to this far below the fill's
        # packing, Fr scaled by (0.01 / gap)^eta so the fill's pressure stays
        # (p_c = Fr (alpha - alphaMin)^eta / (alphaMax - alpha)^p)
        old_gap = phi - v["ALPHA_MIN_FRICTION"]
        v["FR"] *= (old_gap / a.contact_onset) ** v["FR_ETA"]
        v["ALPHA_MIN_FRICTION"] = phi - a.contact_onset
    mu_factor, drag_scale = gc.two_fluid.dry(air, a.dry)
    if air:
        mu_factor = a.air_mu_factor
    # the phase's diameter is the rheology block's d as written there (muI
    # checks it: the DEM's parcels with the calibration); the drag sees the
    # primary particles
    latz = a.rheology == "latzSchmidt"
    v.update(D=P.D_LACTOSE if latz else gc.calibration.entry(v["RHEOLOGY"], "d"), D_DRAG=P.D_LACTOSE, RHO_P=P.RHO_P, G=9.81, DRAG_SCALE=drag_scale, DRY=a.dry,
             RHO_F=P.AIR_RHO, MU=P.AIR_MU * mu_factor, AIR_EOS="rhoConst",
             DRAG_LAW="ErgunGidaspow", PHI_FILL=phi, SHEAR_PRESSURE=a.shear_pressure,
             # the dp/dz probes at the cell centres beside the slot plane: a probe
             # returns its cell's value, so probes at +-1 mm read the centres at
             # +-dx/2 (+-1.25 mm at b/4) and (p1 - p2)/2 mm overstated dp/dz by 25 %
             PROBE_Z=b_mm * 1e-3 / (2 * a.mesh), AIR_MU_FACTOR=mu_factor,
             TITLE=f"The wedge silo, b = {b_mm} mm (cases/wedge-silo/twofluid.py, --fills {a.fills})",
             # the slot row's solid fraction: a probe at each of its N cell centres
             # (equal cells, so their mean is the row's mean)
             SLOT_ROW_PROBES=gc.two_fluid.row_probes(slot_xs(v), dx / 2, P.DEPTH / 2))
    if latz:
        # the frictional model latzSchmidt (its block has no d: the phase's is the
        # primary's); its packing cap cMax - alphaDeltaMin must hold the silo's
        # base: p_y = 2.2 kPa there is reached at c = 0.5751, and the cap at
        # cMax - 0.0005 = 0.5766 carries 9.4 kPa (the muI contact law's 0.005
        # would cap it at 0.5721, 0.7 kPa)
        v.update(FRICTION_MODEL="latzSchmidt", ALPHA_DELTA_MIN=LATZ_ALPHA_DELTA_MIN, SHEAR_PRESSURE="off")
    # the outlet's dp/dz: the orifice row's N cells and the N below, their mean
    # (DEM-CFD's outlet monitor averages snGrad(p) over the slot's faces)
    v["ORIFICE_PROBES"] = gc.two_fluid.orifice_probes(slot_xs(v), 2 * v["PROBE_Z"], P.DEPTH / 2)
    if a.shear_pressure_phi_max is not None:
        # p_I's packing at I = 0 (MuIFrictionalStress: the rheology block's phiMax is
        # read by p_I only, mu(I) does not use it); the span phiMax - phiMin is kept
        phi_max = gc.two_fluid.p_i_phi_max(a.shear_pressure_phi_max, v["ALPHA_MAX"])
        span = v["PHI_MAX"] - v["PHI_MIN"]
        v["RHEOLOGY"] = gc.two_fluid.p_i_packing(v["RHEOLOGY"], phi_max, span,
                                                 "twofluid.py --shear-pressure-phi-max (span kept)")
        v.update(PHI_MAX=phi_max, PHI_MIN=phi_max - span)
    # only when not the default, so runs set up before these options resume as they were
    if a.pressure_face != "linear":
        v["PRESSURE_FACE_KIND"] = a.pressure_face
    if a.shear_pressure_onset is not None:
        v["SHEAR_ALPHA_MIN"] = v["PHI_MIN"] if a.shear_pressure_onset == "phiMin" else float(a.shear_pressure_onset)
    return v


def slot_xs(v):
    """The x of the centres of the slot's N cells (equal cells across its width)."""
    dx = 2 * v["B"] / v["N"]
    return [(i + 0.5) * dx - v["B"] for i in range(v["N"])]


def staircase(run, v, b):
    """An orthogonal (staircase) mesh of the silo: blockMesh of four rectangular
    blocks (free fall below the slot, the slot column, the two side columns up to
    the top), then topoSet/subsetMesh remove the side cells outside the hopper
    (cell centres beyond B + z tan(half angle)); exposed faces become walls.
    Why: Debian's twoPhaseEulerFoam calls fvc::reconstruct, which with Debian's
    build gives wrong vectors in non-orthogonal cells (docs/two-fluid-model.md);
    on the continuum's trapezoidal hopper cells it blew up in the second step
    (air 4650 m/s in the cell beside the slot edge, measured)."""
    dx = b / v["N"]
    B, W, D = b / 2, P.WIDTH / 2, P.DEPTH
    ns = max(1, round((W - B) / dx))
    W = B + ns * dx                        # side columns a whole number of cells
    nz = round(v["HT"] / dx)
    ht = nz * dx
    nf = max(1, round(v["FREEFALL"] / dx))
    zf = nf * dx
    pts = [(-B, -zf), (B, -zf), (-W, 0), (-B, 0), (B, 0), (W, 0), (-W, ht), (-B, ht), (B, ht), (W, ht)]
    verts = "\n".join(f"    ({x:.9g} {y:.9g} {z:.9g})" for y in (0, D) for x, z in pts)
    text = f"""FoamFile {{ version 2.0; format ascii; class dictionary; object blockMeshDict; }}
// The wedge silo b = {b * 1e3:g} mm as a staircase of square cells dx = {dx * 1e3:g} mm (twofluid.py staircase()).
scale 1;
vertices
(
{verts}
);
blocks
(
    hex (0 1 11 10 3 4 14 13) ({v["N"]} 1 {nf}) simpleGrading (1 1 1)
    hex (3 4 14 13 7 8 18 17) ({v["N"]} 1 {nz}) simpleGrading (1 1 1)
    hex (2 3 13 12 6 7 17 16) ({ns} 1 {nz}) simpleGrading (1 1 1)
    hex (4 5 15 14 8 9 19 18) ({ns} 1 {nz}) simpleGrading (1 1 1)
);
boundary
(
    outlet       {{ type patch; faces ((0 1 11 10)); }}
    freefall     {{ type patch; faces ((0 10 13 3) (1 4 14 11)); }}
    atmosphere   {{ type patch; faces ((6 7 17 16) (7 8 18 17) (8 9 19 18)); }}
    walls        {{ type wall;  faces ((2 3 13 12) (2 12 16 6) (4 5 15 14) (5 9 19 15)); }}
    frontAndBack {{ type empty; faces ((0 1 4 3) (3 4 8 7) (2 3 7 6) (4 5 9 8)
                                       (10 13 14 11) (13 17 18 14) (12 16 17 13) (14 18 19 15)); }}
);
"""
    gc.template.write(os.path.join(run, "system", "blockMeshDict"), text)
    tan = np.tan(np.radians(P.HALF_ANGLE))
    outside = []
    for k in range(nz):
        zc = (k + 0.5) * dx
        w = B + zc * tan
        if zc > v["HH"] or w >= W:
            break
        outside += [(lo, k * dx + 1e-9, hi, (k + 1) * dx - 1e-9) for lo, hi in ((-W - 1, -w), (w, W + 1))]
    gc.two_fluid.silo_cells(run, outside)


def fitted(run, v):
    """The continuum level's body-fitted mesh (continuum/template's blockMeshDict:
    the hopper's N columns of trapezoidal cells graded to stay about square, the
    shaft and the free fall below the slot), for granairTwoPhaseEulerFoam, whose
    reconstruct is right on such cells (cfd-side/twoFluid/FvcReconstructOverride.H);
    the topoSet keeps every cell (the run's subsetMesh then changes nothing)."""
    gc.template.render(os.path.join(HERE, "continuum", "template"), run, v, ["system/blockMeshDict"])
    gc.two_fluid.silo_cells(run, [])


def post(run, out, name, v, wall=None):
    os.makedirs(out, exist_ok=True)
    t, w, dpdz, alpha = gc.two_fluid.series(run, 2 * v["PROBE_Z"], v["N"], f"wedge-silo two-fluid {name}",
                                            xs=slot_xs(v))
    dt = gc.series.step_lengths(t)
    # timeseries.csv: means over 1 ms (each row t ends its block; a b/8 run has
    # ~100 steps per ms); the window means below are over the steps themselves
    ends, blocks = gc.two_fluid.block_means(t, dt, [w, dpdz, alpha], SERIES_BLOCK)
    out_t = np.cumsum(w * dt)
    # the bed height that holds the powder left at each block's end (the DEM's and
    # the continuum's fill_level_m: whole_widths.py draws every level against it)
    left = v["FILL_G"] * 1e-3 - np.interp(ends, t, out_t)
    gc.series.write_csv(os.path.join(out, "timeseries.csv"),
                        [("t", ends), ("mass_flow_kg_s", blocks[0]), ("outlet_dpdz_Pa_m", blocks[1]),
                         ("slot_row_alpha", blocks[2]), ("fill_level_m", P.fill_level(2 * v["B"], left, v["RHO_B"]))])
    # The DEM case's steady window: from min(0.3 s, t1/2) to t1, t1 the time
    # half of the fill has left (or the end of the run).
    half = np.nonzero(out_t >= 0.5e-3 * v["FILL_G"])[0]
    t1 = float(t[half[0]]) if half.size else float(t[-1])
    t0 = min(P.STEADY_FROM, 0.5 * t1)
    W = gc.series.time_mean(t, w, t0, t1, dt=dt)
    G = gc.series.time_mean(t, dpdz, t0, t1, dt=dt)
    A = gc.series.time_mean(t, alpha, t0, t1, dt=dt)
    out_kg = float(out_t[-1])
    # the air pressure at the orifice and about b above it, as DEM-CFD's outlet and
    # above monitors give it, from the fields written in the window (every --chunk s)
    planes = gc.two_fluid.plane_pressures(run, 2 * v["B"], 2 * v["PROBE_Z"], t0, t1, v["RHO_F"], v["G"]) \
        if v["AIR"] else None
    planes = [(f"fields_{k}", x) for k, x in planes.items()] if planes else []
    gc.series.write_keys(os.path.join(out, "summary.txt"), [("W_kg_s", W), ("outlet_dpdz_Pa_m", G),
                                                             ("slot_row_alpha", A), ("window_t0_s", t0),
                                                             ("window_t1_s", t1), ("t_end_s", float(t[-1])),
                                                             ("discharged_g", out_kg * 1e3), ("fill_g", v["FILL_G"])]
                         + planes)
    air = bool(v["AIR"])
    if wall is None:    # from the solver logs (start-up and main run)
        wall = gc.two_fluid.wall_seconds(run)
    latz = v.get("FRICTION_MODEL") == "latzSchmidt"
    law = ("Latz-Schmidt at local equilibrium (tan phi 0.416)" if latz else
           f"{'DEM-calibrated ' if v['RHEOLOGY_FROM'] == 'calibration' else ''}muI (mu_s {v['MU_S']:.3f}"
           + (f", d = {v['D'] * 1e3:.3g} mm in I" if v["RHEOLOGY_FROM"] == "calibration" else "") + ")")
    onset = f", from alpha {v['SHEAR_ALPHA_MIN']:.4g}" if "SHEAR_ALPHA_MIN" in v else ""
    pressure = ("" if latz else f"shear-induced pressure (phiMax {v['PHI_MAX']:.4g}{onset}), "
                if v["SHEAR_PRESSURE"] == "on" else "contact pressure only, ")
    if v.get("PRESSURE_FACE_KIND", "linear") != "linear":
        pressure += f"particle pressure on faces {v['PRESSURE_FACE_KIND']}, "
    air_text = (("air" if v["AIR_MU_FACTOR"] == 1 else f"air at {v['AIR_MU_FACTOR']:g}x viscosity (diagnostic)")
                if air else {"viscosity": "air at 1/100 viscosity (dry)", "drag": "drag x 1/100 (dry)"}[v["DRY"]])
    gc.levels.write(os.path.join(out, "level.json"), case="wedge-silo", level="two-fluid",
                    model=(f"two-fluid {v.get('SOLVER', 'twoPhaseEulerFoam')} + granair {law} and ErgunGidaspow, Coulomb walls, "
                           f"{v.get('MESH_KIND', 'staircase')} mesh b/{v['N']}, {pressure}{air_text}"),
                    b_mm=v["B_MM"], air=air, steady_mass_flow_kg_s=W, steady_window_s=[t0, t1],
                    outlet_dpdz_Pa_m=G if air else None, wall_time_s=wall, cores=1, timeseries="timeseries.csv")
    print(f"wedge-silo two-fluid {name}: W = {W:.4g} kg/s, outlet dp/dz {G:.4g} Pa/m, slot row alpha {A:.3f} "
          f"over [{t0:.3g}, {t1:.3g}] s; {out_kg * 1e3:.1f} g out of {v['FILL_G']:.1f} g", flush=True)
    return dict(run=name, b_mm=v["B_MM"], mesh=v["N"], air=int(v["AIR"]), W_kg_s=W, outlet_dpdz_Pa_m=G,
                slot_row_alpha=A, t0_s=t0, t1_s=t1, discharged_g=out_kg * 1e3, fill_g=v["FILL_G"])


def run_one(a, b_mm, air):
    """One run in chunks of --chunk s (gc.two_fluid.run: the mesh and the
    start-up, then twoPhaseEulerFoam from its newest time to the next chunk
    end, until --end or until half the fill has left, the end of the DEM
    case's window). With --resume a run folder set up with the same numbers
    goes on where it stopped (a longer --end goes further)."""
    name = f"b{b_mm}_{'air' if air else 'noair'}"
    run = os.path.join(a.out, "runs", name)
    if a.post_only:     # the run's own numbers (it may have been set up by older code)
        with open(os.path.join(run, "values.json")) as fh:
            v = json.load(fh)
        cpu, wall, _ = gc.chunks.cost(run)
        r = post(run, os.path.join(a.out, name), name, v, wall=wall)
        r["cpu_s"] = cpu
        return r
    v = numbers(a, b_mm, air)
    mesh = (lambda d: fitted(d, v)) if a.mesh_kind == "fitted" else (lambda d: staircase(d, v, b_mm * 1e-3))
    gc.two_fluid.setup(run, T, v, mesh, a.resume)
    if a.setup_only:
        return None
    rec = gc.two_fluid.run(run, T, v, a.end, a.chunk, f"wedge-silo two-fluid {name}", v["FILL_G"], a.until,
                           a.past_half, outer=(a.outer_until, 3) if a.outer_until > 0 else None)
    r = post(run, os.path.join(a.out, name), name, v, wall=sum(c["wall_s"] for c in rec["chunks"]))
    r["cpu_s"] = rec["cpu_s"]
    gc.series.write_keys(os.path.join(a.out, name, "cost.txt"),
                         [("cpu_s", rec["cpu_s"]), ("wall_s", sum(c["wall_s"] for c in rec["chunks"])),
                          ("cells", gc.foam.checkmesh(os.path.join(run, "log", "checkMesh.log"))[0]),
                          ("t_end_s", gc.foam.time_dirs(run)[-1][0])])
    return r


def main():
    ap = gc.cli.parser(__doc__)
    ap.add_argument("--b", type=int, action="append", choices=[5, 10, 15], help="slot width [mm] (default 10)")
    ap.add_argument("--air", choices=["on", "off", "both"], default="both")
    ap.add_argument("--end", type=float, default=0.6,
                    help="longest simulated time [s] (default 0.6); a run ends earlier once half the fill has left")
    ap.add_argument("--chunk", type=float, default=0.1,
                    help="simulated time per solver call [s], also the field output interval (default 0.1)")
    ap.add_argument("--past-half", action="store_true",
                    help="go on to --end after the --until share of the fill has left (a steadiness check; the window stays the DEM's)")
    ap.add_argument("--until", type=float, default=0.5,
                    help="a run ends once this share of the fill has left (default 0.5, the end of the DEM case's "
                         "window; 0.95: the whole discharge; measured, about 2.7 %% of the fill stays on the hopper's "
                         "staircase cells, so 0.99 is never reached)")
    ap.add_argument("--fills", choices=["demo", "study"], default="demo",
                    help="the DEM fills to start from (parameters.py FILLS, FILLS_STUDY; the continuum's --fills)")
    ap.add_argument("--resume", action="store_true",
                    help="go on with the runs already in OUT/runs (set up with the same numbers) to --end")
    ap.add_argument("--post-only", action="store_true",
                    help="post-process the runs in OUT/runs again from their own values.json (no solver, no "
                         "set-up check: runs set up by older code too), e.g. after a change of the post-processing")
    ap.add_argument("--mesh", type=int, default=4, help="cells across the slot (default 4: square cells of b/4)")
    ap.add_argument("--solver", choices=sorted(gc.two_fluid.SOLVERS), default=None,
                    help="Debian's /usr/bin/twoPhaseEulerFoam (default on the staircase) or granairTwoPhaseEulerFoam "
                         "(the same source built here with a correct reconstruct; default on the fitted mesh)")
    ap.add_argument("--mesh-kind", choices=["staircase", "fitted"], default="staircase",
                    help="staircase (default): square cells b/N, the hopper walls as stairs, Debian's "
                         "twoPhaseEulerFoam; fitted: the continuum level's body-fitted mesh (N columns, "
                         "trapezoidal hopper cells) with granairTwoPhaseEulerFoam, the same solver source built "
                         "here with a correct reconstruct (docs/two-fluid-model.md)")
    # on by default: without it the powder leaves the slot as a dense plug and
    # the air hardly slows it (docs/two-fluid-model.md "On a silo", measured)
    ap.add_argument("--shear-pressure", choices=["on", "off"], default="on",
                    help="the muI model's shear-induced (dilatant) pressure p_I (default on; off: the contact part only)")
    # default: the fill's packing rho_b/rho_p (0.5843 at b = 10 mm), the continuum's
    # phiMax; the hopper compacts above it under the contact law (alphaMax = fill + 0.04)
    ap.add_argument("--shear-pressure-phi-max", default=None, metavar="PHI|alphaMax",
                    help="p_I's solid fraction at I = 0 (its denominator max(PHI - alpha, delta)), phiMin "
                         "moved with it; alphaMax: the contact pressure's alphaMax (fill + 0.04) "
                         "(default: the rheology's phiMax, the fill's packing)")
    # default viscosity: the committed references' dry runs; on the finer meshes
    # (b/6 at b = 10 mm, b/10 at b = 15 mm) those stopped at t ~ 0.11 s (README)
    ap.add_argument("--dry", choices=sorted(gc.two_fluid.DRY), default="viscosity",
                    help="how a dry run uncouples the air: its viscosity (default) or its drag (granair drag's "
                         "scale) times 1/100")
    # measured: the dry b = 10 mm run on b/6 cells stopped at t = 0.094 s (drag
    # x 1/100) or 0.108 s (viscosity x 1/100): the bed's top rows bounced (+3.9
    # then -4.2 m/s at solid fraction 0.6) and the air's energy equation gave a
    # negative temperature; with three outer correctors it passed 0.12 s
    ap.add_argument("--outer-until", type=float, default=0.0, metavar="T",
                    help="three outer correctors per step until T s, then the template's one (default 0: one "
                         "throughout); for the start's transient on fine meshes without air")
    ap.add_argument("--rheology", choices=["muI", "latzSchmidt"], default="muI",
                    help="the frictional stress: muI (default) or latzSchmidt, the lactose closure of the source "
                         "paper at local equilibrium of its granular temperature (continuum.py --rheology)")
    ap.add_argument("--rheology-from", choices=["literature", "calibration"], default="literature",
                    help="the mu(I) block: the literature's (default) or the DEM calibration of the DEM's parcels "
                         "(continuum.py --rheology-from, with its bulk density)")
    ap.add_argument("--dem-size", choices=sorted(P.SIZES), default="demo",
                    help="with the calibration: the DEM run whose parcel d goes in I (default demo; continuum.py)")
    ap.add_argument("--rheology-d", type=float, default=None,
                    help="with the calibration: the grain diameter of I and of the particle phase [m] instead of "
                         "the DEM parcel's (diagnostic, continuum.py --rheology-d)")
    ap.add_argument("--contact-stiffness", type=float, default=1.0, metavar="F",
                    help="diagnostic: the muI contact pressure's Fr times F (default 1: 49 Pa at the fill's packing, "
                         "gc.two_fluid.closure)")
    ap.add_argument("--pressure-face", choices=sorted(gc.two_fluid.PRESSURE_FACE), default="linear",
                    help="the particle pressure's coefficient on the faces: linear (default, twoPhaseEulerFoam's: "
                         "the cells' derivative interpolated), secant (the frictional law's secant between the "
                         "cells: the force is the pressure's difference) or localMin (a bound); "
                         "docs/two-fluid-model.md \"The particle pressure across a face\"")
    ap.add_argument("--shear-pressure-onset", default=None, metavar="PHI|phiMin",
                    help="p_I's onset in alpha (muICoeffs shearInducedAlphaMin): a solid fraction, or phiMin (the "
                         "rheology's, after --shear-pressure-phi-max); default alphaMinFriction, with the contact "
                         "pressure's")
    ap.add_argument("--contact-onset", type=float, default=None, metavar="DPHI",
                    help="diagnostic: the contact pressure's onset alphaMinFriction DPHI below the fill's packing "
                         "(default 0.01, gc.two_fluid.closure), its Fr scaled to keep the fill's pressure")
    ap.add_argument("--air-mu-factor", type=float, default=1.0,
                    help="diagnostic: the air run's air viscosity in units of the real one (default 1)")
    a = gc.cli.parse(ap, os.path.join(HERE, "two-fluid-results"))
    if a.rheology_d is not None and not (a.rheology_d > 0 and a.rheology_from == "calibration"):
        ap.error(f"--rheology-d {a.rheology_d:g}: expected a diameter > 0 [m], with --rheology-from calibration")
    if a.rheology == "latzSchmidt" and (a.rheology_from != "literature" or a.shear_pressure_phi_max is not None):
        ap.error("--rheology latzSchmidt: the closure is the source paper's (no --rheology-from calibration) "
                 "and has no shear-induced pressure of muI (no --shear-pressure-phi-max)")
    if a.contact_onset is not None and not 0 < a.contact_onset < 0.2:
        ap.error(f"--contact-onset {a.contact_onset:g}: expected 0 < DPHI < 0.2 below the fill's packing")
    if not a.contact_stiffness > 0:
        ap.error(f"--contact-stiffness {a.contact_stiffness:g}: expected a factor > 0")
    if not (a.chunk > 0 and a.end > 0):
        ap.error(f"--chunk {a.chunk:g} / --end {a.end:g}: expected times > 0 [s]")
    if not a.outer_until >= 0:
        ap.error(f"--outer-until {a.outer_until:g}: expected a time >= 0 [s]")
    if not 0 < a.until <= 1:
        ap.error(f"--until {a.until:g}: expected a share of the fill in (0, 1]")
    gc.two_fluid.check_p_i_option(ap, a.shear_pressure_phi_max)
    if a.shear_pressure_onset not in (None, "phiMin"):
        try:
            ok = 0 < float(a.shear_pressure_onset) < 1
        except ValueError:
            ok = False
        if not ok:
            ap.error(f"--shear-pressure-onset {a.shear_pressure_onset}: expected 0 < PHI < 1 or phiMin")
    if a.shear_pressure_onset is not None and (a.rheology != "muI" or a.shear_pressure == "off"):
        ap.error("--shear-pressure-onset: p_I's onset needs --rheology muI with --shear-pressure on")
    airs = {"on": [True], "off": [False], "both": [True, False]}[a.air]
    tasks = [(f"b{b}_{'air' if x else 'noair'}", run_one, (a, b, x)) for b in (a.b or [10]) for x in airs]
    res = gc.runner.pool(tasks, 2, "wedge-silo two-fluid")
    if a.setup_only:
        return 0
    # summary.csv over the runs in OUT: those of an earlier call (another --air) are kept
    summary = os.path.join(a.out, "summary.csv")
    rows = [x for x in gc.series.read_table(summary) if x["run"] not in res] if os.path.exists(summary) else []
    for name, r in sorted(res.items()):
        dem = {}
        for ref in ("reference-demo", f"reference-study-b{r['b_mm']}"):
            path = os.path.join(HERE, ref, "summary.csv")
            if os.path.exists(path):
                for x in gc.series.read_table(path):
                    if x["run"] == name:
                        dem[ref] = (float(x["W_kg_s"]), float(x["outlet_dpdz_Pa_m"]))
        r.update({f"W_{k}": w for k, (w, g) in dem.items()})
        r.update({f"dpdz_{k}": g for k, (w, g) in dem.items()})
        rows.append(r)
    gc.series.write_rows(summary, sorted(rows, key=lambda x: x["run"]))
    return 0


if __name__ == "__main__":
    gc.cli.main(main)
