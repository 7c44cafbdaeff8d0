"""LIGGGHTS building blocks of the DEM cases (cases/wedge-silo, cases/mcc-hopper).

    rayleigh_time(r, E, nu, rho)        the contact time-step scale of the smallest particle
    time_steps(cfd_dt, t_rayleigh, f)   (coupling interval, DEM dt <= f x Rayleigh time)
    loose_packing(...)                  random sequential addition of spheres in a region
    write_data(path, atoms, box, rho)   a LIGGGHTS read_data file of those spheres
    stl(name, quads)                    a triangulated wall (mesh/surface) from quadrilaterals (or triangles)
    read_dump(path)                     a `custom` dump as columns
    read_dumps(path)                    every snapshot of a `custom` dump file: [(step, columns)]
    read_mesh_vtk(path)                 a `dump mesh/vtk` file: points, triangles, per-element fields
    wall_loads(path)                    its normal and shear stress and area per element (LIGGGHTS mesh stress)
    numbered(pattern)                   [(step, path)] of numbered outputs (walls_*.vtk), by step
    merge_dumps(paths, out)             the snapshots of a chunked run's dump files in one, each step once
    snapshots(pattern)                  every snapshot of a chunked run's dump files: [(step, columns)], each step once
    read_print(paths, columns)          the rows of a `fix print` file (a step first) of a chunked run, each step once
    next_prime(n)                       the smallest prime >= n (LIGGGHTS' seeds)
    merge_points(mesh)                  a `dump mesh/vtk` mesh with its repeated points merged
    write_mesh_vtk(path, ...)           triangles with per-element fields as legacy VTK (ParaView)
    discharge_balance(log)              the particle accounting granairFoam prints at the end
    fill_report(log, start)             the last line of a fill's LIGGGHTS log that begins with start
"""
import glob
import math
import os
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
    """ASCII STL of quadrilaterals (each 4 points in order), two triangles each, or
    of triangles (3 points, e.g. the fan of a disk); normals left to LIGGGHTS."""
    lines = [f"solid {name}"]
    for q in quads:
        for tri in ((q[0], q[1], q[2]),) if len(q) == 3 else ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
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
    # reshaped: a snapshot of one particle or none (an emptied silo) keeps its columns
    data = np.array([[float(v) for v in line.split()] for line in lines[i + 1:] if line.strip()]).reshape(-1, len(cols))
    return {c: data[:, k] for k, c in enumerate(cols)}


def read_dumps(path):
    """Every snapshot of a LIGGGHTS `custom` (or `local`) dump file (one file, many
    steps, as `dump_modify append yes` writes it): [(step, {column: numpy array})],
    the columns named as in its ITEM: ATOMS (ENTRIES) line; an empty snapshot has
    arrays of length 0."""
    with open(path) as fh:
        lines = fh.read().splitlines()
    out, i = [], 0
    while i < len(lines):
        if not lines[i].startswith("ITEM: TIMESTEP"):
            i += 1
            continue
        step, n = int(lines[i + 1]), int(lines[i + 3])
        j = next((k for k in range(i + 4, len(lines)) if lines[k].startswith(("ITEM: ATOMS", "ITEM: ENTRIES"))), None)
        cols = lines[j].split()[2:] if j is not None else []
        rows = [line.split() for line in lines[j + 1:j + 1 + n]] if j is not None else []
        if j is None or len(rows) < n or any(len(r) != len(cols) for r in rows):
            break                       # a snapshot cut short (a run killed while writing)
        data = np.array(rows, dtype=float).reshape(n, len(cols))
        out.append((step, {c: data[:, k] for k, c in enumerate(cols)}))
        i = j + 1 + n
    return out


def merge_dumps(paths, out):
    """The snapshots of several `dump custom` files (the chunks of a run: the first step of
    one is the last of the one before) in one file, each step once, in order; a snapshot
    a stopped chunk cut short is left out. Returns (out, number of snapshots)."""
    seen = {}
    for path in paths:
        with open(path) as fh:
            lines = fh.read().splitlines()
        starts = [i for i, line in enumerate(lines) if line.startswith("ITEM: TIMESTEP")] + [len(lines)]
        for a, b in zip(starts[:-1], starts[1:]):
            n = int(lines[a + 3])
            if b - a >= 9 + n:
                seen.setdefault(int(lines[a + 1]), lines[a:a + 9 + n])
    with open(out, "w") as fh:
        for step in sorted(seen):
            fh.write("\n".join(seen[step]) + "\n")
    return out, len(seen)


def snapshots(pattern):
    """Every snapshot of the dump files matching a glob pattern (the chunks of a run, in
    name order), each step once (the first file's), by step: [(step, columns)]."""
    snaps = {}
    for path in sorted(glob.glob(pattern)):
        for step, cols in read_dumps(path):
            snaps.setdefault(step, cols)
    return sorted(snaps.items())


def read_print(paths, columns):
    """The rows of `fix print` files (the chunks of a run, in order) whose first number is
    a step and which have one number per column: {column: array}, one row per step (a
    later file's row replaces an earlier one's), by step."""
    rows = {}
    for path in paths:
        with open(path) as fh:
            for line in fh:
                parts = line.split()
                if len(parts) == len(columns) and parts[0].isdigit():
                    rows[int(parts[0])] = [float(x) for x in parts]
    data = np.array([rows[s] for s in sorted(rows)]).reshape(-1, len(columns))
    return {c: data[:, i] for i, c in enumerate(columns)}


def next_prime(n):
    """The smallest prime >= n (LIGGGHTS wants prime seeds)."""
    while n < 2 or any(n % q == 0 for q in range(2, int(math.isqrt(n)) + 1)):
        n += 1
    return n


def merge_points(mesh):
    """(points, triangles) of a read_mesh_vtk mesh with the points LIGGGHTS repeats per
    triangle merged (to 1 nm): a smaller VTK of the same surface."""
    uniq, inverse = np.unique(np.round(mesh["points"], 9), axis=0, return_inverse=True)
    return uniq, inverse.reshape(-1)[np.array(mesh["cells"])]


def numbered(pattern):
    """[(n, path)] of the files matching a glob pattern whose one `*` stands for a
    whole number (a step: walls_*.vtk, particles_*.dump, profile_*.csv), by n."""
    head, tail = pattern.split("*")
    out = []
    for path in glob.glob(pattern):
        mid = path[len(head):len(path) - len(tail)]
        if mid.isdigit():
            out.append((int(mid), path))
    return sorted(out)


def wall_loads(path):
    """(normal, shear stress [Pa], area [m2]) per element of a `dump mesh/vtk ... stress`
    file: |f.n| / A and |f - (f.n) n| / A of the contact forces of that step (LIGGGHTS'
    fix mesh/surface/stress), and the triangles' areas."""
    m = read_mesh_vtk(path)
    try:
        f = m["fields"]
        normal, shear = np.abs(f["normal_stress_average"]), np.abs(f["shear_stress_average"])
    except KeyError as e:
        raise CaseError(f"{path}: no field {e} (was the dump written with the `stress` keyword?)")
    p = m["points"][np.array(m["cells"])]
    return normal, shear, 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)


def read_mesh_vtk(path):
    """A legacy ASCII VTK polydata file of `dump mesh/vtk` (LIGGGHTS 3.8 writes the
    OFFSETS/CONNECTIVITY form of VTK 5.1; the older per-cell lists are read too):
    {"points": (n, 3), "cells": [index arrays], "fields": {name: per-element array}}."""
    with open(path) as fh:
        tok = fh.read().split()
    try:
        k = tok.index("POINTS")
    except ValueError:
        raise CaseError(f"{path}: no POINTS (not a VTK polydata file)")
    n = int(tok[k + 1])
    points = np.array(tok[k + 3:k + 3 + 3 * n], dtype=float).reshape(n, 3)
    k = tok.index("POLYGONS", k)
    ncell, size = int(tok[k + 1]), int(tok[k + 2])
    k += 3
    if tok[k] == "OFFSETS":
        off = np.array(tok[k + 2:k + 2 + ncell], dtype=int)
        k += 2 + ncell
        if tok[k] != "CONNECTIVITY":
            raise CaseError(f"{path}: OFFSETS not followed by CONNECTIVITY")
        conn = np.array(tok[k + 2:k + 2 + size], dtype=int)
        k += 2 + size
        cells = [conn[off[c]:off[c + 1]] for c in range(ncell - 1)]
    else:
        cells = []
        for _ in range(ncell):
            m = int(tok[k])
            cells.append(np.array(tok[k + 1:k + 1 + m], dtype=int))
            k += 1 + m
    fields = {}
    if "CELL_DATA" in tok[k:]:
        k = tok.index("CELL_DATA", k)
        nc = int(tok[k + 1])
        k += 2
        while k < len(tok) and tok[k] != "POINT_DATA":
            if tok[k] == "FIELD":
                narr, k = int(tok[k + 2]), k + 3
                for _ in range(narr):
                    name, ncomp, ntup = tok[k], int(tok[k + 1]), int(tok[k + 2])
                    vals = np.array(tok[k + 4:k + 4 + ncomp * ntup], dtype=float)
                    fields[name] = vals if ncomp == 1 else vals.reshape(ntup, ncomp)
                    k += 4 + ncomp * ntup
            elif tok[k] == "SCALARS":
                name, k = tok[k + 1], k + 3 + (tok[k + 3] != "LOOKUP_TABLE")
                k += 2 if tok[k] == "LOOKUP_TABLE" else 0
                fields[name] = np.array(tok[k:k + nc], dtype=float)
                k += nc
            else:
                k += 1
    return {"points": points, "cells": cells, "fields": fields}


def write_mesh_vtk(path, points, triangles, fields, title="granair wall loads"):
    """Triangles (indices into points) with per-element scalar fields {name: values}
    as a legacy ASCII VTK polydata file (ParaView, VisIt)."""
    points, triangles = np.asarray(points, dtype=float), np.asarray(triangles, dtype=int)
    lines = ["# vtk DataFile Version 3.0", title[:255], "ASCII", "DATASET POLYDATA",
             f"POINTS {len(points)} double"]
    lines += ["%.9g %.9g %.9g" % tuple(p) for p in points]
    lines.append(f"POLYGONS {len(triangles)} {4 * len(triangles)}")
    lines += ["3 %d %d %d" % tuple(t) for t in triangles]
    lines.append(f"CELL_DATA {len(triangles)}")
    for name, vals in fields.items():
        vals = np.asarray(vals, dtype=float)
        if vals.shape != (len(triangles),):
            raise CaseError(f"{path}: field {name} has {vals.size} values for {len(triangles)} triangles")
        lines += [f"SCALARS {name} double 1", "LOOKUP_TABLE default"]
        lines += ["%.9g" % v for v in vals]
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w") as fh:
        fh.write("\n".join(lines) + "\n")
    return path


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


def fill_report(log, start="granair fill:"):
    """The last line of a LIGGGHTS log beginning with `start` (the fill scripts print
    "granair fill: settled after ..." once the bed is at rest), stripped; a CaseError
    naming the log if there is none (the fill did not finish)."""
    try:
        with open(log) as fh:
            lines = [ln.strip() for ln in fh if ln.startswith(start)]
    except OSError as e:
        raise CaseError(f"{log}: cannot read the fill's log ({e.strerror})")
    if not lines:
        raise CaseError(f"{log}: no line beginning '{start}' (did the fill finish?)")
    return lines[-1]
