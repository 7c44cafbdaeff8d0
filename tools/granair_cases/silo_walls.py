"""The wall loads of a silo measured per ring of wall elements (gc.wall_rings on
LIGGGHTS' mesh stress dumps, cases/corn-silo): the ring profiles at rest and while
discharging, the largest load of each wall and where, the shaft at rest against
Janssen (1895), the mean loads of repeated runs as VTK, and the silo's outline in a
figure. Why here: none of it depends on what the grains are or how the hopper is
meshed, only on the rings and which of them make each wall; and the silo in a figure:
its outline, the layers of its fill at the end of a discharge.

    prof, elements = profiles(rings, fill_vtk, files, steady)
    res = maxima(rings, prof, [("hopper", is_hopper), ("shaft", ~is_hopper)])
    res, depth = janssen_shaft(rings, prof, wall, band, surface, D, rho_b, mu_w, k_band, z, mass, at_depth)
    write(walls_csv, elements_csv, rings, prof, depth, elements, wall_of)   a run's profiles and element loads
    rows = mean_profiles(paths)                  the mean +- SD of repeated runs' profiles (their walls_csv)
    mean_vtk(mesh_vtk, tables, path, state, title)
    outline(ax, r_outlet, R, h, top, lw=1)
    layer_slice(fig, ax, fill, final, floor, thickness, half_width)
    layer_panels(png, runs, r_outlet, R, thickness, half_width, title)       several runs' layers side by side
    force_chain_panels(png, runs, r_outlet, R, half_width, title)           their contact networks at rest and at the end
"""
import math

import numpy as np

from . import closed_forms, dem, plots, wall_rings

G = 9.81


def profiles(rings, fill_vtk, files, steady):
    """The ring-mean loads [Pa]: at rest (the fill's dump), the mean of the steady dumps
    of the discharge and the largest instant of all of them, normal and shear:
    ({static|discharge|peak}_{normal|shear}_Pa: per ring}, (the fill's element normal and
    shear, the steady element means normal and shear)). files, steady: [(step, path)]
    of the discharge's dumps (gc.wall_rings.loads)."""
    sn, ss, _ = dem.wall_loads(fill_vtk)
    ring_n, ring_s, el_n, el_s = wall_rings.loads(rings, files, steady)
    i0 = len(files) - len(steady)
    prof = dict(static_normal_Pa=rings.mean(sn), static_shear_Pa=rings.mean(ss),
                discharge_normal_Pa=ring_n[i0:].mean(axis=0), discharge_shear_Pa=ring_s[i0:].mean(axis=0),
                peak_normal_Pa=ring_n.max(axis=0), peak_shear_Pa=ring_s.max(axis=0))
    return prof, (sn, ss, el_n, el_s)


def maxima(rings, prof, walls):
    """For each (name, rings of that wall): the largest ring-mean load at rest and in the
    discharge, its height and its distance along the wall (<name>_<state>_<q>_max_Pa,
    _max_z_m, _max_along_m), and the largest instant (<name>_peak_<q>_Pa)."""
    res = {}
    for wall, sel in walls:
        for kind in ("static", "discharge"):
            for q in ("normal", "shear"):
                val, z, along = rings.maximum(prof[f"{kind}_{q}_Pa"], sel)
                res[f"{wall}_{kind}_{q}_max_Pa"], res[f"{wall}_{kind}_{q}_max_z_m"] = val, z
                res[f"{wall}_{kind}_{q}_max_along_m"] = along
        for q in ("normal", "shear"):
            res[f"{wall}_peak_{q}_Pa"] = rings.maximum(prof[f"peak_{q}_Pa"], sel)[0]
    return res


def janssen_shaft(rings, prof, wall, band, surface, D, rho_b, mu_w, k_band, z, mass, at_depth, g=G):
    """The shaft at rest against Janssen: over the rings `band` (of the shaft `wall`,
    away from the free surface and the transition) the mean measured pressure, Janssen's
    with the lowest and the highest K of k_band and the hydrostatic rho_b g depth (K = 1,
    no wall friction), the measured over Janssen's with the mean K, K_eff and the wall
    friction mobilised by the slice balance with the run's own wall shear
    (gc.wall_rings.slice_balance over the fill's particles z, mass), and the pressure
    interpolated to at_depth below the surface. Returns (that dict, each ring's depth)."""
    depth = surface - rings.z
    lo, hi = (closed_forms.janssen(depth, D, rho_b, mu_w, kk, g)[1] for kk in k_band)
    mid = closed_forms.janssen(depth, D, rho_b, mu_w, sum(k_band) / 2, g)[1]
    meas = prof["static_normal_Pa"]
    k_eff, mu_mob = wall_rings.slice_balance(rings, meas, prof["static_shear_Pa"], band, wall, z, mass,
                                             math.pi * D ** 2 / 4, g)
    some = band.any()
    res = dict(janssen_rings=int(band.sum()),
               hydrostatic_mean_Pa=float((rho_b * g * depth)[band].mean()) if some else math.nan,
               K_eff=k_eff, mu_mobilised=mu_mob,
               shaft_static_mean_Pa=float(meas[band].mean()) if some else math.nan,
               janssen_lo_mean_Pa=float(lo[band].mean()) if some else math.nan,
               janssen_hi_mean_Pa=float(hi[band].mean()) if some else math.nan,
               shaft_static_over_janssen_mid=float(meas[band].mean() / mid[band].mean()) if some else math.nan)
    order = np.argsort(depth[wall])
    res["shaft_pressure_at_janssen_depth_Pa"] = float(np.interp(at_depth, depth[wall][order], meas[wall][order],
                                                                left=math.nan, right=math.nan))
    return res, depth


def write(walls_csv, elements_csv, rings, prof, depth, elements, wall_of):
    """A run's ring profiles (walls_csv: the wall wall_of(ring) names, z_m, along_wall_m,
    depth_m, each profile of `prof` per ring) and its element loads (elements_csv: the
    fill's normal and shear, the steady discharge means: profiles()' second result)."""
    from .series import write_csv, write_rows
    write_rows(walls_csv, [dict(wall=wall_of(i), z_m=rings.z[i], along_wall_m=rings.along[i], depth_m=depth[i],
                                **{q: float(prof[q][i]) for q in prof}) for i in range(rings.n)], fmt="{:.6g}")
    write_csv(elements_csv, [(f"{s}_{q}_Pa", e) for (s, q), e in zip(
        (("static", "normal"), ("static", "shear"), ("discharge", "normal"), ("discharge", "shear")), elements)],
        fmt="{:.5g}")


def mean_profiles(paths):
    """The mean +- SD (n - 1) of repeated runs' ring profiles (the walls_csv of write()), row
    by row: the first run's wall, z_m and along_wall_m, the mean depth_m, each _Pa profile
    and its SD (<name>_sd_Pa)."""
    from .series import mean_sd_columns, read_table
    profs = [read_table(p) for p in paths]
    cols = [c for c in profs[0][0] if c.endswith("_Pa")]
    ms = mean_sd_columns([{c: [row[c] for row in p] for c in cols + ["depth_m"]} for p in profs], cols + ["depth_m"])
    return [dict(wall=row["wall"], z_m=float(row["z_m"]), along_wall_m=float(row["along_wall_m"]), depth_m=ms["depth_m"][i],
                 **{k: ms[c + s][i] for c in cols for k, s in ((c, ""), (c[:-3] + "_sd_Pa", "_sd"))})
            for i, row in enumerate(profs[0])]


def mean_vtk(mesh_vtk, tables, path, state, title):
    """The mean over runs of their per-element loads (tables with <state>_normal_Pa and
    <state>_shear_Pa columns) on the mesh of a `dump mesh/vtk` file, as VTK for ParaView."""
    pts, tri = dem.merge_points(dem.read_mesh_vtk(mesh_vtk))
    dem.write_mesh_vtk(path, pts, tri, {f"{q}_Pa": np.mean([e[f"{state}_{q}_Pa"] for e in tables], axis=0)
                                        for q in ("normal", "shear")}, title)


def outline(ax, r_outlet, R, h, top, lw=1):
    """A silo's section on ax: the hopper from the outlet edge (r_outlet, 0) to the
    shaft (R, h), the shaft to `top`, both sides."""
    for s in (-1, 1):
        ax.plot([s * r_outlet, s * R, s * R], [0, h, top], "k-", lw=lw)


def layer_slice(fig, ax, fill, final, floor, thickness, half_width, colours=("tab:blue", "tab:orange")):
    """The flow pattern as coloured layers: the particles of the slice |y| < half_width at
    the end (`final`, a dump with id x y z radius) drawn at their size (gc.plots.grains),
    coloured alternately by the layer `thickness` thick above `floor` each was in at rest
    (`fill`, id z); set the axes' limits and aspect first."""
    layer = {int(i): int((z - floor) // thickness) for i, z in zip(fill["id"], fill["z"])}
    sel = np.abs(final["y"]) < half_width
    odd = np.array([layer.get(int(i), 0) % 2 for i in final["id"][sel]], dtype=bool)
    plots.grains(fig, ax, final["x"][sel], final["z"][sel], 2 * final["radius"][sel], np.where(odd, colours[1], colours[0]))


def layer_panels(path, runs, r_outlet, R, thickness, half_width, title, dpi=130):
    """The flow pattern of several runs side by side (layer_slice, the outline): runs
    [(panel title, fill dump, final dump, hopper height h)], each panel from the outlet
    to 3 cm above its fill."""
    plt = plots.pyplot()
    fig, axes = plt.subplots(1, len(runs), figsize=(max(4.5, 2.3 * len(runs) + 0.6), 5.6), squeeze=False)
    fig.subplots_adjust(left=0.08, right=0.98, bottom=0.08, top=0.86, wspace=0.25)
    for ax, (label, fill, final, h) in zip(axes[0], runs):
        ax.set(xlim=(-R * 1.05, R * 1.05), ylim=(-0.02, max(fill["z"]) + 0.03), aspect="equal")
        layer_slice(fig, ax, fill, final, h, thickness, half_width)
        outline(ax, r_outlet, R, h, max(fill["z"]) + 0.02)
        ax.set_title(label, fontsize=8)
        ax.set_xlabel("x [m]")
        ax.tick_params(labelsize=7)
    axes[0][0].set_ylabel("z [m]")
    fig.suptitle(title, fontsize=9)
    return plots.save(fig, path, dpi=dpi)


def force_chain_panels(path, runs, r_outlet, R, half_width, title, dpi=130):
    """The contact network (gc.plots.force_chains, the slice |y| < half_width) of several
    runs, a column each: runs [(label, the run's pair dumps in order, dt, hopper height h,
    top of the panel)], the first dump (at rest) above the last."""
    plt = plots.pyplot()
    runs = [(label, [p[0]] + ([p[-1]] if len(p) > 1 else []), dt, h, top) for label, p, dt, h, top in runs]
    rows = max(len(p) for _, p, _, _, _ in runs)
    fig, axes = plt.subplots(rows, len(runs), figsize=(max(4.5, 2.3 * len(runs) + 0.8), 5.2 * rows), squeeze=False)
    for j, (label, paths, dt, h, top) in enumerate(runs):
        for i, p in enumerate(paths):
            (step, c), = dem.read_dumps(p)[:1]
            ax = axes[i][j]
            lc, mean = plots.force_chains(ax, c, half_width)
            outline(ax, r_outlet, R, h, top, lw=0.8)
            ax.set(xlim=(-R * 1.05, R * 1.05), ylim=(-0.02, top), aspect="equal")
            ax.set_title(f"{label}, {'at rest' if step == 0 else f't = {step * dt:.2f} s'}\n"
                         f"mean force {mean * 1e3:.0f} mN", fontsize=8)
            ax.tick_params(labelsize=7)
    fig.colorbar(lc, ax=axes.ravel().tolist(), fraction=0.02, pad=0.01, label="contact force / mean (stronger than the mean)")
    fig.suptitle(title, fontsize=9)
    return plots.save(fig, path, dpi=dpi)
