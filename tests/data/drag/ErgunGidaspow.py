"""ErgunGidaspow.py: reference drag of the law ErgunGidaspow (run by tests/data/make_reference.py).

Gidaspow (1994): Ergun (1952) in model-A form below switchVoidFraction (the
volumetric coefficient divided by the particle number density), Wen & Yu
(WenYu.py) from it on.
"""
import math

from SchillerNaumann import cd_note
from WenYu import wen_yu

SWITCH = 0.8
PARAMETERS = [("switchVoidFraction", SWITCH)]
POINTS = [
    (1e-4, 0.4, 0.02), (2.25e-4, 0.45, 0.5), (2e-3, 0.55, 3.0), (5e-3, 0.79, 10.0),  # Ergun
    (1e-4, 0.8, 0.05),  # exactly at the switch: Wen-Yu
    (2.25e-4, 0.9, 1.0), (2e-3, 0.95, 2.0), (5e-3, 0.99, 8.0),  # Wen-Yu, both Cd branches
]


def ergun(d, eps, u, rho, mu):
    """Ergun (1952) in Gidaspow's model-A form: beta_vol, then per particle."""
    beta_vol = 150.0 * (1.0 - eps)**2 * mu / (eps * d**2) + 1.75 * (1.0 - eps) * rho * abs(u) / d
    n = (1.0 - eps) / (math.pi * d**3 / 6.0)
    return beta_vol / n


def beta(d, eps, u, rho, mu):
    if eps < SWITCH:
        return ergun(d, eps, u, rho, mu), eps * rho * u * d / mu, "Ergun"
    b, re = wen_yu(d, eps, u, rho, mu)
    return b, re, "Wen-Yu, " + cd_note(re)
