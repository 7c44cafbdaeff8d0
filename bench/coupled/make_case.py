"""make_case.py: writes the benchmark case, a packed column of spheres with
air flowing up through it, for a given particle count.

The bed is a simple cubic lattice of touching spheres (d = 1 mm, 2500 kg/m3,
void fraction 1 - pi/6 = 0.476) resting on the floor of a square column with
walls; it is created in place by LIGGGHTS (no filling or settling stage), so
every run spends its time in the coupled steps being measured. The inlet
sets the air velocity U = 0.2 m/s at the bottom; the flux is eps U with the
bed's void fraction at the inlet face, so the superficial velocity is about
0.095 m/s and the fluid force about 6 % of the particles' weight (Ergun:
~750 Pa/m; measured mean fluid force 7e-7 N per particle, weight 1.3e-5 N):
well below minimum fluidisation, the bed stays packed and the DEM keeps its
contacts, the costly case for the coupling (every particle in a dense cell,
every step). Cells are 3 d wide (the brief's mesh), and the lattice is
aligned with them, so every bed cell holds 27 particle centres.

The spheres start just touching (no overlap), so in the first coupling steps
the column compresses under gravity and rings, the same way with and without
air (the fluid force is small).

The case is template/ (ordinary OpenFOAM dictionaries and a LIGGGHTS script)
filled by gc.template (docs/cases.md).

    make_case.py --out DIR --particles N [--air on|off|forces-off] [--steps S]
                 [--np P] [--vtk-interval T]
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


def make_case(out, particles, air, steps, np_, width=None, bed_height=None, box_height=None, vtk_interval=None):
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

    gc.template.render(os.path.join(HERE, "template"), out, dict(
        W=w, H=h, HB=hb, LX=lx, LZ=lz, NX=nx, NZ=nz, NP=np_, D=D, SKIN=0.2 * D, BED_TOP=h * D, DT_DEM=DT_DEM,
        END_TIME=end_time, DT_CFD=COUPLING_INTERVAL * DT_DEM, COUPLING_INTERVAL=COUPLING_INTERVAL, U_IN=U_IN,
        AIR="off" if air == "off" else "on",
        FORCES="forces { drag off; pressureGradient off; buoyancy off; }\n" if air == "forces-off" else "",
        OUTPUT=f"output {{ vtkInterval {vtk_interval:.10g}; }}\n" if vtk_interval else ""))
    meta = {"particles": n_actual, "width_d": w, "bed_height_d": h, "box_height_d": hb,
            "cells": nx * nx * nz, "air": air, "coupling_steps": steps, "np": np_}
    gc.template.write(os.path.join(out, "bench.json"), json.dumps(meta, indent=1) + "\n")
    return meta


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", required=True)
    ap.add_argument("--particles", type=int)
    ap.add_argument("--width", type=int)
    ap.add_argument("--air", choices=["on", "off", "forces-off"], default="on")
    ap.add_argument("--steps", type=int, default=20)
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--bed-height", type=int)
    ap.add_argument("--box-height", type=int)
    ap.add_argument("--vtk-interval", type=float)
    a = ap.parse_args()
    meta = make_case(a.out, a.particles, a.air, a.steps, a.np, a.width, a.bed_height, a.box_height, a.vtk_interval)
    print(json.dumps(meta))


if __name__ == "__main__":
    main()
