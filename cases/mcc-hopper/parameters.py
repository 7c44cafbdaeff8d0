"""The numbers of the MCC hopper (Remmelgas et al. 2019, reference case B; README.md)
for both fidelities: the continuum runs (study.py) and the coarse-grained DEM
(dem.py). SI units."""
import math

# --- the hopper and the powder ----------------------------------------------
R_OUT, R_CYL = 0.0125, 0.0635     # outlet and cylinder radius [m]
D_OUTLET = 0.025                  # outlet diameter [m]
H_CONE, H_CYL = 0.036, 0.127      # cone and cylinder height [m]
TAN_CONE = (R_CYL - R_OUT) / H_CONE
FILL_MASS = 1.0                   # kg
D_PARTICLE = 660e-6               # median diameter of VIVAPUR MCC Spheres 500 [m]
RHO_P = 1500.0                    # particle density [kg/m3]
RHO_BULK = 900.0                  # bulk density [kg/m3]
AIR_RHO, AIR_MU = 1.22, 1.8e-5
G = 9.81
BEVERLOO_C, K_RANGE = 0.58, (1.0, 3.0)   # Beverloo et al. (1961): W = C rho_b sqrt(g) (D - k d)^2.5

# --- continuum runs (study.py, template/) ---------------------------------------
WEDGE_HALF_ANGLE = math.radians(2.5)    # the axisymmetric mesh is a wedge of this half angle
WINDOW = 0.01                     # s, averaging window of mass_flow.csv
TOLERANCE = 0.005                 # mass balance and fill, relative
FREEFALL = 0.0125                 # free-fall region below the orifice [m] (half the diameter)
WALL_FRICTION = 0.3               # Coulomb wall friction: the DEM's particle-wall friction (assumed)
# --rheology-from calibration: the material of calibration.json (cases/rheology-calibration)
# whose mu(I), phi_max and parcel d replace the literature block's: the CG-DEM's s = 5 parcels
CALIBRATION = "mcc-hopper"
ETA_MAX = "1e5"                   # viscosity cap of mu(I) [Pa s] (README: W does not depend on it)
MAX_CO = 0.4                      # maxCo and maxAlphaCo
OUTER_TOLERANCE = 1e-3            # outerTolerance of study.py --outer N > 1 (OuterCorrectors.H)
# Steady mass flow over Beverloo (k = 1) that the runs gave (README: 0.95-1.11
# for N = 10-28 with Coulomb, free-slip and no-slip walls, with and without
# air): outside the band the flow has stopped, burst or the model changed.
BAND = (0.7, 1.3)

# --- the mesh study (study.py --convergence, convergence.py; README "Mesh convergence") ---
MESHES = (10, 14, 20, 28)         # cells across the orifice diameter, ratio sqrt 2; 0.89 mm >= d at 28
# sensitivity runs on the finest mesh: tag -> the options that differ from the study's
SENSITIVITY = {"maxCo0.2": dict(max_co=0.2), "etaMax1e6": dict(eta_max="1e6"),
               "transposeOff": dict(transpose_stress="off"), "freefall25mm": dict(freefall=0.025)}
TARGETS = dict(gci=0.05, sensitivity=0.02, tension=0.01)   # issue 16: GCI, W change, packed p <= 0
# --rheology latzSchmidt: the lactose closure of reference case A on this
# geometry (a solver test): bulk density rho_p (c0 + cMax)/2 = 1060 x 0.5675,
# the middle of the closure's plastic range of c; particle diameter the middle
# of the 200-250 um sieve fraction (Beverloo band, Darcy-Ergun air drag).
LATZ = dict(rho_bulk=601.55, d=225e-6, block="../wedge-silo/continuum/latzSchmidt/rheology",
            material="lactose latzSchmidt closure (case A) in the MCC hopper",
            model="latzSchmidt, lactose closure on the MCC geometry (solver test)", t_floor=1e-12,
            band=(0.3, 3.0))          # latzSchmidt/results: 0.61 no-slip, 2.26 free slip (N = 20)

# --- coarse-grained DEM (dem.py, template-dem/; README "Coarse-grained DEM") -----
NU = 0.3                          # Poisson ratio (typical of polymers / pellets)
RESTITUTION = 0.55                # particle-particle and particle-wall
FRICTION_PP = 0.4                 # sliding friction particle-particle
FRICTION_PW = 0.3                 # sliding friction particle-wall
YOUNGS = 5e6                      # reduced Young's modulus [Pa] (real MCC ~ GPa): time step
PACKING_INSERT = 0.30             # solid fraction of the random sequential addition
SINK_Z = -0.02                    # parcels are deleted below this [m]
BOX_HALF = R_CYL + 0.002          # half width of the DEM box [m]
CFD_DT = 5e-4                     # sampling step of granairFoam (air off: no CFD) [s]
RAYLEIGH_FRACTION = 0.2           # DEM dt / Rayleigh time
DEM_WINDOW = 0.05                 # s, averaging window of the DEM mass_flow.csv
V_CONE = math.pi * H_CONE / 3 * (R_OUT ** 2 + R_OUT * R_CYL + R_CYL ** 2)


def beverloo(k, rho_b=RHO_BULK, d=D_PARTICLE, outlet=D_OUTLET):
    return BEVERLOO_C * rho_b * math.sqrt(G) * (outlet - k * d) ** 2.5


def fill_height(mass, rho_b=RHO_BULK):
    """Height of a fill of `mass` [kg] at bulk density rho_b in the cone, then the cylinder."""
    v = mass / rho_b
    if v > V_CONE:
        return H_CONE + (v - V_CONE) / (math.pi * R_CYL ** 2)
    lo, hi = 0.0, H_CONE
    for _ in range(60):
        h = 0.5 * (lo + hi)
        r = R_OUT + h * TAN_CONE
        lo, hi = (h, hi) if math.pi * h / 3 * (R_OUT ** 2 + R_OUT * r + r ** 2) < v else (lo, h)
    return 0.5 * (lo + hi)

# --dilatancy (cfd-side/continuum/Dilatancy.H): the rate of d(phi)/dt = -k phi gammaDot (phi - phi(I)),
# Pailha & Pouliquen's (2009) k, the Darcy-Ergun air model's default too
DILATANCY_RATE = 4.09
DILATANCY_RELAXATION = 0.2    # the under-relaxation of the volume source (the solver's default; Dilatancy.H: why)
