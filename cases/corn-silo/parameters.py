"""The numbers of the corn silo (Rivera, Avila & Avila 2023, reference case D;
README.md). SI units. Where the reference is silent the choice and its source
are stated here and in the README."""
import math

# --- corn: sieve analysis of the reference (aperture mm: mass % retained) ------
# 12.7: 0, 9.5: 2.32, 7.94: 37.27, 4.75: 60.25, 2.36: 0.16. The diameter of each
# fraction is not stated; each gets the geometric mean of the two apertures
# that bound it (the middle of the class on a logarithmic size axis).
SIEVES_MM = (12.7, 9.5, 7.94, 4.75, 2.36)
MASS_FRACTIONS = (0.0232, 0.3727, 0.6025, 0.0016)      # retained on 9.5, 7.94, 4.75, 2.36 mm
DIAMETERS = tuple(math.sqrt(a * b) * 1e-3 for a, b in zip(SIEVES_MM[:-1], SIEVES_MM[1:]))  # 10.98, 8.69, 6.14, 3.35 mm
# Kernel density: not in the paper. 1260 kg/m3 = the 5-year average true density of
# US corn, 1.263 g/cm3 (US Grains Council, Corn Harvest Quality Report 2017/18;
# range 1.16-1.34), inside the 1.232-1.315 g/cm3 of Karababa & Coskuner (2007),
# Int. J. Food Prop. 10, 549.
RHO_P = 1260.0
# Materials and contacts of the reference: corn E = 298 MPa, nu = 0.3; concrete
# E = 50 GPa, nu = 0.2; corn-corn e = 0.205, mu = 0.51 (tan 27 deg, the measured
# repose angle); corn-wall e = 0.70, mu = 0.52; no rolling friction.
YOUNGS_REF, NU = 298e6, 0.3
YOUNGS_WALL_REF, NU_WALL = 50e9, 0.2
E_PP, E_PW = 0.205, 0.70
MU_PP, MU_PW = 0.51, 0.52
REPOSE_DEG = 27.0
# Linear spring-dashpot with a tangential spring and Coulomb limit (the reference's
# model): LIGGGHTS `hooke tangential history`, whose normal stiffness is Hertz's at
# the overlap of an impact at CHARACTERISTIC_VELOCITY (the speed of grains leaving
# the outlet and landing on the fill, ~ 1 m/s).
CHARACTERISTIC_VELOCITY = 1.0

# --- the reductions for 2 cores (README "Reductions") -----------------------------
# Softer corn: E 298 MPa -> 5 MPa (x 1/59.6), the wall by the same factor, so the
# corn-wall / corn-corn stiffness ratio is the reference's. The time step is a
# fixed fraction of the Rayleigh time of the smallest grain, as in the reference
# (1e-6 s, which it states as 0.1-0.3 of it): 0.2.
YOUNGS = 5e6
SOFTENING = YOUNGS / YOUNGS_REF
RAYLEIGH_FRACTION = 0.2
G = 9.81

# --- the silo (dimensions only in a figure of the reference: chosen here) ----------
# A cylinder of D = 150 mm on a conical hopper to a D_o = 50 mm outlet: the
# reference's 25 000 grains then stand 0.38-0.40 m high (H/D ~ 2.6, a slender silo
# in EN 1991-4's sense, where Janssen's shaft pressures apply), D/d_50 ~ 22 (the
# wall is many grains away from the axis), D_o/d_50 ~ 7 (Beverloo's range, no
# arching of 7 mm spheres).
D_SILO = 0.150
D_OUTLET = 0.050
ANGLES_DEG = (5, 10, 15, 20, 27, 35)   # hopper wall from the horizontal (5 ~ flat bottom)
# Control volume of the strain invariants: the cylinder over the outlet, its radius
# and its height the outlet's.
CV_RADIUS, CV_HEIGHT = D_OUTLET / 2, D_OUTLET
CG_WIDTH, CG_SPACING = 0.005, 0.005   # m: granairCG's Gaussian kernel (std 4.8 mm) and grid over the control volume
CV_MARGIN = 0.025          # the grains dumped around it: 10 ms of travel, the CG kernel's cutoff (3 x 5 mm) and more
STRESS_TOP = 0.50          # the shaft's stress-tracked mesh ends here; above it a plain wall to the box top
RING_HEIGHT = 0.010        # wall mesh rows in the shaft [m] (~1.4 d_50)
HOPPER_ROWS = 5            # rows along the hopper wall
SECTORS = 24               # elements around the circumference
SINK_Z = -0.06             # grains are deleted (counted) when they cross this plane
INSERT_FRACTION = 0.27     # solid fraction of the random insertion regions (LIGGGHTS insert/pack)
LAYER_HEIGHT = 0.15        # the fill goes in layers this tall (README "Fill") ...
LAYER_TIME = 0.25          # ... this far apart in time [s] ...
BULK_FRACTION = 0.58       # ... each above the rest level of the grains below it at this solid fraction
LAYER_GAP = 0.02           # ... plus this gap [m]
SETTLE_RMS = 0.005         # the fill is settled below this rms speed [m/s] ...
SETTLE_MIN, SETTLE_MAX = 0.3, 2.0   # ... after at least / at most these times [s]

# --- outputs ---------------------------------------------------------------------------
FLOW_EVERY = 0.01          # s, discharged mass, counts (post/flow_*.txt)
CV_EVERY = 0.01            # s, grains over the outlet (post/cv_*.dump): the strain interval
WALL_EVERY = 0.05          # s, wall loads (post/walls_*.vtk)
FULL_EVERY = 0.5           # s, every grain (post/full_*.dump: the layers picture)
CHUNK = 0.25               # s of discharge per LIGGGHTS process (a restart after each)
STEADY_FROM = 0.5          # s, start of the steady window of the discharge
LAYER = 0.03               # m, thickness of the coloured layers of the flow-pattern picture
STAGNANT_MASS_FLOW = 0.005 # mass flow if less of the fill than this has moved less than d/2 by the end
BEVERLOO_C, K_RANGE = 0.58, (1.0, 3.0)

# --- sizes of the study ------------------------------------------------------------------
SIZES = {
    # grains, discharge [s], angles, runs per angle. "study" is what 2 shared cores
    # finish in about an hour (README "Reductions"); "full" keeps the reference's
    # 25 000 grains and a longer discharge (~1.5-2 CPU-h per run, not run here).
    "study": dict(grains=8000, discharge=0.75, angles=ANGLES_DEG, seeds=3),
    "full": dict(grains=25000, discharge=3.0, angles=ANGLES_DEG, seeds=3),
    "demo": dict(grains=8000, discharge=1.0, angles=(10, 35), seeds=1),
    "test": dict(grains=8000, discharge=0.2, angles=(27,), seeds=1),
}
SEEDS = ((86028121, 122949823), (104395301, 141650939), (160481183, 179424673))   # (insertion, size) seeds per run: primes > 10000

# --- Janssen (closed form of the shaft pressure, docs/fidelity-levels.md) ----------------
# K between Rankine's active (1 - sin phi)/(1 + sin phi) and EN 1991-4's
# 1.1 (1 - sin phi) (Jaky's at-rest value x 1.1), phi = the repose angle (27 deg);
# mu_w = the corn-wall friction coefficient (fully mobilised, as Janssen assumes).
PHI = math.radians(REPOSE_DEG)
K_JANSSEN = ((1 - math.sin(PHI)) / (1 + math.sin(PHI)), 1.1 * (1 - math.sin(PHI)))


def janssen_depth(grains):
    """Depth below the free surface of the compared shaft wall pressure [m]: in the
    shaft's fill below its top rings, above the hopper of every angle (8000 grains
    stand ~0.14 m high, 25 000 ~0.41 m)."""
    return 0.25 if grains >= 25000 else 0.08


def number_fractions():
    """Number fraction of each sieve class (mass fraction / grain mass)."""
    w = [m / d ** 3 for m, d in zip(MASS_FRACTIONS, DIAMETERS)]
    return [x / sum(w) for x in w]


def mean_grain_volume():
    """Number-weighted mean grain volume [m3]."""
    return sum(f * math.pi / 6 * d ** 3 for f, d in zip(number_fractions(), DIAMETERS))


def d_mass_mean():
    """Mass-weighted mean diameter [m] (the d of Beverloo's k d)."""
    return sum(m * d for m, d in zip(MASS_FRACTIONS, DIAMETERS))


def hopper_height(angle_deg):
    """Height of the hopper wall from the outlet (z = 0) to the shaft [m]."""
    return (D_SILO - D_OUTLET) / 2 * math.tan(math.radians(angle_deg))


def beverloo(k, rho_b, d=None):
    """Beverloo et al. (1961) mass flow through the outlet [kg/s]."""
    from granair_cases import closed_forms
    return closed_forms.beverloo_circular(D_OUTLET, d_mass_mean() if d is None else d, rho_b, k, BEVERLOO_C, G)
