"""The numbers of the Ergun packed-bed study (README.md). SI units."""
from granair_cases import closed_forms

EPS = 0.4                      # bed void fraction
RHO, MU = 1.2, 1.8e-5          # air [kg/m3], [Pa s]
DIAMETERS = [225e-6, 2e-3]     # lactose-like fine powder, coarse beads [m]
REYNOLDS = [0.1, 0.3, 1, 3, 10, 30, 100]   # particle Re = rho U_s d / mu
LAWS = ["ErgunGidaspow", "DiFelice"]
TOLERANCE = 0.02               # ErgunGidaspow must match Ergun within 2 %
STEPS = 300                    # time steps at Courant 0.5 in the bed: steady to 1e-9

# The packed bed (template/): 1 mm cells; pressure on two planes inside the bed
DZ = 1e-3                      # cell height [m]
Z_LOW, Z_HIGH = 0.02, 0.04     # monitor planes `low`, `high` [m]

# The short bed (template-short-bed/ over template/): sharp void-fraction edges
BED_CELLS = [4, 6]
PLENUM_CELLS = 6               # particle-free cells below the bed
FREEBOARD_CELLS = 6            # particle-free cells above it
AWAY = 2                       # cells next to the bed left out of the plenum/freeboard means


def cell_size(d):
    """Short-bed cell height [m]: at least 3 particle diameters (an unresolved
    CFD-DEM cell holds several particles), and 1 mm for the fine powder."""
    return max(1e-3, 3 * d)


def ergun(u_s, d, eps=EPS):
    """Ergun (1952) pressure drop per length [Pa/m] at superficial velocity U_s."""
    return closed_forms.ergun_gradient(u_s, eps, d, RHO, MU)
