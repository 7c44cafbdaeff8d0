"""exact.py: closed-form steady solutions of the mu(I) rheology that the
continuum solver (granairContinuumFoam) must reproduce.

Every function evaluates the rheology exactly as coupling/rheology/MuI.hpp
documents it (Jop form or the Barker & Gray 2017 partial regularisation,
clamped to [etaMin, etaMax]), written out again here so the check does not
share code with what it checks (only the root finder, gc.numerics.bisect).

References:
    GDR MiDi (2004). On dense granular flows. Eur. Phys. J. E 14, 341-365.
    Jop, P., Forterre, Y., Pouliquen, O. (2006). A constitutive law for dense
    granular flows. Nature 441, 727-730 (glass beads: mu_s = tan 20.9 deg,
    mu_2 = tan 32.76 deg, I0 = 0.279, d = 0.53 mm, rho_p = 2450 kg/m3).
    Barker, T., Gray, J.M.N.T. (2017). J. Fluid Mech. 828, 5-32.
"""
import math

from granair_cases.numerics import bisect

G = 9.81


def mu_jop(I, q):
    """Jop et al. (2006): mu_s + (mu_2 - mu_s)/(I0/I + 1)."""
    return q["muS"] + (q["mu2"] - q["muS"]) * I / (q["I0"] + I)


def barker_gray_i1(q):
    """Lower root of Barker et al.'s (2015) C(I) for the Jop form (bisection)."""
    def c(I):
        mu = mu_jop(I, q)
        nu = I * (q["mu2"] - q["muS"]) * q["I0"] / (q["I0"] + I) ** 2 / mu
        return 4 * nu * nu - 4 * nu + mu * mu * (1 - nu / 2) ** 2
    tz = math.tan((math.atan(q["muS"]) + math.atan(q["mu2"])) / 2)
    return bisect(c, 1e-14, (tz - q["muS"]) * q["I0"] / (q["mu2"] - tz), n=300, increasing=False)


def friction(I, q):
    """mu(I) of the form q['regularisation'] names."""
    if q.get("regularisation", "none") == "none":
        return mu_jop(I, q)
    i1 = barker_gray_i1(q)
    a, m = q.get("alphaReg", 1.9), q.get("muInf", 0.05)
    if I < i1:
        A = i1 * math.exp(a * (q["I0"] + i1) ** 2 / (q["muS"] * q["I0"] + q["mu2"] * i1 + m * i1 ** 2) ** 2)
        return math.sqrt(a / math.log(A / I)) if I > 0 else 0.0
    return (q["muS"] * q["I0"] + q["mu2"] * I + m * I * I) / (q["I0"] + I)


def eta_min(q):
    return q.get("etaMin", q["rhoP"] * q["d"] * math.sqrt(G * q["d"]))


def viscosity(p, gd, q):
    """eta(p, gammaDot): stress-free (etaMin) for p <= 0, else clamp(mu p/gd, etaMin, etaMax)."""
    if p <= 0:
        return eta_min(q)
    gd = max(gd, q.get("gammaDotMin", 1e-6))
    I = gd * q["d"] / math.sqrt(p / q["rhoP"])
    return min(max(friction(I, q) * p / gd, eta_min(q)), q.get("etaMax", 1e5))


def inertial_number_at(mu_target, q):
    """I with mu(I) = mu_target (mu is increasing in I)."""
    return bisect(lambda I: friction(I, q) - mu_target, 1e-14, 1e6, n=300, geometric=True)


# ------------------------------------------------------------ inclined plane
def bagnold(y, h, theta_deg, phi, q):
    """Steady uniform flow of depth h down a plane at theta (GDR MiDi 2004,
    Jop et al. 2006): mu(I) = tan(theta) everywhere, so I is uniform,
    p = phi rho_p g cos(theta) (h - y) and gammaDot = (I/d) sqrt(p/rho_p):
        u(y) = (2/3) (I/d) sqrt(phi g cos(theta)) (h^1.5 - (h - y)^1.5)."""
    th = math.radians(theta_deg)
    I = inertial_number_at(math.tan(th), q)
    k = (2.0 / 3.0) * I / q["d"] * math.sqrt(phi * G * math.cos(th))
    return k * (h ** 1.5 - max(h - y, 0.0) ** 1.5), I


def bagnold_flux(h, theta_deg, phi, q):
    """Depth-integrated velocity q = (3/5) h u_surface [m2/s]."""
    us, _ = bagnold(h, h, theta_deg, phi, q)
    return 0.6 * h * us


def dilatant_layer(h0, phi0, theta_deg, q, phi_max, phi_min):
    """The steady layer with the solid fraction fed back into the volume: a layer
    laid down h0 deep at the packing phi0 dilates until phi = phi(I) of the Bagnold
    I (uniform with depth, so the steady div U = 0 needs phi uniform too), with
    phi(I) = phi_max - (phi_max - phi_min) I clamped to [phi_min, phi_max]
    (coupling/rheology/MuI.hpp). The grains' volume per area h0 phi0 is kept, so
    the depth is h = h0 phi0 / phi(I); the velocity is bagnold(y, h, theta, phi).
    Returns (phi, h, I)."""
    I = inertial_number_at(math.tan(math.radians(theta_deg)), q)
    phi = min(max(phi_max - (phi_max - phi_min) * I, phi_min), phi_max)
    return phi, h0 * phi0 / phi, I


# ------------------------------------------------- plane shear, Coulomb wall
def couette_coulomb(y, H, V, P, mu_w, q):
    """Plane shear of a layer of height H under the pressure P (no gravity):
    the top wall moves at V (no-slip), the bottom wall has Coulomb friction
    mu_w. The shear stress tau is uniform. If the stress of the no-slip
    profile, tau0 = eta(P, V/H) V/H, is at most mu_w P the layer sticks:
    u = V y/H. Otherwise it slides with tau = mu_w P: the shear rate gd
    solves eta(P, gd) gd = mu_w P (mu(I) = mu_w if that is between the
    limits, else the viscosity floor or cap sets it) and
        u(y) = V - gd (H - y),  slip velocity V - gd H.
    Returns (u(y), regime, gd)."""
    gd0 = V / H
    tau0 = viscosity(P, gd0, q) * gd0
    if tau0 <= mu_w * P:
        return V * y / H, "stick", gd0
    gd = bisect(lambda g: viscosity(P, g, q) * g - mu_w * P, 1e-12, gd0, n=300, geometric=True)
    return V - gd * (H - y), "slide", gd
