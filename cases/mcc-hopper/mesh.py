#!/usr/bin/env python3
"""mesh.py: blockMeshDict and setAlphaFieldDict of the axisymmetric MCC hopper.

Usage: mesh.py N CASE [RHO_BULK]
                         writes CASE/system/blockMeshDict and
                         CASE/system/setAlphaFieldDict for resolution N;
                         RHO_BULK [kg/m3] (default 900, MCC) sets the fill
                         level of the 1000 g (Allrun --rheology latzSchmidt:
                         the lactose bulk density).

Geometry (Remmelgas et al. 2019, reference case B): a cylinder of diameter
Dc = 127 mm and height 127 mm on a cone 36 mm high that narrows to the
outlet, Do = 25 mm. The mesh is a wedge of half angle 2.5 deg about the z
axis, vertices at (r, +-r tan a, z), so the full hopper is exactly pi/tan(a)
wedges (cfd-side/continuum/PowderBalance.C).

Why curved block edges. A cone block whose grid lines run along the rays of
the cone and across it horizontally meets the 54.8 deg cone wall at 35 deg:
55 deg of mesh non-orthogonality at the wall and at the orifice edge, which
made both interFoam and granairContinuumFoam blow up within a few steps (the
explicit non-orthogonal correction exceeds the implicit part above 45 deg).
Here the cone is meshed in the natural coordinates of radial hopper flow:
  - its bottom is the spherical cap centred on the cone apex through the
    orifice edge (radius 15.30 mm, 6.48 mm high on the axis): the outlet
    patch. Its rays meet it at 90 deg. The lens between this cap and the
    orifice plane (1.73e-6 m3, 1.6 g of powder) is outside the domain: the
    stress-free exit surface is the cap instead of the orifice plane, the
    exit surface of radial flow (Brown & Richards 1960) and close to the
    free-fall arch of Beverloo's picture;
  - its top (the interface with the cylinder block) is an arc leaving the
    cone/cylinder corner along the bisector of the corner angle and meeting
    the axis at right angles (from z = 36 mm at the wall to 51.5 mm on the
    axis), so both blocks have 62.6 deg there instead of 35 deg.
checkMesh: max non-orthogonality ~30 deg (printed by Allrun).

Resolution N: N cells across both blocks; ~N cells along the cone (graded
finer towards the outlet) and 2N in the cylinder.
"""
import math
import os
import sys

RO, RC = 0.0125, 0.0635     # outlet and cylinder radius [m]
HCONE, HCYL = 0.036, 0.127  # cone and cylinder height [m]
HALF_ANGLE = math.radians(2.5)
FILL_MASS = 1.0             # kg
BULK_DENSITY = 900.0        # kg/m3, MCC (default)

# Cone apex (on the axis, below the orifice) and the exit cap.
Z_APEX = -HCONE * RO / (RC - RO)
RHO_OUT = math.hypot(RO, Z_APEX)
Z_CAP = Z_APEX + RHO_OUT
WALL_ANGLE = math.atan2(RC - RO, HCONE)  # from the vertical
# Junction arc: centre on the axis, tangent at the wall corner along the
# bisector of the corner between the cone wall and the cylinder wall.
_BISECTOR = math.pi - 0.5 * WALL_ANGLE  # direction from +r (152.6 deg), pointing to the axis
_SLOPE = -math.cos(_BISECTOR) / math.sin(_BISECTOR)  # (Hc - zc)/Rc
Z_JCENTRE = HCONE - _SLOPE * RC
R_JUNCTION = math.hypot(RC, HCONE - Z_JCENTRE)
Z_JUNCTION = Z_JCENTRE + R_JUNCTION


def fill_height(bulk_density):
    """Height of the powder surface for FILL_MASS: frustum minus the exit lens, then cylinder."""
    frustum = math.pi * HCONE / 3 * (RC * RC + RC * RO + RO * RO)
    h = Z_CAP
    lens = math.pi * h * h * (3 * RHO_OUT - h) / 3
    rest = FILL_MASS / bulk_density - (frustum - lens)
    return HCONE + rest / (math.pi * RC * RC)


def block_mesh_dict(n):
    t = math.tan(HALF_ANGLE)
    n_cone = max(4, n)
    n_cyl = max(8, 2 * n)
    htop = HCONE + HCYL
    # (r, z) of the block corners: K cap on axis, B orifice edge, C cone top
    # at the wall, J junction on the axis, D/E top at the wall/axis.
    corners = {"K": (0.0, Z_CAP), "B": (RO, 0.0), "C": (RC, HCONE), "J": (0.0, Z_JUNCTION),
               "D": (RC, htop), "E": (0.0, htop)}
    verts, index = [], {}
    for name, (r, z) in corners.items():
        if r == 0.0:  # on the axis: one vertex for both wedge planes
            index[name, "f"] = index[name, "b"] = len(verts)
            verts.append((0.0, 0.0, z))
        else:
            index[name, "f"] = len(verts)
            verts.append((r, -r * t, z))
            index[name, "b"] = len(verts)
            verts.append((r, r * t, z))

    def v(name, side):
        return index[name, side]

    def hexa(a, b, c, d):
        # a-b bottom edge (axis to wall), c-d top edge (wall to axis); local
        # x = r, y = z, so local z = x cross y = -y: the +y side first.
        return "(%d %d %d %d %d %d %d %d)" % tuple(
            [v(k, "b") for k in (a, b, c, d)] + [v(k, "f") for k in (a, b, c, d)])

    def face(*names_sides):
        return "(%s)" % " ".join(str(v(k, s)) for k, s in names_sides)

    def arc(a, b, mid):
        # One arc per wedge plane, through the midpoint (r, z) = mid.
        r, z = mid
        return ["    arc %d %d (%.12g %.12g %.12g)" % (v(a, side), v(b, side), r, sgn * r * t, z)
                for side, sgn in (("f", -1), ("b", 1))]

    cap_mid = (RHO_OUT * math.sin(WALL_ANGLE / 2), Z_APEX + RHO_OUT * math.cos(WALL_ANGLE / 2))
    phi_c = math.atan2(RC, HCONE - Z_JCENTRE)
    junction_mid = (R_JUNCTION * math.sin(phi_c / 2), Z_JCENTRE + R_JUNCTION * math.cos(phi_c / 2))

    lines = [
        "FoamFile { version 2.0; format ascii; class dictionary; object blockMeshDict; }",
        "// GENERATED by cases/mcc-hopper/mesh.py for N = %d; do not edit." % n,
        "convertToMeters 1;",
        "vertices",
        "(",
    ]
    lines += ["    (%.12g %.12g %.12g)" % p for p in verts]
    lines += [");", "blocks", "("]
    lines.append("    hex %s (%d %d 1) simpleGrading (1 4 1)   // cone, finer at the outlet" % (
        hexa("K", "B", "C", "J"), n, n_cone))
    lines.append("    hex %s (%d %d 1) simpleGrading (1 1 1)   // cylinder" % (hexa("J", "C", "D", "E"), n, n_cyl))
    lines += [");", "edges", "("]
    lines += arc("K", "B", cap_mid) + arc("J", "C", junction_mid)
    lines += [");", "boundary", "("]
    lines.append("    outlet { type patch; faces (%s); }" % face(("K", "f"), ("K", "b"), ("B", "b"), ("B", "f")))
    lines.append("    atmosphere { type patch; faces (%s); }" % face(("E", "f"), ("D", "f"), ("D", "b"), ("E", "b")))
    lines.append("    wall { type wall; faces (%s %s); }" % (
        face(("B", "f"), ("B", "b"), ("C", "b"), ("C", "f")), face(("C", "f"), ("C", "b"), ("D", "b"), ("D", "f"))))
    lines.append("    front { type wedge; faces (%s %s); }" % (
        face(("K", "f"), ("B", "f"), ("C", "f"), ("J", "f")), face(("J", "f"), ("C", "f"), ("D", "f"), ("E", "f"))))
    lines.append("    back { type wedge; faces (%s %s); }" % (
        face(("K", "b"), ("J", "b"), ("C", "b"), ("B", "b")), face(("J", "b"), ("E", "b"), ("D", "b"), ("C", "b"))))
    lines.append("    axis { type empty; faces (%s %s); }" % (
        face(("K", "f"), ("J", "f"), ("J", "b"), ("K", "b")), face(("J", "f"), ("E", "f"), ("E", "b"), ("J", "b"))))
    lines += [");", "mergePatchPairs ();", ""]
    return "\n".join(lines)


def set_alpha_field_dict(bulk_density):
    h = fill_height(bulk_density)
    if not h < HCONE + HCYL:
        sys.exit("mesh.py: %.0f g at %g kg/m3 does not fit in the hopper" % (FILL_MASS * 1e3, bulk_density))
    return "\n".join([
        "FoamFile { version 2.0; format ascii; class dictionary; object setAlphaFieldDict; }",
        "// GENERATED by cases/mcc-hopper/mesh.py; do not edit.",
        "// %.0f g of powder at the bulk density %g kg/m3: the cone below the exit cap" % (FILL_MASS * 1e3, bulk_density),
        "// and the cylinder up to z = %.6f m." % h,
        "field           alpha.powder;",
        "type            plane;",
        "origin          (0 0 %.9g);" % h,
        "direction       (0 0 1);",
        "",
    ])


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit("usage: mesh.py N CASE [RHO_BULK]")
    bulk_density = float(sys.argv[3]) if len(sys.argv) == 4 else BULK_DENSITY
    if not bulk_density > 0:
        sys.exit("mesh.py: RHO_BULK = %g, expected > 0" % bulk_density)
    n = int(sys.argv[1])
    if n < 4:
        sys.exit("mesh.py: N = %d, expected N >= 4" % n)
    system = os.path.join(sys.argv[2], "system")
    with open(os.path.join(system, "blockMeshDict"), "w") as out:
        out.write(block_mesh_dict(n))
    with open(os.path.join(system, "setAlphaFieldDict"), "w") as out:
        out.write(set_alpha_field_dict(bulk_density))


if __name__ == "__main__":
    main()
