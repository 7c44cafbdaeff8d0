"""LIGGGHTS building blocks of the DEM cases (cases/wedge-silo, cases/mcc-hopper).

    rayleigh_time(r, E, nu, rho)        the contact time-step scale of the smallest particle
    time_steps(cfd_dt, t_rayleigh, f)   (coupling interval, DEM dt <= f x Rayleigh time)
    loose_packing(...)                  random sequential addition of spheres in a region
    write_data(path, atoms, box, rho)   a LIGGGHTS read_data file of those spheres
    stl(name, quads)                    a triangulated wall (mesh/surface) from quadrilaterals
    read_dump(path)                     a `custom` dump as columns
    discharge_balance(log)              the particle accounting granairFoam prints at the end
"""
import math
import re

import numpy as np

from . import CaseError


def rayleigh_time(r, youngs, nu, rho):
    """Rayleigh time [s] of a sphere of radius r: pi r sqrt(rho/G) / (0.1631 nu + 0.8766)."""
    shear = youngs / (2 * (1 + nu))
    return math.pi * r * math.sqrt(rho / shear) / (0.1631 * nu + 0.8766)


def time_steps(cfd_dt, t_rayleigh, fraction):
    """(coupling interval, DEM dt): the CFD step a whole number of DEM steps, each at
    most `fraction` of the Rayleigh time."""
    n = max(1, math.ceil(cfd_dt / (fraction * t_rayleigh)))
    return n, cfd_dt / n


def loose_packing(diameters, rng, sample, inside, grow, top, cell, gap, origin=(0.0, 0.0, 0.0),
                  periodic_y=None, attempts=2000, square=lambda v: v * v, periodic_x=None):
    """Random sequential addition: each sphere (in the order given) is tried at
    positions sample(rng, r, top) -> (x, y, z) until inside(x, y, z, r) holds and it
    keeps `gap` from every sphere placed; after `attempts` misses the region grows
    (top = grow(top)). Neighbours are found on a grid of `cell` (>= the largest
    diameter) from `origin`; periodic_y = L wraps y in [0, L) (periodic_x = L
    x in [0, L): the shear cell of cases/rheology-calibration). `square` squares
    the contact distance (x * x; `x ** 2` differs from it in the last bit for
    about 0.1 % of x, and a packing is only reproduced bit for bit by the same
    one). Returns [(x, y, z, d)]."""
    grid, atoms = {}, []
    ny = max(1, int(periodic_y / cell)) if periodic_y else None
    nx = max(1, int(periodic_x / cell)) if periodic_x else None

    def key(x, y, z):
        iy = int(y / cell) % ny if ny else math.floor((y - origin[1]) / cell)
        ix = int(x / cell) % nx if nx else math.floor((x - origin[0]) / cell)
        return ix, iy, math.floor((z - origin[2]) / cell)

    def free(x, y, z, r):
        ix, iy, iz = key(x, y, z)
        for dx in (-1, 0, 1):
            jx = (ix + dx) % nx if nx else ix + dx
            for dz in (-1, 0, 1):
                for dy in (-1, 0, 1):
                    jy = (iy + dy) % ny if ny else iy + dy
                    for (px, py, pz, pr) in grid.get((jx, jy, iz + dz), ()):
                        ddy, ddx = y - py, x - px
                        if ny:
                            ddy -= periodic_y * round(ddy / periodic_y)
                        if nx:
                            ddx -= periodic_x * round(ddx / periodic_x)
                        rr = r + pr + gap
                        if ddx ** 2 + ddy ** 2 + (z - pz) ** 2 < square(rr):
                            return False
        return True

    for dia in diameters:
        r = dia / 2
        while True:
            for _ in range(attempts):
                x, y, z = sample(rng, r, top)
                if inside(x, y, z, r) and free(x, y, z, r):
                    grid.setdefault(key(x, y, z), []).append((x, y, z, r))
                    atoms.append((x, y, z, dia))
                    break
            else:
                top = grow(top)         # crowded: let the region grow
                continue
            break
    return atoms


def write_data(path, atoms, box, rho, title, types=None):
    """LIGGGHTS read_data file (atom_style granular: id type diameter density x y z)
    of atoms [(x, y, z, d)] in box (xlo, xhi, ylo, yhi, zlo, zhi), all of type 1
    (type 2 is left for walls), or of the per-atom `types` (1 or 2: walls made of
    particles, cases/rheology-calibration)."""
    types = types or [1] * len(atoms)
    if len(types) != len(atoms) or not set(types) <= {1, 2}:
        raise CaseError(f"{path}: {len(types)} atom types for {len(atoms)} atoms, each 1 or 2 expected")
    lines = [f"# {title}", "", f"{len(atoms)} atoms", "2 atom types",
             f"{box[0]:.12g} {box[1]:.12g} xlo xhi", f"{box[2]:.12g} {box[3]:.12g} ylo yhi",
             f"{box[4]:.12g} {box[5]:.12g} zlo zhi", "", "Atoms", ""]
    lines += [f"{i} {t} {d:.9g} {rho} {x:.9g} {y:.9g} {z:.9g}"
              for i, ((x, y, z, d), t) in enumerate(zip(atoms, types), 1)]
    with open(path, "w") as fh:
        fh.write("\n".join(lines) + "\n")


def stl(name, quads):
    """ASCII STL of quadrilaterals (each 4 points in order), two triangles each;
    normals left to LIGGGHTS."""
    lines = [f"solid {name}"]
    for q in quads:
        for tri in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
            lines.append("  facet normal 0 0 0\n    outer loop")
            lines += ["      vertex %.12g %.12g %.12g" % v for v in tri]
            lines.append("    endloop\n  endfacet")
    lines.append(f"endsolid {name}")
    return "\n".join(lines) + "\n"


def read_dump(path):
    """A LIGGGHTS `custom` dump (one snapshot): {column: numpy array}, columns from
    its ITEM: ATOMS line."""
    with open(path) as fh:
        lines = fh.read().splitlines()
    try:
        i = next(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    except StopIteration:
        raise CaseError(f"{path}: no 'ITEM: ATOMS' line (not a LIGGGHTS custom dump)")
    cols = lines[i].split()[2:]
    data = np.array([[float(v) for v in line.split()] for line in lines[i + 1:] if line.strip()])
    return {c: data[:, k] for k, c in enumerate(cols)}


BALANCE = (("inserted", "inserted"), ("present", "present"), ("removed", "removed at the sink"),
           ("lost", "lost (inserted - present - removed)"), ("discharged", "discharged (crossed the outlet)"))


def discharge_balance(log):
    """The particle accounting granairFoam prints at the end (DischargeCounter::report):
    counts and masses [kg] of inserted, present, removed, lost and discharged
    particles, the run's wall time, and `closes`: inserted = present + removed, lost 0."""
    with open(log) as fh:
        text = fh.read()
    i = text.rfind("DEM discharge balance")
    if i < 0:
        raise CaseError(f"{log}: no DEM discharge balance (did the run finish?)")
    bal = {}
    for key, label in BALANCE:
        m = re.search(r"^\s+" + re.escape(label) + r"\s+(-?\d+)\s+(\S+) kg", text[i:], re.M)
        if not m:
            raise CaseError(f"{log}: '{label}' missing from the discharge balance")
        bal[key], bal[key + "_kg"] = int(m.group(1)), float(m.group(2))
    m = re.search(r"total wall time\s+([\d.]+) s", text[i:])
    bal["wall_time_s"] = float(m.group(1)) if m else float("nan")
    bal["closes"] = bal["lost"] == 0 and bal["inserted"] == bal["present"] + bal["removed"]
    return bal
