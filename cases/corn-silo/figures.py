"""The corn silo's figures (post.study): mass flow with the Beverloo band, wall
loads (maximum and where) against the angle, wall-load profiles with Janssen's
band, strain invariants against the angle, the flow pattern as coloured layers."""
import math
import os

import numpy as np

import granair_cases as gc
import parameters as P


def all(out, by_angle, run_root):
    plt = gc.plots.pyplot()
    angles = sorted(by_angle)
    means = [by_angle[a][0] for a in angles]
    mass_flow(plt, out, angles, means)
    wall_loads(plt, out, angles, means)
    profiles(plt, out, angles, means)
    strain(plt, out, angles, means)
    layers(plt, out, angles, by_angle, run_root)
    force_chains(plt, out, angles, by_angle, run_root)


_err = gc.plots.errorbars


def mass_flow(plt, out, angles, means):
    fig, ax = plt.subplots(figsize=(7.5, 4.2))
    rho_b = float(np.nanmean([m["bulk_density_kg_m3"] for m in means]))
    band = (P.beverloo(P.K_RANGE[1], rho_b), P.beverloo(P.K_RANGE[0], rho_b))
    ax.axhspan(*band, color="0.85", label=f"Beverloo, d = {P.d_mass_mean() * 1e3:.1f} mm, k = 1..3, "
               f"rho_b = {rho_b:.0f} kg/m3")
    for a, m in zip(angles, means):
        s = gc.series.read_csv(os.path.join(out, f"a{a}", "mass_flow.csv"))
        ax.plot(s["t"], s["mass_flow_kg_s"], lw=1.2, label=f"{a} deg: W = {m['steady_mass_flow_kg_s']:.3g} kg/s "
                f"(mean of {m['runs']})")
    ax.set(xlabel="t [s]", ylabel="mass flow [kg/s] (0.1 s means)", ylim=(0, None),
           title=f"Corn silo, D = {P.D_SILO * 1e3:.0f} mm, outlet {P.D_OUTLET * 1e3:.0f} mm, {means[0]['grains']} grains")
    ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(out, "mass_flow.png"))


def wall_loads(plt, out, angles, means):
    fig, axes = plt.subplots(4, 2, figsize=(9, 11), sharex=True)
    for row, (wall, q, name) in enumerate((("hopper", "normal", "hopper wall pressure"),
                                          ("hopper", "shear", "hopper wall shear stress"),
                                          ("shaft", "normal", "shaft wall pressure"),
                                          ("shaft", "shear", "shaft wall shear stress"))):
        for state, style in (("static", dict(color="tab:blue")), ("discharge", dict(color="tab:red"))):
            lab = "fill at rest" if state == "static" else f"discharge (mean over t >= {means[0]['steady_from_s']:.2g} s)"
            _err(axes[row][0], angles, means, f"{wall}_{state}_{q}_max_Pa", lab, **style)
            _err(axes[row][1], angles, means, f"{wall}_{state}_{q}_max_z_m", lab, **style)
        _err(axes[row][0], angles, means, f"{wall}_peak_{q}_Pa", "discharge, largest instant", color="tab:red",
             ls=":", mfc="none")
        axes[row][0].set_ylabel(f"max {name} [Pa]", fontsize=8)
        axes[row][1].set_ylabel("height of the max [m]", fontsize=8)
        axes[row][0].set_ylim(0, None)
    axes[0][0].legend(fontsize=7)
    for ax in axes[-1]:
        ax.set_xlabel("hopper angle from the horizontal [deg]")
    fig.suptitle("Maximum ring-mean wall loads and where (mean +- SD of the runs)", fontsize=10)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(out, "wall_loads.png"))


def profiles(plt, out, angles, means):
    fig, axes = plt.subplots(1, 3, figsize=(12, 5.5), sharey=True)
    cmap = plt.get_cmap("viridis")
    for i, (a, m) in enumerate(zip(angles, means)):
        rows = gc.series.read_table(os.path.join(out, f"a{a}", "walls.csv"))
        z = np.array([float(r["z_m"]) for r in rows])
        col = cmap(i / max(1, len(angles) - 1))
        for ax, key in zip(axes, ("static_normal_Pa", "discharge_normal_Pa", "discharge_shear_Pa")):
            ax.plot([float(r[key]) for r in rows], z, color=col, lw=1.2, label=f"{a} deg")
    # Janssen's band for the shaft at rest, from the mean fill of all angles
    surface = float(np.nanmean([m["fill_surface_m"] for m in means]))
    rho_b = float(np.nanmean([m["bulk_density_kg_m3"] for m in means]))
    z = np.linspace(P.hopper_height(max(angles)), surface, 60)
    lo, hi = (gc.closed_forms.janssen(surface - z, P.D_SILO, rho_b, P.MU_PW, k, P.G)[1] for k in P.K_JANSSEN)
    for ax in axes[:2]:
        ax.fill_betweenx(z, lo, hi, color="0.8", label=f"Janssen, K = {P.K_JANSSEN[0]:.2f}-{P.K_JANSSEN[1]:.2f}, "
                         f"mu_w = {P.MU_PW}")
    axes[0].set(xlabel="wall pressure at rest [Pa]", ylabel="height above the outlet [m]", title="fill at rest")
    axes[1].set(xlabel="wall pressure [Pa]", title=f"discharge, mean over t >= {means[0]['steady_from_s']:.2g} s")
    axes[2].set(xlabel="wall shear stress [Pa]", title="discharge, mean")
    for ax in axes:
        ax.set_xlim(0, None)
        ax.set_ylim(-0.01, max(m["fill_surface_m"] for m in means) + 0.03)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle("Ring-mean wall loads (hopper below the kink, shaft above; mean of the runs)", fontsize=10)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(out, "wall_profiles.png"))


def strain(plt, out, angles, means):
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
    for ax, inv in zip(axes, ("I1", "J2")):
        _err(ax, angles, means, f"{inv}_mean", "convex hull: mean of the 10 ms strains", color="tab:blue")
        _err(ax, angles, means, f"{inv}_of_mean", "convex hull: of the mean strain", color="tab:blue", ls="--",
             mfc="none")
        if any(math.isfinite(m["cg_" + inv]) for m in means):
            _err(ax, angles, means, f"cg_{inv}", f"CG velocity field (Gauss w = {P.CG_WIDTH * 1e3:.0f} mm): "
                 "of the mean strain rate x 10 ms", color="tab:green", ls=":")
    axes[0].legend(fontsize=7)
    for ax, lab in zip(axes, ("I1 = tr eps", "J2 = I2 - I1^2/3")):
        ax.set(xlabel="hopper angle from the horizontal [deg]", ylabel=f"{lab} per {P.CV_EVERY:g} s")
        ax.axhline(0, color="0.5", lw=0.6)
        ax.grid(alpha=0.3)
    fig.suptitle(f"Strain over the outlet (cylinder r = {P.CV_RADIUS * 1e3:.0f} mm, h = {P.CV_HEIGHT * 1e3:.0f} mm), "
                 f"convex-hull method; mean over t >= {means[0]['steady_from_s']:.2g} s, +- SD of the runs", fontsize=9)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(out, "strain_invariants.png"))


def layers(plt, out, angles, by_angle, run_root):
    """A vertical slice |y| < d of the first run of every angle at the end of the
    discharge, the grains coloured by the layer they were in at rest (gc.silo_walls)."""
    found = [(a, os.path.join(run_root, f"a{a}-s1", "post")) for a in angles]
    found = [(a, p) for a, p in found if os.path.exists(os.path.join(p, "final.dump"))]
    if found:
        gc.silo_walls.layer_panels(os.path.join(out, "flow_pattern.png"), [
            (f"{a} deg, t = {by_angle[a][1][0]['discharge_s']:.2f} s\n{by_angle[a][0]['pattern']}",
             gc.dem.read_dump(os.path.join(p, "fill.dump")), gc.dem.read_dump(os.path.join(p, "final.dump")),
             P.hopper_height(a)) for a, p in found], P.D_OUTLET / 2, P.D_SILO / 2, P.LAYER, P.d_mass_mean(),
            f"Layers {P.LAYER * 1e3:.0f} mm thick at rest,\nafter the discharge (slice |y| < d)")


def force_chains(plt, out, angles, by_angle, run_root):
    """The contact network of the first run of every angle in a slice |y| < d
    (contact midpoints), at rest and at the end of the discharge: a line from
    centre to centre for every contact stronger than the mean, its width and
    colour the force over the mean force (gc.silo_walls, gc.plots.force_chains)."""
    found = [(a, [p for _, p in gc.dem.numbered(os.path.join(run_root, f"a{a}-s1", "post", "pairs_*.dump"))])
             for a in angles]
    found = [(f"{a} deg", pairs, by_angle[a][1][0]["dt_s"], P.hopper_height(a), by_angle[a][0]["fill_surface_m"] + 0.02)
             for a, pairs in found if pairs]
    if found:
        gc.silo_walls.force_chain_panels(os.path.join(out, "force_chains.png"), found, P.D_OUTLET / 2, P.D_SILO / 2,
                                         P.d_mass_mean(), "Force chains (slice |y| < d, first run of each angle)")
