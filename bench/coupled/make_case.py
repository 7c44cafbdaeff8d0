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

D = 1e-3  # particle diameter [m]
DT_DEM = 1e-5  # [s]
COUPLING_INTERVAL = 50
U_IN = 0.2  # superficial air velocity [m/s]

FOAM_HEADER = "FoamFile {{ version 2.0; format ascii; class {cls}; object {obj}; }}\n"


def column_size(n):
    """Width W and bed height H in diameters, multiples of 3, H ~ 2 W, W^2 H ~ n."""
    w = max(3, 3 * round((n / 2.0) ** (1.0 / 3.0) / 3.0))
    h = max(3, 3 * round(n / (w * w) / 3.0))
    return w, h


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


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

    write(os.path.join(out, "system/blockMeshDict"), FOAM_HEADER.format(cls="dictionary", obj="blockMeshDict") + f"""
// {w} x {w} x {hb} particle diameters, cells of 3 diameters
convertToMeters 1;
vertices ( (0 0 0) ({lx} 0 0) ({lx} {lx} 0) (0 {lx} 0) (0 0 {lz}) ({lx} 0 {lz}) ({lx} {lx} {lz}) (0 {lx} {lz}) );
blocks ( hex (0 1 2 3 4 5 6 7) ({nx} {nx} {nz}) simpleGrading (1 1 1) );
boundary
(
    walls {{ type wall; faces ( (0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) ); }}
    bottom {{ type patch; faces ( (0 3 2 1) ); }}
    top {{ type patch; faces ( (4 5 6 7) ); }}
);
""")
    write(os.path.join(out, "system/controlDict"), FOAM_HEADER.format(cls="dictionary", obj="controlDict") + f"""
application granairFoam;
startFrom startTime; startTime 0; stopAt endTime; endTime {end_time:.10g}; deltaT {COUPLING_INTERVAL * DT_DEM:.10g};
// No field output inside the measured steps (the benchmark times the coupling).
writeControl timeStep; writeInterval 1000000; purgeWrite 0; writeFormat binary; writePrecision 8;
timeFormat general; timePrecision 8; runTimeModifiable false;
""")
    write(os.path.join(out, "system/fvSchemes"), FOAM_HEADER.format(cls="dictionary", obj="fvSchemes") + """
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default Gauss linear; div(epsPhi,U) Gauss limitedLinearV 1; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
""")
    write(os.path.join(out, "system/fvSolution"), FOAM_HEADER.format(cls="dictionary", obj="fvSolution") + """
solvers
{
    p { solver PCG; preconditioner DIC; tolerance 1e-8; relTol 0; }
    pFinal { $p; relTol 0; }
    "(U|UFinal)" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-8; relTol 0; }
}
PIMPLE { nOuterCorrectors 1; nCorrectors 2; nNonOrthogonalCorrectors 0; momentumPredictor no; pRefCell 0; pRefValue 0; }
""")
    write(os.path.join(out, "system/decomposeParDict"), FOAM_HEADER.format(cls="dictionary", obj="decomposeParDict") + f"""
numberOfSubdomains {np_};
method simple;
coeffs {{ n ({np_} 1 1); }}
""")
    write(os.path.join(out, "constant/transportProperties"), FOAM_HEADER.format(cls="dictionary", obj="transportProperties") + """
rho 1.2;      // air density [kg/m3]
mu 1.8e-5;    // air dynamic viscosity [Pa s]
""")
    output = f"output {{ vtkInterval {vtk_interval:.10g}; }}\n" if vtk_interval else ""
    forces = "forces { drag off; pressureGradient off; buoyancy off; }\n" if air == "forces-off" else ""
    write(os.path.join(out, "constant/couplingProperties"), FOAM_HEADER.format(cls="dictionary", obj="couplingProperties") + f"""
couplingInterval {COUPLING_INTERVAL};
air {"off" if air == "off" else "on"};
{forces}gravity (0 0 -9.81);
drag {{ type ErgunGidaspow; }}
voidFraction {{ type centre; }}
monitors {{ outlet {{ type patch; patch top; normal (0 0 1); }} }}
{output}""")
    write(os.path.join(out, "0/U"), FOAM_HEADER.format(cls="volVectorField", obj="U") + f"""
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 {U_IN});
boundaryField
{{
    walls {{ type slip; }}
    bottom {{ type fixedValue; value uniform (0 0 {U_IN}); }}
    top {{ type zeroGradient; }}
}}
""")
    write(os.path.join(out, "0/p"), FOAM_HEADER.format(cls="volScalarField", obj="p") + """
dimensions [1 -1 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    walls { type zeroGradient; }
    bottom { type zeroGradient; }
    top { type fixedValue; value uniform 0; }
}
""")
    write(os.path.join(out, "dem/in.liggghts"), f"""# benchmark column: {w} x {w} x {h} spheres of d = {D} m on a simple cubic lattice
atom_style      granular
atom_modify     map array
boundary        f f f
newton          off
communicate     single vel yes
units           si
processors      {np_} 1 1
region          domain block 0 {lx} 0 {lx} 0 {lz} units box
create_box      1 domain
neighbor        {0.2 * D} bin
neigh_modify    delay 0
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style      gran model hertz tangential history
pair_coeff      * *
timestep        {DT_DEM}
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix wz  all wall/gran model hertz tangential history primitive type 1 zplane 0.0
fix wx0 all wall/gran model hertz tangential history primitive type 1 xplane 0.0
fix wx1 all wall/gran model hertz tangential history primitive type 1 xplane {lx}
fix wy0 all wall/gran model hertz tangential history primitive type 1 yplane 0.0
fix wy1 all wall/gran model hertz tangential history primitive type 1 yplane {lx}
lattice         sc {D} origin 0.5 0.5 0.5
region          bed block 0 {lx} 0 {lx} 0 {h * D} units box
create_atoms    1 region bed
set             group all diameter {D} density 2500
fix integr all nve/sphere
""")
    meta = {"particles": n_actual, "width_d": w, "bed_height_d": h, "box_height_d": hb,
            "cells": nx * nx * nz, "air": air, "coupling_steps": steps, "np": np_}
    write(os.path.join(out, "bench.json"), json.dumps(meta, indent=1) + "\n")
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
