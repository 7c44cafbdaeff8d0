"""The linear spring-dashpot contact of LIGGGHTS `gran model hooke/stiffness` from a
stiffness and a coefficient of restitution: the damping that gives that restitution
and the contact time, per kind of contact (a pair, m_eff = m / 2; a wall, m_eff = m).

    law = linear_dashpot(k_n, e, m)   {gamman_pp, t_contact_pp, gamman_pw, t_contact_pw}

The damped oscillator m_eff x'' + c x' + k x = 0 leaves contact at t_c = pi / omega_d with
velocity ratio e = exp(-beta t_c), beta = c / (2 m_eff), so beta = omega_0 |ln e| /
sqrt(pi^2 + ln^2 e), omega_0 = sqrt(k / m_eff), omega_d = sqrt(omega_0^2 - beta^2);
LIGGGHTS' gamman (absolute_damping off) is c / m_eff = 2 beta [1/s].
"""
import math


def linear_dashpot(k_n, e, m):
    """gamman [1/s] and the contact time [s] of particle pairs (suffix _pp, m_eff = m/2) and
    particle-wall contacts (_pw, m_eff = m) of mass m with stiffness k_n and restitution e."""
    ln_e = abs(math.log(e))
    out = {}
    for name, m_eff in (("pp", m / 2), ("pw", m)):
        w0 = math.sqrt(k_n / m_eff)
        beta = w0 * ln_e / math.sqrt(math.pi ** 2 + ln_e ** 2)
        out["gamman_" + name] = 2 * beta
        out["t_contact_" + name] = math.pi / math.sqrt(w0 ** 2 - beta ** 2)
    return out
