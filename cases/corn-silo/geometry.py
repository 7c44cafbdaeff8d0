"""The silo of one hopper angle: its walls as LIGGGHTS meshes (ASCII STL) and
the rings of wall elements its wall loads are averaged over.

The walls: the hopper (a cone frustum from the outlet, z = 0, to the shaft,
HOPPER_ROWS rows), the shaft (rows of RING_HEIGHT up to STRESS_TOP), the shaft
continued to the box top, the shutter and outlet disks at z = 0 and the sink
plane. The angle is the hopper wall's from the horizontal (5 deg: nearly a flat
bottom; the half angle from the vertical is 90 deg minus it). A ring is one
row of the mesh all round: the hopper's rows along its wall, the shaft's."""
import math
import os

import numpy as np

import granair_cases as gc
import parameters as P

R, R_O = P.D_SILO / 2, P.D_OUTLET / 2


def shaft_rows(h_hopper):
    """Row boundaries of the shaft mesh: RING_HEIGHT from the hopper's top, the last row to STRESS_TOP."""
    n = max(1, math.floor((P.STRESS_TOP - h_hopper) / P.RING_HEIGHT + 1e-9))
    return [h_hopper + k * P.RING_HEIGHT for k in range(n)] + [P.STRESS_TOP]


def write(folder, angle_deg, half, z_top):
    """The STL files of one angle into folder/ (the run's dem/); returns the hopper height."""
    h, n = P.hopper_height(angle_deg), P.SECTORS
    rows = shaft_rows(h)
    shaft = [q for z0, z1 in zip(rows[:-1], rows[1:]) for q in gc.stl_walls.revolution(R, R, z0, z1, 1, n)]
    top_rows = max(1, round((z_top - P.STRESS_TOP) / 0.1))
    square = [[(-0.99 * half, -0.99 * half, P.SINK_Z), (0.99 * half, -0.99 * half, P.SINK_Z),
               (0.99 * half, 0.99 * half, P.SINK_Z), (-0.99 * half, 0.99 * half, P.SINK_Z)]]
    for name, polys in (("hopper", gc.stl_walls.revolution(R_O, R, 0.0, h, P.HOPPER_ROWS, n)), ("shaft", shaft),
                        ("top", gc.stl_walls.revolution(R, R, P.STRESS_TOP, z_top, top_rows, n)),
                        ("shutter", gc.stl_walls.disk(R_O, 0.0, n)), ("outlet", gc.stl_walls.disk(R_O, 0.0, n)),
                        ("sink", square)):
        gc.template.write(os.path.join(folder, f"{name}.stl"), gc.dem.stl(name, polys))
    return h


def rings(mesh, angle_deg):
    """The rings of the wall-load mesh (hopper then shaft: gc.wall_rings.Rings), their
    distance along the wall from the outlet edge, and rings.is_hopper."""
    c = mesh["points"][np.array(mesh["cells"])].mean(axis=1)
    r, z = np.hypot(c[:, 0], c[:, 1]), c[:, 2]
    h = P.hopper_height(angle_deg)
    hopper = z < h - 1e-9
    rows = shaft_rows(h)
    ring = np.where(hopper, np.clip(((r - R_O) / (R - R_O) * P.HOPPER_ROWS).astype(int), 0, P.HOPPER_ROWS - 1),
                    P.HOPPER_ROWS + np.clip(np.searchsorted(rows, z) - 1, 0, len(rows) - 2))
    along = np.where(hopper, np.hypot(r - R_O, z), np.hypot(R - R_O, h) + z - h)
    out = gc.wall_rings.Rings(mesh, ring, P.HOPPER_ROWS + len(rows) - 1, along)
    out.is_hopper = np.arange(out.n) < P.HOPPER_ROWS
    return out
