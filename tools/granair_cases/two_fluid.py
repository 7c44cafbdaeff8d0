"""The two-fluid level's runs (Debian's twoPhaseEulerFoam with libgranairTwoFluid.so,
docs/two-fluid-model.md) on a staircase mesh (or a body-fitted one with granairTwoPhaseEulerFoam), shared by cases/wedge-silo/twofluid.py
and cases/mcc-hopper/twofluid.py; the dictionaries are cases/wedge-silo/two-fluid/template
(geometry-free but for the values a case fills in).

    setup(run_dir, template, values, write_mesh, resume)        the run folder (or the one to resume)
    rec = run(run_dir, template, values, end, chunk, label)      the chunked run, resumable
    orifice_probes(xs, dz, y)                                    the template's ORIFICE_PROBES
    row_probes(xs, z, y)                                         a row's probes (SLOT_ROW_PROBES)
    t, w, dpdz, alpha = series(run_dir, probe_dz, probes)        the run's rows, every time step
    ends, means = block_means(t, dt, [w, dpdz, alpha], block)     their means over blocks of time
    plane_pressures(run_dir, b, dx, t0, t1, rho_f, g)            p and dp/dz at the orifice and b above (fields)
    out_by(run_dir, fill_g, share)                               when that share of the fill had left
    stall_time(t, rate, fill_g)                                  when a discharge stalled (past 80 % out)
    run_end(run_dir, fill_g, until)                              a chunked run's stop: (share out, stalled)
    closure(phi_fill)                                            the frictional closure's numbers
    friction(values)                                             its entry in turbulenceProperties.particles
    pressure_face(kind)                                          the particle-pressure face entry of fvSchemes

A case writes system/blockMeshDict (its blocks of orthogonal cells) and
system/topoSetDict (a cellSet `silo` of the cells inside its hopper); the first
chunk meshes (blockMesh, topoSet, subsetMesh: the exposed faces become the
patch `walls`), fills (setFields) and starts (200 fixed steps of 1 us), each
later chunk runs the solver from its newest time to the next multiple of
`chunk`. Why staircase cells: Debian's twoPhaseEulerFoam calls fvc::reconstruct,
which with Debian's build gives wrong vectors in non-orthogonal cells
(docs/two-fluid-model.md). values["SOLVER"] = "granairTwoPhaseEulerFoam" runs the
same solver source built here with that fixed, for a body-fitted mesh (a case's
topoSetDict then keeps every cell; cases/wedge-silo/twofluid.py --mesh-kind
fitted); the default is Debian's. The template's function objects give the powder's
flow through `outlet` and `freefall`, the air pressure at the centres of the
orifice row's cells and of the row below the orifice plane (`orificePressure`,
orifice_probes(): dp/dz = the area-weighted mean of their differences / probe_dz,
as granairFoam's outlet monitor averages snGrad(p) over the orifice faces) and
the solid fraction at the probes of the orifice row (`slotRow`).
"""
import os
import re

import numpy as np

from . import CaseError, calibration, chunks, foam, runner, series as _series, template

# the patches the powder leaves through, their flows summed (positive outwards)
OUT_PATCHES = ("outlet", "freefall")
# A dry run keeps the air (the solver has two phases) but all but uncouples it,
# in one of two ways: its viscosity times DRY_MU_FACTOR (the wedge silo's runs:
# Ergun's viscous term 1/100 of the real one, the inertial term kept; its dry
# slot dp/dz is 1/9 to 1/13 of its air runs', measured) or the drag times
# DRY_DRAG_SCALE (granair drag's `scale`: both terms). Its density stays (a
# lighter air, 1/100 or 1/10 of it, stopped in the start-up with a negative air
# temperature from the energy equation the solver always solves, measured).
DRY_MU_FACTOR = 0.01
DRY_DRAG_SCALE = 0.01
# the two ways by name (the cases' --dry), with the words their level texts use
DRY = {"drag": "dry: drag x 1/100", "viscosity": "dry: air viscosity x 1/100"}
# The solver binaries by the name a case gives (values["SOLVER"] holds the binary):
# Debian's, and the same source built here with a reconstruct right on skewed cells
SOLVERS = {"debian": "twoPhaseEulerFoam", "granair": "granairTwoPhaseEulerFoam"}


def dry(air, how):
    """(air viscosity factor, drag scale) of a run: (1, 1) with air, else those of
    the dry way `how` (a key of DRY)."""
    if air:
        return 1.0, 1
    if how not in DRY:
        raise CaseError(f"dry run: '{how}' is not one of {sorted(DRY)}")
    return (DRY_MU_FACTOR, 1) if how == "viscosity" else (1.0, DRY_DRAG_SCALE)


def closure(phi_fill):
    """The template's numbers of the frictional closure (cfd-side/twoFluid/MuIFrictionalStress.H)
    and of the solver, for a fill at solid fraction phi_fill: the contact pressure is
    zero 0.01 below the fill's packing and 49 Pa at it; one outer corrector per step
    (~3x faster than three and stable on the wedge silo: its runs switched from 3 to
    1 at t ~ 0.014 s); the shear-induced pressure p_I on (without it the wedge silo's
    powder left its slot as a dense plug and the air hardly slowed it,
    docs/two-fluid-model.md "On a silo")."""
    return dict(ALPHA_MIN_FRICTION=phi_fill - 0.01, ALPHA_MAX=phi_fill + 0.04, FR=0.05, FR_ETA=2, FR_P=5,
                ALPHA_DELTA_MIN=0.005, SHEAR_PRESSURE="on", FACE_MOMENTUM="no", N_OUTER=1, DRAG_SCALE=1)


# The frictional-stress models of libgranairTwoFluid.so (cfd-side/twoFluid) by
# the name a case selects (FRICTION_MODEL, default muI) -> the comment and the
# coefficients after the rheology block, as @KEY:spec@ text of values.
FRICTION = {
    "muI": ("granair: mu(I) shear stress and a contact pressure >= 0, zero below\n"
            "        // alphaMinFriction (cfd-side/twoFluid/MuIFrictionalStress.H).",
            "            Fr              @FR:.8g@;\n"
            "            eta             @FR_ETA:.6g@;\n"
            "            p               @FR_P:.6g@;\n"
            "            alphaDeltaMin   @ALPHA_DELTA_MIN:.6g@;\n"
            "            shearInducedPressure @SHEAR_PRESSURE@;"),
    "latzSchmidt": ("granair: Latz-Schmidt at local equilibrium of its granular temperature,\n"
                    "        // its yield pressure zero below c0 (cfd-side/twoFluid/LatzSchmidtFrictionalStress.H).",
                    "            alphaDeltaMin   @ALPHA_DELTA_MIN:.6g@;"),
}


def friction(values, where="two-fluid template"):
    """The frictionalStressModel entry of turbulenceProperties.particles (the
    template's @FRICTION@): the model values["FRICTION_MODEL"] (default muI), its
    coefficients with values["RHEOLOGY"] (the rheology block) first."""
    model = values.get("FRICTION_MODEL", "muI")
    if model not in FRICTION:
        raise CaseError(f"{where}: frictional stress model '{model}' is not one of {sorted(FRICTION)}")
    comment, coeffs = FRICTION[model]
    if "SHEAR_ALPHA_MIN" in values:
        if model != "muI":
            raise CaseError(f"{where}: SHEAR_ALPHA_MIN (p_I's onset) is a muI coefficient, not {model}'s")
        coeffs += "\n            shearInducedAlphaMin @SHEAR_ALPHA_MIN:.6g@;"
    return template.fill(f"        // {comment}\n        frictionalStressModel   {model};\n        {model}Coeffs\n"
                         f"        {{\n@RHEOLOGY@\n{coeffs}\n        }}", values, where)


# How the particle pressure's coefficient pPrime reaches the faces
# (cfd-side/twoFluid/PressureSecant.H; docs/two-fluid-model.md "The particle
# pressure across a face"): OpenFOAM's linear interpolation of the cells'
# derivative (the default, the solver as shipped), the secant of the
# frictional law between the two cells (the force the pressure's difference),
# or the smaller cell's value (localMin: a bound, not a model).
PRESSURE_FACE = {
    "linear": "",
    "secant": '"interpolate\\(.*pfPrime.*\\)" frictionalPressureSecant pfSecantRatio.particles;',
    "localMin": '"interpolate\\(.*pfPrime.*\\)" localMin;',
}


def pressure_face(kind, where="two-fluid template"):
    """The fvSchemes interpolationSchemes entry (the template's @PRESSURE_FACE@)
    for the particle-pressure coefficient's face value `kind` (a key of PRESSURE_FACE)."""
    if kind not in PRESSURE_FACE:
        raise CaseError(f"{where}: particle-pressure face '{kind}' is not one of {sorted(PRESSURE_FACE)}")
    return PRESSURE_FACE[kind]


def check_p_i_option(ap, option):
    """The cases' --shear-pressure-phi-max: None, alphaMax or a number 0 < PHI <= 1
    (else ap.error, naming the option)."""
    if option in (None, "alphaMax"):
        return
    try:
        ok = 0 < float(option) <= 1
    except ValueError:
        ok = False
    if not ok:
        ap.error(f"--shear-pressure-phi-max {option}: expected 0 < PHI <= 1 or alphaMax")


def p_i_phi_max(option, alpha_max):
    """p_I's packing for a checked --shear-pressure-phi-max (not None): the closure's
    alpha_max for alphaMax, else the number."""
    return alpha_max if option == "alphaMax" else float(option)


def p_i_packing(rheology, phi_max, span, note):
    """The muI block with the shear-induced pressure's packing at I = 0 (its phiMax,
    read by p_I only: mu(I) does not use it) at phi_max and phiMin = phi_max - span.
    Why: where the contact law lets the powder compact above phiMax (up to the
    closure's alphaMax), p_I's denominator max(phiMax - alpha, delta) sits at its
    floor and p_I is large (cfd-side/twoFluid/MuIFrictionalStress.C)."""
    for key, value in (("phiMax", phi_max), ("phiMin", phi_max - span)):
        rheology = calibration.set_entry(rheology, key, value, note)
    return rheology


def block_means(t, dt, columns, block):
    """Means of the columns over blocks of `block` s of the time steps (t the step
    ends, dt their lengths): the time each block ends and the means."""
    centres, means = _series.window_means(t, dt, columns, block, keep_last=0.0)
    ends = np.empty_like(centres)
    start = float(t[0] - dt[0])
    for i, c in enumerate(centres):
        ends[i] = start = 2 * c - start
    return ends, means


def rows_of(path, columns):
    """The first `columns` numbers of each row of a function object's file: rows with the
    file's usual number of fields only (a solver killed mid-write leaves a cut row, or a
    run of NUL bytes where the restart's rows begin: measured, a b = 5 mm run)."""
    rows = []
    with open(path, errors="replace") as fh:
        for line in fh:
            line = line.replace("\0", "").strip()
            if line and not line.startswith("#"):
                rows.append(line.split())
    if not rows:
        return np.empty((0, columns))
    n = max(set(map(len, rows)), key=[len(r) for r in rows].count)     # the usual number of fields
    out = []
    for r in rows:
        if len(r) == n:
            try:
                out.append([float(x) for x in r[:columns]])
            except ValueError:
                continue
    return np.array(out, ndmin=2)


def read_series(run, name, file, columns):
    """Rows of a function object's output over every restart, in time order: the
    files postProcessing/<name>/<t0>/<file> or, where a restart from t0 wrote
    into the same folder, the newest of them (<stem>_<t>.dat beside it). A
    later restart's rows replace an earlier file's from its first time on (a
    chunk killed past its last written time is run again from there)."""
    base = os.path.join(run, "postProcessing", name)
    stem, ext = os.path.splitext(file)
    parts = []
    for sub in os.listdir(base):
        # a restart from a folder's time writes <stem>_<t> beside the first run's
        # file (surface values) or overwrites it (probes): the newest file counts
        files = [os.path.join(base, sub, f) for f in os.listdir(os.path.join(base, sub))
                 if f == file or (f.startswith(stem + "_") and f.endswith(ext))]
        if files:
            d = rows_of(max(files, key=os.path.getmtime), columns)
            if len(d):
                parts.append(d)
    if not parts:
        raise CaseError(f"{base}: no {file} written")
    parts.sort(key=lambda d: d[0, 0])
    rows = [d[d[:, 0] < nxt[0, 0]] for d, nxt in zip(parts, parts[1:])] + [parts[-1]]
    return np.concatenate(rows)


def out_flow(run):
    """t [s] and the rate [kg/s] out through the outlet and the free-fall sides, as
    far as both files are written (a file caught mid-row is read again at the next
    poll), or None before they exist."""
    try:
        o, f = (read_series(run, f"{patch}Flow", "surfaceFieldValue.dat", 2) for patch in OUT_PATCHES)
    except (ValueError, CaseError):
        return None
    n = min(len(o), len(f))
    return o[:n, 0], o[:n, 1] + f[:n, 1]


def mass_out(t, rate):
    """The mass out since t = 0 [kg] at each row (row i covers (t[i-1], t[i]])."""
    return np.cumsum(np.asarray(rate, float) * _series.step_lengths(np.asarray(t, float)))


def share_time(t, rate, fill_g, share):
    """The time the share of the fill [g] had left, or None."""
    k = np.nonzero(mass_out(t, rate) >= share * 1e-3 * fill_g)[0]
    return float(t[k[0]]) if k.size else None


def out_by(run, fill_g, share):
    """The time the share of the fill [g] had left (0.5: the DEM window's end), or
    None: from the outlet and free-fall flow files as far as they are written."""
    flow = out_flow(run)
    return None if flow is None else share_time(*flow, fill_g, share)


def stall_time(t, rate, fill_g, after=0.8, window=0.5, below=0.05):
    """The first time [s] of flow rates rate [kg/s] at times t [s] at which a
    discharge has stalled, or None: the share `after` of the fill [g] has left
    and the mass that left over the `window` s before is less than `below` of
    what the run's mean rate so far would carry in that time. The whole
    discharge runs (--until 0.95) otherwise never end when their last few %
    stay on the hopper's staircase cells (b = 15 mm on b/4: stopped by hand;
    its tails carried 0.7-2.7 % of the mean rate, dry and with air: this stops
    them at 2.1 s dry and 2.3 s with air, 91 and 93 % out)."""
    t = np.asarray(t, float)
    if t.size < 2:
        return None
    out = mass_out(t, rate)
    k = np.nonzero((out >= after * 1e-3 * fill_g) & (t >= window))[0]
    recent = out[k] - np.interp(t[k] - window, t, out)
    hit = k[recent < below * window * out[k] / t[k]]
    return float(t[hit[0]]) if hit.size else None


def run_end(run, fill_g, until):
    """(the time the share `until` of the fill had left, the time the discharge
    stalled) of a run so far, each or None (the stall only while the share is
    not out): the run's stop, from one read of its flow files."""
    flow = out_flow(run)
    if flow is None:
        return None, None
    done = share_time(*flow, fill_g, until)
    return done, None if done is not None else stall_time(*flow, fill_g)


def orifice_probes(xs, dz, y=0.0):
    """ORIFICE_PROBES: the centres of the cells of the orifice row (z = dz/2) and of
    the row below the orifice plane (-dz/2) at each x of xs, the row above first.
    Before 2026-12-07 the runs had one pair on the axis: the axis cell's gradient
    is 0.74-0.89x the orifice's mean (the cells at the slot's edges carry 1.5x the
    centre's, measured on the wedge silo's fields), and DEM-CFD's outlet monitor
    gives the mean."""
    return f"{row_probes(xs, dz / 2, y)} {row_probes(xs, -dz / 2, y)}"


def row_probes(xs, z, y=0.0):
    """probeLocations of a row of cells: (x, y, z) for each x of xs."""
    return " ".join(f"({x:.9g} {y:.6g} {z:.9g})" for x in xs)


def orifice_gradient(p, probe_dz, weights):
    """dp/dz of every row of orifice_probes' pressures p (columns: the n cells above,
    then the n below): the weighted mean of (above - below) / probe_dz."""
    n = len(weights)
    w = np.asarray(weights, dtype=float)
    return ((p[:, :n] - p[:, n:2 * n]) / probe_dz) @ (w / w.sum())


def axis_to_mean(t, g_axis, snap_t, offset):
    """The axis pair's dp/dz series g_axis (runs before orifice_probes) moved to the
    orifice's mean by the mean-minus-axis offset of the field snapshots at snap_t,
    interpolated linearly in time (held beyond the first and last). An offset,
    not a ratio: where the axis gradient is small or changes sign (the MCC
    hopper's ~100 Pa/m) a ratio is meaningless."""
    return g_axis + np.interp(t, snap_t, offset)


def snapshot_offsets(run, xs, dz, weights, patch, axis_x=0.0):
    """The orifice's mean dp/dz minus the axis pair's in every written p field of a
    run with the axis probes only: the cells whose centres are nearest to
    (x, +-dz/2) for x in xs, and to (axis_x, +-dz/2). Returns (times, offsets,
    ratios of the means to the axis values)."""
    c = foam.cell_centres(run, patch)
    cell = lambda x, z: int(np.argmin((c[:, 0] - x) ** 2 + (c[:, 1] - z) ** 2))
    up, down = [cell(x, dz / 2) for x in xs], [cell(x, -dz / 2) for x in xs]
    axis = (cell(axis_x, dz / 2), cell(axis_x, -dz / 2))
    snaps = []
    for t, d in foam.time_dirs(run):
        if t <= 0 or not os.path.exists(os.path.join(d, "p")):
            continue
        p = foam.read_field(os.path.join(d, "p"), len(c))
        g_mean = orifice_gradient(np.concatenate([p[up], p[down]])[None, :], dz, weights)[0]
        snaps.append((t, g_mean, (p[axis[0]] - p[axis[1]]) / dz))
    if not snaps:
        raise CaseError(f"{run}: no p fields to move the axis probes' dp/dz to the orifice's mean")
    s = np.array(snaps)
    with np.errstate(divide="ignore", invalid="ignore"):
        return s[:, 0], s[:, 1] - s[:, 2], s[:, 1] / s[:, 2]


def plane_pressures(run, b, dx, t0, t1, rho_f, g, patch="frontAndBack"):
    """The air pressure at two planes of a plane (2-D) silo from the field
    snapshots in [t0, t1], as DEM-CFD's monitors give them: the orifice
    plane z = 0 over |x| < b/2 (its cells above and below: the mean p of the
    pair, the mean gradient) and the face layer z = b (DEM-CFD's `above`,
    about b over the orifice: every cell of the row below it with one above
    it). p relative to the air at rest: p - p_top - rho_f g (z_top - z), p_top
    the mean of the top row of cells (air above the powder). Returns dict
    (outlet_p_Pa, outlet_dpdz_Pa_m, above_p_Pa, above_dpdz_Pa_m, snapshots),
    or None when no field was written in the window."""
    c = foam.cell_centres(run, patch)
    levels = np.unique(np.round(c[:, 1] / (1e-3 * dx)) * (1e-3 * dx))   # the rows' centre heights
    row = lambda z: np.nonzero(np.abs(c[:, 1] - z) < 1e-2 * dx)[0]

    def pairs(z, half=None):
        """The cells of the rows just below and just above z, each lower one with the
        upper one at its x (staircase: the same x; a fitted mesh's trapezoids: the
        nearest, within a quarter of the lower row's spacing), and the weight of
        the upper row in the linear interpolation to z."""
        below, above = levels[levels < z], levels[levels > z]
        if not (below.size and above.size):
            raise CaseError(f"{run}: no cells on both sides of z = {z:g} m")
        zl, zh = below.max(), above.min()
        lo, hi = row(zl), row(zh)
        if half is not None:
            lo, hi = lo[np.abs(c[lo, 0]) < half], hi[np.abs(c[hi, 0]) < half]
        spacing = np.diff(np.sort(c[lo, 0])).min() if lo.size > 1 else dx
        keep = []
        for i in lo:
            if hi.size:
                j = hi[np.argmin(np.abs(c[hi, 0] - c[i, 0]))]
                if abs(c[j, 0] - c[i, 0]) < 0.25 * spacing:
                    keep.append((i, j))
        if not keep:
            raise CaseError(f"{run}: no cells on both sides of z = {z:g} m")
        lo, hi = np.array(keep).T
        return lo, hi, (z - c[lo, 1]) / (c[hi, 1] - c[lo, 1]), c[hi, 1] - c[lo, 1]

    (o_lo, o_hi, o_w, o_h), (a_lo, a_hi, a_w, a_h) = pairs(0.0, b / 2), pairs(b)
    top = np.nonzero(c[:, 1] > c[:, 1].max() - 0.1 * dx)[0]
    rows = []
    for t, d in foam.time_dirs(run):
        if t < t0 - 1e-9 or t > t1 + 1e-9 or not os.path.exists(os.path.join(d, "p")):
            continue
        p = foam.read_field(os.path.join(d, "p"), len(c))
        p = p - p[top].mean() - rho_f * g * (c[top, 1].mean() - c[:, 1])
        rows.append([(p[o_lo] + o_w * (p[o_hi] - p[o_lo])).mean(), ((p[o_hi] - p[o_lo]) / o_h).mean(),
                     (p[a_lo] + a_w * (p[a_hi] - p[a_lo])).mean(), ((p[a_hi] - p[a_lo]) / a_h).mean()])
    if not rows:       # a short run (a test) writes no field in its window
        return None
    m = np.array(rows).mean(axis=0)
    return dict(outlet_p_Pa=m[0], outlet_dpdz_Pa_m=m[1], above_p_Pa=m[2], above_dpdz_Pa_m=m[3], snapshots=len(rows))


def probe_x(run, name="orificePressure", file="p"):
    """The x of a probes function object's first probe, from its file's header."""
    base = os.path.join(run, "postProcessing", name)
    for sub in sorted(os.listdir(base)):
        path = os.path.join(base, sub, file)
        if os.path.exists(path):
            with open(path, errors="replace") as fh:
                m = re.search(r"#\s*Probe\s+0\s*\(\s*(\S+)", fh.read(4096))
            if m:
                return float(m.group(1))
    raise CaseError(f"{base}: no {file} with a '# Probe 0 (x y z)' header")


def series(run, probe_dz, probes, label="two-fluid", xs=None, weights=None, patch="frontAndBack"):
    """Every time step of a run: t, the powder's mass flow out [kg/s] (outlet + free
    fall, positive out), the air's dp/dz at the orifice [Pa/m]: the weighted mean
    over its `probes` cells (orifice_probes; weights None: equal), the mean solid
    fraction of the orifice row's `probes` probes. A run with the axis pair only
    (before orifice_probes) has its axis dp/dz moved to the mean by its field
    snapshots (snapshot_offsets: xs the cells' x, patch the plane mesh's front),
    said. The start-up's rows before the probes' first time (its first ~11 us)
    are left out, so every series has the same steps; a chunk killed mid-write,
    which loses probe rows, ends them there (said)."""
    weights = np.ones(probes) if weights is None else np.asarray(weights, dtype=float)
    pr = read_series(run, "orificePressure", "p", 1 + 2 * probes)
    row = read_series(run, "slotRow", "alpha.particles", 1 + probes)
    flows = {patch_: (lambda d: d[d[:, 0] >= pr[0, 0] * (1 - 1e-9)])(
                 read_series(run, f"{patch_}Flow", "surfaceFieldValue.dat", 2))
             for patch_ in OUT_PATCHES}
    # as far as every file is written (a run still going has rows in some files only)
    n = min(len(pr), len(row), *(len(f) for f in flows.values()))
    t = flows["outlet"][:n, 0]
    w = flows["outlet"][:n, 1] + flows["freefall"][:n, 1]      # boundary fluxes are positive outwards
    same = np.isclose(t[:n], pr[:n, 0], rtol=1e-6) & np.isclose(t[:n], row[:n, 0], rtol=1e-6)
    if not same[:max(1, n // 2)].all():
        raise CaseError(f"{run}/postProcessing: the flow and probe files are not on the same time steps")
    if not same.all():
        k = int(np.argmin(same))
        print(f"{label}: the probe rows stop matching the flow rows at t = {t[k]:g} s "
              f"(a chunk killed mid-write): the series ends there, not at {t[n - 1]:g} s", flush=True)
        n = k
    if pr.shape[1] == 1 + 2 * probes:
        g = orifice_gradient(pr[:n, 1:], probe_dz, weights)
    elif pr.shape[1] == 3 and xs is not None:
        g_axis = (pr[:n, 1] - pr[:n, 2]) / probe_dz
        snap_t, offset, ratio = snapshot_offsets(run, xs, probe_dz, weights, patch, probe_x(run))
        g = axis_to_mean(t[:n], g_axis, snap_t, offset)
        win = (snap_t >= t[0]) & (snap_t <= t[n - 1])
        win = win if win.any() else np.ones_like(win)      # no snapshot inside the series: all of them
        print(f"{label}: axis probes only (a run set up before 2026-12-07): dp/dz moved to the orifice's mean "
              f"by {len(offset)} field snapshots (mean - axis, median {np.median(offset[win]):.4g} Pa/m; "
              f"mean / axis, median {np.nanmedian(ratio[win]):.3f})", flush=True)
    else:
        raise CaseError(f"{run}/postProcessing/orificePressure: {pr.shape[1] - 1} pressure probes, expected "
                        f"{2 * probes} (orifice_probes over {probes} cells)")
    return t[:n], w[:n], g, row[:n, 1:].mean(axis=1)


def wall_seconds(run):
    """The solver's own wall clock over a run's logs (start-up and main), for a
    level.json of a run whose chunk record is not at hand."""
    wall = 0.0
    for log in ("twoPhaseEulerFoam_startup.log", "twoPhaseEulerFoam.log"):
        with open(os.path.join(run, "log", log)) as fh:
            clock = re.findall(r"ClockTime = ([\d.eE+-]+) s", fh.read())
        wall += float(clock[-1]) if clock else 0.0
    return wall


def silo_cells(run_dir, outside):
    """system/topoSetDict: the cellSet `silo` of every cell but those in the boxes
    `outside` ((x_lo, z_lo, x_hi, z_hi): the cells of the rectangular blocks that
    lie outside the hopper, by their centres; y spans the mesh)."""
    boxes = "\n".join(f"        {{ action subtract; type cellSet; name silo; source boxToCell; "
                      f"box ({x0:.9g} -1 {z0:.9g}) ({x1:.9g} 1 {z1:.9g}); }}" for x0, z0, x1, z1 in outside)
    template.write(os.path.join(run_dir, "system", "topoSetDict"),
                   "FoamFile { version 2.0; format ascii; class dictionary; object topoSetDict; }\nactions\n(\n"
                   "        { action new; type cellSet; name silo; source boxToCell; box (-1 -1 -1) (1 1 1); }\n"
                   + boxes + "\n);\n")


def setup(run_dir, template_dir, values, write_mesh, resume=False):
    """The run folder: the template rendered with the values (kept in values.json
    but END: a resumed run may go further) and the case's mesh dictionaries
    (write_mesh(run_dir)). resume: a folder set up with the same values is kept
    as it is (different values stop, naming them)."""
    keep = {k: x for k, x in values.items() if k != "END"}
    path = os.path.join(run_dir, "values.json")
    if resume and os.path.exists(path):
        # where the pressure probes are does not change a run: one set up with the
        # axis pair (before orifice_probes) goes on with it (series() moves it to the mean)
        template.check_values(path, keep, "rerun without --resume to start again", ignore=("ORIFICE_PROBES",))
        return
    runner.clean(run_dir)
    template.render(template_dir, run_dir, {**values, "FRICTION": friction(values, template_dir),
                                            "PRESSURE_FACE": pressure_face(values.get("PRESSURE_FACE_KIND", "linear"),
                                                                           template_dir)})
    write_mesh(run_dir)
    template.save_values(path, keep)


def run(run_dir, template_dir, values, end, chunk, label, fill_g, until=0.5, past_half=False, outer=None):
    """The chunked run (gc.chunks.loop, record log/chunks.json): the mesh and the
    start-up, then twoPhaseEulerFoam from its newest time to the next chunk end,
    until `end` or until the share `until` of the fill has left or the
    discharge has stalled past 80 % out (stall_time; a chunk is stopped there
    with writeNow; past_half: on to `end` all the same). The case
    has rendered the template and written its blockMeshDict and topoSetDict.
    outer = (T, n): n outer correctors per step before t = T (a chunk ends at
    T), the template's N_OUTER after; each chunk records its number."""
    control = os.path.join(run_dir, "system", "controlDict")
    solution = os.path.join(run_dir, "system", "fvSolution")
    solver = values.get("SOLVER", SOLVERS["debian"])

    def step(rec):
        if not rec["chunks"]:
            cpu = 0.0
            # The mesh's points at 15 digits, the fields at the template's: with 8
            # digits the MCC hopper's wedge faces' normals differed by 4e-8 and
            # OpenFOAM's wedgePolyPatch warned "not planar" for every face, in
            # every log (measured: 168 warnings per chunk).
            precision = foam.read_entry(control, "writePrecision")
            foam.set_entry(control, "writePrecision", 15)
            for cmd in (["blockMesh"], ["topoSet"], ["subsetMesh", "silo", "-patch", "walls", "-overwrite"]):
                cpu += runner.run(cmd, run_dir)
            foam.set_entry(control, "writePrecision", precision)
            # subsetMesh maps the fields onto the cut mesh, but the faces it exposes
            # (the staircase walls) get undefined patch values: the powder's
            # coulombWallSlip valueFraction came out 1e5 on 62 of 226 wall faces in
            # one b/4 set-up, 0 on 22 of 346 in a b/8 one, 1 in another (measured),
            # and a first step with f = 1e5 is violent (outlet dp/dz ~ -1e8 Pa/m).
            # The template's 0/ fields are uniform: written again, every wall
            # face starts from the template's values.
            template.render(template_dir, run_dir, values, ["0"])
            for cmd in (["checkMesh"], ["setFields"]):
                cpu += runner.run(cmd, run_dir)
            print(f"{label}: {foam.checkmesh(os.path.join(run_dir, 'log', 'checkMesh.log'))[0]} cells, "
                  f"up to t = {end:g} s", flush=True)
            # Start-up: 200 fixed steps of 1 us. With the adjustable step from 1e-5 s
            # the wedge silo's powder over the open slot blew up in the second step
            # (air 200 m/s and 3.4 bar in the slot cells, measured); after 0.2 ms the
            # adjustable step is stable, limited by the relative-velocity Courant number.
            for key, value in (("endTime", 2e-4), ("deltaT", 1e-6), ("adjustTimeStep", "no")):
                foam.set_entry(control, key, value)
            cpu += runner.run([solver], run_dir, "twoPhaseEulerFoam_startup")
            for key, value in (("startFrom", "latestTime"), ("deltaT", 1e-5), ("adjustTimeStep", "yes")):
                foam.set_entry(control, key, value)
            return {"from": 0.0, "to": 2e-4, "cpu_s": cpu, "what": "mesh and start-up"}
        t0 = foam.time_dirs(run_dir)[-1][0]
        # "half_out_s": chunks.json of the runs before --until (always 0.5)
        done = rec["chunks"][-1].get("until_s", rec["chunks"][-1].get("half_out_s"))
        if done is not None and not past_half:
            return f"{until:.0%} of the fill out at t = {done:g} s"
        stall = rec["chunks"][-1].get("stalled_s")
        if stall is not None and not past_half:
            return f"the discharge stalled at t = {stall:g} s (stall_time: under 5 % of its mean rate for 0.5 s)"
        if t0 >= end - 1e-9:
            return f"t_end = {end:g} s"
        t1 = min(end, (np.floor(t0 / chunk + 1e-6) + 1) * chunk)
        n_outer = values["N_OUTER"]
        if outer and t0 < outer[0] - 1e-9:
            t1, n_outer = min(t1, outer[0]), outer[1]
        foam.set_entry(solution, "nOuterCorrectors", n_outer)
        foam.set_entry(control, "stopAt", "endTime")
        foam.set_entry(control, "endTime", f"{t1:.10g}")
        # OpenFOAM counts write times from the start time and does not write at
        # endTime: one interval from t0 to t1 makes t1 a write time (a run
        # stopped at half the fill out starts off the chunk grid)
        foam.set_entry(control, "writeInterval", f"{t1 - t0:.10g}")
        print(f"{label}: {t0:g} -> {t1:g} s" + (f" ({n_outer} outer correctors)" if n_outer != values["N_OUTER"] else ""),
              flush=True)
        cpu = runner.run([solver], run_dir, f"twoPhaseEulerFoam_{t0:g}-{t1:g}",
                         stop_when=None if past_half else lambda: run_end(run_dir, fill_g, until) != (None, None),
                         poll=20.0)
        got = foam.time_dirs(run_dir)[-1][0]
        half, stall = run_end(run_dir, fill_g, until)
        stall = None if past_half else stall
        if got < t1 - 1e-9 and (half is None and stall is None or past_half):
            raise CaseError(f"{run_dir}: twoPhaseEulerFoam ended without writing t = {t1:g} s (newest: {got:g} s); "
                            f"see log/twoPhaseEulerFoam_{t0:g}-{t1:g}.log")
        return {"from": t0, "to": got, "cpu_s": cpu, "until_s": half, "n_outer": n_outer,
                **({"stalled_s": stall} if stall is not None else {})}

    rec = chunks.loop(run_dir, step)
    print(f"{label}: {rec['reason']}", flush=True)
    return rec
