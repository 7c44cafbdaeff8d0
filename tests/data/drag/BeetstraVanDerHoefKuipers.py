"""BeetstraVanDerHoefKuipers.py: reference drag of the law BeetstraVanDerHoefKuipers
(run by tests/data/make_reference.py).

Beetstra, van der Hoef & Kuipers (2007), eq. 16, as printed:
F = F_d / (3 pi mu d U), U = eps u superficial, Re = rho d U / mu.
"""
import math

PARAMETERS = []
POINTS = [
    (1e-4, 0.4, 0.02), (2.25e-4, 0.5, 0.5), (2e-3, 0.6, 3.0), (5e-3, 0.7, 4.0), (1e-3, 0.9, 1.0),
    (1e-3, 1.0, 1.0),
]


def beta(d, eps, u, rho, mu):
    phi = 1.0 - eps
    big_u = eps * u
    re = rho * d * big_u / mu
    f = (10.0 * phi / (1.0 - phi)**2 + (1.0 - phi)**2 * (1.0 + 1.5 * math.sqrt(phi))
         + 0.413 * re / (24.0 * (1.0 - phi)**2)
         * (1.0 / (1.0 - phi) + 3.0 * phi * (1.0 - phi) + 8.4 * re**-0.343)
         / (1.0 + 10.0**(3.0 * phi) * re**(-(1.0 + 4.0 * phi) / 2.0)))
    drag = 3.0 * math.pi * mu * d * big_u * f
    return drag / u, re, "F = %.6f" % f
