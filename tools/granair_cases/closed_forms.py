"""closed_forms.py: the closed-form estimates (discharge, wall pressure) every fidelity level is
compared with (used by tools/compare.py and the case studies,
so the numbers in a case's summary and in the comparison table are the same).

All SI: lengths m, densities kg/m3, viscosity Pa s, mass flow kg/s, z up.

- Beverloo et al. (1961), Chem. Eng. Sci. 15, 260, circular orifice D:
      W = C rho_b sqrt(g) (D - k d)^(5/2)
- Hagen-Beverloo for a slot of width b and length L (Nedderman 1992,
  "Statics and kinematics of granular materials", ch. 10):
      W = C rho_b sqrt(g) L (b - k d)^(3/2)
  C ~ 0.58, k = 1..3 (the empty annulus): the band between k = 3 and k = 1.
- Crewdson, Ormond & Nedderman (1977), Powder Technol. 16, 197: an air
  pressure gradient dp/dz at the orifice (z up; negative = suction below the
  bed) acts as extra weight: W = W0 sqrt(1 + (dp/dz)/(rho_b g)).
  Needs dp/dz from a run: it is a check of a run, not a prediction.
- Carleton (1972), Powder Technol. 6, 91, as quoted by Nedderman (1992):
  the mean orifice velocity V0 of a free-flowing powder against still air,
      4 V0^2 sin(theta) / B + 15 rho_f^(1/3) mu^(2/3) V0^(4/3) / (rho_p d^(5/3)) = g,
  theta the hopper half angle from the vertical, B the orifice diameter
  (slot: its width). The first term alone is the dry free-fall-arch flow; the
  second is particle drag at intermediate Reynolds number (C_D ~ Re^(-2/3)),
  which is where the exponents come from. Used here only as the ratio
  V0(air)/V0(dry) applied to the Beverloo band, the closed-form air-impeded
  estimate. It is the drag of still air on particles leaving at V0; the
  suction that the dilating bed draws above the orifice (the pressure
  gradient the DEM-CFD and continuum runs resolve) is not in it.
- Ergun (1952), Chem. Eng. Prog. 48(2), 89: the pressure gradient of a packed
  bed of spheres, void fraction eps, superficial velocity U_s,
      -dp/dz = 150 mu U_s (1-eps)^2 / (eps^3 d^2) + 1.75 rho U_s^2 (1-eps) / (eps^3 d).
- Wen & Yu (1966), AIChE J. 12(3), 610: minimum fluidisation,
      Re_mf = sqrt(33.7^2 + 0.0408 Ar) - 33.7, Ar = rho_f (rho_p - rho_f) g d^3 / mu^2.
- Janssen (1895), Z. Ver. Dtsch. Ing. 39, 1045 (Nedderman 1992, ch. 3): the
  stresses at depth h below the free surface of a bulk solid at rest in a
  vertical cylinder of diameter D, wall friction mu_w, ratio K of horizontal to
  vertical stress (the differential slice with the wall friction fully mobilised),
      p_v = rho_b g D / (4 mu_w K) (1 - exp(-4 mu_w K h / D)),   p_w = K p_v,
  the wall shear stress mu_w p_w; p_w tends to rho_b g D / (4 mu_w) far below the surface.
"""
import math

import numpy as np

from . import numerics

G = 9.81


def beverloo_circular(D, d, rho_b, k, C=0.58, g=G):
    """Beverloo mass flow through a circular orifice of diameter D [kg/s]."""
    return C * rho_b * math.sqrt(g) * max(D - k * d, 0.0) ** 2.5


def beverloo_slot(b, d, rho_b, length, k, C=0.58, g=G):
    """Hagen-Beverloo mass flow through a slot b wide and `length` long [kg/s]."""
    return C * rho_b * math.sqrt(g) * length * max(b - k * d, 0.0) ** 1.5


def beverloo_band(orifice, B, d, rho_b, k_range=(1.0, 3.0), C=0.58, length=None):
    """(low, high) Beverloo band: low at the largest k, high at the smallest."""
    if orifice == "slot":
        if length is None:
            raise ValueError("a slot orifice needs its length")
        f = lambda k: beverloo_slot(B, d, rho_b, length, k, C)          # noqa: E731
    elif orifice == "circular":
        f = lambda k: beverloo_circular(B, d, rho_b, k, C)              # noqa: E731
    else:
        raise ValueError(f"orifice must be 'slot' or 'circular', not {orifice!r}")
    return f(max(k_range)), f(min(k_range))


def crewdson(w0, dpdz, rho_b, g=G):
    """Air-impeded rate W0 sqrt(1 + (dp/dz)/(rho_b g)); 0 when the suction
    exceeds the bed's weight."""
    return w0 * math.sqrt(max(1.0 + dpdz / (rho_b * g), 0.0))


def carleton_velocity(B, theta_deg, d, rho_p, rho_f=0.0, mu=0.0, g=G):
    """V0 [m/s] solving Carleton's balance (dry when rho_f or mu is 0)."""
    a = 4.0 * math.sin(math.radians(theta_deg)) / B
    c = 15.0 * rho_f ** (1.0 / 3.0) * mu ** (2.0 / 3.0) / (rho_p * d ** (5.0 / 3.0))
    # the left side grows with V0; the dry root is sqrt(g / a)
    return numerics.bisect(lambda v: a * v * v + c * v ** (4.0 / 3.0) - g, 0.0, math.sqrt(g / a))


def carleton_ratio(B, theta_deg, d, rho_p, rho_f, mu, g=G):
    """W(with air)/W(dry) = V0(air)/V0(dry) of Carleton's balance (same bulk density)."""
    return carleton_velocity(B, theta_deg, d, rho_p, rho_f, mu, g) / \
        carleton_velocity(B, theta_deg, d, rho_p, 0.0, 0.0, g)


def ergun_gradient(u_s, eps, d, rho, mu):
    """Ergun (1952) pressure drop per length [Pa/m] of a packed bed at superficial velocity u_s."""
    return (150 * mu * u_s * (1 - eps) ** 2 / (eps ** 3 * d ** 2)
            + 1.75 * rho * u_s ** 2 * (1 - eps) / (eps ** 3 * d))


def archimedes(d, rho_p, rho_f, mu, g=G):
    """Ar = rho_f (rho_p - rho_f) g d^3 / mu^2."""
    return rho_f * (rho_p - rho_f) * g * d ** 3 / mu ** 2


def wen_yu_umf(d, rho_p, rho_f, mu, g=G):
    """Minimum fluidisation velocity [m/s] of Wen & Yu (1966)."""
    re_mf = math.sqrt(33.7 ** 2 + 0.0408 * archimedes(d, rho_p, rho_f, mu, g)) - 33.7
    return re_mf * mu / (rho_f * d)


def janssen(depth, D, rho_b, mu_w, K, g=G):
    """Janssen's (vertical stress, wall pressure) [Pa] at `depth` [m] below the free
    surface of a cylinder of diameter D; depth may be a numpy array."""
    z0 = D / (4.0 * mu_w * K)
    p_v = rho_b * g * z0 * (1.0 - np.exp(-np.asarray(depth, dtype=float) / z0))
    return p_v, K * p_v


def latz_yield_pressure(c, c0, c_max, t0):
    """The Latz-Schmidt closure's yield pressure per particle density at rest
    (T -> 0, coupling/rheology/LatzSchmidt.hpp): p_y = T0 (c - c0)/(1 - c/cMax)
    for c0 < c < cMax, 0 at or below c0 [m2/s2]."""
    if not c < c_max:
        raise ValueError(f"latz_yield_pressure: c = {c} at or above cMax = {c_max}")
    return t0 * (c - c0) / (1 - c / c_max) if c > c0 else 0.0


def latz_yield_packing(q, c0, c_max, t0):
    """Its inverse: the packing c0 <= c < cMax at which p_y = q >= 0 [m2/s2];
    p_y (1 - c/cMax) = T0 (c - c0) is linear in c: c = (q + T0 c0)/(T0 + q/cMax)."""
    return (q + t0 * c0) / (t0 + q / c_max) if q > 0 else c0
