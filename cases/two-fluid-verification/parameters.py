"""The numbers of the two-fluid verification (README.md): four 1-D columns of
twoPhaseEulerFoam with granair's muI frictional stress and granair drag
against closed forms. SI units. The template (template/) prints them through
the placeholders named as here."""
import math
import os

from granair_cases import calibration, closed_forms as cf

G = 9.81
RHO_F, MU = 1.2, 1.8e-5        # air [kg/m3], [Pa s] (incompressible: rhoConst)
AIR_EOS = "rhoConst"
W = 0.01                       # width of the one cell across [m] (sides empty)
ALPHA_DELTA_MIN = 0.005        # bound of the contact law's divergence at alphaMax
SHEAR_PRESSURE = "off"
DRAG_SCALE = 1.0               # granair drag's scale: the law's drag (a dry reference would take less)

# The mu(I) block of the solid phase (coupling/rheology/MuI.hpp), the form the
# continuum solver reads; d and rhoP are each test's own.
RHEOLOGY = """            rheology
            {{
                type        muI;
                muS         {mu_s:.6g};
                mu2         {mu_2:.6g};
                I0          {i0:.6g};
                d           {d:.8g};
                rhoP        {rho_p:.8g};
                phiMax      {phi_max:.6g};
                phiMin      {phi_min:.6g};
                etaMax      {eta_max:.6g};
            }}"""

# --- 1 and 2: packed bed under upflow (Ergun) and the onset of fluidisation
# glass beads 0.5 mm, as cases/fluidised-bed (the DEM-CFD check of the same).
# Loose packing (alphaMinFriction, where the contacts unload): 0.626, the
# packing the same beads defluidise into in cases/fluidised-bed's DEM-CFD
# (eps_mf = 0.374, README there): a calibration from DEM, as the project's
# continuum inputs are. As U -> U_mf the contact pressure vanishes and the bed
# loosens to this packing, so the model's U_mf is Ergun's at eps = 0.374
# (0.171 m/s, -9.4 % on Wen & Yu). The a-priori 0.60 used before (eps 0.40,
# "glass beads at minimum fluidisation") gave U_mf 0.219 m/s, +16.4 %
# (measured; README). alphaMax 0.64 (random close packing of smooth spheres:
# the DEM's poured and defluidised beds, 0.622-0.628, lie between the two).
# The bed starts at 0.627, the mean of the loaded column (0.626 at the
# surface, ~0.628 at the base under its weight): a denser start springs back
# and throws its top layer up.
BED = dict(D=0.5e-3, RHO_P=2500.0, H=0.10, NZ=50, BED_H=0.05, ALPHA0=0.627,
           ALPHA_MAX=0.64, ALPHA_MIN_FRICTION=0.626, FR=0.05, FR_ETA=2, FR_P=5,
           DRAG_LAW="ErgunGidaspow", DT=4e-4, MAX_CO=0.2, N_OUTER=3, FACE_MOMENTUM="no")
UMF_DEM = 0.1670                      # [m/s] cases/fluidised-bed (DEM-CFD, same beads), README there
# etaMax 100 Pa s (the silo cases use 1e5): in a 1-D column the packing can only
# settle by uniaxial creep at ~p/etaMax, so with 1e5 the bed was still
# compacting at 2 mm/s after 0.1 s and the air it displaced added 3 % to the
# Ergun pressure drop; the rheology is not what these columns test.
BED_FRICTION = dict(mu_s=0.38, mu_2=0.64, i0=0.279, phi_max=0.64, phi_min=0.626, eta_max=100.0)
ERGUN_FRACTIONS = (0.4, 0.8)          # U_s / U_mf,WY of the Ergun runs
ERGUN_T_END = 0.3                     # [s]: the bed settles in ~0.1 s, then steady
# The onset of fluidisation is where the contacts unload: the contact
# pressure at the base (pf.particles, bottom cell) falls to zero. Two more
# runs near it bracket it: 0.9 (still packed, measured pf_base 19 Pa) and 1.0
# (contacts unloaded); U_mf is where pf_base, linear between the last two
# loaded runs, reaches zero.
ONSET_FRACTIONS = (0.9, 1.0)
PF_UNLOADED = 1e-3                    # pf_base below this fraction of the weight: unloaded
TOL_ERGUN = 0.02                      # the 2 %
# --- skewed: the packed bed again on a mesh of skewed cells (two columns whose
# shared faces zigzag: each vertex of the middle line is moved across by
# SKEW_OFFSET x dz, alternately left and right, so the faces lean by
# atan(2 x 0.3) = 31 degrees, as much as the wedge silo's fitted hopper cells;
# its sides are symmetry planes). Checks granairTwoPhaseEulerFoam, the solver
# source built here with its reconstruct written out (docs/two-fluid-model.md):
# Ergun within TOL_ERGUN and the orthogonal column's dp within TOL_SKEW_SAME.
# Debian's binary runs the same case for the report (not checked).
SKEW_FRACTION = 0.8                   # U_s / U_mf,WY (an Ergun run of the bed test)
SKEW_OFFSET = 0.3                     # the middle line's zigzag, in cell heights
TOL_SKEW_SAME = 0.005                 # against the same run on the orthogonal column
FLUID_FRACTIONS = (1.5, 2.0)         # U_s / U_mf,WY of the fluidised runs
FLUID_T_END = 0.6
FLUID_WINDOW = 0.2                    # [s] the fluidised dp is the time mean from here to the end
TOL_UMF = 0.15                        # the 15 % against Wen & Yu (1966)
TOL_PLATEAU = 0.02                    # fluidised dp vs the buoyant weight per area

# --- 3: hindered settling (Richardson & Zaki 1954), Re_t < 0.2 so n = 4.65
SETTLE = dict(D=30e-6, RHO_P=2500.0, H=0.10, NZ=100, BED_H=0.08,
              ALPHA_MAX=0.62, ALPHA_MIN_FRICTION=0.55, FR=0.05, FR_ETA=2, FR_P=5,
              DRAG_LAW="ErgunGidaspow", DT=2e-4, MAX_CO=0.2, N_OUTER=3, FACE_MOMENTUM="no",
              T_END=0.4, U_S=0.0)
SETTLE_ALPHAS = (0.05, 0.15)
SETTLE_WINDOW = (0.1, 0.4)            # [s] interface tracked (after the start-up, before the sediment)
TOL_RZ = 0.05                         # the 5 %

# --- 4: consolidation of a loose column (Terzaghi 1943), linear contact law
# p_c = Fr (alpha - alphaMinFriction): constant stiffness, so the excess air
# pressure obeys Terzaghi's equation with c_v = eps^3 Fr d^2/(150 mu alpha)
# (Stokes-Ergun drag); the friction is made negligible (mu ~ 1e-4) because in
# a 1-D compaction the mu(I) deviator adds ~mu p to the vertical stress,
# a rate-independent part Terzaghi's linear theory does not have.
CONSOL = dict(D=30e-6, RHO_P=2500.0, H=0.06, NZ=120, BED_H=0.05, ALPHA0=0.55,
              ALPHA_MAX=0.64, ALPHA_MIN_FRICTION=0.55, FR=4e5, FR_ETA=1, FR_P=0,
              DRAG_LAW="ErgunGidaspow", DT=2e-5, MAX_CO=0.2, N_OUTER=3, FACE_MOMENTUM="no",
              U_S=0.0)
CONSOL_FRICTION = dict(mu_s=1e-4, mu_2=2e-4, i0=0.279, phi_max=0.64, phi_min=0.55, eta_max=1e5)
CONSOL_TV = (0.05, 0.1, 0.2, 0.4, 0.8)   # time factors T_v = c_v t / H^2 compared
TOL_TERZAGHI = 0.05                      # of the initial excess pressure at the base


# --- 5: a powder column at rest with the Latz-Schmidt frictional stress
# (frictionalStressModel latzSchmidt): the lactose of reference case A (its
# closure and density, the block granairContinuumFoam reads) settles from a
# uniform 0.566 under its own weight in air; at rest the packing in each cell
# must carry the buoyant weight above it through the closure's yield pressure
# p_y(c) = T0 (c - c0)/(1 - c/cMax) (gc.closed_forms.latz_yield_pressure).
# alphaMinFriction 0.555 (below c0: the kinetic part of the closure acts from
# there), the packing cap 5e-4 below cMax (as the wedge silo's runs), alphaMax
# of the kinetic theory's radial function 0.60 (above the closure's cMax).
PACKING = dict(D=225e-6, RHO_P=1060.0, H=0.06, NZ=60, BED_H=0.05, ALPHA0=0.566,
               ALPHA_MAX=0.60, ALPHA_MIN_FRICTION=0.555, ALPHA_DELTA_MIN=5e-4, FRICTION_MODEL="latzSchmidt",
               DRAG_LAW="ErgunGidaspow", DT=1e-4, MAX_CO=0.2, N_OUTER=3, FACE_MOMENTUM="no",
               U_S=0.0, T_END=2.0, T_WRITE=0.25)
LATZ_BLOCK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "wedge-silo", "continuum",
                          "latzSchmidt", "rheology")
PACKING_DEEP = 0.1       # cells compared: overburden >= this share of the base's (not the surface's transition)
TOL_PACKING = 0.05       # p_y at the cell's packing vs its buoyant overburden
TOL_REST = 0.01          # the muI contact pressure at rest vs its buoyant overburden (a continuous law)
REST_T_END = 2.0         # [s]: the column at rest (its creep under etaMax settled)


def latz_block():
    """(the Latz-Schmidt rheology block's text, {c0, cMax, T0})."""
    return calibration.read_block(LATZ_BLOCK, ("c0", "cMax", "T0"))


def rheology(p, friction):
    return RHEOLOGY.format(d=p["D"], rho_p=p["RHO_P"], **friction)


def wen_yu_umf(p=BED):
    return cf.wen_yu_umf(p["D"], p["RHO_P"], RHO_F, MU, G)


def terminal_velocity(d, rho_p, law_re=None):
    """Stokes terminal velocity with Schiller-Naumann's correction (the single-sphere
    limit of the WenYu branch), solved by fixed point [m/s]."""
    u = (rho_p - RHO_F) * G * d * d / (18 * MU)
    for _ in range(100):
        re = RHO_F * u * d / MU
        u = (rho_p - RHO_F) * G * d * d / (18 * MU * (1 + 0.15 * re ** 0.687))
    return u


def richardson_zaki_n(re_t):
    """Richardson & Zaki (1954) exponent for d/D -> 0."""
    if re_t < 0.2:
        return 4.65
    if re_t < 1:
        return 4.35 * re_t ** -0.03
    if re_t < 500:
        return 4.45 * re_t ** -0.1
    return 2.39


def consolidation_cv(p=CONSOL):
    a = p["ALPHA0"]
    eps = 1 - a
    return eps ** 3 * p["FR"] * p["D"] ** 2 / (150 * MU * a)


def terzaghi(zeta_over_h, tv, terms=300):
    """Excess pore pressure at depth zeta over the initial excess at the base, for an
    initial excess growing linearly with depth (self-weight), drained top and
    impermeable base (Terzaghi 1943): p(zeta, 0) = p0 zeta/H,
    p = sum A_m sin(M zeta/H) exp(-M^2 T_v), M = (2m+1) pi/2,
    A_m = (2/H) int_0^H p0 (zeta/H) sin(M zeta/H) d zeta = 2 p0 (-1)^m / M^2."""
    s = 0.0
    for m in range(terms):
        M = (2 * m + 1) * math.pi / 2
        s += 2 * (-1) ** m / M ** 2 * math.sin(M * zeta_over_h) * math.exp(-M * M * tv)
    return s
