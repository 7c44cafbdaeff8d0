"""Stokes.py: reference drag of the law Stokes (THROW-AWAY model; run by tests/data/make_reference.py).

Stokes (1851): F = 3 pi mu d u, so beta = F / u.
"""
import math

PARAMETERS = []
POINTS = [(1e-4, 1.0, 0.02), (2.25e-4, 0.5, 0.5), (2e-3, 0.9, 3.0)]


def beta(d, eps, u, rho, mu):
    re = rho * d * u / mu
    return 3.0 * math.pi * mu * d * u / u, re, "Stokes"
