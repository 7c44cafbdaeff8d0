"""CG fields of a wedge-silo run at the orifice (README, "CG fields at the orifice").

From the particle and contact dumps a run writes at its field times
(dem/post/cg, switched by cg_every in dem/in.liggghts), granairCG computes
solid fraction, velocity and pressure (contact + kinetic stress, walls
included) on an x-z grid averaged over the periodic depth, Gaussian kernel of
width w = one mean parcel diameter, over a window around the orifice; the
picture puts them next to the air's void fraction and pressure of the same
time. Checked per field time (`checks`):

  - the CG solid volume in the window equals the parcels' volume weighted by
    the share of each one's kernel inside the window (1e-3: the grid's midpoint
    rule on a kernel cut at 3 w), and the volume of the parcels whose centres
    are inside, within the larger of what the kernel carries out of and into
    the window across its top edge (the only edge that cuts the bed);
  - in the dense bulk (at least 3 w from the walls and the window's top, above
    the orifice), the mean CG solid fraction equals the mean 1 - void fraction
    of the air mesh's cells there within P.CG_VS_AIR_BULK: the same parcels,
    two volume-conserving kernels of different widths (w and 1.6 w, the air's
    cut at 4.8 w and renormalised at the walls).

    run(d, v, res, name) -> [dict per time], picture(...), checks(c, name, rows)
"""
import math
import os

import numpy as np

import granair_cases as gc
import parameters as P

CUT = 3.0      # granairCG's default Gaussian cutoff, in widths


def window(v):
    """The CG window [m]: wall to wall in x plus the kernel's reach (no parcel's kernel is cut
    at the sides), from below the sink (none below it) to max(3 b, 30 mm) above the orifice;
    y the whole periodic slice (the averaged direction). And the kernel width w."""
    w = v["D_PARCEL"]
    reach = CUT * w + v["S"] * P.D_MAX_PSD
    lo = (-P.WIDTH / 2 - reach, 0.0, -P.SINK_DEPTH - reach)
    hi = (P.WIDTH / 2 + reach, v["SLICE"], max(3 * 2 * v["B"], 0.03))
    return lo, hi, w


def step_of(v, t):
    return int(round(t / v["DEM_DT"]))


def compute(d, v, t, stem, average=None):
    """granairCG on the one snapshot at time t; returns the CSV path (None without dumps).
    average=(t0, t1): instead the uniform time average of every snapshot in [t0, t1] (t unused)."""
    cg = os.path.join(d, "dem", "post", "cg")
    if average:
        files = {k: os.path.join(cg, f"{k}_*.dump") for k in ("particles", "pairs", "walls")}
        when = [("time-average", "uniform"), ("from", f"{average[0] - 1e-9:.9g}"), ("to", f"{average[1] + 1e-9:.9g}")]
        log = f"granairCG_t{average[0]:g}-{average[1]:g}"
    else:
        step = step_of(v, t)
        files = {k: os.path.join(cg, f"{k}_{step}.dump") for k in ("particles", "pairs", "walls")}
        if not all(os.path.exists(f) for f in files.values()):
            return None
        when, log = [], f"granairCG_t{t:g}"
    lo, hi, w = window(v)
    gc.cg.run(d, stem, [("particles", files["particles"]), ("pairs", files["pairs"]), ("walls", files["walls"]),
                        ("plane-wall", ["shaftL", "x", f"{-P.WIDTH / 2:.12g}"]),
                        ("plane-wall", ["shaftR", "x", f"{P.WIDTH / 2:.12g}"]),
                        ("dt", f"{v['DEM_DT']:.12g}"), ("coordinates", "XZ"), ("kernel", "gauss"),
                        ("width", f"{w:.9g}"), ("spacing", f"{w / 2:.9g}"), ("min", [f"{x:.9g}" for x in lo]),
                        ("max", [f"{x:.9g}" for x in hi]), ("threads", 1), ("format", ["csv", "vti"])] + when,
              log=log)
    return stem + ".csv"


def read_grid(csv):
    """The CSV of an XZ run: the x and z values and the fields as [iz, ix]."""
    f = gc.cg.read(csv, order=("z", "x"))
    return f["x"], f["z"], f


def wall_distance(v, x, z):
    """Distance [m] of points above the orifice plane to the nearest silo wall (hopper or shaft)."""
    th = v["THETA"]
    half = np.where(z < v["HH"], v["B"] + z * math.tan(th), P.WIDTH / 2)
    return np.where(z < v["HH"], (half - np.abs(x)) * math.cos(th), half - np.abs(x))


def analyse(d, v, t, csv):
    """The numbers of one time: CG solid volume in the window against the parcels', and the
    bulk CG solid fraction against 1 - the air mesh's void fraction."""
    xs, zs, g = read_grid(csv)
    lo, hi, w = window(v)
    phi = g["volume_fraction"]
    area = (xs[1] - xs[0]) * (zs[1] - zs[0])
    cg_volume = float(np.nansum(phi) * area * v["SLICE"])          # per the slice: x-z integral x depth
    p = gc.dem.read_dump(os.path.join(d, "dem", "post", "cg", f"particles_{step_of(v, t)}.dump"))
    vol = p["mass"] / P.RHO_P
    share = gc.cg.kernel_share_below((hi[2] - p["z"]) / w, CUT)
    inside = p["z"] < hi[2]
    band = np.abs(p["z"] - hi[2]) < CUT * w
    out = dict(t=t, csv=csv, cg_volume_m3=cg_volume, kernel_weighted_m3=float(np.sum(vol * share)),
               centres_inside_m3=float(np.sum(vol[inside])),
               # what the kernel carries across the top edge, out of the window and into it: their
               # difference (the CG volume less the centred parcels') is at most the larger of the two
               edge_bound_m3=float(max(np.sum((vol * (1 - share))[band & inside]), np.sum((vol * share)[band & ~inside]))),
               parcels_inside=int(np.sum(inside)))
    # bulk: air cells 3 w from the walls, above z = b and 3 w below the window's top, dense
    cx, cz = (gc.foam.read_field(os.path.join(d, "0", f)) for f in ("Cx", "Cz"))
    td = gc.foam.time_dir(d, t)
    eps = gc.foam.read_field(os.path.join(td, "voidfraction"), len(cx))
    cg_at = gc.cg.bilinear(zs, xs, phi, cz, cx)
    bulk = ((cz > 2 * v["B"]) & (cz < hi[2] - CUT * w) & (wall_distance(v, cx, cz) > CUT * w)
            & (1 - eps > P.CG_BULK_MIN_SOLID) & np.isfinite(cg_at))
    out.update(bulk_cells=int(bulk.sum()), bulk_cg_solid=float(np.mean(cg_at[bulk])) if bulk.any() else math.nan,
               bulk_air_solid=float(np.mean(1 - eps[bulk])) if bulk.any() else math.nan,
               bulk_rms_cell_difference=float(np.sqrt(np.mean((cg_at[bulk] - (1 - eps[bulk])) ** 2)))
               if bulk.any() else math.nan)
    return out


def cfd_fields(d, v, t):
    """The air mesh's fields at time t: cell centres, 1 - void fraction, the solid velocity Us
    (the drag-weighted parcel velocity), and with air the air's p, grad(p) and U."""
    cx, cz = (gc.foam.read_field(os.path.join(d, "0", f)) for f in ("Cx", "Cz"))
    td, n = gc.foam.time_dir(d, t), len(cx)
    f = dict(x=cx, z=cz, solid=1 - gc.foam.read_field(os.path.join(td, "voidfraction"), n))
    if os.path.exists(os.path.join(td, "Us")):      # not in the start time's folder
        f["Us_z"] = gc.foam.read_field(os.path.join(td, "Us"), n)[:, 2]
    if v["AIR"] == "on":
        f.update(p=gc.foam.read_field(os.path.join(td, "p"), n), U_z=gc.foam.read_field(os.path.join(td, "U"), n)[:, 2],
                 dpdz=gc.foam.read_field(os.path.join(td, "grad(p)"), n)[:, 2])
    return f


CFD_KEYS = ("solid", "Us_z", "p", "dpdz", "U_z")


def cfd_axis(f):
    """The CFD fields on the centre line: per row of cells the cell nearest x = 0, by z."""
    rows = np.round(f["z"], 7)
    col = np.array([i[np.argmin(np.abs(f["x"][i]))] for z in np.unique(rows) for i in [np.flatnonzero(rows == z)]])
    col = col[np.argsort(f["z"][col])]
    return f["z"][col], {k: f[k][col] for k in CFD_KEYS if k in f}


def cfd_orifice(f, b2):
    """The CFD fields on the orifice plane z = 0 across the slot |x| < b2, by x: linear in z
    between the row of cells just below it and the first row of the hopper above it (its
    cells stand on the same faces, in the same order); dp/dz the face gradient (p above -
    p below) / their distance, as the outlet monitor's."""
    zr = np.round(f["z"], 7)
    zs = np.unique(zr)
    below, above = zs[zs < 0].max(), zs[zs > 0].min()
    r = [np.flatnonzero((zr == below) & (np.abs(f["x"]) < b2)), np.flatnonzero(zr == above)]
    r = [i[np.argsort(f["x"][i])] for i in r]
    if len(r[0]) != len(r[1]):
        raise gc.CaseError(f"the air mesh has {len(r[0])} cells across the slot below the orifice and "
                           f"{len(r[1])} above it, expected the same")
    wt = -below / (above - below)
    out = {k: (1 - wt) * f[k][r[0]] + wt * f[k][r[1]] for k in CFD_KEYS if k in f}
    if "p" in f:
        out["dpdz"] = (f["p"][r[1]] - f["p"][r[0]]) / (above - below)
    return f["x"][r[0]], out


# the CFD side's columns in profiles() and orifice_numbers()
CFD_NAMES = dict(solid="cfd_solid_fraction", Us_z="cfd_solid_velocity_z", p="air_pressure", dpdz="air_dpdz",
                 U_z="air_velocity_z")


def profiles(v, grid, f):
    """The CG fields and the CFD fields on the centre line x = 0 (by z) and across the orifice
    plane z = 0 (by x), the CFD's interpolated linearly onto the CG grid's points:
    {"axis": (z, columns), "orifice": (x, columns)}."""
    xs, zs, g = grid
    cg = dict(cg_solid_fraction=g["volume_fraction"], cg_velocity_z=g["velocity_z"], cg_pressure=g["pressure"])
    out = {}
    for kind, coord, pick, (at, vals) in (("axis", zs, lambda a: a[:, np.argmin(np.abs(xs))], cfd_axis(f)),
                                          ("orifice", xs, lambda a: a[np.argmin(np.abs(zs)), :], cfd_orifice(f, v["B"]))):
        cols = {k: pick(a) for k, a in cg.items()}
        cols.update({CFD_NAMES[k]: np.interp(coord, at, y, left=np.nan, right=np.nan) for k, y in vals.items()})
        out[kind] = (coord, cols)
    return out


def orifice_numbers(v, grid, f):
    """Means over the slot |x| < b/2 on the orifice plane z = 0: the CG fields (the grid's row
    nearest z = 0) and the CFD's (its cells across the slot are of equal width); and the CG
    mass flow through the plane, rho_p phi v_z integrated across at the full depth [kg/s]."""
    xs, zs, g = grid
    k, slot = np.argmin(np.abs(zs)), np.abs(xs) < v["B"]
    m = dict(cg_solid_fraction=g["volume_fraction"][k, slot], cg_velocity_z=g["velocity_z"][k, slot],
             cg_pressure=g["pressure"][k, slot])
    m = {key: float(np.nanmean(y)) for key, y in m.items()}
    m.update({CFD_NAMES[key]: float(np.mean(y)) for key, y in cfd_orifice(f, v["B"])[1].items()})
    m["cg_mass_flow_kg_s"] = float(-np.sum(g["momentum_density_z"][k, :]) * (xs[1] - xs[0]) * P.DEPTH)
    return m


def run(d, v, res, name, times):
    """CG fields of run folder d at the given times (those with dumps and parcels): granairCG,
    analysis, profiles (res/<name>_cg_axis.csv, _cg_orifice.csv), the picture. Returns
    (rows, png path or None)."""
    os.makedirs(os.path.join(res, "cg"), exist_ok=True)
    times = [t for t in times if has_parcels(d, v, t)]
    if v["AIR"] == "on" and times:      # the air's pressure gradient at the field times
        gc.runner.run(["postProcess", "-func", "grad(p)", "-time", ",".join(f"{t:g}" for t in times)], d, "grad_p")
    rows, tables = [], {"axis": [], "orifice": []}
    for t in times:
        csv = compute(d, v, t, os.path.abspath(os.path.join(res, "cg", f"{name}_t{t:g}")))
        if not csv:
            continue
        r = analyse(d, v, t, csv)
        grid, f = read_grid(csv), cfd_fields(d, v, t)
        r["profiles"] = profiles(v, grid, f)
        r["orifice"] = orifice_numbers(v, grid, f)
        rows.append(r)
        for kind, (coord, cols) in r["profiles"].items():
            tables[kind].append((t, coord, cols))
    for kind, key in (("axis", "z"), ("orifice", "x")):
        if tables[kind]:
            keys = list(dict.fromkeys(k for _, _, cols in tables[kind] for k in cols))   # Us not at t = 0
            gc.series.write_csv(os.path.join(res, f"{name}_cg_{kind}.csv"),
                                [("t", np.concatenate([np.full(len(c), t) for t, c, _ in tables[kind]])),
                                 (f"{key}_m", np.concatenate([c for _, c, _ in tables[kind]]))]
                                + [(k, np.concatenate([cols.get(k, np.full(len(c), np.nan)) for _, c, cols in tables[kind]]))
                                   for k in keys])
    shown = rows if len(rows) <= 3 else [rows[i] for i in sorted({0, len(rows) // 2, len(rows) - 1})]
    png = picture(d, v, shown, os.path.join(res, f"{name}_cg_orifice.png"), name) if rows else None
    return rows, png


def has_parcels(d, v, t):
    path = os.path.join(d, "dem", "post", "cg", f"particles_{step_of(v, t)}.dump")
    return os.path.exists(path) and len(gc.dem.read_dump(path)["x"]) > 0


def picture(d, v, rows, path, name):
    """Two rows per time. Maps: CG solid fraction, 1 - air void fraction, CG |velocity|, CG
    pressure, air pressure, air dp/dz. Profiles on the centre line x = 0 against z: solid
    fraction, pressure (CG, air), vertical velocity (CG, CFD solid, air), air dp/dz; across the
    orifice plane against x: solid fraction, vertical velocity."""
    plt = gc.plots.pyplot()
    cells = [c * 1e3 for c in gc.foam.plane_cells(d)]
    lo, hi, w = window(v)
    xlim, zlim = (-P.WIDTH / 2 * 1e3, P.WIDTH / 2 * 1e3), (-P.SINK_DEPTH * 1e3, hi[2] * 1e3)
    grids = [read_grid(r["csv"]) for r in rows]
    fields = [cfd_fields(d, v, r["t"]) for r in rows]
    speed = [np.where(g["volume_fraction"] > 0.05, np.hypot(g["velocity_x"], g["velocity_z"]), np.nan) for _, _, g in grids]
    vmax = max(float(np.nanmax(sp)) if np.isfinite(sp).any() else 0.1 for sp in speed)
    pmax = max(float(np.nanpercentile(g["pressure"], 99.5)) for _, _, g in grids)
    pm = max([float(np.max(np.abs(f["p"]))) for f in fields if "p" in f] + [1e-6])
    gm = max([float(np.percentile(np.abs(f["dpdz"]), 99)) for f in fields if "dpdz" in f] + [1e-6])
    ncol = 6
    fig, axes = plt.subplots(2 * len(rows), ncol, squeeze=False, figsize=(2.45 * ncol, 2.5 * 2 * len(rows) + 0.8))
    fig.suptitle(f"{name}: CG fields (granairCG, x-z over the slice, Gauss w = parcel d = {w * 1e3:.2f} mm) next to "
                 f"the air mesh's fields (kernel 1.6 d); profiles: centre line x = 0 and orifice plane z = 0",
                 fontsize=9)
    maps = ["CG solid fraction", "1 - air void fraction", "CG |velocity| [m/s]", "CG pressure [Pa]",
            "air p - ambient [Pa]", "air dp/dz [Pa/m]"]
    for i, (r, (xs, zs, g), f, sp) in enumerate(zip(rows, grids, fields, speed)):
        for j, label in enumerate(maps):
            ax = axes[2 * i][j]
            ax.set(xlim=xlim, ylim=zlim, aspect="equal")
            ax.tick_params(labelsize=6)
            ax.set_title(f"{label}, t = {r['t']:g} s", fontsize=7)
            if j in (1, 4, 5):
                key = {1: "solid", 4: "p", 5: "dpdz"}[j]
                if key not in f:
                    ax.text(0.5, 0.5, "DEM only: no air", ha="center", va="center", transform=ax.transAxes, fontsize=7)
                    continue
                lim, cmap = {1: ((0, 0.65), "viridis"), 4: ((-pm, pm), "RdBu_r"), 5: ((-gm, gm), "PuOr_r")}[j]
                art = gc.plots.cell_map(ax, cells, f[key], cmap, lim)
            else:
                a, cmap, lim = {0: (g["volume_fraction"], "viridis", (0, 0.65)), 2: (sp, "magma", (0, vmax)),
                                3: (g["pressure"], "cividis", (0, pmax))}[j]
                art = gc.plots.grid_map(ax, xs, zs, a, cmap, lim)
            fig.colorbar(art, ax=ax, fraction=0.05, pad=0.02).ax.tick_params(labelsize=6)
            if j == 0:
                ax.set_ylabel("z [mm]", fontsize=7)
        z, ca = r["profiles"]["axis"]
        x, co = r["profiles"]["orifice"]
        z, x = z * 1e3, x * 1e3
        panels = [
            ("centre line: solid fraction", z, [("cg_solid_fraction", "CG"), ("cfd_solid_fraction", "1 - air eps")], ca),
            ("centre line: pressure [Pa]", z, [("cg_pressure", "CG granular P"), ("air_pressure", "air p")], ca),
            ("centre line: v_z [m/s]", z, [("cg_velocity_z", "CG"), ("cfd_solid_velocity_z", "CFD Us"),
                                          ("air_velocity_z", "air U")], ca),
            ("centre line: air dp/dz [Pa/m]", z, [("air_dpdz", "air dp/dz")], ca),
            ("orifice z = 0: solid fraction", x, [("cg_solid_fraction", "CG"), ("cfd_solid_fraction", "1 - air eps")], co),
            ("orifice z = 0: v_z [m/s]", x, [("cg_velocity_z", "CG"), ("cfd_solid_velocity_z", "CFD Us"),
                                            ("air_velocity_z", "air U")], co)]
        for j, (title, coord, lines, cols) in enumerate(panels):
            ax = axes[2 * i + 1][j]
            for k, label in lines:
                if k in cols and np.isfinite(cols[k]).any():
                    y = np.where(np.isfinite(cols[k]), cols[k], np.nan)
                    ax.plot(*((coord, y) if j >= 4 else (y, coord)), lw=1.2, label=label)
            if j < 4:
                ax.set(ylim=zlim, ylabel="z [mm]" if j == 0 else None)
                ax.axhline(0, color="k", lw=0.5)
            else:
                ax.set(xlim=(-v["B"] * 1e3 * 2, v["B"] * 1e3 * 2), xlabel="x [mm]")
                for sgn in (-1, 1):
                    ax.axvline(sgn * v["B"] * 1e3, color="k", lw=0.5, ls="--")
            ax.set_title(f"{title}, t = {r['t']:g} s", fontsize=7)
            ax.tick_params(labelsize=6)
            ax.grid(alpha=0.3)
            if any(not ln.get_label().startswith("_") for ln in ax.lines):
                ax.legend(fontsize=5.5)
    fig.tight_layout()
    return gc.plots.save(fig, path, dpi=90)


def checks(c, name, rows):
    for r in rows:
        t = f"t = {r['t']:g} s"
        c.close(f"{name}: CG solid volume in the orifice window vs the parcels' kernel-weighted volume, {t}",
                r["cg_volume_m3"], r["kernel_weighted_m3"], P.CG_VOLUME_QUADRATURE,
                "the same kernel integrated exactly per parcel; the grid's midpoint rule (spacing w/2) on a kernel "
                "cut at 3 w with a 1 % step, dumps of 6 digits")
        c.near(f"{name}: CG solid volume vs the volume of the {r['parcels_inside']} parcels centred in the window, {t}",
               r["cg_volume_m3"] * 1e9, r["centres_inside_m3"] * 1e9,
               (r["edge_bound_m3"] + P.CG_VOLUME_QUADRATURE * r["kernel_weighted_m3"]) * 1e9,
               "tolerance: the larger of what the kernel carries out of the window and into it across its top "
               "edge, the only edge in the bed (their difference is the mismatch), plus the grid's quadrature "
               "error as above (what is left when no parcel is near the edge)", " mm3")
        if r["bulk_cells"]:
            c.close(f"{name}: bulk CG solid fraction vs 1 - air void fraction, {r['bulk_cells']} cells, {t}",
                    r["bulk_cg_solid"], r["bulk_air_solid"], P.CG_VS_AIR_BULK,
                    "same parcels, two volume-conserving kernels (w and 1.6 w, the air's renormalised at the walls); "
                    "mean over cells 3 w from walls and window edge")
