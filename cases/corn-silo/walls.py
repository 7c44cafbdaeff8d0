"""Wall loads from LIGGGHTS' own mesh stress module (`fix mesh/surface/stress`,
written by `dump mesh/vtk`): per wall element the normal stress (pressure) and
the shear stress, |f.n|/A and |f - (f.n)n|/A of the contact forces of that step.

Elements are grouped into rings (one row of the mesh all round the silo: the
hopper's rows along its wall, the shaft's of RING_HEIGHT) and averaged over
each ring by area: a ring is the smallest patch that carries enough contacts
(~100) for a load that is not one grain's. Profiles are rings against height."""
import numpy as np

import geometry
import parameters as P


class Rings:
    """The ring of every element of one silo's wall-load files (hopper then shaft)."""

    def __init__(self, mesh, angle_deg):
        pts = mesh["points"]
        tri = np.array(mesh["cells"])
        p = pts[tri]
        self.points, self.triangles = pts, tri
        self.area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)  # as gc.dem.wall_loads
        c = p.mean(axis=1)
        r, z = np.hypot(c[:, 0], c[:, 1]), c[:, 2]
        h = P.hopper_height(angle_deg)
        self.hopper = z < h - 1e-9
        rows = geometry.shaft_rows(h)
        ring = np.where(self.hopper,
                        np.clip(((r - geometry.R_O) / (geometry.R - geometry.R_O) * P.HOPPER_ROWS).astype(int),
                                0, P.HOPPER_ROWS - 1),
                        P.HOPPER_ROWS + np.clip(np.searchsorted(rows, z) - 1, 0, len(rows) - 2))
        self.ring, self.n = ring, P.HOPPER_ROWS + len(rows) - 1
        # ring centres: height, and the distance along the wall from the outlet edge
        self.z = np.array([np.average(z[ring == k], weights=self.area[ring == k]) for k in range(self.n)])
        slant = np.where(self.hopper, np.hypot(r - geometry.R_O, z), 0.0)
        self.along = np.array([np.average(np.where(self.hopper, slant, np.hypot(geometry.R - geometry.R_O, h) + z - h)
                                          [ring == k], weights=self.area[ring == k]) for k in range(self.n)])
        self.is_hopper = np.arange(self.n) < P.HOPPER_ROWS
        self.weights = np.bincount(ring, weights=self.area, minlength=self.n)

    def mean(self, values):
        """Area-weighted mean of per-element values over each ring."""
        return np.bincount(self.ring, weights=values * self.area, minlength=self.n) / self.weights


def maximum(rings, profile, hopper):
    """(value, z, distance along the wall) of the largest ring value of one wall."""
    sel = rings.is_hopper if hopper else ~rings.is_hopper
    k = np.flatnonzero(sel)[int(np.argmax(profile[sel]))]
    return float(profile[k]), float(rings.z[k]), float(rings.along[k])
