#!/usr/bin/python3
"""mu(I) and phi(I) of the cases' DEM materials from a DEM shear cell (README.md).

    study.py [--material wedge-silo mcc-hopper] [--I 0.3 0.1 ...] [--jobs 2] [--quick]
             [--out DIR] [--stage all|runs|post] [--setup-only] [--check]

Per material (OUT/runs/<material>/): a periodic cell (x, y) between two rough
walls of frozen parcels; compaction under the confining pressure (compact/),
then plane shear at the top-wall speeds of the target inertial numbers, from
the fastest to the slowest, each from the restart of the one before (I<target>/).
A finished run (its restart written) is not run again: an interrupted sweep
continues where it stopped. The materials' sweeps run side by side (--jobs).

Post (per run): granairCG profiles across the gap (coordinates Z, Gaussian
kernel), time-averaged over the last AVERAGE_FRACTION of the run and per
snapshot; in the bulk (BAND parcel diameters from either wall) the shear rate
(slope of V_x), the pressure P = tr(sigma)/3, tau = sqrt(J2), sigma_xz,
sigma_zz, phi, hence I = gammaDot d / sqrt(P / rho_p) and mu = |sigma_xz| / P
(also sqrt(J2) / P and sigma_xz / sigma_zz), with standard errors from 5
blocks of snapshots. Fits over the dense steady runs (parameters.py FIT_I_MAX,
FIT_I_SE): mu(I) = mu_s + (mu_2 - mu_s) / (I0 / I + 1) (Jop et al. 2006),
phi(I) = phi_max - (phi_max - phi_min) I, with their covariance. OUT: <material>/points.csv, profiles.png, muI (the
entries for a rheology block), rheology (a complete block), calibration.json,
mu_I.png, phi_I.png.

Checked (--check exits 1 on a failure): the CG bulk shear and normal stress
against the top wall's traction (force / area), sigma_xz uniform across the
bulk, mu at the lowest I in the quasi-static band of frictional spheres
(parameters.py, with sources).
"""
import json
import math
import os
import random
import time

import numpy as np

import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
NAMES = {"wedge-silo": "wedge", "mcc-hopper": "mcc"}
BLOCKS = 5


def cell(name, a):
    """The numbers of one material's cell, shared by all its runs."""
    m = P.MATERIALS[name]
    d = m["d_mean"]
    t_r = gc.dem.rayleigh_time(m["d_min"] / 2, m["youngs"], m["nu"], m["rho"])
    lx, ly, gap = a.cell_x * d, a.cell_x * d, a.gap * d
    coh = m["cohesion"] > 0
    return dict(MATERIAL=m["title"], SOURCE=m["source"], D=d, SKIN=0.3 * m["d_max"], YOUNGS=m["youngs"], NU=m["nu"],
                E=m["restitution"], MU=m["friction"], RHO=m["rho"], DEM_DT=m["rayleigh_fraction"] * t_r,
                RAYLEIGH_S=t_r, LX=lx, LY=ly, GAP=gap, AREA=lx * ly, PRESSURE=a.pressure,
                SOFT_PARTICLES="soft_particles  yes             # LIGGGHTS asks for this below E = 5e6 Pa"
                if m["youngs"] < 5e6 else "# (E >= 5e6 Pa: no soft_particles needed)",
                COHESION_FIX=("fix m5 all property/global cohesionEnergyDensity peratomtypepair 2 "
                              + " ".join([f"{m['cohesion']:.6g}"] * 4)) if coh else "# (no cohesion)",
                COHESION_MODEL=" cohesion sjkr" if coh else "",
                COHESION_NOTE=", SJKR cohesion" if coh else ", no cohesion",
                Z_MID=(P.WALL_THICKNESS + 0.5 * a.gap) * d, CG_DUMPS=os.path.join(ROOT, "dem-side", "liggghts",
                                                                                  "cg-dumps.liggghts"),
                COMPACT_VT=P.COMPACT_VT, COMPACT_STEPS=a.compact_steps)


def packing(name, v, seed):
    """Bottom wall, loose flowing parcels, top wall: [(x, y, z, d)], types, box."""
    m, d = P.MATERIALS[name], v["D"]
    rng = random.Random(seed)
    lx, ly, wt = v["LX"], v["LY"], P.WALL_THICKNESS * d
    vol = math.pi / 6 * d ** 3
    cellsize = 1.0001 * m["d_max"]

    def layer(diams, z0, top):
        def sample(rng, r, top):
            return rng.uniform(0, lx), rng.uniform(0, ly), rng.uniform(z0 + r, top - r)
        return gc.dem.loose_packing(diams, rng, sample, lambda x, y, z, r: True, lambda t: t + 0.1 * d, top,
                                    cellsize, 0.0, periodic_y=ly, periodic_x=lx)
    n_wall = round(0.45 * lx * ly * wt / vol)           # a rough, not close-packed, layer
    bottom = layer([d] * n_wall, 0.0, wt)
    n_flow = round(0.60 * lx * ly * v["GAP"] / vol)     # fills the gap at ~0.6 once compacted
    diams = [m["psd"](rng) for _ in range(n_flow)]
    h_loose = 0.60 * v["GAP"] / P.PACKING_INSERT
    flow = layer(diams, wt, wt + h_loose)
    z1 = max(z + dd / 2 for _, _, z, dd in flow)
    top = layer([d] * n_wall, z1, z1 + wt)
    atoms = bottom + flow + top
    types = [2] * len(bottom) + [1] * len(flow) + [2] * len(top)
    return atoms, types, (0.0, lx, 0.0, ly, -0.5 * d, z1 + wt + 0.5 * d), len(top)


def run_numbers(v, i_target, strain, prev, prev_name):
    """The numbers of one shear run at target inertial number i_target."""
    speed = i_target * v["GAP"] * math.sqrt(v["PRESSURE"] / v["RHO"]) / v["D"]
    n_steps = math.ceil(strain * v["GAP"] / (speed * v["DEM_DT"]))
    snap = max(1, round(n_steps / P.SNAPSHOTS))
    n_steps = snap * math.ceil(n_steps / snap)
    return dict(v, V=speed, I_TARGET=i_target, STRAIN=strain, N_STEPS=n_steps, SNAP=snap,
                LOG_EVERY=max(1, snap // 4), THERMO=max(1, n_steps // 10), PREV=prev, PREV_NAME=prev_name)


def sweep(name, a, runs):
    """Compaction, then the shear runs from fast to slow; skips finished runs. Returns CPU seconds."""
    v = cell(name, a)
    base = os.path.join(runs, name)
    src = os.path.join(HERE, "template")
    cpu = {}
    compact = os.path.join(base, "compact")
    if not os.path.exists(os.path.join(compact, "dem", "shear.restart")):
        gc.runner.clean(compact)
        atoms, types, box, n_top = packing(name, v, a.seed)
        f_atom = -v["PRESSURE"] * v["AREA"] / n_top
        v.update(N_TOP=n_top, F_ATOM=f_atom, GAMMA=abs(f_atom) / P.COMPACT_VT, THERMO=max(1, a.compact_steps // 10))
        os.makedirs(os.path.join(compact, "dem"))
        gc.template.render(src, os.path.join(compact, "dem"), v, only=["in.materials", "in.servo", "in.compact"])
        gc.dem.write_data(os.path.join(compact, "dem", "packing.data"), atoms, box, v["RHO"],
                          f"shear cell of {v['MATERIAL']}: {len(atoms)} parcels (study.py)", types=types)
        with open(os.path.join(base, "cell.json"), "w") as fh:
            json.dump(dict(n_top=n_top, n_atoms=len(atoms), n_flow=types.count(1), n_wall=types.count(2)), fh)
        if a.setup_only:
            return {}
        cpu["compact"] = liggghts(compact, "in.compact")
        print(f"{name}: compacted ({len(atoms)} parcels, {cpu['compact']:.0f} s CPU)", flush=True)
    with open(os.path.join(base, "cell.json")) as fh:
        n_top = json.load(fh)["n_top"]
    f_atom = -v["PRESSURE"] * v["AREA"] / n_top
    v.update(N_TOP=n_top, F_ATOM=f_atom)
    prev, prev_name = os.path.join(compact, "dem", "shear.restart"), "the compaction"
    for k, i_t in enumerate(a.I):
        run = os.path.join(base, f"I{i_t:g}")
        strain = a.strain[i_t] + (P.FIRST_STRAIN_EXTRA if k == 0 else 0.0)
        rv = run_numbers(v, i_t, strain, os.path.relpath(prev, os.path.join(run)), prev_name)
        done = os.path.join(run, "dem", "shear.restart")
        if not os.path.exists(done):
            gc.runner.clean(run)
            gc.template.render(src, os.path.join(run, "dem"), rv, only=["in.materials", "in.servo", "in.liggghts"])
            with open(os.path.join(run, "run.json"), "w") as fh:
                json.dump({k2: rv[k2] for k2 in ("V", "I_TARGET", "STRAIN", "N_STEPS", "SNAP", "LOG_EVERY", "DEM_DT",
                                                 "D", "LX", "LY", "GAP", "RHO", "PRESSURE")}, fh, indent=1)
            if a.setup_only:
                return cpu
            os.makedirs(os.path.join(run, "post"), exist_ok=True)
            print(f"{name}: I = {i_t:g} started: V = {rv['V']:.4g} m/s, {rv['N_STEPS']} steps (strain {strain:g}); "
                  f"progress in {run}/log/liggghts.log", flush=True)
            t0 = time.time()
            cpu[f"I{i_t:g}"] = liggghts(run, "in.liggghts")
            print(f"{name}: I = {i_t:g} done, {cpu[f'I{i_t:g}']:.0f} s CPU, {time.time() - t0:.0f} s wall", flush=True)
            with open(os.path.join(run, "cpu.json"), "w") as fh:
                json.dump({"cpu_s": cpu[f"I{i_t:g}"]}, fh)
        prev, prev_name = done, f"I{i_t:g}"
    return dict(cpu_s=sum(cpu.values()))


def liggghts(run, script):
    # the run's own folder: the templates name dem/..., post/... relative to it
    return gc.runner.liggghts(run, f"dem/{script}", "liggghts", "log/log.liggghts", "log/screen.liggghts")


# --- post-processing --------------------------------------------------------------

def cg_profiles(run, rv, t_from):
    """granairCG across the gap: the time average from t_from and each snapshot (post/profile*.csv)."""
    stem = os.path.join("post", "profile")
    out = os.path.join(run, stem + ".csv")
    if not os.path.exists(out) or os.path.getmtime(out) < os.path.getmtime(os.path.join(run, "dem", "shear.restart")):
        gc.cg.run(run, stem, {"particles": "post/cg/particles_*.dump", "pairs": "post/cg/pairs_*.dump",
                              "dt": rv["DEM_DT"], "coordinates": "Z", "kernel": "gauss", "width": P.CG_WIDTH * rv["D"],
                              "spacing": P.CG_SPACING * rv["D"], "from": t_from, "every": True, "format": "csv"},
                  log="granairCG")
    return os.path.join(run, stem)


def post_run(run, rv):
    """The run's bulk values, their block standard errors and the wall check."""
    steps = rv["N_STEPS"]
    t_end = steps * rv["DEM_DT"]
    t_from = (1 - P.AVERAGE_FRACTION) * t_end
    stem = cg_profiles(run, rv, t_from)
    wall = np.loadtxt(os.path.join(run, "post", "wall.txt"), comments="#", ndmin=2)
    t_wall = rv["LOG_EVERY"] * rv["DEM_DT"] * np.arange(1, len(wall) + 1)
    w = wall[t_wall >= t_from - 1e-12]
    d = rv["D"]
    wt = P.WALL_THICKNESS * d
    z_bot, z_top = float(np.mean(w[:, 4])), float(np.mean(w[:, 3]))
    lo, hi = z_bot + 0.5 * wt + P.BAND * d, z_top - 0.5 * wt - P.BAND * d
    mean = gc.cg.read(stem + ".csv")
    tables = [gc.cg.read(p) for step, p in gc.dem.numbered(stem + "_*.csv") if step * rv["DEM_DT"] >= t_from - 1e-12]
    res = gc.calibration.shear_point(mean, tables, lo, hi, rv["RHO"], w, rv["LX"] * rv["LY"], BLOCKS)
    res.update(gap=z_top - z_bot - wt, band=(lo, hi), snapshots=len(tables), V=rv["V"], I_target=rv["I_TARGET"],
               t_from=t_from, t_end=t_end)
    return res, mean


def write_outputs(name, out, rows, fm, fp, v):
    """The fit as the entries of a muI block (muI) and a complete block (rheology): template/muI, template/rheology."""
    d = dict(fm, **fp)
    gc.template.render(os.path.join(HERE, "template"), out, dict(
        {k.upper(): x for k, x in d.items()}, TITLE=P.MATERIALS[name]["title"], WHEN=time.strftime("%Y-%m-%d"),
        N=len(rows), I_MIN=min(r["I"] for r in rows), I_MAX=max(r["I"] for r in rows), PRESSURE=v["PRESSURE"],
        D=v["D"], RHO=P.MATERIALS[name]["rho"]), only=["muI", "rheology"])
    return d


def post(a, runs, out):
    c = gc.checks.Checks("rheology-calibration")
    summary, allrows = {}, {}
    for name in a.material:
        base = os.path.join(runs, name)
        res_dir = os.path.join(out, name)
        os.makedirs(res_dir, exist_ok=True)
        rows, profiles = [], []
        cpu_total = 0.0
        for i_t in a.I:
            run = os.path.join(base, f"I{i_t:g}")
            if not os.path.exists(os.path.join(run, "dem", "shear.restart")):
                print(f"{name}: I = {i_t:g} not run (yet): left out", flush=True)
                continue
            with open(os.path.join(run, "run.json")) as fh:
                rv = json.load(fh)
            r, prof = post_run(run, rv)
            with open(os.path.join(run, "cpu.json")) as fh:
                r["cpu_s"] = json.load(fh)["cpu_s"]
            cpu_total += r["cpu_s"]
            rows.append(r)
            profiles.append((rv, r, prof))
        if not rows:
            continue
        with open(os.path.join(base, "cell.json")) as fh:
            cellinfo = json.load(fh)
        for r in rows:
            r["in_fit"] = int(r["I"] <= P.FIT_I_MAX and r["I_se"] <= P.FIT_I_SE * r["I"])
        keys = ["I_target", "in_fit", "V", "I", "I_se", "mu", "mu_se", "mu_J2", "mu_J2_se", "mu_xz", "mu_xz_se", "wall_mu", "phi",
                "phi_se", "P", "P_se", "sigma_xz", "sigma_xz_se", "sigma_zz", "sigma_zz_se", "wall_tau", "wall_sigma",
                "uniformity", "gamma_dot", "d", "gap", "snapshots", "cpu_s"]
        gc.series.write_rows(os.path.join(res_dir, "points.csv"), [{k: r[k] for k in keys} for r in rows],
                             fmt="{:.6g}")
        plot_profiles(name, profiles, os.path.join(res_dir, "profiles.png"))
        fit_rows = [r for r in rows if r["in_fit"]]
        col = lambda k: np.array([r[k] for r in fit_rows])          # noqa: E731
        fits, alt = {}, {}
        if len(fit_rows) >= 4:
            fm, fp = (gc.calibration.fit_mu(col("I"), col("mu"), col("mu_se")),
                      gc.calibration.fit_phi(col("I"), col("phi"), col("phi_se")))
            fits = write_outputs(name, res_dir, fit_rows, fm, fp, cell(name, a))
            alt = {k: gc.calibration.fit_mu(col("I"), col(k), col(f"{k}_se")) for k in ("mu_xz", "mu_J2")}
            for f in alt.values():
                f.pop("covariance")
            print(f"{name}: mu_s = {fm['mu_s']:.4f} +- {fm['mu_s_se']:.4f}, mu_2 = {fm['mu_2']:.4f} +- "
                  f"{fm['mu_2_se']:.4f}, I0 = {fm['I0']:.4g} +- {fm['I0_se']:.2g}; phi_max = {fp['phi_max']:.4f} +- "
                  f"{fp['phi_max_se']:.4f}, phi_min = {fp['phi_min']:.4f} +- {fp['phi_min_se']:.4f}", flush=True)
        m = P.MATERIALS[name]
        summary[name] = dict(
            {key: m[k] for key, k in (("material", "title"), ("source", "source"), ("d_parcel_m", "d_mean"),
                                      ("rho_p", "rho"), ("youngs_Pa", "youngs"), ("poisson", "nu"),
                                      ("restitution", "restitution"), ("friction", "friction"),
                                      ("rolling_friction", "rolling_friction"),
                                      ("cohesion_energy_density_J_m3", "cohesion"))},
            pressure_Pa=a.pressure, cell=dict(lx_d=a.cell_x, ly_d=a.cell_x, gap_d=a.gap, **cellinfo),
            fit={k: v for k, v in fits.items() if k != "covariance"}, mu_fit_covariance=fits.get("covariance"),
            fit_other_definitions=dict(alt, note="mu_xz = sigma_xz / sigma_zz (plane-shear convention), mu_J2 = "
                                       "sqrt(J2) / P (with the normal-stress differences); the fit above is "
                                       "mu = |sigma_xz| / P, P = tr(sigma)/3"),
            points=[{k: r[k] for k in keys} for r in rows], cpu_s=round(cpu_total, 1),
            continuum_now=continuum_now()[name])
        allrows[name] = (rows, fits)
        ref = os.path.join(HERE, "results", "calibration.json")
        if (a.pressure != P.PRESSURE or a.cell != [P.CELL_X, P.GAP]) and os.path.exists(ref):
            with open(ref) as fh:
                f0 = json.load(fh).get(name, {}).get("fit")
            if f0:
                dev = gc.calibration.vs_fit(rows, f0)
                gc.series.write_rows(os.path.join(res_dir, f"vs_P{P.PRESSURE:g}_fit.csv"), dev, fmt="{:.6g}")
                for x in dev:
                    print(f"{name}, P = {a.pressure:g} Pa, cell {a.cell_x:g} x {a.gap:g} d: I = {x['I']:.3g}: mu {x['mu']:.4f} +- {x['mu_se']:.4f}, "
                          f"the P = {P.PRESSURE:g} Pa fit {x['mu_reference_fit']:.4f}: {x['difference']:+.4f}", flush=True)
        for r in rows:
            for what, val, ref, se in (("|sigma_xz| vs the top wall's shear traction", abs(r["sigma_xz"]), r["wall_tau"],
                                        r["sigma_xz_se"]),
                                       ("sigma_zz vs the top wall's normal traction", r["sigma_zz"], r["wall_sigma"],
                                        r["sigma_zz_se"])):
                tol = max(P.WALL_BALANCE * ref, P.WALL_BALANCE_SE * se)
                c.near(f"{name} I = {r['I']:.3g}: CG bulk {what}", val, ref, tol,
                       f"steady plane shear: the stress is uniform and the wall carries it; {100 * P.WALL_BALANCE:g} % "
                       f"or {P.WALL_BALANCE_SE:g} block standard errors ({se:.3g} Pa) if larger", " Pa")
            c.within(f"{name} I = {r['I']:.3g}: rms deviation of sigma_xz across the bulk / its mean",
                     r["uniformity"], 0.0, P.UNIFORMITY, "momentum balance in steady shear: d sigma_xz / dz = 0")
        low = min(rows, key=lambda r: r["I"])
        if low["I"] < 0.05:
            c.within(f"{name}: mu at the lowest I = {low['I']:.3g}", low["mu"], *P.MU_LOW_I_BAND,
                     f"quasi-static friction of Hertz spheres of sliding friction {m['friction']} without rolling "
                     "resistance (parameters.py: da Cruz et al. 2005, Chialvo et al. 2012)")
    if summary:
        with open(os.path.join(out, "calibration.json"), "w") as fh:
            json.dump(summary, fh, indent=1)
        plot_fits(allrows, out, a.pressure)
    return c


def plot_profiles(name, profiles, path):
    plt = gc.plots.pyplot()
    fig, ax = plt.subplots(1, 4, figsize=(13, 4.2), sharey=True)
    cmap = plt.get_cmap("viridis")
    for k, (rv, r, prof) in enumerate(profiles):
        col = cmap(k / max(1, len(profiles) - 1))
        z = (prof["z"] - prof["z"][0]) / rv["D"]
        lab = f"I = {r['I']:.2g}"
        ax[0].plot(prof["velocity_x"] / rv["V"], z, color=col, label=lab)
        ax[1].plot(prof["volume_fraction"], z, color=col)
        ax[2].plot(np.abs(prof["stress_xz"]) / rv["PRESSURE"], z, color=col)
        ax[3].plot(prof["friction_coefficient"], z, color=col)
        for axx in ax:
            for zb in r["band"]:
                axx.axhline((zb - prof["z"][0]) / rv["D"], color=col, lw=0.4, ls=":")
    ax[0].set(xlabel="V_x / V_wall", ylabel="z / d")
    ax[1].set(xlabel="solid fraction phi", xlim=(0.3, 0.7))
    ax[2].set(xlabel="|sigma_xz| / P_wall", xlim=(0, 1))
    ax[3].set(xlabel="sqrt(J2) / P (granairCG friction_coefficient)", xlim=(0, 1))
    ax[0].legend(fontsize=7)
    fig.suptitle(f"{P.MATERIALS[name]['title']}: CG profiles across the gap (dotted: the bulk band)")
    fig.tight_layout()
    gc.plots.save(fig, path, dpi=100)


def continuum_now():
    """The mu(I) parameters the continuum cases use today: the MCC hopper's
    rheology block (Remmelgas et al. 2019) and the wedge silo's (shear-test mu_s,
    Jop et al. 2006 span and I0; cases/wedge-silo/parameters.py)."""
    with open(os.path.join(HERE, "..", "mcc-hopper", "rheology", "muI")) as fh:
        text = fh.read()
    mcc = {k: gc.calibration.entry(text, key) for key, k in gc.calibration.KEYS.items()}
    w = P.WEDGE
    mu_s = w.fit_mu_s()[0]
    phi_max = w.FILLS[10][1] / w.RHO_P
    return {"mcc-hopper": dict(mcc, label="mcc-hopper continuum now (Remmelgas et al. 2019)"),
            "wedge-silo": dict(mu_s=mu_s, mu_2=mu_s + w.JOP_MU_SPAN, I0=w.JOP_I0, phi_max=phi_max,
                               phi_min=phi_max - w.DILATANCY_SPAN,
                               label="wedge-silo continuum now (shear test + Jop et al. 2006)")}


def plot_fits(allrows, out, pressure):
    plt = gc.plots.pyplot()
    colours = {"wedge-silo": "tab:blue", "mcc-hopper": "tab:red"}
    lit = continuum_now()
    for key, fname, ylab in (("mu", "mu_I.png", "mu = |sigma_xz| / P"), ("phi", "phi_I.png", "solid fraction phi")):
        fig, ax = plt.subplots(figsize=(6.5, 4.5))
        ii = np.logspace(-3.5, 0, 200)
        for name, (rows, fits) in allrows.items():
            col = colours.get(name, "k")
            i = np.array([r["I"] for r in rows])
            for inside in (1, 0):
                sel = [r for r in rows if r["in_fit"] == inside]
                if sel:
                    ax.errorbar([r["I"] for r in sel], [r[key] for r in sel], yerr=[2 * r[f"{key}_se"] for r in sel],
                                xerr=[2 * r["I_se"] for r in sel], fmt="o", color=col, ms=4, capsize=2,
                                mfc=col if inside else "none",
                                label=f"{name} DEM (+- 2 s.e.)" if inside else f"{name} DEM, not fitted (unsteady "
                                f"or I > {P.FIT_I_MAX:g})")
            if fits and key == "mu":
                ax.plot(ii, gc.calibration.mu_jop(ii, fits), color=col, label=f"fit: mu_s {fits['mu_s']:.3f}, mu_2 "
                                                                 f"{fits['mu_2']:.3f}, I0 {fits['I0']:.3g}")
                ax.plot(i, [r["wall_mu"] for r in rows], "x", color=col, ms=5, label=f"{name}: top wall -F_x/F_z (= sigma_xz/sigma_zz)")
            if fits and key == "phi":
                jj = ii[ii <= P.FIT_I_MAX]
                ax.plot(jj, fits["phi_max"] - (fits["phi_max"] - fits["phi_min"]) * jj, color=col,
                        label=f"fit: phi_max {fits['phi_max']:.3f}, phi_min {fits['phi_min']:.3f}")
        for name, f in lit.items():
            if name in allrows:
                y = gc.calibration.mu_jop(ii, f) if key == "mu" else f["phi_max"] - (f["phi_max"] - f["phi_min"]) * ii
                ax.plot(ii, y, color=colours[name], ls="--", lw=0.8, label=f["label"])
        ax.set(xscale="log", xlabel="inertial number I", ylabel=ylab, title=f"{ylab}: DEM shear cell, P = "
               f"{pressure:g} Pa")
        ax.legend(fontsize=7)
        fig.tight_layout()
        gc.plots.save(fig, os.path.join(out, fname), dpi=110)


def main():
    ap = gc.cli.parser(__doc__, out_help="results (default: results/ beside this script)")
    ap.add_argument("--material", nargs="+", default=list(P.MATERIALS), choices=list(P.MATERIALS))
    ap.add_argument("--I", type=float, nargs="+", default=list(P.I_TARGETS), help="target inertial numbers")
    ap.add_argument("--jobs", type=int, default=2, help="materials swept at a time")
    ap.add_argument("--quick", action="store_true",
                    help="mcc-hopper only, a 6 x 6 x 8 d cell, I = 0.1 and 0.02 (the case test)")
    ap.add_argument("--stage", default="all", choices=["all", "runs", "post"])
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--pressure", type=float, default=P.PRESSURE,
                    help=f"confining pressure [Pa] (default {P.PRESSURE:g}; another value: results-P<value>/ by default)")
    ap.add_argument("--cell", type=float, nargs=2, default=[P.CELL_X, P.GAP], metavar=("L", "H"),
                    help=f"periodic length and gap in mean diameters (default {P.CELL_X:g} {P.GAP:g}; another: "
                         "results-cell<L>x<H>/ by default)")
    a = gc.cli.parse(ap, lambda a: os.path.join(HERE, "results" + ("" if a.pressure == P.PRESSURE else
                                                                    f"-P{a.pressure:g}")
                                                + ("" if a.cell == [P.CELL_X, P.GAP] else
                                                   f"-cell{a.cell[0]:g}x{a.cell[1]:g}")))
    if not a.pressure > 0:
        ap.error(f"--pressure {a.pressure}: expected > 0 Pa")
    if not (a.cell[0] >= 4 and a.cell[1] >= 2 * P.BAND + 4):
        ap.error(f"--cell {a.cell[0]:g} {a.cell[1]:g}: expected L >= 4 and H >= {2 * P.BAND + 4:g} diameters "
                 f"(a bulk band {P.BAND:g} d from either wall)")
    if not all(0 < i <= 1 for i in a.I) or len(set(a.I)) != len(a.I):
        ap.error(f"--I {' '.join(f'{i:g}' for i in a.I)}: expected distinct inertial numbers in (0, 1]")
    a.cell_x, a.gap, a.compact_steps = a.cell[0], a.cell[1], P.COMPACT_STEPS
    a.strain = dict(P.STRAIN)
    if a.quick:
        a.material, a.I, a.cell_x, a.gap, a.compact_steps = ["mcc-hopper"], [0.1, 0.02], 6.0, 8.0, 6000
        a.strain = {0.1: 2.0, 0.02: 1.5}
    missing = [i for i in a.I if i not in a.strain]
    if missing:
        a.strain.update({i: P.STRAIN[min(P.STRAIN, key=lambda k: abs(math.log(k / i)))] for i in missing})
    a.I = sorted(a.I, reverse=True)
    runs = os.path.join(a.out, "runs")
    os.makedirs(runs, exist_ok=True)
    print(f"rheology-calibration: {a.material}, I = {a.I}, P = {a.pressure:g} Pa; work in {runs}", flush=True)
    if a.stage in ("all", "runs"):
        gc.runner.pool([(n, sweep, (n, a, runs)) for n in a.material], a.jobs, "rheology-calibration")
        if a.setup_only:
            return print(f"rheology-calibration: run folders written to {runs}")
    c = post(a, runs, a.out)
    c.report(enforce=a.check)


if __name__ == "__main__":
    gc.cli.main(main)
