"""SchillerNaumann.py: reference drag of the law SchillerNaumann (run by tests/data/make_reference.py).

Schiller & Naumann (1933): single-sphere drag, no crowding correction,
F = 1/2 Cd rho (pi d^2/4) u^2, Cd from Re = rho d u / mu (0.44 from Re = 1000).
"""
import math

PARAMETERS = []  # (key, value) pairs of the drag dictionary besides `type`
POINTS = [  # (d [m], eps [-], slip [m/s])
    (1e-4, 1.0, 0.02), (2.25e-4, 0.5, 0.5), (2e-3, 1.0, 3.0), (5e-3, 1.0, 10.0), (1e-3, 0.7, 1.0),
]


def cd_schiller_naumann(re):
    """Schiller & Naumann (1933); 0.44 plateau for Re >= 1000."""
    return 24.0 / re * (1.0 + 0.15 * re**0.687) if re < 1000.0 else 0.44


def cd_note(re):
    return "Cd " + ("24/Re(1+0.15Re^0.687)" if re < 1000 else "0.44")


def beta(d, eps, u, rho, mu):
    """(beta [kg/s], Re, note) for one particle."""
    re = rho * d * u / mu
    force = 0.5 * cd_schiller_naumann(re) * rho * math.pi * d**2 / 4.0 * u * u
    return force / u, re, cd_note(re)
