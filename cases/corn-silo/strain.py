"""Strain of the grains in the control volume over the outlet by the convex-hull
method of Rivera, Avila & Avila (2023) (reference case D):

    the grains inside the control volume at t_k; the triangles of their convex
    hull from a Delaunay triangulation; over one interval each triangle n moves
    by u_n, the mean displacement of its three grains, and
        eps = sym[ (1/V) sum_n u_n (x) n_n A_n ]
    (n_n outward unit normal, A_n area, V the hull's volume) - the divergence
    theorem applied to the displacement field, exact for a homogeneous one;
    I1 = tr eps, I2 = the sum of the principal 2 x 2 minors, J2 = I2 - I1^2 / 3
    (the reference's definition: J2 = -(1/2) s:s <= 0, s the deviator).

scipy.spatial.Delaunay (Debian's python3-scipy) gives the hull's triangles.
"""
import numpy as np
from scipy.spatial import Delaunay


def hull_strain(x0, u):
    """(eps 3 x 3, hull volume [m3], number of hull triangles) of grains at x0 (n, 3)
    displaced by u (n, 3)."""
    x0, u = np.asarray(x0, dtype=float), np.asarray(u, dtype=float)
    facets = Delaunay(x0).convex_hull                      # (m, 3) indices of the boundary triangles
    p = x0[facets]
    area = 0.5 * np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])       # n_n A_n, orientation still open
    centre = p.mean(axis=1)
    inside = x0.mean(axis=0)                               # a point inside a convex hull
    area *= np.sign(np.einsum("ij,ij->i", area, centre - inside))[:, None]   # outward
    volume = float(np.einsum("ij,ij->i", centre, area).sum() / 3.0)       # divergence theorem on x
    grad = np.einsum("ni,nj->ij", u[facets].mean(axis=1), area) / volume
    return 0.5 * (grad + grad.T), volume, len(facets)


def invariants(eps):
    """(I1, I2, J2) of a symmetric strain, J2 = I2 - I1^2/3 as the reference defines it."""
    i1 = float(np.trace(eps))
    i2 = float(eps[0, 0] * eps[1, 1] + eps[1, 1] * eps[2, 2] + eps[0, 0] * eps[2, 2]
               - eps[0, 1] ** 2 - eps[1, 2] ** 2 - eps[0, 2] ** 2)
    return i1, i2, i2 - i1 * i1 / 3.0


def in_cv(x, radius, height):
    """Mask of grain centres inside the cylinder r < radius, 0 < z < height."""
    return (np.hypot(x[:, 0], x[:, 1]) < radius) & (x[:, 2] > 0.0) & (x[:, 2] < height)


def series(snapshots, radius, height, min_grains=20):
    """The strain of every interval between consecutive snapshots [(step, columns)]
    (columns id, x, y, z): rows (step0, step1, grains, grains_lost, volume, I1, J2,
    eps_xx, eps_yy, eps_zz, eps_xy, eps_yz, eps_xz). Grains of the control volume at
    step0 missing at step1 (left the dumped region) are counted and left out."""
    rows = []
    for (s0, a), (s1, b) in zip(snapshots[:-1], snapshots[1:]):
        if not len(a["id"]):
            continue
        x0 = np.column_stack([a["x"], a["y"], a["z"]])
        sel = in_cv(x0, radius, height)
        where = {int(i): k for k, i in enumerate(b["id"])}
        ids = a["id"][sel].astype(int)
        keep = np.array([i in where for i in ids], dtype=bool)
        if keep.sum() < min_grains:
            continue
        j = np.array([where[i] for i in ids[keep]])
        x1 = np.column_stack([b["x"][j], b["y"][j], b["z"][j]])
        eps, vol, _ = hull_strain(x0[sel][keep], x1 - x0[sel][keep])
        i1, _, j2 = invariants(eps)
        rows.append((s0, s1, int(keep.sum()), int((~keep).sum()), vol, i1, j2, eps[0, 0], eps[1, 1], eps[2, 2],
                     eps[0, 1], eps[1, 2], eps[0, 2]))
    return rows
