"""CG fields of the orifice-arch runs (README.md, "CG fields"): granairCG on the
averaging window's snapshots, the profiles and maps of the reference, and the
free-fall arch.

    compute(a, variant, R_d, case, g, dt, st)   granairCG for every kernel of the size (skip if done)
    check(c, a, variant, R_d)                   stresses finite; density integral = particle mass
    summarise(a, wanted)                        arch.csv, arch.png across outlets and kernels

RZ about the silo axis, XZ for the monolayer (averaged over the gap); kernels, their
grids and windows: gc.cg_runs. Per run and kernel (OUT/fields/<run>_<kernel><w/d>.csv)
the fields of gc.cg_runs.reduce (stresses compression positive: P_kinetic = rho <v'^2>/3
> 0; the reference prints sigma_k tension-positive). The arch three ways and its
paraboloid: gc.arch, in ARCH_Z_RANGE x R for r (|x|) <= ARCH_FIT_R x R; alpha's
uncertainty: its standard error over `block_count` consecutive blocks of the snapshots
(each its own granairCG run on a window around the outlet), and the fit's own.
"""
import glob
import math
import os
import shutil

import numpy as np

import granair_cases as gc
import parameters as P

def _axis(variant):
    return "r" if variant == "silo" else "x"


def _window(variant, g, R, h, z_top, r_top=None, z_bottom=None):
    """granairCG window options (gc.cg_runs.aligned): RZ about the axis to r_top (default
    CG_R_OVER_OUTLET R) or XZ over |x| <= r_top and the gap; z from z_bottom (default:
    CG_Z_BELOW d or the arch's range below the floor) to z_top."""
    r_top = r_top if r_top is not None else P.CG_R_OVER_OUTLET * R
    if z_bottom is None:
        z_bottom = -max(P.CG_Z_BELOW * P.D, -P.ARCH_Z_RANGE[0] * R)
    if variant == "silo":
        return gc.cg_runs.aligned("RZ", h, r_top, z_bottom, z_top, g["half_x"], g["half_y"])
    return gc.cg_runs.aligned("XZ", h, r_top, z_bottom, z_top, None, g["half_gap"])


def _inputs(variant, g):
    o = [("particles", "post/cg/particles_*.dump"), ("pairs", "post/cg/pairs_*.dump"), ("walls", "post/cg/walls_*.dump")]
    if variant == "slab":
        o += [("plane-wall", ["plateLo", "y", -g["half_gap"]]), ("plane-wall", ["plateHi", "y", g["half_gap"]])]
    return o


def read_reduced(path, variant):
    return gc.cg_grids.read(path, _axis(variant))


def arch(red, variant, R):
    """z_c(r), the kinetic pressure's maximum along z (gc.arch.kinetic_max in ARCH_Z_RANGE R, r <= ARCH_FIT_R R)."""
    return gc.arch.kinetic_max(red, _axis(variant), R, P.ARCH_Z_RANGE, P.ARCH_FIT_R)


def arch_free_fall(red, variant, R):
    """z_ff = v_z(r, 0)^2 / (2 g) (gc.arch.free_fall), r <= ARCH_FIT_R R."""
    return gc.arch.free_fall(red, _axis(variant), R, P.G, P.ARCH_FIT_R)


def arch_contact(red, variant, R, rho_b):
    """Where tr(sigma_c)/3 falls to CONTACT_VANISH rho_b g R coming down (gc.arch.contact_vanish)."""
    return gc.arch.contact_vanish(red, _axis(variant), R, P.CONTACT_VANISH * rho_b * P.G * R, P.ARCH_Z_RANGE,
                                  P.ARCH_FIT_R)


def compute(a, variant, R_d, case, g, dt, st, keep_dumps=False):
    """granairCG for every kernel of the size on the averaging window's snapshots, the
    blocks for alpha's uncertainty, the enclosing-window mass run; the reduced CSVs, arch
    table and plots of this run in OUT/fields. Skips what exists. Returns dict(cpu_s)."""
    cfg = P.SIZES[a.size]
    name, ax = f"{variant}_R{R_d:g}", _axis(variant)
    out = os.path.join(a.out, "fields")
    os.makedirs(out, exist_ok=True)
    R = R_d * P.D
    t_from, t_to = st["avg_from"] * dt, st["total"] * dt
    rows = []
    have_dumps = os.path.isdir(os.path.join(case, "post", "cg"))
    snaps = [s * dt for s, _ in gc.dem.numbered(os.path.join(case, "post", "cg", "particles_*.dump"))
             if t_from - 1e-9 <= s * dt <= t_to + 1e-9] if have_dumps else []
    cg = gc.cg_runs.Batch(case, [("dt", dt)] + _inputs(variant, g), bool(snaps),
                          f"needs the dumps post/cg/*.dump of t = {t_from:g}-{t_to:g} s, which are gone (removed after "
                          "an earlier CG run?); rerun the run with --keep-dumps", f"orifice-arch {name}")

    def reduced(stem):
        """OUT/fields/<stem>.csv, the kept fields of the run's post/fields/<stem>.csv (made once)."""
        path = os.path.join(out, stem + ".csv")
        if not os.path.exists(path):
            gc.cg_grids.write(path, gc.cg_runs.reduce(gc.cg.read(os.path.join(case, "post", "fields", stem + ".csv")),
                                                      ax), ax)
        return read_reduced(path, variant)

    for kind, w_d in cfg["kernels"]:
        w, h, reach = gc.cg_runs.kernel_grid(kind, w_d * P.D)
        tag = gc.cg_runs.tag(kind, w_d)
        opts = dict(_window(variant, g, R, h, P.CG_Z_TOP * P.D), kernel=kind, width=w, spacing=h)
        opts.update({"from": t_from, "to": t_to})
        cg.run(f"post/fields/{name}_{tag}", opts, f"{tag}, whole window, {len(snaps) or '?'} snapshots")
        red = reduced(f"{name}_{tag}")
        alpha, se_fit = gc.arch.paraboloid(*arch(red, variant, R), R)
        blocks = []
        n_b = cfg["block_count"]
        if n_b >= 2:
            times = snaps or [t_from + k * st["snap"] * dt for k in range(round((t_to - t_from) / (st["snap"] * dt)) + 1)]
            for b, chunk in enumerate(np.array_split(np.array(times), n_b)):
                small = _window(variant, g, R, h, P.ARCH_Z_RANGE[1] * R + P.ARCH_WINDOW_PAD * reach,
                                r_top=R + P.ARCH_WINDOW_PAD * reach,
                                z_bottom=P.ARCH_Z_RANGE[0] * R - P.ARCH_WINDOW_PAD * reach)
                bopts = dict(small, kernel=kind, width=w, spacing=h)
                bopts.update({"from": float(chunk[0]) - 1e-9, "to": float(chunk[-1]) + 1e-9})
                cg.run(f"post/fields/{name}_{tag}_block{b + 1}", bopts, f"{tag}, block {b + 1}/{n_b} ({len(chunk)} snapshots)")
                blocks.append(gc.arch.paraboloid(*arch(reduced(f"{name}_{tag}_block{b + 1}"), variant, R), R)[0])
        rows.append(dict(variant=variant, R_over_d=R_d, kernel=kind, w_over_d=w_d, alpha=alpha,
                         alpha_se_blocks=gc.arch.block_se(blocks), alpha_se_fit=se_fit,
                         arch_points=len(arch(red, variant, R)[0]), blocks=" ".join(f"{x:.4g}" for x in blocks)))
    # the mass check: a Gaussian w = d window enclosing every particle, the last two snapshots
    w, h, reach = gc.cg_runs.kernel_grid("gauss", 1.0 * P.D)
    if variant == "silo":
        enc = gc.cg_runs.enclosing("RZ", reach, g["R_s"], g["z_sink"], g["z_hi"], g["half_x"], g["half_y"])
    else:
        enc = gc.cg_runs.enclosing("XZ", reach, g["width"] / 2, g["z_sink"], g["z_hi"], None, g["half_gap"])
    last = snaps[-2:] if snaps else [t_to]
    mopts = dict(enc, kernel="gauss", width=w, spacing=h)
    mopts.update({"from": last[0] - 1e-9, "to": t_to + 1e-9})
    cg.run(f"post/fields/{name}_mass", mopts, "mass check, enclosing window, last 2 snapshots")
    mass = gc.cg_runs.mass_record(os.path.join(case, "post", "fields", f"{name}_mass.csv"),
                                  os.path.join(case, "log", f"{name}_mass.log"),
                                  None if variant == "silo" else 2 * g["half_gap"])
    gc.series.write_rows(os.path.join(out, f"{name}_arch.csv"), rows, fmt="{:.6g}")
    gc.series.write_keys(os.path.join(out, f"{name}_mass.txt"), list(mass.items()),
                         f"orifice-arch {name}: int rho dV over a window enclosing every particle (Gauss w = d, "
                         "last two snapshots) and the particles' mass in it (granairCG's log)")
    cg.write_costs(os.path.join(out, f"{name}_cost.txt"), [("snapshots", len(snaps))],
                   f"orifice-arch {name}: CPU seconds of the granairCG runs (this pass; total over all passes)")
    plots(a, variant, R_d, out)
    if not keep_dumps and have_dumps:
        shutil.rmtree(os.path.join(case, "post", "cg"))
    return dict(cpu_s=cg.cpu, rows=rows, mass=mass)


def check(c, a, variant, R_d):
    """Every stress of the run's CG outputs finite; the density integral over the enclosing
    window equals the particles' mass within MASS_INTEGRAL_TOL (gc.cg_runs.check)."""
    name, out = f"{variant}_R{R_d:g}", os.path.join(a.out, "fields")
    gc.cg_runs.check(c, name, [p for p in sorted(glob.glob(os.path.join(out, f"{name}_*.csv"))) if not p.endswith("_arch.csv")],
                     gc.series.read_keys(os.path.join(out, f"{name}_mass.txt")), P.MASS_INTEGRAL_TOL)


# ------------------------------------------------------------------ plots
def plots(a, variant, R_d, out):
    """Density and velocity profiles, stress maps of one run (the size's kernels)."""
    plt = gc.plots.pyplot()
    name, ax_name = f"{variant}_R{R_d:g}", _axis(variant)
    kernels = P.SIZES[a.size]["kernels"]
    reds = {(k, w): read_reduced(os.path.join(out, f"{name}_{gc.cg_runs.tag(k, w)}.csv"), variant) for k, w in kernels}
    main = reds[kernels[0]]
    at_d = {key: red for key, red in reds.items() if key[1] == 1.0}     # the profiles: w = d
    style = {("gauss", 1.0): "-", ("heaviside", 1.0): "--", ("gauss", 0.5): ":", ("heaviside", 0.5): "-."}
    # density and velocity profiles (w = d: Gauss solid, Heaviside dashed)
    zs = [z for z in P.DENSITY_PROFILE_Z if z * P.D <= main["z"][-1] + 1e-9]
    gc.profile_plots.profiles_figure(os.path.join(out, f"{name}_density_profiles.png"), at_d, ax_name, ["density"],
                                     ["density / rho_p (solid fraction)"], zs, P.RHO_P, kernels[0], style, P.D, R_d,
                                     f"{name}: density profiles, Gauss (solid) and Heaviside (dashed), w = d", ncol=3)
    gc.profile_plots.profiles_figure(os.path.join(out, f"{name}_velocity_profiles.png"), at_d, ax_name,
                                     [f"velocity_{ax_name}", "velocity_z"], [f"v_{ax_name} / sqrt(g d)", "v_z / sqrt(g d)"],
                                     P.VELOCITY_PROFILE_Z, math.sqrt(P.G * P.D), kernels[0], style, P.D, R_d,
                                     f"{name}: velocity profiles, Gauss (solid) and Heaviside (dashed), w = d",
                                     figsize=(10, 4.2), suptitle=True)
    # stress maps (the first kernel)
    fig, axes = plt.subplots(1, 4, figsize=(13, 4.6), sharey=True)
    gc.profile_plots.maps(fig, axes, main[ax_name] / P.D, main["z"] / P.D, main, [
        ("p_contact", "contact: tr/3 [kPa]"), ("tau_contact", "contact: sqrt(J2) of the deviator [kPa]"),
        ("p_kinetic", "kinetic: tr/3 [kPa]"), ("tau_kinetic", "kinetic: sqrt(J2) [kPa]")], mark=R_d)
    for axx in axes:
        axx.set_xlabel(f"{ax_name} / d")
    axes[0].set_ylabel("z / d")
    r, zc = arch(main, variant, R_d * P.D)
    for axx in axes[2:]:
        axx.plot(r / P.D, zc / P.D, "w.", ms=3)
    fig.suptitle(f"{name}: contact and kinetic stress ({kernels[0][0]}, w = {kernels[0][1]:g} d; "
                 "compression positive; dots: kinetic pressure maximum along z)", fontsize=9)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(out, f"{name}_stress_maps.png"))


def _panel(axx, var, title, ylabel):
    axx.set(xlabel="r / R" if var == "silo" else "|x| / R", ylabel=ylabel, xlim=(0, 1.05), title=title)
    axx.title.set_fontsize(9)
    axx.grid(alpha=0.3)


def summarise(a, wanted):
    """arch.csv (every run and kernel) and arch.png: z_c / R against r / R with the fits,
    one panel per geometry. Returns summary keys."""
    out = os.path.join(a.out, "fields")
    rows = []
    for var, rs in wanted.items():
        for R_d in rs:
            p = os.path.join(out, f"{var}_R{R_d:g}_arch.csv")
            if os.path.exists(p):
                rows += gc.series.read_table(p)
    if not rows:
        return []
    gc.series.write_rows(os.path.join(out, "arch.csv"), rows)
    plt = gc.plots.pyplot()
    variants = [v for v in wanted if any(r["variant"] == v for r in rows)]
    fig, axes = plt.subplots(1, len(variants), figsize=(6.2 * len(variants), 4.6), squeeze=False)
    keys = []
    for axx, var in zip(axes[0], variants):
        n = 0
        for row in rows:
            if row["variant"] != var or row["kernel"] != "gauss":
                continue
            R_d, w_d = float(row["R_over_d"]), float(row["w_over_d"])
            red = read_reduced(os.path.join(out, f"{var}_R{R_d:g}_{gc.cg_runs.tag('gauss', w_d)}.csv"), var)
            alpha, se, col = float(row["alpha"]), float(row["alpha_se_blocks"]), f"C{n}"
            gc.profile_plots.paraboloid(axx, *arch(red, var, R_d * P.D), R_d * P.D, alpha,
                                        f"R = {R_d:g} d, Gauss w = {w_d:g} d: alpha = {alpha:.3f} +- {se:.3f}",
                                        "o" if w_d == 1.0 else "s", col, mfc="none" if w_d != 1.0 else col)
            keys += [(f"{var}_R{R_d:g}_gauss{w_d:g}_alpha", alpha), (f"{var}_R{R_d:g}_gauss{w_d:g}_alpha_se", se)]
            n += 1
        _panel(axx, var, ("3-D silo" if var == "silo" else "monolayer") + ": kinetic pressure maximum z_c(r), "
               "fits alpha (1 - (r/R)^2)", "z_c / R")
        axx.legend(fontsize=7)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(out, "arch.png"))
    return keys + estimates(a, wanted, out)


def estimates(a, wanted, out):
    """The arch three ways for every run with CG fields (Gauss, w = d): the kinetic pressure's
    maximum z_c, the free-fall height of the outlet velocity z_ff, the contact stress's
    fall to CONTACT_VANISH rho_b g R; each fitted with alpha (1 - (r/R)^2).
    fields/arch_estimates.csv, fields/arch_estimates.png; returns summary keys."""
    rows, keys = [], []
    runs = [(var, R_d) for var, rs in wanted.items() for R_d in rs
            if os.path.exists(os.path.join(out, f"{var}_R{R_d:g}_gauss1.csv"))]
    if not runs:
        return []
    plt = gc.plots.pyplot()
    fig, axes = plt.subplots(1, len(runs), figsize=(4.2 * len(runs), 4.0), squeeze=False)
    for axx, (var, R_d) in zip(axes[0], runs):
        R = R_d * P.D
        red = read_reduced(os.path.join(out, f"{var}_R{R_d:g}_gauss1.csv"), var)
        rho_b = float(gc.series.read_keys(os.path.join(a.out, "runs", var, "fill", "summary.txt"))["bulk_density_kg_m3"])
        for (what, label, mk), (r, z) in zip(
                (("kinetic_max", "kinetic pressure maximum", "o"), ("free_fall", "v_z(r,0)^2 / 2g", "^"),
                 ("contact_vanish", f"contact P = {P.CONTACT_VANISH:g} rho_b g R", "s")),
                (arch(red, var, R), arch_free_fall(red, var, R), arch_contact(red, var, R, rho_b))):
            alpha, se = gc.arch.paraboloid(r, z, R)
            rows.append(dict(variant=var, R_over_d=R_d, estimate=what, alpha=alpha, alpha_se_fit=se, points=len(r),
                             z_axis_over_R=float(z[np.argmin(r)] / R) if len(r) else math.nan))
            keys.append((f"{var}_R{R_d:g}_{what}_alpha", alpha))
            gc.profile_plots.paraboloid(axx, r, z, R, alpha, f"{label}: alpha = {alpha:.2f} +- {se:.2f}", mk)
        _panel(axx, var, f"{var} R = {R_d:g} d (Gauss w = d)", "z / R")
        axx.legend(fontsize=6.5)
    fig.suptitle("orifice-arch: the free-fall arch three ways, each fitted with alpha (1 - (r/R)^2)", fontsize=9)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(out, "arch_estimates.png"))
    gc.series.write_rows(os.path.join(out, "arch_estimates.csv"), rows, fmt="{:.6g}")
    return keys
