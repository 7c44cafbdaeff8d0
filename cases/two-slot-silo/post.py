"""Post-processing of the two-slot silo (README "Outputs"): per run the
particle accounting, the flow rate in 200 ms windows and the CG fields over
the openings; per study the tables, figures, level.json files and checks."""
import glob
import json
import math
import os
import re

import numpy as np

import granair_cases as gc
import parameters as P
import silo

ORDER = [P.SINGLE, 0, 8, 32, 2, 16, 4, 1]


def priority(L):
    return ORDER.index(L) if L in ORDER else len(ORDER)


# --- accounting (gc.tally) ---------------------------------------------------------
def fill_count(fill):
    path = os.path.join(fill, "log", "fill.liggghts")
    with open(path) as fh:
        m = re.search(r"^granair fill: (\d+) particles \((\d+) requested\)", fh.read(), re.M)
    if not m:
        raise gc.CaseError(f"{path}: no 'granair fill:' line (did the fill finish?)")
    return int(m.group(1)), int(m.group(2))


def events(run, stem, with_x=False):
    """(id, t, d) of every particle massflow/mesh wrote to dem/<stem>_<k>.txt
    (and x, where it crossed, with_x)."""
    a = gc.outlet.read_records(sorted(glob.glob(os.path.join(run, "dem", f"{stem}_*.txt"))), 4)
    out = (a[:, 0].astype(int), a[:, 1], a[:, 2])
    return out + (a[:, 3],) if with_x else out


def accounting(v, run, fill):
    """The exact balance of the run's chunks (gc.tally.balance); the ids the chunks deleted
    at their ends are in dem/pending_<k>.txt (template/dem/in.chunk)."""
    ks = [k for k, _, _ in silo.chunks(v)]
    pend = []
    for k in ks:
        path = os.path.join(run, "dem", f"pending_{k}.txt")
        if not os.path.exists(path):
            raise gc.CaseError(f"{path}: missing (did chunk {k} finish? runs set up before the pending deletions "
                               f"must be run again)")
        pend += [int(i) for i in gc.dem.read_dump(path)["id"]]
    return gc.tally.balance(*fill_count(fill), [gc.tally.chunk_states(os.path.join(run, "log", f"chunk_{k}.liggghts"), k)
                                                for k in ks], events(run, "crossings")[0], events(run, "removed")[0],
                            pend, sum(gc.tally.lost_atoms(os.path.join(run, "log", f"chunk_{k}.screen")) for k in ks))


# --- flow rate -------------------------------------------------------------------
def flow(v, L, run, t_end):
    """Mass flow through the outlet plane (gc.tally.crossing_flow): 200 ms windows from the
    steady start (mean, SD over windows), per opening (the crossings left and right of
    the axis; one opening for the single slot), and a 20 ms series for the figures."""
    _, t, d, x = events(run, "crossings", with_x=True)
    return gc.tally.crossing_flow(t, P.RHO_P * math.pi / 6 * d ** 3, v["STEADY_FROM"], t_end, P.WINDOW,
                                  None if L == P.SINGLE else [x < 0, x >= 0], 0.02)


# --- CG fields (gc.cg_slab) ------------------------------------------------------------
def cg_fields(v, L, run):
    """The time-averaged XZ fields over the openings (20 snapshots), the R2
    averages above each opening, the phi(I) points of R1, and the mass check."""
    box, width = (v["XLO"], v["XHI"], v["DEPTH"]), P.CG_WIDTH_OVER_D * P.D_MEAN
    grid = (v["DEM_DT"], width, P.CG_CUTOFF, P.CG_GRID)
    os.makedirs(os.path.join(run, "cg"), exist_ok=True)
    cpu, steps = gc.cg_slab.run(run, "fields", box, (v["XLO"], 0.0, -0.01), (v["XHI"], v["DEPTH"], P.R1_HEIGHT + 0.01),
                                *grid, "granairCG")
    f = gc.series.read_csv(os.path.join(run, "cg", "fields.csv"))
    x, z, p, phi = f["x"], f["z"], f["pressure"], f["volume_fraction"]
    gd, i_paper, eta = gc.cg_slab.fullard(f, P.D_MEAN, P.RHO_P)      # the paper's shear rate, I and eta
    named = (("shear_rate", gd), ("pressure", p), ("inertial_number", i_paper), ("volume_fraction", phi),
             ("viscosity", eta), ("shear_rate_granairCG", f["shear_rate"]), ("inertial_number_granairCG", f["inertial_number"]))
    r2 = [gc.cg_slab.box_mean(named, (np.abs(x - xc) <= P.R2_HALF_WIDTH) & (z >= 0) & (z <= P.R2_HEIGHT))
          for xc in P.centres(L)]
    # R1 for phi(I): 0-5 cm above the floor, less one kernel cutoff at the side
    # walls and below the fill height (there the kernel reaches past the
    # particles and phi drops for a reason that is not I)
    cut = P.CG_CUTOFF * P.CG_WIDTH_OVER_D * P.D_MEAN
    r1 = ((z >= 0) & (z <= min(P.R1_HEIGHT, v["HEIGHT"] - cut)) & (np.abs(x) <= v["WIDTH"] / 2 - cut)
          & np.isfinite(i_paper) & (i_paper > P.I_FIT_MIN))
    keep = ["x", "z", "velocity_x", "velocity_z", "volume_fraction", "pressure", "shear_stress"]
    cols = [(k, f[k]) for k in keep] + [("shear_rate", gd), ("inertial_number", i_paper), ("viscosity", eta)]
    cg_mass, dump_mass, cpu_m = gc.cg_slab.mass_check(run, box, (P.SINK_Z, v["ZHI"]), *grid, steps[-1])
    return dict(snapshots=len(steps), t_from=steps[0] * v["DEM_DT"], t_to=steps[-1] * v["DEM_DT"], r2=r2,
                phi_I=np.column_stack([i_paper[r1], phi[r1]]).tolist(), cg_mass_kg=cg_mass,
                particle_mass_kg=dump_mass, cpu_s=round(cpu + cpu_m, 1)), cols


def run(v, L, run_dir, fill, out):
    """Post-process one finished run into out/<geom>.json, _flow.csv, _cg.csv
    (gc.chunk_inputs.post_once: kept while its json is newer than the run's last chunk)."""
    name = silo.geometry_name(L)
    os.makedirs(out, exist_ok=True)

    def post():
        cost = gc.chunk_inputs.cost(run_dir)
        acc = accounting(v, run_dir, fill)
        q, (tc, series) = flow(v, L, run_dir, acc["t_end"])
        gc.series.write_csv(os.path.join(out, f"{name}_flow.csv"), [("t", tc), ("mass_flow_kg_s", series)], fmt="{:.6g}")
        r = dict(friction=v["FRICTION"], geometry=name, L_mm=None if L == P.SINGLE else L, size=v["SIZE"],
                 openings_m=P.openings(L), accounting=acc, flow=q,
                 cost=dict(cost, total_cpu_s=round(sum(c["cpu_s"] for c in cost.values()), 1)),
                 fill_cost=silo.fill_cost(fill), dem_dt_s=v["DEM_DT"], particles_fill=acc["fill"])
        if v["CG"]:
            r["cg"], cols = cg_fields(v, L, run_dir)
            gc.series.write_csv(os.path.join(out, f"{name}_cg.csv"), cols, fmt="{:.6g}")
        return r
    return gc.chunk_inputs.post_once(os.path.join(out, f"{name}.json"), run_dir, post)


# --- the study -------------------------------------------------------------------
def bulk_density(fill, v):
    """Bulk density of the settled fill [kg/m3] between 2 d above the floor and 2 d
    below the 200 highest particles, and that top."""
    dump = gc.dem.read_dump(os.path.join(fill, "dem", "fill.dump"))
    return gc.outlet.bulk_density(dump["z"], dump["mass"], v["WIDTH"] * v["DEPTH"], P.D_MEAN)


def hagen_beverloo(b, rho_b):
    """(low, high) Hagen-Beverloo band of one slot b wide over the depth [kg/s]."""
    return gc.closed_forms.beverloo_band("slot", b, P.D_MEAN, rho_b, P.K_RANGE, P.BEVERLOO_C, P.DEPTH)


def load(out, f, L):
    p = os.path.join(out, f, f"{silo.geometry_name(L)}.json")
    if not os.path.exists(p):
        return None
    with open(p) as fh:
        return json.load(fh)


def study(a, runs, geoms, c):
    """Tables, figures, level.json and checks over every finished run."""
    res, rho_b = {}, {}
    for f in a.friction:
        v = silo.numbers(a.size, f)
        fill = os.path.join(runs, f, "fill")
        rho = fill_density(fill, v, os.path.join(a.out, f, "fill.json"))
        if rho is not None:
            rho_b[f] = rho
        for L in geoms:
            run_dir = os.path.join(runs, f, silo.geometry_name(L))
            if not os.path.exists(os.path.join(a.out, f, f"{silo.geometry_name(L)}.json")) and \
                    os.path.exists(gc.chunk_inputs.record_file(run_dir)) and gc.chunk_inputs.finished(run_dir, silo.chunks(v)):
                try:
                    run(v, L, run_dir, fill, os.path.join(a.out, f))
                except gc.CaseError as e:
                    print(f"two-slot-silo {f} {silo.geometry_name(L)}: post-processing failed: {e}", flush=True)
            r = load(a.out, f, L)
            if r:
                res[(f, L)] = r
    if not res:
        print("two-slot-silo: no finished runs to post-process", flush=True)
        return
    rows = table(a, res, rho_b)
    plot_flow(a, res, rho_b)
    plot_r2(a, res)
    plot_phi_I(a, res)
    for f in a.friction:
        plot_maps(a, f, [L for L in geoms if (f, L) in res])
    levels(a, res, rho_b)
    checks(a, res, rho_b, c)
    return rows


def ratio(x, y):
    return x / y if y and math.isfinite(y) else math.nan


def table(a, res, rho_b):
    head = ["friction", "geometry", "L_mm", "L_over_d", "particles", "windows", "flow_kg_s", "flow_sd_kg_s",
            "flow_over_L0", "flow_over_single", "per_opening_kg_s", "interaction", "R2_shear_rate_1_s", "R2_pressure_Pa", "R2_inertial_number",
            "R2_volume_fraction", "R2_viscosity_Pa_s", "cpu_s", "accounting_closes"]
    rows = []
    for (f, L), r in sorted(res.items(), key=lambda t: (t[0][0], priority(t[0][1]))):
        q0 = res.get((f, 0), {}).get("flow", {}).get("mean", math.nan)
        q1 = res.get((f, P.SINGLE), {}).get("flow", {}).get("mean", math.nan)
        q = r["flow"]
        r2 = r.get("cg", {}).get("r2", [])
        mean = {k: float(np.mean([x[k] for x in r2])) if r2 else math.nan
                for k in ("shear_rate", "pressure", "inertial_number", "volume_fraction", "viscosity")}
        rows.append([f, r["geometry"], "" if L == P.SINGLE else L, "" if L == P.SINGLE else f"{L * 1e-3 / P.D_MEAN:.3g}",
                     r["particles_fill"], q["n_windows"], f"{q['mean']:.5g}", f"{q['sd']:.3g}", f"{ratio(q['mean'], q0):.4g}",
                     f"{ratio(q['mean'], q1):.4g}", " / ".join(f"{x:.5g}" for x in q.get("per_opening_mean", [])),
                     f"{ratio(q['mean'], (1 if L == P.SINGLE else 2) * q1):.4g}", *(f"{mean[k]:.4g}" for k in mean), r["cost"]["total_cpu_s"],
                     int(r["accounting"]["closes"])])
    gc.series.write_rows(os.path.join(a.out, "flow_rate.csv"), [dict(zip(head, row)) for row in rows])
    with open(os.path.join(a.out, "summary.txt"), "w") as fh:
        fh.write(f"# two-slot silo, size {a.size}: flow rate in {P.WINDOW * 1e3:.0f} ms windows (mean, SD), per "
                 f"opening (left / right), interaction = total / (number of openings x the single 14 mm rate), R2 "
                 f"averages, CPU seconds per run (fill not included)\n")
        for f in sorted(rho_b):
            lo, hi = hagen_beverloo(P.D0, rho_b[f])
            lo2, hi2 = hagen_beverloo(2 * P.D0, rho_b[f])
            fh.write(f"# {f}: settled bulk density {rho_b[f]:.1f} kg/m3; Hagen-Beverloo (C = {P.BEVERLOO_C}, k = 1..3): "
                     f"14 mm {lo * 1e3:.2f}-{hi * 1e3:.2f} g/s, 28 mm {lo2 * 1e3:.2f}-{hi2 * 1e3:.2f} g/s\n")
        fh.write("".join(line + "\n" for line in gc.tables.aligned([head] + rows)))
    return rows


def _xs(res, f, key):
    Ls = sorted(L for (g, L) in res if g == f and L != P.SINGLE)
    return Ls, [key(res[(f, L)]) for L in Ls]


COLOURS = {"low": "tab:blue", "high": "tab:red"}


def _l_axis(ax, over_d=False):
    """L (or L/d) on a symlog axis that shows L = 0 and 1..32 mm."""
    lin = 1.0 / (P.D_MEAN * 1e3) if over_d else 1.0
    ax.set_xscale("symlog", linthresh=lin)
    ax.set_xlim(-0.1 * lin, (45 / (P.D_MEAN * 1e3)) if over_d else 45)
    ax.set_xlabel("L / d" if over_d else "L [mm]")
    ax.grid(alpha=0.3)


def plot_flow(a, res, rho_b):
    plt = gc.plots.pyplot()
    fig, axs = plt.subplots(1, 4, figsize=(19, 4.4))
    for f in sorted({g for g, _ in res}):
        col = COLOURS[f]
        Ls, q = _xs(res, f, lambda r: r["flow"]["mean"])
        _, sd = _xs(res, f, lambda r: r["flow"]["sd"])
        _, per = _xs(res, f, lambda r: np.mean(r["flow"].get("per_opening_mean", [math.nan])))
        q, sd, per = np.array(q), np.array(sd), np.array(per)
        q0 = res.get((f, 0), {}).get("flow", {}).get("mean", math.nan)
        q1 = res.get((f, P.SINGLE), {}).get("flow", {}).get("mean", math.nan)
        mu = P.FRICTION[f]
        lab = f"{f} friction ({mu[0]}/{mu[1]})"
        axs[0].errorbar(Ls, q * 1e3, sd * 1e3, color=col, marker="o", capsize=3, label=lab)
        for ax, x in ((axs[1], np.array(Ls, float)), (axs[2], np.array(Ls, float) * 1e-3 / P.D_MEAN)):
            ax.errorbar(x, q / q0, sd / q0, color=col, marker="o", capsize=3, label=lab)
            if math.isfinite(q1):
                ax.axhline(q1 / q0, color=col, ls=":", lw=1, label=f"one 14 mm slot ({f})")
                ax.axhline(2 * q1 / q0, color=col, ls="--", lw=1, label=f"twice one 14 mm slot ({f})")
        # the interaction: each opening's rate over the single opening's (1 = no interaction)
        axs[3].plot(Ls, per / q1, "o-", color=col, label=lab)
        if math.isfinite(q1):
            axs[0].axhline(q1 * 1e3, color=col, ls=":", lw=1)
            axs[0].axhline(2 * q1 * 1e3, color=col, ls="--", lw=1)
        if f in rho_b:
            lo, hi = hagen_beverloo(P.D0, rho_b[f])
            lo2, hi2 = hagen_beverloo(2 * P.D0, rho_b[f])
            axs[0].axhspan(lo2 * 1e3, hi2 * 1e3, color=col, alpha=0.10)
            axs[0].axhspan(2 * lo * 1e3, 2 * hi * 1e3, facecolor="none", edgecolor=col, hatch="//", lw=0.5)
    axs[0].set(ylabel="flow rate [g/s]")
    axs[0].set_title("total flow rate; shaded: Hagen-Beverloo 28 mm,\nhatched: 2 x Hagen-Beverloo 14 mm (k = 1..3)",
                     fontsize=9)
    axs[1].set(ylabel="W / W(L = 0)")
    axs[1].set_title("normalised by the 28 mm slot (L = 0)", fontsize=9)
    axs[2].set(ylabel="W / W(L = 0)")
    axs[2].set_title(f"against L / d, d = {P.D_MEAN * 1e3:.2f} mm", fontsize=9)
    axs[3].axhline(1, color="k", lw=0.8)
    axs[3].set(ylabel="per opening / one 14 mm slot")
    axs[3].set_title("interaction: each opening's rate over the single slot's\n(L = 0: each half of the 28 mm slot)",
                     fontsize=9)
    for k, ax in enumerate(axs):
        _l_axis(ax, over_d=(k == 2))
    axs[0].legend(fontsize=7)
    axs[1].legend(fontsize=6, loc="best")
    fig.suptitle(f"Two-slot silo (D0 = 14 mm, depth 15 mm, {a.size} size): dotted one 14 mm slot, dashed twice it; "
                 f"error bars SD of {P.WINDOW * 1e3:.0f} ms windows", fontsize=9)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(a.out, "flow_rate.png"), dpi=110)


R2_FIELDS = (("shear_rate", "shear rate [1/s]"), ("pressure", "P [Pa]"), ("inertial_number", "I"),
             ("volume_fraction", "phi"), ("viscosity", "eta [Pa s]"))


def plot_r2(a, res):
    plt = gc.plots.pyplot()
    fig, axs = plt.subplots(1, 5, figsize=(17, 3.8))
    for f in sorted({g for g, _ in res}):
        col = COLOURS[f]
        for ax, (k, lab) in zip(axs, R2_FIELDS):
            Ls, vals = _xs(res, f, lambda r: np.mean([x[k] for x in r["cg"]["r2"]]) if "cg" in r else math.nan)
            ax.plot(Ls, vals, "o-", color=col, label=f"{f} friction")
            one = res.get((f, P.SINGLE))
            if one and "cg" in one:
                ax.axhline(one["cg"]["r2"][0][k], color=col, ls=":", lw=1, label=f"one 14 mm slot ({f})")
            ax.set_title(lab, fontsize=9)
            _l_axis(ax)
    axs[0].legend(fontsize=7)
    fig.suptitle("R2 averages (14.5 x 14 mm above each opening, mean of both), 20 snapshots 5 ms apart", fontsize=9)
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(a.out, "r2_fields.png"), dpi=110)


def plot_phi_I(a, res):
    gc.phi_i.plot(os.path.join(a.out, "phi_I.png"), os.path.join(a.out, "phi_I_fit.txt"),
                  [(f, COLOURS[f], [p for (g, _), r in res.items() if g == f and "cg" in r for p in r["cg"]["phi_I"]])
                   for f in sorted({g for g, _ in res})], P.I_FIT_MIN,
                  "phi against I over R1 (I > 0.05; not within 3w of the side walls), fit phi = a1 / (1 + a2 I)",
                  "phi = a1 / (1 + a2 I), least squares in phi, over R1 (0-5 cm above the floor, not within one "
                  "kernel cutoff of the side walls) for I > 0.05, every run of the set")


MAPS = (("speed", "|v| [m/s]", "viridis"), ("shear_rate", "shear rate [1/s]", "magma"),
        ("pressure", "P [Pa]", "cividis"), ("volume_fraction", "phi", "Blues"))


def plot_maps(a, f, Ls):
    rows = []
    for L in Ls:
        path = os.path.join(a.out, f, f"{silo.geometry_name(L)}_cg.csv")
        if not os.path.exists(path):
            continue
        d = gc.series.read_csv(path)
        d["speed"] = np.hypot(d["velocity_x"], d["velocity_z"])

        def openings(ax, L=L):
            for (x0, x1) in P.openings(L):
                ax.plot([x0 * 1e3, x1 * 1e3], [0, 0], color="w", lw=2)
        rows.append((silo.geometry_name(L), np.unique(d["x"]) * 1e3, np.unique(d["z"]) * 1e3, d, openings))
    gc.field_maps.draw(os.path.join(a.out, f"maps_{f}.png"),
                       f"CG fields, {f} friction (Gaussian w = d, depth averaged, 20 snapshots); white: the openings; "
                       "x, z in mm", rows, MAPS)


def fill_density(fill, v, saved):
    """The settled fill's bulk density: from its dump when the run folder has it, else
    from `saved` (gc.chunk_inputs.kept), so --post-only on a checkout without the runs'
    dumps still makes the Hagen-Beverloo rows and checks. None if neither exists."""
    d = gc.chunk_inputs.kept(saved, os.path.join(fill, "dem", "fill.dump"),
                             lambda: dict(zip(("rho_b_kg_m3", "top_m"), bulk_density(fill, v))), "dem/fill.dump of the fill run")
    return d and d["rho_b_kg_m3"]


def levels(a, res, rho_b):
    """level.json for the single 14 mm slot and the 28 mm slot (L = 0): the two
    sizes `./granair compare` has closed forms for."""
    for (f, L), r in res.items():
        if L not in (P.SINGLE, 0):
            continue
        name = silo.geometry_name(L)
        mu = P.FRICTION[f]
        gc.levels.write(os.path.join(a.out, f, f"{name}.level.json"), case="two-slot-silo", level="cg-dem",
                        model=f"DEM at the real particle size (s = 1), linear spring-dashpot, mu = {mu[0]}/{mu[1]} "
                              f"({f}), {a.size} size",
                        b_mm=14 if L == P.SINGLE else 28, air=False, steady_mass_flow_kg_s=r["flow"]["mean"],
                        steady_window_s=[r["flow"]["window_start"], r["accounting"]["t_end"]], outlet_dpdz_Pa_m=None,
                        wall_time_s=round(sum(c.get("wall_s", 0) for k, c in r["cost"].items() if isinstance(c, dict)), 1),
                        cores=1, timeseries=f"{name}_flow.csv", flow_sd_kg_s=r["flow"]["sd"],
                        cpu_s=r["cost"]["total_cpu_s"], rho_b=rho_b.get(f))


def checks(a, res, rho_b, c):
    for (f, L), r in sorted(res.items(), key=lambda t: (t[0][0], priority(t[0][1]))):
        n = f"{f} {r['geometry']}"
        gc.tally.check(c, n, r["accounting"], len(r["cost"]))
        if f in rho_b and L in (P.SINGLE, 0, 32):
            # one slot of 14 or 28 mm; at L = 32 mm (15 d) two 14 mm slots, each its own band
            lo, hi = hagen_beverloo(2 * P.D0 if L == 0 else P.D0, rho_b[f])
            k = 2 if L == 32 else 1
            c.within(f"{n}: flow rate [kg/s] in {'twice ' if k == 2 else ''}the Hagen-Beverloo band "
                     f"x {1 / P.HB_WIDEN:.2g}..{P.HB_WIDEN:.2g}", r["flow"]["mean"], k * lo / P.HB_WIDEN, k * hi * P.HB_WIDEN,
                     P.HB_WHY + (" (L = 32 mm: each opening its own band)" if k == 2 else ""))
        if "cg" in r:
            cg = r["cg"]
            c.exact(f"{n}: CG snapshots", cg["snapshots"], P.CG_SNAPSHOTS, "20 snapshots 5 ms apart (paper)")
            c.close(f"{n}: CG mass (density integrated over the grid) = particle mass in the window",
                    cg["cg_mass_kg"], cg["particle_mass_kg"], P.CG_MASS_TOL, P.CG_MASS_WHY)

