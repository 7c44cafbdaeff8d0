"""Wall loads per ring of wall elements, from LIGGGHTS' mesh stress module
(`fix mesh/surface/stress`, written by `dump mesh/vtk`; read by gc.dem.wall_loads),
and Janssen's slice balance of a silo fill with them.

    rings = Rings(mesh, ring, n, along)      which ring each element is in (the case decides)
    rings.mean(per_element)                  area-weighted mean over each ring
    value, z, along = rings.maximum(profile, sel)   the largest ring value among sel, and where
    ring_n, ring_s, el_n, el_s = loads(rings, files, steady)   every dump's ring loads, the steady element means
    k_eff, mu_mob = slice_balance(rings, normal, shear, sel, shaft, z, mass, area)

One element carries only a few particles, so a load that is not one particle's
is a mean over a ring (one row of the mesh all round a silo: a few hundred
contacts). The case gives the rings: a ring index per element, and optionally
each element's distance along the wall (a profile's abscissa).
"""
import math

import numpy as np

from . import dem


class Rings:
    """The ring of every element of one wall mesh (a `dump mesh/vtk` file: gc.dem.read_mesh_vtk)."""

    def __init__(self, mesh, ring, n, along=None):
        tri = np.array(mesh["cells"])
        p = mesh["points"][tri]
        self.points, self.triangles = mesh["points"], tri
        self.area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)  # as gc.dem.wall_loads
        self.centres = p.mean(axis=1)
        self.ring, self.n = ring, n
        self.z = self.average(self.centres[:, 2])                  # ring centres: height ...
        self.along = self.average(along) if along is not None else self.z    # ... and along the wall
        self.weights = np.bincount(ring, weights=self.area, minlength=n)    # ring areas

    def average(self, values):
        """Area-weighted mean of per-element values over each ring (np.average per ring)."""
        return np.array([np.average(values[self.ring == k], weights=self.area[self.ring == k]) for k in range(self.n)])

    def mean(self, values):
        """Area-weighted mean of per-element values over each ring (the loads)."""
        return np.bincount(self.ring, weights=values * self.area, minlength=self.n) / self.weights

    def maximum(self, profile, sel):
        """(value, z, distance along the wall) of the largest ring value among the rings sel."""
        k = np.flatnonzero(sel)[int(np.argmax(profile[sel]))]
        return float(profile[k]), float(self.z[k]), float(self.along[k])


def loads(rings, files, steady):
    """The ring means of the normal and shear stress of every wall-load dump `files`
    [(step, path)] (arrays [dump, ring]), and the per-element means over the dumps of
    `steady` (a subset of files: the steady window)."""
    el_n, el_s = np.zeros(len(rings.ring)), np.zeros(len(rings.ring))
    ring_n, ring_s = [], []
    for s, p in files:
        n_, s_, _ = dem.wall_loads(p)
        ring_n.append(rings.mean(n_))
        ring_s.append(rings.mean(s_))
        if (s, p) in steady:
            el_n += n_ / len(steady)
            el_s += s_ / len(steady)
    return np.array(ring_n), np.array(ring_s), el_n, el_s


def slice_balance(rings, normal, shear, sel, wall, z, mass, area, g=9.81):
    """Janssen's slice balance of a fill with its own wall shear: the vertical stress at
    a ring is the weight of the particles (heights z, masses) above it less the shear
    on the rings `wall` above it (taken as vertical), over the cross-section `area`;
    over the rings `sel`: K_eff = the mean of wall pressure / that stress, mu_mob =
    total wall shear / total wall pressure (the friction mobilised). NaN, NaN if sel
    holds no ring."""
    if not sel.any():
        return math.nan, math.nan
    above_w = np.array([mass[z > zk].sum() * g for zk in rings.z])
    above_t = np.array([(shear * rings.weights)[wall & (rings.z > zk)].sum() for zk in rings.z])
    sigma_v = (above_w - above_t) / area
    return (float(np.mean(normal[sel] / sigma_v[sel])),
            float(np.sum((shear * rings.weights)[sel]) / np.sum((normal * rings.weights)[sel])))
