#!/usr/bin/env python3
"""The case layer's outlet, fits, cg_grids and stl_walls modules (tools/granair_cases)
on inputs whose answer is known: window rates of evenly spaced records, the bulk
density of a cubic lattice, Beverloo's C and k recovered from rates made with
them, phi = a1/(1 + a2 I) and y = alpha f recovered from exact data, the density
integral of a uniform RZ and XZ grid (the RZ end term removed), the CSV round trip,
and flat walls that tile their area."""
import math
import os
import sys
import tempfile

import numpy as np

from granair_cases import cg_grids, closed_forms, fits, outlet, stl_walls

failures = []


def check(name, got, want, rel=1e-9):
    if not (abs(got - want) <= rel * max(abs(want), 1e-300)):
        failures.append(f"{name}: got {got!r}, expected {want!r} (rel {rel})")


# window rates: one record of mass 2 every 1 ms from t = 0 (1000 per s): 2 kg/s in
# every whole 200 ms window from 0.1 s; 0.1..0.55 s holds two whole windows
t = np.arange(0.0, 0.6, 1e-3) + 0.5e-3
rates = outlet.window_rates(t, np.full(t.size, 2.0), 0.1, 0.55, 0.2)
check("window count", rates.size, 2)
for k, r in enumerate(rates):
    check(f"window {k} rate", r, 2000.0, 1e-12)
mean, sd = outlet.mean_sd(np.array([1.0, 3.0]))
check("mean", mean, 2.0)
check("sd", sd, math.sqrt(2.0))

# bulk density: a simple cubic lattice of spacing a, mass m each: rho_b = m / a^3
a, m = 1e-3, 5e-7
zs = np.repeat((np.arange(40) + 0.5) * a, 100)      # 40 layers of 10 x 10 over 1 cm^2
rho, top = outlet.bulk_density(zs, np.full(zs.size, m), (10 * a) ** 2, a, k_top=100)
check("lattice top", top, 39.5 * a)
# between 2a and 37.5a: layers 2.5a .. 37.5a excluded at the ends -> layers 2.5..36.5 (35 layers) over 35.5 a
check("lattice bulk density", rho, 35 * 100 * m / ((10 * a) ** 2 * 35.5 * a))

# the same lattice on a floor at 5a, the free surface a radius over the top centres, and a fill
# too low for a bulk density: NaN with min_height, an error without
rho_f, top_f = outlet.bulk_density(zs + 5 * a, np.full(zs.size, m), (10 * a) ** 2, a, k_top=100, floor=5 * a,
                                   radius=0.5 * a)
check("lattice on a floor: top", top_f, 45.0 * a)
check("lattice on a floor: bulk density", rho_f, 36 * 100 * m / ((10 * a) ** 2 * 36.0 * a))
low = outlet.bulk_density(zs[:300], np.full(300, m), (10 * a) ** 2, a, k_top=100, min_height=4 * a)[0]
if not math.isnan(low):
    failures.append(f"bulk density of a 3-layer fill with min_height 4 d: {low}, expected NaN")

# flow pattern: a silo R = 10 d whose wall zone stays put while the core descends by 2 d and
# one core particle leaves (to the sink at -5 d)
d = 1e-3
xs = np.array([9.5, -9.5, 0.5, -0.5, 0.0, 5.0]) * d
zs_p = np.array([1.5, 2.5, 1.5, 2.5, 2.0, 12.0]) * d
fill = dict(id=np.arange(1.0, 7.0), x=xs, y=np.zeros(6), z=zs_p, mass=np.array([1.0, 1.0, 1.0, 1.0, 2.0, 4.0]))
final = {k: v[[0, 1, 2, 3, 5]].copy() for k, v in fill.items()}
final["z"][2:4] -= 2 * d
final["z"][4] -= 3 * d
ratio, stagnant, h_dead = outlet.flow_pattern(fill, final, d, 10 * d, 0.0, 12 * d, -5 * d)
check("wall over core descent", ratio, 0.0)
check("stagnant mass fraction", stagnant, 2.0 / 10.0)
check("highest stagnant particle at the wall", h_dead, 2.5 * d)

# Beverloo's C, k recovered from rates of the closed form itself (circular orifice)
d, rho_b, C, k = 2e-3, 900.0, 0.6, 1.5
D = [10e-3, 14e-3, 20e-3]
W = [closed_forms.beverloo_circular(x, d, rho_b, k, C) for x in D]
c_fit, k_fit = outlet.beverloo_fit(D, W, rho_b, d)
check("Beverloo C", c_fit, C, 1e-9)
check("Beverloo k", k_fit, k, 1e-9)
c_fit, k_fit = outlet.beverloo_fit(D[:1], W[:1], rho_b, d)
if not (math.isnan(c_fit) and math.isnan(k_fit)):
    failures.append("Beverloo fit from one outlet: expected NaN, NaN")

# phi(I) and through-origin fits on exact data
i = np.linspace(0.05, 0.6, 40)
a1, a2 = fits.phi_of_I(i, 0.58 / (1 + 0.4 * i))
check("phi(I) a1", a1, 0.58, 1e-6)
check("phi(I) a2", a2, 0.4, 1e-6)
alpha, se = fits.through_origin([0.2, 0.5, 1.0], [0.1, 0.25, 0.5])
check("alpha", alpha, 0.5)
check("alpha se", se + 1.0, 1.0)

# density integral: uniform rho0 on an RZ grid r = (i + 1/2) dr, i < n: the midpoint
# rule of 2 pi r is exact for the linear integrand, so the end term is all the difference
rho0, dr, dz, n, nz = 1500.0, 1e-3, 2e-3, 20, 5
r = (np.arange(n) + 0.5) * dr
f = {"axes": ("r", "z"), "r": r, "z": np.arange(nz) * dz, "density": np.full((n, nz), rho0)}
grid, raw = cg_grids.mass(f)
exact = rho0 * math.pi * (n * dr) ** 2 * nz * dz
check("RZ midpoint sum", raw, exact, 1e-12)
check("RZ end term", raw - grid, dr * dr / 24 * 2 * math.pi * rho0 * nz * dz, 1e-9)
fx = {"axes": ("x", "z"), "x": np.arange(n) * dr, "z": np.arange(nz) * dz, "density": np.full((n, nz), rho0)}
check("XZ integral", cg_grids.mass(fx, depth=0.015)[0], rho0 * n * dr * nz * dz * 0.015, 1e-12)
with tempfile.TemporaryDirectory() as tmp:
    p = cg_grids.write(os.path.join(tmp, "g.csv"), {"r": r, "z": f["z"], "density": f["density"] * (1 + r[:, None])}, "r")
    back = cg_grids.read(p, "r")
    check("CSV round trip", float(back["density"][7, 3]), rho0 * (1 + r[7]), 1e-5)


# flat walls: the pieces cover the area they are for
def area(quads):
    return sum(abs((q[1][0] - q[0][0]) * (q[3][1] - q[0][1])) for q in quads)


q = stl_walls.strips(0.0, [(-0.05, -0.014), (0.014, 0.05)], 0.0, 0.015, 0.01)
check("strips area", area(q), 2 * 0.036 * 0.015, 1e-12)
if max(abs(x[1][0] - x[0][0]) for x in q) > 0.01 + 1e-12:
    failures.append("strips: a piece longer than asked")
check("tiles area", area(stl_walls.tiles(-0.1, -1.0, 1.0, -0.5, 0.5, 7, 3)), 2.0, 1e-12)
ring = stl_walls.annulus(0.0, 0.1, 0.5, 96)
inner = [x[0] for x in ring[:96]]
poly = 0.5 * abs(sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(inner, inner[1:] + inner[:1])))
check("annulus hole area", poly, math.pi * 0.1 ** 2, 1e-12)

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("outlet, fits, cg_grids, stl_walls: all checks passed")
