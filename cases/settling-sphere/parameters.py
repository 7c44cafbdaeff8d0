"""The numbers of the settling-sphere validation (README.md), and the drag
laws' terminal velocities written here from the papers, independently of
coupling/drag/ (the C++ laws under test). SI units."""
import math

from granair_cases.numerics import bisect

G = 9.81                       # [m/s2], as in dem/in.liggghts and couplingProperties
TOLERANCE = 0.02               # plateau velocity vs the law's v_t
FLATNESS = 0.1 * TOLERANCE     # the plateau may change by at most this over its window
PLATEAU = 0.2                  # the last 20 % of each run is the plateau window
FREE_FALL_TOLERANCE = 1e-6     # air off: |v - g t| / (g t)
FREE_FALL_END = 0.02           # air-off run of the "air" set-up: falls 2 mm in 0.02 s
LAWS = ["SchillerNaumann", "DiFelice"]
N_WRITES = 20                  # U is written this often: the air velocity in the sphere's cell

# The two regimes. Cells are much larger than the sphere (void fraction ~ 1,
# small back-reaction); the run covers >= 10 linearised relaxation times and
# the coupling interval is <= 1/20 of one (both checked by study.py).
SETUPS = {
    # ~30 um glass (lactose-like size) in air: Stokes regime, Re_t ~ 0.13
    "air": dict(label="30 µm glass in air", d=30e-6, rho_p=2500.0, rho_f=1.2, mu=1.8e-5,
                box=(25e-3, 25e-3, 30e-3), cells=(5, 5, 6), start=(12.5e-3, 12.5e-3, 22.5e-3),
                dt_dem=1e-5, n_couple=10, end=0.08, skin=1e-3),
    # 0.8 mm glass in water: Re_t ~ 95 (Schiller-Naumann), ~ 88 (Di Felice)
    "water": dict(label="0.8 mm glass in water", d=0.8e-3, rho_p=2500.0, rho_f=1000.0, mu=1e-3,
                  box=(50e-3, 50e-3, 80e-3), cells=(5, 5, 8), start=(25e-3, 25e-3, 65e-3),
                  dt_dem=2.5e-5, n_couple=10, end=0.2, skin=2e-3),
}


# beta [kg/s]: drag on one sphere = beta * slip velocity.
def beta_schiller_naumann(d, eps, slip, rho, mu):
    """Schiller & Naumann (1933): Cd = 24/Re (1 + 0.15 Re^0.687), Re < 1000
    (Cd = 0.44 above). Single sphere: eps is not used."""
    re_p = rho * d * slip / mu
    cd_re = 24.0 * (1.0 + 0.15 * re_p ** 0.687) if re_p < 1000 else 0.44 * re_p
    # F = 1/2 Cd rho (pi d^2/4) |u| u, and Cd rho d |u| = Cd Re mu
    return math.pi / 8.0 * mu * d * cd_re


def beta_di_felice(d, eps, slip, rho, mu):
    """Di Felice (1994): Dallavalle Cd = (0.63 + 4.8/sqrt(Re))^2 with Re =
    rho d eps |u| / mu, times eps^(2 - chi), chi = 3.7 - 0.65 exp(-(1.5 -
    log10 Re)^2 / 2):  beta = (pi/8) Cd rho d^2 eps^(2-chi) |u|."""
    re_p = rho * d * eps * slip / mu
    chi = 3.7 - 0.65 * math.exp(-0.5 * (1.5 - math.log10(re_p)) ** 2) if re_p > 0 else 3.7
    sqrt_cd_re = 0.63 * math.sqrt(re_p) + 4.8      # sqrt(Cd Re)
    return math.pi / 8.0 * mu * d * eps ** (1.0 - chi) * sqrt_cd_re ** 2


BETA = {"SchillerNaumann": beta_schiller_naumann, "DiFelice": beta_di_felice}


def net_weight(s):
    """(rho_p - rho_f) V_p g [N]: gravity less buoyancy."""
    return (s["rho_p"] - s["rho_f"]) * math.pi / 6.0 * s["d"] ** 3 * G


def terminal_velocity(law, s, eps):
    """Solve (rho_p - rho_f) V_p g = beta(v) v by bisection (beta(v) v grows with v)."""
    beta = BETA[law]

    def excess(v):
        return beta(s["d"], eps, v, s["rho_f"], s["mu"]) * v - net_weight(s)
    hi = 1e-3
    while excess(hi) < 0:
        hi *= 2
    return bisect(excess, 0.0, hi, rtol=1e-15)


def relaxation_time(law, s, eps, v_t):
    """Linearised approach time m / (d(beta v)/dv) at v_t [s] (= rho_p d^2/(18 mu) for Stokes)."""
    beta = BETA[law]
    h = 1e-6 * v_t
    slope = (beta(s["d"], eps, v_t + h, s["rho_f"], s["mu"]) * (v_t + h)
             - beta(s["d"], eps, v_t - h, s["rho_f"], s["mu"]) * (v_t - h)) / (2 * h)
    return s["rho_p"] * math.pi / 6.0 * s["d"] ** 3 / slope
