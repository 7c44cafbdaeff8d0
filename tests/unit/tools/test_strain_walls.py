#!/usr/bin/env python3
"""The case layer's strain, wall_rings and the silo pieces of stl_walls, dem and
plots (tools/granair_cases) on inputs whose answer is known: the hull strain of a
homogeneous deformation (exact by the divergence theorem), the invariants of a
diagonal strain, a CG strain-rate field that is uniform, the ring means and the
slice balance of a hand-made cylinder wall, the areas of a frustum and a disk,
prime seeds, `fix print` rows of two chunks and the snapshots of two dump files,
and the figures' panels drawn without error."""
import math
import os
import sys
import tempfile

import numpy as np

from granair_cases import dem, plots, stl_walls, strain, wall_rings

failures = []


def check(name, got, want, tol=1e-12):
    if not abs(got - want) <= tol:
        failures.append(f"{name}: got {got!r}, expected {want!r} (tolerance {tol})")


# hull strain: u = G x + c is homogeneous; eps = sym(G) exactly, any translation drops out
rng = np.random.default_rng(3)
x = rng.uniform(-0.02, 0.02, (200, 3))
G = np.array([[0.010, 0.020, 0.0], [0.0, -0.030, 0.005], [0.001, 0.0, 0.020]])
eps, vol, m = strain.hull_strain(x, x @ G.T + 0.003)
check("hull strain of a homogeneous deformation", float(np.abs(eps - 0.5 * (G + G.T)).max()), 0.0)
if not 0 < vol < 0.04 ** 3 or m < 4:
    failures.append(f"hull: volume {vol} outside (0, box), {m} triangles")
i1, i2, j2 = strain.invariants(np.diag([1.0, 2.0, 3.0]))
check("I1 of diag(1, 2, 3)", i1, 6.0)
check("I2 of diag(1, 2, 3)", i2, 11.0)
check("J2 = I2 - I1^2/3 = -(1/2) s:s", j2, -0.5 * sum((v - 2.0) ** 2 for v in (1.0, 2.0, 3.0)))

# series: snapshots of particles under the same homogeneous deformation per interval;
# a particle that leaves (missing in the next snapshot) is counted, not used
ids = np.arange(1, 301)
pos = rng.uniform(-0.02, 0.02, (300, 3)) + [0.0, 0.0, 0.025]
snaps = []
for k in range(3):
    snaps.append((100 * k, dict(id=ids.astype(float), x=pos[:, 0], y=pos[:, 1], z=pos[:, 2])))
    pos = pos + pos @ G.T * 0.1
snaps[2] = (200, {c: v[1:] for c, v in snaps[2][1].items()})          # particle 1 gone at the end
rows = strain.series(snaps, 0.02, 0.05)
if len(rows) != 2 or len(rows[0]) != len(strain.COLUMNS):
    failures.append(f"series: {len(rows)} rows of {len(rows[0]) if rows else 0}, expected 2 of {len(strain.COLUMNS)}")
else:
    e = 0.05 * (G + G.T)
    for r in rows:
        check(f"series interval {r[0]}: eps_xy", r[10], e[0, 1])
        check(f"series interval {r[0]}: J2", r[6], strain.invariants(e)[2])
    inside0 = strain.in_cylinder(np.column_stack([snaps[1][1][c] for c in "xyz"]), 0.02, 0.05)
    check("series: particle lost", rows[1][3], float(inside0[0]))
    mi1, mj2 = strain.mean_invariants(rows, 0.0, 1e-3)
    check("mean invariants: I1", mi1, strain.invariants(e)[0])
    if not all(math.isnan(v) for v in strain.mean_invariants(rows, 1.0, 1e-3)):
        failures.append("mean_invariants after the last interval: expected NaN")
# a uniform CG strain rate D: eps = D x the interval over any set of points
f = {f"strain_rate_{c}": np.full(10, v) for c, v in zip(strain.COMPONENTS, (1.0, 2.0, 3.0, 0.5, 0.0, 0.0))}
f["strain_rate_xx"][0] = np.nan
ci1, cj2, ceps, n = strain.cg_mean(f, np.ones(10, bool), 0.01)
check("CG strain: I1", ci1, 0.06)
check("CG strain: eps_xy", ceps[0, 1], 0.005)
check("CG strain: points (a NaN left out)", n, 9)

# rings of a cylinder wall R = 0.1, rows of 0.01 m, 24 sectors: ring areas, means, maximum
R, n_sec, rows_z = 0.1, 24, np.arange(6) * 0.01
quads = [q for z0, z1 in zip(rows_z[:-1], rows_z[1:]) for q in stl_walls.revolution(R, R, z0, z1, 1, n_sec)]
pts, cells = [], []
for q in quads:
    base = len(pts)
    pts += q
    cells += [np.array([base, base + 1, base + 2]), np.array([base, base + 2, base + 3])]
mesh = {"points": np.array(pts), "cells": cells}
c = np.array(pts)[np.array(cells)].mean(axis=1)
ring = np.clip(np.searchsorted(rows_z, c[:, 2]) - 1, 0, 4)
rings = wall_rings.Rings(mesh, ring, 5)
chord = 2 * R * math.sin(math.pi / n_sec)
check("ring area", float(rings.weights[2]), n_sec * chord * 0.01, 1e-15)
check("ring centre height", float(rings.z[3]), 0.035, 1e-15)
load = c[:, 2] * 1e4                                   # linear in z: the ring mean is the ring centre's
prof = rings.mean(load)
check("ring mean of a linear load", float(prof[1]), 150.0, 1e-9)
val, zmax, _ = rings.maximum(prof, np.array([True, True, True, False, False]))
check("maximum among the first three rings", val, 250.0, 1e-9)
check("its height", zmax, 0.025, 1e-15)
# slice balance without wall shear: sigma_v = the weight above / area; K_eff = p_w / sigma_v
zm, mm = np.array([0.012, 0.032, 0.048]), np.array([1.0, 2.0, 3.0])
normal = np.full(5, 100.0)
k_eff, mu = wall_rings.slice_balance(rings, normal, np.zeros(5), np.array([False, True, False, False, False]),
                                     np.ones(5, bool), zm, mm, 0.5, g=10.0)
check("K_eff without wall shear", k_eff, 100.0 / (50.0 / 0.5), 1e-12)
check("mu mobilised without wall shear", mu, 0.0)
# with a uniform wall shear tau on every ring: the rings above carry tau x their area
tau = np.full(5, 20.0)
k2, mu2 = wall_rings.slice_balance(rings, normal, tau, np.array([False, True, False, False, False]),
                                   np.ones(5, bool), zm, mm, 0.5, g=10.0)
check("K_eff with wall shear", k2, 100.0 / ((50.0 - 3 * 20.0 * float(rings.weights[0])) / 0.5), 1e-9)
check("mu mobilised", mu2, 0.2, 1e-12)
if not all(math.isnan(v) for v in wall_rings.slice_balance(rings, normal, tau, np.zeros(5, bool), np.ones(5, bool),
                                                           zm, mm, 0.5)):
    failures.append("slice balance over no ring: expected NaN")
pts2, tri2 = dem.merge_points(mesh)
if len(pts2) != 6 * n_sec or tri2.shape != (len(cells), 3):
    failures.append(f"merge_points: {len(pts2)} points, {tri2.shape} triangles; expected {6 * n_sec}, ({len(cells)}, 3)")

# a frustum's quadrilaterals and a disk's triangles have the polygonal surfaces' areas
def area(polys):
    tot = 0.0
    for p in polys:
        p = np.array(p)
        for k in range(1, len(p) - 1):
            tot += 0.5 * np.linalg.norm(np.cross(p[k] - p[0], p[k + 1] - p[0]))
    return tot


n = 64
r0, r1, h = 0.025, 0.075, 0.03
# each quadrilateral is a trapezoid: chords 2 r sin(pi/n), their midpoints at r cos(pi/n)
check("frustum area", area(stl_walls.revolution(r0, r1, 0.0, h, 5, n)),
      n * math.sin(math.pi / n) * (r0 + r1) * math.hypot((r1 - r0) * math.cos(math.pi / n), h), 1e-15)
check("disk area", area(stl_walls.disk(0.025, 0.0, n)), 0.5 * n * 0.025 ** 2 * math.sin(2 * math.pi / n), 1e-15)
check("next prime after 90", dem.next_prime(90), 97, 0)
check("a prime is its own", dem.next_prime(97), 97, 0)
check("2 is prime", dem.next_prime(0), 2, 0)

with tempfile.TemporaryDirectory() as tmp:
    # fix print rows of two chunks: the second chunk's first row (the same step) wins; headers skipped
    a, b = os.path.join(tmp, "flow_001.txt"), os.path.join(tmp, "flow_002.txt")
    open(a, "w").write("# step n m\n0 10 0.5\n100 9 0.4\n")
    open(b, "w").write("# step n m\n100 8 0.3\n200 7 0.2\nnot a row\n")
    t = dem.read_print([a, b], ("step", "n", "m"))
    check("fix print rows", len(t["step"]), 3, 0)
    check("the later chunk's row", t["n"][1], 8.0, 0)
    # snapshots of two dump files: a step in both is the first file's
    def dump(path, steps):
        with open(path, "w") as fh:
            for s, v in steps:
                fh.write(f"ITEM: TIMESTEP\n{s}\nITEM: NUMBER OF ATOMS\n1\nITEM: BOX BOUNDS pp pp pp\n0 1\n0 1\n0 1\n"
                         f"ITEM: ATOMS id x y z\n1 {v} 0 0\n")
    dump(os.path.join(tmp, "cv_001.dump"), [(0, 0.1), (10, 0.2)])
    dump(os.path.join(tmp, "cv_002.dump"), [(10, 0.9), (20, 0.3)])
    snaps = dem.snapshots(os.path.join(tmp, "cv_*.dump"))
    if [s for s, _ in snaps] != [0, 10, 20] or snaps[1][1]["x"][0] != 0.2:
        failures.append(f"snapshots: steps {[s for s, _ in snaps]}, x at 10 = {snaps[1][1]['x'][0]}")
    # the panels draw (Agg) without error
    plt = plots.pyplot()
    fig, ax = plt.subplots()
    plots.errorbars(ax, [1, 2], [dict(w=1.0, w_sd=0.1), dict(w=2.0, w_sd=math.nan)], "w", "W")
    ax.set(xlim=(-0.1, 0.1), ylim=(0, 0.1), aspect="equal")
    plots.grains(fig, ax, np.zeros(3), np.full(3, 0.05), np.full(3, 0.007), ["r", "g", "b"])
    pairs = {f"c_pairs[{k}]": np.array([0.0, 0.0]) for k in range(1, 13)}
    pairs["c_pairs[3]"], pairs["c_pairs[6]"] = np.array([0.01, 0.02]), np.array([0.02, 0.03])
    pairs["c_pairs[10]"] = np.array([1.0, 3.0])
    lc, mean = plots.force_chains(ax, pairs, 0.01)
    check("force chains: mean force", mean, 2.0)
    check("force chains: contacts above the mean", len(lc.get_segments()), 1, 0)
    plots.save(fig, os.path.join(tmp, "p.png"))

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("strain, wall_rings, stl_walls (revolution, disk), dem (snapshots, read_print, primes), plots panels: all passed")
