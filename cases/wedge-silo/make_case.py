#!/usr/bin/env python3
"""make_case.py: the wedge-silo geometry, material and model reductions, and
the writers of its run folders (standard library only).

One set of numbers (`Case`) drives everything: the OpenFOAM mesh (blockMesh),
the LIGGGHTS walls (hopper planes as STL, shaft walls and shutter as
primitive planes), the initial particle packing, the LIGGGHTS scripts, the
coupling settings and the post-processing (cell layout, depth scale).

    make_case.py fill  --size demo --b 10 DIR      # DEM-only fill + settle stage
    make_case.py run   --size demo --b 10 --air on --fill FILLDIR DIR
    make_case.py info  --size demo --b 10          # parameters and particle counts

Coordinates [m]: x across the silo (width 45 mm, centred), y along the slot
(depth; a thin periodic slice of it is simulated), z up with z = 0 the
orifice plane (the shutter). See README.md for the physics and the choices.
"""
import argparse
import json
import math
import os
import random
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "pylib"))
import dem_io  # noqa: E402  (read_dump, the discharge balance, the settle block)

# ---------------------------------------------------------------------------
# The silo and the powder of the study (cases.md section A). SI units.
# ---------------------------------------------------------------------------
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
K_COH_REAL = 1.0e5       # SJKR cohesion energy density at E_REAL [J/m3]
AIR_RHO, AIR_MU = 1.2, 1.8e-5
G = 9.81

PACKING_SETTLED = 0.58   # expected settled solid fraction (only to size the fill)
PACKING_INSERT = 0.33    # random sequential addition target of the loose packing

# ---------------------------------------------------------------------------
# Sizes. A size fixes the reductions per orifice width b [mm]:
#   b_over_d  orifice width in mean parcel diameters (sets the coarse-graining
#             factor s = b / (b_over_d * mean primary d))
#   fill      settled fill height above the orifice [m], enough for the
#             discharge time at the measured DEM-only rates
# and, for all b: the discharge time [s], Young's modulus [Pa], the slice
# thickness in mean parcel diameters, the DEM time step as a fraction of the
# Rayleigh time of the smallest parcel, the CFD (coupling) time step [s].
# demo: all six runs in about 10 min on 2 idle cores (README): the b = 5 mm
# runs cost most (smallest parcels), hence b_over_d 5.5 there, E = 2e6 Pa, a
# slice three parcels thick (four in the study) and 0.5 s of discharge (the
# rates are steady after about 0.2 s; the study runs 2 s). write_interval:
# the times of the field pictures and VTK files [s].
# ---------------------------------------------------------------------------
SIZES = {
    "demo": dict(
        t_end=0.5, write_interval=0.25, youngs=2e6, slice_parcels=3.0, rayleigh_fraction=0.2,
        cfd_dt=5e-4,
        per_b={5: dict(b_over_d=5.5, fill=0.085),
               10: dict(b_over_d=6.0, fill=0.135),
               15: dict(b_over_d=6.0, fill=0.190)}),
    "study": dict(
        t_end=2.0, write_interval=1.0, youngs=5e6, slice_parcels=4.0, rayleigh_fraction=0.2,
        cfd_dt=5e-4,
        per_b={5: dict(b_over_d=7.0, fill=0.150),
               10: dict(b_over_d=7.0, fill=0.260),
               15: dict(b_over_d=7.0, fill=0.250)}),
}


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


class Case:
    """All numbers of one run (or fill) of the wedge silo."""

    def __init__(self, size, b_mm, air=True, s=None, t_end=None, write_interval=None,
                 youngs=None, cohesion="matched", np=2, seed=1, fill=None,
                 slice_parcels=None):
        if size not in SIZES:
            raise SystemExit(f"make_case: unknown size '{size}', expected one of {sorted(SIZES)}")
        cfg = SIZES[size]
        if b_mm not in cfg["per_b"]:
            raise SystemExit(f"make_case: b = {b_mm} mm not in size '{size}' "
                             f"(expected one of {sorted(cfg['per_b'])})")
        pb = cfg["per_b"][b_mm]
        self.size, self.b_mm, self.air, self.np, self.seed = size, b_mm, air, np, seed
        self.b = b_mm * 1e-3
        self.theta = math.radians(HALF_ANGLE)
        self.hopper_height = (WIDTH - self.b) / 2 / math.tan(self.theta)
        self.d_primary_mean, d3 = psd_moments()
        self.v_primary_mean = math.pi / 6 * d3
        # coarse graining: parcel = s^3 primaries, s * primary diameter
        self.s = s if s is not None else self.b / (pb["b_over_d"] * self.d_primary_mean)
        if not self.s >= 1.0:
            raise SystemExit(f"make_case: coarse-graining factor s = {self.s} < 1")
        self.d_parcel_mean = self.s * self.d_primary_mean
        self.d_parcel_max = self.s * D_MAX_PSD
        self.r_parcel_min = self.s * D_MIN_PSD / 2
        self.v_parcel_mean = self.s ** 3 * self.v_primary_mean
        self.slice_parcels = slice_parcels if slice_parcels is not None else cfg["slice_parcels"]
        self.slice = self.slice_parcels * self.d_parcel_mean
        self.depth_scale = DEPTH / self.slice
        self.fill_height = fill if fill is not None else pb["fill"]
        self.t_end = t_end if t_end is not None else cfg["t_end"]
        self.write_interval = write_interval if write_interval is not None else cfg["write_interval"]
        # stiffness: E reduced, cohesion energy density scaled so the cohesive
        # force at a given contact load stays that of the real material
        # (SJKR force = k_coh * contact area, and the area at a given load
        # grows as E^(-2/3) for Hertz contacts).
        self.youngs = youngs if youngs is not None else cfg["youngs"]
        self.cohesion_mode = cohesion
        if cohesion == "matched":
            self.k_coh = K_COH_REAL * (self.youngs / E_REAL) ** (2.0 / 3.0)
        elif cohesion == "raw":
            self.k_coh = K_COH_REAL
        elif cohesion == "off":
            self.k_coh = 0.0
        else:
            raise SystemExit(f"make_case: cohesion '{cohesion}', expected matched, raw or off")
        # time steps: DEM dt a fraction of the Rayleigh time of the smallest
        # parcel, CFD step a whole number of DEM steps; fields every second.
        shear = self.youngs / (2 * (1 + NU))
        self.rayleigh_time = (math.pi * self.r_parcel_min * math.sqrt(RHO_P / shear)
                              / (0.1631 * NU + 0.8766))
        self.cfd_dt = cfg["cfd_dt"]
        self.coupling_interval = max(1, math.ceil(self.cfd_dt / (cfg["rayleigh_fraction"]
                                                                 * self.rayleigh_time)))
        self.dem_dt = self.cfd_dt / self.coupling_interval
        self.n_steps = round(self.t_end / self.cfd_dt)
        if abs(self.n_steps * self.cfd_dt - self.t_end) > 1e-9:
            raise SystemExit(f"make_case: discharge time {self.t_end} s is not a whole number "
                             f"of CFD steps ({self.cfd_dt} s)")
        self.mesh = self._mesh_layout()
        # void fraction: a Gaussian kernel one orifice-cell wide, so a parcel
        # crossing a cell face changes the void fraction smoothly (the `centre`
        # model's jumps drive spurious air flow and pressure spikes)
        self.void_fraction_model = "gaussian"
        self.kernel_width = 1.6 * self.d_parcel_mean
        self.kernel_cutoff = 3.0

    def void_fraction_dict(self):
        if self.void_fraction_model == "centre":
            return "type centre;"
        return f"type gaussian; width {self.kernel_width:.6g}; cutoff {self.kernel_cutoff:g};"

    # ----------------------------------------------------------------- mesh
    def _mesh_layout(self):
        """Cell counts of the five blocks: ~1.6 mean parcel diameters near the orifice."""
        h = 1.6 * self.d_parcel_mean
        nx = max(4, round(self.b / h))
        nz_h = max(4, round(self.hopper_height / h))
        nz_b = max(4, round(BOX_BELOW / h))
        nx_side = max(2, round((WIDTH - self.b) / 2 / (2 * h)))
        nz_s = max(10, round(SHAFT_HEIGHT / max(2 * h, 0.004)))
        return dict(nx=nx, nx_side=nx_side, nz_below=nz_b, nz_hopper=nz_h, nz_shaft=nz_s)

    def points2d(self):
        """The 12 corner points (x, z) of the blocks."""
        w, b, hh, hs, hb = WIDTH / 2, self.b / 2, self.hopper_height, SHAFT_HEIGHT, BOX_BELOW
        return [(-w, -hb), (-b, -hb), (b, -hb), (w, -hb),
                (-w, 0.0), (-b, 0.0), (b, 0.0), (w, 0.0),
                (-w, hh), (w, hh), (-w, hh + hs), (w, hh + hs)]

    def blocks(self):
        """(name, corners bl br tr tl, nx, nz) in blockMesh order (cells numbered block by block)."""
        m = self.mesh
        return [("belowLeft", (0, 1, 5, 4), m["nx_side"], m["nz_below"]),
                ("belowCentre", (1, 2, 6, 5), m["nx"], m["nz_below"]),
                ("belowRight", (2, 3, 7, 6), m["nx_side"], m["nz_below"]),
                ("hopper", (5, 6, 9, 8), m["nx"], m["nz_hopper"]),
                ("shaft", (8, 9, 11, 10), m["nx"], m["nz_shaft"])]

    def cell_polygons(self):
        """x-z corner polygons of every cell in OpenFOAM's cell order (blockMesh, or
        reconstructPar after a parallel run): block by block, x fastest, then z.
        Each block is bilinear with uniform spacing, as blockMesh builds it."""
        pts = self.points2d()
        polys = []
        for _, (bl, br, tr, tl), nx, nz in self.blocks():
            P = [pts[bl], pts[br], pts[tr], pts[tl]]

            def at(u, v):
                return tuple((1 - u) * (1 - v) * P[0][a] + u * (1 - v) * P[1][a]
                             + u * v * P[2][a] + (1 - u) * v * P[3][a] for a in range(2))
            for k in range(nz):
                for i in range(nx):
                    u0, u1, v0, v1 = i / nx, (i + 1) / nx, k / nz, (k + 1) / nz
                    polys.append((at(u0, v0), at(u1, v0), at(u1, v1), at(u0, v1)))
        return polys

    def locate_cell(self, x, z):
        """Cell index of the point (x, z) (the `centre` void-fraction model), or -1."""
        offset = 0
        pts = self.points2d()
        for _, (bl, br, tr, tl), nx, nz in self.blocks():
            zb, zt = pts[bl][1], pts[tl][1]
            if zb <= z < zt or (z == zt and zt == pts[11][1]):
                v = (z - zb) / (zt - zb)
                xl = pts[bl][0] + v * (pts[tl][0] - pts[bl][0])
                xr = pts[br][0] + v * (pts[tr][0] - pts[br][0])
                if xl <= x < xr:
                    i = min(nx - 1, int((x - xl) / (xr - xl) * nx))
                    k = min(nz - 1, int(v * nz))
                    return offset + i + nx * k
            offset += nx * nz
        return -1

    def cell_volumes(self):
        """Cell volumes [m3] (planar quads times the slice thickness)."""
        vols = []
        for poly in self.cell_polygons():
            a = 0.0
            for j in range(4):
                (x0, z0), (x1, z1) = poly[j], poly[(j + 1) % 4]
                a += x0 * z1 - x1 * z0
            vols.append(abs(a) / 2 * self.slice)
        return vols

    def n_cells(self):
        return sum(nx * nz for _, _, nx, nz in self.blocks())

    def monitor_above_z(self):
        """Height of the hopper face layer about one orifice width above the orifice."""
        nz = self.mesh["nz_hopper"]
        k = max(1, min(nz - 1, round(self.b / (self.hopper_height / nz))))
        return k * self.hopper_height / nz

    # ---------------------------------------------------------------- counts
    def full_silo_particles(self, d=225e-6, fill=None):
        """Primary particles a full 60 mm deep silo filled to `fill` would hold."""
        return PACKING_SETTLED * self.fill_area(fill) * DEPTH / (math.pi / 6 * d ** 3)

    def fill_area(self, fill=None):
        """x-z area [m2] of the silo below height `fill` above the orifice."""
        h = self.fill_height if fill is None else fill
        hh = self.hopper_height
        if h <= hh:
            top = self.b + 2 * h * math.tan(self.theta)
            return 0.5 * (self.b + top) * h
        return 0.5 * (self.b + WIDTH) * hh + WIDTH * (h - hh)

    def n_parcels(self):
        return round(PACKING_SETTLED * self.fill_area() * self.slice / self.v_parcel_mean)

    def info(self):
        return dict(
            size=self.size, b_mm=self.b_mm, air=self.air,
            coarse_graining_factor=self.s, d_primary_mean_m=self.d_primary_mean,
            d_parcel_mean_m=self.d_parcel_mean, b_over_d_parcel=self.b / self.d_parcel_mean,
            slice_m=self.slice, slice_parcels=self.slice_parcels, depth_scale=self.depth_scale,
            hopper_height_m=self.hopper_height, fill_height_target_m=self.fill_height,
            n_parcels_target=self.n_parcels(),
            full_silo_primaries_d225=self.full_silo_particles(),
            youngs_Pa=self.youngs, youngs_real_Pa=E_REAL, cohesion_mode=self.cohesion_mode,
            cohesion_energy_density_J_m3=self.k_coh, cohesion_real_J_m3=K_COH_REAL,
            rayleigh_time_s=self.rayleigh_time, dem_dt_s=self.dem_dt,
            coupling_interval=self.coupling_interval, cfd_dt_s=self.cfd_dt,
            t_end_s=self.t_end, write_interval_s=self.write_interval,
            n_cells=self.n_cells(), mesh=self.mesh,
            monitor_above_z_m=self.monitor_above_z(),
            sink_z_m=-SINK_DEPTH, rho_p=RHO_P, np=self.np, seed=self.seed,
            wall_friction=math.tan(math.radians(WALL_FRICTION_ANGLE)),
            friction_pp=FRICTION_PP, restitution=RESTITUTION, poisson=NU,
            psd=dict(mean=D_MEAN_PSD, sigma=D_SIGMA_PSD, min=D_MIN_PSD, max=D_MAX_PSD),
            width_m=WIDTH, depth_m=DEPTH, shaft_height_m=SHAFT_HEIGHT, half_angle_deg=HALF_ANGLE,
            box_below_m=BOX_BELOW)


# ---------------------------------------------------------------------------
# Writers
# ---------------------------------------------------------------------------
FOAM_HEADER = "FoamFile {{ version 2.0; format ascii; class {cls}; object {obj}; }}\n"


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as fh:
        fh.write(text)


def hopper_stl(case, side):
    """One hopper wall as triangles in strips of about one slice thickness along the
    slope, spanning the periodic slice y in [0, slice] exactly. (LIGGGHTS 3.8 sizes
    its mesh-topology bins by the largest triangle; one long triangle in a thin
    periodic box fails an internal assertion, small ones do not.)"""
    sgn = -1 if side == "left" else 1
    hh, b2, t = case.hopper_height, case.b / 2, math.tan(case.theta)
    length = hh / math.cos(case.theta)
    n = max(2, math.ceil(length / case.slice))
    lines = [f"solid hopper_{side}"]
    for k in range(n):
        z0, z1 = hh * k / n, hh * (k + 1) / n
        x0, x1 = sgn * (b2 + z0 * t), sgn * (b2 + z1 * t)
        quad = [(x0, 0.0, z0), (x0, case.slice, z0), (x1, case.slice, z1), (x1, 0.0, z1)]
        for tri in ((quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])):
            lines.append("  facet normal 0 0 0\n    outer loop")
            lines += ["      vertex %.12g %.12g %.12g" % v for v in tri]
            lines.append("    endloop\n  endfacet")
    lines.append(f"endsolid hopper_{side}")
    return "\n".join(lines) + "\n"


def dem_box(case):
    """LIGGGHTS box: a little wider than the silo, from below the sink to above the loose fill."""
    top = max(case.hopper_height + SHAFT_HEIGHT, 1.9 * case.fill_height + 0.02)
    return (-WIDTH / 2 - 0.001, WIDTH / 2 + 0.001, 0.0, case.slice, -SINK_DEPTH - 0.005, top)


def dem_common(case):
    """Material, contact model, walls (not the shutter), gravity, integrator."""
    mu_w = math.tan(math.radians(WALL_FRICTION_ANGLE))
    k = case.k_coh
    skin = 0.3 * case.d_parcel_mean
    return f"""neighbor        {skin:.6g} bin
neigh_modify    delay 0

# Material (type 1 particles, type 2 walls). E reduced from {E_REAL:.3g} Pa (see README).
{"soft_particles  yes             # LIGGGHTS asks for this below E = 5e6 Pa" if case.youngs < 5e6 else ""}
fix m1 all property/global youngsModulus peratomtype {case.youngs:.6g} {case.youngs:.6g}
fix m2 all property/global poissonsRatio peratomtype {NU} {NU}
fix m3 all property/global coefficientRestitution peratomtypepair 2 {RESTITUTION} {RESTITUTION} {RESTITUTION} {RESTITUTION}
fix m4 all property/global coefficientFriction peratomtypepair 2 {FRICTION_PP} {mu_w:.6g} {mu_w:.6g} {mu_w:.6g}
# SJKR cohesion energy density [J/m3] ({case.cohesion_mode}; {K_COH_REAL:.3g} at the real E)
fix m5 all property/global cohesionEnergyDensity peratomtypepair 2 {k:.6g} {k:.6g} {k:.6g} {k:.6g}

# Hertz normal + Mindlin-type tangential history, Coulomb limit, SJKR cohesion
pair_style      gran model hertz tangential history cohesion sjkr
pair_coeff      * *
timestep        {case.dem_dt:.10g}
fix gravi all gravity {G} vector 0.0 0.0 -1.0

# Walls from the same numbers as the CFD mesh: shaft planes x = +-{WIDTH / 2} m
# and the two hopper planes (STL written by make_case.py)
fix shaftL all wall/gran model hertz tangential history cohesion sjkr primitive type 2 xplane {-WIDTH / 2:.12g}
fix shaftR all wall/gran model hertz tangential history cohesion sjkr primitive type 2 xplane {WIDTH / 2:.12g}
fix hopL all mesh/surface file dem/hopper_left.stl type 2
fix hopR all mesh/surface file dem/hopper_right.stl type 2
fix hopper all wall/gran model hertz tangential history cohesion sjkr mesh n_meshes 2 meshes hopL hopR

fix integr all nve/sphere
# Declares particle type 1 to LIGGGHTS (it refuses to run once the silo is
# empty unless a particle distribution names the types); never used to insert.
fix typeDecl all particletemplate/sphere 15485863 atom_type 1 density constant {RHO_P} radius constant {case.s * D_MEAN_PSD / 2:.6g}
fix typeDist all particledistribution/discrete 32452843 1 typeDecl 1.0
"""


def write_fill(case, d):
    """The DEM-only fill stage: loose random packing (read_data), settle on the shutter,
    write the restart both discharge runs start from."""
    rng = random.Random(case.seed)
    atoms, zmax = loose_packing(case, rng)
    box = dem_box(case)
    if zmax > box[5]:
        raise SystemExit(f"make_case: loose packing reaches z = {zmax:.4f} m above the DEM box")
    lines = [f"# wedge silo loose packing: {len(atoms)} parcels (make_case.py)", "",
             f"{len(atoms)} atoms", "2 atom types",
             f"{box[0]:.12g} {box[1]:.12g} xlo xhi", f"{box[2]:.12g} {box[3]:.12g} ylo yhi",
             f"{box[4]:.12g} {box[5]:.12g} zlo zhi", "", "Atoms", ""]
    for i, (x, y, z, dia) in enumerate(atoms, 1):
        lines.append(f"{i} 1 {dia:.9g} {RHO_P} {x:.9g} {y:.9g} {z:.9g}")
    write(os.path.join(d, "dem", "packing.data"), "\n".join(lines) + "\n")
    write(os.path.join(d, "dem", "hopper_left.stl"), hopper_stl(case, "left"))
    write(os.path.join(d, "dem", "hopper_right.stl"), hopper_stl(case, "right"))
    settle_min = 0.15
    settle_max = 0.6
    chunk = max(1, round(0.02 / case.dem_dt))
    n_min = math.ceil(settle_min / (chunk * case.dem_dt))
    n_max = math.ceil(settle_max / (chunk * case.dem_dt))
    script = f"""# Wedge silo, fill stage (DEM only): settle a loose random packing on the
# closed shutter, then write the restart both discharge runs start from.
# Written by make_case.py: b = {case.b_mm} mm, size {case.size}, s = {case.s:.4g}
atom_style      granular
atom_modify     map array
boundary        f p f
newton          off
communicate     single vel yes
units           si
processors      * 1 1
read_data       dem/packing.data

{dem_common(case)}
{dem_io.settle_on_shutter("wall/gran model hertz tangential history cohesion sjkr primitive type 2 zplane 0.0", chunk, n_min, n_max, settle_min, settle_max)}"""
    write(os.path.join(d, "dem", "in.fill"), script)
    write(os.path.join(d, "case.json"), json.dumps(case.info(), indent=1) + "\n")


def loose_packing(case, rng):
    """Random sequential addition of parcels (PSD scaled by s) into the silo above the
    shutter, periodic in y, at about PACKING_INSERT solid fraction. Returns
    [(x, y, z, d)] and the highest top."""
    n = case.n_parcels()
    diameters = [case.s * draw_primary_diameter(rng) for _ in range(n)]
    diameters.sort(reverse=True)          # large first: easier to place
    vol = sum(math.pi / 6 * dd ** 3 for dd in diameters)
    t = math.tan(case.theta)
    hh, b2, w2, sl = case.hopper_height, case.b / 2, WIDTH / 2, case.slice
    gap = 0.02 * case.d_parcel_mean        # clearance from walls and neighbours

    # height of the region that holds the solid volume at PACKING_INSERT
    def area_below(h):
        return case.fill_area(h)
    top = case.fill_height
    while area_below(top) * sl * PACKING_INSERT < vol:
        top += 0.001
    cell = case.d_parcel_max * 1.0001
    grid = {}
    atoms = []
    ny = max(1, int(sl / cell))

    def inside(x, z, r):
        if z < r + gap:
            return False
        if abs(x) > w2 - r - gap:
            return False
        if z < hh + r:
            c = math.cos(case.theta)
            if (x + b2 + z * t) * c < r + gap or (b2 + z * t - x) * c < r + gap:
                return False
        return True

    def free(x, y, z, r):
        ix, iy, iz = int((x + w2) / cell), int(y / cell) % ny, int(z / cell)
        for dx in (-1, 0, 1):
            for dz in (-1, 0, 1):
                for dy in (-1, 0, 1):
                    for (px, py, pz, pr) in grid.get((ix + dx, (iy + dy) % ny, iz + dz), ()):
                        ddy = y - py
                        ddy -= sl * round(ddy / sl)     # periodic in y
                        rr = r + pr + gap
                        if (x - px) ** 2 + ddy ** 2 + (z - pz) ** 2 < rr * rr:
                            return False
        return True

    attempts = 0
    for dia in diameters:
        r = dia / 2
        placed = False
        while not placed:
            for _ in range(2000):
                attempts += 1
                z = rng.uniform(r, top)
                x = rng.uniform(-w2 + r, w2 - r)
                y = rng.uniform(0.0, sl)
                if inside(x, z, r) and free(x, y, z, r):
                    key = (int((x + w2) / cell), int(y / cell) % ny, int(z / cell))
                    grid.setdefault(key, []).append((x, y, z, r))
                    atoms.append((x, y, z, dia))
                    placed = True
                    break
            if not placed:
                top *= 1.05                 # crowded: let the region grow
    return atoms, max(a[2] + a[3] / 2 for a in atoms)


def write_run(case, d, fill_dir):
    """One discharge run folder (with or without air) that starts from the fill's restart."""
    fill_rel = os.path.relpath(os.path.abspath(fill_dir), os.path.abspath(d))
    write(os.path.join(d, "system", "blockMeshDict"), block_mesh_dict(case))
    write(os.path.join(d, "system", "controlDict"), control_dict(case))
    write(os.path.join(d, "system", "fvSchemes"), FV_SCHEMES)
    write(os.path.join(d, "system", "fvSolution"), FV_SOLUTION)
    write(os.path.join(d, "system", "decomposeParDict"),
          FOAM_HEADER.format(cls="dictionary", obj="decomposeParDict")
          + f"numberOfSubdomains {case.np};\nmethod simple;\n"
            f"coeffs {{ n ({case.np} 1 1); }}   // split across x, as LIGGGHTS (processors * 1 1)\n")
    write(os.path.join(d, "constant", "transportProperties"),
          FOAM_HEADER.format(cls="dictionary", obj="transportProperties")
          + f"rho {AIR_RHO};      // air density [kg/m3]\nmu {AIR_MU};    // air viscosity [Pa s]\n")
    write(os.path.join(d, "constant", "couplingProperties"), coupling_properties(case))
    write(os.path.join(d, "0", "U"), U_FIELD)
    write(os.path.join(d, "0", "p"), P_FIELD)
    write(os.path.join(d, "dem", "hopper_left.stl"), hopper_stl(case, "left"))
    write(os.path.join(d, "dem", "hopper_right.stl"), hopper_stl(case, "right"))
    os.makedirs(os.path.join(d, "dem", "post"), exist_ok=True)
    snap = round(case.write_interval / case.dem_dt)
    script = f"""# Wedge silo, discharge ({'with air' if case.air else 'DEM only, no air'}).
# Written by make_case.py: b = {case.b_mm} mm, size {case.size}, s = {case.s:.4g}.
# Starts from the settled fill; the shutter is not defined here: it opens at
# discharge time 0 (the first coupled step). granairFoam runs the steps.
atom_style      granular
atom_modify     map array
newton          off
communicate     single vel yes
processors      * 1 1
read_restart    {fill_rel}/dem/fill.restart    # step 0 (reset by the fill)

{dem_common(case)}
thermo_style    custom step atoms ke
thermo          {snap}
thermo_modify   norm no

# particle snapshots at discharge times 0, {case.write_interval:g}, ... s
dump            snap all custom {snap} dem/post/particles_*.txt id x y z radius mass vx vz
"""
    write(os.path.join(d, "dem", "in.liggghts"), script)
    write(os.path.join(d, "case.json"), json.dumps(dict(case.info(), fill_dir=fill_rel), indent=1) + "\n")


def block_mesh_dict(case):
    pts = case.points2d()
    n = len(pts)
    verts = [f"    ({x:.12g} 0 {z:.12g})   // {i}" for i, (x, z) in enumerate(pts)]
    verts += [f"    ({x:.12g} {case.slice:.12g} {z:.12g})   // {i + n}" for i, (x, z) in enumerate(pts)]

    def hexv(c):
        bl, br, tr, tl = c
        return f"({bl} {br} {br + n} {bl + n} {tl} {tr} {tr + n} {tl + n})"

    blocks = [f"    hex {hexv(c)} ({nx} 1 {nz}) simpleGrading (1 1 1)   // {name}"
              for name, c, nx, nz in case.blocks()]

    def side(a, b):
        return f"({a} {b} {b + n} {a + n})"
    faces_empty = []
    for _, (bl, br, tr, tl), _, _ in case.blocks():
        faces_empty.append(f"({bl} {br} {tr} {tl})")
        faces_empty.append(f"({bl + n} {tl + n} {tr + n} {br + n})")
    return (FOAM_HEADER.format(cls="dictionary", obj="blockMeshDict") + f"""// Wedge silo, b = {case.b_mm} mm, 2-D slice {case.slice * 1e3:.4g} mm thick (one cell, empty).
// Written by make_case.py. Blocks: the air box below the orifice (three
// columns), the trapezoidal hopper converging to the slot, the shaft.
// The orifice plane z = 0 is the face between belowCentre and hopper.
convertToMeters 1;
vertices
(
{chr(10).join(verts)}
);
blocks
(
{chr(10).join(blocks)}
);
edges ();
boundary
(
    walls      // silo walls and the underside around the orifice: no slip
    {{
        type wall;
        faces ( {side(4, 5)} {side(6, 7)} {side(5, 8)} {side(6, 9)} {side(8, 10)} {side(9, 11)} );
    }}
    top        // the open top of the shaft: ambient pressure
    {{
        type patch;
        faces ( {side(10, 11)} );
    }}
    atmosphere // bottom and sides of the air box below the orifice: ambient pressure
    {{
        type patch;
        faces ( {side(0, 1)} {side(1, 2)} {side(2, 3)} {side(0, 4)} {side(3, 7)} );
    }}
    frontAndBack
    {{
        type empty;
        faces ( {' '.join(faces_empty)} );
    }}
);
mergePatchPairs ();
""")


def control_dict(case):
    every = round(case.write_interval / case.cfd_dt)
    return FOAM_HEADER.format(cls="dictionary", obj="controlDict") + f"""application     granairFoam;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         {case.t_end:.10g};     // discharge time [s]; t = 0 when the shutter opens
deltaT          {case.cfd_dt:.10g};    // = couplingInterval ({case.coupling_interval}) x DEM dt ({case.dem_dt:.6g} s)
writeControl    timeStep;
writeInterval   {every};        // fields every {case.write_interval:g} s
purgeWrite      0;
writeFormat     ascii;
writePrecision  8;
writeCompression off;
timeFormat      general;
timePrecision   8;
runTimeModifiable false;
"""


def coupling_properties(case):
    zab = case.monitor_above_z()
    half_ab = case.b / 2 + zab * math.tan(case.theta)
    eps = 1e-6
    return FOAM_HEADER.format(cls="dictionary", obj="couplingProperties") + f"""// Wedge silo, b = {case.b_mm} mm (make_case.py). See README.md.
couplingInterval     {case.coupling_interval};       // DEM steps per CFD step
air                  {'on' if case.air else 'off'};
coarseGrainingFactor {case.s:.10g};   // parcel = s^3 primaries of the lactose PSD
voidFractionFloor    0.3;
gravity              (0 0 -{G});
forces               {{ drag on; pressureGradient on; buoyancy on; }}
drag                 {{ type ErgunGidaspow; }}
voidFraction         {{ {case.void_fraction_dict()} }}
monitors
{{
    outlet   // the orifice faces, z = 0
    {{
        type plane; point (0 0 0); normal (0 0 1);
        boxMin ({-case.b / 2 - eps:.12g} -1 -1e-4); boxMax ({case.b / 2 + eps:.12g} 1 1e-4);
    }}
    above    // the hopper cross-section about one orifice width above it
    {{
        type plane; point (0 0 {zab:.12g}); normal (0 0 1);
        boxMin ({-half_ab - eps:.12g} -1 {zab - 1e-4:.12g}); boxMax ({half_ab + eps:.12g} 1 {zab + 1e-4:.12g});
    }}
}}
discharge
{{
    outletZ        0;
    sinkZ          {-SINK_DEPTH};
    massFlowWindow 0.1;
    depthScale     {case.depth_scale:.10g};   // {DEPTH * 1e3:g} mm / slice {case.slice * 1e3:.4g} mm
}}
dem                  {{ script dem/in.liggghts; }}
airSolverLog         off;
"""


FV_SCHEMES = FOAM_HEADER.format(cls="dictionary", obj="fvSchemes") + """ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default Gauss linear; div(epsPhi,U) Gauss limitedLinearV 1; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
"""

FV_SOLUTION = FOAM_HEADER.format(cls="dictionary", obj="fvSolution") + """solvers
{
    p { solver PCG; preconditioner DIC; tolerance 1e-9; relTol 0; }
    pFinal { $p; }
    "(U|UFinal)" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-10; relTol 0; }
}
PIMPLE { nOuterCorrectors 1; nCorrectors 2; nNonOrthogonalCorrectors 0; momentumPredictor no; pRefCell 0; pRefValue 0; }
"""

U_FIELD = FOAM_HEADER.format(cls="volVectorField", obj="U") + """dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    walls        { type noSlip; }
    top          { type pressureInletOutletVelocity; value uniform (0 0 0); }
    atmosphere   { type pressureInletOutletVelocity; value uniform (0 0 0); }
    frontAndBack { type empty; }
}
"""

P_FIELD = FOAM_HEADER.format(cls="volScalarField", obj="p") + """// air pressure relative to ambient (hydrostatic part excluded) [Pa]
dimensions [1 -1 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    walls        { type zeroGradient; }
    top          { type fixedValue; value uniform 0; }
    atmosphere   { type fixedValue; value uniform 0; }
    frontAndBack { type empty; }
}
"""


read_dump = dem_io.read_dump


def cell_centres(case):
    """Cell centres (x, z) [m]: centroids of the planar cell polygons, as OpenFOAM
    computes them for prisms of a planar polygon."""
    out = []
    for poly in case.cell_polygons():
        a = cx = cz = 0.0
        for j in range(4):
            (x0, z0), (x1, z1) = poly[j], poly[(j + 1) % 4]
            cr = x0 * z1 - x1 * z0
            a += cr
            cx += (x0 + x1) * cr
            cz += (z0 + z1) * cr
        out.append((cx / (3 * a), cz / (3 * a)))
    return out


def cell_neighbours(case):
    """Face neighbours of every cell (cells sharing an edge of their x-z polygons)."""
    owners = {}
    for c, poly in enumerate(case.cell_polygons()):
        for j in range(4):
            p0, p1 = poly[j], poly[(j + 1) % 4]
            key = tuple(sorted((tuple(round(v, 12) for v in p0), tuple(round(v, 12) for v in p1))))
            owners.setdefault(key, []).append(c)
    nbrs = [[] for _ in range(case.n_cells())]
    for cells in owners.values():
        if len(cells) == 2:
            nbrs[cells[0]].append(cells[1])
            nbrs[cells[1]].append(cells[0])
    return nbrs


class VoidFractionMapper:
    """The coupling's void-fraction model in Python (coupling/voidfraction):
    `centre` (all volume to the cell holding the centre) or `gaussian` (truncated
    Gaussian of standard deviation `width` over the cells whose centres are within
    cutoff * width, found by breadth-first search from the centre cell, weights
    g_c V_c normalised; 3-D distances, cell centres at y = slice / 2)."""

    def __init__(self, case):
        self.case = case
        self.vols = case.cell_volumes()
        self.centres = cell_centres(case)
        self.nbrs = cell_neighbours(case)
        self.model = case.void_fraction_model

    def solid_volume(self, atoms):
        c = self.case
        solid = [0.0] * len(self.vols)
        w = c.kernel_width
        rc2 = (c.kernel_cutoff * w) ** 2
        yc = c.slice / 2
        for a in atoms:
            x, y, z = a["x"], a["y"] % c.slice, a["z"]
            vp = math.pi / 6 * (2 * a["radius"]) ** 3
            cell = c.locate_cell(x, z)
            if cell < 0:
                continue
            if self.model == "centre":
                solid[cell] += vp
                continue
            dy2 = (y - yc) ** 2
            cx, cz = self.centres[cell]
            used = {cell: (cx - x) ** 2 + (cz - z) ** 2 + dy2}
            visited = {cell}
            queue = [cell]
            head = 0
            while head < len(queue):
                for nb in self.nbrs[queue[head]]:
                    if nb in visited:
                        continue
                    visited.add(nb)
                    cx, cz = self.centres[nb]
                    d2 = (cx - x) ** 2 + (cz - z) ** 2 + dy2
                    if d2 > rc2:          # beyond the cutoff: not used, not expanded
                        continue
                    used[nb] = d2
                    queue.append(nb)
                head += 1
            d2min = min(used.values())
            g = {k: math.exp(-(d2 - d2min) / (2 * w * w)) * self.vols[k] for k, d2 in used.items()}
            tot = sum(g.values())
            for k, gk in g.items():
                solid[k] += vp * gk / tot
        return solid

    def void_fraction(self, atoms, floor=None):
        eps = [1 - s / v for s, v in zip(self.solid_volume(atoms), self.vols)]
        return [max(floor, e) for e in eps] if floor is not None else eps


def write_initial_void_fraction(case, d, dump):
    """0/voidfraction of a with-air run: the settled bed (the air starts at rest in it,
    so the first air step sees no spurious change of void fraction)."""
    eps = VoidFractionMapper(case).void_fraction(read_dump(dump), floor=0.3)
    body = "\n".join(f"{e:.8g}" for e in eps)
    write(os.path.join(d, "0", "voidfraction"),
          FOAM_HEADER.format(cls="volScalarField", obj="voidfraction")
          + f"""// settled bed before the shutter opens (same model as the coupling, floor 0.3), make_case.py
dimensions [0 0 0 0 0 0 0];
internalField nonuniform List<scalar>
{len(eps)}
(
{body}
);
boundaryField
{{
    walls        {{ type zeroGradient; }}
    top          {{ type zeroGradient; }}
    atmosphere   {{ type zeroGradient; }}
    frontAndBack {{ type empty; }}
}}
""")


def case_from_args(a, air=True):
    return Case(a.size, a.b, air=air, s=a.s, t_end=a.t_end, write_interval=a.write_interval,
                youngs=a.youngs, cohesion=a.cohesion, np=a.np, seed=a.seed, fill=a.fill_height)


def add_case_args(p):
    p.add_argument("--size", default="demo", choices=sorted(SIZES))
    p.add_argument("--b", type=int, default=10, help="orifice width [mm]: 5, 10 or 15")
    p.add_argument("--s", type=float, default=None, help="coarse-graining factor (default: from size)")
    p.add_argument("--t-end", type=float, default=None, help="discharge time [s]")
    p.add_argument("--write-interval", type=float, default=None, help="field output interval [s] (default: the size's)")
    p.add_argument("--youngs", type=float, default=None, help="Young's modulus used [Pa]")
    p.add_argument("--cohesion", default="matched", choices=["matched", "raw", "off"])
    p.add_argument("--fill-height", type=float, default=None, help="settled fill height [m]")
    p.add_argument("--np", type=int, default=2, help="MPI ranks")
    p.add_argument("--seed", type=int, default=1)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    p_fill = sub.add_parser("fill", help="write the DEM-only fill stage")
    add_case_args(p_fill)
    p_fill.add_argument("dir")
    p_run = sub.add_parser("run", help="write a discharge run folder")
    add_case_args(p_run)
    p_run.add_argument("--air", choices=["on", "off"], default="on")
    p_run.add_argument("--fill", required=True, help="the fill folder (its dem/fill.restart)")
    p_run.add_argument("dir")
    p_info = sub.add_parser("info", help="print the parameters")
    add_case_args(p_info)
    a = ap.parse_args()
    if a.cmd == "fill":
        write_fill(case_from_args(a), a.dir)
    elif a.cmd == "run":
        case = case_from_args(a, air=a.air == "on")
        write_run(case, a.dir, a.fill)
        dump = os.path.join(a.fill, "dem", "fill.dump")
        if case.air and os.path.exists(dump):
            write_initial_void_fraction(case, a.dir, dump)
    else:
        json.dump(case_from_args(a).info(), sys.stdout, indent=1)
        print()


if __name__ == "__main__":
    main()
