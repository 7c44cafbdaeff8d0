"""The silo of one hopper angle as LIGGGHTS wall meshes (ASCII STL): the hopper
(a cone frustum from the outlet, z = 0, to the shaft), the shaft (rows of
RING_HEIGHT up to STRESS_TOP), the shaft continued to the box top, the shutter
and outlet disks at z = 0 and the sink plane. The angle is the hopper wall's
from the horizontal (5 deg: nearly a flat bottom; the half angle from the
vertical is 90 deg minus it)."""
import math
import os

import granair_cases as gc
import parameters as P

R, R_O = P.D_SILO / 2, P.D_OUTLET / 2


def _band(r0, r1, z0, z1, rows):
    """Quadrilaterals of the surface of revolution from (r0, z0) to (r1, z1): rows x SECTORS."""
    quads = []
    for k in range(rows):
        ra, rb = r0 + (r1 - r0) * k / rows, r0 + (r1 - r0) * (k + 1) / rows
        za, zb = z0 + (z1 - z0) * k / rows, z0 + (z1 - z0) * (k + 1) / rows
        for j in range(P.SECTORS):
            a0, a1 = 2 * math.pi * j / P.SECTORS, 2 * math.pi * (j + 1) / P.SECTORS
            quads.append([(ra * math.cos(a0), ra * math.sin(a0), za), (ra * math.cos(a1), ra * math.sin(a1), za),
                          (rb * math.cos(a1), rb * math.sin(a1), zb), (rb * math.cos(a0), rb * math.sin(a0), zb)])
    return quads


def _disk(r, z):
    return [[(0.0, 0.0, z), (r * math.cos(2 * math.pi * j / P.SECTORS), r * math.sin(2 * math.pi * j / P.SECTORS), z),
             (r * math.cos(2 * math.pi * (j + 1) / P.SECTORS), r * math.sin(2 * math.pi * (j + 1) / P.SECTORS), z)]
            for j in range(P.SECTORS)]


def shaft_rows(h_hopper):
    """Row boundaries of the shaft mesh: RING_HEIGHT from the hopper's top, the last row to STRESS_TOP."""
    n = max(1, math.floor((P.STRESS_TOP - h_hopper) / P.RING_HEIGHT + 1e-9))
    return [h_hopper + k * P.RING_HEIGHT for k in range(n)] + [P.STRESS_TOP]


def write(folder, angle_deg, half, z_top):
    """The STL files of one angle into folder/ (the run's dem/); returns the hopper height."""
    h = P.hopper_height(angle_deg)
    rows = shaft_rows(h)
    shaft = [q for z0, z1 in zip(rows[:-1], rows[1:]) for q in _band(R, R, z0, z1, 1)]
    top_rows = max(1, round((z_top - P.STRESS_TOP) / 0.1))
    square = [[(-0.99 * half, -0.99 * half, P.SINK_Z), (0.99 * half, -0.99 * half, P.SINK_Z),
               (0.99 * half, 0.99 * half, P.SINK_Z), (-0.99 * half, 0.99 * half, P.SINK_Z)]]
    for name, polys in (("hopper", _band(R_O, R, 0.0, h, P.HOPPER_ROWS)), ("shaft", shaft),
                        ("top", _band(R, R, P.STRESS_TOP, z_top, top_rows)),
                        ("shutter", _disk(R_O, 0.0)), ("outlet", _disk(R_O, 0.0)), ("sink", square)):
        gc.template.write(os.path.join(folder, f"{name}.stl"), gc.dem.stl(name, polys))
    return h
