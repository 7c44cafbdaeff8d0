"""DiFelice.py: reference drag of the law DiFelice (run by tests/data/make_reference.py).

Di Felice (1994): F = 1/2 Cd rho (pi d^2/4) eps^2 u^2 eps^-chi, Dallavalle's
Cd = (0.63 + 4.8/sqrt(Re))^2 at Re = rho d eps u / mu and
chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2).
"""
import math

PARAMETERS = []
POINTS = [
    (1e-4, 0.4, 0.02), (2.25e-4, 0.6, 0.5), (2e-3, 0.8, 3.0), (5e-3, 0.95, 10.0), (1e-3, 1.0, 1.0),
]


def beta(d, eps, u, rho, mu):
    re = rho * d * eps * u / mu
    cd = (0.63 + 4.8 / math.sqrt(re))**2
    chi = 3.7 - 0.65 * math.exp(-((1.5 - math.log10(re))**2) / 2.0)
    force = 0.5 * cd * rho * math.pi * d**2 / 4.0 * eps**2 * u * u * eps**-chi
    return force / u, re, "chi = %.6f" % chi
