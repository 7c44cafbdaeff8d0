"""The numbers of the mu(I) calibration (README.md): the two DEM materials, taken
from the DEM levels of their cases (no copy: those cases' parameters.py are
read here), the shear cell and the sweep. SI units.

Coordinates: x the shear direction, y the vorticity direction (both periodic),
z across the gap; the bottom wall is at rest, the top wall moves at +V in x
under the normal force -P Lx Ly (servo: fix aveforce)."""
import importlib.util
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def _case(name):
    spec = importlib.util.spec_from_file_location(f"{name.replace('-', '_')}_parameters",
                                                  os.path.join(HERE, "..", name, "parameters.py"))
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


WEDGE, MCC = _case("wedge-silo"), _case("mcc-hopper")

# --- the materials: exactly the contact parameters of each case's DEM level ----
# wedge-silo: the "study" size (E = 5e6 Pa) at b = 10 mm (b/d = 7: s = 6.52, mean
# parcel 1.43 mm), the truncated Gaussian PSD scaled by s, SJKR cohesion
# "matched" (k = k_real (E/E_real)^(2/3)), walls made of the same parcels.
# With Hertz contacts and SJKR the dimensionless rheology does not depend on s
# at a fixed E/P (README, "Why one calibration serves every s").
_W_SIZE = WEDGE.SIZES["study"]
_W_B = 10
_W_DMEAN = WEDGE.psd_moments()[0]
_W_S = _W_B * 1e-3 / (_W_SIZE["per_b"][_W_B]["b_over_d"] * _W_DMEAN)
MATERIALS = {
    "wedge-silo": dict(
        title="lactose parcels of the wedge silo (study size, b = 10 mm)",
        s=_W_S, d_mean=_W_S * _W_DMEAN, d_min=_W_S * WEDGE.D_MIN_PSD, d_max=_W_S * WEDGE.D_MAX_PSD,
        psd=lambda rng, s=_W_S: s * WEDGE.draw_primary_diameter(rng),
        rho=WEDGE.RHO_P, youngs=_W_SIZE["youngs"], nu=WEDGE.NU, restitution=WEDGE.RESTITUTION,
        friction=WEDGE.FRICTION_PP, rolling_friction=None,
        cohesion=WEDGE.K_COH_REAL * (_W_SIZE["youngs"] / WEDGE.E_REAL) ** (2.0 / 3.0),
        rayleigh_fraction=_W_SIZE["rayleigh_fraction"],
        source="cases/wedge-silo: parameters.py (SIZES['study'], b = 10), study.py numbers(), template/dem/in.materials"),
    "mcc-hopper": dict(
        title="MCC parcels of the MCC hopper (s = 5, 3.3 mm)",
        s=5.0, d_mean=5.0 * MCC.D_PARTICLE, d_min=5.0 * MCC.D_PARTICLE, d_max=5.0 * MCC.D_PARTICLE,
        psd=lambda rng: 5.0 * MCC.D_PARTICLE,
        rho=MCC.RHO_P, youngs=MCC.YOUNGS, nu=MCC.NU, restitution=MCC.RESTITUTION,
        friction=MCC.FRICTION_PP, rolling_friction=None, cohesion=0.0,
        rayleigh_fraction=MCC.RAYLEIGH_FRACTION,
        source="cases/mcc-hopper: parameters.py (coarse-grained DEM block), dem.py (--s 5 default), "
               "template-dem/dem/in.materials"),
}

# --- the shear cell -------------------------------------------------------------
PRESSURE = 500.0          # confining normal stress [Pa]: the silos' pressure near the orifice (README)
CELL_X, CELL_Y = 8.0, 8.0  # periodic lengths in mean parcel diameters
GAP = 12.0                # initial gap between the walls' inner faces, after compaction [d] (README)
WALL_THICKNESS = 1.5      # each wall: a random layer of frozen parcels this thick [d]
PACKING_INSERT = 0.36     # solid fraction of the random sequential addition (the servo compacts it)
COMPACT_VT = 0.2          # terminal speed of the top wall while it compacts the packing [m/s]
COMPACT_STEPS = 20000     # steps of compaction (no shear) before the first run
# The sweep: target inertial numbers, run from the fastest to the slowest, each
# from the end state of the one before (restart), for a strain of STRAIN[I]
# (top-wall displacement / gap); SNAPSHOTS CG snapshots per run, averaged over
# the last AVERAGE_FRACTION of the run.
# Fast runs are cheap and noisy (the servo wall bounces): long strains there.
I_TARGETS = (0.6, 0.4, 0.2, 0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001)
STRAIN = {0.6: 20.0, 0.4: 16.0, 0.2: 12.0, 0.1: 8.0, 0.05: 3.0, 0.02: 2.5, 0.01: 2.5, 0.005: 2.0, 0.002: 1.8,
          0.001: 1.5}
SNAPSHOTS = 50
AVERAGE_FRACTION = 0.7
FIRST_STRAIN_EXTRA = 2.0  # the first run also shears the compacted packing into steady flow
BAND = 3.0                # the bulk: at least this many d from either wall's inner face (README)
CG_WIDTH = 0.5            # Gaussian kernel width [d] of the CG profiles
CG_SPACING = 0.25         # profile spacing [d]

# --- the fits ------------------------------------------------------------------
# mu(I) = mu_s + (mu_2 - mu_s) / (I0 / I + 1) (Jop, Forterre & Pouliquen 2006);
# phi(I) = phi_max - (phi_max - phi_min) I (the continuum solver's form,
# Forterre & Pouliquen 2008). Both fitted to the dense, steady runs: measured
# I <= FIT_I_MAX (phi >= ~0.52; beyond it the cell's flow turns collisional and
# the servo wall bounces) and a block standard error of I within FIT_I_SE of I.
# The others are reported (points.csv: in_fit 0) and plotted open.
FIT_I_MAX = 0.4
FIT_I_SE = 0.10

# --- checks (study.py --check) ----------------------------------------------------
# Stress balance: in steady plane shear sigma_xz and sigma_zz are uniform across
# the gap and equal the top wall's traction. The CG bulk values against the
# wall's (time means over the same window): relative.
WALL_BALANCE = 0.05
WALL_BALANCE_SE = 3.0     # or this many block standard errors of the CG value, if larger (high I: the wall bounces)
# Uniformity: the rms deviation of sigma_xz over the bulk band from its mean.
UNIFORMITY = 0.10
# Quasi-static friction: DEM of frictional spheres without rolling resistance
# gives a quasi-static stress ratio of about 0.3-0.4 once the sliding friction
# exceeds ~0.3, rising slowly and saturating with it (Chialvo, Sun & Sundaresan
# 2012, Phys. Rev. E 85:021305; Goncu & Luding 2013, Acta Geotech. 8:629; in
# 2-D da Cruz et al. 2005). The band is that range widened by 0.05 each way.
MU_LOW_I_BAND = (0.25, 0.45)
