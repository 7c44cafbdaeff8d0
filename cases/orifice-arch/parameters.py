"""The numbers of the orifice / free-fall-arch study (reference case E, README.md).
SI units; lengths in the sizes below are in particle diameters d. Coordinates:
z up, z = 0 the silo floor (the orifice plane), the silo axis (3-D) or the
slit's centre line (quasi-2-D) at x = y = 0.

Given by the reference (shared/reference/cases.md, E): monodisperse spheres
r_p = 1/64 m, rho = 7520 kg/m3, e_n = 0.5, linear normal contact with viscous
damping, a flat-bottomed cylindrical silo with a circular outlet of radius R;
the experiment a quasi-2-D silo (a monolayer between two sheets, slit outlet
D = 2R, R = 17 d and 26 d). Not given, chosen here (README, "Parameters"):
the silo size, particle count, stiffness, friction, run length, averaging.
"""
import math

# --- the particles (reference) -----------------------------------------------
R_P = 1.0 / 64.0                  # particle radius [m]
D = 2 * R_P                       # diameter d [m]
RHO_P = 7520.0                    # particle density [kg/m3]
RESTITUTION = 0.5                 # normal coefficient of restitution e_n
G = 9.81
MASS = RHO_P * math.pi / 6 * D ** 3   # one particle [kg] (0.1202)
T_D = math.sqrt(2 * R_P / G)      # the reference's time unit t_d = sqrt(2 r_p / g) [s] (0.05644)

# --- the contact law (chosen; README "Parameters") --------------------------
# Linear spring-dashpot in the normal direction, LIGGGHTS 3.8
# `gran model hooke/stiffness` (F_n = k_n delta - m_eff gamma_n v_n, constant
# k_n, no force limit), gamma_n from e_n for particle pairs (m_eff = m/2) and
# particle-wall contacts (m_eff = m) by contact_law() below; tangential: Mindlin-type
# spring with history and the Coulomb limit (`tangential history`),
# k_t = 2/7 k_n and gamma_t = 2/7 gamma_n (a sphere's tangential oscillation then
# has the normal one's frequency and damping ratio).
K_N = 1.0e6                       # normal stiffness [N/m] = 2.65e4 m g / d
KT_OVER_KN = 2.0 / 7.0
FRICTION_PP = 0.5                 # sliding friction particle-particle
FRICTION_PW = 0.5                 # particle-wall (floor, silo wall, plates)
STEPS_PER_CONTACT = 25            # DEM dt = contact time of a pair / this
SKIN = 0.2                        # neighbour skin [d]

# --- the run (chosen) -------------------------------------------------------
PACKING_SETTLED = 0.60            # 3-D settled solid fraction, only to size the fill (measured 0.574 at the study size: README "Flow rate")
PACKING_SETTLED_2D = 0.80         # monolayer: area fraction of the discs, only to size the fill
PACKING_INSERT = 0.30             # random sequential addition of the loose fill (3-D; monolayer 0.40)
PACKING_INSERT_2D = 0.40
SETTLE_MIN, SETTLE_MAX = 20.0, 60.0   # settling on the closed floor: at least, at most [t_d] (demo; sizes set their own)
SETTLE_VRMS = 0.01                # settled when the rms speed < this x sqrt(g d)
FEED_HEIGHT = 4.0                 # the re-insertion region above the fill: this many d tall
FEED_FRACTION = 0.30              # re-insertion: fill that region to this solid fraction, ...
FEED_EVERY = 0.25                 # ... every this many t_d (the free surface stays at the fill height)
FEED_SPEED_2D = 2.0               # monolayer: the re-inserted particles move down at this x sqrt(g d) (the 3-D
                                  # silo's at rest): from rest a layer 4 d tall fed 88 per t_d, its R = 17 d slit
                                  # took 130 (README "Flow rate")
SINK_DEPTH = 4.0                  # particles are deleted (and counted removed) this far below the floor [d]
PRINT_EVERY = 0.05                # counts written every this many t_d
GAP_2D = 1.1                      # monolayer: plate gap [d] ("slightly above d")

# --- sizes (README "Sizes"); lengths in d, times in t_d ---------------------
# silo: R_s the silo radius, h the fill height, R the outlet radii; cg: the
# outlets whose CG fields are computed; slab: the monolayer (width, fill
# height, outlet half widths R). transient: discharge before the averaging
# window; average: its length; snapshot: CG snapshot interval.
SIZES = {
    "test": dict(silo=dict(R_s=6.0, h=12.0, R=[3.0], cg=[3.0]),
                 slab=dict(width=40.0, h=24.0, R=[6.0], cg=[6.0]),
                 transient=4.0, average=2.0, snapshot=1.0, segment=3.0, settle=(4.0, 30.0),
                 kernels=[("gauss", 1.0)], block_count=0),
    "demo": dict(silo=dict(R_s=10.0, h=24.0, R=[3.0, 4.0, 5.0], cg=[5.0]),
                 slab=dict(width=70.0, h=50.0, R=[17.0], cg=[17.0]),
                 transient=8.0, average=10.0, snapshot=1.0, segment=10.0, settle=(SETTLE_MIN, SETTLE_MAX),
                 kernels=[("gauss", 1.0), ("heaviside", 1.0), ("gauss", 0.5)], block_count=2),
    # run on this machine (README "Sizes"): what two cores shared by six jobs finish in an hour
    "study": dict(silo=dict(R_s=12.0, h=24.0, R=[3.0, 4.0, 5.0], cg=[4.0, 5.0]),
                  slab=dict(width=200.0, h=50.0, R=[17.0, 26.0], cg=[17.0, 26.0]),   # 100 d wide: the slit a third to half
                  transient=6.0, average=14.0, snapshot=0.5, segment=5.0, settle=(10.0, 40.0),
                  kernels=[("gauss", 1.0), ("heaviside", 1.0), ("gauss", 0.5)], block_count=4),
    # the reference's R = 16 d with a silo 2.5 R wide (README "Sizes": ~4.6e5 particles,
    # ~2.8e4 CPU-s per run at the measured 3.5e6 particle-steps per CPU-s; not run here)
    "full": dict(silo=dict(R_s=40.0, h=80.0, R=[8.0, 12.0, 16.0], cg=[12.0, 16.0]),
                 slab=dict(width=400.0, h=200.0, R=[17.0, 26.0], cg=[17.0, 26.0]),
                 transient=20.0, average=60.0, snapshot=0.5, segment=5.0, settle=(SETTLE_MIN, SETTLE_MAX),
                 kernels=[("gauss", 1.0), ("heaviside", 1.0), ("gauss", 0.5), ("heaviside", 0.5)],
                 block_count=4),
}

# --- CG post-processing (README "CG fields") --------------------------------
DENSITY_PROFILE_Z = [2, 4, 8, 12, 16, 20, 24, 28, 32]   # z / d of the density profiles
VELOCITY_PROFILE_Z = [4, 8, 16, 20]                      # z / d of the velocity profiles
CG_R_OVER_OUTLET = 2.0            # the CG window reaches r (or |x|) = this x R ...
CG_Z_TOP = 33.0                   # ... and z from below the floor to this [d]
CG_Z_BELOW = 3.0                  # the window starts this far below the floor [d]
ARCH_Z_RANGE = (-1.0, 2.0)        # z_c(r) is searched for in this range of z / R
ARCH_FIT_R = 0.9                  # the parabola is fitted over r / R <= this (the rim: noise, the edge's corner)
CONTACT_VANISH = 0.1              # the contact-stress "arch": where tr(sigma_c)/3 falls to this x rho_b g R (README)
ARCH_WINDOW_PAD = 3.0             # the small window of the block runs reaches R + this x the kernel's cutoff...

# --- closed form (README "Flow rate"): Beverloo's band k = 1..3 at C (gc.closed_forms.beverloo_band) ---
BEVERLOO_C, K_RANGE = 0.58, (1.0, 3.0)

# --- checks -----------------------------------------------------------------
MASS_INTEGRAL_TOL = 1e-3          # CG: int rho dV over an enclosing window vs the particles' mass (README)


def contact_law(k_n=K_N, e=RESTITUTION, m=MASS):
    """LIGGGHTS hooke/stiffness numbers for a linear spring-dashpot with restitution e
    (gc.linear_contact.linear_dashpot: gamman and the contact time of particle pairs, m_eff = m/2,
    and particle-wall contacts, m_eff = m) and the DEM step: a pair's contact time /
    STEPS_PER_CONTACT."""
    from granair_cases import linear_contact
    out = linear_contact.linear_dashpot(k_n, e, m)
    out["dt"] = out["t_contact_pp"] / STEPS_PER_CONTACT
    return out
