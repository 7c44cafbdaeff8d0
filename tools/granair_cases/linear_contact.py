"""The linear spring-dashpot contact (LIGGGHTS `hooke/stiffness`, MFIX's DEM): its
duration and the damping that gives a restitution coefficient (cases/two-slot-silo,
cases/orifice-arch). Why here: the
damped oscillator m_eff x'' + c x' + k x = 0 is the same in every case that uses the
model, and a case's time step rests on its contact time.

    t_c = contact_time(m_eff, k, e)     pi / omega_d = pi sqrt(m_eff / k) sqrt(1 + (ln e / pi)^2)
    zeta = damping_ratio(e)             c / (2 sqrt(m_eff k)) = -ln e / sqrt(pi^2 + ln^2 e)
    gamman = gamma_per_mass(m_eff, k, e)   LIGGGHTS' gamman [1/s]: c / m_eff = 2 zeta sqrt(k / m_eff)
    law = linear_dashpot(k_n, e, m)     {gamman_pp, t_contact_pp, gamman_pw, t_contact_pw}: pairs
                                        (m_eff = m / 2) and walls (m_eff = m) at once
"""
import math


def contact_time(m_eff, k, e):
    """Duration of a linear spring-dashpot contact of effective mass m_eff, stiffness k
    and restitution e [s] (the half period of the damped oscillation)."""
    ln = math.log(e)
    return math.pi * math.sqrt(m_eff / k) * math.sqrt(1 + (ln / math.pi) ** 2)


def damping_ratio(e):
    """zeta = c / (2 sqrt(m_eff k)) of a linear dashpot giving restitution e (the
    velocity ratio exp(-zeta omega_0 t_c) at the end of the contact)."""
    ln = -math.log(e)
    return ln / math.sqrt(math.pi ** 2 + ln ** 2)


def gamma_per_mass(m_eff, k, e):
    """LIGGGHTS hooke/stiffness `gamman` [1/s] (damping force = gamman m_eff v_n, with
    absolute_damping off) that gives restitution e for a contact of effective mass m_eff."""
    return 2 * damping_ratio(e) * math.sqrt(k / m_eff)


def linear_dashpot(k_n, e, m):
    """gamman [1/s] and the contact time [s] of particle pairs (suffix _pp, m_eff = m/2) and
    particle-wall contacts (_pw, m_eff = m) of mass m with stiffness k_n and restitution e
    (cases/orifice-arch's contact law, which needs both kinds at once)."""
    out = {}
    for name, m_eff in (("pp", m / 2), ("pw", m)):
        out["gamman_" + name] = gamma_per_mass(m_eff, k_n, e)
        out["t_contact_" + name] = contact_time(m_eff, k_n, e)
    return out
