#!/usr/bin/python3
"""The wedge-silo study (README.md): for each orifice width b one DEM-only
fill (settled on the closed shutter), then two discharge runs from that
restart, with air (granairFoam) and without (DEM only); then the results
tables, field pictures and VTK files, the study plots and the checks.

    study.py [--size demo|study] [--b 5 10 15] [--runs air noair] [--out DIR] [--jobs 2] [--np 1]
             [--t-end T] [--write-interval T] [--cfd-dt DT] [--s S] [--youngs E] [--cohesion matched|raw|off]
             [--rolling MU_R [--rolling-model epsd2|cdt]]
             [--fill-height H] [--cg-every T] [--whole [--chunk T]] [--pack DIR] [--stage all|fill|runs|post]
             [--full-depth] [--setup-only] [--check]

Fills and runs are independent serial jobs, --jobs of them at a time (on a
shared machine this beats one 2-rank job: the thin periodic slice gives every
rank as many ghost particles as it owns); --np N runs each discharge on N ranks.

--full-depth simulates the silo's whole 60 mm depth between front and back
walls (DEM walls of the shaft's material, a 3-D air mesh with no-slip walls)
instead of the periodic slice: about 12x the parcels at demo size; what the
slice reduction changes (README, "Full depth against the slice").

--whole runs each discharge until the silo is empty or the flow has stopped
(parameters.py WHOLE_*, --t-end the limit, default 15 s), granairFoam a chunk
at a time from its restart points (gc.chunks): a stopped or killed study
resumes where it was, a finished run is skipped. --pack DIR keeps each fill
and run as one file in DIR (gc.chunks.pack: the newest restart point only),
so a run outlives the machine: the same command elsewhere unpacks what its
work folder lacks and goes on (README, "Study size over the whole
discharge"). Every run's time series
carries the fill level (the bed height above the orifice holding the powder
left at the fill's bulk density); fill_level.png puts the mass flow, the
outlet gradient and the pressure about b above against it.

Checked per run (--check exits 1 on a failure): the particle accounting
closes exactly (inserted = present + removed, lost 0); fields, picture and VTK
at t = 0 and the end; with air, the air drawn in through the open top less
the air leaving down through the orifice equals the growth of the silo's pore
volume (continuity of the incompressible air), and that growth equals the
volume of powder discharged (the silo's volume is fixed), within the
tolerances of parameters.py and their reasons; at every field time with CG
dumps, the CG fields at the orifice (cg.py): their solid volume against the
parcels' and their bulk solid fraction against the air mesh's.
"""
import json
import math
import os
import random
import shutil
import time

import numpy as np

import cg
import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))


def numbers(a, b_mm, air):
    """Every number of one fill or run of size a.size at b (the template's placeholders)."""
    cfg, pb = P.SIZES[a.size], P.SIZES[a.size]["per_b"][b_mm]
    b, theta = b_mm * 1e-3, math.radians(P.HALF_ANGLE)
    hh = P.hopper_height(b)
    d_mean, d3 = P.psd_moments()
    s = a.s if a.s is not None else b / (pb["b_over_d"] * d_mean)
    if not s >= 1.0:
        raise gc.CaseError(f"coarse-graining factor s = {s}, expected >= 1")
    d = s * d_mean
    rolling = f" rolling_friction {a.rolling_model}" if a.rolling else ""   # every wall/gran and pair style
    # the DEM and the air in a thin periodic slice of the depth (one cell, empty
    # sides), or --full-depth: the silo's 60 mm between front and back walls
    # (issue 22: the slice reduction measured)
    slice_ = P.DEPTH if a.full_depth else cfg["slice_parcels"] * d
    youngs = a.youngs if a.youngs is not None else cfg["youngs"]
    k_coh = {"matched": P.K_COH_REAL * (youngs / P.E_REAL) ** (2.0 / 3.0), "raw": P.K_COH_REAL, "off": 0.0}[a.cohesion]
    t_r = gc.dem.rayleigh_time(s * P.D_MIN_PSD / 2, youngs, P.NU, P.RHO_P)
    # the air's step (the coupling step); --cfd-dt: a coupling-interval study or the
    # benchmark at the guide's interval of 50 (bench/wedge/run.py --cfd-dt)
    cfd_dt = a.cfd_dt if a.cfd_dt is not None else cfg["cfd_dt"]
    interval, dem_dt = gc.dem.time_steps(cfd_dt, t_r, cfg["rayleigh_fraction"])
    t_end = a.t_end if a.t_end is not None else P.WHOLE_T_MAX if a.whole else cfg["t_end"]
    every = a.write_interval if a.write_interval is not None else cfg["write_interval"]
    for name, span in (("discharge time", t_end), ("field interval", every)):
        if abs(round(span / cfd_dt) * cfd_dt - span) > 1e-9:
            raise gc.CaseError(f"{name} {span:g} s is not a whole number of CFD steps ({cfd_dt:g} s)")
    h = P.KERNEL_WIDTHS * d         # cells near the orifice and the kernel width: 1.6 parcel diameters
    nz_h = max(4, round(hh / h))
    z_above = max(1, min(nz_h - 1, round(b / (hh / nz_h)))) * hh / nz_h    # a face layer about b above
    fill = a.fill_height if a.fill_height is not None else pb["fill"]
    chunk = max(1, round(0.02 / dem_dt))
    cg_every = every if a.cg_every is None else a.cg_every     # CG dumps [s]: by default at the field times
    if not (a.rolling >= 0.0 and math.isfinite(a.rolling)):
        raise gc.CaseError(f"--rolling {a.rolling}: expected a rolling friction coefficient >= 0 (0: none)")
    mu_r = f"{a.rolling:.6g}"
    return dict(gc.template.constants(P), SIZE=a.size, B_MM=b_mm, B=b / 2, W=P.WIDTH / 2, HH=hh,
                HT=hh + P.SHAFT_HEIGHT, THETA=theta, SLICE=slice_, SLICE_MM=slice_ * 1e3, NX=max(4, round(b / h)),
                NX_SIDE=max(2, round((P.WIDTH - b) / 2 / (2 * h))), NZ_BELOW=max(4, round(P.BOX_BELOW / h)),
                NZ_HOPPER=nz_h, NZ_SHAFT=max(10, round(P.SHAFT_HEIGHT / max(2 * h, 0.004))), S=s, D_PRIMARY=d_mean,
                D_PARCEL=d, DEPTH_SCALE=P.DEPTH / slice_, FILL_HEIGHT=fill, T_END=t_end, WRITE_INTERVAL=every,
                CFD_DT=cfd_dt, DEM_DT=dem_dt, COUPLING_INTERVAL=interval, RAYLEIGH_S=t_r,
                WRITE_EVERY=round(every / cfd_dt), SNAP=round(every / dem_dt), NP=a.np,
                AIR="on" if air else "off", KERNEL_WIDTH=h, OUTLET_X=b / 2 + 1e-6, ABOVE_Z=z_above,
                ABOVE_X=b / 2 + z_above * math.tan(theta) + 1e-6, ABOVE_Z_LO=z_above - 1e-4,
                ABOVE_Z_HI=z_above + 1e-4, SKIN=0.3 * d, YOUNGS=youngs, MU_W=P.WALL_FRICTION,
                COHESION=a.cohesion, K_COH=k_coh, ROLLING_MU=a.rolling,
                ROLLING=rolling,
                ROLLING_FIX=f"fix m6 all property/global coefficientRollingFriction peratomtypepair 2 {mu_r} {mu_r} {mu_r} {mu_r}"
                if a.rolling else "# (none: --rolling 0)", R_TYPE=s * P.D_MEAN_PSD / 2, CHUNK=chunk,
                SOFT_PARTICLES="soft_particles  yes             # LIGGGHTS asks for this below E = 5e6 Pa"
                if youngs < 5e6 else "# (E >= 5e6 Pa: no soft_particles needed)",
                N_MIN=math.ceil(P.SETTLE_MIN / (chunk * dem_dt)), N_MAX=math.ceil(P.SETTLE_MAX / (chunk * dem_dt)),
                FILL="../fill", SEED=a.seed, CG_EVERY=round(cg_every / dem_dt),
                GRANAIR_ROOT=os.path.normpath(os.path.join(HERE, "..", "..")),
                N_PARCELS=round(P.PACKING_SETTLED * P.fill_area(b, fill) * slice_ / (s ** 3 * (math.pi / 6 * d3))),
                **depth(a.full_depth, slice_, h, rolling))


def depth(full, slice_, h, rolling):
    """The placeholders that differ between the periodic slice and the full depth: the
    air mesh's cells across the depth (the side columns' size 2h) and its front/back
    patch, the DEM's y boundary and its front/back walls (the shaft planes' material)."""
    if not full:
        return dict(NY=1, FRONT_BACK="empty", FRONT_BACK_U="empty", FRONT_BACK_P="empty", Y_BOUNDARY="p",
                    DEPTH_WALLS="# (no front and back walls: a periodic slice of the depth)",
                    DEPTH_NOTE=f"a 2-D slice {slice_ * 1e3:.4g} mm thick (one cell, empty)", FULL_DEPTH=0)
    walls = "\n".join(f"fix {n} all wall/gran model hertz tangential history cohesion sjkr{rolling} primitive type 2 "
                       f"yplane {y:.12g}" for n, y in (("front", 0.0), ("back", slice_)))
    return dict(NY=max(2, round(slice_ / (2 * h))), FRONT_BACK="wall", FRONT_BACK_U="noSlip",
                FRONT_BACK_P="zeroGradient", Y_BOUNDARY="f", DEPTH_WALLS="# the silo's front and back walls\n" + walls,
                DEPTH_NOTE=f"the full depth {slice_ * 1e3:.4g} mm between front and back walls", FULL_DEPTH=1)


def hopper_walls(v, d):
    """The two hopper walls as STL triangles in strips of about one slice thickness
    along the slope, spanning the periodic slice exactly (LIGGGHTS 3.8 sizes its
    mesh bins by the largest triangle; one long triangle in a thin periodic box
    fails an internal assertion)."""
    hh, b2, t, sl = v["HH"], v["B"], math.tan(v["THETA"]), v["SLICE"]
    n = max(2, math.ceil(hh / math.cos(v["THETA"]) / sl))
    for side, sgn in (("left", -1), ("right", 1)):
        quads = []
        for k in range(n):
            z0, z1 = hh * k / n, hh * (k + 1) / n
            x0, x1 = sgn * (b2 + z0 * t), sgn * (b2 + z1 * t)
            quads.append([(x0, 0.0, z0), (x0, sl, z0), (x1, sl, z1), (x1, 0.0, z1)])
        gc.template.write(os.path.join(d, "dem", f"hopper_{side}.stl"), gc.dem.stl(f"hopper_{side}", quads))


def write_fill(v, d):
    """The fill folder: a loose random packing of the parcels (the PSD scaled by s)
    at about PACKING_INSERT solid fraction, periodic in y, and the settle script."""
    rng = random.Random(v["SEED"])
    diam = sorted((v["S"] * P.draw_primary_diameter(rng) for _ in range(v["N_PARCELS"])), reverse=True)
    vol = sum(math.pi / 6 * dd ** 3 for dd in diam)
    t, hh, b2, w2, sl, gap = math.tan(v["THETA"]), v["HH"], v["B"], v["W"], v["SLICE"], 0.02 * v["D_PARCEL"]
    top = v["FILL_HEIGHT"]
    while P.fill_area(2 * b2, top) * sl * P.PACKING_INSERT < vol:
        top += 0.001

    full = v["FULL_DEPTH"]

    def sample(rng, r, top):
        z = rng.uniform(r, top)
        return rng.uniform(-w2 + r, w2 - r), rng.uniform(r, sl - r) if full else rng.uniform(0.0, sl), z

    def inside(x, y, z, r):
        c = math.cos(v["THETA"])
        if full and not r + gap <= y <= sl - r - gap:      # the front and back walls
            return False
        return not (z < r + gap or abs(x) > w2 - r - gap or (z < hh + r and (
            (x + b2 + z * t) * c < r + gap or (b2 + z * t - x) * c < r + gap)))
    atoms = gc.dem.loose_packing(diam, rng, sample, inside, lambda tp: tp * 1.05, top,
                                 v["S"] * P.D_MAX_PSD * 1.0001, gap, origin=(-w2, 0.0, 0.0), periodic_y=None if full else sl)
    box = (-P.WIDTH / 2 - 0.001, P.WIDTH / 2 + 0.001, 0.0, sl, -P.SINK_DEPTH - 0.005,
           max(hh + P.SHAFT_HEIGHT, 1.9 * v["FILL_HEIGHT"] + 0.02))
    if max(z + dd / 2 for _, _, z, dd in atoms) > box[5]:
        raise gc.CaseError("the loose packing reaches above the DEM box")
    gc.template.render(os.path.join(HERE, "template"), d, v, only=["dem/in.fill", "dem/in.materials"])
    gc.dem.write_data(os.path.join(d, "dem", "packing.data"), atoms, box, P.RHO_P,
                      f"wedge silo loose packing: {len(atoms)} parcels (study.py)")
    hopper_walls(v, d)


def packed(a, d, name):
    """--pack: the folder d from a.pack/<name>.tar.xz when d has no state of its own
    (no fill restart; no finished chunk) and the pack exists; True if it did."""
    if not a.pack or a.setup_only:
        return False
    path = os.path.join(a.pack, f"{name}.tar.xz")
    own = os.path.exists(os.path.join(d, "dem", "fill.restart")) or gc.chunks.record(d)["chunks"]
    if own or not os.path.exists(path):
        return False
    shutil.rmtree(d, ignore_errors=True)
    gc.chunks.unpack(path, d)
    print(f"wedge-silo: {name} unpacked from {path}", flush=True)
    return True


def pack(a, d, name):
    """--pack: d as a.pack/<name>.tar.xz (a fill without its initial packing, which only a new fill needs)."""
    path = os.path.join(a.pack, f"{name}.tar.xz")
    size = gc.chunks.pack(d, path, skip=[os.path.join("dem", "packing.data")])
    print(f"wedge-silo: {name} packed to {path} ({size / 1e6:.1f} MB)", flush=True)


def do_fill(a, b, work):
    d = os.path.join(work, f"b{b}", "fill")
    if packed(a, d, f"b{b}_fill"):
        return {}
    shutil.rmtree(d, ignore_errors=True)
    write_fill(numbers(a, b, False), d)
    if a.setup_only:
        return {}
    t0 = time.time()
    cpu = gc.runner.liggghts(d, "dem/in.fill", "fill", "log/log.liggghts", "log/screen.liggghts", np=a.fill_np)
    if a.pack:
        pack(a, d, f"b{b}_fill")
    return dict(cpu_s=cpu, wall_s=time.time() - t0)


def finished(d):
    """Why a whole-discharge run is done (a string), or None: the DEM nearly empty, or
    nothing crossed the orifice for STALL_TIME (a stopped flow: an arch, a cohesive rest)."""
    try:
        s = gc.series.read_csv(os.path.join(d, "postProcessing", "timeSeries.csv"))
    except (OSError, gc.CaseError):
        return None
    t, n, out = s["t"], s["particles"], s["discharged_kg"]
    if n[-1] <= P.EMPTY_FRACTION * n[0]:
        return f"empty: {int(n[-1])} of {int(n[0])} parcels left at t = {t[-1]:g} s"
    before = t <= t[-1] - P.STALL_TIME
    if t[-1] > 2 * P.STALL_TIME and before.any() and out[-1] <= out[before][-1]:
        return f"stopped: nothing crossed the orifice in {P.STALL_TIME:g} s before t = {t[-1]:g} s, {int(n[-1])} parcels left"
    return None


def do_run(a, b, air, work):
    name, d = f"b{b}_{'air' if air else 'noair'}", os.path.join(work, f"b{b}", "air" if air else "noair")
    v = numbers(a, b, air)
    packed(a, os.path.join(work, f"b{b}", "fill"), f"b{b}_fill")
    if a.whole:
        packed(a, d, name)
    resume = a.whole and not a.setup_only and gc.chunks.record(d)["chunks"]
    if resume:
        # folders from before --full-depth hold a periodic slice
        gc.template.check_values(os.path.join(d, "case.json"), v,
                                 since=depth(False, v["SLICE"], v["KERNEL_WIDTH"], v["ROLLING"]))
        gc.template.relocate(os.path.join(HERE, "template"), d, v)   # a pack from another checkout
        gc.template.save_values(os.path.join(d, "case.json"), v)
    else:
        shutil.rmtree(d, ignore_errors=True)
        gc.template.render(os.path.join(HERE, "template"), d, v, only=["system", "constant", "0", "dem/in.liggghts",
                                                                      "dem/in.materials"])
        hopper_walls(v, d)
        os.makedirs(os.path.join(d, "dem", "post"))
        gc.template.save_values(os.path.join(d, "case.json"), v)
    if a.setup_only:
        return {}
    if not resume:
        gc.runner.mesh(d, a.np)
    t0 = time.time()
    if a.whole:
        every = v["WRITE_INTERVAL"]
        chunk = every * max(1, math.ceil(a.chunk / every - 1e-9))
        rec = gc.chunks.foam(d, chunk, finished, v["T_END"], np=a.np,
                             progress=lambda m: print(f"wedge-silo: {m}", flush=True),
                             after=(lambda rec: pack(a, d, name)) if a.pack else None)
        print(f"wedge-silo: {name} finished ({rec['reason']}), {rec['cpu_s']:.0f} s CPU in "
              f"{len(rec['chunks'])} chunk(s)", flush=True)
        cpu = rec["cpu_s"]
    else:
        cpu = gc.runner.run(["granairFoam"], d, np=a.np)
    wall = time.time() - t0
    if a.np > 1:
        gc.runner.run(["reconstructPar", "-withZero"], d)   # the start-time void fraction is in processor*/0
    field_products(d, v, air)
    return dict(cpu_s=cpu, wall_s=wall)


def field_products(d, v, air):
    """What the post stage reads beside the time series: the VTK fields at the field times
    and the silo's cell centres and volumes at t = 0 (its pore volume). A pack holds the
    run as its last chunk left it, so the post stage makes them for an unpacked run too."""
    times = ",".join(f"{t:g}" for t in field_times(v) if gc.foam.time_dir(d, t))
    gc.runner.run(["foamToVTK", "-time", times, "-fields", "(voidfraction p U)" if air else "(voidfraction)"], d)
    for func in ("writeCellCentres", "writeCellVolumes"):       # the silo's cells and volumes: its pore volume
        gc.runner.run(["postProcess", "-func", func, "-time", "0"], d, func)


def field_times(v):
    return [round(k * v["WRITE_INTERVAL"], 9) for k in range(int(math.floor(v["T_END"] / v["WRITE_INTERVAL"] + 1e-9)) + 1)]


def fill_stats(fill_dir, v):
    """Bulk density of the settled fill (parcels with centres between 5 mm above the
    orifice and 3 parcel diameters below the top, over that silo volume), the settled
    fill height (mean over x-bins of the highest parcel top) and the mass."""
    f = gc.dem.read_dump(os.path.join(fill_dir, "dem", "fill.dump"))
    x, z, r, m = f["x"], f["z"], f["radius"], f["mass"]
    edges = np.linspace(-P.WIDTH / 2, P.WIDTH / 2, 6)
    top = float(np.mean([np.max(z[sel] + r[sel]) for lo, hi in zip(edges[:-1], edges[1:])
                         for sel in [(x >= lo) & (x < hi)] if sel.any()]))
    z0, z1 = 0.005, top - 3 * v["D_PARCEL"]
    b = 2 * v["B"]
    rho_b = float(m[(z >= z0) & (z < z1)].sum() / ((P.fill_area(b, z1) - P.fill_area(b, z0)) * v["SLICE"]))
    beverloo = [[gc.closed_forms.beverloo_slot(b, dd, rho_b, P.DEPTH, k, P.BEVERLOO_C, P.G) for k in P.K_RANGE]
                for dd in (v["D_PRIMARY"], v["D_PARCEL"])]
    return dict(rho_b=rho_b, solid_fraction=rho_b / P.RHO_P, fill_top_m=top, n_parcels=len(x),
                mass_slice_kg=float(m.sum()), mass_full_depth_kg=float(m.sum() * v["DEPTH_SCALE"]),
                full_silo_primaries_d225=P.PACKING_SETTLED * P.fill_area(b, top) * P.DEPTH / (math.pi / 6 * 225e-6 ** 3),
                beverloo_kg_s=beverloo[0], beverloo_parcel_kg_s=beverloo[1], case=v)


MONITORS = ("outlet_dpdz_Pa_m", "outlet_p_Pa", "above_p_Pa", "above_dpdz_Pa_m")   # granairFoam's air monitors


def steady_rates(t, s, air):
    """The steady window (t0, t1) of a run's series s (gc.powder.dem), W over it
    [kg/s] and, with air, the monitors' means there: the figures a run reports
    (kernel_width.py reads its runs with this too)."""
    t0, t1 = gc.series.steady_window(t, s["particles"], P.STEADY_FROM)
    out = dict(steady_from_s=t0, steady_to_s=t1, W_kg_s=gc.series.slope(t, s["discharged_kg"], t0, t1))
    if air:
        out.update({k: gc.series.time_mean(t, s[k], t0, t1) for k in MONITORS})
    return out


def post_run(d, res, name):
    """One run: results CSV, steady rates and means, the air volume balance, fields."""
    with open(os.path.join(d, "case.json")) as fh:
        v = json.load(fh)
    r = gc.powder.dem(d)
    chunks = gc.chunks.record(d)["chunks"]
    if chunks:      # a whole-discharge run: its log holds the last chunk's wall time only
        r["balance"]["wall_time_s"] = sum(c["wall_s"] for c in chunks)
    s, t, air = r["series"], r["t"], v["AIR"] == "on"
    fill = fill_stats(os.path.join(d, "..", "fill"), v)
    zero = np.zeros(len(t))
    # the bed height holding what is still above the orifice at the fill's bulk density
    level = P.fill_level(2 * v["B"], fill["mass_full_depth_kg"] - s["discharged_kg"], fill["rho_b"])
    gc.series.write_csv(os.path.join(res, f"{name}.csv"), [("t", t), ("mass_flow_kg_s", s["mass_flow_kg_s"])] + [
        (k, s.get(k, zero)) for k in MONITORS] + [
        ("discharged_kg", s["discharged_kg"]), ("particles", s["particles"]), ("fill_level_m", level)])
    out = dict(name=name, b_mm=v["B_MM"], air=air, s=v["S"], size=v["SIZE"], np=v["NP"], t_end=float(t[-1]),
               **steady_rates(t, s, air),
               balance=r["balance"], whole=bool(chunks), full_depth=bool(v.get("FULL_DEPTH")), rolling=f", rolling friction {v['ROLLING'].split()[-1]} mu_r = "
               f"{v['ROLLING_MU']:g}" if v.get("ROLLING") else "", field_times=[x for x in field_times(v) if gc.foam.time_dir(d, x)])
    if air:
        first = np.argmax(s["discharged_kg"] > 0)        # "while discharging": from the first discharged particle on
        out["outlet_p_mean_discharging_Pa"] = float(np.mean(s["outlet_p_Pa"][first:]))
        # the air volume balance of the silo above the orifice up to the last field time
        out["balance_time_s"] = out["field_times"][-1]
        out.update(gc.powder.air_balance(d, s, out["balance_time_s"], P.AIR_RHO, P.RHO_P, v["DEPTH_SCALE"]))
    # the pictures and the CG fields' orifice window are drawn from a plane mesh: the
    # full depth's 3-D fields are in its VTK files (ParaView) and its time series
    full = bool(v.get("FULL_DEPTH"))
    out["full_depth"] = full
    out["cg"], out["cg_png"] = ([], None) if full else cg.run(d, v, res, name, out["field_times"])
    for c in out["cg"]:     # the discharge counter's rate (0.1 s window) next to the CG flux through the orifice
        c["orifice"]["series_mass_flow_kg_s"] = float(np.interp(c["t"], t, s["mass_flow_kg_s"]))
    levels = {x: float(np.interp(x, t, level)) for x in out["field_times"]}      # the fill level at each field time
    out["field_fill_levels_m"] = [levels[x] for x in out["field_times"]]
    kind = f"b = {v['B_MM']} mm, {'with air' if air else 'DEM only'}"
    rows = [("voidfraction", "void fraction", "viridis", (0.35, 1.0))] + (
        [("p", "air pressure - ambient [Pa]", "RdBu_r", None)] if air else [])
    lims = (-P.WIDTH / 2 * 1e3, P.WIDTH / 2 * 1e3), (-P.BOX_BELOW * 1e3, min(v["HT"], v["FILL_HEIGHT"] + 0.03) * 1e3)
    notes = {x: f"fill level {1e3 * h:.0f} mm" for x, h in levels.items()}
    out["png"] = None if full else gc.plots.case_fields(os.path.join(res, f"{name}_fields.png"), f"{name}: {kind}", d,
                                                        out["field_times"], rows, *lims, notes=notes)
    three = [] if full else fill_level_times(levels)
    if three:       # the same fields at the field times nearest 3/4, 1/2 and 1/4 of the initial fill level
        gc.plots.case_fields(os.path.join(res, f"{name}_fill_levels.png"), f"{name}: {kind}, at three fill levels",
                             d, three, rows, *lims, notes=notes)
    dst = os.path.join(res, "vtk", name, "openfoam")
    shutil.rmtree(dst, ignore_errors=True)
    if os.path.isdir(os.path.join(d, "VTK")):
        shutil.copytree(os.path.join(d, "VTK"), dst)
    return out


def fill_level_times(levels):
    """The field times whose fill levels ({t: level}) are nearest 3/4, 1/2 and 1/4 of
    the first one; [] unless three distinct times qualify (a run with few field times)."""
    h0 = levels[min(levels)] if levels else 0.0
    picks = sorted({min(levels, key=lambda x: abs(levels[x] - f * h0)) for f in (0.75, 0.5, 0.25)}) if h0 > 0 else []
    return picks if len(picks) == 3 else []


def crewdson(w0, dpdz, rho_b):
    """Air-impeded rate W0 sqrt(1 + (dp/dz)/(rho_b g)) (Crewdson et al. 1977), z up; W0, dp/dz numbers or arrays."""
    return np.vectorize(lambda w, x: gc.closed_forms.crewdson(w, x, rho_b, P.G))(w0, dpdz)


def post_study(a, work, res, timings, wall):
    fills, runs, series = {}, [], {}
    for b in a.b:
        for name in ["fill"] + a.runs:     # a fill or run only packed (another machine's) is unpacked first
            d = os.path.join(work, f"b{b}", name)
            unpacked = packed(a, d, f"b{b}_{name}")
            if not os.path.isdir(d):
                raise gc.CaseError(f"{d}: no {name} folder to post-process; run --stage {'fill' if name == 'fill' else 'runs'}"
                                   f" first, or give --pack DIR holding b{b}_{name}.tar.xz")
            if name != "fill" and (unpacked or not os.path.exists(os.path.join(d, "0", "Cz"))):
                field_products(d, numbers(a, b, name == "air"), name == "air")
        fills[b] = fill_stats(os.path.join(work, f"b{b}", "fill"), numbers(a, b, False))
        for r in a.runs:
            runs.append(post_run(os.path.join(work, f"b{b}", r), res, f"b{b}_{r}"))
            series[runs[-1]["name"]] = gc.series.read_csv(os.path.join(res, f"b{b}_{r}.csv"))
    by = {(x["b_mm"], x["air"]): x for x in runs}
    for x in runs:
        if x["air"] and (x["b_mm"], False) in by:
            x["crewdson_kg_s"] = float(crewdson(by[(x["b_mm"], False)]["W_kg_s"], x["outlet_dpdz_Pa_m"], fills[x["b_mm"]]["rho_b"]))
    plots(runs, fills, series, res, a.size)
    write_summary(runs, fills, timings, res, wall, a)
    for x in runs:
        gc.levels.write(os.path.join(res, f"{x['name']}.level.json"), case="wedge-silo",
                        level="cg-dem-cfd" if x["air"] else "cg-dem",
                        model=f"DEM{'-CFD' if x['air'] else ''}, s = {x['s']:.3g}, {x['size']} size"
                        + (", whole discharge" if x["whole"] else "")
                        + (", full 60 mm depth between walls" if x["full_depth"] else "") + x["rolling"], b_mm=x["b_mm"],
                        air=x["air"], steady_mass_flow_kg_s=x["W_kg_s"], steady_window_s=[x["steady_from_s"], x["steady_to_s"]],
                        outlet_dpdz_Pa_m=x.get("outlet_dpdz_Pa_m"), wall_time_s=x["balance"]["wall_time_s"], cores=x["np"],
                        timeseries=f"{x['name']}.csv", parcels=fills[x["b_mm"]]["n_parcels"], coarse_graining_factor=x["s"])
    print(open(os.path.join(res, "summary.txt")).read())
    check(runs, res).report(enforce=a.check)
    print(f"wedge-silo: results in {res}: mass_flow.png, outlet_pressure_gradient.png (the study plots), summary.txt|csv, "
          f"b<b>_<air|noair>.csv (time series), _fields.png and vtk/ (fields); the cases in {work}", flush=True)


def check(runs, res):
    c = gc.checks.Checks("wedge-silo")
    for x in runs:
        n, bal = x["name"], x["balance"]
        c.exact(f"{n}: inserted = present + removed", bal["inserted"], bal["present"] + bal["removed"], "integer counts")
        c.exact(f"{n}: lost", bal["lost"], 0, "DischargeCounter: every parcel is in the silo, below it or removed")
        c.true(f"{n}: fields, picture (a slice) and VTK at t = 0 and the end", x["field_times"][:1] == [0] and
               (x["png"] or x["full_depth"]) and
               os.path.isdir(os.path.join(res, "vtk", n, "openfoam")), f"field times {x['field_times']}")
        cg.checks(c, n, x["cg"])
        if x["air"]:
            t = f"0-{x['balance_time_s']:g} s"
            c.close(f"{n}: air in through the top - out through the orifice vs pore-volume growth of the silo, {t}",
                    x["air_in_top_m3"] - x["air_out_orifice_m3"], x["pore_growth_m3"], P.AIR_CONTINUITY,
                    "the incompressible air's continuity, summed over the steps: each closes to the pressure solver's "
                    "1e-9; a face flux lost or counted twice would show at 1e-2")
            c.close(f"{n}: pore-volume growth vs powder volume discharged, {t}", x["pore_growth_m3"], x["powder_out_m3"],
                    P.PORE_VS_POWDER, "the silo's volume is fixed; the Gaussian kernel puts a share of the parcels "
                    "within ~3 kernel widths of the orifice plane on its other side")
    return c


def plots(runs, fills, series, res, size):
    plt = gc.plots.pyplot()
    colours = {5: "tab:blue", 10: "tab:orange", 15: "tab:green"}
    by = {(x["b_mm"], x["air"]): x for x in runs}
    fig, ax = plt.subplots(figsize=(11.5, 5.5))
    for b in sorted(fills):
        c, f = colours.get(b, "k"), fills[b]
        ax.axhspan(f["beverloo_kg_s"][1], f["beverloo_kg_s"][0], color=c, alpha=0.15, lw=0,
                   label=f"b = {b} mm, Hagen-Beverloo, k = 1..3")
        for x in (by.get((b, air)) for air in (True, False)):
            if x:
                ts = series[x["name"]]
                ax.plot(ts["t"], ts["mass_flow_kg_s"], color=c, ls="-" if x["air"] else ":", lw=1.6,
                        label=f"b = {b} mm, {'with air' if x['air'] else 'DEM only'}")
        if (b, True) in by and (b, False) in by:
            ts = series[f"b{b}_air"]
            ax.plot(ts["t"], crewdson(by[(b, False)]["W_kg_s"], gc.series.trailing_mean(ts["t"], ts["outlet_dpdz_Pa_m"], 0.1),
                                      f["rho_b"]), color=c, ls="--", lw=1,
                    label=f"b = {b} mm, Crewdson: W0 sqrt(1 + (dp/dz)/(rho_b g))")
    ax.set(xlabel="time since the shutter opened [s]", ylabel="mass flow rate, full 60 mm depth [kg/s]", ylim=(0, None))
    ax.set_title(f"Wedge silo ({size}): mass flow; shaded: Hagen-Beverloo slot band (C = {P.BEVERLOO_C}, k = 1..3)", fontsize=9)
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    ax.grid(alpha=0.3)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(res, "mass_flow.png"))
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for x in (x for x in runs if x["air"]):
        b, ts, c = x["b_mm"], series[x["name"]], colours.get(x["b_mm"], "k")
        mean = lambda k: gc.series.trailing_mean(ts["t"], ts[k], 0.1)   # noqa: E731
        axes[0].plot(ts["t"], ts["outlet_dpdz_Pa_m"], color=c, lw=0.4, alpha=0.35)
        axes[0].plot(ts["t"], mean("outlet_dpdz_Pa_m"), color=c, lw=1.8, label=f"b = {b} mm (0.1 s mean)")
        axes[0].axhline(-fills[b]["rho_b"] * P.G, color=c, lw=0.8, ls=":")
        axes[1].plot(ts["t"], mean("outlet_p_Pa"), color=c, lw=1.8, label=f"b = {b} mm, orifice plane")
        axes[1].plot(ts["t"], mean("above_p_Pa"), color=c, lw=1.2, ls="--", label=f"b = {b} mm, about b above")
    axes[0].set(xlabel="time [s]", ylabel="dp/dz [Pa/m]")
    axes[0].set_title("air pressure gradient at the orifice, dp/dz (z up); dotted: -rho_b g", fontsize=9)
    axes[1].set(xlabel="time [s]", ylabel="p [Pa]")
    axes[1].set_title("air pressure relative to ambient (0.1 s mean)", fontsize=9)
    for ax in axes:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(res, "outlet_pressure_gradient.png"))
    fill_level_plot(runs, fills, series, res, size, colours)


def fill_level_plot(runs, fills, series, res, size, colours):
    """Mass flow, outlet dp/dz and the air pressure about b above the orifice against the
    fill level (the bed height above the orifice), 0.1 s means; the Crewdson estimate from
    the DEM-only rate at the same fill level and the gradient with air."""
    plt = gc.plots.pyplot()
    by = {(x["b_mm"], x["air"]): x for x in runs}
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.8))
    for x in runs:
        b, ts, c = x["b_mm"], series[x["name"]], colours.get(x["b_mm"], "k")
        h, ls = ts["fill_level_m"] * 1e3, "-" if x["air"] else ":"
        axes[0].plot(h, ts["mass_flow_kg_s"], color=c, ls=ls, lw=1.5, label=f"b = {b} mm, {'with air' if x['air'] else 'DEM only'}")
        if x["air"]:
            mean = lambda k: gc.series.trailing_mean(ts["t"], ts[k], 0.1)   # noqa: E731
            axes[1].plot(h, mean("outlet_dpdz_Pa_m"), color=c, lw=1.5, label=f"b = {b} mm")
            axes[1].axhline(-fills[b]["rho_b"] * P.G, color=c, lw=0.8, ls=":")
            axes[2].plot(h, mean("above_p_Pa"), color=c, lw=1.5, label=f"b = {b} mm, about b above")
            axes[2].plot(h, mean("outlet_p_Pa"), color=c, lw=1.0, ls="--", label=f"b = {b} mm, orifice plane")
            if (b, False) in by:        # the DEM-only rate at the same fill level (its level falls monotonically)
                t0 = series[by[(b, False)]["name"]]
                w0 = np.interp(h, t0["fill_level_m"][::-1] * 1e3, t0["mass_flow_kg_s"][::-1], left=np.nan, right=np.nan)
                axes[0].plot(h, crewdson(w0, mean("outlet_dpdz_Pa_m"), fills[b]["rho_b"]),
                             color=c, ls="--", lw=1, label=f"b = {b} mm, Crewdson from the DEM-only W at that level")
    for b in sorted(fills):
        axes[0].axhspan(fills[b]["beverloo_kg_s"][1], fills[b]["beverloo_kg_s"][0], color=colours.get(b, "k"),
                        alpha=0.12, lw=0)
    titles = ["mass flow, full 60 mm depth [kg/s]; shaded: Hagen-Beverloo k = 1..3",
              "outlet air dp/dz [Pa/m] (0.1 s mean); dotted: -rho_b g", "air pressure - ambient [Pa] (0.1 s mean)"]
    for ax, title in zip(axes, titles):
        ax.set_xlabel("fill level: bed height above the orifice [mm] (falls as the silo empties)")
        ax.set_title(title, fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=6)
    axes[0].set_ylim(0, None)
    fig.suptitle(f"Wedge silo ({size}) against the fill level", fontsize=10)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(res, "fill_level.png"))


def write_summary(runs, fills, timings, res, wall, a):
    rows = [dict(run=x["name"], b_mm=x["b_mm"], air=int(x["air"]), s=f"{x['s']:.4g}", W_kg_s=f"{x['W_kg_s']:.5g}",
                 **{k: f"{x.get(k, 0):.5g}" for k in ("outlet_dpdz_Pa_m", "outlet_p_Pa", "above_p_Pa")},
                 crewdson_kg_s=f"{x.get('crewdson_kg_s', math.nan):.5g}", rho_b_kg_m3=f"{fills[x['b_mm']]['rho_b']:.5g}",
                 beverloo_k3_kg_s=f"{fills[x['b_mm']]['beverloo_kg_s'][1]:.5g}",
                 beverloo_k1_kg_s=f"{fills[x['b_mm']]['beverloo_kg_s'][0]:.5g}",
                 **{k: x["balance"][k] for k in ("inserted", "present", "removed", "lost")},
                 run_wall_s=f"{x['balance']['wall_time_s']:.1f}",
                 **{k: f"{x[k]:.5g}" for k in ("air_in_top_m3", "air_out_orifice_m3", "pore_growth_m3", "powder_out_m3")
                    if k in x}) for x in runs]
    gc.series.write_rows(os.path.join(res, "summary.csv"), rows)
    rolling = f", rolling friction {a.rolling_model} mu_r = {a.rolling:g}" if a.rolling else ""
    lines = [f"wedge-silo study, size {a.size}{rolling} (total wall time {wall:.0f} s)", ""]
    for b, f in sorted(fills.items()):
        v, bev = f["case"], f["beverloo_kg_s"] + f["beverloo_parcel_kg_s"]
        lines += [f"b = {b} mm: s = {v['S']:.3g}, parcel d = {v['D_PARCEL'] * 1e3:.3g} mm (b/d = {b * 1e-3 / v['D_PARCEL']:.3g}), "
                  f"slice {v['SLICE'] * 1e3:.3g} mm (x{v['DEPTH_SCALE']:.3g} to 60 mm), {f['n_parcels']} parcels; settled fill "
                  f"{f['fill_top_m'] * 1e3:.0f} mm, rho_b = {f['rho_b']:.0f} kg/m3 (solid fraction {f['solid_fraction']:.3f}); "
                  f"full 60 mm silo at d = 225 um: {f['full_silo_primaries_d225']:.3g} particles",
                  f"   Hagen-Beverloo (C = {P.BEVERLOO_C}, k = 1..3, primary d): {bev[1]:.4g} .. {bev[0]:.4g} kg/s; "
                  f"with the parcel d: {bev[3]:.4g} .. {bev[2]:.4g} kg/s"]
    lines += ["", f"{'run':14s} {'W [kg/s]':>10s} {'dp/dz [Pa/m]':>13s} {'p_out [Pa]':>11s} {'p_above [Pa]':>12s} "
              f"{'Crewdson':>9s} {'balance':>22s} {'wall [s]':>9s}  air in - out | pore growth | powder out [mm3]"]
    for x in runs:
        bal = x["balance"]
        lines.append(f"{x['name']:14s} {x['W_kg_s']:10.4g} {x.get('outlet_dpdz_Pa_m', 0):13.4g} {x.get('outlet_p_Pa', 0):11.4g} "
                     f"{x.get('above_p_Pa', 0):12.4g} {x.get('crewdson_kg_s', math.nan):9.4g} "
                     f"{bal['inserted']:>7d}={bal['present']}+{bal['removed']}{'' if bal['closes'] else ' OPEN'} "
                     f"{bal['wall_time_s']:9.0f}" + (f"  {1e9 * (x['air_in_top_m3'] - x['air_out_orifice_m3']):.4g} | "
                                                     f"{1e9 * x['pore_growth_m3']:.4g} | {1e9 * x['powder_out_m3']:.4g}"
                                                     if x["air"] else ""))
    cg_rows = [(x["name"], r) for x in runs for r in x["cg"]]
    if cg_rows:
        lines += ["", "CG fields at the orifice (cg.py): solid volume in the window [mm3] by granairCG | kernel-weighted "
                  "parcels | parcels centred inside (+- edge bound); bulk solid fraction CG | 1 - air eps (cells)"]
        lines += [f"  {n:12s} t = {r['t']:<5g} {1e9 * r['cg_volume_m3']:10.5g} | {1e9 * r['kernel_weighted_m3']:10.5g} | "
                  f"{1e9 * r['centres_inside_m3']:10.5g} (+- {1e9 * r['edge_bound_m3']:.3g});  {r['bulk_cg_solid']:.4f} | "
                  f"{r['bulk_air_solid']:.4f} ({r['bulk_cells']}, rms per cell {r['bulk_rms_cell_difference']:.3f})"
                  for n, r in cg_rows]
        lines += ["", "CG fields on the orifice plane (means over the slot): solid fraction CG | CFD 1 - eps (CG/CFD - 1); "
                  "v_z CG | CFD Us [m/s]; CG pressure [Pa]; air p [Pa], dp/dz [Pa/m]; mass flow CG flux | counter [kg/s]"]
        for n, r in cg_rows:
            o = r["orifice"]
            lines.append(f"  {n:12s} t = {r['t']:<5g} {o['cg_solid_fraction']:.4f} | {o['cfd_solid_fraction']:.4f} "
                         f"({100 * (o['cg_solid_fraction'] / o['cfd_solid_fraction'] - 1):+.1f} %);  "
                         f"{o['cg_velocity_z']:.3f} | {o.get('cfd_solid_velocity_z', math.nan):.3f};  {o['cg_pressure']:6.1f};  "
                         f"{o.get('air_pressure', math.nan):6.1f}, {o.get('air_dpdz', math.nan):7.0f};  "
                         f"{o['cg_mass_flow_kg_s']:.4f} | {o['series_mass_flow_kg_s']:.4f}")
    if timings:
        lines += ["", "Stage times: wall [s] (on this machine, at its load) and CPU [s] of the stage's processes"]
        lines += [f"  {k:14s} wall {t['wall_s']:8.0f}   cpu {t['cpu_s']:8.0f}" for k, t in sorted(timings.items())]
        lines.append(f"  total CPU {sum(t['cpu_s'] for t in timings.values()):.0f} s")
    by = {(x["b_mm"], x["air"]): x for x in runs}
    lines += ["", "Air against no air, and the DEM-only rate against the Hagen-Beverloo band (reported):"]
    for b in sorted(fills):
        (hi, lo), wa, w0 = fills[b]["beverloo_kg_s"], by.get((b, True), {}).get("W_kg_s"), by.get((b, False), {}).get("W_kg_s")
        if wa and w0:
            lines.append(f"  b = {b}: with air W {wa:.4g}, without {w0:.4g} kg/s ({100 * (wa / w0 - 1):+.1f} %)")
        if w0:
            lines.append(f"  b = {b}: DEM-only W {w0:.4g} kg/s = {w0 / (0.5 * (lo + hi)):.2f} x the middle of {lo:.4g}..{hi:.4g}")
    with open(os.path.join(res, "summary.txt"), "w") as fh:
        fh.write("\n".join(lines) + "\n")

def main():
    ap = gc.cli.parser(__doc__)
    ap.add_argument("--size", default="demo", choices=sorted(P.SIZES))
    ap.add_argument("--b", type=int, nargs="+", default=[5, 10, 15], choices=[5, 10, 15])
    ap.add_argument("--runs", nargs="+", default=["air", "noair"], choices=["air", "noair"])
    ap.add_argument("--jobs", type=int, default=2, help="runs at a time")
    ap.add_argument("--fill-np", type=int, default=1, help="MPI ranks per fill (plain LIGGGHTS)")
    ap.add_argument("--s", type=float, default=None, help="coarse-graining factor for every b")
    ap.add_argument("--t-end", type=float, default=None, help="discharge time [s]")
    ap.add_argument("--write-interval", type=float, default=None, help="field interval [s] (demo 0.25, study 1)")
    ap.add_argument("--cfd-dt", type=float, default=None,
                    help="the air's (coupling) time step [s] (default the size's, 5e-4 s: coupling interval ~26)")
    ap.add_argument("--youngs", type=float, default=None, help="Young's modulus used [Pa]")
    ap.add_argument("--cohesion", default="matched", choices=["matched", "raw", "off"])
    ap.add_argument("--rolling", type=float, default=0.0, metavar="MU_R",
                    help="rolling friction coefficient, parcels and walls (default 0: none; README, Rolling resistance)")
    ap.add_argument("--rolling-model", default=P.ROLLING_MODELS[0], choices=P.ROLLING_MODELS,
                    help="LIGGGHTS rolling friction model (default %(default)s)")
    ap.add_argument("--fill-height", type=float, default=None, help="settled fill height [m]")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--cg-every", type=float, default=None,
                    help="interval of the CG-field dumps [s] (default: the field interval; 0: none)")
    ap.add_argument("--full-depth", action="store_true",
                    help="the silo's full 60 mm depth between front and back walls, not a periodic slice "
                         "(the air mesh 3-D; about 12x the parcels of the demo slice)")
    ap.add_argument("--whole", action="store_true",
                    help="until the silo is empty or the flow stops, in resumable chunks (--t-end: the limit)")
    ap.add_argument("--chunk", type=float, default=P.WHOLE_CHUNK,
                    help="--whole: granairFoam runs this long at a time [s], whole field intervals (default %(default)g)")
    ap.add_argument("--pack", default=None, metavar="DIR",
                    help="keep each fill and --whole run as DIR/b<b>_<fill|air|noair>.tar.xz, written after the fill "
                         "and after every chunk; a fill or run with no folder here is unpacked from DIR first")
    ap.add_argument("--stage", default="all", choices=["all", "fill", "runs", "post"],
                    help="fill: the fills only; runs: the runs from existing fills, then post; post: post only")
    a = gc.cli.parse(ap, os.path.join(HERE, "run"))
    if a.cfd_dt is not None and not (a.cfd_dt > 0 and math.isfinite(a.cfd_dt)):
        ap.error(f"--cfd-dt {a.cfd_dt:g}: expected the air's time step > 0 [s]")
    a.pack = a.pack and os.path.abspath(a.pack)
    work, res = os.path.join(a.out, "runs"), os.path.join(a.out, "results")
    os.makedirs(work, exist_ok=True)
    os.makedirs(res, exist_ok=True)
    t0 = time.time()
    print(f"wedge-silo: size {a.size}, b = {a.b} mm, runs {a.runs}, stage {a.stage}, {a.jobs} job(s) of {a.np} "
          f"rank(s); work in {work}", flush=True)
    timing_file = os.path.join(res, "timings.json")
    timings = {}            # stage times accumulate over invocations (--stage fill, then --stage runs)
    if os.path.exists(timing_file):
        with open(timing_file) as fh:
            timings = json.load(fh)
        timings = timings if isinstance(timings, dict) else {}    # an older study's list: start again
    for stage, tasks in (("fill", [(f"b{b}_fill", do_fill, (a, b, work)) for b in a.b]),
                         ("runs", [(f"b{b}_{r}", do_run, (a, b, r == "air", work)) for b in a.b for r in a.runs])):
        if a.stage in ("all", stage):
            if stage == "runs" and not a.setup_only:
                print(f"wedge-silo: discharge runs started; each prints its progress (simulated time, ETA) to "
                      f"{work}/b<b>/<air|noair>/log/granairFoam.log", flush=True)
            timings.update({k: r for k, r in gc.runner.pool(tasks, a.jobs, "wedge-silo").items() if r})
    if a.setup_only:
        return print(f"wedge-silo: fill and run folders written to {work}")
    with open(timing_file, "w") as fh:
        json.dump(timings, fh, indent=1)
    if a.stage == "fill":
        return
    post_study(a, work, res, timings, time.time() - t0)


if __name__ == "__main__":
    gc.cli.main(main)
