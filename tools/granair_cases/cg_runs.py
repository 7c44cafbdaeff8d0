"""The granairCG runs of a study on 2-D grids (RZ about an axis, XZ averaged over a gap):
kernels and their grids, windows whose grid points fall on round positions, the fields
a study keeps, the mass check's record, and the check that what it keeps is finite.

    w, h, reach = kernel_grid("gauss", w)     width, grid spacing, how far a particle's kernel reaches
    opts = aligned("RZ", h, a_top, z_bottom, z_top, half_x, half_y)   a window on the grid
    opts = enclosing("XZ", reach, a_max, z_lo, z_hi, half_x, half_y)   a window around every particle
    kept = reduce(f, "r")                     coordinates, density, velocity, P and sqrt(J2) of both stresses
    rec = mass_record(csv, log, depth)        int rho dV on the grid against granairCG's particle mass
    bad, n = nonfinite(paths, keys)           the fields of kept CSVs with a NaN or an infinity
    check(checks, name, paths, mass, tol)     the kept fields finite; the mass record within tol
    b = Batch(case, base, have, missing, label)   granairCG runs of one case, each once; b.run(stem, opts, what)
    b.write_costs(path, extra, header)        their CPU seconds by what they were, the total over all passes

Why aligned windows: granairCG puts grid points at min + (i + 1/2) h; a window from
h floor(z / h) - h/2 puts them on multiples of h in z and x (z = 0, the orifice plane,
is a row) and at (i + 1/2) h in r (no ring on the axis, where r dr vanishes).
"""
import math
import os
import re

import numpy as np

from . import CaseError, cg, cg_grids, series


def kernel_grid(kind, w):
    """(width, spacing, reach) [m] of a kernel of width w: gauss (standard deviation w, cut
    at 3 w) on a grid of spacing w; heaviside (a ball of radius w) on spacing w / 2."""
    return (w, w, 3 * w) if kind == "gauss" else (w, w / 2, w)


def tag(kind, w_d):
    """A kernel's name in file names: gauss1, heaviside0.5 (w in particle diameters)."""
    return f"{kind}{w_d:g}"


def aligned(coordinates, h, a_top, z_bottom, z_top, half_x, half_y):
    """granairCG window options on a grid of spacing h: RZ rings to rmax = a_top rounded up
    to h (the particles of the box |x| <= half_x, |y| <= half_y), or XZ over |x| <= a_top
    rounded up to h plus h / 2 and |y| <= half_y (the gap); z from z_bottom rounded down
    to z_top rounded up, each less / plus h / 2."""
    zlo = h * math.floor(z_bottom / h + 1e-9) - h / 2
    zhi = h * math.ceil(z_top / h - 1e-9) + h / 2
    if coordinates == "RZ":
        return {"coordinates": "RZ", "axis": [0.0, 0.0], "rmax": h * math.ceil(a_top / h - 1e-9),
                "min": [-half_x, -half_y, zlo], "max": [half_x, half_y, zhi]}
    x = h * math.ceil(a_top / h - 1e-9) + h / 2
    return {"coordinates": "XZ", "min": [-x, -half_y, zlo], "max": [x, half_y, zhi]}


def enclosing(coordinates, reach, a_max, z_lo, z_hi, half_x, half_y):
    """A window that holds the whole kernel of every particle in r (|x|) <= a_max,
    z_lo <= z <= z_hi: each bound widened by the kernel's reach (the mass check: the
    density integrated over it is the particles' mass)."""
    lo, hi = z_lo - reach, z_hi + reach
    if coordinates == "RZ":
        return {"coordinates": "RZ", "axis": [0.0, 0.0], "rmax": a_max + reach,
                "min": [-half_x, -half_y, lo], "max": [half_x, half_y, hi]}
    x = a_max + reach
    return {"coordinates": "XZ", "min": [-x, -half_y, lo], "max": [x, half_y, hi]}


def reduce(f, axis):
    """The fields a study keeps of a gc.cg.read() grid: the coordinates, density, solid
    fraction, velocity (axis and z), and P = tr(sigma)/3 and sqrt(J2) of the contact and
    the kinetic stress (p_contact, tau_contact, p_kinetic, tau_kinetic): the invariants
    are what the profiles and maps show, and a few columns instead of all components
    keep the committed CSV small."""
    pc, tc = cg.invariants(f, "contact_stress")
    pk, tk = cg.invariants(f, "kinetic_stress")
    return {axis: f[axis], "z": f["z"], "density": f["density"], "volume_fraction": f["volume_fraction"],
            f"velocity_{axis}": f[f"velocity_{axis}"], "velocity_z": f["velocity_z"], "p_contact": pc,
            "tau_contact": tc, "p_kinetic": pk, "tau_kinetic": tk}


def mass_record(csv, log, depth=None):
    """int rho dV of a granairCG CSV on its grid (gc.cg_grids.mass: RZ less the midpoint
    rule's end term at the axis; XZ x depth) and the particle mass in the window
    granairCG logged (the snapshots' mean), as the dict a study writes."""
    grid, raw = cg_grids.mass(cg.read(csv), depth)
    logged, particles = cg_grids.logged_mass(log)
    return dict(grid_mass_kg=grid, grid_mass_midpoint_kg=raw, granairCG_grid_mass_kg=logged,
                particle_mass_kg=particles, relative_difference=grid / particles - 1)


def nonfinite(paths, keys=("p_contact", "tau_contact", "p_kinetic", "tau_kinetic", "density")):
    """(["file:field" with a NaN or infinity], the number of values looked at) over the
    columns `keys` of the CSVs: densities and stresses are defined everywhere (zero where
    empty), so one that is not is a failed run."""
    bad, n = [], 0
    for path in paths:
        t = series.read_csv(path)
        for k in keys:
            n += t[k].size
            if not np.all(np.isfinite(t[k])):
                bad.append(f"{os.path.basename(path)}:{k}")
    return bad, n


def check(checks, name, paths, mass, tol):
    """The checks of a run's CG outputs (a gc.checks.Checks): every density and stress of
    the kept CSVs `paths` finite, and the density integrated over a window enclosing every
    particle (`mass`: mass_record's keys) their mass within `tol`."""
    bad, n = nonfinite(paths)
    checks.true(f"{name}: CG stresses and density finite", not bad and n > 0,
                f"{n} values in {len(paths)} files" + (f"; not: {bad}" if bad else ""),
                "densities and stresses are defined everywhere (zero where empty)")
    checks.close(f"{name}: CG density integrated over a window enclosing every particle vs their mass [kg]",
                 mass["grid_mass_kg"], mass["particle_mass_kg"], tol,
                 "the kernel integrates to 1 and lies inside the window; the grid sum is a midpoint rule (spacing = w), "
                 "in RZ less its end term at the axis (gc.cg_grids.mass)")


class Batch:
    """The granairCG runs of one case folder that a study makes once each: run(stem, opts,
    what) runs granairCG with base + opts (+ CSV output) unless stem.csv exists (a stopped
    study goes on; the dumps may be gone by then), and stops with `missing` when it must
    run but `have` is false (no dumps); it prints "<label>: CG <what>: N CPU-s" and keeps
    the CPU seconds (cpu, costs) for write_costs."""

    def __init__(self, case, base, have, missing, label):
        self.case, self.base, self.have, self.missing, self.label = case, list(base), have, missing, label
        self.cpu, self.costs = 0.0, []

    def run(self, stem, opts, what):
        if os.path.exists(os.path.join(self.case, stem + ".csv")):
            return 0.0
        if not self.have:
            raise CaseError(f"{self.case}: CG {what} {self.missing}")
        c = cg.run(self.case, stem, self.base + list(opts.items()) + [("format", "csv")], os.path.basename(stem))
        self.cpu += c
        self.costs.append((what, c))
        print(f"{self.label}: CG {what}: {c:.0f} CPU-s", flush=True)
        return c

    def write_costs(self, path, extra, header):
        """key = value lines: <what as a name>_cpu_s of this pass's runs, `extra` pairs, and
        total_cpu_s, this pass's CPU added to the total an earlier pass wrote at path."""
        old = series.read_keys(path) if os.path.exists(path) else {}
        total = float(old.get("total_cpu_s", 0.0)) + self.cpu
        return series.write_keys(path, [(re.sub(r"\W+", "_", lab).strip("_") + "_cpu_s", round(c, 1))
                                        for lab, c in self.costs] + list(extra) + [("total_cpu_s", round(total, 1))],
                                 header)
