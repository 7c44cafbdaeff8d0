#!/usr/bin/env python3
"""Roache's grid convergence index (tools/granair_cases/gci.py) on sequences whose
answer is known: a manufactured f = f0 + c h^p recovers p, the extrapolated
value f0 and GCI = 1.25 |e21/f1|/(r^p - 1); Celik et al.'s (2008) worked
example; and oscillatory / diverging sequences get no GCI."""
import math
import sys

from granair_cases import gci

failures = []


def check(name, got, want, rel=1e-9):
    if not (abs(got - want) <= rel * max(abs(want), 1e-300)):
        failures.append(f"{name}: got {got!r}, expected {want!r} (rel {rel})")


for p in (1.0, 2.0, 2.5):
    for h in [(1 / 28, 1 / 20, 1 / 14), (1.0, 1.5, 2.25)]:   # non-constant and constant ratio
        f = tuple(0.15 + 0.02 * x ** p for x in h)
        g = gci.gci(f, h)
        check(f"manufactured p={p} order", g["order"], p, 1e-9)
        check(f"manufactured p={p} extrapolated", g["extrapolated"], 0.15, 1e-9)
        rp = (h[1] / h[0]) ** p
        check(f"manufactured p={p} GCI", g["gci_fine"], 1.25 * abs((f[1] - f[0]) / f[0]) / (rp - 1), 1e-9)
        if g["convergence"] != "monotonic":
            failures.append(f"manufactured p={p}: convergence {g['convergence']}")

# Celik et al. (2008), J. Fluids Eng. 130, 078001, Table 1, first column:
# N 18000/8000/4500 cells (2-D, h = N^-1/2: r21 1.5, r32 1.333), phi 6.063,
# 5.972, 5.863 -> p 1.53, phi_ext 6.1685, GCI_fine 2.2 %.
h = tuple(n ** -0.5 for n in (18000, 8000, 4500))
g = gci.gci((6.063, 5.972, 5.863), h)
check("Celik order", g["order"], 1.53, 0.01)
check("Celik extrapolated", g["extrapolated"], 6.1685, 1e-4)
check("Celik GCI", g["gci_fine"], 0.022, 0.03)

for f, kind in [((1.0, 1.1, 1.05), "oscillatory"), ((1.0, 1.1, 1.15), "diverging")]:
    g = gci.gci(f, (1.0, 1.4, 2.0))
    if g["convergence"] != kind or not math.isnan(g["gci_fine"]):
        failures.append(f"{f}: expected {kind} and no GCI, got {g['convergence']} {g['gci_fine']}")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("test_gci: all checks passed")
