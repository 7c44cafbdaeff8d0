#!/usr/bin/env python3
"""The two-fluid level's readers (tools/granair_cases/two_fluid.py) on hand-made
function-object files: a restart's rows replace the earlier file's from its first
time on, a row cut by a killed solver is dropped, the flow and probe series are
put on the same steps (dp/dz = the weighted mean of the orifice probes' differences
over their distance, a run with the axis pair moved by its snapshots' offset, the
orifice row's mean), the share-of-fill time, the stall stop, block means that end at the
blocks' ends, and the air pressure on the orifice plane and one b above it from
the fields of a hand-made plane mesh (plane_pressures, snapshot_offsets); the
fvSchemes entry of the particle pressure's face value and p_I's onset in the
frictional coefficients."""
import os
import sys
import tempfile

import numpy as np

from granair_cases import two_fluid

failures = []


def check(name, got, want, tol=1e-12):
    if not np.allclose(got, want, rtol=0, atol=tol):
        failures.append(f"{name}: got {got!r}, expected {want!r}")


def write(path, header, rows):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as fh:
        fh.write(header)
        for r in rows:
            fh.write(r + "\n")


with tempfile.TemporaryDirectory() as run:
    pp = os.path.join(run, "postProcessing")
    steps = [0.001 * k for k in range(1, 11)]              # 10 steps of 1 ms
    # outlet and free-fall flows: the first run to 6 ms, a restart from 5 ms (its
    # rows replace the first file's from 5 ms on) to 10 ms; outlet 2 g/s, free fall 1 g/s
    for patch, w in (("outlet", 2e-3), ("freefall", 1e-3)):
        write(os.path.join(pp, f"{patch}Flow", "0", "surfaceFieldValue.dat"), "# Time sum(alphaRhoPhi)\n",
              [f"{t:g} {9.0 if t > 0.0045 else w}" for t in steps[:6]])
        write(os.path.join(pp, f"{patch}Flow", "0.005", "surfaceFieldValue.dat"), "# Time sum(alphaRhoPhi)\n",
              [f"{t:g} {w}" for t in steps[4:]])
    # orifice_probes over two cells: p above (both 100000) and below (100100, 100300)
    # over 2 mm: -5e4 and -1.5e5 Pa/m, mean -1e5 (weights 1:3: -1.25e5); a row of two
    # probes at 0.5 and 0.7; the second run's file ends in a row cut mid-write
    head = "".join(f"# Probe {i} ({x} 0 {z})\n" for i, (x, z) in enumerate([(0.5, 1), (1.5, 1), (0.5, -1), (1.5, -1)]))
    write(os.path.join(pp, "orificePressure", "0", "p"), head, [f"{t:g} 100000 100000 100100 100300" for t in steps[:6]])
    write(os.path.join(pp, "orificePressure", "0.005", "p"), head,
          [f"{t:g} 100000 100000 100100 100300" for t in steps[4:]] + ["0.011 1000 1000"])
    write(os.path.join(pp, "slotRow", "0", "alpha.particles"), "# Probe 0\n# Probe 1\n",
          [f"{t:g} 0.5 0.7" for t in steps])
    os.utime(os.path.join(pp, "orificePressure", "0.005", "p"))

    rows = two_fluid.rows_of(os.path.join(pp, "orificePressure", "0.005", "p"), 5)
    check("a cut row is dropped", len(rows), 6)
    flow = two_fluid.read_series(run, "outletFlow", "surfaceFieldValue.dat", 2)
    check("restart: steps", flow[:, 0], steps)
    check("restart: the later file's rows from its first time on", flow[:, 1], [2e-3] * 10)
    t, w, dpdz, alpha = two_fluid.series(run, 2e-3, 2)
    check("series: steps", t, steps)
    check("series: outlet + free fall", w, [3e-3] * 10)
    check("series: dp/dz, the orifice's mean", dpdz, [-1e5] * 10, 1e-6)
    check("series: dp/dz, area-weighted", two_fluid.series(run, 2e-3, 2, weights=[1, 3])[2], [-1.25e5] * 10, 1e-6)
    check("probe_x: the first probe's x", two_fluid.probe_x(run), 0.5)
    check("series: orifice row mean", alpha, [0.6] * 10)
    # 3 g/s for 10 ms: 0.03 g out; a third of a 0.09 g fill is out at the step that reaches it
    check("out_by", two_fluid.out_by(run, 0.09, 1 / 3), 0.010)
    if two_fluid.out_by(run, 0.09, 0.5) is not None:
        failures.append("out_by: half of the fill is not out yet, expected None")

# the stall stop: 10 g/s for 4 s (40 g of a 42 g fill out, 95 % never reached), then
# 0.1 g/s: stalled once the last 0.5 s carry less than 5 % of 0.5 s at the mean rate,
# 10 (0.5 - x) + 0.1 x < 0.025 (40 + 0.1 x) / (4 + x) [g], x > 0.4826 s after the drop
tt = np.arange(1, 6001) * 1e-3
ww = np.where(tt <= 4.0, 1e-2, 1e-4)
check("stall_time", two_fluid.stall_time(tt, ww, 42.0), 4.483, 1.5e-3)
# the same trickle before 80 % is out (an arch over the slot at half out): no stop
check("stall_time: under 80 % out", two_fluid.stall_time(tt, ww, 100.0) is None, True)
# a steady flow never stalls
check("stall_time: steady", two_fluid.stall_time(tt, np.full_like(tt, 1e-2), 60.0) is None, True)

# a run with the axis pair only: its dp/dz plus the snapshots' mean-minus-axis offset,
# linear in time between them and held beyond
check("axis_to_mean", two_fluid.axis_to_mean(np.array([0.0, 0.1, 0.15, 0.2, 0.3]), np.full(5, -100.0),
                                             np.array([0.1, 0.2]), np.array([-20.0, -40.0])), [-120, -120, -130, -140, -140])
check("orifice_probes: above, then below", [float(x) for x in two_fluid.orifice_probes([0.5, 1.5], 2.0, 0.25)
                                            .replace("(", " ").replace(")", " ").split()],
      [0.5, 0.25, 1, 1.5, 0.25, 1, 0.5, 0.25, -1, 1.5, 0.25, -1])

# block means over 5 ms of a ramp on 1 ms steps: the blocks end at 5 and 10 ms
t = np.array(steps)
ends, (m,) = two_fluid.block_means(t, np.full(10, 1e-3), [t * 1e3], 0.005)
check("block ends", ends, [0.005, 0.010])
check("block means", m, [3.0, 8.0])

c = two_fluid.closure(0.6)
check("closure: contact pressure zero 0.01 below the fill", c["ALPHA_MIN_FRICTION"], 0.59)
check("closure: alphaMax 0.04 above it", c["ALPHA_MAX"], 0.64)
check("closure: full drag", c["DRAG_SCALE"], 1)

# a dry run's (air viscosity factor, drag scale): one of the two made small, with air neither
check("dry: with air", two_fluid.dry(True, "drag"), (1.0, 1))
check("dry: drag x 1/100", two_fluid.dry(False, "drag"), (1.0, two_fluid.DRY_DRAG_SCALE))
check("dry: viscosity x 1/100", two_fluid.dry(False, "viscosity"), (two_fluid.DRY_MU_FACTOR, 1))
try:
    two_fluid.dry(False, "density")
    failures.append("dry: an unknown way should stop with a CaseError")
except two_fluid.CaseError as e:
    if "density" not in str(e):
        failures.append(f"dry: the message should name the way, got: {e}")

# A plane mesh of 1 mm cells (x -2..2 mm, z -2..6 mm; the patch frontAndBack its only
# faces, which is all plane_cells reads) and p = P0 + G(x) z - rho_f g z with
# G(x) = G0 (1 + (x / 1 mm)^2): relative to the air at rest (the top row's mean
# at z_top = 5.5 mm, the hydrostatic removed) p is G(x) z - mean(G) z_top, so on
# the orifice plane of a 2 mm slot (x = +-0.5 mm) p = -mean(G) z_top and dp/dz
# = G(0.5 mm); one b = 2 mm above it dp/dz is the mean of G over the row; over
# a 4 mm slot the mean minus the axis cell's (x = 0: the cell at -0.5 mm)
# gradient is mean(G) - G(0.5 mm).
with tempfile.TemporaryDirectory() as run:
    mesh = os.path.join(run, "constant", "polyMesh")
    os.makedirs(mesh)
    nx, nz, dx = 4, 8, 1e-3
    cells = [(i, k) for k in range(nz) for i in range(nx)]
    pts, faces = [], []
    for i, k in cells:
        x0, z0 = -2e-3 + i * dx, -2e-3 + k * dx
        base = len(pts)
        pts += [(x0, y, z0) for y in (0.0, 1.0)] + [(x0 + dx, y, z0) for y in (0.0, 1.0)] + \
               [(x0 + dx, y, z0 + dx) for y in (0.0, 1.0)] + [(x0, y, z0 + dx) for y in (0.0, 1.0)]
        faces += [(base, base + 2, base + 4, base + 6), (base + 1, base + 3, base + 5, base + 7)]
    def flist(name, cls, items):
        with open(os.path.join(mesh, name), "w") as fh:
            fh.write(f"FoamFile {{ class {cls}; object {name}; }}\n{len(items)}\n(\n" + "\n".join(items) + "\n)\n")
    flist("points", "vectorField", [f"({x:.9g} {y:g} {z:.9g})" for x, y, z in pts])
    flist("faces", "faceList", ["4(" + " ".join(map(str, f)) + ")" for f in faces])
    flist("owner", "labelList", [str(f // 2) for f in range(len(faces))])
    with open(os.path.join(mesh, "boundary"), "w") as fh:
        fh.write(f"1\n(\n    frontAndBack\n    {{\n        type empty;\n        nFaces {len(faces)};\n"
                 f"        startFace 0;\n    }}\n)\n")
    g0, rho_f, g = -1000.0, 1.2, 9.81
    xc = np.array([-2e-3 + (i + 0.5) * dx for i, k in cells])
    zc = np.array([-2e-3 + (k + 0.5) * dx for i, k in cells])
    G = lambda x: g0 * (1 + (x / 1e-3) ** 2)      # noqa: E731
    for t in ("0.1", "0.2"):
        os.makedirs(os.path.join(run, t))
        pf = 1e5 + G(xc) * zc - rho_f * g * zc
        with open(os.path.join(run, t, "p"), "w") as fh:
            fh.write(f"internalField nonuniform List<scalar> {len(pf)}\n(\n"
                     + "\n".join(f"{v:.12g}" for v in pf) + "\n)\n;\n")
    got = two_fluid.plane_pressures(run, 2e-3, dx, 0.1, 0.2, rho_f, g)
    g_slot = G(0.5e-3)                              # both slot columns: x = +-0.5 mm
    check("plane_pressures: outlet dp/dz, the slot's columns", got["outlet_dpdz_Pa_m"], g_slot, 1e-6)
    check("plane_pressures: outlet p relative to the air at rest", got["outlet_p_Pa"],
          -np.mean([G(x) for x in (-1.5e-3, -0.5e-3, 0.5e-3, 1.5e-3)]) * 5.5e-3, 1e-6)
    check("plane_pressures: above dp/dz, every column", got["above_dpdz_Pa_m"],
          np.mean([G(x) for x in (-1.5e-3, -0.5e-3, 0.5e-3, 1.5e-3)]), 1e-6)
    check("plane_pressures: snapshots", got["snapshots"], 2)
    check("plane_pressures: no field in the window", two_fluid.plane_pressures(run, 2e-3, dx, 0.3, 0.4, rho_f, g) is None, True)
    t_s, off, ratio = two_fluid.snapshot_offsets(run, [-1.5e-3, -0.5e-3, 0.5e-3, 1.5e-3], dx, np.ones(4), "frontAndBack")
    check("snapshot_offsets: times", t_s, [0.1, 0.2])
    check("snapshot_offsets: the 4 mm slot's mean minus the axis cell's", off,
          [np.mean([G(x) for x in (-1.5e-3, -0.5e-3, 0.5e-3, 1.5e-3)]) - G(0.5e-3)] * 2, 1e-6)

# p_I's packing moved, the span kept, the block's other entries untouched
blk = "rheology\n{\n    type muI;\n    muS 0.4;\n    phiMax 0.6;\n    phiMin 0.45;\n    etaMax 1e5;\n}\n"
moved = two_fluid.p_i_packing(blk, 0.64, 0.15, "test")
check("p_i_packing: phiMax", two_fluid.calibration.entry(moved, "phiMax"), 0.64)
check("p_i_packing: phiMin", two_fluid.calibration.entry(moved, "phiMin"), 0.49, tol=1e-9)
check("p_i_packing: muS kept", two_fluid.calibration.entry(moved, "muS"), 0.4)

# the particle pressure's face entry of fvSchemes: none for linear, the scheme and
# its published ratio for secant, an unknown kind stops naming the known ones
if two_fluid.pressure_face("linear") != "":
    failures.append("pressure_face(linear): expected no entry (twoPhaseEulerFoam's linear)")
if "frictionalPressureSecant pfSecantRatio.particles;" not in two_fluid.pressure_face("secant"):
    failures.append(f"pressure_face(secant): {two_fluid.pressure_face('secant')!r}")
try:
    two_fluid.pressure_face("harmonic")
    failures.append("pressure_face(harmonic): expected a CaseError")
except two_fluid.CaseError as e:
    if "localMin" not in str(e):
        failures.append(f"pressure_face(harmonic): the message should name the kinds: {e}")
# p_I's onset: written into muI's coefficients only when set, refused for Latz-Schmidt
vals = dict(two_fluid.closure(0.58), RHEOLOGY=blk)
if "shearInducedAlphaMin" in two_fluid.friction(vals):
    failures.append("friction: shearInducedAlphaMin written without SHEAR_ALPHA_MIN")
if "shearInducedAlphaMin 0.45;" not in two_fluid.friction(dict(vals, SHEAR_ALPHA_MIN=0.45)):
    failures.append("friction: SHEAR_ALPHA_MIN 0.45 not written as shearInducedAlphaMin")
try:
    two_fluid.friction(dict(vals, SHEAR_ALPHA_MIN=0.45, FRICTION_MODEL="latzSchmidt"))
    failures.append("friction: SHEAR_ALPHA_MIN with latzSchmidt: expected a CaseError")
except two_fluid.CaseError:
    pass

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("two_fluid: all checks pass")
