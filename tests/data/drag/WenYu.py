"""WenYu.py: reference drag of the law WenYu (run by tests/data/make_reference.py).

Gidaspow (1994) form of Wen & Yu (1966): the volumetric coefficient
beta_vol = 3/4 Cd eps (1-eps) rho |u| / d eps^-2.65, divided by the particle
number density (1-eps)/V_p; Cd of Schiller & Naumann at Re = eps rho d |u| / mu.
"""
import math

from SchillerNaumann import cd_note, cd_schiller_naumann

PARAMETERS = []
POINTS = [
    (1e-4, 0.4, 0.02), (2.25e-4, 0.6, 0.5), (2e-3, 0.8, 3.0), (5e-3, 0.95, 10.0), (1e-3, 1.0, 1.0),
    (5e-3, 1.0, 4.0),
]


def wen_yu(d, eps, u, rho, mu):
    """(beta [kg/s], Re): beta_vol, then per particle."""
    re = eps * rho * abs(u) * d / mu
    cd = cd_schiller_naumann(re)
    if eps < 1.0:
        beta_vol = 0.75 * cd * eps * (1.0 - eps) * rho * abs(u) / d * eps**-2.65
        n = (1.0 - eps) / (math.pi * d**3 / 6.0)  # particles per m3
        return beta_vol / n, re
    # eps = 1: no particles per volume; use the force on one sphere instead,
    # F = 1/2 Cd rho A |u| u eps^-1.65 with A = pi d^2/4.
    force = 0.5 * cd * rho * math.pi * d**2 / 4.0 * u * u * eps**-1.65
    return force / u, re


def beta(d, eps, u, rho, mu):
    b, re = wen_yu(d, eps, u, rho, mu)
    return b, re, cd_note(re)
