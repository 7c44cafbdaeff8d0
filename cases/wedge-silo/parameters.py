"""The numbers of the wedge silo (reference case A, README.md): the silo, the
lactose powder, the modelling reductions per size, and the continuum level's
rheology. SI units. Coordinates: x across the silo (centred), y along the
slot (a thin periodic slice of the depth is simulated), z up, z = 0 the
orifice plane (the shutter)."""
import math

WIDTH = 0.045            # shaft width [m]
DEPTH = 0.060            # silo depth, the slot length [m]
SHAFT_HEIGHT = 0.200     # shaft height above the hopper [m]
HALF_ANGLE = 15.0        # hopper half angle from the vertical [deg]
BOX_BELOW = 0.030        # height of the air region below the orifice [m]
SINK_DEPTH = 0.015       # particles are removed this far below the orifice [m]

D_MEAN_PSD, D_SIGMA_PSD = 200e-6, 25e-6   # Gaussian of the sieved lactose [m]; sigma assumed
D_MIN_PSD, D_MAX_PSD = 200e-6, 250e-6     # redrawn until inside [200, 250] um
RHO_P = 1060.0           # particle density [kg/m3]
E_REAL = 2.5e9           # Young's modulus of lactose [Pa]
NU = 0.3                 # Poisson ratio
RESTITUTION = 0.67
FRICTION_PP = 0.95       # particle-particle sliding friction
WALL_FRICTION_ANGLE = 16.0   # aluminium wall friction angle [deg]
WALL_FRICTION = math.tan(math.radians(WALL_FRICTION_ANGLE))   # mu_w of the continuum's Coulomb walls
K_COH_REAL = 1.0e5       # SJKR cohesion energy density at E_REAL [J/m3]
AIR_RHO, AIR_MU = 1.2, 1.8e-5
G = 9.81

PACKING_SETTLED = 0.58   # expected settled solid fraction (only to size the fill)
PACKING_INSERT = 0.33    # random sequential addition target of the loose packing
SETTLE_MIN, SETTLE_MAX = 0.15, 0.6   # settling on the shutter [s]: at least, at most
KERNEL_WIDTHS = 1.6      # Gaussian void-fraction kernel and cells near the orifice: parcel diameters
BEVERLOO_C, K_RANGE = 0.58, (1.0, 3.0)   # Hagen-Beverloo slot band (README)
STEADY_FROM = 0.3        # steady discharge assumed from this time on [s]
# The whole discharge (study.py --whole, issue 21): granairFoam in chunks from
# restart points until the silo is empty or the flow has stopped, at most WHOLE_T_MAX.
WHOLE_T_MAX = 15.0       # [s]; the study-size b = 10 mm silo empties in ~4 s with air
WHOLE_CHUNK = 1.0        # [s] per granairFoam call (rounded up to whole field intervals)
EMPTY_FRACTION = 0.005   # "empty": at most this share of the parcels is left in the DEM
STALL_TIME = 0.25        # "stopped": nothing crossed the orifice for this long [s]
# Fill-level bands of the whole-discharge tables (whole_widths.py) [mm], and the first
# time their rows count from [s] (the 0.1 s windows of the rate and the means are full).
WHOLE_BANDS_MM = [(200, 250), (150, 190), (110, 140), (70, 100), (40, 60), (15, 30), (5, 12)]
WHOLE_BANDS_FROM = 0.1
# Rolling resistance (study.py --rolling MU_R, issue 21; off by default): the parcels
# are smooth spheres, lactose grains are irregular. LIGGGHTS 3.8 (Debian) models
# that need only mu_r: epsd2 (elastic-plastic spring, Iwashita & Oda 1998) and cdt
# (constant torque); epsd needs a damping coefficient too, epsd3 a stiffness factor.
ROLLING_MODELS = ("epsd2", "cdt")

# A size fixes the reductions per orifice width b [mm]: b_over_d, the orifice
# width in mean parcel diameters (sets the coarse-graining factor
# s = b / (b_over_d x mean primary d)), and the settled fill height [m]; for
# all b: the discharge time, Young's modulus, the slice thickness in mean
# parcel diameters, the DEM step as a fraction of the Rayleigh time of the
# smallest parcel, the CFD (coupling) step, the field-output interval [s].
# demo: all six runs in about 10 min on 2 idle cores (README).
SIZES = {
    "demo": dict(t_end=0.5, write_interval=0.25, youngs=2e6, slice_parcels=3.0, rayleigh_fraction=0.2,
                 cfd_dt=5e-4, per_b={5: dict(b_over_d=5.5, fill=0.085), 10: dict(b_over_d=6.0, fill=0.135),
                                     15: dict(b_over_d=6.0, fill=0.190)}),
    "study": dict(t_end=2.0, write_interval=1.0, youngs=5e6, slice_parcels=4.0, rayleigh_fraction=0.2,
                  cfd_dt=5e-4, per_b={5: dict(b_over_d=7.0, fill=0.150), 10: dict(b_over_d=7.0, fill=0.260),
                                      15: dict(b_over_d=7.0, fill=0.250)}),
}

# --- the continuum level (continuum.py) ---------------------------------------
# Settled fills of the DEM demo (reference-demo/summary.txt): b [mm] ->
# (fill height above the orifice [m], bulk density rho_b [kg/m3]).
FILLS = {5: (0.086, 617.66), 10: (0.135, 619.41), 15: (0.191, 617.12)}
# ... of the DEM study (reference-study-b10, -b15 summary.txt; b = 5 mm: reference-study-whole/summary_b5.txt)
FILLS_STUDY = {5: (0.149, 623.0), 10: (0.260, 619.0), 15: (0.253, 612.0)}
# Shear test of the lactose (cases.md, section A): normal, shear stress [kPa].
SHEAR_TEST = [(0.208, 0.11), (0.384, 0.198), (0.718, 0.359), (1.349, 0.667), (2.553, 1.251), (4.845, 2.368)]
# mu(I) parameters not measured for lactose (README, assumptions): mu_2 - mu_s and
# I0 of Jop, Forterre & Pouliquen (2006) for glass beads (tan 32.76 - tan 20.9, 0.279).
JOP_MU_SPAN = math.tan(math.radians(32.76)) - math.tan(math.radians(20.9))
JOP_I0 = 0.279
D_LACTOSE = 225e-6       # particle diameter of the rheology and of the Ergun drag [m]
# Dilatancy phi(I) = phi_max - (phi_max - phi_min) I: phi_max the settled DEM
# solid fraction; the span is not measured for lactose: 0.189 as for MCC
# spheres (Remmelgas et al. 2019; glass beads ~0.2). Assumed.
DILATANCY_SPAN = 0.632 - 0.443
# continuum.py --dilatancy (cfd-side/continuum/Dilatancy.H): the rate k of d(phi)/dt =
# -k phi gammaDot (phi - phi(I)), Pailha & Pouliquen's (2009), and the under-relaxation
# of the volume source: the MCC hopper's values (cases/mcc-hopper/parameters.py)
DILATANCY_RATE = 4.09
DILATANCY_RELAXATION = 0.2


def psd_moments():
    """Number-mean diameter and E[d^3] of the truncated Gaussian PSD (numerical)."""
    n, s1, s3, norm = 2000, 0.0, 0.0, 0.0
    for i in range(n):
        d = D_MIN_PSD + (i + 0.5) * (D_MAX_PSD - D_MIN_PSD) / n
        w = math.exp(-0.5 * ((d - D_MEAN_PSD) / D_SIGMA_PSD) ** 2)
        norm += w
        s1 += w * d
        s3 += w * d ** 3
    return s1 / norm, s3 / norm


def draw_primary_diameter(rng):
    """Primary diameter [m]: Gaussian, redrawn until inside [200, 250] um (as in the study)."""
    while True:
        d = rng.gauss(D_MEAN_PSD, D_SIGMA_PSD)
        if D_MIN_PSD <= d <= D_MAX_PSD:
            return d


def hopper_height(b):
    """Height of the symmetric hopper from the slot b [m] to the 45 mm shaft."""
    return (WIDTH - b) / 2 / math.tan(math.radians(HALF_ANGLE))


def fill_area(b, h):
    """x-z area [m2] of the silo below height h above the orifice."""
    hh = hopper_height(b)
    if h <= hh:
        top = b + 2 * h * math.tan(math.radians(HALF_ANGLE))
        return 0.5 * (b + top) * h
    return 0.5 * (b + WIDTH) * hh + WIDTH * (h - hh)


def fill_level(b, mass_kg, rho_b):
    """The bed height [m] above the orifice that holds mass_kg (numbers or an array, at
    the full depth) at the bulk density rho_b: the fill level of a discharging silo."""
    import numpy as np
    heights = np.linspace(0.0, hopper_height(b) + SHAFT_HEIGHT, 4001)
    areas = np.array([fill_area(b, h) for h in heights])
    return np.interp(np.maximum(mass_kg, 0.0) / (rho_b * DEPTH), areas, heights)


def fit_mu_s():
    """Least-squares line tau = c + mu_s sigma through the shear test: (mu_s, c [kPa]).
    The intercept (cohesion, ~10 Pa) sets the pressure floor c/mu_s of mu(I)."""
    n = len(SHEAR_TEST)
    ms, mt = sum(s for s, _ in SHEAR_TEST) / n, sum(t for _, t in SHEAR_TEST) / n
    slope = sum((s - ms) * (t - mt) for s, t in SHEAR_TEST) / sum((s - ms) ** 2 for s, _ in SHEAR_TEST)
    return slope, mt - slope * ms

# Checks (study.py, continuum.py --check; README "Expected results", "Continuum fidelity")
AIR_CONTINUITY = 1e-6    # air in - out vs pore-volume growth of the silo, relative (measured 2.5e-9)
PORE_VS_POWDER = 0.10    # pore-volume growth vs powder volume discharged, relative (measured -2.5 %, test run)
# CG fields at the orifice (cg.py; README "CG fields at the orifice")
CG_VOLUME_QUADRATURE = 1e-3   # CG solid volume in the window vs the parcels' kernel-weighted volume, relative
CG_VS_AIR_BULK = 0.03         # bulk mean CG solid fraction vs 1 - air void fraction, relative
CG_BULK_MIN_SOLID = 0.45      # "bulk": cells of the air mesh denser than this (not the dilated outflow)
CONTINUUM_W_OVER_DEM = (1.2, 2.2)   # committed runs 1.40-1.87 (Coulomb walls, free fall; README)
# --rheology-from calibration (continuum.py): the material of calibration.json
# (cases/rheology-calibration, the study-size parcels) and issue 16's target against the DEM
CALIBRATION = "wedge-silo"
CALIBRATED_W_OVER_DEM = (0.85, 1.15)
CONTINUUM_DPDZ_OVER_DEM = (0.5, 1.6)
