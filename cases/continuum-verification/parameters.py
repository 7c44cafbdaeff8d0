"""The numbers of the continuum verification (README.md). SI units."""
import math

# Glass beads of Jop, Forterre & Pouliquen (2006): mu_s = tan 20.9 deg,
# mu_2 = tan 32.76 deg, I0 = 0.279, d = 0.53 mm, rho_p = 2450 kg/m3.
GLASS = dict(muS=math.tan(math.radians(20.9)), mu2=math.tan(math.radians(32.76)), I0=0.279, d=0.53e-3,
             rhoP=2450.0, etaMax=1e5, gammaDotMin=1e-6)
PHI = 0.6                  # solid fraction of the flowing layer (bulk density PHI rho_p)
AIR_RHO, AIR_MU = 1.2, 1.8e-5   # the air (model none: it only fills the cells above the plane's layer)

# --- the inclined plane -----------------------------------------------------------
THETA = 25.0               # inclination [deg]: tan 25 = 0.466 between mu_s and mu_2
DEPTH_D = 20               # layer depth in grain diameters
PLANE_CELLS, PLANE_END = 80, 8.0    # cells across the layer, simulated time [s] (defaults)
PLANE_DT_MAX = 5e-3

# --- plane shear over a Coulomb wall ------------------------------------------------
COUETTE_H = 10e-3          # layer height [m]
COUETTE_V = 0.5            # top wall velocity [m/s]
COUETTE_P = 1000.0         # pressure [Pa]
COUETTE_CELLS, COUETTE_END = 10, 10.0
COUETTE_DT_MAX = 1e-3
# (name, mu_w): the no-slip shear (I = 0.0415) needs mu = 0.416: 0.5 holds it,
# 0.40 lets a sheared layer slide, 0.30 < mu_s a rigid block slide.
COUETTE_RUNS = [("couette-stick", 0.50), ("couette-slide", 0.40), ("couette-rigid", 0.30)]

# --- the inclined plane with dilatancy (granularProperties `dilatancy on;`, Dilatancy.H) -----
# phi(I) = phi_max - (phi_max - phi_min) I (MuI.hpp): phi_max = PHI, the packing the layer
# starts at, and a slope of 0.2 (phi_min 0.4): at the Jop I = 0.1328 the steady layer dilates
# to 0.5734 (-4.4 %), deepening by 4.6 %, well above the tolerances below. A test of the
# solver's mass/volume coupling, not a claim about glass beads' phi(I).
DILATANT = dict(phiMax=PHI, phiMin=0.4)
PLANE_DILATANCY_END = 16.0  # [s]: the layer's top creeps to its steady dilation more slowly (measured: the
                            # last two writes of the lower 90 % change by 2e-4 of u_s at 8 s, 2e-5 at 16 s;
                            # with dilatancyRelaxation 0.2 4.4e-4 at 24 s: Dilatancy.H)

RUNS = {"inclined-plane": [("plane-jop", "none"), ("plane-barkerGray", "barkerGray2017")],
        "couette-coulomb": COUETTE_RUNS,
        "inclined-plane-dilatancy": [("plane-dilatancy", "none")]}
WRITES = 8                 # field writes per run (the last two judge steadiness)

# --- checks (--check) --------------------------------------------------------------
PLANE_PROFILE = 0.01       # max |u - u_exact| over the powder cells / exact surface velocity
PLANE_FLUX = 0.01          # depth-integrated flux, relative
COUETTE_PROFILE = 0.005    # max |u - u_exact| / wall velocity (the exact profiles are linear)
STEADY = 1e-4              # change between the last two writes / velocity scale
STICK = 1e-3               # |slip| below this fraction of V counts as sticking
PLANE_PHI = 5e-4           # dilatancy: max |phi - phi(I)| over the lower BULK of the layer (of a 0.027 dilation)
PLANE_PHI_MEAN = 1e-3      # dilatancy: the layer's mean phi (its full cells) against phi(I)
BULK = 0.9                 # dilatancy: the lower 90 % of the layer. The cells under the free surface shear a
                           # little fast (the surface error of the incompressible runs), so their I and phi(I)
                           # are off; the surface cell flickers between stressed and stress-free (phi(I) jumps
                           # to phi_min), which unsettles the cell below it by ~1.5e-4 of u_s between writes
PLANE_DEPTH = 0.005        # dilatancy: layer depth sum(alpha dy) against h0 PHI / phi(I), relative
GRAINS = 1e-9              # dilatancy: grain volume sum(alpha.grains dy) against its start, relative
