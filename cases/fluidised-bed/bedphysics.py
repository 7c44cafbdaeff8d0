"""Fluidised-bed case: the beads, the air, the column and the closed forms the
checker compares with. The DEM scripts (template/dem/) and the mesh
(template/system/blockMeshDict) hold the same numbers."""
import math

D = 0.5e-3                 # bead diameter [m]
RHO_P = 2500.0             # bead density (glass) [kg/m3]
RHO_F, MU = 1.2, 1.8e-5    # air density [kg/m3], viscosity [Pa s] (constant/transportProperties)
G = 9.81                   # [m/s2]
AREA = 0.0045 * 0.0045     # column cross-section [m2] (periodic 4.5 x 4.5 mm)
Z_LOW, Z_HIGH = 0.003, 0.0135   # monitor planes `low`, `high` inside the packed bed [m]


def particle_volume(d=D):
    return math.pi * d ** 3 / 6.0


def buoyant_weight_per_area(n_particles):
    """Bed weight less the air's buoyancy per area [Pa]: m g (1 - rho_f/rho_p)/A."""
    m = n_particles * RHO_P * particle_volume()
    return m * G * (1.0 - RHO_F / RHO_P) / AREA


def ergun_dp(u_s, eps, height):
    """Ergun (1952) pressure drop [Pa] of a bed of spheres of height H [m] and
    void fraction eps at superficial velocity U_s [m/s]:
        dp/H = 150 mu (1-eps)^2 U_s / (eps^3 d^2) + 1.75 rho (1-eps) U_s^2 / (eps^3 d)
    Ergun, S. (1952) Fluid flow through packed columns. Chem. Eng. Prog. 48(2):89-94."""
    return height * (150.0 * MU * (1 - eps) ** 2 * u_s / (eps ** 3 * D ** 2)
                     + 1.75 * RHO_F * (1 - eps) * u_s ** 2 / (eps ** 3 * D))


def archimedes():
    """Ar = rho_f (rho_p - rho_f) g d^3 / mu^2."""
    return RHO_F * (RHO_P - RHO_F) * G * D ** 3 / MU ** 2


def wen_yu_umf():
    """Minimum fluidisation velocity [m/s] of Wen & Yu (1966):
        Re_mf = sqrt(33.7^2 + 0.0408 Ar) - 33.7,  U_mf = Re_mf mu / (rho_f d).
    Wen, C.Y., Yu, Y.H. (1966) A generalized method for predicting the minimum
    fluidization velocity. AIChE J. 12(3):610-612; also Chem. Eng. Prog. Symp.
    Ser. 62(62):100-111."""
    re_mf = math.sqrt(33.7 ** 2 + 0.0408 * archimedes()) - 33.7
    return re_mf * MU / (RHO_F * D)
