"""Least-squares fits the studies share (each with the form it fits in its name).

    a1, a2 = phi_of_I(i, phi)              phi = a1 / (1 + a2 I)   (Fullard et al. 2019's solid fraction law)
    alpha, se = through_origin(f, y)       y = alpha f, and alpha's standard error
"""
import math

import numpy as np


def phi_of_I(i, phi, a2_max=50.0):
    """phi = a1 / (1 + a2 I), least squares in phi (not in 1/phi, which loose points at
    large I would dominate): for a given a2 the best a1 is linear, a2 by a golden-section
    search over [0, a2_max]. (NaN, NaN) with fewer than 3 points."""
    if len(i) < 3:
        return math.nan, math.nan
    i, phi = np.asarray(i, float), np.asarray(phi, float)

    def best(a2):
        u = 1 / (1 + a2 * i)
        a1 = float(np.dot(phi, u) / np.dot(u, u))
        return float(np.sum((phi - a1 * u) ** 2)), a1
    lo, hi, g = 0.0, a2_max, (math.sqrt(5) - 1) / 2
    for _ in range(80):
        m1, m2 = hi - g * (hi - lo), lo + g * (hi - lo)
        if best(m1)[0] < best(m2)[0]:
            hi = m2
        else:
            lo = m1
    a2 = 0.5 * (lo + hi)
    return best(a2)[1], a2


def through_origin(f, y):
    """alpha of y = alpha f (least squares) and its standard error; (NaN, NaN) with
    fewer than two points."""
    f, y = np.asarray(f, float), np.asarray(y, float)
    if len(f) < 2:
        return math.nan, math.nan
    alpha = float(np.sum(f * y) / np.sum(f * f))
    res = y - alpha * f
    return alpha, float(math.sqrt(np.sum(res * res) / (len(f) - 1) / np.sum(f * f)))
