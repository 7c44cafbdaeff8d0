"""The numbers of the two-slot silo (reference case C, Fullard et al., Proc. R.
Soc. A 2019; README.md): the silo, the particles, the contact model of the
paper's MFIX DEM, the sweep and the reductions per size. SI units.
Coordinates: x across the silo (centred on the axis of symmetry), y through
the depth (front wall y = 0, back wall y = DEPTH), z up, z = 0 the floor with
the openings (the outlet plane)."""
import math

# --- the silo (paper) -----------------------------------------------------------
D0 = 0.014               # width of each slot opening [m]
DEPTH = 0.015            # silo depth between the front and back walls [m]
PAPER_WIDTH, PAPER_HEIGHT = 0.200, 0.350   # the experiment's silo [m] (reduced here: SIZES)
L_SWEEP_MM = (0, 1, 2, 4, 8, 16, 32)       # separation of the two openings [mm]; 0 = one 28 mm slot
SINGLE = "single"        # the one 14 mm opening (reference lines)

# --- particles (not given by the paper's DEM: chosen, README "Parameters") -------
D_MEAN = 2.15e-3         # Sauter mean of the mustard seed (paper) [m]
D_SIZES = (2.05e-3, 2.15e-3, 2.25e-3)      # three sizes, equal numbers: +-4.7 %, so 7 d deep does not crystallise
RHO_P = 1202.0           # particle density [kg/m3] (paper)
RESTITUTION = 0.6        # normal coefficient of restitution (paper)
K_N = 1.0e4              # normal spring [N/m] (paper: 1e4, unit not printed; N/m the likely reading)
K_T = 1.0e4              # tangential spring [N/m] (paper: k_t = k_n)
ETA_T_FACTOR = 0.5       # tangential damping / normal damping: MFIX's default DES_ETAT_FAC (not in the paper)
FRICTION = {             # (particle-particle, particle-wall) sliding friction (paper)
    "low": (0.2, 0.2),
    "high": (0.53, 0.4),
}
G = 9.81

# --- time step: a fraction of the contact time of the lightest pair (linear spring) --
DT_FRACTION = 0.1        # dt = t_c / 10 (MFIX's default is t_c / 50; README says what this costs in accuracy)

# --- fill, feed, sink ------------------------------------------------------------
PHI_SETTLED = 0.60       # expected settled solid fraction (only to size the fill; measured in the runs)
FILL_PHI_INSERT = 0.30   # random sequential addition target of the loose packing (LIGGGHTS' insert/pack
                         # of 2e4 particles at once took minutes: quadratic)
FEED_PHI = 0.30          # feed slab at the top kept at this solid fraction (the experiment's feed hopper)
FEED_HEIGHT = 0.015      # feed slab thickness [m], its bottom at the fill height
FEED_EVERY = 0.01        # the feed slab is topped up every 10 ms [s]
SINK_Z = -0.020          # particles are removed at this plane below the openings [m]
BOX_TOP_MARGIN = 0.010   # the DEM box above the feed slab [m]

# --- outputs ---------------------------------------------------------------------
WINDOW = 0.200           # flow-rate windows [s] (paper)
SERIES_EVERY = 0.005     # thermo-style series interval [s]
CG_SNAPSHOTS, CG_SPACING_T = 20, 0.005     # 20 snapshots 5 ms apart (paper), the last 95 ms of each run
CG_WIDTH_OVER_D = 1.0    # Gaussian w = d, cutoff 3 w (paper)
CG_CUTOFF = 3.0
CG_GRID = 1.0e-3         # CG grid spacing [m] (~ d / 2)
R1_HEIGHT = 0.050        # R1: the whole width x depth x 0..5 cm above the floor (paper)
R2_HALF_WIDTH, R2_HEIGHT = 0.00725, 0.014  # R2: 14.5 x 14 mm above each opening (paper)
I_FIT_MIN = 0.05         # phi(I) fit over R1 for I > 0.05 (paper)

# --- closed forms ----------------------------------------------------------------
BEVERLOO_C, K_RANGE = 0.58, (1.0, 3.0)     # Hagen-Beverloo slot band (closed_forms)

# --- sizes: the silo and run lengths that fit the CPU budget (README "Sizes") ----
# width, fill height (bed surface and feed slab bottom), settling time of the
# fill, discharge time before the CG chunk (which adds 95 ms), the start of
# the steady windows, restart chunk length, default geometries.
SIZES = {
    "test": dict(width=0.100, height=0.040, settle=0.25, t_discharge=0.25, steady_from=0.10, chunk=0.125, cg=True,
                 geometries=[32], friction=["low"]),
    "demo": dict(width=0.100, height=0.050, settle=0.30, t_discharge=0.25, steady_from=0.10, chunk=0.25, cg=True,
                 geometries=[SINGLE, 0, 8], friction=["low"]),       # one set: under 10 min on 2 cores
    "study": dict(width=0.100, height=0.060, settle=0.30, t_discharge=0.42, steady_from=0.10, chunk=0.21, cg=True,
                  geometries=[SINGLE] + list(L_SWEEP_MM), friction=["low", "high"]),
}

# --- checks (post.py) ---
# The Hagen-Beverloo band (C = 0.58, k = 1..3) is for wide silos; the 15 mm
# deep silo (7 d) loses flow to its front and back walls, which the per-unit-
# depth form does not know (README "Results").
HB_WIDEN = 2.0
HB_WHY = ("Hagen-Beverloo is per unit length of a long slot; here the slot is 7 d long between two walls, "
          "which slow the flow near them: factor 2 either way")
CG_MASS_TOL = 1e-4
CG_MASS_WHY = ("the dumps print 6 significant digits and the grid sum is a midpoint rule of a kernel with a "
               "step at its cutoff (1.1 % of the peak); measured 1.7e-5 and 3.6e-5 in test runs")

def mass(d):
    return RHO_P * math.pi / 6 * d ** 3


def openings(L_mm):
    """The openings [(x0, x1)] for a separation L [mm] (0: one slot 2 D0 wide), or SINGLE."""
    if L_mm == SINGLE:
        return [(-D0 / 2, D0 / 2)]
    L = L_mm * 1e-3
    if L == 0:
        return [(-D0, D0)]
    return [(-L / 2 - D0, -L / 2), (L / 2, L / 2 + D0)]


def centres(L_mm):
    """The centres O_x of the two 14 mm openings (R2), one for the single slot
    (and two adjacent ones, +-D0/2, for L = 0)."""
    if L_mm == SINGLE:
        return [0.0]
    L = L_mm * 1e-3
    return [-(L + D0) / 2, (L + D0) / 2]
