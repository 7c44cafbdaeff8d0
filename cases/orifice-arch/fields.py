"""CG fields of the orifice-arch runs (README.md, "CG fields"): granairCG on the
averaging window's snapshots, the profiles and maps of the reference, and the
free-fall arch.

    compute(a, variant, R_d, case, g, dt, st)   granairCG for every kernel of the size (skip if done)
    check(c, a, variant, R_d)                   stresses finite; density integral = particle mass
    summarise(a, wanted)                        arch.csv, arch.png across outlets and kernels

Coordinates: RZ about the silo axis (azimuthal averages), XZ for the monolayer
(averaged over the gap). Kernel widths: gauss `--width w` (cutoff 3 w, grid
spacing w), heaviside `--width w` (the ball's radius, spacing w / 2): grid
points at multiples of the spacing in z (and x), at (i + 1/2) spacing in r.

Per run and kernel (OUT/fields/<run>_<kernel><w/d>.csv): density, solid
fraction, velocity (r or x, and z), and for the contact and the kinetic
stress their trace P = tr(sigma)/3 and deviator sqrt(J2) (compression
positive: P_kinetic = rho <v'^2>/3 > 0; the reference prints sigma_k
tension-positive). The free-fall arch: at each r (|x|) below ARCH_FIT_R x R,
z_c is where the kinetic pressure peaks along z within ARCH_Z_RANGE x R
(an interior maximum, refined by the parabola through its neighbours);
z_c / R = alpha (1 - (r / R)^2) by least squares. alpha's uncertainty:
the scatter of alpha over `block_count` consecutive blocks of the snapshots
(each its own granairCG run on a window around the outlet), standard error
of their mean; the fit's own standard error is listed too.
"""
import glob
import math
import os
import re
import shutil

import numpy as np

import granair_cases as gc
import parameters as P

FIELDS = ("density", "volume_fraction")


def _kernel_grid(kind, w_d):
    """(width [m], spacing [m], reach [m]) of a kernel: gauss w (spacing w, cutoff 3 w),
    heaviside radius w (spacing w / 2)."""
    w = w_d * P.D
    return (w, w, 3 * w) if kind == "gauss" else (w, w / 2, w)


def _tag(kind, w_d):
    return f"{kind}{w_d:g}"


def _window(variant, g, R, h, z_top, r_top=None, z_bottom=None):
    """granairCG window options: RZ about the axis to r_top (default CG_R_OVER_OUTLET R) or XZ
    over |x| <= r_top and the gap; z from z_bottom (default: CG_Z_BELOW d or the arch's
    range below the floor) to z_top, grid points on multiples of h (z, x) and at (i + 1/2) h (r)."""
    r_top = r_top if r_top is not None else P.CG_R_OVER_OUTLET * R
    if z_bottom is None:
        z_bottom = -max(P.CG_Z_BELOW * P.D, -P.ARCH_Z_RANGE[0] * R)
    zlo = h * math.floor(z_bottom / h + 1e-9) - h / 2
    zhi = h * math.ceil(z_top / h - 1e-9) + h / 2
    if variant == "silo":
        return {"coordinates": "RZ", "axis": [0.0, 0.0], "rmax": h * math.ceil(r_top / h - 1e-9),
                "min": [-g["half_x"], -g["half_y"], zlo], "max": [g["half_x"], g["half_y"], zhi]}
    x = h * math.ceil(r_top / h - 1e-9) + h / 2
    return {"coordinates": "XZ", "min": [-x, -g["half_gap"], zlo], "max": [x, g["half_gap"], zhi]}


def _inputs(variant, g):
    o = [("particles", "post/cg/particles_*.dump"), ("pairs", "post/cg/pairs_*.dump"), ("walls", "post/cg/walls_*.dump")]
    if variant == "slab":
        o += [("plane-wall", ["plateLo", "y", -g["half_gap"]]), ("plane-wall", ["plateHi", "y", g["half_gap"]])]
    return o


def _reduce(f, variant):
    """The fields the study keeps: coordinates, density, solid fraction, velocity, contact and
    kinetic P and sqrt(J2)."""
    ax = "r" if variant == "silo" else "x"
    pc, tc = gc.cg.invariants(f, "contact_stress")
    pk, tk = gc.cg.invariants(f, "kinetic_stress")
    return {ax: f[ax], "z": f["z"], "density": f["density"], "volume_fraction": f["volume_fraction"],
            f"velocity_{ax}": f[f"velocity_{ax}"], "velocity_z": f["velocity_z"], "p_contact": pc,
            "tau_contact": tc, "p_kinetic": pk, "tau_kinetic": tk}


def read_reduced(path, variant):
    return gc.cg_grids.read(path, "r" if variant == "silo" else "x")


def arch(red, variant, R):
    """z_c(r) of the kinetic pressure's maximum along z at each r (|x|) < ARCH_FIT_R R: (r, z_c)
    arrays (only columns with an interior maximum in ARCH_Z_RANGE R; the monolayer folds |x|)."""
    ax = "r" if variant == "silo" else "x"
    z, pk = red["z"], red["p_kinetic"]
    # the range stops 3 grid spacings below the window's top: a "maximum" there is the window's
    # edge (the monolayer at R = 17 d: P_kinetic grows up to the top of the window)
    top = min(P.ARCH_Z_RANGE[1] * R, z[-1] - 3 * (z[1] - z[0]))
    sel_z = np.nonzero((z >= P.ARCH_Z_RANGE[0] * R - 1e-9) & (z <= top + 1e-9))[0]
    rs, zc = [], []
    for i, r in enumerate(red[ax]):
        if abs(r) > P.ARCH_FIT_R * R:
            continue
        col = pk[i, sel_z]
        if not np.all(np.isfinite(col)):
            continue
        j = int(np.argmax(col))
        if j == 0 or j == len(col) - 1:
            continue
        p0, p1, p2 = col[j - 1], col[j], col[j + 1]
        den = p0 - 2 * p1 + p2
        dz = z[sel_z[1]] - z[sel_z[0]]
        shift = 0.5 * dz * (p0 - p2) / den if den < 0 else 0.0
        rs.append(abs(r))
        zc.append(z[sel_z[j]] + shift)
    return np.array(rs), np.array(zc)


def arch_free_fall(red, variant, R):
    """The free-fall height of the outlet velocity at each r (|x|) <= ARCH_FIT_R R: z_ff =
    v_z(r, 0)^2 / (2 g), the height a particle released at rest falls to cross the
    orifice plane as fast as measured (the classical free-fall arch's definition)."""
    ax = "r" if variant == "silo" else "x"
    j = int(np.argmin(abs(red["z"])))
    sel = (abs(red[ax]) <= P.ARCH_FIT_R * R) & np.isfinite(red["velocity_z"][:, j])
    return abs(red[ax][sel]), red["velocity_z"][sel, j] ** 2 / (2 * P.G)


def arch_contact(red, variant, R, rho_b):
    """Where the contact stress 'vanishes' at each r (|x|) <= ARCH_FIT_R R: coming down from
    ARCH_Z_RANGE[1] R, the first z where tr(sigma_c)/3 falls below CONTACT_VANISH rho_b g R
    (linear between grid points); columns that stay above it to the range's bottom are left out."""
    ax = "r" if variant == "silo" else "x"
    z, pc = red["z"], red["p_contact"]
    ref = P.CONTACT_VANISH * rho_b * P.G * R
    js = [j for j in np.argsort(z)[::-1] if P.ARCH_Z_RANGE[0] * R - 1e-9 <= z[j] <= P.ARCH_Z_RANGE[1] * R + 1e-9]
    rs, zs = [], []
    for i, r in enumerate(red[ax]):
        if abs(r) > P.ARCH_FIT_R * R:
            continue
        for j0, j1 in zip(js, js[1:]):
            if pc[i, j0] >= ref > pc[i, j1]:
                rs.append(abs(r))
                zs.append(z[j0] + (z[j1] - z[j0]) * (pc[i, j0] - ref) / (pc[i, j0] - pc[i, j1]))
                break
    return np.array(rs), np.array(zs)


def fit_alpha(r, zc, R):
    """alpha of z_c / R = alpha (1 - (r / R)^2) (least squares) and its standard error."""
    return gc.fits.through_origin(1 - (r / R) ** 2, zc / R)


def compute(a, variant, R_d, case, g, dt, st, keep_dumps=False):
    """granairCG for every kernel of the size on the averaging window's snapshots, the
    blocks for alpha's uncertainty, the enclosing-window mass run; the reduced CSVs, arch
    table and plots of this run in OUT/fields. Skips what exists. Returns dict(cpu_s)."""
    cfg = P.SIZES[a.size]
    name = f"{variant}_R{R_d:g}"
    out = os.path.join(a.out, "fields")
    os.makedirs(out, exist_ok=True)
    R = R_d * P.D
    t_from, t_to = st["avg_from"] * dt, st["total"] * dt
    cpu, costs, rows = 0.0, [], []
    have_dumps = os.path.isdir(os.path.join(case, "post", "cg"))
    snaps = [s * dt for s, _ in gc.dem.numbered(os.path.join(case, "post", "cg", "particles_*.dump"))
             if t_from - 1e-9 <= s * dt <= t_to + 1e-9] if have_dumps else []
    base = [("dt", dt)] + _inputs(variant, g)

    def run(stem, opts, label):
        nonlocal cpu
        if os.path.exists(os.path.join(case, stem + ".csv")):
            return
        if not snaps:
            raise gc.CaseError(f"{case}: CG {label} needs the dumps post/cg/*.dump of t = {t_from:g}-{t_to:g} s, "
                               "which are gone (removed after an earlier CG run?); rerun the run with --keep-dumps")
        c = gc.cg.run(case, stem, base + list(opts.items()) + [("format", "csv")], os.path.basename(stem))
        cpu += c
        costs.append((label, c))
        print(f"orifice-arch {name}: CG {label}: {c:.0f} CPU-s", flush=True)

    def reduced(stem):
        """OUT/fields/<stem>.csv, the kept fields of the run's post/fields/<stem>.csv (made once)."""
        path = os.path.join(out, stem + ".csv")
        if not os.path.exists(path):
            gc.cg_grids.write(path, _reduce(gc.cg.read(os.path.join(case, "post", "fields", stem + ".csv")), variant),
                              "r" if variant == "silo" else "x")
        return read_reduced(path, variant)

    for kind, w_d in cfg["kernels"]:
        w, h, reach = _kernel_grid(kind, w_d)
        tag = _tag(kind, w_d)
        win = _window(variant, g, R, h, P.CG_Z_TOP * P.D)
        opts = dict(win, kernel=kind, width=w, spacing=h)
        opts.update({"from": t_from, "to": t_to})
        run(f"post/fields/{name}_{tag}", opts, f"{tag}, whole window, {len(snaps) or '?'} snapshots")
        red = reduced(f"{name}_{tag}")
        alpha, se_fit = fit_alpha(*arch(red, variant, R), R)
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
                stem = f"post/fields/{name}_{tag}_block{b + 1}"
                run(stem, bopts, f"{tag}, block {b + 1}/{n_b} ({len(chunk)} snapshots)")
                blocks.append(fit_alpha(*arch(reduced(f"{name}_{tag}_block{b + 1}"), variant, R), R)[0])
        bl = np.array(blocks)
        se_block = float(np.std(bl, ddof=1) / math.sqrt(len(bl))) if len(bl) >= 2 and np.all(np.isfinite(bl)) \
            else math.nan
        rows.append(dict(variant=variant, R_over_d=R_d, kernel=kind, w_over_d=w_d, alpha=alpha,
                         alpha_se_blocks=se_block, alpha_se_fit=se_fit, arch_points=len(arch(red, variant, R)[0]),
                         blocks=" ".join(f"{x:.4g}" for x in blocks)))
    # the mass check: a Gaussian w = d window enclosing every particle, the last two snapshots
    w, h, reach = _kernel_grid("gauss", 1.0)
    top = g["z_hi"] + reach
    if variant == "silo":
        enc = {"coordinates": "RZ", "axis": [0.0, 0.0], "rmax": g["R_s"] + reach,
               "min": [-g["half_x"], -g["half_y"], g["z_sink"] - reach], "max": [g["half_x"], g["half_y"], top]}
    else:
        x = g["width"] / 2 + reach
        enc = {"coordinates": "XZ", "min": [-x, -g["half_gap"], g["z_sink"] - reach], "max": [x, g["half_gap"], top]}
    last = snaps[-2:] if snaps else [t_to]
    mopts = dict(enc, kernel="gauss", width=w, spacing=h)
    mopts.update({"from": last[0] - 1e-9, "to": t_to + 1e-9})
    run(f"post/fields/{name}_mass", mopts, "mass check, enclosing window, last 2 snapshots")
    mass = mass_integral(case, f"post/fields/{name}_mass", variant, g)
    gc.series.write_rows(os.path.join(out, f"{name}_arch.csv"), rows, fmt="{:.6g}")
    gc.series.write_keys(os.path.join(out, f"{name}_mass.txt"), list(mass.items()),
                         f"orifice-arch {name}: int rho dV over a window enclosing every particle (Gauss w = d, "
                         "last two snapshots) and the particles' mass in it (granairCG's log)")
    old = gc.series.read_keys(os.path.join(out, f"{name}_cost.txt")) if os.path.exists(
        os.path.join(out, f"{name}_cost.txt")) else {}
    total = float(old.get("total_cpu_s", 0.0)) + cpu
    gc.series.write_keys(os.path.join(out, f"{name}_cost.txt"),
                         [(re.sub(r"\W+", "_", lab).strip("_") + "_cpu_s", round(c, 1)) for lab, c in costs]
                         + [("snapshots", len(snaps)), ("total_cpu_s", round(total, 1))],
                         f"orifice-arch {name}: CPU seconds of the granairCG runs (this pass; total over all passes)")
    plots(a, variant, R_d, out)
    if not keep_dumps and have_dumps:
        shutil.rmtree(os.path.join(case, "post", "cg"))
    return dict(cpu_s=cpu, rows=rows, mass=mass)


def mass_integral(case, stem, variant, g):
    """int rho dV of a granairCG CSV on its grid (gc.cg_grids.mass: RZ less the midpoint
    rule's end term at the axis; XZ x the gap) and the particle mass in the window
    granairCG logged (the snapshots' mean)."""
    grid, raw = gc.cg_grids.mass(gc.cg.read(os.path.join(case, stem + ".csv")),
                                 None if variant == "silo" else 2 * g["half_gap"])
    logged, particles = gc.cg_grids.logged_mass(os.path.join(case, "log", os.path.basename(stem) + ".log"))
    return dict(grid_mass_kg=grid, grid_mass_midpoint_kg=raw, granairCG_grid_mass_kg=logged,
                particle_mass_kg=particles, relative_difference=grid / particles - 1)


def check(c, a, variant, R_d):
    """Every stress of the run's CG outputs finite; the density integral over the enclosing
    window equals the particles' mass within MASS_INTEGRAL_TOL."""
    name = f"{variant}_R{R_d:g}"
    out = os.path.join(a.out, "fields")
    bad, n = [], 0
    for path in sorted(glob.glob(os.path.join(out, f"{name}_*.csv"))):
        if path.endswith("_arch.csv"):
            continue
        t = gc.series.read_csv(path)
        for k in ("p_contact", "tau_contact", "p_kinetic", "tau_kinetic", "density"):
            n += t[k].size
            if not np.all(np.isfinite(t[k])):
                bad.append(f"{os.path.basename(path)}:{k}")
    c.true(f"{name}: CG stresses and density finite", not bad and n > 0,
           f"{n} values in {len(glob.glob(os.path.join(out, name + '_*.csv'))) - 1} files" + (f"; not: {bad}" if bad else ""),
           "densities and stresses are defined everywhere (zero where empty)")
    m = gc.series.read_keys(os.path.join(out, f"{name}_mass.txt"))
    c.close(f"{name}: CG density integrated over a window enclosing every particle vs their mass [kg]",
            m["grid_mass_kg"], m["particle_mass_kg"], P.MASS_INTEGRAL_TOL,
            "the kernel integrates to 1 and lies inside the window; the grid sum is a midpoint rule (spacing = w), "
            "in RZ less its end term at the axis (mass_integral)")


# ------------------------------------------------------------------ plots
def plots(a, variant, R_d, out):
    """Density and velocity profiles, stress maps of one run (the size's kernels)."""
    plt = gc.plots.pyplot()
    name = f"{variant}_R{R_d:g}"
    ax_name = "r" if variant == "silo" else "x"
    kernels = P.SIZES[a.size]["kernels"]
    reds = {(k, w): read_reduced(os.path.join(out, f"{name}_{_tag(k, w)}.csv"), variant) for k, w in kernels}
    main = reds[kernels[0]]
    rho_p = P.RHO_P
    v0 = math.sqrt(P.G * P.D)
    style = {("gauss", 1.0): "-", ("heaviside", 1.0): "--", ("gauss", 0.5): ":", ("heaviside", 0.5): "-."}
    # density profiles
    zs = [z for z in P.DENSITY_PROFILE_Z if z * P.D <= main["z"][-1] + 1e-9]
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    for i, zd in enumerate(zs):
        for key, red in reds.items():
            if key[1] != 1.0:
                continue
            j = int(np.argmin(abs(red["z"] - zd * P.D)))
            ax.plot(red[ax_name] / P.D, red["density"][:, j] / rho_p, color=f"C{i % 10}", ls=style.get(key, "-"),
                    lw=1.1, label=f"z = {zd:g} d" if key == kernels[0] else None)
    ax.axvline(R_d, color="0.5", lw=0.8)
    ax.set(xlabel=f"{ax_name} / d", ylabel="density / rho_p (solid fraction)",
           title=f"{name}: density profiles, Gauss (solid) and Heaviside (dashed), w = d")
    ax.title.set_fontsize(9)
    ax.legend(fontsize=7, ncol=3)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(out, f"{name}_density_profiles.png"))
    # velocity profiles
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2))
    for i, zd in enumerate(P.VELOCITY_PROFILE_Z):
        for key, red in reds.items():
            if key[1] != 1.0:
                continue
            j = int(np.argmin(abs(red["z"] - zd * P.D)))
            for axx, comp in zip(axes, (f"velocity_{ax_name}", "velocity_z")):
                axx.plot(red[ax_name] / P.D, red[comp][:, j] / v0, color=f"C{i}", ls=style.get(key, "-"), lw=1.1,
                         label=f"z = {zd:g} d" if key == kernels[0] else None)
    for axx, comp in zip(axes, (ax_name, "z")):
        axx.axvline(R_d, color="0.5", lw=0.8)
        axx.set(xlabel=f"{ax_name} / d", ylabel=f"v_{comp} / sqrt(g d)")
        axx.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle(f"{name}: velocity profiles, Gauss (solid) and Heaviside (dashed), w = d", fontsize=9)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(out, f"{name}_velocity_profiles.png"))
    # stress maps (the first kernel)
    fig, axes = plt.subplots(1, 4, figsize=(13, 4.6), sharey=True)
    A, Z = main[ax_name] / P.D, main["z"] / P.D
    for axx, (k, label) in zip(axes, (("p_contact", "contact: tr/3"), ("tau_contact", "contact: sqrt(J2) of the deviator"),
                                      ("p_kinetic", "kinetic: tr/3"), ("tau_kinetic", "kinetic: sqrt(J2)"))):
        m = axx.pcolormesh(A, Z, main[k].T / 1e3, shading="nearest", cmap="viridis")
        axx.set(xlabel=f"{ax_name} / d", title=f"{label} [kPa]", aspect="equal")
        axx.title.set_fontsize(8)
        axx.axvline(R_d, color="w", lw=0.6, ls=":")
        fig.colorbar(m, ax=axx, fraction=0.05, pad=0.02)
    axes[0].set_ylabel("z / d")
    r, zc = arch(main, variant, R_d * P.D)
    for axx in axes[2:]:
        axx.plot(r / P.D, zc / P.D, "w.", ms=3)
    fig.suptitle(f"{name}: contact and kinetic stress ({kernels[0][0]}, w = {kernels[0][1]:g} d; "
                 "compression positive; dots: kinetic pressure maximum along z)", fontsize=9)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(out, f"{name}_stress_maps.png"))


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
            red = read_reduced(os.path.join(out, f"{var}_R{R_d:g}_{_tag('gauss', w_d)}.csv"), var)
            r, zc = arch(red, var, R_d * P.D)
            alpha = float(row["alpha"])
            se = float(row["alpha_se_blocks"])
            col, mk = f"C{n}", "o" if w_d == 1.0 else "s"
            axx.plot(r / (R_d * P.D), zc / (R_d * P.D), mk, color=col, ms=4, mfc="none" if w_d != 1.0 else col,
                     label=f"R = {R_d:g} d, Gauss w = {w_d:g} d: alpha = {alpha:.3f} +- {se:.3f}")
            x = np.linspace(0, 1, 50)
            axx.plot(x, alpha * (1 - x ** 2), color=col, lw=1)
            keys.append((f"{var}_R{R_d:g}_gauss{w_d:g}_alpha", alpha))
            keys.append((f"{var}_R{R_d:g}_gauss{w_d:g}_alpha_se", se))
            n += 1
        axx.set(xlabel="r / R" if var == "silo" else "|x| / R", ylabel="z_c / R", xlim=(0, 1.05),
                title=("3-D silo" if var == "silo" else "monolayer") + ": kinetic pressure maximum z_c(r), "
                "fits alpha (1 - (r/R)^2)")
        axx.title.set_fontsize(9)
        axx.grid(alpha=0.3)
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
            alpha, se = fit_alpha(r, z, R)
            rows.append(dict(variant=var, R_over_d=R_d, estimate=what, alpha=alpha, alpha_se_fit=se, points=len(r),
                             z_axis_over_R=float(z[np.argmin(r)] / R) if len(r) else math.nan))
            keys.append((f"{var}_R{R_d:g}_{what}_alpha", alpha))
            line = axx.plot(r / R, z / R, mk, ms=4, label=f"{label}: alpha = {alpha:.2f} +- {se:.2f}")[0]
            x = np.linspace(0, 1, 50)
            axx.plot(x, alpha * (1 - x ** 2), color=line.get_color(), lw=1)
        axx.set(xlabel="r / R" if var == "silo" else "|x| / R", ylabel="z / R", xlim=(0, 1.05),
                title=f"{var} R = {R_d:g} d (Gauss w = d)")
        axx.title.set_fontsize(9)
        axx.grid(alpha=0.3)
        axx.legend(fontsize=6.5)
    fig.suptitle("orifice-arch: the free-fall arch three ways, each fitted with alpha (1 - (r/R)^2)", fontsize=9)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(out, "arch_estimates.png"))
    gc.series.write_rows(os.path.join(out, "arch_estimates.csv"), rows, fmt="{:.6g}")
    return keys
