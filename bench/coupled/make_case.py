"""make_case.py: writes the benchmark case, a packed column of spheres with
air flowing up through it, for a given particle count.

Two beds (--bed) of spheres of d = 1 mm, 2500 kg/m3, resting on the floor of
a square column with walls:
- lattice (default): a simple cubic lattice of touching spheres (void
  fraction 1 - pi/6 = 0.476) created in place by LIGGGHTS (no filling or
  settling stage). Its side neighbours touch exactly, at zero overlap, so
  whether they are in contact is decided by round-off and by any small
  force: the fluid force adds contacts (3.9 -> 4.5 per particle at 1e4) and
  the pair kernel does 37 % more work (bench/README.md, "Two references").
- random: a random packed bed poured and settled once per size by LIGGGHTS
  (--settle writes that run; bed.data, any rank count), read by every run of
  the size: its contacts carry load whether the air is on or off, as in a
  silo, so the DEM solves nearly the same problem in all three runs.
Neither has a filling stage in the measured runs, so every run spends its time
in the coupled steps being measured. The inlet
sets the air velocity U = 0.2 m/s at the bottom; the flux is eps U with the
bed's void fraction at the inlet face, so the superficial velocity is about
0.095 m/s and the fluid force about 6 % of the particles' weight (Ergun:
~750 Pa/m; measured mean fluid force 7e-7 N per particle, weight 1.3e-5 N):
well below minimum fluidisation, the bed stays packed and the DEM keeps its
contacts, the costly case for the coupling (every particle in a dense cell,
every step). Cells are 3 d wide (the brief's mesh), and the lattice is
aligned with them, so every bed cell holds 27 particle centres.

The lattice's spheres start just touching (no overlap), so in the first
coupling steps the column compresses under gravity and rings; the random bed
starts at rest.

The case is template/ (ordinary OpenFOAM dictionaries and a LIGGGHTS script)
filled by gc.template (docs/cases.md).

    make_case.py --out DIR --particles N [--air on|off|forces-off] [--steps S]
                 [--np P] [--vtk-interval T] [--bed lattice | --bed random --bed-data FILE]
    make_case.py --settle DIR --particles N [--np P]    (the random bed's settling run)
    make_case.py --out DIR --width W --bed-height H [--box-height B] ...

--particles picks the column width W and bed height H (in diameters, both
multiples of 3, H ~ 2 W) so that W*W*H is close to N; the actual count is
printed. --width/--bed-height/--box-height (in diameters) give W, H and the
box height instead (the memory benchmark varies the bed in a fixed box). The case is
decomposed along x for P ranks in both codes (same planes, balanced).

--air forces-off is the fair reference of the coupling overhead: the whole
coupled run (air solve, void fraction, mapping, exchange, granair's LIGGGHTS
fixes) with `forces { drag off; pressureGradient off; buoyancy off; }`, so the
particles feel no fluid force and the DEM solves the same problem as with
`air off` (bench/README.md, "Two references").
"""

import argparse
import json
import math
import os

import granair_cases as gc

HERE = os.path.dirname(os.path.abspath(__file__))
D = 1e-3  # particle diameter [m]
DT_DEM = 1e-5  # [s]
COUPLING_INTERVAL = 50
U_IN = 0.2  # superficial air velocity [m/s]


def column_size(n):
    """Width W and bed height H in diameters, multiples of 3, H ~ 2 W, W^2 H ~ n."""
    w = max(3, 3 * round((n / 2.0) ** (1.0 / 3.0) / 3.0))
    h = max(3, 3 * round(n / (w * w) / 3.0))
    return w, h


FILL_FRACTION = 0.3  # solid fraction the random bed is poured at (random insertion stalls near 0.35)
REST_STEPS = 8000  # DEM steps after the last particle lands for the random bed to come to rest


def fill_height(w, n):
    """Height [d] of the column the random bed is poured into, a multiple of 3: the
    centres keep half a diameter from the walls (insert/pack all_in), so the volume
    they can take is (w - 1)^2 (h - 1); with the whole w^2 h a 9 d wide column held
    only 903 of its 972 spheres at 0.3 (measured)."""
    return 3 * math.ceil((n * math.pi / 6.0 / (FILL_FRACTION * (w - 1) ** 2) + 1) / 3.0)


def make_settle(out, particles, np_):
    """The LIGGGHTS run that pours and settles the random bed of this size."""
    w, h = column_size(particles)
    n = w * w * h
    hf = fill_height(w, n)
    # free fall from the top of the fill, then time to come to rest
    steps = int(math.sqrt(2.0 * hf * D / 9.81) / DT_DEM) + REST_STEPS
    values = dict(N=n, W=w, D=D, R=D / 2, LX=w * D, LZ_FILL=hf * D, NP=np_, SKIN=0.2 * D, DT_DEM=DT_DEM,
                  SETTLE_STEPS=steps)
    gc.template.render(os.path.join(HERE, "settle"), out, values)
    gc.template.render(os.path.join(HERE, "template"), out, values, ["dem/in.column"])   # the same column
    return {"particles": n, "width_d": w, "fill_height_d": hf, "settle_steps": steps, "np": np_}


def read_bed(path, n, lx, lz):
    """The settled bed's data file with its box top moved to the benchmark's
    lz; stops naming the file if it does not hold n particles inside the box."""
    with open(path) as f:
        lines = f.readlines()
    count = next((int(l.split()[0]) for l in lines if l.strip().endswith(" atoms")), None)
    if count != n:
        raise SystemExit(f"make_case: {path} holds {count} particles, expected {n} (did the settling run "
                         "insert them all? see its log)")
    out, zmax, in_atoms = [], 0.0, False
    for l in lines:
        f = l.split()
        if l.strip().endswith("xlo xhi") or l.strip().endswith("ylo yhi"):
            if abs(float(f[1]) - lx) > 1e-12:
                raise SystemExit(f"make_case: {path}: box {f[2]} {f[3]} {f[0]} {f[1]}, expected 0 {lx}")
        if l.strip().endswith("zlo zhi"):
            l = f"{f[0]} {lz!r} zlo zhi\n"
        if f and f[0] in ("Atoms", "Velocities"):
            in_atoms = f[0] == "Atoms"
        elif in_atoms and len(f) >= 7:
            zmax = max(zmax, float(f[6]) + 0.5 * float(f[2]))
        out.append(l)
    if zmax > lz:
        raise SystemExit(f"make_case: {path}: the bed reaches z = {zmax:.4g} m, above the box top {lz:.4g} m")
    return "".join(out), zmax


def make_case(out, particles, air, steps, np_, width=None, bed_height=None, box_height=None, vtk_interval=None,
              bed="lattice", bed_data=None):
    if particles is not None:
        w, h = column_size(particles)
    elif width is None or bed_height is None:
        raise SystemExit("make_case: give --particles, or --width and --bed-height")
    if width is not None:
        w = width
    if bed_height is not None:
        h = bed_height
    # Free board of a quarter of the bed, rounded up to whole cells.
    hb = box_height if box_height is not None else 3 * math.ceil(1.25 * h / 3.0)
    if w % 3 or hb % 3 or h > hb:
        raise SystemExit("make_case: width and box height must be multiples of 3 and the bed must fit")
    nx, nz = w // 3, hb // 3
    lx, lz = w * D, hb * D
    n_actual = w * w * h
    end_time = steps * COUPLING_INTERVAL * DT_DEM

    if bed == "lattice":
        box = f"region          domain block 0 {lx!r} 0 {lx!r} 0 {lz!r} units box\ncreate_box      1 domain"
        atoms = (f"lattice         sc {D!r} origin 0.5 0.5 0.5\n"
                 f"region          bed block 0 {lx!r} 0 {lx!r} 0 {h * D!r} units box\n"
                 f"create_atoms    1 region bed\n"
                 f"set             group all diameter {D!r} density 2500\n")
        kind = "simple cubic lattice"
    else:
        if not bed_data:
            raise SystemExit("make_case: --bed random needs --bed-data (the settled bed, make_case.py --settle)")
        text, zmax = read_bed(bed_data, n_actual, lx, lz)
        gc.template.write(os.path.join(out, "dem", "bed.data"), text)
        box, atoms = "read_data       dem/bed.data", ""  # LIGGGHTS runs in the case folder
        kind = f"random packed bed settled by LIGGGHTS, top at {zmax / D:.1f} d"
    gc.template.render(os.path.join(HERE, "template"), out, dict(
        BOX=box, ATOMS=atoms, BED_KIND=kind, THERMO_EVERY=10 * COUPLING_INTERVAL,
        W=w, H=h, HB=hb, LX=lx, LZ=lz, NX=nx, NZ=nz, NP=np_, D=D, SKIN=0.2 * D, BED_TOP=h * D, DT_DEM=DT_DEM,
        END_TIME=end_time, DT_CFD=COUPLING_INTERVAL * DT_DEM, COUPLING_INTERVAL=COUPLING_INTERVAL, U_IN=U_IN,
        AIR="off" if air == "off" else "on",
        FORCES="forces { drag off; pressureGradient off; buoyancy off; }\n" if air == "forces-off" else "",
        OUTPUT=f"output {{ vtkInterval {vtk_interval:.10g}; }}\n" if vtk_interval else ""))
    meta = {"particles": n_actual, "width_d": w, "bed_height_d": h, "box_height_d": hb, "bed": bed,
            "cells": nx * nx * nz, "air": air, "coupling_steps": steps, "np": np_}
    gc.template.write(os.path.join(out, "bench.json"), json.dumps(meta, indent=1) + "\n")
    return meta


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out")
    ap.add_argument("--particles", type=int)
    ap.add_argument("--width", type=int)
    ap.add_argument("--air", choices=["on", "off", "forces-off"], default="on")
    ap.add_argument("--steps", type=int, default=20)
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--bed-height", type=int)
    ap.add_argument("--box-height", type=int)
    ap.add_argument("--vtk-interval", type=float)
    ap.add_argument("--bed", choices=["lattice", "random"], default="lattice")
    ap.add_argument("--bed-data", help="the settled random bed (bed.data of a --settle run)")
    ap.add_argument("--settle", metavar="DIR", help="write the random bed's settling run to DIR instead")
    a = ap.parse_args()
    if a.settle:
        if a.particles is None:
            raise SystemExit("make_case: --settle needs --particles")
        print(json.dumps(make_settle(a.settle, a.particles, a.np)))
        return
    if a.out is None:
        raise SystemExit("make_case: give --out (or --settle)")
    meta = make_case(a.out, a.particles, a.air, a.steps, a.np, a.width, a.bed_height, a.box_height, a.vtk_interval,
                     a.bed, a.bed_data)
    print(json.dumps(meta))


if __name__ == "__main__":
    main()
