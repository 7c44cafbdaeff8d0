#!/usr/bin/env python3
"""dem_case.py: the coarse-grained DEM version of the MCC hopper (dry, no air):
geometry, material, reductions, and the writers of the fill and discharge folders
(standard library only).

    dem_case.py fill --s 5 --fill-g 1000 DIR      # loose packing + settle (LIGGGHTS)
    dem_case.py run  --s 5 --fill-g 1000 --end 1.5 --fill FILLDIR DIR   # granairFoam, air off
    dem_case.py info --s 5 --fill-g 1000          # parameters and parcel count (JSON)

Coordinates [m]: z up, z = 0 the orifice plane, the hopper axis is the z axis.
Hopper (Remmelgas et al. 2020, reference case B): cone from r = Do/2 = 12.5 mm
at z = 0 to r = Dc/2 = 63.5 mm at z = 36 mm (54.8 deg from the vertical), then
the cylinder (127 mm high; in the DEM an infinite LIGGGHTS zcylinder, so the
loose packing may stand above its top before it settles). The cone is an STL
written here; the shutter during the fill is the plane z = 0.
See README.md, section "Coarse-grained DEM", for the choices and their sources.
"""
import argparse
import json
import math
import os
import random
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "pylib"))
import dem_io  # noqa: E402  (read_dump, the discharge balance, the settle block)

# --- the hopper and the powder (reference case B) ---------------------------
R_OUT, R_CYL = 0.0125, 0.0635     # orifice and cylinder radius [m]
H_CONE, H_CYL = 0.036, 0.127      # cone and cylinder height [m]
D_PRIMARY = 660e-6                # median diameter of VIVAPUR MCC Spheres 500 [m]
RHO_P = 1500.0                    # particle density [kg/m3]
RHO_BULK = 900.0                  # bulk density [kg/m3]
G = 9.81

# --- DEM contact parameters (not in the reference; README gives the reasons) --
NU = 0.3                          # Poisson ratio (typical of polymers / pellets)
RESTITUTION = 0.55                # particle-particle and particle-wall
FRICTION_PP = 0.4                 # sliding friction particle-particle
FRICTION_PW = 0.3                 # sliding friction particle-wall
YOUNGS_DEFAULT = 5e6              # reduced Young's modulus [Pa] (real MCC ~ GPa): time step

# --- fill and discharge -------------------------------------------------------
PACKING_INSERT = 0.30             # solid fraction of the random sequential addition
SINK_Z = -0.02                    # parcels are deleted below this [m]
BOX_HALF = R_CYL + 0.002          # half width of the DEM box [m]
CFD_DT = 5e-4                     # sampling step of granairFoam (air off: no CFD) [s]
RAYLEIGH_FRACTION = 0.2           # DEM dt / Rayleigh time
TAN_CONE = (R_CYL - R_OUT) / H_CONE


class Case:
    def __init__(self, s=5.0, fill_g=1000.0, t_end=1.5, youngs=YOUNGS_DEFAULT, np=1, seed=1,
                 settle_min=0.2, settle_max=0.6):
        if not s >= 1.0:
            raise SystemExit(f"dem_case: coarse-graining factor s = {s}, expected >= 1")
        if not 0 < fill_g <= 1500:
            raise SystemExit(f"dem_case: fill {fill_g} g, expected 0 < fill <= 1500 g")
        if not t_end > 0:
            raise SystemExit(f"dem_case: discharge time {t_end} s, expected > 0")
        if np not in (1, 2):
            raise SystemExit(f"dem_case: --np {np}, expected 1 or 2")
        self.s, self.fill_g, self.np, self.seed = s, fill_g, np, seed
        self.d = s * D_PRIMARY                       # parcel diameter [m]
        self.v_parcel = math.pi / 6 * self.d ** 3
        self.n_parcels = round(fill_g * 1e-3 / (RHO_P * self.v_parcel))
        self.youngs = youngs
        shear = youngs / (2 * (1 + NU))
        self.rayleigh_time = math.pi * self.d / 2 * math.sqrt(RHO_P / shear) / (0.1631 * NU + 0.8766)
        self.coupling_interval = max(1, math.ceil(CFD_DT / (RAYLEIGH_FRACTION * self.rayleigh_time)))
        self.dem_dt = CFD_DT / self.coupling_interval
        self.n_steps = max(1, round(t_end / CFD_DT))
        self.t_end = self.n_steps * CFD_DT
        self.settle_min, self.settle_max = settle_min, settle_max
        self.fill_height = fill_height(fill_g * 1e-3)

    def info(self):
        return dict(case="mcc-hopper", level="cg-dem", s=self.s, d_primary_m=D_PRIMARY,
                    d_parcel_m=self.d, outlet_over_d_parcel=2 * R_OUT / self.d,
                    fill_g=self.fill_g, n_parcels=self.n_parcels,
                    fill_height_bulk_m=self.fill_height, youngs_Pa=self.youngs, poisson=NU,
                    restitution=RESTITUTION, friction_pp=FRICTION_PP, friction_pw=FRICTION_PW,
                    rho_p=RHO_P, rho_bulk_ref=RHO_BULK, rayleigh_time_s=self.rayleigh_time,
                    dem_dt_s=self.dem_dt, coupling_interval=self.coupling_interval,
                    sample_dt_s=CFD_DT, t_end_s=self.t_end, sink_z_m=SINK_Z, np=self.np,
                    seed=self.seed, settle_min_s=self.settle_min, settle_max_s=self.settle_max)


def fill_height(mass):
    """Height of a fill of `mass` [kg] at the reference bulk density (cone, then cylinder)."""
    v = mass / RHO_BULK
    v_cone = math.pi * H_CONE / 3 * (R_OUT ** 2 + R_OUT * R_CYL + R_CYL ** 2)
    if v <= v_cone:
        lo, hi = 0.0, H_CONE
        for _ in range(60):
            h = 0.5 * (lo + hi)
            r = R_OUT + h * TAN_CONE
            if math.pi * h / 3 * (R_OUT ** 2 + R_OUT * r + r ** 2) < v:
                lo = h
            else:
                hi = h
        return 0.5 * (lo + hi)
    return H_CONE + (v - v_cone) / (math.pi * R_CYL ** 2)


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as fh:
        fh.write(text)


def cone_stl(n_phi=48, n_z=6):
    """The cone wall as a triangulated surface (quads split in two), normals left to LIGGGHTS."""
    lines = ["solid cone"]
    for k in range(n_z):
        z0, z1 = H_CONE * k / n_z, H_CONE * (k + 1) / n_z
        r0, r1 = R_OUT + z0 * TAN_CONE, R_OUT + z1 * TAN_CONE
        for j in range(n_phi):
            a0, a1 = 2 * math.pi * j / n_phi, 2 * math.pi * (j + 1) / n_phi
            p = [(r0 * math.cos(a0), r0 * math.sin(a0), z0), (r0 * math.cos(a1), r0 * math.sin(a1), z0),
                 (r1 * math.cos(a1), r1 * math.sin(a1), z1), (r1 * math.cos(a0), r1 * math.sin(a0), z1)]
            for tri in ((p[0], p[1], p[2]), (p[0], p[2], p[3])):
                lines.append("  facet normal 0 0 0\n    outer loop")
                lines += ["      vertex %.12g %.12g %.12g" % v for v in tri]
                lines.append("    endloop\n  endfacet")
    lines.append("endsolid cone")
    return "\n".join(lines) + "\n"


def loose_packing(case, rng):
    """Random sequential addition of equal parcels into cone + cylinder above the
    shutter at about PACKING_INSERT solid fraction. Returns [(x, y, z)] and the top."""
    r = case.d / 2
    gap = 0.02 * case.d
    vol = case.n_parcels * case.v_parcel / PACKING_INSERT
    v_cone = math.pi * H_CONE / 3 * (R_OUT ** 2 + R_OUT * R_CYL + R_CYL ** 2)
    if vol <= v_cone:
        top = H_CONE
    else:
        top = H_CONE + (vol - v_cone) / (math.pi * R_CYL ** 2)
    cosc = math.cos(math.atan(TAN_CONE))
    rmax = R_CYL - r - gap
    cell = case.d * 1.0001
    grid = {}
    atoms = []

    def inside(x, y, z):
        if z < r + gap:
            return False
        rho = math.hypot(x, y)
        if rho > rmax:
            return False
        if z < H_CONE + r and (R_OUT + z * TAN_CONE - rho) * cosc < r + gap:
            return False
        return True

    def free(x, y, z):
        ix, iy, iz = int(math.floor(x / cell)), int(math.floor(y / cell)), int(math.floor(z / cell))
        lim = (2 * r + gap) ** 2
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for (px, py, pz) in grid.get((ix + dx, iy + dy, iz + dz), ()):
                        if (x - px) ** 2 + (y - py) ** 2 + (z - pz) ** 2 < lim:
                            return False
        return True

    for _ in range(case.n_parcels):
        placed = False
        while not placed:
            for _ in range(2000):
                z = rng.uniform(r, top)
                rr = min(rmax, R_OUT + z * TAN_CONE) if z < H_CONE else rmax
                x, y = rng.uniform(-rr, rr), rng.uniform(-rr, rr)
                if inside(x, y, z) and free(x, y, z):
                    key = (int(math.floor(x / cell)), int(math.floor(y / cell)), int(math.floor(z / cell)))
                    grid.setdefault(key, []).append((x, y, z))
                    atoms.append((x, y, z))
                    placed = True
                    break
            if not placed:
                top += 0.002                 # crowded: let the region grow upwards
    return atoms, max(a[2] for a in atoms) + r


def dem_box(top):
    return (-BOX_HALF, BOX_HALF, -BOX_HALF, BOX_HALF, SINK_Z - 0.01, top)


def box_top(case):
    """Top of the DEM box (and CFD mesh): above the loose packing and the cylinder."""
    loose = case.n_parcels * case.v_parcel / PACKING_INSERT
    v_cone = math.pi * H_CONE / 3 * (R_OUT ** 2 + R_OUT * R_CYL + R_CYL ** 2)
    h = H_CONE + max(0.0, loose - v_cone) / (math.pi * R_CYL ** 2)
    return max(H_CONE + H_CYL, 1.25 * h + 0.01)


def dem_common(case):
    skin = 0.3 * case.d
    soft = "soft_particles  yes             # LIGGGHTS asks for this below E = 5e6 Pa\n" \
        if case.youngs < 5e6 else ""
    c = "model hertz tangential history"
    return f"""neighbor        {skin:.6g} bin
neigh_modify    delay 0

# Material: type 1 parcels, type 2 walls. E reduced from ~GPa for the time step (README).
{soft}fix m1 all property/global youngsModulus peratomtype {case.youngs:.6g} {case.youngs:.6g}
fix m2 all property/global poissonsRatio peratomtype {NU} {NU}
fix m3 all property/global coefficientRestitution peratomtypepair 2 {RESTITUTION} {RESTITUTION} {RESTITUTION} {RESTITUTION}
fix m4 all property/global coefficientFriction peratomtypepair 2 {FRICTION_PP} {FRICTION_PW} {FRICTION_PW} {FRICTION_PW}

# Hertz normal + Mindlin-type tangential history, Coulomb limit; no cohesion
# (free-flowing 660 um spheres)
pair_style      gran {c}
pair_coeff      * *
timestep        {case.dem_dt:.10g}
fix gravi all gravity {G} vector 0.0 0.0 -1.0

# Walls: the cylinder r = {R_CYL} m (infinite zcylinder) and the cone (STL, dem_case.py)
fix cyl all wall/gran {c} primitive type 2 zcylinder {R_CYL} 0.0 0.0
fix coneMesh all mesh/surface file dem/cone.stl type 2
fix cone all wall/gran {c} mesh n_meshes 1 meshes coneMesh

fix integr all nve/sphere
# Declares particle type 1 to LIGGGHTS (it refuses to run once the hopper is
# empty unless a particle distribution names the types); never used to insert.
fix typeDecl all particletemplate/sphere 15485863 atom_type 1 density constant {RHO_P} radius constant {case.d / 2:.6g}
fix typeDist all particledistribution/discrete 32452843 1 typeDecl 1.0
"""


def write_fill(case, d):
    rng = random.Random(case.seed)
    atoms, zmax = loose_packing(case, rng)
    top = box_top(case)
    if zmax > top:
        top = zmax + 0.01
    box = dem_box(top)
    lines = [f"# MCC hopper loose packing: {len(atoms)} parcels of {case.d * 1e3:.4g} mm (dem_case.py)", "",
             f"{len(atoms)} atoms", "2 atom types",
             f"{box[0]:.12g} {box[1]:.12g} xlo xhi", f"{box[2]:.12g} {box[3]:.12g} ylo yhi",
             f"{box[4]:.12g} {box[5]:.12g} zlo zhi", "", "Atoms", ""]
    for i, (x, y, z) in enumerate(atoms, 1):
        lines.append(f"{i} 1 {case.d:.9g} {RHO_P} {x:.9g} {y:.9g} {z:.9g}")
    write(os.path.join(d, "dem", "packing.data"), "\n".join(lines) + "\n")
    write(os.path.join(d, "dem", "cone.stl"), cone_stl())
    chunk = max(1, round(0.02 / case.dem_dt))
    n_min = math.ceil(case.settle_min / (chunk * case.dem_dt))
    n_max = math.ceil(case.settle_max / (chunk * case.dem_dt))
    script = f"""# MCC hopper, fill stage (DEM only): settle a loose random packing on the
# closed shutter, then write the restart the discharge starts from.
# Written by dem_case.py: s = {case.s:g}, {case.fill_g:g} g, {len(atoms)} parcels.
atom_style      granular
atom_modify     map array
boundary        f f f
newton          off
communicate     single vel yes
units           si
processors      * 1 1
read_data       dem/packing.data

{dem_common(case)}
{dem_io.settle_on_shutter("wall/gran model hertz tangential history primitive type 2 zplane 0.0", chunk, n_min, n_max, case.settle_min, case.settle_max, track_top=True)}"""
    write(os.path.join(d, "dem", "in.fill"), script)
    write(os.path.join(d, "case.json"), json.dumps(dict(case.info(), box_top_m=top), indent=1) + "\n")


FOAM_HEADER = "FoamFile {{ version 2.0; format ascii; class {cls}; object {obj}; }}\n"


def write_run(case, d, fill_dir):
    fill_rel = os.path.relpath(os.path.abspath(fill_dir), os.path.abspath(d))
    with open(os.path.join(fill_dir, "case.json")) as fh:
        top = json.load(fh)["box_top_m"]
    x0, x1, y0, y1, z0, z1 = dem_box(top)
    # A coarse box: air is off, the mesh only has to hold every parcel (granairFoam checks it).
    nz = max(4, round((z1 - z0) / 0.02))
    write(os.path.join(d, "system", "blockMeshDict"), FOAM_HEADER.format(cls="dictionary", obj="blockMeshDict") + f"""// MCC hopper, DEM-only run: a coarse box around the DEM box (dem_case.py); no air is solved.
convertToMeters 1;
vertices
(
    ({x0} {y0} {z0}) ({x1} {y0} {z0}) ({x1} {y1} {z0}) ({x0} {y1} {z0})
    ({x0} {y0} {z1}) ({x1} {y0} {z1}) ({x1} {y1} {z1}) ({x0} {y1} {z1})
);
blocks ( hex (0 1 2 3 4 5 6 7) (4 4 {nz}) simpleGrading (1 1 1) );
edges ();
boundary
(
    outside {{ type patch; faces ( (0 3 2 1) (4 5 6 7) (0 1 5 4) (1 2 6 5) (2 3 7 6) (3 0 4 7) ); }}
);
mergePatchPairs ();
""")
    write(os.path.join(d, "system", "controlDict"), FOAM_HEADER.format(cls="dictionary", obj="controlDict") + f"""application     granairFoam;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         {case.t_end:.10g};     // discharge time [s]; t = 0 when the shutter opens
deltaT          {CFD_DT:.10g};    // = couplingInterval ({case.coupling_interval}) x DEM dt ({case.dem_dt:.6g} s)
writeControl    timeStep;
writeInterval   {case.n_steps};
purgeWrite      0;
writeFormat     ascii;
writePrecision  8;
writeCompression off;
timeFormat      general;
timePrecision   8;
runTimeModifiable false;
""")
    write(os.path.join(d, "system", "fvSchemes"), FOAM_HEADER.format(cls="dictionary", obj="fvSchemes") + """ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default Gauss linear; div(epsPhi,U) Gauss limitedLinearV 1; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
""")
    write(os.path.join(d, "system", "fvSolution"), FOAM_HEADER.format(cls="dictionary", obj="fvSolution") + """solvers
{
    p { solver PCG; preconditioner DIC; tolerance 1e-9; relTol 0; }
    pFinal { $p; }
    "(U|UFinal)" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-10; relTol 0; }
}
PIMPLE { nOuterCorrectors 1; nCorrectors 2; nNonOrthogonalCorrectors 0; momentumPredictor no; pRefCell 0; pRefValue 0; }
""")
    write(os.path.join(d, "system", "decomposeParDict"), FOAM_HEADER.format(cls="dictionary", obj="decomposeParDict")
          + f"numberOfSubdomains {case.np};\nmethod simple;\ncoeffs {{ n ({case.np} 1 1); }}   // across x, as LIGGGHTS (processors * 1 1)\n")
    write(os.path.join(d, "constant", "transportProperties"), FOAM_HEADER.format(cls="dictionary", obj="transportProperties")
          + "rho 1.22;      // air density [kg/m3] (unused: air off)\nmu 1.8e-5;    // air viscosity [Pa s] (unused)\n")
    write(os.path.join(d, "constant", "couplingProperties"), FOAM_HEADER.format(cls="dictionary", obj="couplingProperties") + f"""// MCC hopper, coarse-grained DEM without air (dem_case.py). See README.md.
couplingInterval     {case.coupling_interval};       // DEM steps per sampling step
air                  off;
coarseGrainingFactor {case.s:.10g};   // parcel = s^3 primaries of d = {D_PRIMARY * 1e6:g} um
voidFractionFloor    0.3;
gravity              (0 0 -{G});
forces               {{ drag on; pressureGradient on; buoyancy on; }}
drag                 {{ type ErgunGidaspow; }}
voidFraction         {{ type centre; }}
discharge
{{
    outletZ        0;
    sinkZ          {SINK_Z};
    massFlowWindow 0.05;
    depthScale     1;      // the full 3-D hopper is simulated
}}
dem                  {{ script dem/in.liggghts; }}
airSolverLog         off;
""")
    write(os.path.join(d, "0", "U"), FOAM_HEADER.format(cls="volVectorField", obj="U") + """dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField { outside { type pressureInletOutletVelocity; value uniform (0 0 0); } }
""")
    write(os.path.join(d, "0", "p"), FOAM_HEADER.format(cls="volScalarField", obj="p") + """dimensions [1 -1 -2 0 0 0 0];
internalField uniform 0;
boundaryField { outside { type fixedValue; value uniform 0; } }
""")
    write(os.path.join(d, "dem", "cone.stl"), cone_stl())
    script = f"""# MCC hopper, discharge (DEM only, no air). Written by dem_case.py: s = {case.s:g}.
# Starts from the settled fill without the shutter; granairFoam runs the steps.
atom_style      granular
atom_modify     map array
newton          off
communicate     single vel yes
processors      * 1 1
read_restart    {fill_rel}/dem/fill.restart

{dem_common(case)}
thermo_style    custom step atoms ke
thermo          {round(0.1 / case.dem_dt)}
thermo_modify   norm no
"""
    write(os.path.join(d, "dem", "in.liggghts"), script)
    write(os.path.join(d, "case.json"), json.dumps(dict(case.info(), fill_dir=fill_rel), indent=1) + "\n")


def add_args(p):
    p.add_argument("--s", type=float, default=5.0, help="coarse-graining factor (parcel d = s x 660 um)")
    p.add_argument("--fill-g", type=float, default=1000.0, help="fill mass [g]")
    p.add_argument("--end", type=float, default=1.5, help="discharge time [s]")
    p.add_argument("--youngs", type=float, default=YOUNGS_DEFAULT, help="Young's modulus used [Pa]")
    p.add_argument("--settle-min", type=float, default=0.2, help="minimum settling time [s]")
    p.add_argument("--np", type=int, default=1)
    p.add_argument("--seed", type=int, default=1)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    pf = sub.add_parser("fill")
    add_args(pf)
    pf.add_argument("dir")
    pr = sub.add_parser("run")
    add_args(pr)
    pr.add_argument("--fill", required=True)
    pr.add_argument("dir")
    pi = sub.add_parser("info")
    add_args(pi)
    a = ap.parse_args()
    case = Case(a.s, a.fill_g, a.end, a.youngs, a.np, a.seed, settle_min=a.settle_min)
    if a.cmd == "fill":
        write_fill(case, a.dir)
    elif a.cmd == "run":
        write_run(case, a.dir, a.fill)
    else:
        json.dump(case.info(), sys.stdout, indent=1)
        print()


if __name__ == "__main__":
    main()
