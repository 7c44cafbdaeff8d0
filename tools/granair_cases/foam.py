"""OpenFOAM files: fields, dictionary entries, time folders, checkMesh.

Only ASCII files (every case writes `writeFormat ascii`)."""
import os
import re

import numpy as np

from . import CaseError

_UNIFORM = re.compile(r"internalField\s+uniform\s+(\([^)]*\)|[^;\s]+)\s*;")
_LIST = re.compile(r"internalField\s+nonuniform\s+List<(scalar|vector)>\s*(\d+)\s*\(")


def read_field(path, n=None):
    """internalField of a volScalarField (shape (n,)) or volVectorField ((n, 3)).
    A uniform field needs n, the number of cells."""
    try:
        with open(path) as fh:
            text = fh.read()
    except OSError as e:
        raise CaseError(f"{path}: cannot read the field ({e.strerror})")
    m = _UNIFORM.search(text)
    if m:
        if n is None:
            raise CaseError(f"{path}: uniform internalField, the number of cells is needed")
        v = m.group(1)
        value = [float(x) for x in v.strip("()").split()] if v.startswith("(") else float(v)
        return np.tile(value, (n, 1)) if isinstance(value, list) else np.full(n, value)
    m = _LIST.search(text)
    if not m:
        raise CaseError(f"{path}: no ASCII internalField (uniform or nonuniform List)")
    count, depth, end = int(m.group(2)), 1, m.end()
    while depth and end < len(text):      # the list's closing parenthesis (short lists are on one line)
        depth += {"(": 1, ")": -1}.get(text[end], 0)
        end += 1
    body = text[m.end():end - 1].replace("(", " ").replace(")", " ").split()
    vals = np.array(body, dtype=float)
    width = 3 if m.group(1) == "vector" else 1
    if vals.size != count * width or (n is not None and count != n):
        raise CaseError(f"{path}: internalField lists {vals.size // width} values, "
                        f"expected {count if n is None else n}")
    return vals.reshape(count, 3) if width == 3 else vals


def nonuniform(values, fmt="%g"):
    """A field's `nonuniform List<scalar|vector>` for a template (values: n numbers or n x 3)."""
    rows = [(fmt % v) if isinstance(v, (int, float)) else "(" + " ".join(fmt % c for c in v) + ")" for v in values]
    kind = "scalar" if not len(values) or isinstance(values[0], (int, float)) else "vector"
    return f"nonuniform List<{kind}> {len(rows)} ({' '.join(rows)})"


def _list(path):
    """The body of the one list in an ASCII OpenFOAM file (after its header)."""
    with open(path) as fh:
        text = fh.read()
    text = text[text.index("}", text.index("FoamFile")) + 1:]
    m = re.search(r"^(\d+)\s*\(", text, re.M)
    if not m:
        raise CaseError(f"{path}: no ASCII list (is the mesh written with writeFormat ascii?)")
    return int(m.group(1)), text[m.end():text.rindex(")")]


def plane_cells(case, patch="frontAndBack"):
    """Each cell of a plane mesh (one cell thick in y, `patch` the empty front and
    back) as its polygon [(x, z), ...], in OpenFOAM's cell order: the face of the
    cell on `patch` with the smaller y. Needs an ASCII polyMesh."""
    mesh = os.path.join(case, "constant", "polyMesh")
    _, body = _list(os.path.join(mesh, "points"))
    pts = np.array(body.replace("(", " ").replace(")", " ").split(), dtype=float).reshape(-1, 3)
    _, body = _list(os.path.join(mesh, "faces"))
    faces = [[int(i) for i in f.split()] for f in re.findall(r"\d+\(([^)]*)\)", body)]
    n_owner, body = _list(os.path.join(mesh, "owner"))
    owner = np.array(body.split(), dtype=int)
    with open(os.path.join(mesh, "boundary")) as fh:
        m = re.search(re.escape(patch) + r"\s*\{[^}]*?nFaces\s+(\d+);\s*startFace\s+(\d+);", fh.read())
    if not m:
        raise CaseError(f"{mesh}/boundary: no patch '{patch}' (a plane mesh needs its empty front and back)")
    n, start = int(m.group(1)), int(m.group(2))
    polys = {}
    for f in range(start, start + n):
        xyz = pts[faces[f]]
        c = owner[f]
        if c not in polys or xyz[:, 1].mean() < polys[c][1]:
            polys[c] = (xyz[:, [0, 2]], xyz[:, 1].mean())
    return [polys[c][0] for c in range(len(polys))]


def cell_centres(case, patch="frontAndBack"):
    """(x, z) of each cell of a plane mesh of rectangular cells (plane_cells: the
    vertex mean of its face on `patch` is its centre), shape (n, 2)."""
    return np.array([q.mean(axis=0) for q in plane_cells(case, patch)])


def time_dirs(case):
    """[(t, path)] of the time folders of a case (serial or reconstructed), sorted."""
    out = []
    for name in os.listdir(case):
        try:
            out.append((float(name), os.path.join(case, name)))
        except ValueError:
            pass
    return sorted(out)


def time_dir(case, t, tol=1e-9):
    """The time folder of time t, or None."""
    return next((p for tt, p in time_dirs(case) if abs(tt - t) < tol), None)


def _entry(key):
    """The top-level entry `key value;`: group 1 up to the value, group 2 the value
    (one pattern for read_entry and set_entry)."""
    return re.compile(r"^(\s*" + re.escape(key) + r"\s+)([^;\n]*);", re.M)


def read_entry(path, key):
    """The value (text) of the top-level entry `key value;` of a dictionary file."""
    with open(path) as fh:
        m = _entry(key).search(fh.read())
    if m is None:
        raise CaseError(f"{path}: no entry '{key}'")
    return m.group(2).strip()


def set_entry(path, key, value):
    """Set the top-level entry `key value;` of a dictionary file (it must exist)."""
    with open(path) as fh:
        text = fh.read()
    new, n = _entry(key).subn(lambda m: f"{m.group(1)}{value};", text, count=1)
    if n != 1:
        raise CaseError(f"{path}: no entry '{key}' to set")
    with open(path, "w") as fh:
        fh.write(new)


def checkmesh(log):
    """(cells, max non-orthogonality [deg]) from a checkMesh log."""
    with open(log) as fh:
        text = fh.read()
    cells = re.search(r"^\s*cells:\s+(\d+)", text, re.M)
    nonorth = re.search(r"non-orthogonality Max:\s+([\d.eE+-]+)", text)
    if not cells:
        raise CaseError(f"{log}: no cell count (did checkMesh run?)")
    return int(cells.group(1)), float(nonorth.group(1)) if nonorth else float("nan")


# The wall conditions of granairContinuumFoam's velocity (docs/continuum-model.md):
# Coulomb wall friction (coulombWallSlip, CoulombWallSlipFvPatchVectorField.H), free slip, no-slip.
WALLS = ("coulomb", "slip", "noSlip")


def wall_velocity(walls, mu_w):
    """The 0/U entry of a wall patch for `walls` (one of WALLS), mu_w the wall
    friction coefficient of coulomb."""
    if walls == "coulomb":
        return f"type coulombWallSlip; frictionCoefficient {mu_w:.6g}; value uniform (0 0 0);"
    if walls in WALLS:
        return f"type {walls};"
    raise CaseError(f"walls {walls!r}: expected one of {', '.join(WALLS)}")


def line_profile(case, t, names, points, patch="frontAndBack"):
    """Fields of a plane or wedge mesh (one cell thick; `patch` its empty or wedge side)
    at time t, interpolated linearly between cell centres (the mean of each cell's
    vertices on `patch`) to points [(x, z), ...]: {name: values} (a vector field gives
    its x and z components as name_x, name_z). NaN outside the mesh's centres."""
    from matplotlib.tri import LinearTriInterpolator, Triangulation
    d = time_dir(case, t)
    if d is None:
        raise CaseError(f"{case}: no time folder {t:g} (written: {[tt for tt, _ in time_dirs(case)]})")
    centres = np.array([poly.mean(axis=0) for poly in plane_cells(case, patch)])
    tri = Triangulation(centres[:, 0], centres[:, 1])
    pts = np.asarray(points, dtype=float)
    out = {}
    for name in names:
        f = read_field(os.path.join(d, name), len(centres))
        comps = {name: f} if f.ndim == 1 else {name + "_x": f[:, 0], name + "_z": f[:, 2]}
        for key, v in comps.items():
            out[key] = np.ma.filled(LinearTriInterpolator(tri, v)(pts[:, 0], pts[:, 1]).astype(float), np.nan)
    return out
