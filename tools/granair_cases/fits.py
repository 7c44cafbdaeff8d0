"""Least-squares fits the studies share (each with the form it fits in its name).

    a1, a2 = phi_of_I(i, phi)              phi = a1 / (1 + a2 I)   (Fullard et al. 2019's solid fraction law)
    alpha, se = through_origin(f, y)       y = alpha f, and alpha's standard error
    mean, se = mean_se(x)                  the mean of a correlated series and its standard error
    fit = beverloo_size(d, w, w_se, D, at) W^(1/n) = b0 + b1 d over grain (parcel) sizes d, W at d = at
                                           (n = 2.5 a circular orifice, 1.5 a slot)
"""
import math

import numpy as np

from . import numerics


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
    a2 = numerics.golden(lambda a: best(a)[0], 0.0, a2_max)
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


def mean_se(x):
    """Mean of a series of window means and its standard error, sd / sqrt(n) inflated by
    sqrt((1 + r1) / (1 - r1)) for the lag-1 autocorrelation r1 (AR(1); r1 < 0 taken as 0,
    so the error is never shrunk). (mean, NaN) with fewer than three values."""
    x = np.asarray(x, float)
    if x.size < 3:
        return (float(x.mean()) if x.size else math.nan), math.nan
    r = x - x.mean()
    r1 = min(max(float(np.dot(r[1:], r[:-1]) / np.dot(r, r)), 0.0), 0.9) if np.dot(r, r) > 0 else 0.0
    return float(x.mean()), float(x.std(ddof=1) / math.sqrt(x.size) * math.sqrt((1 + r1) / (1 - r1)))


def beverloo_size(d, w, w_se, outlet, at, exponent=2.5):
    """Beverloo's size term over runs at one orifice and several grain (parcel) sizes d.

    W = C rho_b sqrt(g) (D - k d)^n at fixed D, C and rho_b (n = `exponent`: 2.5 for a
    circular orifice of diameter D, Beverloo et al. 1961; 1.5 for a slot of width D,
    Hagen-Beverloo) makes y = W^(1/n) linear in d: y = b0 + b1 d with b0 = a D, b1 = -a k,
    so k = -b1 D / b0 whatever C and rho_b are.
    Weighted least squares with sigma_y = (1/n) W^(1/n - 1) sigma_W (w_se: the standard errors of
    the W). Returns a dict: b0, b1, k, k_se, w_at (W extrapolated to d = at), w_at_se_stat
    (from the weights alone), w_at_se (scaled by the Birge ratio sqrt(chi2/dof) when it
    exceeds 1, i.e. when the points scatter about the line more than their errors allow),
    chi2, dof, birge (NaN with two points), residuals (in units of each point's sigma).
    Needs at least two sizes and positive errors."""
    d, w, w_se = (np.asarray(v, float) for v in (d, w, w_se))
    if d.size < 2 or not (d.size == w.size == w_se.size) or np.any(w_se <= 0) or np.any(w <= 0):
        raise ValueError(f"beverloo_size: need >= 2 sizes with W > 0 and errors > 0, got d {d}, W {w}, se {w_se}")
    if not exponent > 0:
        raise ValueError(f"beverloo_size: exponent {exponent}, expected > 0 (2.5 circular, 1.5 slot)")
    n = float(exponent)
    y, sy = w ** (1 / n), w ** (1 / n - 1) * w_se / n
    a = np.column_stack([np.ones_like(d), d]) / sy[:, None]
    cov = np.linalg.inv(a.T @ a)
    b = cov @ (a.T @ (y / sy))
    res = (y - b[0] - b[1] * d) / sy
    dof = d.size - 2
    chi2 = float(res @ res)
    birge = math.sqrt(chi2 / dof) if dof > 0 else math.nan
    scale = max(1.0, birge) if dof > 0 else 1.0

    def spread(grad, c):
        return math.sqrt(float(grad @ c @ grad))
    y_at = float(b[0] + b[1] * at)
    w_at = max(y_at, 0.0) ** n
    se_y = spread(np.array([1.0, at]), cov)
    k = float(-b[1] * outlet / b[0])
    k_grad = np.array([b[1] * outlet / b[0] ** 2, -outlet / b[0]])
    dw = n * max(y_at, 0.0) ** (n - 1) * se_y        # dW/dy sigma_y at d = at
    return dict(b0=float(b[0]), b1=float(b[1]), k=k, k_se=spread(k_grad, cov) * scale, w_at=w_at,
                w_at_se_stat=dw, w_at_se=dw * scale, chi2=chi2, dof=dof, birge=birge,
                residuals=[float(v) for v in res], exponent=n)
