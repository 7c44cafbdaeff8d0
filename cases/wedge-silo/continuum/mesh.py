#!/usr/bin/env python3
"""mesh.py: writes one continuum run of the wedge silo (granairContinuumFoam).

Usage: mesh.py --b MM --mesh N --air on|off [--walls slip|noSlip] CASE

CASE is a copy of continuum/template/; this writes into it
  system/blockMeshDict        the silo as a plane mesh, one cell across the depth
  system/setAlphaFieldDict    the settled fill (powder below z = fill height)
  constant/granularProperties powder bulk density, mu(I) of lactose, air model
and sets the wall condition in 0/U. `mesh.py --info --b MM` prints the numbers.

Geometry: the numbers of the DEM-CFD case (cases/wedge-silo/make_case.py,
imported): shaft 45 mm wide and 200 mm high on a symmetric wedge hopper of
half angle 15 deg that narrows to the slot b at z = 0, the orifice plane.
x across the silo (centred), z up, y the depth. The mesh is ONE cell of the
full 60 mm depth (front and back `empty`), so masses and flows from
granairContinuumFoam (PowderBalance: scale 1 for a plane mesh) are those of
the whole 60 mm silo without any scaling. The DEM air box below the orifice
is not meshed: the outlet patch is the orifice plane itself (static
pressure 0, air pressure 0), as in cases/mcc-hopper (README: why).

Blocks: the hopper (N cells across, graded in z so its cells stay about
square while the width grows from b to 45 mm) and the shaft (N columns of
45 mm/N, square cells). Hopper walls are at 15 deg to the mesh lines:
max non-orthogonality ~15 deg.

Fill and density: the settled DEM demo fills (reference-demo/summary.txt):
fill height above the orifice and bulk density rho_b of each b (solid
fraction 0.582-0.584 at rho_p = 1060 kg/m3).
"""
import argparse
import json
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
import make_case as mc  # noqa: E402  (the DEM case's geometry and material numbers)

# Settled fills of the DEM demo (reference-demo/summary.txt): b [mm] ->
# (fill height above the orifice [m], bulk density rho_b [kg/m3]).
FILLS = {5: (0.086, 617.66), 10: (0.135, 619.41), 15: (0.191, 617.12)}

# Shear-test data of the lactose (shared/reference/cases.md, section A):
# normal stress sigma [kPa], shear stress tau [kPa].
SHEAR_TEST = [(0.208, 0.11), (0.384, 0.198), (0.718, 0.359), (1.349, 0.667), (2.553, 1.251), (4.845, 2.368)]

# mu(I) parameters not measured for lactose (README, "Continuum fidelity",
# assumptions): mu_2 - mu_s and I0 of Jop, Forterre & Pouliquen (2006) for
# glass beads (mu_s = tan 20.9 deg, mu_2 = tan 32.76 deg, I0 = 0.279).
JOP_MU_SPAN = math.tan(math.radians(32.76)) - math.tan(math.radians(20.9))
JOP_I0 = 0.279
D_LACTOSE = 225e-6       # particle diameter of the rheology and of the Ergun drag [m]
# Dilatancy phi(I) = phi_max - (phi_max - phi_min) I (the packing relaxes
# towards it with shear, AirPercolation.H): phi_max the settled DEM solid
# fraction rho_b/rho_p; the span phi_max - phi_min is not measured for
# lactose: 0.189 as measured for MCC spheres (Remmelgas et al. 2019, cases.md
# section B; glass beads ~0.2, Pouliquen et al. 2006). Assumed.
DILATANCY_SPAN = 0.632 - 0.443


def fit_mu_s():
    """Least-squares line tau = c + mu_s sigma through the shear-test points:
    (mu_s, c [kPa]). The slope is the friction coefficient of the yield locus;
    the intercept c (cohesion, ~10 Pa) has no place in mu(I); it only sets
    the pressure floor pMin = c/mu_s (the tensile strength of the locus)."""
    n = len(SHEAR_TEST)
    ms = sum(s for s, _ in SHEAR_TEST) / n
    mt = sum(t for _, t in SHEAR_TEST) / n
    slope = (sum((s - ms) * (t - mt) for s, t in SHEAR_TEST)
             / sum((s - ms) ** 2 for s, _ in SHEAR_TEST))
    return slope, mt - slope * ms


class Silo:
    """The numbers of one continuum run."""

    def __init__(self, b_mm, n, rheology="muI"):
        if b_mm not in FILLS:
            raise SystemExit(f"mesh.py: b = {b_mm} mm, expected one of {sorted(FILLS)}")
        if n < 4:
            raise SystemExit(f"mesh.py: --mesh {n}, expected N >= 4 cells across the slot")
        self.b_mm, self.n = b_mm, n
        self.b = b_mm * 1e-3
        self.theta = math.radians(mc.HALF_ANGLE)
        self.hopper_height = (mc.WIDTH - self.b) / 2 / math.tan(self.theta)
        self.fill_height, self.rho_b = FILLS[b_mm]
        self.rheology = rheology
        if rheology == "latzSchmidt":
            # The closure fixes its own packing range: c0 < c < cMax for a
            # powder with a yield pressure. The DEM fill's 0.583 is above cMax,
            # so the bulk density is the middle of the range, rho_p (c0 + cMax)/2
            # (as cases/mcc-hopper does), at the DEM fill height (3 % less mass).
            ls = latz_parameters()
            self.rho_b = mc.RHO_P * 0.5 * (ls["c0"] + ls["cMax"])
        self.mu_s, self.cohesion_kPa = fit_mu_s()
        self.mu_2 = self.mu_s + JOP_MU_SPAN
        self.phi_max = self.rho_b / mc.RHO_P
        self.phi_min = self.phi_max - DILATANCY_SPAN
        # pressure floor of mu(I): the tensile strength c/mu_s of the fitted
        # cohesive yield locus (where tau = c + mu_s sigma meets tau = 0)
        self.p_min = self.cohesion_kPa * 1e3 / self.mu_s
        # hopper: cells about square, width w(z) = (b + 2 z tan)/N, so the
        # heights grow geometrically by q = 1 + 2 tan/N per cell.
        q = 1 + 2 * math.tan(self.theta) / n
        self.nz_hopper = max(4, round(math.log(mc.WIDTH / self.b) / math.log(q)))
        self.grading_hopper = mc.WIDTH / self.b
        self.nz_shaft = max(4, round(mc.SHAFT_HEIGHT / (mc.WIDTH / n)))

    def fill_area(self):
        """x-z area [m2] of the silo below the fill height."""
        h, hh = self.fill_height, self.hopper_height
        if h <= hh:
            return 0.5 * (2 * self.b + 2 * h * math.tan(self.theta)) * h
        return 0.5 * (self.b + mc.WIDTH) * hh + mc.WIDTH * (h - hh)

    def fill_mass(self):
        """Powder mass of the full 60 mm deep fill [kg]."""
        return self.rho_b * self.fill_area() * mc.DEPTH

    def n_cells(self):
        return self.n * (self.nz_hopper + self.nz_shaft)

    def info(self):
        return dict(b_mm=self.b_mm, mesh_n=self.n, cells=self.n_cells(), nz_hopper=self.nz_hopper,
                    nz_shaft=self.nz_shaft, hopper_height_m=self.hopper_height,
                    fill_height_m=self.fill_height, rho_b=self.rho_b, fill_mass_kg=self.fill_mass(),
                    mu_s=self.mu_s, shear_test_cohesion_kPa=self.cohesion_kPa, mu_2=self.mu_2,
                    I0=JOP_I0, d=D_LACTOSE, rho_p=mc.RHO_P, phi_max=self.phi_max, phi_min=self.phi_min,
                    p_min_Pa=self.p_min, rheology=self.rheology)


def block_mesh_dict(s):
    w, b, hh = mc.WIDTH / 2, s.b / 2, s.hopper_height
    top = hh + mc.SHAFT_HEIGHT
    pts = [(-b, 0.0), (b, 0.0), (w, hh), (-w, hh), (w, top), (-w, top)]
    n = len(pts)
    verts = [f"    ({x:.12g} 0 {z:.12g})" for x, z in pts]
    verts += [f"    ({x:.12g} {mc.DEPTH:.12g} {z:.12g})" for x, z in pts]

    def hexa(bl, br, tr, tl):
        return f"({bl} {br} {br + n} {bl + n} {tl} {tr} {tr + n} {tl + n})"

    def side(a, c):
        return f"({a} {c} {c + n} {a + n})"

    return f"""FoamFile {{ version 2.0; format ascii; class dictionary; object blockMeshDict; }}
// GENERATED by cases/wedge-silo/continuum/mesh.py: b = {s.b_mm} mm, N = {s.n}; do not edit.
// Plane mesh (x across, z up), one cell of the full {mc.DEPTH * 1e3:g} mm depth in y.
convertToMeters 1;
vertices
(
{chr(10).join(verts)}
);
blocks
(
    hex {hexa(0, 1, 2, 3)} ({s.n} 1 {s.nz_hopper}) simpleGrading (1 1 {s.grading_hopper:.6g})   // hopper
    hex {hexa(3, 2, 4, 5)} ({s.n} 1 {s.nz_shaft}) simpleGrading (1 1 1)   // shaft
);
edges ();
boundary
(
    outlet       {{ type patch; faces ( {side(1, 0)} ); }}             // the slot, z = 0
    atmosphere   {{ type patch; faces ( {side(5, 4)} ); }}             // open top of the shaft
    walls        {{ type wall; faces ( {side(1, 2)} {side(2, 4)} {side(3, 0)} {side(5, 3)} ); }}
    frontAndBack {{ type empty; faces ( (0 1 2 3) ({n} {n + 3} {n + 2} {n + 1}) (3 2 4 5) ({n + 3} {n + 5} {n + 4} {n + 2}) ); }}
);
mergePatchPairs ();
"""


def set_alpha_field_dict(s):
    return f"""FoamFile {{ version 2.0; format ascii; class dictionary; object setAlphaFieldDict; }}
// GENERATED by cases/wedge-silo/continuum/mesh.py; do not edit.
// Settled fill of the DEM demo, b = {s.b_mm} mm: powder below z = {s.fill_height} m,
// {s.fill_mass() * 1e3:.2f} g at rho_b = {s.rho_b} kg/m3 over the full depth.
field           alpha.powder;
type            plane;
origin          (0 0 {s.fill_height:.9g});
direction       (0 0 1);
"""


LATZ_RHEOLOGY = os.path.join(os.path.dirname(os.path.abspath(__file__)), "latzSchmidt", "rheology")


def latz_parameters():
    """The numbers of the lactose Latz-Schmidt block (latzSchmidt/rheology)."""
    with open(LATZ_RHEOLOGY) as fh:
        text = fh.read()
    out = {}
    for key in ("c0", "cMax", "T0", "eta0", "lambda0", "eps0", "rhoP", "etaMax", "TMin"):
        m = re.search(r"^\s*" + key + r"\s+([-+0-9.eE]+)\s*;", text, re.M)
        if not m:
            raise SystemExit(f"mesh.py: {LATZ_RHEOLOGY}: key '{key}' missing")
        out[key] = float(m.group(1))
    return out


def rheology_block(s):
    if s.rheology == "latzSchmidt":
        with open(LATZ_RHEOLOGY) as fh:
            return fh.read()
    return f"""{rheology_block(s)}"""


T_FIELD = """FoamFile { version 2.0; format ascii; class volScalarField; object T; }
// Granular temperature of the latzSchmidt rheology [m2/s2]. GENERATED by
// cases/wedge-silo/continuum/mesh.py --rheology latzSchmidt. The powder starts
// at rest: T at the floor TMin of the rheology block.
dimensions      [0 2 -2 0 0 0 0];
internalField   uniform %(t)g;
boundaryField
{
    outlet       { type inletOutlet; inletValue uniform %(t)g; value uniform %(t)g; }
    atmosphere   { type inletOutlet; inletValue uniform %(t)g; value uniform %(t)g; }
    walls        { type zeroGradient; }   // no flux of fluctuation energy through the walls
    frontAndBack { type empty; }
}
"""


def granular_properties(s, air):
    return f"""// granularProperties: the wedge silo of lactose (reference case A), b = {s.b_mm} mm.
// GENERATED by cases/wedge-silo/continuum/mesh.py; do not edit. Read by
// granairContinuumFoam (cfd-side/continuum/GranularMixture.H, AirPercolation.H).

outletPatch     outlet;

powder
{{
    rho         {s.rho_b:.6g};       // bulk density [kg/m3]: the settled DEM fill (muI), rho_p (c0 + cMax)/2 (latzSchmidt)
}}

air
{{
    rho         {mc.AIR_RHO:g};            // [kg/m3]
    mu          {mc.AIR_MU:g};         // [Pa s]
    model       {'darcyErgun' if air else 'none'};     // Allrun-continuum --air on|off
    drag        {{ type ErgunGidaspow; }}
    diameter    {D_LACTOSE:g};       // [m]
    solidFraction dilatancy;    // phi(I) of the rheology: the powder dilates as it shears
    powderThreshold 0.5;
}}

rheology
{{
    type        muI;
    muS         {s.mu_s:.4f};       // slope of the shear-test yield locus (cases.md A; cohesion c = {s.cohesion_kPa * 1e3:.1f} Pa: see pMin)
    mu2         {s.mu_2:.4f};       // mu_s + 0.2616, the span of Jop et al. (2006) glass beads (assumed)
    I0          {JOP_I0:g};          // Jop et al. (2006) glass beads (assumed)
    d           {D_LACTOSE:g};       // [m]
    rhoP        {mc.RHO_P:g};          // particle density [kg/m3]
    phiMax      {s.phi_max:.4f};       // settled DEM solid fraction rho_b/rho_p
    phiMin      {s.phi_min:.4f};       // phiMax - {DILATANCY_SPAN:.3g}, the MCC span (Remmelgas et al. 2019; assumed)
    etaMax      1e3;            // viscosity cap [Pa s] (cases/mcc-hopper README: 1e4 unstable)
    pMin        {s.p_min:.4g};          // pressure floor [Pa]: tensile strength c/mu_s of the shear-test fit
    gammaDotMin 1e-6;           // shear-rate floor [1/s]
    regularisation none;
}}
"""


def set_walls(case_dir, walls):
    path = os.path.join(case_dir, "0", "U")
    with open(path) as fh:
        text = fh.read()
    old = "walls        { type slip; }"
    if old not in text:
        raise SystemExit(f"mesh.py: {path} has no line '{old}' to set the wall condition in")
    with open(path, "w") as fh:
        fh.write(text.replace(old, "walls        { type %s; }" % walls))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--b", type=int, required=True, help="slot width [mm]: 5, 10 or 15")
    ap.add_argument("--mesh", type=int, default=12, help="cells across the slot")
    ap.add_argument("--air", choices=["on", "off"], default="on")
    ap.add_argument("--walls", choices=["slip", "noSlip"], default="slip")
    ap.add_argument("--rheology", choices=["muI", "latzSchmidt"], default="muI",
                    help="muI (default) or the lactose Latz-Schmidt closure (latzSchmidt/rheology, writes 0/T)")
    ap.add_argument("--info", action="store_true", help="print the numbers as JSON and exit")
    ap.add_argument("case", nargs="?")
    a = ap.parse_args()
    s = Silo(a.b, a.mesh, a.rheology)
    if a.info:
        print(json.dumps(s.info(), indent=1))
        return
    if not a.case:
        ap.error("CASE is required unless --info")
    with open(os.path.join(a.case, "system", "blockMeshDict"), "w") as fh:
        fh.write(block_mesh_dict(s))
    with open(os.path.join(a.case, "system", "setAlphaFieldDict"), "w") as fh:
        fh.write(set_alpha_field_dict(s))
    with open(os.path.join(a.case, "constant", "granularProperties"), "w") as fh:
        fh.write(granular_properties(s, a.air == "on"))
    set_walls(a.case, a.walls)
    if a.rheology == "latzSchmidt":
        with open(os.path.join(a.case, "0", "T"), "w") as fh:
            fh.write(T_FIELD % {"t": latz_parameters()["TMin"]})
    with open(os.path.join(a.case, "silo.json"), "w") as fh:
        json.dump(dict(s.info(), air=a.air == "on", walls=a.walls), fh, indent=1)
        fh.write("\n")


if __name__ == "__main__":
    main()
